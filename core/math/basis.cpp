/**************************************************************************/
/*  basis.cpp                                                             */
/**************************************************************************/

#include "core/math/basis.h"

#include "core/error/error_macros.h"

Basis Basis::inverse() const {
	// Adjugate divided by the determinant.
	real_t co[3] = {
		rows[1][1] * rows[2][2] - rows[1][2] * rows[2][1],
		rows[1][2] * rows[2][0] - rows[1][0] * rows[2][2],
		rows[1][0] * rows[2][1] - rows[1][1] * rows[2][0],
	};
	real_t det = rows[0][0] * co[0] + rows[0][1] * co[1] + rows[0][2] * co[2];
	ERR_FAIL_COND_V_MSG(det == 0, Basis(), "Basis::inverse(): the basis is singular (determinant 0); returning identity.");
	real_t s = real_t(1) / det;
	return Basis(co[0] * s, (rows[0][2] * rows[2][1] - rows[0][1] * rows[2][2]) * s, (rows[0][1] * rows[1][2] - rows[0][2] * rows[1][1]) * s,
			co[1] * s, (rows[0][0] * rows[2][2] - rows[0][2] * rows[2][0]) * s, (rows[0][2] * rows[1][0] - rows[0][0] * rows[1][2]) * s,
			co[2] * s, (rows[0][1] * rows[2][0] - rows[0][0] * rows[2][1]) * s, (rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]) * s);
}

Basis Basis::orthonormalized() const {
	// Gram-Schmidt on the columns.
	Vector3 x = get_column(0).normalized();
	Vector3 y = get_column(1);
	y = (y - x * x.dot(y)).normalized();
	Vector3 z = get_column(2);
	z = (z - x * x.dot(z) - y * y.dot(z)).normalized();
	return from_columns(x, y, z);
}

Basis Basis::scaled(const Vector3 &p_scale) const {
	return from_scale(p_scale) * *this;
}

Basis Basis::operator*(const Basis &p_b) const {
	Basis r;
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++) {
			r.rows[i][j] = rows[i][0] * p_b.rows[0][j] + rows[i][1] * p_b.rows[1][j] + rows[i][2] * p_b.rows[2][j];
		}
	}
	return r;
}

Basis Basis::from_columns(const Vector3 &p_x, const Vector3 &p_y, const Vector3 &p_z) {
	return Basis(p_x.x, p_y.x, p_z.x, p_x.y, p_y.y, p_z.y, p_x.z, p_y.z, p_z.z);
}

Basis Basis::from_scale(const Vector3 &p_scale) {
	return Basis(p_scale.x, 0, 0, 0, p_scale.y, 0, 0, 0, p_scale.z);
}

Basis Basis::from_axis_angle(const Vector3 &p_axis, real_t p_angle) {
	// Rodrigues' rotation formula.
	Vector3 a = p_axis.normalized();
	real_t c = std::cos(p_angle), s = std::sin(p_angle), t = 1 - c;
	return Basis(t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y,
			t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x,
			t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c);
}

Basis Basis::from_euler(const Vector3 &p_euler) {
	return from_axis_angle(Vector3(0, 1, 0), p_euler.y) * from_axis_angle(Vector3(1, 0, 0), p_euler.x) * from_axis_angle(Vector3(0, 0, 1), p_euler.z);
}

Basis Basis::looking_at(const Vector3 &p_target, const Vector3 &p_up) {
	ERR_FAIL_COND_V_MSG(p_target.length_squared() == 0, Basis(), "Basis::looking_at(): the target direction is zero.");
	Vector3 z = -p_target.normalized();
	Vector3 x = p_up.cross(z);
	if (x.length_squared() < real_t(1e-12)) {
		// Up is parallel to the view direction: pick any perpendicular.
		x = (std::fabs(z.y) < real_t(0.9) ? Vector3(0, 1, 0) : Vector3(1, 0, 0)).cross(z);
	}
	x.normalize();
	Vector3 y = z.cross(x);
	return from_columns(x, y, z);
}
