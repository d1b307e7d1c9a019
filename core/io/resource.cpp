/**************************************************************************/
/*  resource.cpp                                                          */
/**************************************************************************/

#include "core/io/resource.h"

#include "core/object/class_db.h"

void Resource::set_path(const String &p_path) {
	path = p_path;
}

void Resource::set_name(const String &p_name) {
	name = p_name;
	emit_changed();
}

void Resource::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_path", "path"), &Resource::set_path);
	ClassDB::bind_method(D_METHOD("get_path"), &Resource::get_path);
	ClassDB::bind_method(D_METHOD("set_name", "name"), &Resource::set_name);
	ClassDB::bind_method(D_METHOD("get_name"), &Resource::get_name);
	ClassDB::bind_method(D_METHOD("emit_changed"), &Resource::emit_changed);

	ADD_GROUP("Resource", "resource_");
	ADD_PROPERTY(PropertyInfo(Variant::STRING, "resource_path", PROPERTY_HINT_FILE, "", PROPERTY_USAGE_EDITOR), "set_path", "get_path");
	ADD_PROPERTY(PropertyInfo(Variant::STRING, "resource_name"), "set_name", "get_name");
	ADD_GROUP("", "");
}
