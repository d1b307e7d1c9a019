/**************************************************************************/
/*  class_db.cpp                                                          */
/**************************************************************************/

#include "core/object/class_db.h"

#include "core/error/error_macros.h"
#include "core/object/ref_counted.h"

#include <map>
#include <memory>
#include <unordered_map>

namespace {

struct ConstantInfo {
	String name;
	String enum_name;
	int64_t value = 0;
};

struct ClassInfo {
	String name;
	String inherits;
	ClassDB::CreateFunc creator = nullptr;
	bool is_abstract = true;
	bool registered = false; // register_class / register_abstract_class was called.

	std::unordered_map<String, std::unique_ptr<MethodBind>> method_map; // Owned; freed at exit.
	std::vector<String> method_order;

	std::vector<PropertyInfo> property_list; // Includes group/subgroup markers.
	std::unordered_map<String, ClassDB::PropertySetGet> property_setget;

	std::vector<ConstantInfo> constants;
	std::unordered_map<String, size_t> constant_map;

	bool defaults_cached = false;
	bool defaults_valid = false;
	std::unordered_map<String, Variant> default_values;
};

std::map<String, ClassInfo> &_classes() {
	static std::map<String, ClassInfo> classes;
	return classes;
}

ClassInfo *_get_class(const String &p_class) {
	std::map<String, ClassInfo> &classes = _classes();
	auto it = classes.find(p_class);
	return it == classes.end() ? nullptr : &it->second;
}

} // namespace

void _classdb_add_class(const String &p_class, const String &p_inherits) {
	ClassDB::_add_class(p_class, p_inherits);
}

void ClassDB::_add_class(const String &p_class, const String &p_inherits) {
	std::map<String, ClassInfo> &classes = _classes();
	if (classes.count(p_class)) {
		return;
	}
	ClassInfo &ci = classes[p_class];
	ci.name = p_class;
	ci.inherits = p_inherits;
}

void ClassDB::_set_creator(const String &p_class, CreateFunc p_creator, bool p_abstract) {
	ClassInfo *ci = _get_class(p_class);
	ERR_FAIL_NULL_MSG(ci, vformat("Class '%s' was not initialized before registration.", p_class.c_str()));
	ci->creator = p_creator;
	ci->is_abstract = p_abstract;
	ci->registered = true;
}

Object *ClassDB::instantiate(const String &p_class) {
	ClassInfo *ci = _get_class(p_class);
	ERR_FAIL_COND_V_MSG(!ci || !ci->registered, nullptr, vformat("Cannot instantiate class '%s': it is not registered in ClassDB.", p_class.c_str()));
	ERR_FAIL_COND_V_MSG(ci->is_abstract || !ci->creator, nullptr, vformat("Cannot instantiate class '%s': it is abstract.", p_class.c_str()));
	return ci->creator();
}

bool ClassDB::can_instantiate(const String &p_class) {
	ClassInfo *ci = _get_class(p_class);
	return ci && ci->registered && !ci->is_abstract && ci->creator;
}

bool ClassDB::class_exists(const String &p_class) {
	return _get_class(p_class) != nullptr;
}

bool ClassDB::is_parent_class(const String &p_class, const String &p_inherits) {
	String c = p_class;
	while (!c.empty()) {
		if (c == p_inherits) {
			return true;
		}
		ClassInfo *ci = _get_class(c);
		if (!ci) {
			return false;
		}
		c = ci->inherits;
	}
	return false;
}

String ClassDB::get_parent_class(const String &p_class) {
	ClassInfo *ci = _get_class(p_class);
	return ci ? ci->inherits : String();
}

void ClassDB::get_class_list(std::vector<String> *r_classes) {
	for (const auto &E : _classes()) {
		r_classes->push_back(E.first);
	}
}

void ClassDB::get_inheriters_from_class(const String &p_class, std::vector<String> *r_classes) {
	for (const auto &E : _classes()) {
		if (E.first != p_class && is_parent_class(E.first, p_class)) {
			r_classes->push_back(E.first);
		}
	}
}

