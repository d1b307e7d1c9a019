/**************************************************************************/
/*  godot_area_object.cpp                                                 */
/**************************************************************************/
/* godot-area: engine objects and nodes in Python. Property access goes   */
/* through ClassDB (Object::try_set / Object::get) only, so every bound   */
/* property of every class is reachable by name or as an attribute.      */
/* Errors become exceptions carrying the engine's message:                */
/*   unknown property -> AttributeError, wrong type -> TypeError,         */
/*   value rejected by the setter -> ValueError.                          */

#include "modules/python/godot_area_bindings.h"

#include "modules/python/python_session.h"
#include "scene/main/node.h"

#include <algorithm>
#include <unordered_map>

namespace godot_area_py {

namespace {

// Object* -> its Python wrapper (borrowed: the wrapper removes itself when it dies).
std::unordered_map<Object *, PyObject *> wrapper_registry;

EngineObject *_wrapper_of(PyObject *p_object) {
	return py::handle(p_object).cast<EngineObject *>();
}

void _warn(const std::vector<String> &p_warnings) {
	for (const String &w : p_warnings) {
		PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 2);
	}
}

bool _find_property_info(Object *p_object, const String &p_name, PropertyInfo &r_info) {
	if (ClassDB::get_property_info(p_object->get_class(), p_name, &r_info)) {
		return true;
	}
	std::vector<PropertyInfo> list;
	p_object->get_property_list(&list);
	for (const PropertyInfo &pi : list) {
		if (pi.name == p_name && !pi.is_group_marker()) {
			r_info = pi;
			return true;
		}
	}
	return false;
}

void _set_property(EngineObject &p_self, const String &p_name, py::handle p_value) {
	Object *object = p_self.get_checked();
	PropertyInfo info;
	const bool listed = _find_property_info(object, p_name, info) || object->has_property(p_name);
	Variant value;
	try {
		value = python_to_variant(p_value, info.type);
	} catch (const py::type_error &e) {
		if (!listed) {
			// An unknown name is the first problem to report (_set may still take unlisted names).
			throw py::attribute_error(vformat("Invalid property '%s' on class '%s': no such property.", p_name.c_str(), object->get_class().c_str()));
		}
		throw py::type_error(vformat("Cannot set property '%s' of class '%s': %s", p_name.c_str(), object->get_class().c_str(), e.what()));
	}
	String error;
	ErrorCapture capture;
	if (!object->try_set(p_name, value, &error)) {
		if (!object->has_property(p_name)) {
			throw py::attribute_error(error);
		}
		throw py::type_error(error);
	}
	if (!capture.errors.empty()) {
		throw py::value_error(capture.joined());
	}
	_warn(capture.warnings);
}

py::object _get_property(EngineObject &p_self, const String &p_name) {
	Object *object = p_self.get_checked();
	bool valid = false;
	Variant value;
	{
		ErrorCapture capture;
		value = object->get(p_name, &valid);
		if (!valid) {
			throw py::attribute_error(capture.errors.empty() ? vformat("Invalid property '%s' on class '%s'.", p_name.c_str(), object->get_class().c_str()) : capture.joined());
		}
	}
	return variant_to_python(value);
}

py::list _property_list(const std::vector<PropertyInfo> &p_list) {
	py::list out;
	for (const PropertyInfo &pi : p_list) {
		out.append(property_info_to_dict(pi));
	}
	return out;
}

String _repr(const EngineObject &p_self) {
	if (!p_self.object) {
		return "<freed engine object>";
	}
	const Node *node = dynamic_cast<const Node *>(p_self.object);
	if (node) {
		return vformat("<%s '%s'%s>", node->get_class().c_str(), node->get_name().c_str(), node->is_inside_tree() ? (" at " + node->get_path()).c_str() : " (not in the tree)");
	}
	return vformat("<%s>", p_self.object->get_class().c_str());
}

EngineNode &_as_node(py::handle p_value, const char *p_what) {
	if (!py::isinstance<EngineNode>(p_value)) {
		throw py::type_error(vformat("%s must be a Node, got %s.", p_what, python_type_name(p_value).c_str()));
	}
	return *p_value.cast<EngineNode *>();
}

void _free_node(Node *p_node) {
	if (p_node->get_parent()) {
		p_node->get_parent()->remove_child(p_node);
	}
	invalidate_subtree(p_node);
	delete p_node;
}

} // namespace

Object *EngineObject::get_checked() const {
	if (!object) {
		throw std::runtime_error("This engine object was freed (by free(), by its parent, or at engine shutdown).");
	}
	return object;
}

