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

#include "core/object/class_db.h"

#include "modules/python/python_session.h"
#include "scene/main/node.h"

#include <algorithm>
#include <fnmatch.h>
#include <unordered_map>

namespace godot_area_py {

namespace {

// Object* -> its Python wrapper (borrowed: the wrapper removes itself when it dies).
std::unordered_map<Object *, PyObject *> wrapper_registry;
// ClassDB class name -> its generated Python class (godot_area_classes.py fills it at import).
PyObject *class_map = nullptr;

// The generated Python class of p_object's class, or of its nearest ancestor that has one.
py::object _python_class_of(const Object *p_object) {
	if (!class_map) {
		return py::object();
	}
	py::dict map = py::reinterpret_borrow<py::dict>(class_map);
	for (String name = p_object->get_class(); !name.empty(); name = ClassDB::get_parent_class(name)) {
		py::str key(name);
		if (map.contains(key)) {
			return map[key];
		}
	}
	return py::object();
}

EngineObject *_wrapper_of(PyObject *p_object) {
	return py::handle(p_object).cast<EngineObject *>();
}

void _warn(const std::vector<String> &p_warnings) {
	for (const String &w : p_warnings) {
		if (PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 2) != 0) {
			throw py::error_already_set(); // The warnings filter made it an error.
		}
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
	py::object cls = _python_class_of(p_object);
	py::object result;
	if (cls) {
		// An instance of the generated class that matches the engine class (type(light) is
		// AreaLight3D), made the way pybind11 makes one for its own classes: allocate, then
		// let the pybind11 base adopt the wrapper as its owned value.
		result = py::reinterpret_steal<py::object>(py::detail::make_new_instance((PyTypeObject *)cls.ptr()));
		py::detail::instance *inst = reinterpret_cast<py::detail::instance *>(result.ptr());
		inst->owned = true;
		py::detail::value_and_holder v_h = *py::detail::values_and_holders(inst).begin();
		v_h.value_ptr() = wrapper;
		v_h.type->init_instance(inst, nullptr);
	} else {
		result = py::cast(wrapper, py::return_value_policy::take_ownership);
	}
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

void set_class_map(py::dict p_map) {
	Py_XDECREF(class_map);
	class_map = p_map.inc_ref().ptr();
}

void on_node_deleted(Node *p_node) {
	auto it = wrapper_registry.find(p_node);
	if (it != wrapper_registry.end()) {
		_wrapper_of(it->second)->object = nullptr;
		wrapper_registry.erase(it);
	}
}

py::list class_api() {
	std::vector<String> classes;
	ClassDB::get_class_list(&classes);
	py::list out;
	for (const String &name : classes) {
		py::dict c;
		c["name"] = name;
		c["parent"] = ClassDB::get_parent_class(name);
		c["instantiable"] = ClassDB::can_instantiate(name);
		py::list methods;
		std::vector<String> method_names;
		ClassDB::get_method_list(name, &method_names, true);
		for (const String &m : method_names) {
			const MethodBind *bind = ClassDB::get_method(name, m);
			if (!bind) {
				continue;
			}
			py::dict d;
			d["name"] = m;
			py::list args;
			for (int i = 0; i < bind->get_argument_count(); i++) {
				const String arg_name = i < (int)bind->get_argument_names().size() ? bind->get_argument_names()[i] : vformat("arg%d", i);
				args.append(py::make_tuple(arg_name, Variant::get_type_name(bind->get_argument_type(i))));
			}
			d["args"] = args;
			py::list defaults;
			for (const Variant &v : bind->get_default_arguments()) {
				defaults.append(variant_to_python(v));
			}
			d["defaults"] = defaults;
			d["return_type"] = bind->has_return() ? Variant::get_type_name(bind->get_return_type()) : String("void");
			d["const"] = bind->is_const_method();
			methods.append(d);
		}
		c["methods"] = methods;
		py::list properties;
		std::vector<PropertyInfo> list;
		ClassDB::get_property_list(name, &list, true);
		for (const PropertyInfo &pi : list) {
			if (pi.is_group_marker()) {
				continue;
			}
			py::dict d = property_info_to_dict(pi);
			d["setter"] = ClassDB::get_property_setter(name, pi.name);
			d["getter"] = ClassDB::get_property_getter(name, pi.name);
			properties.append(d);
		}
		c["properties"] = properties;
		py::list constants;
		std::vector<String> constant_names;
		ClassDB::get_integer_constant_list(name, &constant_names, true);
		for (const String &k : constant_names) {
			constants.append(py::make_tuple(k, ClassDB::get_integer_constant_enum(name, k, true), ClassDB::get_integer_constant(name, k)));
		}
		c["constants"] = constants;
		out.append(c);
	}
	return out;
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
			.def(
					"is_valid", [](EngineObject &self) { return self.object != nullptr; }, "False once the engine freed the object.")
			.def("get", &_get_property, py::arg("property"), "Reads a property by name (AttributeError for unknown names).")
			.def("set", &_set_property, py::arg("property"), py::arg("value"), "Writes a property by name (AttributeError, TypeError or ValueError with the engine's message).")
			.def("has_property", [](EngineObject &self, const String &p_name) { return self.get_checked()->has_property(p_name); })
			.def(
					"get_property_list", [](EngineObject &self) {
						std::vector<PropertyInfo> list;
						self.get_checked()->get_property_list(&list);
						return _property_list(list);
					},
					"Dicts with name, type, type_name, class_name, hint, hint_string, usage (group markers included, flagged in usage).")
			.def("has_method", [](EngineObject &self, const String &p_name) { return self.get_checked()->has_method(p_name); })
			.def(
					"call", [](EngineObject &self, const String &p_method, py::args p_args) {
						Object *object = self.get_checked();
						// The bound method's argument types guide the conversion (2 -> 2.0 for a float, a
						// 3-tuple -> Color for a Color argument).
						const MethodBind *bind = ClassDB::get_method(object->get_class(), p_method);
						std::vector<Variant> args;
						int index = 0;
						for (py::handle a : p_args) {
							const Variant::Type hint = bind && index < bind->get_argument_count() ? bind->get_argument_type(index) : Variant::NIL;
							try {
								args.push_back(python_to_variant(a, hint));
							} catch (const py::type_error &e) {
								throw py::type_error(vformat("%s.%s(): argument %d ('%s'): %s", object->get_class().c_str(), p_method.c_str(), index + 1,
										bind && index < (int)bind->get_argument_names().size() ? bind->get_argument_names()[index].c_str() : "?", e.what()));
							}
							index++;
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
					},
					py::arg("method"), "Calls a bound method by name.")
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
			.def(
					"get_node", [](EngineNode &self, const String &p_path) {
						Node *found = self.get_node_checked()->get_node_or_null(p_path);
						if (!found) {
							throw py::key_error(vformat("Node not found: '%s' (relative to %s).", p_path.c_str(), _repr(self).c_str()));
						}
						return wrap_object(found);
					},
					py::arg("path"), "Finds a node by relative path ('A/B', '..') or absolute path ('/root/...'); KeyError if missing.")
			.def(
					"get_node_or_null", [](EngineNode &self, const String &p_path) { return wrap_object(self.get_node_checked()->get_node_or_null(p_path)); }, py::arg("path"))
			.def(
					"has_node", [](EngineNode &self, const String &p_path) { return self.get_node_checked()->has_node(p_path); }, py::arg("path"))
			.def(
					"add_child", [](EngineNode &self, py::object p_child) {
						Node *parent = self.get_node_checked();
						Node *child = _as_node(p_child, "child").get_node_checked();
						ErrorCapture capture;
						parent->add_child(child);
						if (child->get_parent() != parent) {
							throw py::value_error(capture.errors.empty() ? String("add_child() failed.") : capture.joined());
						}
						return p_child;
					},
					py::arg("child"), "Adds (and gives ownership of) an orphan node; returns it.")
			.def(
					"remove_child", [](EngineNode &self, py::object p_child) {
						Node *parent = self.get_node_checked();
						Node *child = _as_node(p_child, "child").get_node_checked();
						if (child->get_parent() != parent) {
							throw py::value_error(vformat("%s is not a child of %s.", _repr(*p_child.cast<EngineNode *>()).c_str(), _repr(self).c_str()));
						}
						parent->remove_child(child);
						return p_child;
					},
					py::arg("child"), "Removes a child; Python owns it afterwards.")
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
			.def(
					"get_groups", [](EngineNode &self) {
						py::list out;
						for (const String &g : self.get_node_checked()->get_groups()) {
							out.append(py::str(g));
						}
						return out;
					},
					"The node's groups, in the order they were added (add_to_group).")
			.def(
					"find_children", [](EngineNode &self, const String &p_pattern, const String &p_class, bool p_recursive) {
						py::list out;
						std::vector<Node *> stack = { self.get_node_checked() };
						while (!stack.empty()) {
							Node *node = stack.back();
							stack.pop_back();
							for (int i = node->get_child_count() - 1; i >= 0; i--) {
								Node *child = node->get_child(i);
								if ((p_class.empty() || child->is_class(p_class)) && fnmatch(p_pattern.c_str(), child->get_name().c_str(), 0) == 0) {
									out.append(wrap_object(child));
								}
								if (p_recursive) {
									stack.push_back(child);
								}
							}
						}
						return out;
					},
					py::arg("pattern") = "*", py::arg("type") = "", py::arg("recursive") = true, "Descendants whose name matches pattern (* and ?) and whose class is type or a subclass ('' for any), in tree order.")
			.def(
					"free", [](EngineNode &self) {
						Node *node = self.get_node_checked();
						if (node->is_inside_tree() && !node->get_parent()) {
							throw py::value_error("The tree's root node cannot be freed.");
						}
						_free_node(node);
					},
					"Deletes the node and its subtree now; their wrappers become invalid.");
}

} // namespace godot_area_py
