/**************************************************************************/
/*  test_sky_reflections.cpp                                              */
/**************************************************************************/
/* godot-area: sky reflections (issue 16): the radiance cubemap of SkyRD  */
/* (GGX-prefiltered mips, split-sum DFG fit in the scene shader) on a     */
/* smooth and a rough metal sphere under Godot's default                  */
/* ProceduralSkyMaterial, against the Embree reference, which integrates  */
/* sky(L) f_spec (N.L) exactly (GGX importance sampling, no split sum).  */
/* Bounds measured with this test (the MESSAGE lines print them) and set */
/* a little above: see REFLECTION_* below. Also: the cubemap is filtered */
/* once per sky change, a view without a sky or with                     */
/* reflected_light_source DISABLED builds none, and the RS wiring of      */
/* Environment.reflected_light_source.                                    */

#include "modules/reference/reference_renderer.h"
#include "scene/resources/environment.h"
#include "scene/resources/sky.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "tests/scene/scene_test_fixture.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestSkyReflections {

// Measured 2026-12-02 03:37 UTC on lavapipe (64x64, 256 reference samples per pixel; doc/sun_sky.md,
// "Sky reflections"): roughness 0.05: relative RMSE 0.0334, mean ratio GPU/reference 0.974; roughness 0.6:
// 0.0925 and 0.925. Most of it is Karis' analytic DFG fit (a few % low for a mirror, 4-14 % low at 0.6
// against this BRDF: misc/scripts/env_brdf_check.py). Bounds a little above.
static const double REFLECTION_SMOOTH_RMSE_BOUND = 0.045;
static const double REFLECTION_SMOOTH_RATIO_BOUND = 0.035;
static const double REFLECTION_ROUGH_RMSE_BOUND = 0.12;
static const double REFLECTION_ROUGH_RATIO_BOUND = 0.10;

// Default ProceduralSkyMaterial as background; ambient source BG (sky ambient); reflected_light_source BG.
static void set_default_sky(RenderSceneData &r_d) {
	r_d.environment.has_environment = true;
	r_d.environment.has_sky = true;
	r_d.environment.sky = RS::ProceduralSkyParams();
	r_d.environment.background = RS::ENV_BG_SKY;
	r_d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_BG;
	r_d.environment.sky_ambient = true;
	r_d.environment.ambient_sky_contribution = 1.0f;
	r_d.environment.sky_reflections = true;
}

struct SphereError {
	double rel_rmse = 0.0;
	double mean_ratio = 0.0;
	int pixels = 0;
};

// Relative RMSE and mean brightness ratio (luminance) over the pixels inside the unit sphere's silhouette.
static SphereError sphere_error(const RenderSceneData &p_d, const Transform3D &p_cam, int p_w, int p_h, const std::vector<float> &p_gpu, const std::vector<float> &p_ref) {
	const Projection view_from_clip = (Projection::create_depth_correction(true) * p_d.cam_projection).inverse();
	double se = 0.0, sr = 0.0, sum_g = 0.0, sum_r = 0.0;
	SphereError e;
	for (int y = 0; y < p_h; y++) {
		for (int x = 0; x < p_w; x++) {
			const float nx = (x + 0.5f) / p_w * 2.0f - 1.0f, ny = (y + 0.5f) / p_h * 2.0f - 1.0f;
			const Vector3 a = p_cam.xform(view_from_clip.xform(Vector3(nx, ny, 0.0f)));
			const Vector3 dir = (p_cam.xform(view_from_clip.xform(Vector3(nx, ny, 1.0f))) - a).normalized();
			const float bq = a.dot(dir), disc = bq * bq - (a.length_squared() - 1.0f);
			if (disc <= 0.05f) {
				continue; // Outside, or a silhouette pixel (partly background).
			}
			const size_t i = (size_t(y) * p_w + x) * 4;
			const double lg = 0.2126 * p_gpu[i] + 0.7152 * p_gpu[i + 1] + 0.0722 * p_gpu[i + 2];
			const double lr = 0.2126 * p_ref[i] + 0.7152 * p_ref[i + 1] + 0.0722 * p_ref[i + 2];
			se += (lg - lr) * (lg - lr);
			sr += lr * lr;
			sum_g += lg;
			sum_r += lr;
			e.pixels++;
		}
	}
	e.rel_rmse = sr > 0.0 ? std::sqrt(se / sr) : 1e9;
	e.mean_ratio = sum_r > 0.0 ? sum_g / sum_r : 0.0;
	return e;
}

