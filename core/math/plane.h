/**************************************************************************/
/*  plane.h                                                               */
/**************************************************************************/
/* Plane n·p = d. distance_to() is positive on the side n points to;      */
/* frustum planes point outward, so "inside" means distance <= 0.          */

#pragma once

#include "core/math/vector3.h"

struct Plane {
	Vector3 normal;
	real_t d = 0;

	real_t distance_to(const Vector3 &p_point) const { return normal.dot(p_point) - d; }
	bool is_point_over(const Vector3 &p_point) const { return distance_to(p_point) > real_t(CMP_EPSILON); }
	Vector3 get_center() const { return normal * d; }
	Plane normalized() const {
		real_t l = normal.length();
		return l == 0 ? Plane() : Plane(normal / l, d / l);
	}

	Plane() {}
	Plane(const Vector3 &p_normal, real_t p_d) :
			normal(p_normal), d(p_d) {}
	Plane(const Vector3 &p_normal, const Vector3 &p_point) :
			normal(p_normal), d(p_normal.dot(p_point)) {}
};