// Methods.

MethodBind *ClassDB::_bind_method(MethodBind *p_bind, const MethodDefinition &p_definition) {
	ERR_FAIL_NULL_V(p_bind, nullptr);
	ClassInfo *ci = _get_class(p_bind->instance_class);
	if (!ci) {
		ERR_PRINT(vformat("Cannot bind method '%s': class '%s' is not initialized.", p_definition.name.c_str(), p_bind->instance_class.c_str()));
		delete p_bind;
		return nullptr;
	}
	if (ci->method_map.count(p_definition.name)) {
		ERR_PRINT(vformat("Method '%s::%s' is already bound.", ci->name.c_str(), p_definition.name.c_str()));
		delete p_bind;
		return nullptr;
	}
	if (!p_definition.args.empty() && (int)p_definition.args.size() != p_bind->get_argument_count()) {
		ERR_PRINT(vformat("Method '%s::%s' takes %d argument(s) but D_METHOD names %d.", ci->name.c_str(), p_definition.name.c_str(), p_bind->get_argument_count(), (int)p_definition.args.size()));
	}
	p_bind->name = p_definition.name;
	p_bind->arg_names = p_definition.args;
	p_bind->arg_names.resize(p_bind->arg_types.size());
	for (size_t i = 0; i < p_bind->arg_names.size(); i++) {
		if (p_bind->arg_names[i].empty()) {
			p_bind->arg_names[i] = "arg" + itos(i);
		}
	}
	ci->method_map[p_definition.name].reset(p_bind);
	ci->method_order.push_back(p_definition.name);
	return p_bind;
}

MethodBind *ClassDB::get_method(const String &p_class, const String &p_method) {
	ClassInfo *ci = _get_class(p_class);
	while (ci) {
		auto it = ci->method_map.find(p_method);
		if (it != ci->method_map.end()) {
			return it->second.get();
		}
		ci = _get_class(ci->inherits);
	}
	return nullptr;
}

bool ClassDB::has_method(const String &p_class, const String &p_method, bool p_no_inheritance) {
	if (p_no_inheritance) {
		ClassInfo *ci = _get_class(p_class);
		return ci && ci->method_map.count(p_method);
	}
	return get_method(p_class, p_method) != nullptr;
}

void ClassDB::get_method_list(const String &p_class, std::vector<String> *r_methods, bool p_no_inheritance) {
	std::vector<ClassInfo *> chain;
	for (ClassInfo *ci = _get_class(p_class); ci; ci = p_no_inheritance ? nullptr : _get_class(ci->inherits)) {
		chain.insert(chain.begin(), ci);
	}
	for (ClassInfo *ci : chain) {
		r_methods->insert(r_methods->end(), ci->method_order.begin(), ci->method_order.end());
	}
}

// Properties.

void ClassDB::add_property_group(const String &p_class, const String &p_name, const String &p_prefix) {
	ClassInfo *ci = _get_class(p_class);
	ERR_FAIL_NULL_MSG(ci, vformat("Cannot add property group '%s': class '%s' is not initialized.", p_name.c_str(), p_class.c_str()));
	ci->property_list.push_back(PropertyInfo(Variant::NIL, p_name, PROPERTY_HINT_NONE, p_prefix, PROPERTY_USAGE_GROUP));
}

void ClassDB::add_property_subgroup(const String &p_class, const String &p_name, const String &p_prefix) {
	ClassInfo *ci = _get_class(p_class);
	ERR_FAIL_NULL_MSG(ci, vformat("Cannot add property subgroup '%s': class '%s' is not initialized.", p_name.c_str(), p_class.c_str()));
	ci->property_list.push_back(PropertyInfo(Variant::NIL, p_name, PROPERTY_HINT_NONE, p_prefix, PROPERTY_USAGE_SUBGROUP));
}

