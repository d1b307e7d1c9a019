/**************************************************************************/
/*  scene_tree_dock.cpp                                                   */
/**************************************************************************/
/* godot-area: SceneTreeDock (see scene_tree_dock.h).                     */

#include "editor/scene_tree_dock.h"

#include "core/error/error_macros.h"
#include "core/object/class_db.h"
#include "core/object/undo_redo.h"
#include "scene/3d/node_3d.h"
#include "scene/main/node.h"

namespace {

// A node that is out of the scene belongs to the action that took it out. The do and undo
// operations of that action share one holder; when the action leaves the history the holder
// goes, and deletes the node if it is still out.
struct DetachedNode {
	Node *node = nullptr;
	bool owned = false;
	~DetachedNode() {
		if (owned) {
			delete node;
		}
	}
};

} // namespace

void SceneTreeDock::_changed() {
	version++;
	if (changed_callback) {
		changed_callback();
	}
}

bool SceneTreeDock::_is_in_scene(const Node *p_node) const {
	return p_node && edited_scene && (p_node == edited_scene || edited_scene->is_ancestor_of(p_node));
}

void SceneTreeDock::_unselect_subtree(const Node *p_node) {
	if (selected && (selected == p_node || p_node->is_ancestor_of(selected))) {
		selected = nullptr;
	}
}

void SceneTreeDock::set_edited_scene(Node *p_root) {
	if (undo_redo) {
		// Actions name nodes of the old scene; nodes they hold out of it are deleted here.
		undo_redo->clear_history();
	}
	edited_scene = p_root;
	selected = nullptr;
	_changed();
}

void SceneTreeDock::select(Node *p_node) {
	if (p_node) {
		ERR_FAIL_COND_MSG(!_is_in_scene(p_node), vformat("SceneTreeDock: cannot select node \"%s\": it is not in the edited scene.", p_node->get_name().c_str()));
	}
	if (selected == p_node) {
		return;
	}
	selected = p_node;
	_changed();
}

