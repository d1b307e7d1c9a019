/**************************************************************************/
/*  class_db.h                                                            */
/**************************************************************************/
/* Registry of engine classes: inheritance, factories, bound methods,     */
/* properties (with groups and hints) and integer constants.              */
/*                                                                        */
/* Typical _bind_methods():                                               */
/*   ClassDB::bind_method(D_METHOD("set_param", "param", "value"),        */
/*           &Light3D::set_param);                                        */
/*   ClassDB::bind_method(D_METHOD("get_param", "param"),                 */
/*           &Light3D::get_param);                                        */
/*   ADD_GROUP("Light", "light_");                                        */
/*   ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_energy",           */
/*           PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"),               */
/*           "set_param", "get_param", PARAM_ENERGY);                     */
/*   BIND_ENUM_CONSTANT(PARAM_ENERGY);                                    */
/* Methods must be bound before a property names them.                    */

#pragma once

#include "core/object/method_bind.h"
#include "core/object/object.h"
#include "core/object/property_info.h"
#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <cstdint>
#include <vector>

class ClassDB {
public:
	struct PropertySetGet {
		PropertyInfo info;
		String setter;
		String getter;
		MethodBind *setter_bind = nullptr;
		MethodBind *getter_bind = nullptr;
		int index = -1; // >= 0: passed as the first argument (ADD_PROPERTYI).
	};

	typedef Object *(*CreateFunc)();

private:
	template <class T>
	static Object *_create() { return new T; }
	static void _set_creator(const String &p_class, CreateFunc p_creator, bool p_abstract);
	static MethodBind *_bind_method(MethodBind *p_bind, const MethodDefinition &p_definition);
	static String _enum_name_from_signature(const char *p_pretty_function);

public:
	// GDREGISTER_CLASS / GDREGISTER_ABSTRACT_CLASS. Registering also registers
	// (abstractly) any parent that was not registered yet, and runs _bind_methods.
	template <class T>
	static void register_class() {
		T::initialize_class();
		_set_creator(T::get_class_static(), &_create<T>, false);
	}
	template <class T>
	static void register_abstract_class() {
		T::initialize_class();
		_set_creator(T::get_class_static(), nullptr, true);
	}

	// Returns a new instance (owned by the caller; wrap RefCounted ones in a Ref),
	// or nullptr with an error for unknown or abstract classes.
	static Object *instantiate(const String &p_class);
	static bool can_instantiate(const String &p_class);
	static bool class_exists(const String &p_class);
	// True when p_class is p_inherits or derives from it (Godot semantics).
	static bool is_parent_class(const String &p_class, const String &p_inherits);
	// Empty for Object or unknown classes.
	static String get_parent_class(const String &p_class);
	static void get_class_list(std::vector<String> *r_classes);
	static void get_inheriters_from_class(const String &p_class, std::vector<String> *r_classes);

	// Methods.
	// Trailing p_defaults (DEFVAL(...)) are the defaults of the last arguments.
	template <class M, class... D>
	static MethodBind *bind_method(const MethodDefinition &p_definition, M p_method, D... p_defaults) {
		MethodBind *bind = create_method_bind(p_method);
		bind->default_arguments = std::vector<Variant>{ Variant(p_defaults)... };
		return _bind_method(bind, p_definition);
	}
	// Searches p_class then its ancestors.
	static MethodBind *get_method(const String &p_class, const String &p_method);
	static bool has_method(const String &p_class, const String &p_method, bool p_no_inheritance = false);
	static void get_method_list(const String &p_class, std::vector<String> *r_methods, bool p_no_inheritance = false);

