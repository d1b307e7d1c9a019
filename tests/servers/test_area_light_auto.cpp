/**************************************************************************/
/*  test_area_light_auto.cpp                                              */
/**************************************************************************/
/* godot-area: the AUTO area shading method (issue "All shading methods", */
/* item 5): ProjectSettings and the error-budget setting, the selector    */
/* (large budget -> cheapest, tiny budget -> most accurate, choices that  */
/* follow the committed table), the .tscn round trip of AUTO, and a GPU   */
/* scene with AUTO lights that compiles only the chosen methods.          */

#include "core/config/project_settings.h"
#include "scene/3d/light_3d.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/renderer_rd/area_lights/area_method_selector.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "servers/rendering/rendering_server_globals.h"
#include "tests/scene/scene_test_fixture.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace {

// Restores a setting's default when the test ends.
struct SettingOverride {
	String name;
	SettingOverride(const String &p_name, const Variant &p_value) :
			name(p_name) {
		ProjectSettings::get_singleton()->set_setting(p_name, p_value);
	}
	~SettingOverride() { ProjectSettings::get_singleton()->clear_override(name); }
};

// A size/distance value inside each size bin, and a roughness at each bin centre.
std::vector<float> size_samples() {
	return { 0.1f, 0.6f, 1.5f, 10.0f };
}
std::vector<float> roughness_samples() {
	return { 0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f };
}

} // namespace

TEST_CASE("[ProjectSettings] GLOBAL_DEF registers a default, overrides win and bad input is rejected") {
	ProjectSettings *ps = ProjectSettings::get_singleton();
	const String name = "tests/auto/some_float";
	CHECK(GLOBAL_DEF(name, 0.25).to_float() == doctest::Approx(0.25));
	CHECK(ps->is_registered(name));
	CHECK(GLOBAL_DEF(name, 9.0).to_float() == doctest::Approx(0.25)); // The first default wins.
	CHECK(ps->set_setting(name, 0.5));
	CHECK(GLOBAL_GET(name).to_float() == doctest::Approx(0.5));
	{
		SceneTest::ErrorCatcher errors;
		CHECK_FALSE(ps->set_setting(name, "text")); // A string does not convert to a float.
		CHECK(errors.contains(name));
		CHECK_FALSE(ps->parse_override("no_equals_sign"));
		CHECK_FALSE(ps->parse_override(name + "=abc"));
	}
	CHECK(GLOBAL_GET(name).to_float() == doctest::Approx(0.5));
	String error;
	CHECK_MESSAGE(ps->parse_override(name + "=0.125", &error), error);
	CHECK(GLOBAL_GET(name).to_float() == doctest::Approx(0.125));
	ps->clear_override(name);
	CHECK(GLOBAL_GET(name).to_float() == doctest::Approx(0.25));
	// An override given before the engine registers the setting (CLI) wins once registered.
	CHECK(ps->parse_override("tests/auto/late=3"));
	CHECK(GLOBAL_DEF("tests/auto/late", 1.0).to_float() == doctest::Approx(3.0));
	ps->clear_override("tests/auto/late");
}

TEST_CASE("[AreaLight3D][AUTO] AUTO is appended before the MAX sentinel and the budget setting is registered") {
	CHECK((int)RS::LIGHT_AREA_SHADING_AUTO == 4);
	CHECK((int)RS::LIGHT_AREA_SHADING_LTC_2LOBE == 5); // Appended after AUTO, so AUTO keeps its saved value.
	CHECK((int)RS::LIGHT_AREA_SHADING_MAX == 6);
	CHECK((int)AreaLight3D::AREA_SHADING_AUTO == (int)RS::LIGHT_AREA_SHADING_AUTO);
	const float budget = AreaMethodSelector::get_error_budget();
	CHECK(ProjectSettings::get_singleton()->is_registered(AreaMethodSelector::SETTING_ERROR_BUDGET));
	CHECK(budget == doctest::Approx(AreaMethodSelector::DEFAULT_ERROR_BUDGET));
	{
		SettingOverride o(AreaMethodSelector::SETTING_ERROR_BUDGET, 0.3);
		CHECK(AreaMethodSelector::get_error_budget() == doctest::Approx(0.3));
	}
	{
		SceneTest::ErrorCatcher errors;
		SettingOverride o(AreaMethodSelector::SETTING_ERROR_BUDGET, -1.0);
		CHECK(AreaMethodSelector::get_error_budget() == doctest::Approx(AreaMethodSelector::DEFAULT_ERROR_BUDGET));
		CHECK(errors.contains("area_light_error_budget"));
	}
}