Node *SceneTreeDock::add_node(const String &p_class_name, Node *p_parent) {
	ERR_FAIL_NULL_V_MSG(edited_scene, nullptr, vformat("SceneTreeDock: cannot add a %s: there is no edited scene.", p_class_name.c_str()));
	Node *parent = p_parent ? p_parent : edited_scene;
	ERR_FAIL_COND_V_MSG(!_is_in_scene(parent), nullptr, vformat("SceneTreeDock: cannot add a %s under \"%s\": that node is not in the edited scene.", p_class_name.c_str(), parent->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(!ClassDB::class_exists(p_class_name), nullptr, vformat("SceneTreeDock: cannot add a node of class \"%s\": there is no such class.", p_class_name.c_str()));
	ERR_FAIL_COND_V_MSG(!ClassDB::is_parent_class(p_class_name, "Node"), nullptr, vformat("SceneTreeDock: cannot add a node of class \"%s\": it is not a Node (it derives from %s).", p_class_name.c_str(), ClassDB::get_parent_class(p_class_name).c_str()));
	ERR_FAIL_COND_V_MSG(!ClassDB::can_instantiate(p_class_name), nullptr, vformat("SceneTreeDock: cannot add a node of class \"%s\": the class is abstract.", p_class_name.c_str()));
	Object *object = ClassDB::instantiate(p_class_name);
	Node *node = Object::cast_to<Node>(object);
	if (!node) {
		delete object;
		ERR_FAIL_V_MSG(nullptr, vformat("SceneTreeDock: instantiating \"%s\" did not give a Node.", p_class_name.c_str()));
	}
	// The empty name becomes the class name, numbered when a sibling has it ("AreaLight3D2").
	std::shared_ptr<DetachedNode> holder = std::make_shared<DetachedNode>();
	holder->node = node;
	holder->owned = true;
	std::shared_ptr<SceneTreeDock *> link = self_link;

	auto do_add = [holder, parent, link]() {
		parent->add_child(holder->node);
		holder->owned = holder->node->get_parent() != parent;
		if (*link) {
			(*link)->selected = holder->node;
			(*link)->_changed();
		}
	};
	auto undo_add = [holder, parent, link]() {
		if (*link) {
			(*link)->_unselect_subtree(holder->node);
		}
		if (holder->node->get_parent() == parent) {
			parent->remove_child(holder->node);
			holder->owned = true;
		}
		if (*link) {
			(*link)->_changed();
		}
	};
	if (!undo_redo) {
		do_add();
		holder->owned = false;
		return node;
	}
	undo_redo->create_action("Add Node");
	undo_redo->add_do_method(do_add);
	undo_redo->add_undo_method(undo_add);
	undo_redo->commit_action(true);
	return node;
}

bool SceneTreeDock::delete_node(Node *p_node) {
	ERR_FAIL_NULL_V_MSG(p_node, false, "SceneTreeDock: cannot delete a null node.");
	ERR_FAIL_COND_V_MSG(!_is_in_scene(p_node), false, vformat("SceneTreeDock: cannot delete node \"%s\": it is not in the edited scene.", p_node->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(p_node == edited_scene, false, vformat("SceneTreeDock: cannot delete \"%s\": it is the scene root.", p_node->get_name().c_str()));
	Node *parent = p_node->get_parent();
	const int index = p_node->get_index();

	if (!undo_redo) {
		_unselect_subtree(p_node);
		parent->remove_child(p_node);
		delete p_node;
		_changed();
		return true;
	}

	std::shared_ptr<DetachedNode> holder = std::make_shared<DetachedNode>();
	holder->node = p_node;
	std::shared_ptr<SceneTreeDock *> link = self_link;
	auto do_delete = [holder, parent, link]() {
		if (*link) {
			(*link)->_unselect_subtree(holder->node);
		}
		if (holder->node->get_parent() == parent) {
			parent->remove_child(holder->node);
			holder->owned = true;
		}
		if (*link) {
			(*link)->_changed();
		}
	};
	auto undo_delete = [holder, parent, index, link]() {
		parent->add_child(holder->node);
		if (holder->node->get_parent() == parent) {
			holder->owned = false;
			if (index < parent->get_child_count()) {
				parent->move_child(holder->node, index);
			}
		}
		if (*link) {
			(*link)->selected = holder->node;
			(*link)->_changed();
		}
	};
	undo_redo->create_action("Delete Node");
	undo_redo->add_do_method(do_delete);
	undo_redo->add_undo_method(undo_delete);
	undo_redo->commit_action(true);
	return true;
}

bool SceneTreeDock::reparent_node(Node *p_node, Node *p_new_parent) {
	ERR_FAIL_NULL_V_MSG(p_node, false, "SceneTreeDock: cannot reparent a null node.");
	ERR_FAIL_NULL_V_MSG(p_new_parent, false, vformat("SceneTreeDock: cannot reparent \"%s\" to a null parent.", p_node->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(!_is_in_scene(p_node), false, vformat("SceneTreeDock: cannot reparent \"%s\": it is not in the edited scene.", p_node->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(!_is_in_scene(p_new_parent), false, vformat("SceneTreeDock: cannot reparent \"%s\" to \"%s\": the new parent is not in the edited scene.", p_node->get_name().c_str(), p_new_parent->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(p_node == edited_scene, false, vformat("SceneTreeDock: cannot reparent \"%s\": it is the scene root.", p_node->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(p_new_parent == p_node, false, vformat("SceneTreeDock: cannot reparent \"%s\" to itself.", p_node->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(p_node->is_ancestor_of(p_new_parent), false, vformat("SceneTreeDock: cannot reparent \"%s\" to \"%s\": the new parent is one of its descendants.", p_node->get_name().c_str(), p_new_parent->get_name().c_str()));
	ERR_FAIL_COND_V_MSG(p_node->get_parent() == p_new_parent, false, vformat("SceneTreeDock: \"%s\" is already a child of \"%s\".", p_node->get_name().c_str(), p_new_parent->get_name().c_str()));

	Node *node = p_node;
	Node *new_parent = p_new_parent;
	Node *old_parent = p_node->get_parent();
	const int old_index = p_node->get_index();
	const String old_name = p_node->get_name();
	Node3D *node_3d = Object::cast_to<Node3D>(p_node);
	const Transform3D old_local = node_3d ? node_3d->get_transform() : Transform3D();
	const Transform3D global = node_3d ? node_3d->get_global_transform() : Transform3D();
	std::shared_ptr<SceneTreeDock *> link = self_link;

	auto do_reparent = [node, node_3d, old_parent, new_parent, global, link]() {
		old_parent->remove_child(node);
		new_parent->add_child(node);
		if (node_3d) {
			node_3d->set_global_transform(global); // As Godot's reparent(keep_global_transform = true).
		}
		if (*link) {
			(*link)->_changed();
		}
	};
	auto undo_reparent = [node, node_3d, old_parent, new_parent, old_index, old_name, old_local, link]() {
		new_parent->remove_child(node);
		node->set_name(old_name);
		old_parent->add_child(node);
		if (old_index < old_parent->get_child_count()) {
			old_parent->move_child(node, old_index);
		}
		if (node_3d) {
			node_3d->set_transform(old_local);
		}
		if (*link) {
			(*link)->_changed();
		}
	};
	if (!undo_redo) {
		do_reparent();
		return true;
	}
	undo_redo->create_action("Reparent Node");
	undo_redo->add_do_method(do_reparent);
	undo_redo->add_undo_method(undo_reparent);
	undo_redo->commit_action(true);
	return true;
}
