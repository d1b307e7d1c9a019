/**************************************************************************/
/*  variant_caster.h                                                      */
/**************************************************************************/
/* VariantCaster<T>: how a bound method's argument/return type maps to a  */
/* Variant. check() says whether a Variant may be passed as T (used to     */
/* reject wrong types with a message), cast() converts, to_variant()      */
/* converts back. Ref<T> has its specialization in ref_counted.h.          */

#pragma once

#include "core/variant/variant.h"

#include <cstdint>
#include <limits>
#include <type_traits>

class Object;

template <class T, class = void>
struct VariantCaster; // Unsupported argument type: add a specialization.

#define _VARIANT_CASTER_SIMPLE(m_type, m_vtype, m_getter)                                            \
	template <>                                                                                      \
	struct VariantCaster<m_type> {                                                                   \
		static constexpr Variant::Type TYPE = m_vtype;                                               \
		static bool check(const Variant &p_v) { return Variant::can_convert(p_v.get_type(), TYPE); } \
		static m_type cast(const Variant &p_v) { return p_v.m_getter(); }                            \
		static Variant to_variant(const m_type &p_value) { return Variant(p_value); }                \
	};

_VARIANT_CASTER_SIMPLE(bool, Variant::BOOL, operator bool)
_VARIANT_CASTER_SIMPLE(String, Variant::STRING, operator String)
_VARIANT_CASTER_SIMPLE(Vector2, Variant::VECTOR2, operator Vector2)
_VARIANT_CASTER_SIMPLE(Vector3, Variant::VECTOR3, operator Vector3)
_VARIANT_CASTER_SIMPLE(Color, Variant::COLOR, operator Color)
_VARIANT_CASTER_SIMPLE(Transform3D, Variant::TRANSFORM3D, operator Transform3D)

// The values of integer type T that an INT Variant (int64) may hold; enums are bound as int (Godot's
// enums are int-sized). Other types have no range (min > max).
template <class T>
constexpr int64_t variant_int_min() {
	if constexpr (std::is_enum<T>::value) {
		return INT32_MIN;
	} else if constexpr (std::is_integral<T>::value && std::is_signed<T>::value) {
		return int64_t(std::numeric_limits<T>::min());
	} else {
		return 0;
	}
}
template <class T>
constexpr int64_t variant_int_max() {
	if constexpr (std::is_enum<T>::value) {
		return INT32_MAX;
	} else if constexpr (std::is_integral<T>::value && !std::is_same<T, bool>::value) {
		return std::numeric_limits<T>::max() > uint64_t(INT64_MAX) ? INT64_MAX : int64_t(std::numeric_limits<T>::max());
	} else {
		return -1;
	}
}

// Integers (not bool) and enums go through INT. check() also rejects a value outside T's range, so an
// int64 is never narrowed silently (4294967301 would otherwise reach an int setter as 5).
template <class T>
struct VariantCaster<T, typename std::enable_if<(std::is_integral<T>::value && !std::is_same<T, bool>::value) || std::is_enum<T>::value>::type> {
	static constexpr Variant::Type TYPE = Variant::INT;
	static bool check(const Variant &p_v) {
		if (!Variant::can_convert(p_v.get_type(), TYPE)) {
			return false;
		}
		const int64_t v = p_v.operator int64_t();
		return v >= variant_int_min<T>() && v <= variant_int_max<T>();
	}
	static T cast(const Variant &p_v) { return (T)p_v.operator int64_t(); }
	static Variant to_variant(T p_value) { return Variant((int64_t)p_value); }
};

template <class T>
struct VariantCaster<T, typename std::enable_if<std::is_floating_point<T>::value>::type> {
	static constexpr Variant::Type TYPE = Variant::FLOAT;
	static bool check(const Variant &p_v) { return Variant::can_convert(p_v.get_type(), TYPE); }
	static T cast(const Variant &p_v) { return (T)p_v.operator double(); }
	static Variant to_variant(T p_value) { return Variant((double)p_value); }
};

// A Variant argument accepts anything. TYPE NIL means "any" here.
template <>
struct VariantCaster<Variant> {
	static constexpr Variant::Type TYPE = Variant::NIL;
	static bool check(const Variant &p_v) { return true; }
	static Variant cast(const Variant &p_v) { return p_v; }
	static Variant to_variant(const Variant &p_value) { return p_value; }
};

// Raw Object-derived pointers (non-owning). Null or a matching class passes.
template <class T>
struct VariantCaster<T *, typename std::enable_if<std::is_class<T>::value>::type> {
	static constexpr Variant::Type TYPE = Variant::OBJECT;
	static bool check(const Variant &p_v) {
		if (p_v.get_type() == Variant::NIL) {
			return true;
		}
		return p_v.get_type() == Variant::OBJECT && (p_v.get_object() == nullptr || dynamic_cast<T *>(p_v.get_object()) != nullptr);
	}
	static T *cast(const Variant &p_v) { return dynamic_cast<T *>(p_v.get_object()); }
	static Variant to_variant(T *p_value) { return Variant((const Object *)p_value); }
};
