/**************************************************************************/
/*  test_environment_ss_lighting.cpp                                      */
/**************************************************************************/
/* godot-area: Environment's SSAO / SSIL properties (issue 22): Godot 4's */
/* names and defaults, validation, the path to the renderer, and a Godot  */
/* text scene that enables them.                                          */

#include "scene/3d/world_environment.h"
#include "scene/resources/environment.h"
#include "scene/resources/resource_format_text.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

namespace TestEnvironmentSSLighting {

TEST_CASE("[Environment] SSAO and SSIL properties have Godot 4's names and defaults") {
	SceneTest::DummyServer server;
	Ref<Environment> env;
	env.instantiate();
	CHECK(env->get("ssao_enabled") == Variant(false));
	CHECK(float(env->get("ssao_radius")) == doctest::Approx(1.0f));
	CHECK(float(env->get("ssao_intensity")) == doctest::Approx(2.0f));
	CHECK(float(env->get("ssao_power")) == doctest::Approx(1.5f));
	CHECK(float(env->get("ssao_detail")) == doctest::Approx(0.5f));
	CHECK(float(env->get("ssao_horizon")) == doctest::Approx(0.06f));
	CHECK(float(env->get("ssao_sharpness")) == doctest::Approx(0.98f));
	CHECK(float(env->get("ssao_light_affect")) == doctest::Approx(0.0f));
	CHECK(float(env->get("ssao_ao_channel_affect")) == doctest::Approx(0.0f));
	CHECK(env->get("ssil_enabled") == Variant(false));
	CHECK(float(env->get("ssil_radius")) == doctest::Approx(5.0f));
	CHECK(float(env->get("ssil_intensity")) == doctest::Approx(1.0f));
	CHECK(float(env->get("ssil_sharpness")) == doctest::Approx(0.98f));
	CHECK(float(env->get("ssil_normal_rejection")) == doctest::Approx(1.0f));
	// ssao_light_affect is Godot's saved name of the direct_light_affect setter pair.
	env->set("ssao_light_affect", 0.25f);
	CHECK(env->get_ssao_direct_light_affect() == doctest::Approx(0.25f));
	{
		SceneTest::ErrorCatcher errors;
		env->set_ssil_normal_rejection(1.5f);
		CHECK(errors.contains("ssil_normal_rejection"));
		env->set_ssao_radius(-1.0f);
		CHECK(errors.contains("ssao_radius"));
	}
	CHECK(env->get_ssil_normal_rejection() == doctest::Approx(1.0f)); // The old value is kept.
	CHECK(env->get_ssao_radius() == doctest::Approx(1.0f));
}

TEST_CASE("[Environment] SSIL and SSAO settings and the global quality reach the renderer") {
	SceneTest::DummyServer server;
	Ref<Environment> env;
	env.instantiate();
	env->set_ssil_enabled(true);
	env->set_ssil_radius(2.5f);
	env->set_ssil_intensity(0.5f);
	env->set_ssao_enabled(true);
	env->set_ssao_power(2.0f);
	server.rs->environment_set_ssil_quality(RS::ENV_SSIL_QUALITY_HIGH, false, 1);
	RID scenario = server.rs->scenario_create();
	RID camera = server.rs->camera_create();
	server.rs->scenario_set_environment(scenario, env->get_rid());
	RenderSceneData data;
	REQUIRE(server.rs->get_scene_cull()->build_render_scene_data(camera, scenario, 8, 8, Color(0.3f, 0.3f, 0.3f), data));
	const ScreenSpaceLightingSettings &s = data.environment.ss_lighting;
	CHECK(s.ssil_enabled);
	CHECK(s.ssil_radius == doctest::Approx(2.5f));
	CHECK(s.ssil_intensity == doctest::Approx(0.5f));
	CHECK(s.ssao_enabled);
	CHECK(s.ssao_power == doctest::Approx(2.0f));
	CHECK(s.ssil_quality == RS::ENV_SSIL_QUALITY_HIGH);
	CHECK_FALSE(s.ssil_half_size);
	CHECK(s.ssil_blur_passes == 1);
	CHECK(RS::get_ss_radiosity_sample_count(s.ssil_quality) == 80);
	// A camera environment without SSIL overrides the world's.
	Ref<Environment> plain;
	plain.instantiate();
	server.rs->camera_set_environment(camera, plain->get_rid());
	REQUIRE(server.rs->get_scene_cull()->build_render_scene_data(camera, scenario, 8, 8, Color(0.3f, 0.3f, 0.3f), data));
	CHECK_FALSE(data.environment.ss_lighting.is_active());
	{
		SceneTest::ErrorCatcher errors;
		server.rs->environment_set_ssao_quality(RS::EnvironmentSSAOQuality(7), true, 2);
		CHECK(errors.contains("quality"));
	}
	server.rs->environment_set_ssil_quality(RS::ENV_SSIL_QUALITY_MEDIUM, true, 2); // Restore the global default.
	server.rs->free(camera);
	server.rs->free(scenario);
}

static const char *SSIL_SCENE = R"([gd_scene load_steps=2 format=3 uid="uid://b1ssilroom"]

[sub_resource type="Environment" id="Environment_ssil"]
ssao_enabled = true
ssao_radius = 0.5
ssao_light_affect = 0.3
ssil_enabled = true
ssil_radius = 3.0
ssil_intensity = 0.8
ssil_normal_rejection = 0.5

[node name="Main" type="Node3D"]

[node name="WorldEnvironment" type="WorldEnvironment" parent="."]
environment = SubResource("Environment_ssil")
)";

TEST_CASE("[Environment][TSCN] a Godot scene with SSIL and SSAO loads them and saves them back") {
	SceneTest::DummyServer server;
	String err;
	Node *root = ResourceFormatText::load_scene_from_string(SSIL_SCENE, "res_test/ssil.tscn", &err);
	REQUIRE_MESSAGE(root != nullptr, err.c_str());
	WorldEnvironment *we = Object::cast_to<WorldEnvironment>(root->get_node_or_null("WorldEnvironment"));
	REQUIRE(we != nullptr);
	Ref<Environment> env = we->get_environment();
	REQUIRE(env.is_valid());
	CHECK(env->is_ssao_enabled());
	CHECK(env->get_ssao_radius() == doctest::Approx(0.5f));
	CHECK(env->get_ssao_direct_light_affect() == doctest::Approx(0.3f));
	CHECK(env->is_ssil_enabled());
	CHECK(env->get_ssil_radius() == doctest::Approx(3.0f));
	CHECK(env->get_ssil_intensity() == doctest::Approx(0.8f));
	CHECK(env->get_ssil_normal_rejection() == doctest::Approx(0.5f));
	CHECK(env->get_ssil_sharpness() == doctest::Approx(0.98f)); // Missing key: Godot's default.
	const String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("ssil_radius = 3") != String::npos);
	CHECK(saved.find("ssao_light_affect = 0.3") != String::npos);
	CHECK(saved.find("ssil_sharpness") == String::npos); // Defaults are not written, as Godot.
	delete root;
}

} // namespace TestEnvironmentSSLighting
