/**************************************************************************/
/*  test_area_light_3d.cpp                                                */
/**************************************************************************/
/* AreaLight3D: the contract's defaults, property access by name, the     */
/* .tscn round trip, rejection of bad values, the thesis Listing A.1      */
/* AABB, property list order/groups/hints, and forwarding to the server   */
/* (read back through the dummy light storage).                           */

#include "scene/3d/light_3d.h"

#include "scene/main/scene_tree.h"
#include "scene/resources/resource_format_text.h"
#include "scene/resources/texture.h"
#include "servers/rendering/rendering_server_globals.h"
#include "servers/rendering/storage/light_storage.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestAreaLight3D {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

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

TEST_CASE("[AreaLight3D] is a registered, instantiable Light3D; enum values equal the server's") {
	DummyServer server;
	CHECK((int)AreaLight3D::AREA_SHADING_LTC == (int)RS::LIGHT_AREA_SHADING_LTC);
	CHECK((int)AreaLight3D::AREA_SHADING_LTC == 0);
	CHECK((int)RS::LIGHT_AREA == 3);
	CHECK(ClassDB::is_parent_class("AreaLight3D", "Light3D"));
	CHECK(ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_LTC") == 0);
	CHECK(ClassDB::get_integer_constant_enum("AreaLight3D", "AREA_SHADING_LTC") == "AreaShadingMethod");
	Object *obj = ClassDB::instantiate("AreaLight3D");
	REQUIRE(obj != nullptr);
	AreaLight3D *light = Object::cast_to<AreaLight3D>(obj);
	REQUIRE(light != nullptr);
	CHECK(light->get_light_type() == RS::LIGHT_AREA);
	delete obj;
}

TEST_CASE("[AreaLight3D] defaults follow the contract and reach the server") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	CHECK(Vector2(light->get("area_size")) == Vector2(1, 1));
	CHECK(light->get("area_range").to_float() == doctest::Approx(5.0));
	CHECK(light->get("area_attenuation").to_float() == doctest::Approx(1.0));
	CHECK(light->get("area_normalize_energy").to_bool() == true);
	CHECK(light->get("area_shading_method").to_int() == AreaLight3D::AREA_SHADING_LTC);
	// Upstream Godot 4.7's AreaLight3D overrides of Light3D's defaults.
	CHECK(light->get("light_specular").to_float() == doctest::Approx(1.0));
	CHECK(light->get("light_size").to_float() == doctest::Approx(0.5));
	CHECK(light->get("shadow_bias").to_float() == doctest::Approx(0.1));
	CHECK(light->get("shadow_normal_bias").to_float() == doctest::Approx(1.0));
	// Light3D's other defaults are unchanged.
	CHECK(light->get("light_energy").to_float() == doctest::Approx(1.0));
	CHECK(light->get("shadow_enabled").to_bool() == false);
	CHECK(light->get_configuration_warnings().empty());

	// Read back through the dummy light storage: node defaults were pushed, not storage defaults.
	RID rid = light->get_light();
	CHECK(RSG::light_storage->light_get_type(rid) == RS::LIGHT_AREA);
	CHECK(RSG::light_storage->light_area_get_size(rid) == Vector2(1, 1));
	CHECK(RSG::light_storage->light_area_get_normalize_energy(rid) == true);
	CHECK(RSG::light_storage->light_area_get_shading_method(rid) == RS::LIGHT_AREA_SHADING_LTC);
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_RANGE) == doctest::Approx(5.0));
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_ATTENUATION) == doctest::Approx(1.0));
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_SPECULAR) == doctest::Approx(1.0));
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_SIZE) == doctest::Approx(0.5));
	delete light;
}