TEST_CASE("[Render][Sky] sky reflections on a smooth and a rough metal sphere match the Embree reference") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		ReferenceRenderOptions ro;
		ro.threads = 2;
		ro.sky_samples = 256;
		ReferenceRenderer reference(&f.light_storage, &f.mesh_storage, &f.material_storage, ro);
		const int W = 64, H = 64;
		RID sphere = f.mesh(RenderTest::make_sphere(1.0f, 48, 96));
		// Camera a little above the equator: the sphere reflects the sky, the horizon and the ground.
		const Transform3D cam(Basis::looking_at(Vector3(0, -0.25f, -1).normalized(), Vector3(0, 1, 0)), Vector3(0, 1.0f, 4.0f));
		RID rt = f.renderer.render_target_create(W, H);
		RID ref_rt = reference.render_target_create(W, H);
		const float roughness[2] = { 0.05f, 0.6f };
		const double rmse_bound[2] = { REFLECTION_SMOOTH_RMSE_BOUND, REFLECTION_ROUGH_RMSE_BOUND };
		const double ratio_bound[2] = { REFLECTION_SMOOTH_RATIO_BOUND, REFLECTION_ROUGH_RATIO_BOUND };
		for (int k = 0; k < 2; k++) {
			RS::MaterialParams mp;
			mp.albedo = Color(0.95f, 0.93f, 0.88f, 1);
			mp.metallic = 1.0f;
			mp.roughness = roughness[k];
			RID mat = f.material(mp);
			RenderSceneData d = RenderTest::make_scene(cam, 60.0f, W, H, 50.0f);
			set_default_sky(d);
			RenderTest::add_geometry(d, sphere, mat, Transform3D());
			f.renderer.render_scene(d, rt);
			reference.render_scene(d, ref_rt);
			const std::vector<float> gpu = f.renderer.render_target_get_data(rt);
			const std::vector<float> ref = reference.render_target_get_data(ref_rt);
			REQUIRE(gpu.size() == size_t(W * H * 4));
			REQUIRE(ref.size() == gpu.size());
			const SphereError e = sphere_error(d, cam, W, H, gpu, ref);
			MESSAGE("sky reflection, metal sphere roughness ", roughness[k], ": relative RMSE ", e.rel_rmse, ", mean brightness ratio GPU/reference ", e.mean_ratio, " (", e.pixels, " pixels)");
			REQUIRE(e.pixels > 500);
			CHECK(e.rel_rmse <= rmse_bound[k]);
			CHECK(std::fabs(e.mean_ratio - 1.0) <= ratio_bound[k]);
		}
		CHECK((f.renderer.get_compiled_feature_mask() & RenderForwardClustered::SCENE_VERSION_SKY_REFLECTION) != 0u);
		const SkyRD &sky = f.renderer.get_sky();
		CHECK(sky.get_radiance_texture().is_valid());
		CHECK(sky.get_radiance_mips() == 8); // radiance_size 256: 256 .. 2, Godot's 8 roughness layers.
		// Two frames with the same sky (the second sphere is a new material, not a new sky): filtered once.
		CHECK(sky.get_radiance_update_count() == 1u);
		bool timed = false;
		for (const auto &p : f.renderer.get_last_frame_profile()) {
			timed = timed || p.first == "sky_radiance";
		}
		CHECK_FALSE(timed); // A static sky is not re-filtered, so the pass is absent.
		RenderSceneData d = RenderTest::make_scene(cam, 60.0f, W, H, 50.0f);
		set_default_sky(d);
		d.environment.sky.sky_top_color = Color(0.1f, 0.3f, 0.9f);
		f.renderer.render_scene(d, rt);
		CHECK(sky.get_radiance_update_count() == 2u);
		if (rd->get_device_info().timestamps_supported) {
			for (const auto &p : f.renderer.get_last_frame_profile()) {
				timed = timed || p.first == "sky_radiance";
			}
			CHECK(timed);
		}
		// A different radiance_size rebuilds the cubemap at that size.
		d.environment.sky_radiance_size = 32;
		f.renderer.render_scene(d, rt);
		CHECK(sky.get_radiance_update_count() == 3u);
		CHECK(sky.get_radiance_mips() == 6);
		reference.render_target_free(ref_rt);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][Sky] no sky reflections without a sky or with reflected_light_source DISABLED: no cubemap") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		RID plane = f.plane(5.0f);
		RS::MaterialParams mp;
		mp.metallic = 1.0f;
		mp.roughness = 0.1f;
		RID mat = f.material(mp);
		RenderSceneData d = RenderTest::make_scene(RenderTest::camera_looking_down(3.0f), 60.0f, 16, 16, 20.0f);
		RenderTest::add_geometry(d, plane, mat, Transform3D());
		RID rt = f.renderer.render_target_create(16, 16);
		f.renderer.render_scene(d, rt);
		CHECK_FALSE(f.renderer.get_sky().get_radiance_texture().is_valid());
		// A sky background and ambient, but reflections resolved off (DISABLED): background and SH only.
		set_default_sky(d);
		d.environment.sky_reflections = false;
		f.renderer.render_scene(d, rt);
		CHECK_FALSE(f.renderer.get_sky().get_radiance_texture().is_valid());
		CHECK(f.renderer.get_sky().get_radiance_update_count() == 0u);
		CHECK((f.renderer.get_compiled_feature_mask() & RenderForwardClustered::SCENE_VERSION_SKY_REFLECTION) == 0u);
		for (const auto &p : f.renderer.get_last_frame_profile()) {
			CHECK(p.first != "sky_radiance");
		}
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Environment][Sky] reflected_light_source: Godot's default BG and meanings reach the renderer") {
	SceneTest::DummyServer server;
	Ref<ProceduralSkyMaterial> material;
	material.instantiate();
	Ref<Sky> sky;
	sky.instantiate();
	sky->set_material(material);
	Ref<Environment> env;
	env.instantiate();
	CHECK(env->get_reflection_source() == Environment::REFLECTION_SOURCE_BG);
	env->set_sky(sky);
	RID scenario = server.rs->scenario_create();
	RID camera = server.rs->camera_create();
	server.rs->scenario_set_environment(scenario, env->get_rid());
	RenderSceneData data;
	auto build = [&]() {
		data = RenderSceneData();
		REQUIRE(server.rs->get_scene_cull()->build_render_scene_data(camera, scenario, 8, 8, Color(0.3f, 0.3f, 0.3f), data));
	};
	// BG with a colour background: no sky reflections (and no sky at all).
	env->set("background_mode", (int)Environment::BG_COLOR);
	build();
	CHECK_FALSE(data.environment.sky_reflections);
	CHECK_FALSE(data.environment.has_sky);
	// SKY: the sky reflects whatever the background.
	env->set_reflection_source(Environment::REFLECTION_SOURCE_SKY);
	build();
	CHECK(data.environment.sky_reflections);
	CHECK(data.environment.has_sky);
	// BG with a sky background: reflections from the sky.
	env->set_reflection_source(Environment::REFLECTION_SOURCE_BG);
	env->set("background_mode", (int)Environment::BG_SKY);
	build();
	CHECK(data.environment.sky_reflections);
	// DISABLED: none, even under a sky background.
	env->set("reflected_light_source", (int)Environment::REFLECTION_SOURCE_DISABLED);
	build();
	CHECK_FALSE(data.environment.sky_reflections);
	CHECK(data.environment.has_sky); // Still the background.
	{
		SceneTest::ErrorCatcher errors;
		env->set_reflection_source(Environment::ReflectionSource(7));
		CHECK(errors.contains("reflected_light_source"));
	}
	CHECK(env->get_reflection_source() == Environment::REFLECTION_SOURCE_DISABLED);
	server.rs->free(camera);
	server.rs->free(scenario);
}

} // namespace TestSkyReflections
