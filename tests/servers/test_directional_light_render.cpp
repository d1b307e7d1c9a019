/**************************************************************************/
/*  test_directional_light_render.cpp                                     */
/**************************************************************************/
/* godot-area: DirectionalLight3D in the Forward+ renderer and in the     */
/* Embree reference (issue 16). A sun over a white Lambert plane shows    */
/* light_energy * cos(theta) (Godot scales the light colour by pi and the */
/* Lambert BRDF is 1/pi), uniformly over the image, for several sun       */
/* elevations; the reference samples the sun disk (light_angular_distance)*/
/* and must agree. A view without a directional light compiles no        */
/* directional code and allocates no directional buffer.                  */

#include "modules/reference/reference_renderer.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include "core/error/error_macros.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestDirectionalLightRender {

using RenderTest::add_geometry;
using RenderTest::camera_looking_down;
using RenderTest::make_plane;
using RenderTest::make_scene;

// A directional light whose -Z points down at p_elevation_deg above the horizon, towards +X.
static Transform3D sun_transform(float p_elevation_deg) {
	const float e = Math::deg_to_rad(p_elevation_deg);
	const Vector3 shine(std::cos(e), -std::sin(e), 0.0f); // Direction the light travels.
	return Transform3D(Basis::looking_at(shine, Vector3(0, 0, 1)), Vector3(0, 10, 0));
}

static void add_sun(RenderSceneData &r_d, RID p_light, const Transform3D &p_xform) {
	RenderSceneData::LightInstance l;
	l.light = p_light;
	l.type = RS::LIGHT_DIRECTIONAL;
	l.transform = p_xform;
	r_d.directional_lights.push_back(l);
}