void ClassDB::add_property(const String &p_class, const PropertyInfo &p_info, const String &p_setter, const String &p_getter, int p_index) {
	ClassInfo *ci = _get_class(p_class);
	ERR_FAIL_NULL_MSG(ci, vformat("Cannot add property '%s': class '%s' is not initialized.", p_info.name.c_str(), p_class.c_str()));
	ERR_FAIL_COND_MSG(ci->property_setget.count(p_info.name), vformat("Property '%s::%s' already exists.", p_class.c_str(), p_info.name.c_str()));

	PropertySetGet psg;
	psg.info = p_info;
	psg.setter = p_setter;
	psg.getter = p_getter;
	psg.index = p_index;
	int extra = p_index >= 0 ? 1 : 0;
	if (!p_setter.empty()) {
		psg.setter_bind = get_method(p_class, p_setter);
		ERR_FAIL_NULL_MSG(psg.setter_bind, vformat("Invalid setter '%s::%s' for property '%s': bind the method first.", p_class.c_str(), p_setter.c_str(), p_info.name.c_str()));
		ERR_FAIL_COND_MSG(psg.setter_bind->get_argument_count() != 1 + extra, vformat("Setter '%s::%s' for property '%s' must take %d argument(s).", p_class.c_str(), p_setter.c_str(), p_info.name.c_str(), 1 + extra));
	}
	if (!p_getter.empty()) {
		psg.getter_bind = get_method(p_class, p_getter);
		ERR_FAIL_NULL_MSG(psg.getter_bind, vformat("Invalid getter '%s::%s' for property '%s': bind the method first.", p_class.c_str(), p_getter.c_str(), p_info.name.c_str()));
		ERR_FAIL_COND_MSG(psg.getter_bind->get_argument_count() != extra, vformat("Getter '%s::%s' for property '%s' must take %d argument(s).", p_class.c_str(), p_getter.c_str(), p_info.name.c_str(), extra));
	}
	ci->property_list.push_back(p_info);
	ci->property_setget[p_info.name] = psg;
}

void ClassDB::get_property_list(const String &p_class, std::vector<PropertyInfo> *r_list, bool p_no_inheritance, const Object *p_validator) {
	std::vector<ClassInfo *> chain;
	for (ClassInfo *ci = _get_class(p_class); ci; ci = p_no_inheritance ? nullptr : _get_class(ci->inherits)) {
		chain.insert(chain.begin(), ci);
	}
	for (ClassInfo *ci : chain) {
		for (const PropertyInfo &pi : ci->property_list) {
			PropertyInfo copy = pi;
			if (p_validator && !copy.is_group_marker()) {
				p_validator->_validate_propertyv(copy);
			}
			r_list->push_back(copy);
		}
	}
}

const ClassDB::PropertySetGet *ClassDB::get_property_setget(const String &p_class, const String &p_property) {
	ClassInfo *ci = _get_class(p_class);
	while (ci) {
		auto it = ci->property_setget.find(p_property);
		if (it != ci->property_setget.end()) {
			return &it->second;
		}
		ci = _get_class(ci->inherits);
	}
	return nullptr;
}

bool ClassDB::has_property(const String &p_class, const String &p_property, bool p_no_inheritance) {
	if (p_no_inheritance) {
		ClassInfo *ci = _get_class(p_class);
		return ci && ci->property_setget.count(p_property);
	}
	return get_property_setget(p_class, p_property) != nullptr;
}

bool ClassDB::get_property_info(const String &p_class, const String &p_property, PropertyInfo *r_info) {
	const PropertySetGet *psg = get_property_setget(p_class, p_property);
	if (!psg) {
		return false;
	}
	if (r_info) {
		*r_info = psg->info;
	}
	return true;
}

String ClassDB::get_property_setter(const String &p_class, const String &p_property) {
	const PropertySetGet *psg = get_property_setget(p_class, p_property);
	return psg ? psg->setter : String();
}

String ClassDB::get_property_getter(const String &p_class, const String &p_property) {
	const PropertySetGet *psg = get_property_setget(p_class, p_property);
	return psg ? psg->getter : String();
}

