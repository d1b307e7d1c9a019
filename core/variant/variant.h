/**************************************************************************/
/*  variant.h                                                             */
/**************************************************************************/
/* A small tagged value: the subset of Godot's Variant that scene files   */
/* and property binding need. OBJECT holds an Object pointer; when the    */
/* object is RefCounted the Variant keeps a reference to it.              */

#pragma once

#include "core/math/color.h"
#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"
#include "core/string/ustring.h"

#include <cstdint>
#include <type_traits>

class Object;

class Variant {
public:
	// Order follows Godot's Variant::Type for the types we keep.
	enum Type {
		NIL,
		BOOL,
		INT,
		FLOAT,
		STRING,
		VECTOR2,
		VECTOR3,
		COLOR,
		TRANSFORM3D,
		OBJECT,
		VARIANT_MAX,
	};

private:
	// Plain members rather than a union: simpler and safe; size is not a concern here.
	Type type = NIL;
	bool _bool = false;
	int64_t _int = 0;
	double _float = 0.0;
	String _string;
	Vector2 _vector2;
	Vector3 _vector3;
	Color _color;
	Transform3D _transform;
	Object *_object = nullptr;
	bool _object_ref = false; // OBJECT holds a reference on a RefCounted.

	void _clear();
	void _copy(const Variant &p_other);
	void _set_object(const Object *p_object);

public:
	static String get_type_name(Type p_type);
	// Conversion rules used by the typed getters and by method binding:
	// same type; INT <-> FLOAT; BOOL <-> INT; NIL -> OBJECT (a null reference).
	static bool can_convert(Type p_from, Type p_to);

	Type get_type() const { return type; }
	bool is_nil() const { return type == NIL; }

	// Typed getters. A conversion outside can_convert() prints an error that
	// names both types and returns a neutral value (false, 0, empty, identity).
	operator bool() const;
	operator int() const;
	operator int64_t() const;
	operator uint32_t() const;
	operator uint64_t() const;
	operator float() const;
	operator double() const;
	operator String() const;
	operator Vector2() const;
	operator Vector3() const;
	operator Color() const;
	operator Transform3D() const;
	// Null unless OBJECT (no reference is taken; wrap in Ref<T> to keep it).
	Object *get_object() const;
	// Explicit forms (handy where implicit conversion is ambiguous).
	bool to_bool() const { return operator bool(); }
	int64_t to_int() const { return operator int64_t(); }
	double to_float() const { return operator double(); }
	String to_string() const { return operator String(); }

	// Equality: same type and value; INT and FLOAT compare numerically;
	// OBJECT compares pointers. Floats compare exactly.
	bool operator==(const Variant &p_other) const;
	bool operator!=(const Variant &p_other) const { return !(*this == p_other); }

	// Human-readable text ("1.5", "(1, 2, 3)", "<Object:Class>"), not scene syntax
	// (VariantWriter writes scene syntax).
	String stringify() const;

	Variant(const Variant &p_other);
	Variant(Variant &&p_other);
	Variant &operator=(const Variant &p_other);
	Variant &operator=(Variant &&p_other);

	Variant() {}
	Variant(std::nullptr_t) {}
	Variant(bool p_bool);
	Variant(int p_int);
	Variant(unsigned int p_int);
	Variant(long p_int);
	Variant(unsigned long p_int);
	Variant(long long p_int);
	Variant(unsigned long long p_int);
	Variant(float p_float);
	Variant(double p_float);
	Variant(const char *p_string);
	Variant(const String &p_string);
	Variant(const Vector2 &p_vector2);
	Variant(const Vector3 &p_vector3);
	Variant(const Color &p_color);
	Variant(const Transform3D &p_transform);
	// Takes a reference when p_object is RefCounted. Null gives NIL.
	Variant(const Object *p_object);
	// Unscoped enums become INT.
	template <class E, typename std::enable_if<std::is_enum<E>::value, int>::type = 0>
	Variant(E p_enum) :
			Variant((int64_t)p_enum) {}

	~Variant();
};

// Godot requires this after every bound enum so the enum converts to/from
// Variant INT. Here enums convert automatically; the macro checks the type.
#define VARIANT_ENUM_CAST(m_enum) \
	static_assert(std::is_enum<m_enum>::value, #m_enum " must be an enum to be cast to Variant.")
#define VARIANT_BITFIELD_CAST(m_enum) VARIANT_ENUM_CAST(m_enum)