TEST_CASE("[Render][DirectionalLight3D] sun over a white Lambert plane shows energy * cos(theta), GPU and reference, several elevations") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		ReferenceRenderOptions ro;
		ro.threads = 2;
		ro.sun_samples = 64;
		ReferenceRenderer reference(&f.light_storage, &f.mesh_storage, &f.material_storage, ro);

		const int W = 33, H = 33;
		RID plane = f.plane(30.0f);
		RS::MaterialParams mp;
		mp.albedo = Color(1, 1, 1, 1);
		mp.roughness = 1.0f;
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		RID mat = f.material(mp);

		const float energy = 1.7f;
		RID sun = f.light_storage.light_create(RS::LIGHT_DIRECTIONAL);
		f.lights.push_back(sun);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_ENERGY, energy);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SIZE, 4.0f); // A large disk: the reference really samples it.

		RID rt = f.renderer.render_target_create(W, H);
		RID ref_rt = reference.render_target_create(W, H);
		REQUIRE(rt.is_valid());
		REQUIRE(ref_rt.is_valid());
		const float elevations[4] = { 90.0f, 60.0f, 35.0f, 15.0f };
		for (float elevation : elevations) {
			RenderSceneData d = make_scene(camera_looking_down(4.0f), 60.0f, W, H, 20.0f);
			add_geometry(d, plane, mat, Transform3D());
			add_sun(d, sun, sun_transform(elevation));
			f.renderer.render_scene(d, rt);
			reference.render_scene(d, ref_rt);
			const std::vector<float> gpu = f.renderer.render_target_get_data(rt);
			const std::vector<float> ref = reference.render_target_get_data(ref_rt);
			REQUIRE(gpu.size() == size_t(W * H * 4));
			REQUIRE(ref.size() == gpu.size());
			// Plane normal +Y; the angle to the sun's centre is 90 degrees minus the elevation.
			const double expected = energy * std::sin(Math::deg_to_rad(double(elevation)));
			double gpu_min = 1e30, gpu_max = -1e30, ref_worst = 0.0;
			for (int i = 0; i < W * H; i++) {
				for (int c = 0; c < 3; c++) {
					const double g = gpu[size_t(i) * 4 + c];
					gpu_min = std::fmin(gpu_min, g);
					gpu_max = std::fmax(gpu_max, g);
					ref_worst = std::fmax(ref_worst, std::fabs(ref[size_t(i) * 4 + c] - expected) / expected);
				}
			}
			INFO("elevation ", elevation, " expected ", expected, " GPU min ", gpu_min, " max ", gpu_max, " reference worst relative error ", ref_worst);
			CHECK(std::fabs(gpu_min - expected) <= 0.01 * expected);
			CHECK(std::fabs(gpu_max - expected) <= 0.01 * expected);
			CHECK(ref_worst <= 0.01);
		}
		CHECK(f.renderer.get_compiled_feature_mask() == RenderForwardClustered::SCENE_VERSION_DIRECTIONAL);

		// The light's cull mask leaves a plane on other layers unlit; the directional loop honours it.
		f.light_storage.light_set_cull_mask(sun, 2u);
		RenderSceneData d = make_scene(camera_looking_down(4.0f), 60.0f, W, H, 20.0f);
		add_geometry(d, plane, mat, Transform3D());
		add_sun(d, sun, sun_transform(60.0f));
		f.renderer.render_scene(d, rt);
		reference.render_scene(d, ref_rt);
		CHECK(f.renderer.render_target_get_data(rt)[(W * (H / 2) + W / 2) * 4] == 0.0f);
		CHECK(reference.render_target_get_data(ref_rt)[(W * (H / 2) + W / 2) * 4] == 0.0f);
		reference.render_target_free(ref_rt);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][DirectionalLight3D] a view without a directional light compiles no directional code and allocates no buffer") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		RID plane = f.plane(5.0f);
		RS::MaterialParams mp;
		RID mat = f.material(mp);
		RID omni = f.light_storage.light_create(RS::LIGHT_OMNI);
		f.lights.push_back(omni);
		RenderSceneData d = make_scene(camera_looking_down(3.0f), 60.0f, 16, 16, 20.0f);
		add_geometry(d, plane, mat, Transform3D());
		RenderTest::add_light(d, omni, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(0, 1, 0)));
		RID rt = f.renderer.render_target_create(16, 16);
		f.renderer.render_scene(d, rt);
		CHECK(f.renderer.get_compiled_feature_mask() == 0u);
		CHECK_FALSE(f.light_storage.get_directional_light_buffer().is_valid());
		CHECK(f.light_storage.get_directional_light_count() == 0u);
		// Only a directional version defines USE_DIRECTIONAL_LIGHTS (the guard of binding 8 and of the loop).
		CHECK(RenderForwardClustered::get_scene_version_defines(0u).find("USE_DIRECTIONAL_LIGHTS") == String::npos);
		CHECK(RenderForwardClustered::get_scene_version_defines(RenderForwardClustered::SCENE_VERSION_DIRECTIONAL) == "#define USE_DIRECTIONAL_LIGHTS\n");
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[LightStorage] more than MAX_DIRECTIONAL_LIGHTS directional lights: the first eight are kept, the rest counted") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		std::vector<RenderSceneData::LightInstance> lights;
		for (int i = 0; i < 10; i++) {
			RID l = f.light_storage.light_create(RS::LIGHT_DIRECTIONAL);
			f.lights.push_back(l);
			f.light_storage.light_set_param(l, RS::LIGHT_PARAM_ENERGY, float(i + 1));
			RenderSceneData::LightInstance li;
			li.light = l;
			li.type = RS::LIGHT_DIRECTIONAL;
			lights.push_back(li);
		}
		int warnings = 0;
		ErrorHandlerList handler;
		handler.callback = [&warnings](ErrorHandlerType p_type, const String &p_text) {
			warnings += (p_type == ERR_HANDLER_WARNING && p_text.find("directional lights beyond") != String::npos) ? 1 : 0;
		};
		add_error_handler(&handler);
		set_error_print_silenced(true);
		f.light_storage.update_directional_light_buffer(lights, Transform3D());
		set_error_print_silenced(false);
		remove_error_handler(&handler);
		CHECK(warnings == 1);
		CHECK(f.light_storage.get_directional_light_count() == RendererRD::LightStorage::MAX_DIRECTIONAL_LIGHTS);
		CHECK(f.light_storage.get_directional_lights_dropped() == 2u);
		const RendererRD::LightStorage::DirectionalLightBlock &b = f.light_storage.get_directional_light_block();
		CHECK(b.data[7].color[0] == doctest::Approx(8.0 * Math::PI));
		// Light -Z in view space with an identity view: (0, 0, -1).
		CHECK(b.data[0].direction[2] == doctest::Approx(-1.0));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestDirectionalLightRender
