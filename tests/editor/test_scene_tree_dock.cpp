/**************************************************************************/
/*  test_scene_tree_dock.cpp                                              */
/**************************************************************************/
/* SceneTreeDock (headless): add by class name with unique names, delete  */
/* and reparent, each undone and redone; selection and change counter;    */
/* nodes held by the history are freed once (live-node counter, RID leak  */
/* report). Dummy RenderingServer (no GPU).                               */

#include "editor/scene_tree_dock.h"

#include "core/object/undo_redo.h"
#include "core/templates/rid_owner.h"
#include "scene/3d/light_3d.h"
#include "scene/3d/node_3d.h"
#include "scene/main/scene_tree.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

namespace TestSceneTreeDock {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

static int live_dock_nodes = 0;

// Counts its live instances, so tests see every node freed exactly once.
class DockTestNode : public Node3D {
	GDCLASS(DockTestNode, Node3D);

public:
	DockTestNode() { live_dock_nodes++; }
	~DockTestNode() override { live_dock_nodes--; }
};

// A tree with an edited scene "Main" (Node3D) under the root.
struct DockScene {
	DummyServer server;
	SceneTree *tree = nullptr;
	Node3D *main = nullptr;
	UndoRedo undo_redo;
	SceneTreeDock dock;

	DockScene() {
		GDREGISTER_CLASS(DockTestNode);
		tree = new SceneTree;
		main = new Node3D;
		main->set_name("Main");
		tree->get_root()->add_child(main);
		dock.set_undo_redo(&undo_redo);
		dock.set_edited_scene(main);
	}
	~DockScene() {
		undo_redo.clear_history(); // Frees the nodes the history holds.
		delete tree;
	}
};

TEST_CASE("[SceneTreeDock] add_node instantiates by class name with unique names; undo and redo") {
	const uint64_t leaks_before = RID_AllocBase::get_leaked_total();
	{
		DockScene s;
		CHECK(s.dock.get_edited_scene() == s.main);
		Node *a = s.dock.add_node("AreaLight3D", nullptr);
		REQUIRE(a != nullptr);
		CHECK(a->get_class() == "AreaLight3D");
		CHECK(a->get_name() == "AreaLight3D");
		CHECK(a->get_parent() == s.main);
		CHECK(a->is_inside_tree());
		Node *b = s.dock.add_node("AreaLight3D", s.main);
		REQUIRE(b != nullptr);
		CHECK(b->get_name() == "AreaLight3D2");
		CHECK(s.dock.get_selected() == b);
		Node *c = s.dock.add_node("Node3D", b);
		REQUIRE(c != nullptr);
		CHECK(c->get_parent() == b);
		CHECK(s.undo_redo.get_history_count() == 3);
		CHECK(s.undo_redo.get_current_action_name() == "Add Node");

		REQUIRE(s.undo_redo.undo()); // c
		REQUIRE(s.undo_redo.undo()); // b
		CHECK(s.main->get_child_count() == 1);
		CHECK(b->get_parent() == nullptr);
		CHECK_FALSE(b->is_inside_tree());
		CHECK(s.dock.get_selected() == nullptr);
		REQUIRE(s.undo_redo.redo());
		CHECK(s.main->get_child_count() == 2);
		CHECK(s.main->get_child(1) == b);
		CHECK(b->get_name() == "AreaLight3D2");
		CHECK(s.dock.get_selected() == b);
		// A new action drops the redo of c, which frees it (it was out of the scene).
		Node *d = s.dock.add_node("DockTestNode", nullptr);
		REQUIRE(d != nullptr);
		CHECK(live_dock_nodes == 1);
		CHECK_FALSE(s.undo_redo.has_redo());

		{
			ErrorCatcher errors;
			const int history = s.undo_redo.get_history_count();
			CHECK(s.dock.add_node("NoSuchClass", nullptr) == nullptr);
			CHECK(errors.contains("NoSuchClass"));
			CHECK(s.dock.add_node("Environment", nullptr) == nullptr);
			CHECK(errors.contains("not a Node"));
			CHECK(s.dock.add_node("Light3D", nullptr) == nullptr);
			CHECK(errors.contains("abstract"));
			Node *outside = new Node;
			CHECK(s.dock.add_node("Node", outside) == nullptr);
			CHECK(errors.contains("not in the edited scene"));
			delete outside;
			CHECK(s.undo_redo.get_history_count() == history);
		}
		// Undo the DockTestNode, then clear: the history frees it.
		REQUIRE(s.undo_redo.undo());
		CHECK(live_dock_nodes == 1);
		s.undo_redo.clear_history();
		CHECK(live_dock_nodes == 0);
	}
	CHECK(live_dock_nodes == 0);
	CHECK(RID_AllocBase::get_leaked_total() == leaks_before);
}

TEST_CASE("[SceneTreeDock] delete_node and undo restore the subtree at the same index") {
	const uint64_t leaks_before = RID_AllocBase::get_leaked_total();
	{
		DockScene s;
		Node *a = s.dock.add_node("DockTestNode", nullptr);
		Node *b = s.dock.add_node("DockTestNode", nullptr);
		Node *b1 = s.dock.add_node("AreaLight3D", b);
		Node *b2 = s.dock.add_node("DockTestNode", b);
		Node *c = s.dock.add_node("DockTestNode", nullptr);
		REQUIRE((a && b && b1 && b2 && c));
		CHECK(live_dock_nodes == 4);
		s.undo_redo.clear_history();
		s.dock.select(b1);

		CHECK(s.dock.delete_node(b));
		CHECK(s.main->get_child_count() == 2);
		CHECK(b->get_parent() == nullptr);
		CHECK_FALSE(b1->is_inside_tree());
		CHECK(s.dock.get_selected() == nullptr); // The selection was inside the deleted subtree.
		CHECK(live_dock_nodes == 4); // Held by the history, not freed.
		CHECK(s.undo_redo.get_current_action_name() == "Delete Node");

		REQUIRE(s.undo_redo.undo());
		CHECK(s.main->get_child_count() == 3);
		CHECK(s.main->get_child(1) == b);
		CHECK(b->get_name() == "DockTestNode2");
		CHECK(b->get_child_count() == 2);
		CHECK(b->get_child(0) == b1);
		CHECK(b->get_child(1) == b2);
		CHECK(b1->is_inside_tree());

		REQUIRE(s.undo_redo.redo());
		CHECK(s.main->get_child_count() == 2);
		REQUIRE(s.undo_redo.undo());
		CHECK(s.main->get_child(1) == b);

		// Delete the first child and undo: back at index 0.
		CHECK(s.dock.delete_node(a));
		REQUIRE(s.undo_redo.undo());
		CHECK(s.main->get_child(0) == a);

		{
			ErrorCatcher errors;
			CHECK_FALSE(s.dock.delete_node(s.main));
			CHECK(errors.contains("scene root"));
			CHECK_FALSE(s.dock.delete_node(nullptr));
			Node *outside = new Node;
			CHECK_FALSE(s.dock.delete_node(outside));
			delete outside;
		}

		// Delete for good: clearing the history frees the subtree once.
		CHECK(s.dock.delete_node(b));
		CHECK(live_dock_nodes == 4);
		s.undo_redo.clear_history();
		CHECK(live_dock_nodes == 2);
	}
	CHECK(live_dock_nodes == 0);
	CHECK(RID_AllocBase::get_leaked_total() == leaks_before);
}

TEST_CASE("[SceneTreeDock] reparent keeps the global transform; undo restores parent, index, name and transform") {
	DockScene s;
	Node3D *p1 = Object::cast_to<Node3D>(s.dock.add_node("Node3D", nullptr));
	Node3D *p2 = Object::cast_to<Node3D>(s.dock.add_node("Node3D", nullptr));
	REQUIRE((p1 && p2));
	p1->set_position(Vector3(1, 0, 0));
	p2->set_position(Vector3(0, 5, 0));
	p2->set_rotation(Vector3(0, 1.0f, 0));
	Node3D *light = Object::cast_to<Node3D>(s.dock.add_node("AreaLight3D", p1));
	Node *other = s.dock.add_node("Node", p1);
	Node *clash = s.dock.add_node("Node3D", p2);
	REQUIRE((light && other && clash));
	light->set_name("Light");
	clash->set_name("Light");
	light->set_position(Vector3(0, 0, 2));
	const Transform3D global = light->get_global_transform();
	const Transform3D local = light->get_transform();
	s.undo_redo.clear_history();
	const uint64_t version = s.dock.get_version();

	CHECK(s.dock.reparent_node(light, p2));
	CHECK(light->get_parent() == p2);
	CHECK(light->get_name() == "Light2"); // "Light" is taken there.
	CHECK(light->get_global_transform().is_equal_approx(global));
	CHECK_FALSE(light->get_transform().is_equal_approx(local));
	CHECK(light->is_inside_tree());
	CHECK(s.dock.get_version() > version);
	CHECK(s.undo_redo.get_current_action_name() == "Reparent Node");

	REQUIRE(s.undo_redo.undo());
	CHECK(light->get_parent() == p1);
	CHECK(light->get_index() == 0);
	CHECK(light->get_name() == "Light");
	CHECK(light->get_transform().is_equal_approx(local));
	CHECK(p1->get_child(1) == other);

	REQUIRE(s.undo_redo.redo());
	CHECK(light->get_parent() == p2);
	CHECK(light->get_global_transform().is_equal_approx(global));
	REQUIRE(s.undo_redo.undo());

	{
		ErrorCatcher errors;
		const int history = s.undo_redo.get_history_count();
		CHECK_FALSE(s.dock.reparent_node(p1, p1));
		CHECK(errors.contains("itself"));
		CHECK_FALSE(s.dock.reparent_node(p1, light));
		CHECK(errors.contains("descendants"));
		CHECK_FALSE(s.dock.reparent_node(s.main, p1));
		CHECK(errors.contains("scene root"));
		CHECK_FALSE(s.dock.reparent_node(light, p1));
		CHECK(errors.contains("already a child"));
		CHECK_FALSE(s.dock.reparent_node(light, nullptr));
		CHECK(s.undo_redo.get_history_count() == history);
	}
	CHECK(light->get_parent() == p1);

	// A plain Node (no transform) moves too.
	CHECK(s.dock.reparent_node(other, s.main));
	CHECK(other->get_parent() == s.main);
	REQUIRE(s.undo_redo.undo());
	CHECK(other->get_parent() == p1);
	CHECK(other->get_index() == 1);
}

TEST_CASE("[SceneTreeDock] Selection and the change callback") {
	DockScene s;
	int calls = 0;
	s.dock.set_changed_callback([&calls]() { calls++; });
	Node *a = s.dock.add_node("Node3D", nullptr);
	REQUIRE(a != nullptr);
	CHECK(calls >= 1);
	const int after_add = calls;
	const uint64_t version = s.dock.get_version();
	s.dock.select(s.main);
	CHECK(s.dock.get_selected() == s.main);
	CHECK(calls == after_add + 1);
	CHECK(s.dock.get_version() == version + 1);
	s.dock.select(s.main); // Same selection: no change.
	CHECK(calls == after_add + 1);
	{
		ErrorCatcher errors;
		Node *outside = new Node;
		s.dock.select(outside);
		CHECK(errors.contains("not in the edited scene"));
		delete outside;
	}
	CHECK(s.dock.get_selected() == s.main);
	REQUIRE(s.undo_redo.undo());
	CHECK(calls > after_add + 1); // Undo of the dock's action reports a change.
	s.dock.select(nullptr);
	CHECK(s.dock.get_selected() == nullptr);

	// A new scene clears the selection and the history.
	s.dock.select(s.main);
	s.dock.set_edited_scene(nullptr);
	CHECK(s.dock.get_selected() == nullptr);
	CHECK(s.undo_redo.get_history_count() == 0);
	{
		ErrorCatcher errors;
		CHECK(s.dock.add_node("Node", nullptr) == nullptr);
		CHECK(errors.contains("no edited scene"));
	}
}

TEST_CASE("[SceneTreeDock] Undo after the dock is gone still moves the nodes") {
	DockScene s;
	Node *a = nullptr;
	{
		SceneTreeDock dock;
		dock.set_undo_redo(&s.undo_redo);
		dock.set_edited_scene(s.main);
		a = dock.add_node("DockTestNode", nullptr);
		REQUIRE(a != nullptr);
	}
	REQUIRE(s.undo_redo.undo());
	CHECK(a->get_parent() == nullptr);
	REQUIRE(s.undo_redo.redo());
	CHECK(a->get_parent() == s.main);
}

} // namespace TestSceneTreeDock
