/**************************************************************************/
/*  test_math.cpp                                                         */
/**************************************************************************/

#include "core/math/projection.h"

#include <doctest/doctest.h>

namespace TestMath {

TEST_CASE("[Math] Vector3 products and normalization") {
	Vector3 a(1, 2, 3), b(-4, 5, 0.5);
	CHECK(Math::is_equal_approx(a.dot(b), 1.0f * -4 + 2 * 5 + 3 * 0.5f));
	Vector3 c = a.cross(b);
	CHECK(Math::is_zero_approx(c.dot(a)));
	CHECK(Math::is_zero_approx(c.dot(b)));
	CHECK(Vector3(3, 0, 4).normalized().is_equal_approx(Vector3(0.6f, 0, 0.8f)));
	CHECK(Vector3().normalized() == Vector3());
}

TEST_CASE("[Math] Basis inverse, rotation and looking_at") {
	Basis r = Basis::from_euler(Vector3(0.3f, -1.1f, 0.7f));
	CHECK(Math::is_equal_approx(r.determinant(), 1.0f));
	CHECK((r * r.inverse()).is_equal_approx(Basis()));
	CHECK(r.transposed().is_equal_approx(r.inverse()));
	Basis rot = Basis::from_axis_angle(Vector3(0, 1, 0), float(Math::PI / 2));
	CHECK(rot.xform(Vector3(1, 0, 0)).is_equal_approx(Vector3(0, 0, -1)));
	Basis look = Basis::looking_at(Vector3(1, 0, 0));
	CHECK((-look.get_column(2)).is_equal_approx(Vector3(1, 0, 0)));
	CHECK(look.get_column(1).is_equal_approx(Vector3(0, 1, 0)));
	Basis s = Basis::from_scale(Vector3(2, 3, 4));
	CHECK(s.get_scale().is_equal_approx(Vector3(2, 3, 4)));
	CHECK((s.inverse() * s).is_equal_approx(Basis()));
}

TEST_CASE("[Math] Transform3D composition, inverse and AABB transform") {
	Transform3D t(Basis::from_euler(Vector3(0.2f, 0.4f, -0.3f)).scaled(Vector3(1, 2, 1)), Vector3(1, -2, 3));
	Vector3 p(0.5f, 1.5f, -2);
	CHECK(t.affine_inverse().xform(t.xform(p)).is_equal_approx(p));
	Transform3D u(Basis::from_euler(Vector3(1, 0, 0)), Vector3(0, 1, 0));
	CHECK((t * u).xform(p).is_equal_approx(t.xform(u.xform(p))));
	AABB box(Vector3(-1, -1, -1), Vector3(2, 2, 2));
	AABB tb = t.xform(box);
	for (int i = 0; i < 8; i++) {
		Vector3 c = t.xform(box.get_endpoint(i));
		CHECK(tb.grow(1e-4f).has_point(c));
	}
}

TEST_CASE("[Math] Projection perspective, inverse and frustum planes") {
	Projection p = Projection::create_perspective(75, 16.0f / 9.0f, 0.05f, 100);
	CHECK(Math::is_equal_approx(p.get_fov(), 75.0f, 1e-3f));
	CHECK(Math::is_equal_approx(p.get_z_near(), 0.05f, 1e-5f));
	CHECK(Math::is_equal_approx(p.get_z_far(), 100.0f, 0.05f));
	CHECK((p * p.inverse()).is_equal_approx(Projection()));
	// A point on the near plane maps to NDC z = -1; Vulkan correction maps it to 0.
	CHECK(Math::is_equal_approx(p.xform(Vector3(0, 0, -0.05f)).z, -1.0f, 1e-4f));
	Projection vk = Projection::create_depth_correction(true) * p;
	CHECK(Math::is_equal_approx(vk.xform(Vector3(0, 0, -0.05f)).z, 0.0f, 1e-4f));
	CHECK(Math::is_equal_approx(vk.xform(Vector3(0, 0, -100)).z, 1.0f, 1e-4f));

	Transform3D cam(Basis::looking_at(Vector3(0, 0, -1)), Vector3(0, 0, 5));
	std::vector<Plane> planes = p.get_projection_planes(cam);
	REQUIRE(planes.size() == 6);
	Vector3 inside(0, 0, 0), behind(0, 0, 6), far_left(-500, 0, 0);
	for (const Plane &pl : planes) {
		CHECK(!pl.is_point_over(inside));
	}
	bool out_behind = false, out_left = false;
	for (const Plane &pl : planes) {
		out_behind = out_behind || pl.is_point_over(behind);
		out_left = out_left || pl.is_point_over(far_left);
	}
	CHECK(out_behind);
	CHECK(out_left);
	CHECK(AABB(Vector3(-1, -1, -1), Vector3(2, 2, 2)).intersects_convex_shape(planes));
	CHECK_FALSE(AABB(Vector3(-1, -1, 10), Vector3(2, 2, 2)).intersects_convex_shape(planes));
}

} // namespace TestMath
