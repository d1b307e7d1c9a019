/**************************************************************************/
/*  test_light_3d.cpp                                                     */
/**************************************************************************/
/* Light3D, OmniLight3D, SpotLight3D, DirectionalLight3D: Godot 4.7       */
/* defaults, property access by name, rejection of bad values, property   */
/* list order and groups, per-type AABB, server forwarding.               */

#include "scene/3d/light_3d.h"

#include "scene/main/scene_tree.h"
#include "scene/resources/resource_format_text.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestLight3D {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

static bool approx(const Variant &p_v, double p_expected) {
	return Math::is_equal_approx((real_t)p_v.to_float(), (real_t)p_expected);
}

static int index_of(const std::vector<PropertyInfo> &p_list, const String &p_name) {
	for (size_t i = 0; i < p_list.size(); i++) {
		if (!p_list[i].is_group_marker() && p_list[i].name == p_name) {
			return (int)i;
		}
	}
	return -1;
}

static const PropertyInfo *find(const std::vector<PropertyInfo> &p_list, const String &p_name) {
	int i = index_of(p_list, p_name);
	return i < 0 ? nullptr : &p_list[i];
}

TEST_CASE("[Light3D] Param and enum values equal the RenderingServer's") {
	CHECK((int)Light3D::PARAM_ENERGY == (int)RS::LIGHT_PARAM_ENERGY);
	CHECK((int)Light3D::PARAM_RANGE == (int)RS::LIGHT_PARAM_RANGE);
	CHECK((int)Light3D::PARAM_SPOT_ANGLE == (int)RS::LIGHT_PARAM_SPOT_ANGLE);
	CHECK((int)Light3D::PARAM_SHADOW_BIAS == (int)RS::LIGHT_PARAM_SHADOW_BIAS);
	CHECK((int)Light3D::PARAM_INTENSITY == (int)RS::LIGHT_PARAM_INTENSITY);
	CHECK((int)Light3D::PARAM_MAX == (int)RS::LIGHT_PARAM_MAX);
	// Godot 4.7 order (saved as integers).
	CHECK((int)Light3D::PARAM_SHADOW_NORMAL_BIAS == 14);
	CHECK((int)Light3D::PARAM_INTENSITY == 20);
	CHECK((int)OmniLight3D::SHADOW_CUBE == 1);
	CHECK((int)DirectionalLight3D::SHADOW_PARALLEL_4_SPLITS == 2);
	CHECK((int)Light3D::BAKE_DYNAMIC == 2);

	DummyServer server;
	CHECK(ClassDB::get_integer_constant("Light3D", "PARAM_SPOT_ATTENUATION") == RS::LIGHT_PARAM_SPOT_ATTENUATION);
	CHECK(ClassDB::get_integer_constant_enum("Light3D", "PARAM_ENERGY") == "Param");
	CHECK(ClassDB::get_integer_constant("OmniLight3D", "SHADOW_DUAL_PARABOLOID") == 0);
}

TEST_CASE("[Light3D] Light3D is abstract; the leaves are instantiable") {
	DummyServer server;
	ErrorCatcher errors;
	CHECK_FALSE(ClassDB::can_instantiate("Light3D"));
	CHECK(ClassDB::is_parent_class("SpotLight3D", "Light3D"));
	CHECK(ClassDB::is_parent_class("OmniLight3D", "VisualInstance3D"));
	for (const char *name : { "OmniLight3D", "SpotLight3D", "DirectionalLight3D" }) {
		Object *obj = ClassDB::instantiate(name);
		REQUIRE_MESSAGE(obj != nullptr, "concrete light classes must be instantiable by name");
		CHECK(obj->get_class() == name);
		CHECK(Object::cast_to<Light3D>(obj) != nullptr);
		delete obj;
	}
}

TEST_CASE("[OmniLight3D] defaults match Godot 4.7 and reach the server") {
	DummyServer server;
	OmniLight3D *light = new OmniLight3D;

	CHECK(Color(light->get("light_color")) == Color(1, 1, 1, 1));
	CHECK(approx(light->get("light_energy"), 1.0));
	CHECK(approx(light->get("light_indirect_energy"), 1.0));
	CHECK(approx(light->get("light_volumetric_fog_energy"), 1.0));
	CHECK(light->get("light_negative").to_bool() == false);
	CHECK(approx(light->get("light_specular"), 0.5));
	CHECK(approx(light->get("light_size"), 0.0));
	CHECK(light->get("light_bake_mode").to_int() == Light3D::BAKE_DYNAMIC);
	CHECK((uint32_t)light->get("light_cull_mask").to_int() == 0xFFFFFFFFu);
	CHECK(light->get("shadow_enabled").to_bool() == false);
	CHECK(approx(light->get("shadow_bias"), 0.1));
	CHECK(approx(light->get("shadow_normal_bias"), 1.0));
	CHECK(light->get("shadow_reverse_cull_face").to_bool() == false);
	CHECK(approx(light->get("shadow_transmittance_bias"), 0.05));
	CHECK(approx(light->get("shadow_opacity"), 1.0));
	CHECK(approx(light->get("shadow_blur"), 1.0));
	CHECK(light->get("distance_fade_enabled").to_bool() == false);
	CHECK(approx(light->get("distance_fade_begin"), 40.0));
	CHECK(light->get("editor_only").to_bool() == false);
	CHECK(approx(light->get("omni_range"), 5.0));
	CHECK(approx(light->get("omni_attenuation"), 1.0));
	CHECK(light->get("omni_shadow_mode").to_int() == OmniLight3D::SHADOW_CUBE);
	CHECK(approx(light->get("light_intensity_lumens"), 1000.0));
	CHECK(approx(light->get("light_temperature"), 6500.0));

	RS *rs = RS::get_singleton();
	CHECK(rs->light_get_type(light->get_light()) == RS::LIGHT_OMNI);
	CHECK_MESSAGE(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_RANGE) == doctest::Approx(5.0), "node defaults are pushed to the server, not left at storage defaults");
	CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_SHADOW_BIAS) == doctest::Approx(0.1));
	CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_SPECULAR) == doctest::Approx(0.5));
	delete light;
}

TEST_CASE("[SpotLight3D] defaults match Godot 4.7 (lower shadow bias)") {
	DummyServer server;
	SpotLight3D *light = new SpotLight3D;
	CHECK(approx(light->get("spot_range"), 5.0));
	CHECK(approx(light->get("spot_attenuation"), 1.0));
	CHECK(approx(light->get("spot_angle"), 45.0));
	CHECK(approx(light->get("spot_angle_attenuation"), 1.0));
	CHECK(approx(light->get("shadow_bias"), 0.03));
	CHECK(approx(light->get("shadow_normal_bias"), 1.0));
	CHECK(approx(light->get("light_energy"), 1.0));
	CHECK(RS::get_singleton()->light_get_type(light->get_light()) == RS::LIGHT_SPOT);
	CHECK(RS::get_singleton()->light_get_param(light->get_light(), RS::LIGHT_PARAM_SPOT_ANGLE) == doctest::Approx(45.0));
	CHECK(RS::get_singleton()->light_get_param(light->get_light(), RS::LIGHT_PARAM_SHADOW_BIAS) == doctest::Approx(0.03));
	delete light;
}

TEST_CASE("[DirectionalLight3D] defaults match Godot 4.7") {
	DummyServer server;
	DirectionalLight3D *light = new DirectionalLight3D;
	CHECK(light->get("directional_shadow_mode").to_int() == DirectionalLight3D::SHADOW_PARALLEL_4_SPLITS);
	CHECK(approx(light->get("directional_shadow_split_1"), 0.1));
	CHECK(approx(light->get("directional_shadow_split_2"), 0.2));
	CHECK(approx(light->get("directional_shadow_split_3"), 0.5));
	CHECK(light->get("directional_shadow_blend_splits").to_bool() == false);
	CHECK(approx(light->get("directional_shadow_fade_start"), 0.8));
	CHECK(approx(light->get("directional_shadow_max_distance"), 100.0));
	CHECK(approx(light->get("directional_shadow_pancake_size"), 20.0));
	CHECK(approx(light->get("shadow_normal_bias"), 2.0));
	CHECK(approx(light->get("shadow_bias"), 0.1));
	CHECK(approx(light->get("light_angular_distance"), 0.0));
	CHECK(approx(light->get("light_intensity_lux"), 100000.0));
	CHECK(light->get("sky_mode").to_int() == DirectionalLight3D::SKY_MODE_LIGHT_AND_SKY);
	delete light;
}

