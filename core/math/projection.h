/**************************************************************************/
/*  projection.h                                                          */
/**************************************************************************/
/* 4x4 matrix stored as four columns (Godot's Projection). Perspective    */
/* matrices use OpenGL clip space (depth -1..1, y up); the RD renderer    */
/* multiplies by create_depth_correction() for Vulkan (depth 0..1, y down).*/

#pragma once

#include "core/math/transform_3d.h"
#include "core/math/vector4.h"

#include <vector>

struct Projection {
	enum Planes {
		PLANE_NEAR,
		PLANE_FAR,
		PLANE_LEFT,
		PLANE_TOP,
		PLANE_RIGHT,
		PLANE_BOTTOM
	};

	Vector4 columns[4] = { Vector4(1, 0, 0, 0), Vector4(0, 1, 0, 0), Vector4(0, 0, 1, 0), Vector4(0, 0, 0, 1) };

	Vector4 xform(const Vector4 &p_v) const;
	// Multiplies (v, 1) and divides by w.
	Vector3 xform(const Vector3 &p_v) const;
	Projection operator*(const Projection &p_m) const;
	Projection inverse() const;
	Vector4 get_row(int p_r) const { return Vector4(columns[0][p_r], columns[1][p_r], columns[2][p_r], columns[3][p_r]); }
	bool is_equal_approx(const Projection &p_m) const;

	real_t get_z_near() const;
	real_t get_z_far() const;
	real_t get_fov() const; // Vertical, degrees.
	real_t get_aspect() const;

	// Six planes in world space, normals pointing out of the frustum. p_cam is camera-to-world.
	std::vector<Plane> get_projection_planes(const Transform3D &p_cam) const;

	// p_fovy_degrees is the vertical field of view (Camera3D's KEEP_HEIGHT default).
	static Projection create_perspective(real_t p_fovy_degrees, real_t p_aspect, real_t p_z_near, real_t p_z_far);
	static Projection create_orthogonal(real_t p_left, real_t p_right, real_t p_bottom, real_t p_top, real_t p_z_near, real_t p_z_far);
	// Maps OpenGL depth -1..1 to Vulkan 0..1 and optionally flips y.
	static Projection create_depth_correction(bool p_flip_y);
	static Projection from_transform(const Transform3D &p_t);
	// Columns-major 16 floats, as the GPU expects.
	void to_floats(float *r_out) const;

	Projection() {}
	Projection(const Vector4 &p_x, const Vector4 &p_y, const Vector4 &p_z, const Vector4 &p_w) {
		columns[0] = p_x;
		columns[1] = p_y;
		columns[2] = p_z;
		columns[3] = p_w;
	}
};
