/**************************************************************************/
/*  variant.cpp                                                           */
/**************************************************************************/

#include "core/variant/variant.h"

#include "core/error/error_macros.h"
#include "core/object/object.h"
#include "core/object/ref_counted.h"

#include <cmath>

String Variant::get_type_name(Type p_type) {
	switch (p_type) {
		case NIL:
			return "Nil";
		case BOOL:
			return "bool";
		case INT:
			return "int";
		case FLOAT:
			return "float";
		case STRING:
			return "String";
		case VECTOR2:
			return "Vector2";
		case VECTOR3:
			return "Vector3";
		case COLOR:
			return "Color";
		case TRANSFORM3D:
			return "Transform3D";
		case OBJECT:
			return "Object";
		case VARIANT_MAX:
			break;
	}
	return "<invalid type>";
}

bool Variant::can_convert(Type p_from, Type p_to) {
	if (p_from == p_to) {
		return true;
	}
	switch (p_to) {
		case BOOL:
			return p_from == INT;
		case INT:
			return p_from == FLOAT || p_from == BOOL;
		case FLOAT:
			return p_from == INT;
		case OBJECT:
			return p_from == NIL;
		default:
			return false;
	}
}

void Variant::_clear() {
	if (type == OBJECT && _object && _object_ref) {
		RefCounted *rc = static_cast<RefCounted *>(_object);
		if (rc->unreference()) {
			delete rc;
		}
	}
	_object = nullptr;
	_object_ref = false;
	_string.clear();
	type = NIL;
}

void Variant::_set_object(const Object *p_object) {
	Object *obj = const_cast<Object *>(p_object);
	if (!obj) {
		type = NIL;
		return;
	}
	type = OBJECT;
	_object = obj;
	_object_ref = obj->is_ref_counted();
	if (_object_ref) {
		static_cast<RefCounted *>(obj)->reference();
	}
}

void Variant::_copy(const Variant &p_other) {
	switch (p_other.type) {
		case OBJECT:
			_set_object(p_other._object);
			return;
		case BOOL:
			_bool = p_other._bool;
			break;
		case INT:
			_int = p_other._int;
			break;
		case FLOAT:
			_float = p_other._float;
			break;
		case STRING:
			_string = p_other._string;
			break;
		case VECTOR2:
			_vector2 = p_other._vector2;
			break;
		case VECTOR3:
			_vector3 = p_other._vector3;
			break;
		case COLOR:
			_color = p_other._color;
			break;
		case TRANSFORM3D:
			_transform = p_other._transform;
			break;
		default:
			break;
	}
	type = p_other.type;
}

Variant::Variant(const Variant &p_other) {
	_copy(p_other);
}

Variant::Variant(Variant &&p_other) {
	_copy(p_other);
}

Variant &Variant::operator=(const Variant &p_other) {
	if (this == &p_other) {
		return *this;
	}
	// Copy first: p_other may be owned (indirectly) by the object we release.
	Variant tmp(p_other);
	_clear();
	_copy(tmp);
	return *this;
}

Variant &Variant::operator=(Variant &&p_other) {
	return operator=((const Variant &)p_other);
}

Variant::~Variant() {
	_clear();
}

Variant::Variant(bool p_bool) :
		type(BOOL), _bool(p_bool) {}
Variant::Variant(int p_int) :
		type(INT), _int(p_int) {}
Variant::Variant(unsigned int p_int) :
		type(INT), _int(p_int) {}
Variant::Variant(long p_int) :
		type(INT), _int(p_int) {}
Variant::Variant(unsigned long p_int) :
		type(INT), _int((int64_t)p_int) {}
Variant::Variant(long long p_int) :
		type(INT), _int(p_int) {}
Variant::Variant(unsigned long long p_int) :
		type(INT), _int((int64_t)p_int) {}
Variant::Variant(float p_float) :
		type(FLOAT), _float(p_float) {}
Variant::Variant(double p_float) :
		type(FLOAT), _float(p_float) {}
Variant::Variant(const char *p_string) :
		type(STRING), _string(p_string ? p_string : "") {}
Variant::Variant(const String &p_string) :
		type(STRING), _string(p_string) {}
Variant::Variant(const Vector2 &p_vector2) :
		type(VECTOR2), _vector2(p_vector2) {}
Variant::Variant(const Vector3 &p_vector3) :
		type(VECTOR3), _vector3(p_vector3) {}
Variant::Variant(const Color &p_color) :
		type(COLOR), _color(p_color) {}
Variant::Variant(const Transform3D &p_transform) :
		type(TRANSFORM3D), _transform(p_transform) {}
Variant::Variant(const Object *p_object) {
	_set_object(p_object);
}

#define _VARIANT_CONVERT_FAIL(m_to, m_ret)                                                                                                                             \
	_err_print_error(__FUNCTION__, __FILE__, __LINE__, vformat("Cannot convert Variant of type %s to %s.", get_type_name(type).c_str(), get_type_name(m_to).c_str())); \
	return m_ret;

Variant::operator bool() const {
	switch (type) {
		case BOOL:
			return _bool;
		case INT:
			return _int != 0;
		default:
			_VARIANT_CONVERT_FAIL(BOOL, false);
	}
}

Variant::operator int64_t() const {
	switch (type) {
		case INT:
			return _int;
		case FLOAT:
			if (std::isnan(_float)) {
				return 0;
			}
			if (_float >= 9.2e18) {
				return INT64_MAX;
			}
			if (_float <= -9.2e18) {
				return INT64_MIN;
			}
			return (int64_t)_float;
		case BOOL:
			return _bool ? 1 : 0;
		default:
			_VARIANT_CONVERT_FAIL(INT, 0);
	}
}