TEST_CASE("[Light3D] set and get by property name, as the scene loader does") {
	DummyServer server;
	RS *rs = RS::get_singleton();

	SUBCASE("OmniLight3D") {
		OmniLight3D *light = new OmniLight3D;
		bool valid = false;
		light->set("omni_range", 12.5, &valid);
		CHECK(valid);
		light->set("light_energy", 3.0);
		light->set("light_color", Color(1, 0.5, 0.25));
		light->set("shadow_enabled", true);
		light->set("shadow_bias", 0.25);
		light->set("omni_attenuation", -2.0);
		light->set("omni_shadow_mode", 0);
		light->set("light_cull_mask", 5);
		CHECK(light->get_param(Light3D::PARAM_RANGE) == doctest::Approx(12.5));
		CHECK(approx(light->get("omni_range"), 12.5));
		CHECK(light->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(3.0));
		CHECK(light->get_color() == Color(1, 0.5, 0.25));
		CHECK(light->has_shadow());
		CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(-2.0));
		CHECK(light->get_shadow_mode() == OmniLight3D::SHADOW_DUAL_PARABOLOID);
		CHECK(light->get_cull_mask() == 5u);
		CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_RANGE) == doctest::Approx(12.5));
		CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_ENERGY) == doctest::Approx(3.0));
		CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_SHADOW_BIAS) == doctest::Approx(0.25));
		delete light;
	}
	SUBCASE("SpotLight3D") {
		SpotLight3D *light = new SpotLight3D;
		light->set("spot_angle", 30.0);
		light->set("spot_range", 8.0);
		light->set("spot_angle_attenuation", 0.5);
		CHECK(light->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(30.0));
		CHECK(light->get_param(Light3D::PARAM_RANGE) == doctest::Approx(8.0));
		CHECK(light->get_param(Light3D::PARAM_SPOT_ATTENUATION) == doctest::Approx(0.5));
		CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_SPOT_ANGLE) == doctest::Approx(30.0));
		delete light;
	}
	SUBCASE("unknown names are reported, not crashed on") {
		ErrorCatcher errors;
		OmniLight3D *light = new OmniLight3D;
		bool valid = true;
		light->set("spot_angle", 10.0, &valid);
		CHECK_FALSE_MESSAGE(valid, "spot_angle is not a property of OmniLight3D");
		CHECK(light->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(45.0));
		delete light;
	}
}

TEST_CASE("[Light3D] invalid values are rejected with a message naming the property; the old value is kept") {
	DummyServer server;
	ErrorCatcher errors;
	RS *rs = RS::get_singleton();

	SUBCASE("NaN energy") {
		OmniLight3D *light = new OmniLight3D;
		light->set("light_energy", std::nan(""));
		CHECK(light->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(1.0));
		CHECK(errors.contains("light_energy"));
		CHECK(rs->light_get_param(light->get_light(), RS::LIGHT_PARAM_ENERGY) == doctest::Approx(1.0));
		delete light;
	}
	SUBCASE("infinite and negative range") {
		OmniLight3D *light = new OmniLight3D;
		light->set_param(Light3D::PARAM_RANGE, INFINITY);
		CHECK(errors.contains("omni_range"));
		light->set("omni_range", -3.0);
		CHECK(light->get_param(Light3D::PARAM_RANGE) == doctest::Approx(5.0));
		CHECK(errors.contains("must not be negative"));
		delete light;
	}
	SUBCASE("spot angle beyond 180 degrees") {
		SpotLight3D *light = new SpotLight3D;
		light->set("spot_angle", 200.0);
		CHECK(light->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(45.0));
		CHECK(errors.contains("spot_angle"));
		delete light;
	}
	SUBCASE("shadow opacity above 1 and a negative spot range") {
		SpotLight3D *light = new SpotLight3D;
		light->set("shadow_opacity", 2.0);
		CHECK(light->get_param(Light3D::PARAM_SHADOW_OPACITY) == doctest::Approx(1.0));
		CHECK(errors.contains("shadow_opacity"));
		light->set("spot_range", -1.0);
		CHECK(errors.contains("spot_range"));
		CHECK(light->get_param(Light3D::PARAM_RANGE) == doctest::Approx(5.0));
		delete light;
	}
	SUBCASE("out-of-range Param index and bad enum") {
		OmniLight3D *light = new OmniLight3D;
		light->set_param(Light3D::Param(99), 1.0f);
		CHECK(light->get_param(Light3D::Param(-1)) == 0.0f);
		light->set("omni_shadow_mode", 7);
		CHECK(light->get_shadow_mode() == OmniLight3D::SHADOW_CUBE);
		CHECK(errors.contains("omni_shadow_mode"));
		delete light;
	}
	SUBCASE("attenuation may be negative") {
		OmniLight3D *light = new OmniLight3D;
		size_t before = errors.messages.size();
		light->set("omni_attenuation", -4.0);
		CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(-4.0));
		CHECK(errors.messages.size() == before);
		delete light;
	}
}

