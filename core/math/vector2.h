/**************************************************************************/
/*  vector2.h                                                             */
/**************************************************************************/

#pragma once

#include "core/math/math_funcs.h"

struct Vector2 {
	real_t x = 0;
	real_t y = 0;

	real_t &operator[](int p_axis) { return p_axis == 0 ? x : y; }
	const real_t &operator[](int p_axis) const { return p_axis == 0 ? x : y; }

	real_t dot(const Vector2 &p_other) const { return x * p_other.x + y * p_other.y; }
	real_t length() const { return std::sqrt(x * x + y * y); }
	real_t length_squared() const { return x * x + y * y; }
	Vector2 normalized() const {
		real_t l = length();
		return l == 0 ? Vector2() : Vector2(x / l, y / l);
	}
	bool is_equal_approx(const Vector2 &p_v) const { return Math::is_equal_approx(x, p_v.x) && Math::is_equal_approx(y, p_v.y); }
	bool is_finite() const { return Math::is_finite(x) && Math::is_finite(y); }

	Vector2 operator+(const Vector2 &p_v) const { return Vector2(x + p_v.x, y + p_v.y); }
	Vector2 operator-(const Vector2 &p_v) const { return Vector2(x - p_v.x, y - p_v.y); }
	Vector2 operator*(const Vector2 &p_v) const { return Vector2(x * p_v.x, y * p_v.y); }
	Vector2 operator*(real_t p_s) const { return Vector2(x * p_s, y * p_s); }
	Vector2 operator/(real_t p_s) const { return Vector2(x / p_s, y / p_s); }
	Vector2 operator-() const { return Vector2(-x, -y); }
	bool operator==(const Vector2 &p_v) const { return x == p_v.x && y == p_v.y; }
	bool operator!=(const Vector2 &p_v) const { return !(*this == p_v); }

	Vector2() {}
	Vector2(real_t p_x, real_t p_y) :
			x(p_x), y(p_y) {}
};

inline Vector2 operator*(real_t p_s, const Vector2 &p_v) {
	return p_v * p_s;
}