TEST_CASE("[AreaLight3D] set and get by property name; the server receives the values") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	bool valid = false;
	light->set("area_size", Vector2(2.5f, 0.25f), &valid);
	CHECK(valid);
	light->set("area_range", 12.0, &valid);
	CHECK(valid);
	light->set("area_attenuation", 0.0, &valid);
	CHECK(valid);
	light->set("area_normalize_energy", false, &valid);
	CHECK(valid);
	light->set("area_shading_method", 0, &valid);
	CHECK(valid);
	light->set("light_energy", 3.0);

	CHECK(light->get_area_size() == Vector2(2.5f, 0.25f));
	CHECK(Vector2(light->get("area_size")) == Vector2(2.5f, 0.25f));
	CHECK(light->get_param(Light3D::PARAM_RANGE) == doctest::Approx(12.0));
	CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(0.0));
	CHECK_FALSE(light->is_area_normalizing_energy());
	CHECK(light->get_area_shading_method() == AreaLight3D::AREA_SHADING_LTC);

	RID rid = light->get_light();
	CHECK(RSG::light_storage->light_area_get_size(rid) == Vector2(2.5f, 0.25f));
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_RANGE) == doctest::Approx(12.0));
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_ATTENUATION) == doctest::Approx(0.0));
	CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_ENERGY) == doctest::Approx(3.0));
	CHECK_FALSE(RSG::light_storage->light_area_get_normalize_energy(rid));
	// Through the RenderingServer API too.
	CHECK(RS::get_singleton()->light_area_get_size(rid) == Vector2(2.5f, 0.25f));
	CHECK(RS::get_singleton()->light_get_aabb(rid).is_equal_approx(light->get_aabb()));
	delete light;
}

TEST_CASE("[AreaLight3D] invalid values are rejected with a message naming the property; the old value is kept") {
	DummyServer server;
	ErrorCatcher errors;
	AreaLight3D *light = new AreaLight3D;
	light->set("area_size", Vector2(2, 3));
	RID rid = light->get_light();

	SUBCASE("negative size components are clamped to 0 as upstream does, with a warning naming the value") {
		light->set("area_size", Vector2(-1, 3));
		CHECK(light->get_area_size() == Vector2(0, 3));
		CHECK(errors.contains("area_size"));
		CHECK(errors.contains("(-1, 3)"));
		CHECK(errors.contains("clamped to (0, 3)"));
		light->set_area_size(Vector2(2, -0.001f));
		CHECK(light->get_area_size() == Vector2(2, 0));
		CHECK(RSG::light_storage->light_area_get_size(rid) == Vector2(2, 0));
	}
	SUBCASE("NaN and infinite size") {
		light->set_area_size(Vector2(NAN, 1));
		light->set_area_size(Vector2(1, INFINITY));
		CHECK(light->get_area_size() == Vector2(2, 3));
		CHECK(errors.contains("area_size"));
		CHECK(RSG::light_storage->light_area_get_size(rid) == Vector2(2, 3));
	}
	SUBCASE("infinite or NaN range") {
		light->set("area_range", INFINITY);
		CHECK(errors.contains("area_range"));
		light->set("area_range", NAN);
		light->set("area_range", -2.0);
		CHECK(light->get_param(Light3D::PARAM_RANGE) == doctest::Approx(5.0));
		CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_RANGE) == doctest::Approx(5.0));
	}
	SUBCASE("negative attenuation (allowed for omni lights, not for area lights)") {
		light->set("area_attenuation", -1.0);
		CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(1.0));
		CHECK(errors.contains("area_attenuation"));
		CHECK(errors.contains("must not be negative"));
		CHECK(RSG::light_storage->light_get_param(rid, RS::LIGHT_PARAM_ATTENUATION) == doctest::Approx(1.0));
	}
	SUBCASE("bad shading method") {
		light->set("area_shading_method", 99);
		CHECK(light->get_area_shading_method() == AreaLight3D::AREA_SHADING_LTC);
		CHECK(errors.contains("area_shading_method"));
	}
	SUBCASE("a zero size is valid but warned about") {
		size_t before = errors.messages.size();
		light->set_area_size(Vector2(0, 3));
		CHECK(errors.messages.size() == before);
		CHECK(light->get_area_size() == Vector2(0, 3));
		CHECK(light->get_configuration_warnings().size() == 1);
	}
	delete light;
}

TEST_CASE("[AreaLight3D] get_aabb is the box of thesis Listing A.1") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	light->set("area_size", Vector2(3, 1));
	light->set("area_range", 2.0);
	// AABB(-(a/2 + r, b/2 + r, r), (a + 2r, b + 2r, r)): in front of the light only (z in [-r, 0]).
	AABB box = light->get_aabb();
	CHECK(box.position.is_equal_approx(Vector3(-3.5f, -2.5f, -2)));
	CHECK(box.size.is_equal_approx(Vector3(7, 5, 2)));
	CHECK(box.get_end().z == doctest::Approx(0.0));
	// Every point within the range of the rectangle and in front of it is inside.
	AABB grown = box.grow(1e-4f);
	for (int i = 0; i <= 4; i++) {
		for (int j = 0; j <= 4; j++) {
			Vector3 on_rect(-1.5f + 3.0f * i / 4, -0.5f + 1.0f * j / 4, 0);
			CHECK(grown.has_point(on_rect + Vector3(0, 0, -2)));
			CHECK(grown.has_point(on_rect + Vector3(on_rect.x < 0 ? -2 : 2, 0, 0)));
			CHECK(grown.has_point(on_rect + Vector3(0, on_rect.y < 0 ? -2 : 2, 0)));
		}
	}
	// The storage computes the same box, and scene cull uses it for the instance.
	CHECK(RS::get_singleton()->light_get_aabb(light->get_light()).is_equal_approx(box));
	CHECK(RendererLightStorage::compute_area_light_aabb(2.0f, Vector2(3, 1)).is_equal_approx(box));

	SceneTree *tree = new SceneTree;
	light->set_position(Vector3(10, 0, 0));
	tree->get_root()->add_child(light);
	AABB world = RS::get_singleton()->instance_get_aabb(light->get_instance());
	CHECK(world.position.is_equal_approx(Vector3(6.5f, -2.5f, -2)));
	CHECK(world.size.is_equal_approx(Vector3(7, 5, 2)));
	delete tree; // Deletes the light too.
}

TEST_CASE("[AreaLight3D] property list order, group, hints and enum") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	std::vector<PropertyInfo> list;
	light->get_property_list(&list);

	bool saw_area_group = false;
	String prefix;
	for (const PropertyInfo &p : list) {
		if (p.usage & PROPERTY_USAGE_GROUP) {
			prefix = p.hint_string;
			saw_area_group |= p.name == "Area" && p.hint_string == "area_";
			continue;
		}
		if (prefix == "area_") {
			CHECK_MESSAGE(string_begins_with(p.name, "area_"), (String("property ") + p.name + " must start with the Area group prefix"));
		}
	}
	CHECK(saw_area_group);

	// Light3D's properties first, then the Area group in declaration order.
	CHECK(index_of(list, "editor_only") < index_of(list, "area_size"));
	CHECK(index_of(list, "area_size") < index_of(list, "area_range"));
	CHECK(index_of(list, "area_range") < index_of(list, "area_attenuation"));
	CHECK(index_of(list, "area_attenuation") < index_of(list, "area_normalize_energy"));
	CHECK(index_of(list, "area_normalize_energy") < index_of(list, "area_shading_method"));

	const PropertyInfo *size = find(list, "area_size");
	REQUIRE(size);
	CHECK(size->type == Variant::VECTOR2);
	CHECK(size->hint == PROPERTY_HINT_RANGE);
	CHECK(size->hint_string == "0,4096,0.001,or_greater,suffix:m");
	const PropertyInfo *range = find(list, "area_range");
	REQUIRE(range);
	CHECK(range->hint_string == "0,4096,0.001,or_greater,exp,suffix:m");
	const PropertyInfo *attenuation = find(list, "area_attenuation");
	REQUIRE(attenuation);
	CHECK(attenuation->hint_string == "0,10,0.001,or_greater");
	const PropertyInfo *method = find(list, "area_shading_method");
	REQUIRE(method);
	CHECK(method->type == Variant::INT);
	CHECK(method->hint == PROPERTY_HINT_ENUM);
	CHECK(method->hint_string == "LTC,LTC Polynomial,MRP,Stochastic,Auto,LTC 2-Lobe");
	CHECK(find(list, "area_normalize_energy")->type == Variant::BOOL);

	// Punctual-light properties that do not apply: neither shown nor saved.
	CHECK(find(list, "omni_range") == nullptr);
	CHECK(find(list, "spot_angle") == nullptr);
	// Upstream Godot 4.7: light_size is shown and saved (its PCSS size); light_projector is hidden but
	// still saved (a configuration warning points to area_texture).
	CHECK(find(list, "light_size")->usage == PROPERTY_USAGE_DEFAULT);
	CHECK(find(list, "light_projector")->usage == PROPERTY_USAGE_NO_EDITOR);
	CHECK(find(list, "light_angular_distance")->usage == PROPERTY_USAGE_NONE);
	delete light;
}