	// Properties. Groups apply to the properties added after them; an empty
	// group name closes the group.
	static void add_property_group(const String &p_class, const String &p_name, const String &p_prefix = String());
	static void add_property_subgroup(const String &p_class, const String &p_name, const String &p_prefix = String());
	// p_setter may be empty (read-only); p_index >= 0 binds an indexed pair.
	static void add_property(const String &p_class, const PropertyInfo &p_info, const String &p_setter, const String &p_getter, int p_index = -1);
	// Base class first. With p_validator, each entry goes through its
	// _validate_property chain.
	static void get_property_list(const String &p_class, std::vector<PropertyInfo> *r_list, bool p_no_inheritance = false, const Object *p_validator = nullptr);
	static bool has_property(const String &p_class, const String &p_property, bool p_no_inheritance = false);
	static const PropertySetGet *get_property_setget(const String &p_class, const String &p_property);
	static bool get_property_info(const String &p_class, const String &p_property, PropertyInfo *r_info);
	static String get_property_setter(const String &p_class, const String &p_property);
	static String get_property_getter(const String &p_class, const String &p_property);

	// Property access by name (Object::set/get use these). r_found is false when
	// the class has no such bound property; otherwise the return value says
	// whether the call succeeded and r_error holds the message when it did not.
	static bool set_property(Object *p_object, const String &p_property, const Variant &p_value, bool *r_found, String *r_error = nullptr);
	static bool get_property(const Object *p_object, const String &p_property, Variant &r_value, bool *r_found, String *r_error = nullptr);

	// Default value of a property: one instance per class is created on first
	// use, read, and cached. r_valid false for abstract/unknown class or property.
	static Variant class_get_property_default(const String &p_class, const String &p_property, bool *r_valid = nullptr);

	// Integer constants (BIND_ENUM_CONSTANT / BIND_CONSTANT).
	static void bind_integer_constant(const String &p_class, const String &p_enum, const String &p_name, int64_t p_value);
	// Searches p_class then its ancestors. r_success false (and 0) when missing.
	static int64_t get_integer_constant(const String &p_class, const String &p_name, bool *r_success = nullptr);
	static bool has_integer_constant(const String &p_class, const String &p_name, bool p_no_inheritance = false);
	static void get_integer_constant_list(const String &p_class, std::vector<String> *r_constants, bool p_no_inheritance = false);
	// Enum a constant belongs to ("Param" for PARAM_ENERGY), empty if none.
	static String get_integer_constant_enum(const String &p_class, const String &p_name, bool p_no_inheritance = false);
	// Constants of one enum in binding order.
	static void get_enum_constants(const String &p_class, const String &p_enum, std::vector<String> *r_constants, bool p_no_inheritance = false);

	// Drops every class, binding and cached default. Only for program exit.
	static void cleanup();

	// Implementation detail of BIND_ENUM_CONSTANT: the enum's unqualified name.
	template <class E>
	static String _get_enum_name(E) {
		return _enum_name_from_signature(__PRETTY_FUNCTION__);
	}

	// Called by GDCLASS (via _classdb_add_class).
	static void _add_class(const String &p_class, const String &p_inherits);
};

#define GDREGISTER_CLASS(m_class) ::ClassDB::register_class<m_class>()
#define GDREGISTER_ABSTRACT_CLASS(m_class) ::ClassDB::register_abstract_class<m_class>()

#define ADD_PROPERTY(m_property, m_setter, m_getter) ::ClassDB::add_property(get_class_static(), m_property, String(m_setter), String(m_getter))
#define ADD_PROPERTYI(m_property, m_setter, m_getter, m_index) ::ClassDB::add_property(get_class_static(), m_property, String(m_setter), String(m_getter), (int)(m_index))
#define ADD_GROUP(m_name, m_prefix) ::ClassDB::add_property_group(get_class_static(), String(m_name), String(m_prefix))
#define ADD_SUBGROUP(m_name, m_prefix) ::ClassDB::add_property_subgroup(get_class_static(), String(m_name), String(m_prefix))

#define BIND_ENUM_CONSTANT(m_constant) ::ClassDB::bind_integer_constant(get_class_static(), ::ClassDB::_get_enum_name(m_constant), String(#m_constant), (int64_t)(m_constant))
#define BIND_CONSTANT(m_constant) ::ClassDB::bind_integer_constant(get_class_static(), String(), String(#m_constant), (int64_t)(m_constant))
