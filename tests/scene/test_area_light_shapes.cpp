/**************************************************************************/
/*  test_area_light_shapes.cpp                                            */
/**************************************************************************/
/* AreaLight3D::area_shape (RECTANGLE, DISK, SPHERE, TUBE): enum values   */
/* equal the server's, the default, validation, forwarding to the server, */
/* the .tscn round trip, the per-shape AABB (the same box as the          */
/* server's), the culling radius, the emitting area, the zero-size        */
/* warnings and the warning for an area_texture on a non-rectangle.       */
/* Dummy server.                                                          */

#include "scene/3d/light_3d.h"

#include "core/math/math_funcs.h"
#include "scene/resources/resource_format_text.h"
#include "scene/resources/texture.h"
#include "servers/rendering/rendering_server_globals.h"
#include "servers/rendering/storage/light_storage.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

namespace TestAreaLightShapes {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

TEST_CASE("[AreaLight3D] area_shape: enum values, default, validation and the server") {
	DummyServer server;
	CHECK((int)AreaLight3D::AREA_SHAPE_RECTANGLE == 0);
	CHECK((int)AreaLight3D::AREA_SHAPE_DISK == 1);
	CHECK((int)AreaLight3D::AREA_SHAPE_SPHERE == 2);
	CHECK((int)AreaLight3D::AREA_SHAPE_TUBE == 3);
	CHECK((int)RS::LIGHT_AREA_SHAPE_TUBE == 3);
	CHECK(ClassDB::get_integer_constant("AreaLight3D", "AREA_SHAPE_SPHERE") == 2);

	ErrorCatcher errors;
	AreaLight3D *light = new AreaLight3D;
	RID rid = light->get_light();
	CHECK(light->get_area_shape() == AreaLight3D::AREA_SHAPE_RECTANGLE);
	CHECK(RSG::light_storage->light_area_get_shape(rid) == RS::LIGHT_AREA_SHAPE_RECTANGLE);
	light->set("area_shape", 2);
	CHECK(light->get_area_shape() == AreaLight3D::AREA_SHAPE_SPHERE);
	CHECK(int(light->get("area_shape")) == 2);
	CHECK(RSG::light_storage->light_area_get_shape(rid) == RS::LIGHT_AREA_SHAPE_SPHERE);
	light->set("area_shape", 7);
	CHECK(light->get_area_shape() == AreaLight3D::AREA_SHAPE_SPHERE);
	CHECK(errors.contains("area_shape"));
	CHECK(errors.contains("got 7"));
	// The server rejects bad values on its own too.
	RSG::light_storage->light_area_set_shape(rid, RS::LightAreaShape(-1));
	CHECK(RSG::light_storage->light_area_get_shape(rid) == RS::LIGHT_AREA_SHAPE_SPHERE);
	CHECK(errors.contains("LightAreaShape"));

	std::vector<PropertyInfo> list;
	light->get_property_list(&list);
	const PropertyInfo *shape = nullptr;
	for (const PropertyInfo &p : list) {
		if (p.name == "area_shape" && !p.is_group_marker()) {
			shape = &p;
		}
	}
	REQUIRE(shape);
	CHECK(shape->type == Variant::INT);
	CHECK(shape->hint == PROPERTY_HINT_ENUM);
	CHECK(shape->hint_string == "Rectangle,Disk,Sphere,Tube");
	delete light;
}

TEST_CASE("[AreaLight3D] a scene file with every area_shape round-trips; the rectangle is not written") {
	DummyServer server;
	const String text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Disk" type="AreaLight3D" parent="."]
area_shape = 1
area_size = Vector2(0.5, 0.25)

[node name="Sphere" type="AreaLight3D" parent="."]
area_shape = 2
area_size = Vector2(0.2, 0)

[node name="Tube" type="AreaLight3D" parent="."]
area_shape = 3
area_size = Vector2(1.5, 0.1)

[node name="Rect" type="AreaLight3D" parent="."]
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "shapes.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	const char *names[4] = { "Disk", "Sphere", "Tube", "Rect" };
	const AreaLight3D::AreaShape expected[4] = { AreaLight3D::AREA_SHAPE_DISK, AreaLight3D::AREA_SHAPE_SPHERE, AreaLight3D::AREA_SHAPE_TUBE, AreaLight3D::AREA_SHAPE_RECTANGLE };
	for (int i = 0; i < 4; i++) {
		CAPTURE(i);
		AreaLight3D *l = Object::cast_to<AreaLight3D>(root->get_node_or_null(names[i]));
		REQUIRE(l != nullptr);
		CHECK(l->get_area_shape() == expected[i]);
		CHECK(RSG::light_storage->light_area_get_shape(l->get_light()) == RS::LightAreaShape(expected[i]));
	}
	// A sphere with area_size.y == 0 is a complete light (y is unused): no zero-size warning.
	CHECK(Object::cast_to<AreaLight3D>(root->get_node_or_null("Sphere"))->get_configuration_warnings().empty());
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK_MESSAGE(saved == text, (String("saved text:\n") + saved));
	delete root;
}

TEST_CASE("[AreaLight3D] each shape's AABB, culling radius and emitting area") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	light->set("area_range", 2.0);

	// Disk: one-sided like the rectangle, the same box in front of it.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_DISK);
	light->set_area_size(Vector2(3, 1));
	AABB box = light->get_aabb();
	CHECK(box.position.is_equal_approx(Vector3(-3.5f, -2.5f, -2)));
	CHECK(box.size.is_equal_approx(Vector3(7, 5, 2)));
	CHECK(RS::get_singleton()->light_get_aabb(light->get_light()).is_equal_approx(box));