bool ClassDB::set_property(Object *p_object, const String &p_property, const Variant &p_value, bool *r_found, String *r_error) {
	if (r_found) {
		*r_found = false;
	}
	ERR_FAIL_NULL_V(p_object, false);
	const PropertySetGet *psg = get_property_setget(p_object->get_class(), p_property);
	if (!psg) {
		return false;
	}
	if (r_found) {
		*r_found = true;
	}
	if (!psg->setter_bind) {
		if (r_error) {
			*r_error = vformat("Property '%s' of class '%s' is read-only.", p_property.c_str(), p_object->get_class().c_str());
		}
		return false;
	}
	// Check the value against the declared property type (stricter than the
	// setter's C++ type, e.g. an int-typed property must not take a Vector3).
	if (psg->info.type != Variant::NIL && !Variant::can_convert(p_value.get_type(), psg->info.type)) {
		if (r_error) {
			*r_error = vformat("Cannot set property '%s' of class '%s': expected %s, got %s.", p_property.c_str(), p_object->get_class().c_str(),
					Variant::get_type_name(psg->info.type).c_str(), Variant::get_type_name(p_value.get_type()).c_str());
		}
		return false;
	}
	CallError ce;
	if (psg->index >= 0) {
		Variant index = psg->index;
		const Variant *args[2] = { &index, &p_value };
		psg->setter_bind->call(p_object, args, 2, ce);
		if (ce.error != CallError::CALL_OK && r_error) {
			*r_error = vformat("Cannot set property '%s' of class '%s': %s", p_property.c_str(), p_object->get_class().c_str(), psg->setter_bind->get_call_error_text(ce, args).c_str());
		}
	} else {
		const Variant *args[1] = { &p_value };
		psg->setter_bind->call(p_object, args, 1, ce);
		if (ce.error != CallError::CALL_OK && r_error) {
			*r_error = vformat("Cannot set property '%s' of class '%s': %s", p_property.c_str(), p_object->get_class().c_str(), psg->setter_bind->get_call_error_text(ce, args).c_str());
		}
	}
	return ce.error == CallError::CALL_OK;
}

bool ClassDB::get_property(const Object *p_object, const String &p_property, Variant &r_value, bool *r_found, String *r_error) {
	if (r_found) {
		*r_found = false;
	}
	ERR_FAIL_NULL_V(p_object, false);
	const PropertySetGet *psg = get_property_setget(p_object->get_class(), p_property);
	if (!psg) {
		return false;
	}
	if (r_found) {
		*r_found = true;
	}
	if (!psg->getter_bind) {
		if (r_error) {
			*r_error = vformat("Property '%s' of class '%s' has no getter.", p_property.c_str(), p_object->get_class().c_str());
		}
		return false;
	}
	CallError ce;
	// Getters do not modify the object; the bind API takes a non-const pointer.
	Object *obj = const_cast<Object *>(p_object);
	if (psg->index >= 0) {
		Variant index = psg->index;
		const Variant *args[1] = { &index };
		r_value = psg->getter_bind->call(obj, args, 1, ce);
	} else {
		r_value = psg->getter_bind->call(obj, nullptr, 0, ce);
	}
	if (ce.error != CallError::CALL_OK) {
		if (r_error) {
			*r_error = vformat("Cannot get property '%s' of class '%s'.", p_property.c_str(), p_object->get_class().c_str());
		}
		return false;
	}
	return true;
}

Variant ClassDB::class_get_property_default(const String &p_class, const String &p_property, bool *r_valid) {
	if (r_valid) {
		*r_valid = false;
	}
	ClassInfo *ci = _get_class(p_class);
	if (!ci) {
		return Variant();
	}
	if (!ci->defaults_cached) {
		ci->defaults_cached = true;
		if (can_instantiate(p_class)) {
			Object *obj = ci->creator();
			if (obj) {
				ci->defaults_valid = true;
				std::vector<PropertyInfo> plist;
				get_property_list(p_class, &plist);
				for (const PropertyInfo &pi : plist) {
					if (pi.is_group_marker()) {
						continue;
					}
					Variant value;
					bool found = false;
					if (get_property(obj, pi.name, value, &found)) {
						ci->default_values[pi.name] = value;
					}
				}
				if (obj->is_ref_counted()) {
					Ref<RefCounted> holder(static_cast<RefCounted *>(obj)); // Deletes it.
				} else {
					delete obj;
				}
			}
		}
	}
	auto it = ci->default_values.find(p_property);
	if (it == ci->default_values.end()) {
		return Variant();
	}
	if (r_valid) {
		*r_valid = true;
	}
	return it->second;
}

