/**************************************************************************/
/*  test_primitive_meshes.cpp                                             */
/**************************************************************************/
/* PlaneMesh, QuadMesh, BoxMesh, SphereMesh, CylinderMesh, CapsuleMesh,   */
/* TorusMesh, PrismMesh and ArrayMesh: Godot 4.7 defaults, vertex counts, */
/* unit outward normals, clockwise (Godot) winding seen from outside,     */
/* tangent frames, AABBs, enclosed volumes, index validity and rejection  */
/* of bad parameters.                                                     */

#include "scene/resources/primitive_meshes.h"

#include "scene/main/node.h"
#include "scene/resources/resource_format_text.h"

#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace TestPrimitiveMeshes {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

// Checks array sizes, index range, unit normals, unit tangents orthogonal to the normal with
// w = +-1, and UVs inside [0, 1].
static void check_surface_valid(const RS::SurfaceData &p_s) {
	const size_t n = p_s.vertices.size();
	REQUIRE(n > 0);
	CHECK(ArrayMesh::validate_surface(p_s).empty());
	REQUIRE(p_s.normals.size() == n);
	REQUIRE(p_s.tangents.size() == n * 4);
	REQUIRE(p_s.uvs.size() == n);
	REQUIRE(p_s.indices.size() % 3 == 0);
	int bad_normals = 0, bad_tangents = 0, bad_uvs = 0, bad_indices = 0;
	for (size_t i = 0; i < n; i++) {
		bad_normals += !Math::is_equal_approx(p_s.normals[i].length(), real_t(1), real_t(1e-4));
		Vector3 t(p_s.tangents[i * 4], p_s.tangents[i * 4 + 1], p_s.tangents[i * 4 + 2]);
		float w = p_s.tangents[i * 4 + 3];
		bad_tangents += !Math::is_equal_approx(t.length(), real_t(1), real_t(1e-4)) || std::fabs(t.dot(p_s.normals[i])) > 1e-4f || std::fabs(std::fabs(w) - 1.0f) > 0;
		bad_uvs += p_s.uvs[i].x < -1e-6f || p_s.uvs[i].x > 1 + 1e-6f || p_s.uvs[i].y < -1e-6f || p_s.uvs[i].y > 1 + 1e-6f;
	}
	for (uint32_t idx : p_s.indices) {
		bad_indices += idx >= n;
	}
	CHECK(bad_normals == 0);
	CHECK(bad_tangents == 0);
	CHECK(bad_uvs == 0);
	CHECK(bad_indices == 0);
}

// For every non-degenerate triangle: cross(b - a, c - a) opposes the vertex normals
// (clockwise front faces seen from outside, Godot's convention), and the stored tangent frame agrees with the UV layout:
// tangent along dP/du, cross(N, T) * w along -dP/dv. Returns the number of triangles checked.
static int check_winding_and_tangents(const RS::SurfaceData &p_s) {
	int checked = 0, bad_winding = 0, bad_tangent = 0, bad_bitangent = 0;
	for (size_t i = 0; i + 2 < p_s.indices.size(); i += 3) {
		const uint32_t ia = p_s.indices[i], ib = p_s.indices[i + 1], ic = p_s.indices[i + 2];
		const Vector3 e1 = p_s.vertices[ib] - p_s.vertices[ia];
		const Vector3 e2 = p_s.vertices[ic] - p_s.vertices[ia];
		const Vector3 face = e1.cross(e2);
		if (face.length() < 1e-6f) {
			continue; // Degenerate (sphere poles).
		}
		checked++;
		const Vector3 n = (p_s.normals[ia] + p_s.normals[ib] + p_s.normals[ic]).normalized();
		bad_winding += face.dot(n) >= 0;

		const Vector2 d1 = p_s.uvs[ib] - p_s.uvs[ia];
		const Vector2 d2 = p_s.uvs[ic] - p_s.uvs[ia];
		const real_t det = d1.x * d2.y - d2.x * d1.y;
		if (std::fabs(det) < 1e-9f) {
			continue;
		}
		const Vector3 dp_du = (e1 * d2.y - e2 * d1.y) / det;
		const Vector3 dp_dv = (e2 * d1.x - e1 * d2.x) / det;
		const Vector3 t(p_s.tangents[ia * 4], p_s.tangents[ia * 4 + 1], p_s.tangents[ia * 4 + 2]);
		const float w = p_s.tangents[ia * 4 + 3];
		bad_tangent += t.dot(dp_du) <= 0;
		bad_bitangent += (p_s.normals[ia].cross(t) * w).dot(-dp_dv) <= 0;
	}
	CHECK(bad_winding == 0);
	CHECK(bad_tangent == 0);
	CHECK(bad_bitangent == 0);
	return checked;
}