TEST_CASE("[AreaLight3D][AUTO] a large budget picks the cheapest method, a tiny budget the most accurate") {
	for (int samples : { 1, 8, 64 }) {
		int cheapest = 0;
		for (int m = 1; m < AreaMethodSelector::CANDIDATE_COUNT; m++) {
			if (AreaMethodSelector::relative_cost(RS::LightAreaShadingMethod(m), samples) < AreaMethodSelector::relative_cost(RS::LightAreaShadingMethod(cheapest), samples)) {
				cheapest = m;
			}
		}
		for (float q : size_samples()) {
			for (float r : roughness_samples()) {
				CAPTURE(q);
				CAPTURE(r);
				CAPTURE(samples);
				CHECK((int)AreaMethodSelector::choose(q, r, 1e9f, samples) == cheapest);
				const RS::LightAreaShadingMethod accurate = AreaMethodSelector::choose(q, r, 0.0f, samples);
				CHECK(accurate != RS::LIGHT_AREA_SHADING_AUTO);
				for (int m = 0; m < AreaMethodSelector::CANDIDATE_COUNT; m++) {
					CHECK(AreaMethodSelector::predict_error(accurate, q, r, samples) <= AreaMethodSelector::predict_error(RS::LightAreaShadingMethod(m), q, r, samples));
				}
			}
		}
	}
	// Bad inputs never pick AUTO or crash.
	CHECK((int)AreaMethodSelector::choose(NAN, NAN, NAN, 0) < (int)RS::LIGHT_AREA_SHADING_AUTO);
	CHECK(std::isinf(AreaMethodSelector::predict_error(RS::LIGHT_AREA_SHADING_AUTO, 1.0f, 0.5f, 8)));
}

TEST_CASE("[AreaLight3D][AUTO] the choice follows the prediction table") {
	const int samples = AreaMethodSelector::get_table_mc_samples();
	CHECK(AreaMethodSelector::get_roughness_bin_count() == 6);
	CHECK(AreaMethodSelector::get_size_bin_count() == 4);
	CHECK(AreaMethodSelector::size_bin(0.0f) == 0);
	CHECK(AreaMethodSelector::size_bin(100.0f) == AreaMethodSelector::get_size_bin_count() - 1);
	CHECK(AreaMethodSelector::roughness_bin(0.0f) == 0);
	CHECK(AreaMethodSelector::roughness_bin(1.0f) == AreaMethodSelector::get_roughness_bin_count() - 1);
	// MC error scales as 1/sqrt(samples) from the measured column.
	CHECK(AreaMethodSelector::predict_error(RS::LIGHT_AREA_SHADING_STOCHASTIC, 1.5f, 0.5f, samples * 4) ==
			doctest::Approx(0.5f * AreaMethodSelector::predict_error(RS::LIGHT_AREA_SHADING_STOCHASTIC, 1.5f, 0.5f, samples)));
	int distinct = 0;
	uint32_t chosen_mask = 0;
	for (float q : size_samples()) {
		for (float r : roughness_samples()) {
			// Budgets at every method's predicted error: the choice is the cheapest method at or under it.
			for (int b = 0; b < AreaMethodSelector::CANDIDATE_COUNT; b++) {
				const float budget = AreaMethodSelector::predict_error(RS::LightAreaShadingMethod(b), q, r, samples);
				int expected = -1;
				for (int m = 0; m < AreaMethodSelector::CANDIDATE_COUNT; m++) {
					const RS::LightAreaShadingMethod mm = RS::LightAreaShadingMethod(m);
					if (AreaMethodSelector::predict_error(mm, q, r, samples) <= budget &&
							(expected < 0 || AreaMethodSelector::relative_cost(mm, samples) < AreaMethodSelector::relative_cost(RS::LightAreaShadingMethod(expected), samples))) {
						expected = m;
					}
				}
				CAPTURE(q);
				CAPTURE(r);
				CAPTURE(budget);
				const int got = (int)AreaMethodSelector::choose(q, r, budget, samples);
				CHECK(got == expected);
				CHECK(AreaMethodSelector::predict_error(RS::LightAreaShadingMethod(got), q, r, samples) <= budget);
				chosen_mask |= 1u << got;
			}
		}
	}
	for (int m = 0; m < AreaMethodSelector::CANDIDATE_COUNT; m++) {
		distinct += (chosen_mask >> m) & 1u;
	}
	CHECK_MESSAGE(distinct >= 2, "the table must make AUTO choose between at least two methods");
}