	// Sphere (diameter 1): lit all around, a cube of half side r + range.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_SPHERE);
	light->set_area_size(Vector2(1, 0));
	box = light->get_aabb();
	CHECK(box.position.is_equal_approx(Vector3(-2.5f, -2.5f, -2.5f)));
	CHECK(box.size.is_equal_approx(Vector3(5, 5, 5)));
	CHECK(box.has_point(Vector3(0, 0, 2.4f))); // Behind the node's -Z: lit too.
	CHECK(RS::get_singleton()->light_get_aabb(light->get_light()).is_equal_approx(box));

	// Tube (segment 3 along X, diameter 1): the capsule grown by the range on every side.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_TUBE);
	light->set_area_size(Vector2(3, 1));
	box = light->get_aabb();
	CHECK(box.position.is_equal_approx(Vector3(-4.0f, -2.5f, -2.5f)));
	CHECK(box.size.is_equal_approx(Vector3(8, 5, 5)));
	CHECK(RS::get_singleton()->light_get_aabb(light->get_light()).is_equal_approx(box));

	// Culling sphere radius: range + the farthest point of the shape from its centre.
	CHECK(RendererLightStorage::compute_area_light_cull_radius(2.0f, Vector2(3, 4), RS::LIGHT_AREA_SHAPE_RECTANGLE) == doctest::Approx(4.5));
	CHECK(RendererLightStorage::compute_area_light_cull_radius(2.0f, Vector2(3, 4), RS::LIGHT_AREA_SHAPE_DISK) == doctest::Approx(4.0));
	CHECK(RendererLightStorage::compute_area_light_cull_radius(2.0f, Vector2(3, 4), RS::LIGHT_AREA_SHAPE_SPHERE) == doctest::Approx(3.5));
	CHECK(RendererLightStorage::compute_area_light_cull_radius(2.0f, Vector2(3, 4), RS::LIGHT_AREA_SHAPE_TUBE) == doctest::Approx(5.5));

	// Emitting areas (area_normalize_energy divides by them).
	const double pi = Math::PI;
	CHECK(RendererLightStorage::compute_area_light_emitting_area(Vector2(2, 3), RS::LIGHT_AREA_SHAPE_RECTANGLE) == doctest::Approx(6.0));
	CHECK(RendererLightStorage::compute_area_light_emitting_area(Vector2(2, 3), RS::LIGHT_AREA_SHAPE_DISK) == doctest::Approx(pi * 1.5));
	CHECK(RendererLightStorage::compute_area_light_emitting_area(Vector2(2, 3), RS::LIGHT_AREA_SHAPE_SPHERE) == doctest::Approx(4.0 * pi));
	// Capsule: cylinder 2 pi r l + sphere 4 pi r^2 with r = 1.5, l = 2.
	CHECK(RendererLightStorage::compute_area_light_emitting_area(Vector2(2, 3), RS::LIGHT_AREA_SHAPE_TUBE) == doctest::Approx(2.0 * pi * 1.5 * 2.0 + 4.0 * pi * 1.5 * 1.5));
	delete light;
}

TEST_CASE("[AreaLight3D] zero-size warnings follow the shape's meaning of area_size") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	light->set_area_size(Vector2(1, 0));
	CHECK(light->get_configuration_warnings().size() == 1); // Rectangle: zero height.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_SPHERE);
	CHECK(light->get_configuration_warnings().empty()); // Sphere: only the diameter x counts.
	light->set_area_size(Vector2(0, 1));
	CHECK(light->get_configuration_warnings().size() == 1);
	light->set_area_shape(AreaLight3D::AREA_SHAPE_TUBE);
	CHECK(light->get_configuration_warnings().empty()); // Tube of length 0: a sphere of diameter y.
	light->set_area_size(Vector2(1, 0));
	CHECK(light->get_configuration_warnings().size() == 1);
	delete light;
}

TEST_CASE("[AreaLight3D] an area_texture on a disk, sphere or tube is warned about (rectangles only)") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	Ref<ImageTexture> texture = ImageTexture::create_from_image(Image(2, 2, Color(1, 0.5f, 0.25f, 1)));
	REQUIRE(texture.is_valid());
	light->set_area_texture(texture);
	CHECK(light->get_configuration_warnings().empty()); // A textured rectangle: upstream's case.
	const AreaLight3D::AreaShape shapes[3] = { AreaLight3D::AREA_SHAPE_DISK, AreaLight3D::AREA_SHAPE_SPHERE, AreaLight3D::AREA_SHAPE_TUBE };
	for (AreaLight3D::AreaShape shape : shapes) {
		CAPTURE(int(shape));
		light->set_area_shape(shape);
		const std::vector<String> warnings = light->get_configuration_warnings();
		REQUIRE(warnings.size() == 1);
		CHECK(warnings[0].find("area_texture") != String::npos);
		CHECK(warnings[0].find("untextured") != String::npos);
		// The texture is kept (saved, forwarded): switching back to a rectangle textures it again.
		CHECK(light->get_area_texture() == texture);
	}
	light->set_area_texture(Ref<Texture2D>());
	CHECK(light->get_configuration_warnings().empty()); // An untextured tube.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_RECTANGLE);
	light->set_area_texture(texture);
	CHECK(light->get_configuration_warnings().empty());
	delete light;
}

} // namespace TestAreaLightShapes
