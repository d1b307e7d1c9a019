/**************************************************************************/
/*  vector4.h                                                             */
/**************************************************************************/

#pragma once

#include "core/math/vector3.h"

struct Vector4 {
	real_t x = 0;
	real_t y = 0;
	real_t z = 0;
	real_t w = 0;

	real_t &operator[](int p_axis) { return p_axis == 0 ? x : (p_axis == 1 ? y : (p_axis == 2 ? z : w)); }
	const real_t &operator[](int p_axis) const { return p_axis == 0 ? x : (p_axis == 1 ? y : (p_axis == 2 ? z : w)); }

	real_t dot(const Vector4 &p_v) const { return x * p_v.x + y * p_v.y + z * p_v.z + w * p_v.w; }
	real_t length() const { return std::sqrt(dot(*this)); }
	bool is_equal_approx(const Vector4 &p_v) const {
		return Math::is_equal_approx(x, p_v.x) && Math::is_equal_approx(y, p_v.y) && Math::is_equal_approx(z, p_v.z) && Math::is_equal_approx(w, p_v.w);
	}
	Vector3 xyz() const { return Vector3(x, y, z); }

	Vector4 operator+(const Vector4 &p_v) const { return Vector4(x + p_v.x, y + p_v.y, z + p_v.z, w + p_v.w); }
	Vector4 operator-(const Vector4 &p_v) const { return Vector4(x - p_v.x, y - p_v.y, z - p_v.z, w - p_v.w); }
	Vector4 operator*(real_t p_s) const { return Vector4(x * p_s, y * p_s, z * p_s, w * p_s); }
	Vector4 operator-() const { return Vector4(-x, -y, -z, -w); }
	bool operator==(const Vector4 &p_v) const { return x == p_v.x && y == p_v.y && z == p_v.z && w == p_v.w; }

	Vector4() {}
	Vector4(real_t p_x, real_t p_y, real_t p_z, real_t p_w) :
			x(p_x), y(p_y), z(p_z), w(p_w) {}
	Vector4(const Vector3 &p_v, real_t p_w) :
			x(p_v.x), y(p_v.y), z(p_v.z), w(p_w) {}
};