TEST_CASE("[PrimitiveMesh] defaults match Godot 4.7") {
	DummyServer server;
	Ref<PlaneMesh> plane;
	plane.instantiate();
	CHECK(Vector2(plane->get("size")) == Vector2(2, 2));
	CHECK(plane->get("subdivide_width").to_int() == 0);
	CHECK(plane->get("subdivide_depth").to_int() == 0);
	CHECK(plane->get("orientation").to_int() == PlaneMesh::FACE_Y);
	CHECK(Vector3(plane->get("center_offset")) == Vector3());
	CHECK(plane->get("flip_faces").to_bool() == false);

	Ref<QuadMesh> quad;
	quad.instantiate();
	CHECK(Vector2(quad->get("size")) == Vector2(1, 1));
	CHECK(quad->get("orientation").to_int() == PlaneMesh::FACE_Z);

	Ref<BoxMesh> box;
	box.instantiate();
	CHECK(Vector3(box->get("size")) == Vector3(1, 1, 1));
	CHECK(box->get("subdivide_height").to_int() == 0);

	Ref<SphereMesh> sphere;
	sphere.instantiate();
	CHECK(sphere->get("radius").to_float() == doctest::Approx(0.5));
	CHECK(sphere->get("height").to_float() == doctest::Approx(1.0));
	CHECK(sphere->get("radial_segments").to_int() == 64);
	CHECK(sphere->get("rings").to_int() == 32);

	CHECK_FALSE(ClassDB::can_instantiate("PrimitiveMesh"));
	CHECK(ClassDB::is_parent_class("QuadMesh", "PlaneMesh"));
	CHECK(ClassDB::is_parent_class("SphereMesh", "Mesh"));
}

TEST_CASE("[PrimitiveMesh] PlaneMesh and QuadMesh geometry") {
	DummyServer server;
	Ref<PlaneMesh> plane;
	plane.instantiate();

	SUBCASE("default plane faces +Y") {
		RS::SurfaceData s = plane->get_mesh_arrays();
		CHECK(s.vertices.size() == 4);
		CHECK(s.indices.size() == 6);
		check_surface_valid(s);
		CHECK(check_winding_and_tangents(s) == 2);
		for (const Vector3 &nrm : s.normals) {
			CHECK(nrm == Vector3(0, 1, 0));
		}
		CHECK(plane->get_aabb().is_equal_approx(AABB(Vector3(-1, 0, -1), Vector3(2, 0, 2))));
	}
	SUBCASE("subdivisions and orientations") {
		plane->set("subdivide_width", 3);
		plane->set("subdivide_depth", 2);
		for (int o = 0; o < 3; o++) {
			plane->set("orientation", o);
			RS::SurfaceData s = plane->get_mesh_arrays();
			CHECK(s.vertices.size() == (3 + 2) * (2 + 2));
			CHECK(s.indices.size() == (3 + 1) * (2 + 1) * 6);
			check_surface_valid(s);
			CHECK(check_winding_and_tangents(s) == (3 + 1) * (2 + 1) * 2);
			Vector3 axis = o == 0 ? Vector3(1, 0, 0) : (o == 1 ? Vector3(0, 1, 0) : Vector3(0, 0, 1));
			CHECK(s.normals[0] == axis);
		}
	}
	SUBCASE("quad faces +Z with its texture upright") {
		Ref<QuadMesh> quad;
		quad.instantiate();
		RS::SurfaceData s = quad->get_mesh_arrays();
		check_surface_valid(s);
		CHECK(check_winding_and_tangents(s) == 2);
		CHECK(s.normals[0] == Vector3(0, 0, 1));
		CHECK(quad->get_aabb().is_equal_approx(AABB(Vector3(-0.5f, -0.5f, 0), Vector3(1, 1, 0))));
		// UV (0, 0) is the top-left corner seen from +Z.
		for (size_t i = 0; i < s.vertices.size(); i++) {
			if (s.uvs[i] == Vector2(0, 0)) {
				CHECK(s.vertices[i].is_equal_approx(Vector3(-0.5f, 0.5f, 0)));
			}
		}
	}
	SUBCASE("center_offset moves the plane") {
		plane->set("center_offset", Vector3(0, 2, 0));
		CHECK(plane->get_aabb().position.is_equal_approx(Vector3(-1, 2, -1)));
	}
}