TEST_CASE("[Light3D] property list order, groups and visibility follow Godot 4.7") {
	DummyServer server;
	OmniLight3D *light = new OmniLight3D;
	std::vector<PropertyInfo> list;
	light->get_property_list(&list);

	// Group prefixes: every property inside a prefixed group starts with the prefix.
	String prefix;
	bool saw_light = false, saw_shadow = false, saw_omni = false;
	for (const PropertyInfo &p : list) {
		if (p.usage & PROPERTY_USAGE_GROUP) {
			prefix = p.hint_string;
			saw_light |= p.name == "Light" && p.hint_string == "light_";
			saw_shadow |= p.name == "Shadow" && p.hint_string == "shadow_";
			saw_omni |= p.name == "Omni" && p.hint_string == "omni_";
			continue;
		}
		if (!prefix.empty()) {
			CHECK_MESSAGE(string_begins_with(p.name, prefix), (String("property ") + p.name + " must start with its group prefix " + prefix));
		}
	}
	CHECK(saw_light);
	CHECK(saw_shadow);
	CHECK(saw_omni);

	// Declaration order.
	CHECK(index_of(list, "transform") < index_of(list, "layers"));
	CHECK(index_of(list, "layers") < index_of(list, "light_color"));
	CHECK(index_of(list, "light_color") < index_of(list, "light_energy"));
	CHECK(index_of(list, "light_energy") < index_of(list, "light_indirect_energy"));
	CHECK(index_of(list, "light_specular") < index_of(list, "light_cull_mask"));
	CHECK(index_of(list, "light_cull_mask") < index_of(list, "shadow_enabled"));
	CHECK(index_of(list, "shadow_enabled") < index_of(list, "shadow_bias"));
	CHECK(index_of(list, "shadow_blur") < index_of(list, "editor_only"));
	CHECK(index_of(list, "editor_only") < index_of(list, "omni_range"));
	CHECK(index_of(list, "omni_range") < index_of(list, "omni_attenuation"));
	CHECK(index_of(list, "omni_attenuation") < index_of(list, "omni_shadow_mode"));

	// Hints.
	const PropertyInfo *energy = find(list, "light_energy");
	REQUIRE(energy);
	CHECK(energy->hint == PROPERTY_HINT_RANGE);
	CHECK(energy->hint_string == "0,16,0.001,or_greater");
	const PropertyInfo *color = find(list, "light_color");
	REQUIRE(color);
	CHECK(color->hint == PROPERTY_HINT_COLOR_NO_ALPHA);
	CHECK(find(list, "light_cull_mask")->hint == PROPERTY_HINT_LAYERS_3D_RENDER);
	CHECK(find(list, "omni_shadow_mode")->hint_string == "Dual Paraboloid,Cube");

	// Shadow properties are saved but hidden while shadows are off.
	CHECK(find(list, "shadow_bias")->usage == PROPERTY_USAGE_NO_EDITOR);
	CHECK(find(list, "shadow_enabled")->usage == PROPERTY_USAGE_DEFAULT);
	// Directional-only and physical-unit properties are neither shown nor saved on an omni light.
	CHECK(find(list, "light_angular_distance")->usage == PROPERTY_USAGE_NONE);
	CHECK(find(list, "light_intensity_lux")->usage == PROPERTY_USAGE_NONE);
	CHECK(find(list, "light_temperature")->usage == PROPERTY_USAGE_NONE);
	CHECK(find(list, "light_size")->usage == PROPERTY_USAGE_DEFAULT);

	uint32_t changes = light->get_property_list_changed_count();
	light->set_shadow(true);
	CHECK_MESSAGE(light->get_property_list_changed_count() > changes, "set_shadow must call notify_property_list_changed");
	list.clear();
	light->get_property_list(&list);
	CHECK(find(list, "shadow_bias")->usage == PROPERTY_USAGE_DEFAULT);
	delete light;

	DirectionalLight3D *sun = new DirectionalLight3D;
	list.clear();
	sun->get_property_list(&list);
	CHECK(find(list, "light_angular_distance")->usage == PROPERTY_USAGE_DEFAULT);
	CHECK(find(list, "light_size")->usage == PROPERTY_USAGE_NONE);
	CHECK(find(list, "distance_fade_enabled")->usage == PROPERTY_USAGE_NONE);
	CHECK(index_of(list, "directional_shadow_mode") < index_of(list, "sky_mode"));
	CHECK(find(list, "omni_range") == nullptr);
	delete sun;
}

