/**************************************************************************/
/*  basis.h                                                               */
/**************************************************************************/
/* 3x3 matrix stored as rows, as Godot's Basis. Columns are the local     */
/* axes: get_column(0) is local X in parent space.                        */

#pragma once

#include "core/math/vector3.h"

struct Basis {
	Vector3 rows[3] = { Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1) };

	Vector3 get_column(int p_i) const { return Vector3(rows[0][p_i], rows[1][p_i], rows[2][p_i]); }
	void set_column(int p_i, const Vector3 &p_v) {
		rows[0][p_i] = p_v.x;
		rows[1][p_i] = p_v.y;
		rows[2][p_i] = p_v.z;
	}
	Vector3 xform(const Vector3 &p_v) const { return Vector3(rows[0].dot(p_v), rows[1].dot(p_v), rows[2].dot(p_v)); }
	// Multiplies by the transpose (the inverse for orthonormal bases).
	Vector3 xform_inv(const Vector3 &p_v) const { return Vector3(get_column(0).dot(p_v), get_column(1).dot(p_v), get_column(2).dot(p_v)); }
	real_t determinant() const { return rows[0].dot(rows[1].cross(rows[2])); }
	Basis transposed() const { return Basis::from_columns(rows[0], rows[1], rows[2]); }
	Basis inverse() const;
	Basis orthonormalized() const;
	Vector3 get_scale() const { return Vector3(get_column(0).length(), get_column(1).length(), get_column(2).length()); }
	Basis scaled(const Vector3 &p_scale) const;
	bool is_equal_approx(const Basis &p_b) const { return rows[0].is_equal_approx(p_b.rows[0]) && rows[1].is_equal_approx(p_b.rows[1]) && rows[2].is_equal_approx(p_b.rows[2]); }
	bool is_finite() const { return rows[0].is_finite() && rows[1].is_finite() && rows[2].is_finite(); }

	Basis operator*(const Basis &p_b) const;
	bool operator==(const Basis &p_b) const { return rows[0] == p_b.rows[0] && rows[1] == p_b.rows[1] && rows[2] == p_b.rows[2]; }

	static Basis from_columns(const Vector3 &p_x, const Vector3 &p_y, const Vector3 &p_z);
	static Basis from_scale(const Vector3 &p_scale);
	// Rotation of p_angle radians around the unit axis p_axis (right-handed).
	static Basis from_axis_angle(const Vector3 &p_axis, real_t p_angle);
	// Godot's default Euler order YXZ: R = Ry * Rx * Rz, angles in radians.
	static Basis from_euler(const Vector3 &p_euler);
	// -Z points along p_target, +Y towards p_up.
	static Basis looking_at(const Vector3 &p_target, const Vector3 &p_up = Vector3(0, 1, 0));

	Basis() {}
	Basis(real_t xx, real_t xy, real_t xz, real_t yx, real_t yy, real_t yz, real_t zx, real_t zy, real_t zz) {
		rows[0] = Vector3(xx, xy, xz);
		rows[1] = Vector3(yx, yy, yz);
		rows[2] = Vector3(zx, zy, zz);
	}
};
