/**************************************************************************/
/*  transform_3d.cpp                                                      */
/**************************************************************************/

#include "core/math/transform_3d.h"

AABB Transform3D::xform(const AABB &p_aabb) const {
	// Arvo's method: transform the centre, then the extents by |basis|.
	Vector3 half = p_aabb.size * real_t(0.5);
	Vector3 c = xform(p_aabb.position + half);
	Vector3 e;
	for (int i = 0; i < 3; i++) {
		e[i] = std::fabs(basis.rows[i][0]) * half.x + std::fabs(basis.rows[i][1]) * half.y + std::fabs(basis.rows[i][2]) * half.z;
	}
	return AABB(c - e, e * 2);
}

Plane Transform3D::xform(const Plane &p_plane) const {
	Vector3 point = xform(p_plane.get_center());
	Vector3 n = basis.inverse().transposed().xform(p_plane.normal).normalized();
	return Plane(n, n.dot(point));
}

Transform3D Transform3D::affine_inverse() const {
	Basis inv = basis.inverse();
	return Transform3D(inv, inv.xform(-origin));
}

Transform3D Transform3D::inverse() const {
	Basis inv = basis.transposed();
	return Transform3D(inv, inv.xform(-origin));
}