TEST_CASE("[AreaLight3D] a scene file with an area light loads, saves back identically and reloads") {
	DummyServer server;
	// Written in the saver's own format, so the text must come back unchanged.
	const String text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Panel" type="AreaLight3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0)
light_color = Color(1, 0.5, 0.25, 1)
light_energy = 2.5
area_size = Vector2(2, 0.5)
area_range = 8.0
area_attenuation = 0.5
area_normalize_energy = false

[node name="Default" type="AreaLight3D" parent="."]
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "area.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	AreaLight3D *panel = Object::cast_to<AreaLight3D>(root->get_node_or_null("Panel"));
	AreaLight3D *def = Object::cast_to<AreaLight3D>(root->get_node_or_null("Default"));
	REQUIRE(panel);
	REQUIRE(def);
	CHECK(panel->get_position().is_equal_approx(Vector3(0, 3, 0)));
	CHECK(panel->get_area_size() == Vector2(2, 0.5f));
	CHECK(panel->get_param(Light3D::PARAM_RANGE) == doctest::Approx(8.0));
	CHECK(panel->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(0.5));
	CHECK_FALSE(panel->is_area_normalizing_energy());
	CHECK(panel->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(2.5));
	CHECK(RSG::light_storage->light_area_get_size(panel->get_light()) == Vector2(2, 0.5f));
	CHECK_MESSAGE(def->get_area_size() == Vector2(1, 1), "a missing key means the class default");

	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK_MESSAGE(saved == text, (String("saved text:\n") + saved));
	CHECK_MESSAGE(saved.find("area_shading_method") == String::npos, "defaults are not written");
	CHECK_MESSAGE(saved.find("light_size") == String::npos, "light_size at its default (0.5) is not written");

	Node *again = ResourceFormatText::load_scene_from_string(saved, "area_saved.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error);
	AreaLight3D *panel2 = Object::cast_to<AreaLight3D>(again->get_node_or_null("Panel"));
	REQUIRE(panel2);
	CHECK(panel2->get_area_size() == panel->get_area_size());
	CHECK(panel2->get_param(Light3D::PARAM_RANGE) == panel->get_param(Light3D::PARAM_RANGE));
	CHECK(panel2->get_param(Light3D::PARAM_ATTENUATION) == panel->get_param(Light3D::PARAM_ATTENUATION));
	CHECK(panel2->is_area_normalizing_energy() == panel->is_area_normalizing_energy());
	CHECK(panel2->get_color().is_equal_approx(panel->get_color()));
	CHECK(panel2->get_transform().is_equal_approx(panel->get_transform()));
	delete again;
	delete root;
}