EngineObject::~EngineObject() {
	if (!object) {
		return;
	}
	wrapper_registry.erase(object);
	if (ref.is_valid()) {
		ref.unref();
		return;
	}
	Node *node = dynamic_cast<Node *>(object);
	if (node) {
		// Python owns orphan nodes (made by create(), load_scene() or remove_child()).
		if (!node->get_parent() && !node->is_inside_tree() && PythonSession::is_active()) {
			invalidate_subtree(node);
			delete node;
		}
	} else if (owns_object && PythonSession::is_active()) {
		delete object;
	}
	object = nullptr;
}

Node *EngineNode::get_node_checked() const {
	return static_cast<Node *>(get_checked());
}

py::object wrap_object(Object *p_object, bool p_owns) {
	if (!p_object) {
		return py::none();
	}
	auto it = wrapper_registry.find(p_object);
	if (it != wrapper_registry.end()) {
		return py::reinterpret_borrow<py::object>(it->second);
	}
	bool is_node = dynamic_cast<Node *>(p_object) != nullptr;
	EngineObject *wrapper = is_node ? new EngineNode : new EngineObject;
	wrapper->object = p_object;
	if (p_object->is_ref_counted()) {
		wrapper->ref = Ref<RefCounted>(static_cast<RefCounted *>(p_object));
	} else if (!is_node) {
		wrapper->owns_object = p_owns;
	}
	py::object result = py::cast(wrapper, py::return_value_policy::take_ownership);
	wrapper_registry[p_object] = result.ptr();
	return result;
}

void invalidate_subtree(Node *p_node) {
	auto it = wrapper_registry.find(p_node);
	if (it != wrapper_registry.end()) {
		EngineObject *wrapper = _wrapper_of(it->second);
		wrapper->object = nullptr;
		wrapper_registry.erase(it);
	}
	for (int i = 0; i < p_node->get_child_count(); i++) {
		invalidate_subtree(p_node->get_child(i));
	}
}

void release_all_wrappers() {
	std::vector<Node *> orphan_roots;
	std::vector<Object *> owned;
	std::vector<EngineObject *> wrappers;
	for (auto &entry : wrapper_registry) {
		EngineObject *wrapper = _wrapper_of(entry.second);
		wrappers.push_back(wrapper);
		Node *node = dynamic_cast<Node *>(entry.first);
		if (node) {
			Node *top = node;
			while (top->get_parent()) {
				top = top->get_parent();
			}
			if (!top->is_inside_tree() && std::find(orphan_roots.begin(), orphan_roots.end(), top) == orphan_roots.end()) {
				orphan_roots.push_back(top);
			}
		} else if (wrapper->owns_object) {
			owned.push_back(entry.first);
		}
	}
	wrapper_registry.clear();
	for (EngineObject *wrapper : wrappers) {
		wrapper->object = nullptr;
	}
	for (Node *root : orphan_roots) {
		delete root;
	}
	for (Object *object : owned) {
		delete object;
	}
	for (EngineObject *wrapper : wrappers) {
		wrapper->ref.unref();
	}
}

ErrorCapture::ErrorCapture() {
	handler.callback = [this](ErrorHandlerType p_type, const String &p_text) {
		(p_type == ERR_HANDLER_WARNING ? warnings : errors).push_back(p_text);
	};
	add_error_handler(&handler);
	set_error_print_silenced(true);
}

ErrorCapture::~ErrorCapture() {
	set_error_print_silenced(false);
	remove_error_handler(&handler);
}

String ErrorCapture::joined() const {
	String out;
	for (const String &e : errors) {
		out += (out.empty() ? "" : "\n") + e;
	}
	return out;
}

py::dict property_info_to_dict(const PropertyInfo &p_info) {
	py::dict d;
	d["name"] = p_info.name;
	d["type"] = int(p_info.type);
	d["type_name"] = Variant::get_type_name(p_info.type);
	d["class_name"] = p_info.class_name;
	d["hint"] = int(p_info.hint);
	d["hint_string"] = p_info.hint_string;
	d["usage"] = p_info.usage;
	return d;
}

