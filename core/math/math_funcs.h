/**************************************************************************/
/*  math_funcs.h                                                          */
/**************************************************************************/
/* Scalar helpers in Godot's `Math` namespace. real_t is float.           */

#pragma once

#include <cmath>
#include <cstdint>

typedef float real_t;

#define CMP_EPSILON 0.00001
#define UNIT_EPSILON 0.001

namespace Math {

constexpr double PI = 3.1415926535897932384626433833;
constexpr double TAU = 6.2831853071795864769252867666;

inline double deg_to_rad(double p_deg) {
	return p_deg * (PI / 180.0);
}
inline float deg_to_rad(float p_deg) {
	return p_deg * float(PI / 180.0);
}
inline double rad_to_deg(double p_rad) {
	return p_rad * (180.0 / PI);
}
inline float rad_to_deg(float p_rad) {
	return p_rad * float(180.0 / PI);
}

inline bool is_finite(double p_x) {
	return std::isfinite(p_x);
}
inline bool is_nan(double p_x) {
	return std::isnan(p_x);
}

// Relative-or-absolute comparison, like Godot's: tolerance scales with magnitude.
inline bool is_equal_approx(real_t p_a, real_t p_b) {
	if (p_a == p_b) {
		return true;
	}
	real_t tolerance = real_t(CMP_EPSILON) * std::fabs(p_a);
	if (tolerance < real_t(CMP_EPSILON)) {
		tolerance = real_t(CMP_EPSILON);
	}
	return std::fabs(p_a - p_b) < tolerance;
}
inline bool is_equal_approx(real_t p_a, real_t p_b, real_t p_tolerance) {
	return p_a == p_b || std::fabs(p_a - p_b) < p_tolerance;
}
inline bool is_zero_approx(real_t p_x) {
	return std::fabs(p_x) < real_t(CMP_EPSILON);
}

template <typename T>
inline T clamp(T p_x, T p_min, T p_max) {
	return p_x < p_min ? p_min : (p_x > p_max ? p_max : p_x);
}
template <typename T>
inline T lerp(T p_from, T p_to, T p_weight) {
	return p_from + (p_to - p_from) * p_weight;
}
template <typename T>
inline T sign(T p_x) {
	return p_x > T(0) ? T(1) : (p_x < T(0) ? T(-1) : T(0));
}

} // namespace Math
