/**************************************************************************/
/*  object.cpp                                                            */
/**************************************************************************/

#include "core/object/object.h"

#include "core/error/error_macros.h"
#include "core/object/class_db.h"

void Object::initialize_class() {
	static bool initialized = false;
	if (initialized) {
		return;
	}
	ClassDB::_add_class(get_class_static(), String());
	initialized = true;
	_bind_methods();
}

bool Object::try_set(const String &p_name, const Variant &p_value, String *r_error) {
	_initialize_classv();
	bool found = false;
	String err;
	bool ok = ClassDB::set_property(this, p_name, p_value, &found, &err);
	if (found) {
		if (!ok && r_error) {
			*r_error = err;
		}
		return ok;
	}
	if (_set(p_name, p_value)) {
		return true;
	}
	if (r_error) {
		*r_error = vformat("Invalid property '%s' on class '%s': no such property.", p_name.c_str(), get_class().c_str());
	}
	return false;
}

void Object::set(const String &p_name, const Variant &p_value, bool *r_valid) {
	String err;
	bool ok = try_set(p_name, p_value, &err);
	if (r_valid) {
		*r_valid = ok;
	}
	if (!ok) {
		ERR_PRINT(err);
	}
}

Variant Object::get(const String &p_name, bool *r_valid) const {
	const_cast<Object *>(this)->_initialize_classv();
	bool found = false;
	String err;
	Variant ret;
	bool ok = ClassDB::get_property(this, p_name, ret, &found, &err);
	if (!found) {
		ok = _get(p_name, ret);
		if (!ok) {
			err = vformat("Invalid property '%s' on class '%s': no such property.", p_name.c_str(), get_class().c_str());
		}
	}
	if (r_valid) {
		*r_valid = ok;
	}
	if (!ok) {
		ERR_PRINT(err);
		return Variant();
	}
	return ret;
}

bool Object::has_property(const String &p_name) const {
	const_cast<Object *>(this)->_initialize_classv();
	if (ClassDB::has_property(get_class(), p_name)) {
		return true;
	}
	std::vector<PropertyInfo> extra;
	_get_property_list(&extra);
	for (const PropertyInfo &pi : extra) {
		if (pi.name == p_name && !pi.is_group_marker()) {
			return true;
		}
	}
	return false;
}

void Object::get_property_list(std::vector<PropertyInfo> *r_list) const {
	ERR_FAIL_NULL(r_list);
	const_cast<Object *>(this)->_initialize_classv();
	ClassDB::get_property_list(get_class(), r_list, false, this);
	std::vector<PropertyInfo> extra;
	_get_property_list(&extra);
	for (PropertyInfo &pi : extra) {
		if (!pi.is_group_marker()) {
			_validate_propertyv(pi);
		}
		r_list->push_back(pi);
	}
}

Variant Object::call(const String &p_method, const std::vector<Variant> &p_args, bool *r_valid) {
	_initialize_classv();
	if (r_valid) {
		*r_valid = false;
	}
	MethodBind *mb = ClassDB::get_method(get_class(), p_method);
	if (!mb) {
		ERR_PRINT(vformat("Invalid call: method '%s' does not exist on class '%s'.", p_method.c_str(), get_class().c_str()));
		return Variant();
	}
	std::vector<const Variant *> ptrs;
	for (const Variant &v : p_args) {
		ptrs.push_back(&v);
	}
	CallError ce;
	Variant ret = mb->call(this, p_args, ce); // Fills in DEFVAL defaults.
	if (ce.error != CallError::CALL_OK) {
		ERR_PRINT(vformat("Invalid call to '%s::%s': %s", get_class().c_str(), p_method.c_str(), mb->get_call_error_text(ce, ptrs.empty() ? nullptr : ptrs.data()).c_str()));
		return Variant();
	}
	if (r_valid) {
		*r_valid = true;
	}
	return ret;
}

bool Object::has_method(const String &p_method) const {
	const_cast<Object *>(this)->_initialize_classv();
	return ClassDB::has_method(get_class(), p_method);
}

void Object::notification(int p_what, bool p_reversed) {
	_notificationv(p_what, p_reversed);
}