TEST_CASE("[PrimitiveMesh] BoxMesh geometry") {
	DummyServer server;
	Ref<BoxMesh> box;
	box.instantiate();

	SUBCASE("default box") {
		RS::SurfaceData s = box->get_mesh_arrays();
		CHECK(s.vertices.size() == 24);
		CHECK(s.indices.size() == 36);
		check_surface_valid(s);
		CHECK(check_winding_and_tangents(s) == 12);
		CHECK(box->get_aabb().is_equal_approx(AABB(Vector3(-0.5f, -0.5f, -0.5f), Vector3(1, 1, 1))));
		for (size_t i = 0; i < s.vertices.size(); i++) {
			CHECK_MESSAGE(s.normals[i].dot(s.vertices[i]) > 0, "box normals point outwards");
		}
	}
	SUBCASE("subdivided, non-cubic box") {
		box->set("size", Vector3(2, 3, 4));
		box->set("subdivide_width", 1);
		box->set("subdivide_height", 2);
		box->set("subdivide_depth", 3);
		RS::SurfaceData s = box->get_mesh_arrays();
		// Faces: +-Z (w x h), +-X (d x h), +-Y (w x d), each (segments + 1)^2 vertices.
		const int expected = 2 * (3 * 4) + 2 * (5 * 4) + 2 * (3 * 5);
		CHECK(s.vertices.size() == (size_t)expected);
		CHECK(s.indices.size() == (size_t)(2 * (2 * 3) + 2 * (4 * 3) + 2 * (2 * 4)) * 6);
		check_surface_valid(s);
		check_winding_and_tangents(s);
		CHECK(box->get_aabb().is_equal_approx(AABB(Vector3(-1, -1.5f, -2), Vector3(2, 3, 4))));
	}
	SUBCASE("flip_faces reverses winding and normals") {
		box->set("flip_faces", true);
		RS::SurfaceData s = box->get_mesh_arrays();
		check_surface_valid(s);
		check_winding_and_tangents(s); // Still consistent: normals and winding flip together.
		for (size_t i = 0; i < s.vertices.size(); i++) {
			CHECK(s.normals[i].dot(s.vertices[i]) < 0);
		}
	}
}

