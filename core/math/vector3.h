/**************************************************************************/
/*  vector3.h                                                             */
/**************************************************************************/

#pragma once

#include "core/math/math_funcs.h"

struct Vector3 {
	enum Axis {
		AXIS_X,
		AXIS_Y,
		AXIS_Z,
	};

	real_t x = 0;
	real_t y = 0;
	real_t z = 0;

	real_t &operator[](int p_axis) { return p_axis == 0 ? x : (p_axis == 1 ? y : z); }
	const real_t &operator[](int p_axis) const { return p_axis == 0 ? x : (p_axis == 1 ? y : z); }

	real_t dot(const Vector3 &p_v) const { return x * p_v.x + y * p_v.y + z * p_v.z; }
	Vector3 cross(const Vector3 &p_v) const { return Vector3(y * p_v.z - z * p_v.y, z * p_v.x - x * p_v.z, x * p_v.y - y * p_v.x); }
	real_t length() const { return std::sqrt(x * x + y * y + z * z); }
	real_t length_squared() const { return x * x + y * y + z * z; }
	Vector3 normalized() const {
		real_t l = length();
		return l == 0 ? Vector3() : Vector3(x / l, y / l, z / l);
	}
	void normalize() { *this = normalized(); }
	bool is_normalized() const { return Math::is_equal_approx(length_squared(), real_t(1), real_t(UNIT_EPSILON)); }
	Vector3 abs() const { return Vector3(std::fabs(x), std::fabs(y), std::fabs(z)); }
	Vector3 min(const Vector3 &p_v) const { return Vector3(std::fmin(x, p_v.x), std::fmin(y, p_v.y), std::fmin(z, p_v.z)); }
	Vector3 max(const Vector3 &p_v) const { return Vector3(std::fmax(x, p_v.x), std::fmax(y, p_v.y), std::fmax(z, p_v.z)); }
	real_t distance_to(const Vector3 &p_v) const { return (p_v - *this).length(); }
	Vector3 lerp(const Vector3 &p_to, real_t p_weight) const { return *this + (p_to - *this) * p_weight; }
	bool is_equal_approx(const Vector3 &p_v) const {
		return Math::is_equal_approx(x, p_v.x) && Math::is_equal_approx(y, p_v.y) && Math::is_equal_approx(z, p_v.z);
	}
	bool is_finite() const { return Math::is_finite(x) && Math::is_finite(y) && Math::is_finite(z); }

	Vector3 operator+(const Vector3 &p_v) const { return Vector3(x + p_v.x, y + p_v.y, z + p_v.z); }
	Vector3 operator-(const Vector3 &p_v) const { return Vector3(x - p_v.x, y - p_v.y, z - p_v.z); }
	Vector3 operator*(const Vector3 &p_v) const { return Vector3(x * p_v.x, y * p_v.y, z * p_v.z); }
	Vector3 operator/(const Vector3 &p_v) const { return Vector3(x / p_v.x, y / p_v.y, z / p_v.z); }
	Vector3 operator*(real_t p_s) const { return Vector3(x * p_s, y * p_s, z * p_s); }
	Vector3 operator/(real_t p_s) const { return Vector3(x / p_s, y / p_s, z / p_s); }
	Vector3 operator-() const { return Vector3(-x, -y, -z); }
	Vector3 &operator+=(const Vector3 &p_v) { return *this = *this + p_v; }
	Vector3 &operator-=(const Vector3 &p_v) { return *this = *this - p_v; }
	Vector3 &operator*=(real_t p_s) { return *this = *this * p_s; }
	Vector3 &operator/=(real_t p_s) { return *this = *this / p_s; }
	bool operator==(const Vector3 &p_v) const { return x == p_v.x && y == p_v.y && z == p_v.z; }
	bool operator!=(const Vector3 &p_v) const { return !(*this == p_v); }

	Vector3() {}
	Vector3(real_t p_x, real_t p_y, real_t p_z) :
			x(p_x), y(p_y), z(p_z) {}
};

inline Vector3 operator*(real_t p_s, const Vector3 &p_v) {
	return p_v * p_s;
}