TEST_CASE("[OmniLight3D] get_aabb is a cube of side 2 * range") {
	DummyServer server;
	OmniLight3D *light = new OmniLight3D;
	light->set("omni_range", 3.0);
	AABB box = light->get_aabb();
	CHECK(box.position.is_equal_approx(Vector3(-3, -3, -3)));
	CHECK(box.size.is_equal_approx(Vector3(6, 6, 6)));
	delete light;
}

TEST_CASE("[SpotLight3D] get_aabb bounds the cone, which opens along -Z") {
	DummyServer server;
	SpotLight3D *light = new SpotLight3D;
	light->set("spot_range", 4.0);

	SUBCASE("narrow cone") {
		light->set("spot_angle", 30.0);
		AABB box = light->get_aabb();
		const real_t r = 4.0f * std::sin(Math::deg_to_rad(30.0f));
		CHECK(box.position.is_equal_approx(Vector3(-r, -r, -4)));
		CHECK(box.size.is_equal_approx(Vector3(2 * r, 2 * r, 4)));
		// Every point of the cone (apex at the origin, slant height = range) is inside.
		AABB grown = box.grow(1e-4f);
		for (int a = 0; a <= 6; a++) {
			const real_t theta = Math::deg_to_rad(30.0f) * a / 6.0f;
			for (int b = 0; b < 8; b++) {
				const real_t phi = real_t(Math::TAU) * b / 8.0f;
				Vector3 dir(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta));
				CHECK(grown.has_point(dir * 4.0f));
			}
		}
	}
	SUBCASE("wider than 90 degrees falls back to the omni cube") {
		light->set("spot_angle", 120.0);
		AABB box = light->get_aabb();
		CHECK(box.position.is_equal_approx(Vector3(-4, -4, -4)));
		CHECK(box.size.is_equal_approx(Vector3(8, 8, 8)));
	}
	delete light;
}

TEST_CASE("[SpotLight3D] the server places the light at the node's global transform") {
	DummyServer server;
	SceneTree *tree = new SceneTree;
	Node3D *parent = new Node3D;
	parent->set_position(Vector3(10, 0, 0));
	SpotLight3D *light = new SpotLight3D;
	light->set("spot_range", 2.0);
	light->set("spot_angle", 10.0);
	parent->add_child(light);
	tree->get_root()->add_child(parent);

	AABB world = RS::get_singleton()->instance_get_aabb(light->get_instance());
	CHECK(world.get_center().x == doctest::Approx(10.0));
	CHECK_MESSAGE(world.position.z == doctest::Approx(-2.0), "an unrotated spot light shines down -Z");
	CHECK(world.get_end().z == doctest::Approx(0.0));

	// Turning the parent 180 degrees about Y makes it shine down +Z.
	parent->set_rotation(Vector3(0, real_t(Math::PI), 0));
	world = RS::get_singleton()->instance_get_aabb(light->get_instance());
	CHECK(world.get_end().z == doctest::Approx(2.0).epsilon(1e-4));
	CHECK(world.position.z == doctest::Approx(0.0).epsilon(1e-4));
	delete tree;
}