TEST_CASE("[PrimitiveMesh] SphereMesh geometry") {
	DummyServer server;
	Ref<SphereMesh> sphere;
	sphere.instantiate();

	SUBCASE("default sphere") {
		RS::SurfaceData s = sphere->get_mesh_arrays();
		CHECK(s.vertices.size() == (size_t)(32 + 2) * (64 + 1));
		CHECK(s.indices.size() == (size_t)(32 + 1) * 64 * 6);
		check_surface_valid(s);
		// Two rows of pole triangles are degenerate.
		CHECK(check_winding_and_tangents(s) == (32 + 1) * 64 * 2 - 2 * 64);
		int bad = 0;
		for (size_t i = 0; i < s.vertices.size(); i++) {
			bad += !s.normals[i].is_equal_approx(s.vertices[i].normalized());
			bad += !Math::is_equal_approx(s.vertices[i].length(), real_t(0.5), real_t(1e-5));
		}
		CHECK_MESSAGE(bad == 0, "a sphere's normals are its normalized positions");
		// The poles are exact; the 33 rows miss the equator, so x/z reach slightly less than 0.5.
		AABB box = sphere->get_aabb();
		CHECK(box.position.y == doctest::Approx(-0.5));
		CHECK(box.size.y == doctest::Approx(1.0));
		CHECK(box.size.x == doctest::Approx(1.0).epsilon(0.01));
		CHECK(box.size.x <= 1.0f);
	}
	SUBCASE("ellipsoid normals are outward gradients") {
		sphere->set("radius", 1.0);
		sphere->set("height", 4.0);
		sphere->set("radial_segments", 8);
		sphere->set("rings", 6);
		RS::SurfaceData s = sphere->get_mesh_arrays();
		CHECK(s.vertices.size() == (size_t)(6 + 2) * (8 + 1));
		check_surface_valid(s);
		check_winding_and_tangents(s);
		for (size_t i = 0; i < s.vertices.size(); i++) {
			const Vector3 &p = s.vertices[i];
			Vector3 gradient = Vector3(p.x, p.y / 4.0f, p.z).normalized();
			CHECK(s.normals[i].is_equal_approx(gradient));
		}
		AABB box = sphere->get_aabb();
		CHECK(box.position.y == doctest::Approx(-2.0));
		CHECK(box.size.y == doctest::Approx(4.0));
		CHECK(box.size.x <= 2.0f);
		CHECK(box.size.x > 1.9f);
	}
}

// Volume enclosed by a closed surface from the divergence theorem; with Godot's clockwise front faces
// seen from outside, the triangles' (b - a) x (c - a) point inwards, hence the minus sign.
static double enclosed_volume(const RS::SurfaceData &p_s) {
	double volume = 0.0;
	for (size_t i = 0; i + 2 < p_s.indices.size(); i += 3) {
		const Vector3 &a = p_s.vertices[p_s.indices[i]], &b = p_s.vertices[p_s.indices[i + 1]], &c = p_s.vertices[p_s.indices[i + 2]];
		volume -= double(a.dot(b.cross(c))) / 6.0;
	}
	return volume;
}

TEST_CASE("[PrimitiveMesh] CylinderMesh, CapsuleMesh, TorusMesh and PrismMesh defaults match Godot 4.7") {
	DummyServer server;
	Ref<CylinderMesh> cylinder;
	cylinder.instantiate();
	CHECK(cylinder->get("top_radius").to_float() == doctest::Approx(0.5));
	CHECK(cylinder->get("bottom_radius").to_float() == doctest::Approx(0.5));
	CHECK(cylinder->get("height").to_float() == doctest::Approx(2.0));
	CHECK(cylinder->get("radial_segments").to_int() == 64);
	CHECK(cylinder->get("rings").to_int() == 4);
	CHECK(cylinder->get("cap_top").to_bool());
	CHECK(cylinder->get("cap_bottom").to_bool());
	Ref<CapsuleMesh> capsule;
	capsule.instantiate();
	CHECK(capsule->get("radius").to_float() == doctest::Approx(0.5));
	CHECK(capsule->get("height").to_float() == doctest::Approx(2.0));
	CHECK(capsule->get("radial_segments").to_int() == 64);
	CHECK(capsule->get("rings").to_int() == 8);
	Ref<TorusMesh> torus;
	torus.instantiate();
	CHECK(torus->get("inner_radius").to_float() == doctest::Approx(0.5));
	CHECK(torus->get("outer_radius").to_float() == doctest::Approx(1.0));
	CHECK(torus->get("rings").to_int() == 64);
	CHECK(torus->get("ring_segments").to_int() == 32);
	Ref<PrismMesh> prism;
	prism.instantiate();
	CHECK(prism->get("left_to_right").to_float() == doctest::Approx(0.5));
	CHECK(Vector3(prism->get("size")) == Vector3(1, 1, 1));
	CHECK(prism->get("subdivide_width").to_int() == 0);
	CHECK(prism->get("subdivide_height").to_int() == 0);
	CHECK(prism->get("subdivide_depth").to_int() == 0);
	for (const char *name : { "CylinderMesh", "CapsuleMesh", "TorusMesh", "PrismMesh" }) {
		CAPTURE(name);
		CHECK(ClassDB::can_instantiate(name));
		CHECK(ClassDB::is_parent_class(name, "PrimitiveMesh"));
	}
}

