/**************************************************************************/
/*  object.h                                                              */
/**************************************************************************/
/* Base of every engine class. GDCLASS gives class-name introspection and  */
/* registration; properties are set and read by name through ClassDB.      */
/*                                                                        */
/* Per-class hooks, declared (non-virtual) in each class that needs them: */
/*   static void _bind_methods();            bind methods/properties      */
/*   void _validate_property(PropertyInfo &p_property) const;             */
/*   void _notification(int p_what);                                      */
/* GDCLASS chains them through the hierarchy, base class first, so a      */
/* subclass must NOT call its parent's version (and must not mark them    */
/* virtual/override). _set/_get/_get_property_list are ordinary virtuals  */
/* for dynamic or legacy property names (call the parent yourself).       */
/*                                                                        */
/* Objects are created with `new` and destroyed with `delete`; RefCounted */
/* ones are owned by Ref<T> (see ref_counted.h).                          */

#pragma once

#include "core/object/property_info.h"
#include "core/string/ustring.h"
#include "core/variant/variant.h"
#include "core/variant/variant_caster.h"

#include <cstdint>
#include <memory>
#include <vector>

class ClassDB;

// Implemented in class_db.cpp; called by GDCLASS's initialize_class().
void _classdb_add_class(const String &p_class, const String &p_inherits);

#define GDCLASS(m_class, m_inherits)                                                              \
private:                                                                                          \
	friend class ::ClassDB;                                                                       \
                                                                                                  \
