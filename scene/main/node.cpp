/**************************************************************************/
/*  node.cpp                                                              */
/**************************************************************************/

#include "scene/main/node.h"

#include "core/error/error_macros.h"
#include "scene/main/scene_tree.h"

#include <cstdio>

const char *Node::INVALID_NAME_CHARACTERS = ".:@/\"%";

void Node::set_name(const String &p_name) {
	String fixed = p_name;
	for (char &c : fixed) {
		for (const char *bad = INVALID_NAME_CHARACTERS; *bad; bad++) {
			if (c == *bad) {
				c = '_';
			}
		}
	}
	if (fixed != p_name) {
		WARN_PRINT(vformat("Node name \"%s\" contains one of the characters %s; they were replaced by '_'.", p_name.c_str(), INVALID_NAME_CHARACTERS));
	}
	if (parent) {
		fixed = parent->_validate_child_name(fixed, this);
		parent->children_by_name.erase(name);
		parent->children_by_name[fixed] = this;
	}
	name = fixed;
}

String Node::_validate_child_name(const String &p_name, const Node *p_child) const {
	String base = p_name.empty() ? p_child->get_class() : p_name;
	String candidate = base;
	int number = 2;
	while (true) {
		auto it = children_by_name.find(candidate);
		if (it == children_by_name.end() || it->second == p_child) {
			return candidate;
		}
		candidate = base + itos(number++);
	}
}

void Node::add_child(Node *p_child) {
	ERR_FAIL_NULL_MSG(p_child, "Cannot add a null child node.");
	ERR_FAIL_COND_MSG(p_child == this, vformat("Cannot add node \"%s\" as a child of itself.", name.c_str()));
	ERR_FAIL_COND_MSG(p_child->parent != nullptr, vformat("Cannot add node \"%s\" to \"%s\": it already has a parent (\"%s\"); call remove_child() there first.", p_child->name.c_str(), name.c_str(), p_child->parent->name.c_str()));
	ERR_FAIL_COND_MSG(p_child->is_ancestor_of(this), vformat("Cannot add node \"%s\" to \"%s\": it is an ancestor of that node.", p_child->name.c_str(), name.c_str()));
	ERR_FAIL_COND_MSG(p_child->tree != nullptr, vformat("Cannot add node \"%s\": it is the root of a SceneTree.", p_child->name.c_str()));

	p_child->name = _validate_child_name(p_child->name, p_child);
	p_child->parent = this;
	children.push_back(p_child);
	children_by_name[p_child->name] = p_child;
	p_child->notification(NOTIFICATION_PARENTED);
	if (tree) {
		p_child->_propagate_enter_tree(tree);
		p_child->_propagate_ready();
	}
}

void Node::remove_child(Node *p_child) {
	ERR_FAIL_NULL_MSG(p_child, "Cannot remove a null child node.");
	ERR_FAIL_COND_MSG(p_child->parent != this, vformat("Cannot remove node \"%s\" from \"%s\": it is not a child of that node.", p_child->name.c_str(), name.c_str()));
	if (p_child->tree) {
		p_child->_propagate_exit_tree();
	}
	for (size_t i = 0; i < children.size(); i++) {
		if (children[i] == p_child) {
			children.erase(children.begin() + i);
			break;
		}
	}
	children_by_name.erase(p_child->name);
	p_child->parent = nullptr;
	p_child->notification(NOTIFICATION_UNPARENTED);
}

void Node::move_child(Node *p_child, int p_to_index) {
	ERR_FAIL_NULL_MSG(p_child, "Cannot move a null child node.");
	ERR_FAIL_COND_MSG(p_child->parent != this, vformat("Cannot move node \"%s\" within \"%s\": it is not a child of that node.", p_child->name.c_str(), name.c_str()));
	int count = (int)children.size();
	int to = p_to_index < 0 ? p_to_index + count : p_to_index;
	ERR_FAIL_INDEX_MSG(to, count, vformat("Cannot move node \"%s\" to index %d: \"%s\" has %d children.", p_child->name.c_str(), p_to_index, name.c_str(), count));
	int from = p_child->get_index();
	children.erase(children.begin() + from);
	children.insert(children.begin() + to, p_child);
}

Node *Node::get_child(int p_index) const {
	int count = (int)children.size();
	int index = p_index < 0 ? p_index + count : p_index;
	ERR_FAIL_INDEX_V_MSG(index, count, nullptr, vformat("Child index %d is out of range for node \"%s\" (%d children).", p_index, name.c_str(), count));
	return children[index];
}

int Node::get_index() const {
	if (!parent) {
		return -1;
	}
	for (size_t i = 0; i < parent->children.size(); i++) {
		if (parent->children[i] == this) {
			return (int)i;
		}
	}
	return -1;
}

bool Node::is_ancestor_of(const Node *p_node) const {
	ERR_FAIL_NULL_V(p_node, false);
	for (const Node *p = p_node->parent; p; p = p->parent) {
		if (p == this) {
			return true;
		}
	}
	return false;
}

Node *Node::get_node_or_null(const String &p_path) const {
	const Node *current = this;
	String path = p_path;
	if (!path.empty() && path[0] == '/') {
		// Absolute: start above the topmost ancestor, whose name must be the first element.
		const Node *top = this;
		while (top->parent) {
			top = top->parent;
		}
		std::vector<String> parts = string_split(path.substr(1), '/', false);
		if (parts.empty() || parts[0] != top->name) {
			return nullptr;
		}
		current = top;
		path = path.substr(1 + parts[0].size());
	}
	for (const String &part : string_split(path, '/', false)) {
		if (part == ".") {
			continue;
		}
		if (part == "..") {
			current = current->parent;
			if (!current) {
				return nullptr;
			}
			continue;
		}
		const Node *next = nullptr;
		for (const Node *c : current->children) {
			if (c->name == part) {
				next = c;
				break;
			}
		}
		if (!next) {
			return nullptr;
		}
		current = next;
	}
	return const_cast<Node *>(current);
}