TEST_CASE("[PrimitiveMesh] CylinderMesh geometry: closed, outward, the volume of a (truncated) cone") {
	DummyServer server;
	Ref<CylinderMesh> cylinder;
	cylinder.instantiate();
	SUBCASE("default cylinder") {
		RS::SurfaceData s = cylinder->get_mesh_arrays();
		CHECK(s.vertices.size() == (size_t)(4 + 2) * (64 + 1) + 2 * (64 + 2));
		check_surface_valid(s);
		CHECK(check_winding_and_tangents(s) == (4 + 1) * 64 * 2 + 2 * 64);
		CHECK(enclosed_volume(s) == doctest::Approx(Math::PI * 0.25 * 2.0).epsilon(0.005));
		AABB box = cylinder->get_aabb();
		CHECK(box.position.y == doctest::Approx(-1.0));
		CHECK(box.size.y == doctest::Approx(2.0));
		CHECK(box.size.x == doctest::Approx(1.0).epsilon(0.001));
	}
	SUBCASE("a cone's side normals tilt by its slope") {
		cylinder->set("top_radius", 0.0);
		cylinder->set("bottom_radius", 1.0);
		cylinder->set("height", 1.0);
		cylinder->set("radial_segments", 32);
		RS::SurfaceData s = cylinder->get_mesh_arrays();
		CHECK(s.vertices.size() == (size_t)(4 + 2) * (32 + 1) + (32 + 2)); // No top cap of radius 0.
		check_surface_valid(s);
		check_winding_and_tangents(s);
		// The slope rises 1 over 1: side normals are 45 degrees up.
		CHECK(s.normals[40].y == doctest::Approx(std::sqrt(0.5)).epsilon(1e-4));
		const double n = 32.0;
		CHECK(enclosed_volume(s) == doctest::Approx(n / 2.0 * std::sin(Math::TAU / n) / 3.0).epsilon(1e-4)); // Pyramid on a 32-gon.
	}
	SUBCASE("without caps the side is open") {
		cylinder->set("cap_top", false);
		cylinder->set("cap_bottom", false);
		CHECK(cylinder->get_mesh_arrays().vertices.size() == (size_t)(4 + 2) * (64 + 1));
	}
}

TEST_CASE("[PrimitiveMesh] CapsuleMesh geometry: hemispheres joined by a cylinder") {
	DummyServer server;
	Ref<CapsuleMesh> capsule;
	capsule.instantiate();
	RS::SurfaceData s = capsule->get_mesh_arrays();
	CHECK(s.vertices.size() == (size_t)2 * (8 + 2) * (64 + 1));
	check_surface_valid(s);
	check_winding_and_tangents(s);
	// Every vertex lies at the radius from the capsule's axis segment, with the normal pointing away from it.
	int bad = 0;
	for (size_t i = 0; i < s.vertices.size(); i++) {
		const Vector3 &p = s.vertices[i];
		const Vector3 on_axis(0, std::clamp(p.y, -0.5f, 0.5f), 0);
		bad += !Math::is_equal_approx((p - on_axis).length(), real_t(0.5), real_t(1e-5));
		bad += !s.normals[i].is_equal_approx((p - on_axis).normalized());
	}
	CHECK(bad == 0);
	CHECK(enclosed_volume(s) == doctest::Approx(Math::PI * 0.25 * 1.0 + 4.0 / 3.0 * Math::PI * 0.125).epsilon(0.01));
	CHECK(capsule->get_aabb().size.y == doctest::Approx(2.0));
	// Godot keeps height >= 2 radius by moving the other value.
	capsule->set("radius", 2.0);
	CHECK(capsule->get_height() == doctest::Approx(4.0));
	capsule->set("height", 1.0);
	CHECK(capsule->get_radius() == doctest::Approx(0.5));
}