TEST_CASE("[AreaLight3D] an upstream-style Godot 4.7 scene loads with upstream's values, and saves them back") {
	DummyServer server;
	// Written as upstream Godot 4.7 writes area lights: only non-default values appear, light_size
	// and light_specular included; the second light relies on every default.
	const String text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Screen" type="AreaLight3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1.5, -2)
light_energy = 4.0
light_size = 0.25
light_specular = 0.75
shadow_enabled = true
area_size = Vector2(1.6, 0.9)
area_range = 8.0
area_attenuation = 2.0

[node name="Defaults" type="AreaLight3D" parent="."]
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "upstream_area.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	AreaLight3D *screen = Object::cast_to<AreaLight3D>(root->get_node_or_null("Screen"));
	AreaLight3D *defaults = Object::cast_to<AreaLight3D>(root->get_node_or_null("Defaults"));
	REQUIRE(screen);
	REQUIRE(defaults);
	CHECK(screen->get_param(Light3D::PARAM_SIZE) == doctest::Approx(0.25));
	CHECK(screen->get_param(Light3D::PARAM_SPECULAR) == doctest::Approx(0.75));
	CHECK(screen->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.0));
	CHECK(screen->get_area_size().is_equal_approx(Vector2(1.6f, 0.9f)));
	CHECK(RSG::light_storage->light_get_param(screen->get_light(), RS::LIGHT_PARAM_SIZE) == doctest::Approx(0.25));
	// Upstream's defaults where the file is silent.
	CHECK(defaults->get_param(Light3D::PARAM_SPECULAR) == doctest::Approx(1.0));
	CHECK(defaults->get_param(Light3D::PARAM_SIZE) == doctest::Approx(0.5));
	CHECK(defaults->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(1.0));
	CHECK(defaults->get_param(Light3D::PARAM_RANGE) == doctest::Approx(5.0));
	CHECK(defaults->get_param(Light3D::PARAM_SHADOW_BIAS) == doctest::Approx(0.1));
	CHECK(defaults->get_area_size() == Vector2(1, 1));
	CHECK(defaults->is_area_normalizing_energy());

	// Round trip: every shared property comes back with the same value.
	const String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK_MESSAGE(saved.find("light_size = 0.25") != String::npos, saved);
	CHECK_MESSAGE(saved.find("light_specular = 0.75") != String::npos, saved);
	Node *again = ResourceFormatText::load_scene_from_string(saved, "upstream_area_saved.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error);
	AreaLight3D *screen2 = Object::cast_to<AreaLight3D>(again->get_node_or_null("Screen"));
	AreaLight3D *defaults2 = Object::cast_to<AreaLight3D>(again->get_node_or_null("Defaults"));
	REQUIRE(screen2);
	REQUIRE(defaults2);
	for (const Light3D::Param p : { Light3D::PARAM_ENERGY, Light3D::PARAM_SIZE, Light3D::PARAM_SPECULAR, Light3D::PARAM_RANGE, Light3D::PARAM_ATTENUATION, Light3D::PARAM_SHADOW_BIAS, Light3D::PARAM_SHADOW_NORMAL_BIAS }) {
		CHECK(screen2->get_param(p) == doctest::Approx(screen->get_param(p)));
		CHECK(defaults2->get_param(p) == doctest::Approx(defaults->get_param(p)));
	}
	CHECK(screen2->get_area_size() == screen->get_area_size());
	CHECK(screen2->has_shadow());
	delete again;
	delete root;
}

TEST_CASE("[AreaLight3D] light_projector is hidden and warned about, as upstream does; it is still saved") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	Ref<ImageTexture> texture = ImageTexture::create_from_image(Image(2, 2, Color(1, 1, 1, 1)));
	REQUIRE(texture.is_valid());
	light->set_projector(texture);
	bool warned = false;
	for (const String &w : light->get_configuration_warnings()) {
		warned = warned || w.find("area_texture") != String::npos;
	}
	CHECK(warned);
	delete light;
}

} // namespace TestAreaLight3D