// Constants.

String ClassDB::_enum_name_from_signature(const char *p_pretty_function) {
	// GCC/Clang: "... _get_enum_name(E) [with E = Light3D::Param; ...]" or "[E = Light3D::Param]".
	String s = p_pretty_function;
	size_t pos = s.find("E = ");
	if (pos == String::npos) {
		return String();
	}
	pos += 4;
	size_t end = s.find_first_of(";]", pos);
	String full = s.substr(pos, end == String::npos ? String::npos : end - pos);
	size_t colon = full.rfind("::");
	return colon == String::npos ? full : full.substr(colon + 2);
}

void ClassDB::bind_integer_constant(const String &p_class, const String &p_enum, const String &p_name, int64_t p_value) {
	ClassInfo *ci = _get_class(p_class);
	ERR_FAIL_NULL_MSG(ci, vformat("Cannot bind constant '%s': class '%s' is not initialized.", p_name.c_str(), p_class.c_str()));
	ERR_FAIL_COND_MSG(ci->constant_map.count(p_name), vformat("Constant '%s::%s' is already bound.", p_class.c_str(), p_name.c_str()));
	ConstantInfo c;
	c.name = p_name;
	c.enum_name = p_enum;
	c.value = p_value;
	ci->constant_map[p_name] = ci->constants.size();
	ci->constants.push_back(c);
}

static const ConstantInfo *_find_constant(const String &p_class, const String &p_name, bool p_no_inheritance) {
	ClassInfo *ci = _get_class(p_class);
	while (ci) {
		auto it = ci->constant_map.find(p_name);
		if (it != ci->constant_map.end()) {
			return &ci->constants[it->second];
		}
		ci = p_no_inheritance ? nullptr : _get_class(ci->inherits);
	}
	return nullptr;
}

int64_t ClassDB::get_integer_constant(const String &p_class, const String &p_name, bool *r_success) {
	const ConstantInfo *c = _find_constant(p_class, p_name, false);
	if (r_success) {
		*r_success = c != nullptr;
	}
	return c ? c->value : 0;
}

bool ClassDB::has_integer_constant(const String &p_class, const String &p_name, bool p_no_inheritance) {
	return _find_constant(p_class, p_name, p_no_inheritance) != nullptr;
}

void ClassDB::get_integer_constant_list(const String &p_class, std::vector<String> *r_constants, bool p_no_inheritance) {
	for (ClassInfo *ci = _get_class(p_class); ci; ci = p_no_inheritance ? nullptr : _get_class(ci->inherits)) {
		for (const ConstantInfo &c : ci->constants) {
			r_constants->push_back(c.name);
		}
	}
}

String ClassDB::get_integer_constant_enum(const String &p_class, const String &p_name, bool p_no_inheritance) {
	const ConstantInfo *c = _find_constant(p_class, p_name, p_no_inheritance);
	return c ? c->enum_name : String();
}

void ClassDB::get_enum_constants(const String &p_class, const String &p_enum, std::vector<String> *r_constants, bool p_no_inheritance) {
	for (ClassInfo *ci = _get_class(p_class); ci; ci = p_no_inheritance ? nullptr : _get_class(ci->inherits)) {
		for (const ConstantInfo &c : ci->constants) {
			if (c.enum_name == p_enum) {
				r_constants->push_back(c.name);
			}
		}
	}
}

void ClassDB::cleanup() {
	_classes().clear();
}