TEST_CASE("[PrimitiveMesh] TorusMesh geometry: Pappus's volume, radii in either order") {
	DummyServer server;
	Ref<TorusMesh> torus;
	torus.instantiate();
	RS::SurfaceData s = torus->get_mesh_arrays();
	CHECK(s.vertices.size() == (size_t)(64 + 1) * (32 + 1));
	check_surface_valid(s);
	CHECK(check_winding_and_tangents(s) == 64 * 32 * 2);
	// Tube radius 0.25 around a circle of radius 0.75: V = 2 pi^2 R r^2.
	CHECK(enclosed_volume(s) == doctest::Approx(2.0 * Math::PI * Math::PI * 0.75 * 0.0625).epsilon(0.02));
	AABB box = torus->get_aabb();
	CHECK(box.size.y == doctest::Approx(0.5).epsilon(0.001));
	CHECK(box.size.x == doctest::Approx(2.0).epsilon(0.001));
	torus->set("inner_radius", 1.0);
	torus->set("outer_radius", 0.5);
	CHECK(enclosed_volume(torus->get_mesh_arrays()) == doctest::Approx(enclosed_volume(s)));
}

TEST_CASE("[PrimitiveMesh] PrismMesh geometry: a closed triangular prism, subdivided or not") {
	DummyServer server;
	Ref<PrismMesh> prism;
	prism.instantiate();
	SUBCASE("default prism") {
		RS::SurfaceData s = prism->get_mesh_arrays();
		check_surface_valid(s);
		CHECK(check_winding_and_tangents(s) == 2 * 1 + 2 * 2 + 2); // Ends (one real triangle each), slopes, base.
		CHECK(enclosed_volume(s) == doctest::Approx(0.5));
		CHECK(prism->get_aabb().is_equal_approx(AABB(Vector3(-0.5f, -0.5f, -0.5f), Vector3(1, 1, 1))));
	}
	SUBCASE("apex over the left edge, subdivided, other size") {
		prism->set("left_to_right", 0.0);
		prism->set("size", Vector3(2, 3, 4));
		prism->set("subdivide_width", 2);
		prism->set("subdivide_height", 3);
		prism->set("subdivide_depth", 1);
		RS::SurfaceData s = prism->get_mesh_arrays();
		check_surface_valid(s);
		check_winding_and_tangents(s);
		CHECK(enclosed_volume(s) == doctest::Approx(2.0 * 3.0 * 4.0 / 2.0));
		// The left face is vertical: its normals are -X.
		int left = 0;
		for (size_t i = 0; i < s.normals.size(); i++) {
			left += s.normals[i].is_equal_approx(Vector3(-1, 0, 0));
		}
		CHECK(left == (1 + 1 + 1) * (3 + 1 + 1)); // (subdivide_depth + 2) x (subdivide_height + 2) vertices.
	}
}

static const char *ROUND_MESHES_SCENE = R"([gd_scene load_steps=5 format=3 uid="uid://c7prim1t1ves"]

[sub_resource type="CylinderMesh" id="CylinderMesh_a1b2c"]
top_radius = 0.2
height = 1.5
cap_bottom = false

[sub_resource type="CapsuleMesh" id="CapsuleMesh_d3e4f"]
radius = 0.3
radial_segments = 16

[sub_resource type="TorusMesh" id="TorusMesh_g5h6i"]
inner_radius = 0.8
rings = 24

