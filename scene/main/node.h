/**************************************************************************/
/*  node.h                                                                */
/**************************************************************************/
/* godot-area: the base of every scene node. A node owns its children     */
/* (deleting a node deletes its subtree), has a name unique among its     */
/* siblings and can be found by a relative path ("A/B", "..", ".").       */
/*                                                                        */
/* A node is "inside the tree" when its root is the root of a SceneTree   */
/* (scene/main/scene_tree.h). Entering sends NOTIFICATION_ENTER_TREE      */
/* top-down, then NOTIFICATION_READY bottom-up (once per node); leaving   */
/* sends NOTIFICATION_EXIT_TREE bottom-up. There is no notification on    */
/* plain `delete` (C++ destructors cannot reach derived classes), so      */
/* remove a node from the tree before deleting it, or let its parent or   */
/* the SceneTree delete it.                                               */

#pragma once

#include "core/object/object.h"

#include <unordered_map>
#include <vector>

class SceneTree;

class Node : public Object {
	GDCLASS(Node, Object);

	String name;
	Node *parent = nullptr;
	std::vector<Node *> children;
	// Sibling names are unique, so adding the n-th child is O(1), not O(n) (a 4,096-light scene loaded in
	// quadratic time otherwise). Kept in step with `children` and each child's name.
	std::unordered_map<String, Node *> children_by_name;
	SceneTree *tree = nullptr;
	bool ready_done = false;

	void _propagate_enter_tree(SceneTree *p_tree);
	void _propagate_ready();
	void _propagate_exit_tree();
	String _validate_child_name(const String &p_name, const Node *p_child) const;

protected:
	static void _bind_methods();

	// Only SceneTree uses this, to make its root node live.
	friend class SceneTree;
	void _set_tree_root(SceneTree *p_tree);
	void _unset_tree_root();

public:
	enum {
		// Values follow Godot's Node notifications.
		NOTIFICATION_ENTER_TREE = 10,
		NOTIFICATION_EXIT_TREE = 11,
		NOTIFICATION_READY = 13,
		NOTIFICATION_PARENTED = 18,
		NOTIFICATION_UNPARENTED = 19,
	};

	// Characters that cannot appear in a node name (they are replaced by '_').
	static const char *INVALID_NAME_CHARACTERS;

	void set_name(const String &p_name);
	String get_name() const { return name; }

	// Takes ownership of p_child. An empty name becomes the class name; a name already used by a
	// sibling gets a number appended ("Light", "Light2", ...). Fails with a message (and keeps
	// nothing) for null, self, a child that already has a parent, or an ancestor of this node.
	void add_child(Node *p_child);
	// Gives ownership back to the caller (sends EXIT_TREE first when inside the tree).
	void remove_child(Node *p_child);
	// Moves p_child to position p_to_index among its siblings (negative counts from the end).
	void move_child(Node *p_child, int p_to_index);
	int get_child_count() const { return (int)children.size(); }
	// Negative indices count from the end (-1 = last), as in Godot. Out of range: error, nullptr.
	Node *get_child(int p_index) const;
	int get_index() const;
	Node *get_parent() const { return parent; }
	bool is_ancestor_of(const Node *p_node) const;

	// Relative path of names separated by '/', with "." and ".."; an empty path is this node.
	// A path starting with '/' starts at the tree root ("/root/Main/Light").
	Node *get_node_or_null(const String &p_path) const;
	// Same, but prints an error naming the path when nothing is found.
	Node *get_node(const String &p_path) const;
	bool has_node(const String &p_path) const { return get_node_or_null(p_path) != nullptr; }
	// "/root/A/B" inside the tree; the relative path from the topmost ancestor otherwise.
	String get_path() const;

	bool is_inside_tree() const { return tree != nullptr; }
	bool is_node_ready() const { return ready_done; }
	SceneTree *get_tree() const { return tree; }

	// One line per node, indented by depth ("Name (Class)").
	String get_tree_string() const;
	void print_tree() const;

	Node();
	~Node() override;
};
