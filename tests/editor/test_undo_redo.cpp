/**************************************************************************/
/*  test_undo_redo.cpp                                                    */
/**************************************************************************/
/* UndoRedo: do/undo/redo order, bound methods and properties, history    */
/* truncation by a new action after an undo, nesting, misuse messages.    */

#include "core/object/undo_redo.h"

#include "scene/3d/node_3d.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

namespace TestUndoRedo {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

TEST_CASE("[UndoRedo] do runs in order on commit, undo in reverse, redo in order again") {
	UndoRedo ur;
	std::vector<String> log;
	ur.create_action("Two Steps");
	ur.add_do_method([&]() { log.push_back("do1"); });
	ur.add_do_method([&]() { log.push_back("do2"); });
	ur.add_undo_method([&]() { log.push_back("undo1"); });
	ur.add_undo_method([&]() { log.push_back("undo2"); });
	CHECK(log.empty());
	REQUIRE(ur.commit_action());
	const std::vector<String> done = { "do1", "do2" };
	const std::vector<String> undone = { "undo2", "undo1" };
	CHECK(log == done);
	CHECK(ur.has_undo());
	CHECK_FALSE(ur.has_redo());
	CHECK(ur.get_current_action_name() == "Two Steps");

	log.clear();
	CHECK(ur.undo());
	CHECK_MESSAGE(log == undone, "undo operations run last-added first");
	CHECK_FALSE(ur.has_undo());
	CHECK(ur.has_redo());
	CHECK(ur.get_current_action_name().empty());
	CHECK_FALSE(ur.undo());

	log.clear();
	CHECK(ur.redo());
	CHECK(log == done);
	CHECK_FALSE(ur.redo());
}

TEST_CASE("[UndoRedo] commit without execute does not run the do operations") {
	UndoRedo ur;
	int value = 0;
	ur.create_action("Set");
	ur.add_do_method([&]() { value = 5; });
	ur.add_undo_method([&]() { value = 1; });
	ur.commit_action(false);
	CHECK(value == 0);
	ur.undo();
	CHECK(value == 1);
	ur.redo();
	CHECK(value == 5);
}

TEST_CASE("[UndoRedo] bound methods and properties on an Object") {
	DummyServer server;
	Node3D *node = new Node3D;
	UndoRedo ur;

	SUBCASE("methods") {
		ur.create_action("Move");
		ur.add_do_method(node, "set_position", { Vector3(1, 2, 3) });
		ur.add_undo_method(node, "set_position", { node->get_position() });
		ur.commit_action();
		CHECK(node->get_position().is_equal_approx(Vector3(1, 2, 3)));
		ur.undo();
		CHECK(node->get_position().is_equal_approx(Vector3(0, 0, 0)));
		ur.redo();
		CHECK(node->get_position().is_equal_approx(Vector3(1, 2, 3)));
	}
	SUBCASE("properties") {
		ur.create_action("Scale");
		ur.add_do_property(node, "scale", Vector3(2, 2, 2));
		ur.add_undo_property(node, "scale", node->get_scale());
		ur.commit_action();
		CHECK(node->get_scale().is_equal_approx(Vector3(2, 2, 2)));
		ur.undo();
		CHECK(node->get_scale().is_equal_approx(Vector3(1, 1, 1)));
	}
	ur.clear_history();
	delete node;
}

TEST_CASE("[UndoRedo] a new action after an undo clears the redo history") {
	UndoRedo ur;
	int value = 0;
	for (int i = 1; i <= 3; i++) {
		const int old = value;
		ur.create_action(vformat("Set %d", i));
		ur.add_do_method([&value, i]() { value = i; });
		ur.add_undo_method([&value, old]() { value = old; });
		ur.commit_action();
	}
	CHECK(value == 3);
	CHECK(ur.get_history_count() == 3);
	ur.undo();
	ur.undo();
	CHECK(value == 1);
	CHECK(ur.has_redo());

	ur.create_action("Set 10");
	ur.add_do_method([&value]() { value = 10; });
	ur.add_undo_method([&value]() { value = 1; });
	ur.commit_action();
	CHECK(value == 10);
	CHECK_MESSAGE(!ur.has_redo(), "the undone actions are gone once a new action is committed");
	CHECK(ur.get_history_count() == 2);
	CHECK(ur.get_action_name(0) == "Set 1");
	CHECK(ur.get_action_name(1) == "Set 10");
	ur.undo();
	CHECK(value == 1);
	ur.undo();
	CHECK(value == 0);
	CHECK_FALSE(ur.undo());
}

TEST_CASE("[UndoRedo] nested create_action joins the outer action") {
	UndoRedo ur;
	int a = 0, b = 0;
	ur.create_action("Outer");
	ur.add_do_method([&]() { a = 1; });
	ur.add_undo_method([&]() { a = 0; });
	ur.create_action("Inner");
	ur.add_do_method([&]() { b = 1; });
	ur.add_undo_method([&]() { b = 0; });
	ur.commit_action();
	CHECK(a == 0); // Nothing runs until the outer commit.
	ur.commit_action();
	CHECK(a == 1);
	CHECK(b == 1);
	CHECK(ur.get_history_count() == 1);
	CHECK(ur.get_current_action_name() == "Outer");
	ur.undo();
	CHECK(a == 0);
	CHECK(b == 0);
}

TEST_CASE("[UndoRedo] misuse is reported, not fatal") {
	ErrorCatcher errors;
	UndoRedo ur;
	CHECK_FALSE(ur.commit_action());
	CHECK(errors.contains("no action is open"));
	ur.add_do_method([]() {});
	CHECK(ur.get_history_count() == 0);
	ur.create_action("Open");
	CHECK_FALSE(ur.undo());
	CHECK(errors.contains("still open"));
	ur.add_do_method(nullptr, "set_position", {});
	CHECK(errors.contains("is null"));
	ur.commit_action();
	CHECK(ur.get_history_count() == 1);
	const uint64_t v = ur.get_version();
	ur.clear_history();
	CHECK(ur.get_history_count() == 0);
	CHECK(ur.get_version() > v);
}

} // namespace TestUndoRedo