void bind_objects(py::module_ &m) {
	py::class_<EngineObject>(m, "Object", "An engine object. Its ClassDB properties read and write as attributes or with get()/set().")
			.def("get_class", [](EngineObject &self) { return self.get_checked()->get_class(); })
			.def("is_class", [](EngineObject &self, const String &p_class) { return self.get_checked()->is_class(p_class); })
			.def("is_valid", [](EngineObject &self) { return self.object != nullptr; }, "False once the engine freed the object.")
			.def("get", &_get_property, py::arg("property"), "Reads a property by name (AttributeError for unknown names).")
			.def("set", &_set_property, py::arg("property"), py::arg("value"), "Writes a property by name (AttributeError, TypeError or ValueError with the engine's message).")
			.def("has_property", [](EngineObject &self, const String &p_name) { return self.get_checked()->has_property(p_name); })
			.def("get_property_list", [](EngineObject &self) {
				std::vector<PropertyInfo> list;
				self.get_checked()->get_property_list(&list);
				return _property_list(list);
			}, "Dicts with name, type, type_name, class_name, hint, hint_string, usage (group markers included, flagged in usage).")
			.def("has_method", [](EngineObject &self, const String &p_name) { return self.get_checked()->has_method(p_name); })
			.def("call", [](EngineObject &self, const String &p_method, py::args p_args) {
				Object *object = self.get_checked();
				std::vector<Variant> args;
				for (py::handle a : p_args) {
					args.push_back(python_to_variant(a));
				}
				bool valid = false;
				Variant ret;
				{
					ErrorCapture capture;
					ret = object->call(p_method, args, &valid);
					if (!valid) {
						if (!object->has_method(p_method)) {
							throw py::attribute_error(capture.joined());
						}
						throw py::type_error(capture.joined());
					}
					if (!capture.errors.empty()) {
						throw py::value_error(capture.joined());
					}
				}
				return variant_to_python(ret);
			}, py::arg("method"), "Calls a bound method by name.")
			.def("__getattr__", [](EngineObject &self, const String &p_name) -> py::object {
				if (p_name.size() > 4 && p_name.compare(0, 2, "__") == 0) {
					throw py::attribute_error(p_name);
				}
				return _get_property(self, p_name);
			})
			.def("__setattr__", [](EngineObject &self, const String &p_name, py::object p_value) { _set_property(self, p_name, p_value); })
			.def("__dir__", [](py::object self) {
				py::list names = py::module_::import("builtins").attr("object").attr("__dir__")(self);
				EngineObject *wrapper = self.cast<EngineObject *>();
				if (wrapper->object) {
					std::vector<PropertyInfo> list;
					wrapper->object->get_property_list(&list);
					for (const PropertyInfo &pi : list) {
						if (!pi.is_group_marker()) {
							names.append(py::str(pi.name));
						}
					}
				}
				return names;
			})
			.def("__repr__", &_repr);

	py::class_<EngineNode, EngineObject>(m, "Node", "A scene node. Orphan nodes belong to Python; a parent or the tree owns the others.")
			.def("get_node", [](EngineNode &self, const String &p_path) {
				Node *found = self.get_node_checked()->get_node_or_null(p_path);
				if (!found) {
					throw py::key_error(vformat("Node not found: '%s' (relative to %s).", p_path.c_str(), _repr(self).c_str()));
				}
				return wrap_object(found);
			}, py::arg("path"), "Finds a node by relative path ('A/B', '..') or absolute path ('/root/...'); KeyError if missing.")
			.def("get_node_or_null", [](EngineNode &self, const String &p_path) { return wrap_object(self.get_node_checked()->get_node_or_null(p_path)); }, py::arg("path"))
			.def("has_node", [](EngineNode &self, const String &p_path) { return self.get_node_checked()->has_node(p_path); }, py::arg("path"))
			.def("add_child", [](EngineNode &self, py::object p_child) {
				Node *parent = self.get_node_checked();
				Node *child = _as_node(p_child, "child").get_node_checked();
				ErrorCapture capture;
				parent->add_child(child);
				if (child->get_parent() != parent) {
					throw py::value_error(capture.errors.empty() ? String("add_child() failed.") : capture.joined());
				}
				return p_child;
			}, py::arg("child"), "Adds (and gives ownership of) an orphan node; returns it.")
			.def("remove_child", [](EngineNode &self, py::object p_child) {
				Node *parent = self.get_node_checked();
				Node *child = _as_node(p_child, "child").get_node_checked();
				if (child->get_parent() != parent) {
					throw py::value_error(vformat("%s is not a child of %s.", _repr(*p_child.cast<EngineNode *>()).c_str(), _repr(self).c_str()));
				}
				parent->remove_child(child);
				return p_child;
			}, py::arg("child"), "Removes a child; Python owns it afterwards.")
			.def("get_children", [](EngineNode &self) {
				Node *node = self.get_node_checked();
				py::list out;
				for (int i = 0; i < node->get_child_count(); i++) {
					out.append(wrap_object(node->get_child(i)));
				}
				return out;
			})
			.def("get_child_count", [](EngineNode &self) { return self.get_node_checked()->get_child_count(); })
			.def("get_parent", [](EngineNode &self) { return wrap_object(self.get_node_checked()->get_parent()); })
			.def("get_path", [](EngineNode &self) { return self.get_node_checked()->get_path(); })
			.def("is_inside_tree", [](EngineNode &self) { return self.get_node_checked()->is_inside_tree(); })
			.def("get_tree_string", [](EngineNode &self) { return self.get_node_checked()->get_tree_string(); })
			.def("free", [](EngineNode &self) {
				Node *node = self.get_node_checked();
				if (node->is_inside_tree() && !node->get_parent()) {
					throw py::value_error("The tree's root node cannot be freed.");
				}
				_free_node(node);
			}, "Deletes the node and its subtree now; their wrappers become invalid.");
}

} // namespace godot_area_py