[sub_resource type="PrismMesh" id="PrismMesh_j7k8l"]
left_to_right = 0.25
size = Vector3(2, 1, 0.5)

[node name="Shapes" type="Node3D"]

[node name="Cylinder" type="MeshInstance3D" parent="."]
mesh = SubResource("CylinderMesh_a1b2c")

[node name="Capsule" type="MeshInstance3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0, 0)
mesh = SubResource("CapsuleMesh_d3e4f")

[node name="Torus" type="MeshInstance3D" parent="."]
mesh = SubResource("TorusMesh_g5h6i")

[node name="Prism" type="MeshInstance3D" parent="."]
mesh = SubResource("PrismMesh_j7k8l")
)";

TEST_CASE("[PrimitiveMesh][TSCN] a scene's CylinderMesh, CapsuleMesh, TorusMesh and PrismMesh load as meshes and save back unchanged") {
	DummyServer server;
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(ROUND_MESHES_SCENE, "shapes.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(error.empty());
	auto mesh_of = [&](const char *p_node) {
		Node *node = root->get_node_or_null(p_node);
		REQUIRE(node != nullptr);
		return Ref<Resource>(node->get("mesh"));
	};
	Ref<CylinderMesh> cylinder = mesh_of("Cylinder");
	REQUIRE(cylinder.is_valid());
	CHECK(cylinder->get_top_radius() == doctest::Approx(0.2));
	CHECK(cylinder->get_bottom_radius() == doctest::Approx(0.5));
	CHECK_FALSE(cylinder->is_cap_bottom());
	CHECK(cylinder->get_aabb().size.y == doctest::Approx(1.5));
	Ref<CapsuleMesh> capsule = mesh_of("Capsule");
	REQUIRE(capsule.is_valid());
	CHECK(capsule->get_radial_segments() == 16);
	Ref<TorusMesh> torus = mesh_of("Torus");
	REQUIRE(torus.is_valid());
	CHECK(torus->get_rings() == 24);
	Ref<PrismMesh> prism = mesh_of("Prism");
	REQUIRE(prism.is_valid());
	CHECK(prism->get_size() == Vector3(2, 1, 0.5));
	CHECK(prism->get_aabb().size.x == doctest::Approx(2.0));
	CHECK(ResourceFormatText::save_scene_to_string(root) == String(ROUND_MESHES_SCENE));
	cylinder.unref();
	capsule.unref();
	torus.unref();
	prism.unref();
	delete root;
}

TEST_CASE("[PrimitiveMesh] the new primitives reject bad parameters and keep the old value") {
	DummyServer server;
	ErrorCatcher errors;
	Ref<CylinderMesh> cylinder;
	cylinder.instantiate();
	cylinder->set("top_radius", -1.0);
	cylinder->set("height", 0.0);
	cylinder->set("radial_segments", 3);
	CHECK(cylinder->get_top_radius() == doctest::Approx(0.5));
	CHECK(cylinder->get_height() == doctest::Approx(2.0));
	CHECK(cylinder->get_radial_segments() == 64);
	CHECK(errors.contains("top_radius"));
	Ref<TorusMesh> torus;
	torus.instantiate();
	torus->set("rings", 2);
	torus->set("outer_radius", INFINITY);
	CHECK(torus->get_rings() == 64);
	CHECK(torus->get_outer_radius() == doctest::Approx(1.0));
	CHECK(errors.contains("outer_radius"));
	Ref<PrismMesh> prism;
	prism.instantiate();
	prism->set("left_to_right", 1.5);
	CHECK(prism->get_left_to_right() == doctest::Approx(0.5));
	CHECK(errors.contains("left_to_right"));
	Ref<CapsuleMesh> capsule;
	capsule.instantiate();
	capsule->set("radius", 0.0);
	CHECK(capsule->get_radius() == doctest::Approx(0.5));
}

TEST_CASE("[PrimitiveMesh] bad parameters are rejected with a message; the old value is kept") {
	DummyServer server;
	ErrorCatcher errors;
	Ref<SphereMesh> sphere;
	sphere.instantiate();
	sphere->set("radius", -1.0);
	sphere->set("height", NAN);
	sphere->set("radial_segments", 2);
	sphere->set("rings", 0);
	CHECK(sphere->get_radius() == doctest::Approx(0.5));
	CHECK(sphere->get_height() == doctest::Approx(1.0));
	CHECK(sphere->get_radial_segments() == 64);
	CHECK(sphere->get_rings() == 32);
	CHECK(errors.contains("radius"));
	CHECK(errors.contains("radial_segments"));

	Ref<BoxMesh> box;
	box.instantiate();
	box->set("size", Vector3(1, -1, 1));
	box->set("subdivide_width", -1);
	box->set("subdivide_depth", 1000000);
	CHECK(box->get_size() == Vector3(1, 1, 1));
	CHECK(box->get_subdivide_width() == 0);
	CHECK(box->get_subdivide_depth() == 0);
	CHECK(errors.contains("subdivide_depth"));

	Ref<PlaneMesh> plane;
	plane.instantiate();
	plane->set("orientation", 5);
	CHECK(plane->get_orientation() == PlaneMesh::FACE_Y);
}

TEST_CASE("[PrimitiveMesh] the server receives the generated surface and material") {
	DummyServer server;
	RS *rs = RS::get_singleton();
	Ref<BoxMesh> box;
	box.instantiate();
	Ref<StandardMaterial3D> mat;
	mat.instantiate();
	box->set("material", mat);
	RID rid = box->get_rid();
	REQUIRE(rid.is_valid());
	CHECK(rs->mesh_get_surface_count(rid) == 1);
	CHECK(rs->mesh_get_aabb(rid).is_equal_approx(AABB(Vector3(-0.5f, -0.5f, -0.5f), Vector3(1, 1, 1))));
	CHECK(rs->mesh_surface_get_material(rid, 0) == mat->get_rid());
	box->set_size(Vector3(2, 2, 2));
	CHECK(box->get_rid() == rid);
	CHECK_MESSAGE(rs->mesh_get_surface_count(rid) == 1, "regenerating replaces the surface");
	CHECK(rs->mesh_get_aabb(rid).is_equal_approx(AABB(Vector3(-1, -1, -1), Vector3(2, 2, 2))));
}

TEST_CASE("[PrimitiveMesh] ArrayMesh validates surfaces and merges AABBs") {
	DummyServer server;
	ErrorCatcher errors;
	Ref<ArrayMesh> mesh;
	mesh.instantiate();
	RS::SurfaceData a;
	PlaneMesh::create_plane_arrays(a, Vector2(2, 2), 0, 0, Vector3(), PlaneMesh::FACE_Y);
	CHECK(mesh->add_surface(a));
	RS::SurfaceData b;
	BoxMesh::create_box_arrays(b, Vector3(1, 1, 1), 0, 0, 0);
	for (Vector3 &v : b.vertices) {
		v += Vector3(0, 3, 0);
	}
	CHECK(mesh->add_surface_from_arrays(Mesh::PRIMITIVE_TRIANGLES, b));
	CHECK(mesh->get_surface_count() == 2);
	CHECK(mesh->get_aabb().is_equal_approx(AABB(Vector3(-1, 0, -1), Vector3(2, 3.5f, 2))));
	CHECK(RS::get_singleton()->mesh_get_surface_count(mesh->get_rid()) == 2);

	RS::SurfaceData bad = a;
	bad.indices[0] = 99;
	CHECK_FALSE(mesh->add_surface(bad));
	CHECK(errors.contains("out of range"));
	bad = a;
	bad.normals.pop_back();
	CHECK_FALSE(mesh->add_surface(bad));
	CHECK_FALSE(mesh->add_surface_from_arrays(Mesh::PRIMITIVE_LINES, a));
	CHECK(mesh->get_surface_count() == 2);
}

} // namespace TestPrimitiveMeshes