TEST_CASE("[Light3D] configuration warnings") {
	DummyServer server;
	SpotLight3D *light = new SpotLight3D;
	CHECK(light->get_configuration_warnings().empty());
	light->set_shadow(true);
	light->set_param(Light3D::PARAM_SPOT_ANGLE, 100.0f);
	CHECK(light->get_configuration_warnings().size() == 1);
	light->set_scale(Vector3(2, 2, 2));
	CHECK(light->get_configuration_warnings().size() == 2);
	delete light;
}

TEST_CASE("[Light3D] a Godot 4.7 scene file with lights loads and saves back") {
	DummyServer server;
	const char *text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Omni" type="OmniLight3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 2, 3)
light_color = Color(1, 0.5, 0.25, 1)
light_energy = 2.5
shadow_enabled = true
shadow_bias = 0.2
omni_range = 7.0
omni_shadow_mode = 0

[node name="Spot" type="SpotLight3D" parent="."]
spot_range = 9.0
spot_angle = 30.0

[node name="Sun" type="DirectionalLight3D" parent="."]
light_angular_distance = 0.5
directional_shadow_max_distance = 50.0
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "lights.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);

	OmniLight3D *omni = Object::cast_to<OmniLight3D>(root->get_node_or_null("Omni"));
	SpotLight3D *spot = Object::cast_to<SpotLight3D>(root->get_node_or_null("Spot"));
	DirectionalLight3D *sun = Object::cast_to<DirectionalLight3D>(root->get_node_or_null("Sun"));
	REQUIRE(omni);
	REQUIRE(spot);
	REQUIRE(sun);
	CHECK(omni->get_position().is_equal_approx(Vector3(1, 2, 3)));
	CHECK(omni->get_color().is_equal_approx(Color(1, 0.5f, 0.25f, 1)));
	CHECK(omni->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(2.5));
	CHECK(omni->has_shadow());
	CHECK(omni->get_param(Light3D::PARAM_SHADOW_BIAS) == doctest::Approx(0.2));
	CHECK(omni->get_param(Light3D::PARAM_RANGE) == doctest::Approx(7.0));
	CHECK(omni->get_shadow_mode() == OmniLight3D::SHADOW_DUAL_PARABOLOID);
	CHECK(spot->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(30.0));
	CHECK_MESSAGE(spot->get_param(Light3D::PARAM_SHADOW_BIAS) == doctest::Approx(0.03), "a missing key means Godot's per-class default");
	CHECK(sun->get_param(Light3D::PARAM_SIZE) == doctest::Approx(0.5));
	CHECK(sun->get_param(Light3D::PARAM_SHADOW_MAX_DISTANCE) == doctest::Approx(50.0));

	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("omni_range") != String::npos);
	CHECK(saved.find("light_angular_distance") != String::npos);
	CHECK_MESSAGE(saved.find("spot_angle_attenuation") == String::npos, "defaults are not written");
	CHECK_MESSAGE(saved.find("light_intensity_lumens") == String::npos, "physical-unit properties are not saved while physical units are off");
	CHECK_MESSAGE(saved.find("shadow_bias") == saved.rfind("shadow_bias"), "only the omni light's non-default shadow_bias is written");

	Node *again = ResourceFormatText::load_scene_from_string(saved, "lights_saved.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error);
	OmniLight3D *omni2 = Object::cast_to<OmniLight3D>(again->get_node_or_null("Omni"));
	REQUIRE(omni2);
	CHECK(omni2->get_param(Light3D::PARAM_RANGE) == doctest::Approx(7.0));
	CHECK(omni2->get_param(Light3D::PARAM_SHADOW_BIAS) == doctest::Approx(0.2));
	CHECK(omni2->get_transform().is_equal_approx(omni->get_transform()));
	delete again;
	delete root;
}

} // namespace TestLight3D