TEST_CASE("[AreaLight3D][AUTO] a scene file with AUTO lights loads, saves back identically and reloads") {
	SceneTest::DummyServer server;
	const String text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Auto" type="AreaLight3D" parent="."]
area_shading_method = 4

[node name="AutoMc" type="AreaLight3D" parent="."]
area_shading_method = 4
area_stochastic_samples = 16
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "auto.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	for (const char *name : { "Auto", "AutoMc" }) {
		AreaLight3D *l = Object::cast_to<AreaLight3D>(root->get_node_or_null(name));
		REQUIRE(l != nullptr);
		CHECK(l->get_area_shading_method() == AreaLight3D::AREA_SHADING_AUTO);
		CHECK(RSG::light_storage->light_area_get_shading_method(l->get_light()) == RS::LIGHT_AREA_SHADING_AUTO);
	}
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK_MESSAGE(saved == text, (String("saved text:\n") + saved));
	Node *again = ResourceFormatText::load_scene_from_string(saved, "auto_saved.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error);
	AreaLight3D *l2 = Object::cast_to<AreaLight3D>(again->get_node_or_null("AutoMc"));
	REQUIRE(l2 != nullptr);
	CHECK(l2->get_area_shading_method() == AreaLight3D::AREA_SHADING_AUTO);
	CHECK(l2->get_area_stochastic_samples() == 16);
	{
		SceneTest::ErrorCatcher errors;
		l2->set_area_shading_method(AreaLight3D::AreaShadingMethod(RS::LIGHT_AREA_SHADING_MAX)); // MAX: invalid, the old value stays.
		CHECK(l2->get_area_shading_method() == AreaLight3D::AREA_SHADING_AUTO);
		CHECK(errors.contains("area_shading_method"));
	}
	delete again;
	delete root;
}

namespace {

struct AutoFixture : RenderTest::RenderFixture {
	RID material(float p_roughness) {
		RS::MaterialParams mp;
		mp.roughness = p_roughness;
		mp.cull_back = false;
		return RenderTest::RenderFixture::material(mp);
	}
	RID auto_light(const Vector2 &p_size) {
		RID l = light_storage.light_create(RS::LIGHT_AREA);
		light_storage.light_area_set_size(l, p_size);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, 100.0f);
		light_storage.light_area_set_shading_method(l, RS::LIGHT_AREA_SHADING_AUTO);
		lights.push_back(l);
		return l;
	}
	void render(RenderSceneData &r_data) {
		RID rt = renderer.render_target_create(r_data.viewport_width, r_data.viewport_height);
		light_storage.set_area_auto_receivers(&r_data.geometry, &mesh_storage, &material_storage);
		renderer.render_scene(r_data, rt);
		renderer.render_target_free(rt);
	}
};

} // namespace