// Narrowing saturates instead of wrapping (2^31 must not read as -2^31); bound setters reject such
// values before they get here (VariantCaster::check).
Variant::operator int() const {
	const int64_t v = operator int64_t();
	return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : (int)v);
}

Variant::operator uint32_t() const {
	const int64_t v = operator int64_t();
	return v > int64_t(UINT32_MAX) ? UINT32_MAX : (v < 0 ? 0u : (uint32_t)v);
}

Variant::operator uint64_t() const {
	const int64_t v = operator int64_t();
	return v < 0 ? 0u : (uint64_t)v;
}

Variant::operator double() const {
	switch (type) {
		case FLOAT:
			return _float;
		case INT:
			return (double)_int;
		default:
			_VARIANT_CONVERT_FAIL(FLOAT, 0.0);
	}
}

Variant::operator float() const {
	return (float)operator double();
}

Variant::operator String() const {
	if (type == STRING) {
		return _string;
	}
	_VARIANT_CONVERT_FAIL(STRING, String());
}

Variant::operator Vector2() const {
	if (type == VECTOR2) {
		return _vector2;
	}
	_VARIANT_CONVERT_FAIL(VECTOR2, Vector2());
}

Variant::operator Vector3() const {
	if (type == VECTOR3) {
		return _vector3;
	}
	_VARIANT_CONVERT_FAIL(VECTOR3, Vector3());
}

Variant::operator Color() const {
	if (type == COLOR) {
		return _color;
	}
	_VARIANT_CONVERT_FAIL(COLOR, Color());
}

Variant::operator Transform3D() const {
	if (type == TRANSFORM3D) {
		return _transform;
	}
	_VARIANT_CONVERT_FAIL(TRANSFORM3D, Transform3D());
}

Object *Variant::get_object() const {
	return type == OBJECT ? _object : nullptr;
}

static bool _vec3_eq(const Vector3 &p_a, const Vector3 &p_b) {
	return p_a.x == p_b.x && p_a.y == p_b.y && p_a.z == p_b.z;
}

bool Variant::operator==(const Variant &p_other) const {
	if (type != p_other.type) {
		if ((type == INT && p_other.type == FLOAT) || (type == FLOAT && p_other.type == INT)) {
			return operator double() == p_other.operator double();
		}
		return false;
	}
	switch (type) {
		case NIL:
			return true;
		case BOOL:
			return _bool == p_other._bool;
		case INT:
			return _int == p_other._int;
		case FLOAT:
			return _float == p_other._float || (std::isnan(_float) && std::isnan(p_other._float));
		case STRING:
			return _string == p_other._string;
		case VECTOR2:
			return _vector2.x == p_other._vector2.x && _vector2.y == p_other._vector2.y;
		case VECTOR3:
			return _vec3_eq(_vector3, p_other._vector3);
		case COLOR:
			return _color.r == p_other._color.r && _color.g == p_other._color.g && _color.b == p_other._color.b && _color.a == p_other._color.a;
		case TRANSFORM3D:
			for (int i = 0; i < 3; i++) {
				if (!_vec3_eq(_transform.basis.rows[i], p_other._transform.basis.rows[i])) {
					return false;
				}
			}
			return _vec3_eq(_transform.origin, p_other._transform.origin);
		case OBJECT:
			return _object == p_other._object;
		case VARIANT_MAX:
			break;
	}
	return false;
}

static String _num(double p_value) {
	// Shortest text that reads back to the same double.
	char buf[64];
	for (int prec = 6; prec <= 17; prec++) {
		snprintf(buf, sizeof(buf), "%.*g", prec, p_value);
		if (strtod(buf, nullptr) == p_value) {
			break;
		}
	}
	return String(buf);
}

static String _numf(real_t p_value) {
	char buf[64];
	for (int prec = 6; prec <= 9; prec++) {
		snprintf(buf, sizeof(buf), "%.*g", prec, (double)p_value);
		if ((real_t)strtod(buf, nullptr) == p_value) {
			break;
		}
	}
	return String(buf);
}

static String _vec3_str(const Vector3 &p_v) {
	return "(" + _numf(p_v.x) + ", " + _numf(p_v.y) + ", " + _numf(p_v.z) + ")";
}

String Variant::stringify() const {
	switch (type) {
		case NIL:
			return "<null>";
		case BOOL:
			return _bool ? "true" : "false";
		case INT:
			return itos(_int);
		case FLOAT:
			return _num(_float);
		case STRING:
			return _string;
		case VECTOR2:
			return "(" + _numf(_vector2.x) + ", " + _numf(_vector2.y) + ")";
		case VECTOR3:
			return _vec3_str(_vector3);
		case COLOR:
			return "(" + _numf(_color.r) + ", " + _numf(_color.g) + ", " + _numf(_color.b) + ", " + _numf(_color.a) + ")";
		case TRANSFORM3D:
			return "[X: " + _vec3_str(_transform.basis.get_column(0)) + ", Y: " + _vec3_str(_transform.basis.get_column(1)) + ", Z: " + _vec3_str(_transform.basis.get_column(2)) + ", O: " + _vec3_str(_transform.origin) + "]";
		case OBJECT:
			return _object ? "<" + _object->get_class() + ">" : "<null>";
		case VARIANT_MAX:
			break;
	}
	return String();
}