Node *Node::get_node(const String &p_path) const {
	Node *node = get_node_or_null(p_path);
	ERR_FAIL_NULL_V_MSG(node, nullptr, vformat("Node not found: \"%s\" (relative to \"%s\").", p_path.c_str(), get_path().c_str()));
	return node;
}

String Node::get_path() const {
	String path;
	for (const Node *n = this; n; n = n->parent) {
		path = n->parent ? "/" + n->name + path : n->name + path;
	}
	return tree ? "/" + path : path;
}

String Node::get_tree_string() const {
	String out;
	std::vector<std::pair<const Node *, int>> stack = { { this, 0 } };
	while (!stack.empty()) {
		std::pair<const Node *, int> item = stack.back();
		stack.pop_back();
		out += String(item.second * 2, ' ') + item.first->name + " (" + item.first->get_class() + ")\n";
		for (int i = (int)item.first->children.size() - 1; i >= 0; i--) {
			stack.push_back({ item.first->children[i], item.second + 1 });
		}
	}
	return out;
}

void Node::print_tree() const {
	printf("%s", get_tree_string().c_str());
}

void Node::_propagate_enter_tree(SceneTree *p_tree) {
	tree = p_tree;
	notification(NOTIFICATION_ENTER_TREE);
	// Copy: a handler may add children (they enter through add_child then).
	std::vector<Node *> list = children;
	for (Node *c : list) {
		if (c->parent == this && c->tree == nullptr) {
			c->_propagate_enter_tree(p_tree);
		}
	}
}

void Node::_propagate_ready() {
	std::vector<Node *> list = children;
	for (Node *c : list) {
		if (c->parent == this) {
			c->_propagate_ready();
		}
	}
	if (!ready_done && tree) {
		ready_done = true;
		notification(NOTIFICATION_READY);
	}
}

void Node::_propagate_exit_tree() {
	std::vector<Node *> list = children;
	for (int i = (int)list.size() - 1; i >= 0; i--) {
		if (list[i]->parent == this && list[i]->tree) {
			list[i]->_propagate_exit_tree();
		}
	}
	notification(NOTIFICATION_EXIT_TREE, true);
	tree = nullptr;
}

void Node::_set_tree_root(SceneTree *p_tree) {
	ERR_FAIL_COND_MSG(parent != nullptr, "A node with a parent cannot be a tree root.");
	_propagate_enter_tree(p_tree);
	_propagate_ready();
}

void Node::_unset_tree_root() {
	if (tree) {
		_propagate_exit_tree();
	}
}

void Node::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_name", "name"), &Node::set_name);
	ClassDB::bind_method(D_METHOD("get_name"), &Node::get_name);
	ClassDB::bind_method(D_METHOD("add_child", "node"), &Node::add_child);
	ClassDB::bind_method(D_METHOD("remove_child", "node"), &Node::remove_child);
	ClassDB::bind_method(D_METHOD("move_child", "child_node", "to_index"), &Node::move_child);
	ClassDB::bind_method(D_METHOD("get_child_count"), &Node::get_child_count);
	ClassDB::bind_method(D_METHOD("get_child", "idx"), &Node::get_child);
	ClassDB::bind_method(D_METHOD("get_parent"), &Node::get_parent);
	ClassDB::bind_method(D_METHOD("get_node", "path"), &Node::get_node);
	ClassDB::bind_method(D_METHOD("get_node_or_null", "path"), &Node::get_node_or_null);
	ClassDB::bind_method(D_METHOD("has_node", "path"), &Node::has_node);
	ClassDB::bind_method(D_METHOD("is_inside_tree"), &Node::is_inside_tree);

	// Godot saves the name in the [node name="..."] header, not as a property; it is bound
	// (without storage) so scripts and tools can read it.
	ADD_PROPERTY(PropertyInfo(Variant::STRING, "name", PROPERTY_HINT_NONE, "", PROPERTY_USAGE_NONE), "set_name", "get_name");

	BIND_CONSTANT(NOTIFICATION_ENTER_TREE);
	BIND_CONSTANT(NOTIFICATION_EXIT_TREE);
	BIND_CONSTANT(NOTIFICATION_READY);
	BIND_CONSTANT(NOTIFICATION_PARENTED);
	BIND_CONSTANT(NOTIFICATION_UNPARENTED);
}

Node::Node() {}

Node::~Node() {
	// Derived destructors have already run, so only the children (still whole) can be
	// told that they leave the tree.
	std::vector<Node *> list = children;
	if (tree) {
		for (int i = (int)list.size() - 1; i >= 0; i--) {
			if (list[i]->tree) {
				list[i]->_propagate_exit_tree();
			}
		}
	}
	children.clear();
	children_by_name.clear();
	for (Node *c : list) {
		c->parent = nullptr;
		delete c;
	}
	if (parent) {
		std::vector<Node *> &siblings = parent->children;
		for (size_t i = 0; i < siblings.size(); i++) {
			if (siblings[i] == this) {
				siblings.erase(siblings.begin() + i);
				break;
			}
		}
		parent->children_by_name.erase(name);
		parent = nullptr;
	}
}
