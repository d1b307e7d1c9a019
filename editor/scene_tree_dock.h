/**************************************************************************/
/*  scene_tree_dock.h                                                     */
/**************************************************************************/
/* godot-area: the scene tree dock's model, without a window: the edited  */
/* scene, the selection, and undoable add / delete / reparent.            */
/*                                                                        */
/* Ownership: the caller owns the scene root. A node removed by           */
/* delete_node() (or an added node whose addition was undone) is owned    */
/* by the UndoRedo history: it is deleted when the action that holds it   */
/* leaves the history (clear_history, or a new action after an undo) or   */
/* when the history is destroyed. Without an UndoRedo, a deleted node is  */
/* deleted at once.                                                        */
/*                                                                        */
/* Give the dock a new scene with set_edited_scene(); it clears the       */
/* history (actions name nodes of the old scene by pointer).              */

#pragma once

#include "core/string/ustring.h"

#include <cstdint>
#include <functional>
#include <memory>

class Node;
class UndoRedo;

class SceneTreeDock {
	Node *edited_scene = nullptr;
	UndoRedo *undo_redo = nullptr;
	Node *selected = nullptr;
	uint64_t version = 1;
	std::function<void()> changed_callback;
	// Actions in the history reach the dock through this link; the destructor clears it, so
	// undoing after the dock is gone still moves the nodes (without selection updates).
	std::shared_ptr<SceneTreeDock *> self_link = std::make_shared<SceneTreeDock *>(this);

	void _changed();
	bool _is_in_scene(const Node *p_node) const;
	// Clears the selection when it is p_node or below it.
	void _unselect_subtree(const Node *p_node);

public:
	// Not owned. Clears the selection and the undo history.
	void set_edited_scene(Node *p_root);
	Node *get_edited_scene() const { return edited_scene; }
	// Not owned; shared with the inspector and the gizmos.
	void set_undo_redo(UndoRedo *p_undo_redo) { undo_redo = p_undo_redo; }
	UndoRedo *get_undo_redo() const { return undo_redo; }

	// p_node must be the edited scene or inside it (nullptr clears the selection).
	void select(Node *p_node);
	Node *get_selected() const { return selected; }

	// Bumped by every change of the tree or the selection (including undo/redo of the dock's
	// actions); the callback, when set, runs after each change.
	uint64_t get_version() const { return version; }
	void set_changed_callback(const std::function<void()> &p_callback) { changed_callback = p_callback; }

	// Instantiates p_class_name through ClassDB and adds it under p_parent (the edited scene when
	// null) with a unique name ("AreaLight3D", "AreaLight3D2", ...), in one action "Add Node".
	// Selects the new node. nullptr with an error for an unknown, abstract or non-Node class.
	Node *add_node(const String &p_class_name, Node *p_parent = nullptr);
	// Removes p_node (not the scene root) with its children, in one action "Delete Node";
	// undo puts it back at the same index under the same parent.
	bool delete_node(Node *p_node);
	// Moves p_node under p_new_parent (not itself, not a descendant, not the root), keeping
	// its global transform when both are Node3D, in one action "Reparent Node".
	bool reparent_node(Node *p_node, Node *p_new_parent);

	SceneTreeDock() {}
	~SceneTreeDock() { *self_link = nullptr; }
	SceneTreeDock(const SceneTreeDock &) = delete;
	SceneTreeDock &operator=(const SceneTreeDock &) = delete;
};
