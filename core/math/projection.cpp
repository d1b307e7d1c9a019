/**************************************************************************/
/*  projection.cpp                                                        */
/**************************************************************************/

#include "core/math/projection.h"

#include "core/error/error_macros.h"

Vector4 Projection::xform(const Vector4 &p_v) const {
	return columns[0] * p_v.x + columns[1] * p_v.y + columns[2] * p_v.z + columns[3] * p_v.w;
}

Vector3 Projection::xform(const Vector3 &p_v) const {
	Vector4 r = xform(Vector4(p_v, 1));
	return r.xyz() / r.w;
}

Projection Projection::operator*(const Projection &p_m) const {
	Projection r;
	for (int c = 0; c < 4; c++) {
		r.columns[c] = xform(p_m.columns[c]);
	}
	return r;
}

Projection Projection::inverse() const {
	// Gauss-Jordan elimination with partial pivoting on a row-major copy.
	double m[4][8];
	for (int r = 0; r < 4; r++) {
		for (int c = 0; c < 4; c++) {
			m[r][c] = columns[c][r];
			m[r][c + 4] = r == c ? 1.0 : 0.0;
		}
	}
	for (int c = 0; c < 4; c++) {
		int pivot = c;
		for (int r = c + 1; r < 4; r++) {
			if (std::fabs(m[r][c]) > std::fabs(m[pivot][c])) {
				pivot = r;
			}
		}
		ERR_FAIL_COND_V_MSG(m[pivot][c] == 0.0, Projection(), "Projection::inverse(): the matrix is singular; returning identity.");
		for (int k = 0; k < 8; k++) {
			std::swap(m[c][k], m[pivot][k]);
		}
		double inv = 1.0 / m[c][c];
		for (int k = 0; k < 8; k++) {
			m[c][k] *= inv;
		}
		for (int r = 0; r < 4; r++) {
			if (r != c && m[r][c] != 0.0) {
				double f = m[r][c];
				for (int k = 0; k < 8; k++) {
					m[r][k] -= f * m[c][k];
				}
			}
		}
	}
	Projection res;
	for (int r = 0; r < 4; r++) {
		for (int c = 0; c < 4; c++) {
			res.columns[c][r] = real_t(m[r][c + 4]);
		}
	}
	return res;
}

bool Projection::is_equal_approx(const Projection &p_m) const {
	for (int i = 0; i < 4; i++) {
		if (!columns[i].is_equal_approx(p_m.columns[i])) {
			return false;
		}
	}
	return true;
}

real_t Projection::get_z_near() const {
	// For a perspective matrix, near = m32 / (m22 - 1) with OpenGL depth.
	return columns[3].z / (columns[2].z - 1);
}

real_t Projection::get_z_far() const {
	return columns[3].z / (columns[2].z + 1);
}

real_t Projection::get_fov() const {
	return Math::rad_to_deg(real_t(2) * std::atan(real_t(1) / columns[1].y));
}

real_t Projection::get_aspect() const {
	return columns[1].y / columns[0].x;
}

std::vector<Plane> Projection::get_projection_planes(const Transform3D &p_cam) const {
	// Gribb & Hartmann: clip-space plane k is row3 ± row_i; a view-space point is inside when
	// (row3 ± row_i)·(p, 1) >= 0. Negating gives an outward-facing Plane (n·p - d <= 0 inside).
	Vector4 r0 = get_row(0), r1 = get_row(1), r2 = get_row(2), r3 = get_row(3);
	const Vector4 inside[6] = { r3 + r2, r3 - r2, r3 + r0, r3 - r1, r3 - r0, r3 + r1 };
	std::vector<Plane> planes;
	planes.reserve(6);
	for (int i = 0; i < 6; i++) {
		Plane view_plane = Plane(-inside[i].xyz(), inside[i].w).normalized();
		planes.push_back(p_cam.xform(view_plane));
	}
	return planes;
}

Projection Projection::create_perspective(real_t p_fovy_degrees, real_t p_aspect, real_t p_z_near, real_t p_z_far) {
	real_t f = real_t(1) / std::tan(Math::deg_to_rad(p_fovy_degrees) * real_t(0.5));
	real_t depth = p_z_far - p_z_near;
	Projection p;
	p.columns[0] = Vector4(f / p_aspect, 0, 0, 0);
	p.columns[1] = Vector4(0, f, 0, 0);
	p.columns[2] = Vector4(0, 0, -(p_z_far + p_z_near) / depth, -1);
	p.columns[3] = Vector4(0, 0, -2 * p_z_far * p_z_near / depth, 0);
	return p;
}

Projection Projection::create_orthogonal(real_t p_left, real_t p_right, real_t p_bottom, real_t p_top, real_t p_z_near, real_t p_z_far) {
	Projection p;
	p.columns[0] = Vector4(2 / (p_right - p_left), 0, 0, 0);
	p.columns[1] = Vector4(0, 2 / (p_top - p_bottom), 0, 0);
	p.columns[2] = Vector4(0, 0, -2 / (p_z_far - p_z_near), 0);
	p.columns[3] = Vector4(-(p_right + p_left) / (p_right - p_left), -(p_top + p_bottom) / (p_top - p_bottom), -(p_z_far + p_z_near) / (p_z_far - p_z_near), 1);
	return p;
}

Projection Projection::create_depth_correction(bool p_flip_y) {
	Projection p;
	p.columns[1].y = p_flip_y ? -1 : 1;
	p.columns[2].z = real_t(0.5);
	p.columns[3].z = real_t(0.5);
	return p;
}

Projection Projection::from_transform(const Transform3D &p_t) {
	Projection p;
	for (int c = 0; c < 3; c++) {
		p.columns[c] = Vector4(p_t.basis.get_column(c), 0);
	}
	p.columns[3] = Vector4(p_t.origin, 1);
	return p;
}

void Projection::to_floats(float *r_out) const {
	for (int c = 0; c < 4; c++) {
		for (int r = 0; r < 4; r++) {
			r_out[c * 4 + r] = columns[c][r];
		}
	}
}