TEST_CASE("[AreaLight3D][AUTO] a scene of AUTO lights compiles only the methods chosen for them") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AutoFixture f;
		REQUIRE(f.init());
		RenderSceneData d;
		d.cam_transform = Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 4, 0));
		d.cam_projection = Projection::create_perspective(60.0f, 1.0f, 0.05f, 30.0f);
		d.viewport_width = 16;
		d.viewport_height = 16;
		RenderSceneData::GeometryInstance g;
		g.mesh = f.plane(10.0f);
		g.material_override = f.material(0.25f);
		g.aabb = AABB(Vector3(-10, 0, -10), Vector3(20, 0, 20));
		d.geometry.push_back(g);
		const Basis down = Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
		for (float x : { -1.0f, 1.0f }) {
			RenderSceneData::LightInstance li;
			li.light = f.auto_light(Vector2(1.5f, 1.0f));
			li.type = RS::LIGHT_AREA;
			li.transform = Transform3D(down, Vector3(x, 1, 0));
			d.lights.push_back(li);
		}
		// The estimate: 1.5 m light 1 m above a roughness-0.25 receiver.
		const float q = 1.5f;
		const float r = 0.25f;
		const int n = RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT;
		const ShaderRD &shader = f.renderer.get_scene_shader();
		const uint32_t created_base = shader.get_created_shader_count();

		// Large budget: the cheapest method, one version, nothing else compiled.
		const RS::LightAreaShadingMethod cheap = AreaMethodSelector::choose(q, r, 1e9f, n);
		{
			SettingOverride o(AreaMethodSelector::SETTING_ERROR_BUDGET, 1e9);
			f.render(d);
			f.render(d);
		}
		const std::vector<RendererRD::LightStorage::AreaAutoChoice> &choices = f.light_storage.get_area_auto_choices();
		REQUIRE(choices.size() == 2);
		for (const RendererRD::LightStorage::AreaAutoChoice &c : choices) {
			CHECK(c.requested == RS::LIGHT_AREA_SHADING_AUTO);
			CHECK(c.method == cheap);
			CHECK(c.size_over_distance == doctest::Approx(q));
			CHECK(c.roughness == doctest::Approx(r));
		}
		for (const RendererRD::LightStorage::AreaLightData &a : f.light_storage.get_area_light_data()) {
			CHECK((a.shading_method & RendererRD::LightStorage::AREA_METHOD_MASK) == uint32_t(cheap));
		}
		CHECK(f.light_storage.get_area_shading_method_mask() == (1u << cheap));
		CHECK(f.renderer.get_compiled_area_method_mask() == (1u << cheap));
		CHECK(shader.get_created_shader_count() == created_base + 1);

		// Zero budget: the most accurate method for this light; exactly one more version if it differs.
		const RS::LightAreaShadingMethod accurate = AreaMethodSelector::choose(q, r, 0.0f, n);
		{
			SettingOverride o(AreaMethodSelector::SETTING_ERROR_BUDGET, 0.0);
			f.render(d);
		}
		CHECK(f.light_storage.get_area_shading_method_mask() == (1u << accurate));
		CHECK(f.renderer.get_compiled_area_method_mask() == ((1u << cheap) | (1u << accurate)));
		CHECK(shader.get_created_shader_count() == created_base + (accurate == cheap ? 1 : 2));
		CHECK_FALSE(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_AUTO));

		// Without receivers: the camera distance (3 m) and the default-roughness setting decide.
		{
			SettingOverride o(AreaMethodSelector::SETTING_DEFAULT_ROUGHNESS, 1.0);
			RID rt = f.renderer.render_target_create(16, 16);
			RenderSceneData no_receivers = d;
			no_receivers.geometry.clear();
			f.renderer.render_scene(no_receivers, rt);
			f.renderer.render_target_free(rt);
		}
		REQUIRE(f.light_storage.get_area_auto_choices().size() == 2);
		CHECK(f.light_storage.get_area_auto_choices()[0].roughness == doctest::Approx(1.0f));
		CHECK(f.light_storage.get_area_auto_choices()[0].size_over_distance == doctest::Approx(1.5f / std::sqrt(9.0f + 1.0f)).epsilon(1e-3));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}