public:                                                                                           \
	typedef m_class self_type;                                                                    \
	typedef m_inherits super_type;                                                                \
	static String get_class_static() {                                                            \
		return String(#m_class);                                                                  \
	}                                                                                             \
	static String get_parent_class_static() {                                                     \
		return m_inherits::get_class_static();                                                    \
	}                                                                                             \
	virtual String get_class() const override {                                                   \
		return String(#m_class);                                                                  \
	}                                                                                             \
	virtual bool is_class(const String &p_class) const override {                                 \
		return p_class == #m_class || m_inherits::is_class(p_class);                              \
	}                                                                                             \
	static void initialize_class() {                                                              \
		static bool initialized = false;                                                          \
		if (initialized) {                                                                        \
			return;                                                                               \
		}                                                                                         \
		m_inherits::initialize_class();                                                           \
		::_classdb_add_class(String(#m_class), m_inherits::get_class_static());                   \
		initialized = true;                                                                       \
		if (m_class::_get_bind_methods() != m_inherits::_get_bind_methods()) {                    \
			m_class::_bind_methods();                                                             \
		}                                                                                         \
	}                                                                                             \
                                                                                                  \
protected:                                                                                        \
	virtual void _initialize_classv() override {                                                  \
		initialize_class();                                                                       \
	}                                                                                             \
	static void (*_get_bind_methods())() {                                                        \
		return &m_class::_bind_methods;                                                           \
	}                                                                                             \
	static void (Object::*_get_validate_property())(PropertyInfo &) const {                       \
		return static_cast<void (Object::*)(PropertyInfo &) const>(&m_class::_validate_property); \
	}                                                                                             \
	static void (Object::*_get_notification())(int) {                                             \
		return static_cast<void (Object::*)(int)>(&m_class::_notification);                       \
	}                                                                                             \
	virtual void _validate_propertyv(PropertyInfo &p_property) const override {                   \
		m_inherits::_validate_propertyv(p_property);                                              \
		if (m_class::_get_validate_property() != m_inherits::_get_validate_property()) {          \
			m_class::_validate_property(p_property);                                              \
		}                                                                                         \
	}                                                                                             \
	virtual void _notificationv(int p_what, bool p_reversed) override {                           \
		if (!p_reversed) {                                                                        \
			m_inherits::_notificationv(p_what, p_reversed);                                       \
		}                                                                                         \
		if (m_class::_get_notification() != m_inherits::_get_notification()) {                    \
			m_class::_notification(p_what);                                                       \
		}                                                                                         \
		if (p_reversed) {                                                                         \
			m_inherits::_notificationv(p_what, p_reversed);                                       \
		}                                                                                         \
	}                                                                                             \
                                                                                                  \
private:

// Data a file format keeps for an object without interpreting it (the text
// scene format's unknown properties, groups, connections...; see
// scene/resources/resource_format_text.h), so a save writes it back.
struct ObjectFileData {
	virtual std::unique_ptr<ObjectFileData> clone() const = 0;
	virtual ~ObjectFileData() {}
};

class Object {
	friend class ClassDB;
	friend class RefCounted;

	bool _is_ref_counted = false;
	uint32_t _property_list_changed_count = 0;
	std::unique_ptr<ObjectFileData> _file_data;

protected:
	// Per-class hooks (see the banner). Object's versions do nothing.
	static void _bind_methods() {}
	void _validate_property(PropertyInfo &p_property) const {}
	void _notification(int p_what) {}

	// Dynamic properties, consulted after ClassDB's bound properties.
	// Return true when the name was handled.
	virtual bool _set(const String &p_name, const Variant &p_value) { return false; }
	virtual bool _get(const String &p_name, Variant &r_ret) const { return false; }
	// Extra entries appended after the bound ones.
	virtual void _get_property_list(std::vector<PropertyInfo> *r_list) const {}

	// Machinery used by GDCLASS.
	virtual void _initialize_classv() { initialize_class(); }
	static void (*_get_bind_methods())() { return &Object::_bind_methods; }
	static void (Object::*_get_validate_property())(PropertyInfo &) const { return &Object::_validate_property; }
	static void (Object::*_get_notification())(int) { return &Object::_notification; }
	virtual void _validate_propertyv(PropertyInfo &p_property) const { _validate_property(p_property); }
	virtual void _notificationv(int p_what, bool p_reversed) { _notification(p_what); }

public:
	enum {
		NOTIFICATION_POSTINITIALIZE = 0,
		NOTIFICATION_PREDELETE = 1,
	};

	static String get_class_static() { return String("Object"); }
	static String get_parent_class_static() { return String(); }
	virtual String get_class() const { return String("Object"); }
	virtual bool is_class(const String &p_class) const { return p_class == "Object"; }
	static void initialize_class();

	bool is_ref_counted() const { return _is_ref_counted; }

	template <class T>
	static T *cast_to(Object *p_object) { return dynamic_cast<T *>(p_object); }
	template <class T>
	static const T *cast_to(const Object *p_object) { return dynamic_cast<const T *>(p_object); }

	// Sets a property through its bound setter (or _set). An unknown name or a
	// value whose type cannot convert prints an error naming the class and the
	// property, and sets *r_valid = false.
	void set(const String &p_name, const Variant &p_value, bool *r_valid = nullptr);
	// Same, but silent: returns false and fills r_error with the message.
	// (The scene loader uses it to report file:line warnings itself.)
	bool try_set(const String &p_name, const Variant &p_value, String *r_error = nullptr);
	// Reads a property through its bound getter (or _get). Unknown names print
	// an error, set *r_valid = false and return NIL.
	Variant get(const String &p_name, bool *r_valid = nullptr) const;
	bool has_property(const String &p_name) const;

	// Bound properties, base class first, each in declaration order, including
	// group/subgroup markers (usage PROPERTY_USAGE_GROUP/SUBGROUP). Every entry
	// has been through _validate_property; hidden ones stay in the list with
	// their reduced usage (NONE = neither shown nor saved).
	void get_property_list(std::vector<PropertyInfo> *r_list) const;

	// Calls a bound method by name. Wrong name/argument types print an error
	// and set *r_valid = false.
	Variant call(const String &p_method, const std::vector<Variant> &p_args = std::vector<Variant>(), bool *r_valid = nullptr);
	bool has_method(const String &p_method) const;

	// Call from setters that change which properties are visible. Here it only
	// counts (there is no inspector to refresh).
	void notify_property_list_changed() { _property_list_changed_count++; }
	uint32_t get_property_list_changed_count() const { return _property_list_changed_count; }

	// Sends p_what to every class level's _notification (base first, or
	// most-derived first when p_reversed).
	void notification(int p_what, bool p_reversed = false);

	// Null unless a loader kept something (see ObjectFileData).
	ObjectFileData *get_file_data() const { return _file_data.get(); }
	void set_file_data(std::unique_ptr<ObjectFileData> p_data) { _file_data = std::move(p_data); }

	Object() {}
	Object(const Object &) = delete;
	Object &operator=(const Object &) = delete;
	virtual ~Object() {}
};

// ClassDB, MethodBind and RefCounted/Ref<T> are always wanted with Object.
#include "core/object/class_db.h"
#include "core/object/ref_counted.h"
