/**************************************************************************/
/*  transform_3d.h                                                        */
/**************************************************************************/

#pragma once

#include "core/math/aabb.h"
#include "core/math/basis.h"
#include "core/math/plane.h"

struct Transform3D {
	Basis basis;
	Vector3 origin;

	Vector3 xform(const Vector3 &p_v) const { return basis.xform(p_v) + origin; }
	// Inverse for orthonormal bases only (as Godot's xform_inv).
	Vector3 xform_inv(const Vector3 &p_v) const { return basis.xform_inv(p_v - origin); }
	AABB xform(const AABB &p_aabb) const;
	Plane xform(const Plane &p_plane) const;
	Transform3D affine_inverse() const;
	Transform3D inverse() const; // Orthonormal bases only.
	Transform3D orthonormalized() const { return Transform3D(basis.orthonormalized(), origin); }
	Transform3D translated(const Vector3 &p_offset) const { return Transform3D(basis, origin + p_offset); }
	Transform3D looking_at(const Vector3 &p_target, const Vector3 &p_up = Vector3(0, 1, 0)) const {
		return Transform3D(Basis::looking_at(p_target - origin, p_up), origin);
	}
	bool is_equal_approx(const Transform3D &p_t) const { return basis.is_equal_approx(p_t.basis) && origin.is_equal_approx(p_t.origin); }
	bool is_finite() const { return basis.is_finite() && origin.is_finite(); }

	Transform3D operator*(const Transform3D &p_t) const { return Transform3D(basis * p_t.basis, xform(p_t.origin)); }
	bool operator==(const Transform3D &p_t) const { return basis == p_t.basis && origin == p_t.origin; }
	bool operator!=(const Transform3D &p_t) const { return !(*this == p_t); }

	Transform3D() {}
	Transform3D(const Basis &p_basis, const Vector3 &p_origin = Vector3()) :
			basis(p_basis), origin(p_origin) {}
};
