/**************************************************************************/
/*  test_render_forward_clustered.cpp                                     */
/**************************************************************************/
/* godot-area: the Forward+ renderer on lavapipe with validation on:      */
/* analytic radiance of an omni light on a Lambertian plane, exact zero   */
/* outside a spot cone, and clustered == brute-force shading for many     */
/* lights. Scenes are built directly as RenderSceneData (no scene cull).  */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "servers/rendering/renderer_rd/cluster_builder_rd.h"
#include "servers/rendering/renderer_rd/renderer_compositor_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "servers/rendering/rendering_server_default.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

namespace TestRenderForwardClustered {

// Storages + renderer (tests/servers/render_test_fixture.h), 64 lights per type.
struct RenderFixture : RenderTest::RenderFixture {
	bool init() { return RenderTest::RenderFixture::init(64); }
};

using RenderTest::add_geometry;
using RenderTest::add_light;
using RenderTest::add_quad;
using RenderTest::camera_looking_down;
using RenderTest::make_box;
using RenderTest::make_plane;
using RenderTest::make_scene;
using RenderTest::pixel_on_ground;

static Color pixel(const std::vector<float> &p_img, int p_w, int p_x, int p_y) {
	const float *p = &p_img[(size_t(p_y) * p_w + p_x) * 4];
	return Color(p[0], p[1], p[2], p[3]);
}

// Godot 4's omni attenuation, written independently of the shader.
static double omni_attenuation(double p_d, double p_range, double p_decay) {
	double window = std::max(1.0 - std::pow(p_d / p_range, 4.0), 0.0);
	return window * window * std::pow(std::max(p_d, 1e-4), -p_decay);
}

TEST_CASE("[Render][ForwardClustered] Lambertian plane under an omni light matches the analytic radiance") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());

		const int W = 65, H = 65; // Odd: the centre pixel looks straight down the camera axis.
		RID plane = f.mesh_storage.mesh_create();
		f.meshes.push_back(plane);
		f.mesh_storage.mesh_add_surface(plane, make_plane(20.0f));

		RID mat = f.material_storage.material_create();
		f.materials.push_back(mat);
		RS::MaterialParams mp;
		mp.albedo = Color(0.6f, 0.5f, 0.4f, 1.0f); // sRGB.
		mp.roughness = 1.0f;
		mp.metallic = 0.0f;
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		mp.cull_back = false;
		f.material_storage.material_set_params(mat, mp);

		const float energy = 2.0f, range = 6.0f, decay = 1.0f, height = 2.0f;
		const Color light_color(1.0f, 0.9f, 0.8f, 1.0f); // sRGB.
		RID light = f.light_storage.light_create(RS::LIGHT_OMNI);
		f.lights.push_back(light);
		f.light_storage.light_set_param(light, RS::LIGHT_PARAM_ENERGY, energy);
		f.light_storage.light_set_param(light, RS::LIGHT_PARAM_RANGE, range);
		f.light_storage.light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, decay);
		f.light_storage.light_set_color(light, light_color);

		RenderSceneData d = make_scene(camera_looking_down(5.0f), 60.0f, W, H, 20.0f);
		add_geometry(d, plane, mat, Transform3D());
		const Vector3 light_pos(0, height, 0);
		add_light(d, light, RS::LIGHT_OMNI, Transform3D(Basis(), light_pos));

		RID rt = f.renderer.render_target_create(W, H);
		REQUIRE(rt.is_valid());
		f.renderer.render_scene(d, rt);
		std::vector<float> img = f.renderer.render_target_get_data(rt);
		REQUIRE(img.size() == size_t(W * H * 4));

		// Radiance the shader is documented to produce (scene_forward_lights_inc.glsl):
		// albedo / pi * (pi * energy * colour) * attenuation(d) * cos(theta), all linear.
		Color albedo = mp.albedo.srgb_to_linear();
		Color lc = light_color.srgb_to_linear();
		const int probes[3][2] = { { W / 2, H / 2 }, { 48, 20 }, { 10, 40 } };
		for (const auto &p : probes) {
			Vector3 point = pixel_on_ground(d, p[0], p[1]);
			Vector3 to_light = light_pos - point;
			double dist = to_light.length();
			double cos_theta = to_light.y / dist; // Plane normal +Y.
			double e = (1.0 / Math::PI) * (Math::PI * energy) * omni_attenuation(dist, range, decay) * cos_theta;
			Color got = pixel(img, W, p[0], p[1]);
			double expected[3] = { albedo.r * lc.r * e, albedo.g * lc.g * e, albedo.b * lc.b * e };
			double actual[3] = { got.r, got.g, got.b };
			for (int c = 0; c < 3; c++) {
				INFO("pixel (", p[0], ", ", p[1], ") channel ", c, " expected ", expected[c], " got ", actual[c]);
				CHECK(expected[c] > 0.01);
				CHECK(std::fabs(actual[c] - expected[c]) <= 0.01 * expected[c]);
			}
		}

		// Per-pass GPU timings are reported by name (values are not asserted).
		std::vector<std::pair<String, double>> profile = f.renderer.get_last_frame_profile();
		if (rd->get_device_info().timestamps_supported) {
			REQUIRE(profile.size() == 3);
			CHECK(profile[0].first == "depth_prepass");
			CHECK(profile[1].first == "cluster_build");
			CHECK(profile[2].first == "opaque");
			for (const auto &p : profile) {
				CHECK(p.second >= 0.0);
			}
		}
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][ForwardClustered] a spot light leaves pixels outside its cone exactly black") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RID plane = f.mesh_storage.mesh_create();
		f.meshes.push_back(plane);
		f.mesh_storage.mesh_add_surface(plane, make_plane(20.0f));
		RID mat = f.material_storage.material_create();
		f.materials.push_back(mat);
		RS::MaterialParams mp;
		mp.cull_back = false; // Default Burley + GGX: any shading model must give exact 0 outside the cone.
		f.material_storage.material_set_params(mat, mp);

		RID spot = f.light_storage.light_create(RS::LIGHT_SPOT);
		f.lights.push_back(spot);
		f.light_storage.light_set_param(spot, RS::LIGHT_PARAM_ENERGY, 4.0f);
		f.light_storage.light_set_param(spot, RS::LIGHT_PARAM_RANGE, 10.0f);
		f.light_storage.light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 20.0f);
		f.light_storage.light_set_param(spot, RS::LIGHT_PARAM_SPOT_ATTENUATION, 1.0f);

		RenderSceneData d = make_scene(camera_looking_down(5.0f), 60.0f, W, H, 20.0f);
		add_geometry(d, plane, mat, Transform3D());
		// Local -Z turned to world -Y: the spot points straight down from 2 m.
		const Vector3 spot_pos(0, 2, 0);
		add_light(d, spot, RS::LIGHT_SPOT, Transform3D(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f), spot_pos));

		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.render_scene(d, rt);
		std::vector<float> img = f.renderer.render_target_get_data(rt);
		REQUIRE(img.size() == size_t(W * H * 4));

		Color inside = pixel(img, W, W / 2, H / 2);
		CHECK(inside.r > 0.05f);
		CHECK(inside.g > 0.05f);

		// Every pixel whose ground point is outside the cone (with a small band left out at the edge)
		// must be exactly zero.
		const float cos_angle = std::cos(Math::deg_to_rad(20.0f));
		int outside_count = 0;
		int nonzero_outside = 0;
		for (int y = 0; y < H; y++) {
			for (int x = 0; x < W; x++) {
				Vector3 p = pixel_on_ground(d, x, y);
				Vector3 dir = (p - spot_pos).normalized();
				if (dir.dot(Vector3(0, -1, 0)) < cos_angle - 0.01f) {
					outside_count++;
					Color c = pixel(img, W, x, y);
					if (c.r != 0.0f || c.g != 0.0f || c.b != 0.0f) {
						nonzero_outside++;
					}
				}
			}
		}
		CHECK(outside_count > W * H / 2);
		CHECK_MESSAGE(nonzero_outside == 0, "pixels outside the spot cone must receive exactly no light");
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][ForwardClustered] clustered shading equals brute force for 64 random lights") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RID plane = f.mesh_storage.mesh_create();
		f.meshes.push_back(plane);
		f.mesh_storage.mesh_add_surface(plane, make_plane(10.0f));
		RID box = f.mesh_storage.mesh_create();
		f.meshes.push_back(box);
		f.mesh_storage.mesh_add_surface(box, make_box(Vector3(0.5f, 0.5f, 0.5f)));

		RID ground_mat = f.material_storage.material_create();
		RID box_mat = f.material_storage.material_create();
		f.materials.push_back(ground_mat);
		f.materials.push_back(box_mat);
		RS::MaterialParams gp;
		gp.albedo = Color(0.8f, 0.8f, 0.8f, 1);
		gp.roughness = 0.6f;
		gp.cull_back = false;
		f.material_storage.material_set_params(ground_mat, gp);
		RS::MaterialParams bp;
		bp.albedo = Color(0.9f, 0.4f, 0.2f, 1);
		bp.roughness = 0.3f;
		bp.metallic = 0.5f;
		f.material_storage.material_set_params(box_mat, bp);

		RenderSceneData d = make_scene(Transform3D(Basis::looking_at(Vector3(0, -6, -8)), Vector3(0, 6, 8)), 60.0f, W, H, 40.0f);
		add_geometry(d, plane, ground_mat, Transform3D());
		add_geometry(d, box, box_mat, Transform3D(Basis(), Vector3(-2, 0.5f, 0)));
		add_geometry(d, box, box_mat, Transform3D(Basis::from_axis_angle(Vector3(0, 1, 0), 0.6f), Vector3(1.5f, 0.5f, -1.5f)));
		add_geometry(d, box, box_mat, Transform3D(Basis(), Vector3(0.5f, 0.5f, 2.5f)));

		uint32_t seed = 12345u;
		auto rnd = [&seed]() {
			seed = seed * 1664525u + 1013904223u;
			return float(seed >> 8) / float(1u << 24);
		};
		for (int i = 0; i < 64; i++) {
			bool is_spot = (i % 2) == 1;
			RID l = f.light_storage.light_create(is_spot ? RS::LIGHT_SPOT : RS::LIGHT_OMNI);
			f.lights.push_back(l);
			f.light_storage.light_set_param(l, RS::LIGHT_PARAM_ENERGY, 0.5f + rnd() * 2.0f);
			f.light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, 0.8f + rnd() * 2.5f);
			f.light_storage.light_set_param(l, RS::LIGHT_PARAM_ATTENUATION, 0.5f + rnd() * 1.5f);
			f.light_storage.light_set_color(l, Color(0.3f + 0.7f * rnd(), 0.3f + 0.7f * rnd(), 0.3f + 0.7f * rnd(), 1));
			Vector3 pos(-6.0f + 12.0f * rnd(), 0.2f + 2.5f * rnd(), -6.0f + 12.0f * rnd());
			Basis basis;
			if (is_spot) {
				f.light_storage.light_set_param(l, RS::LIGHT_PARAM_SPOT_ANGLE, 10.0f + 70.0f * rnd());
				Vector3 target(pos.x + (rnd() - 0.5f) * 3.0f, 0.0f, pos.z + (rnd() - 0.5f) * 3.0f);
				basis = Basis::looking_at(target - pos, Vector3(0, 0, 1));
			}
			add_light(d, l, is_spot ? RS::LIGHT_SPOT : RS::LIGHT_OMNI, Transform3D(basis, pos));
		}

		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.set_debug_force_all_lights(false);
		f.renderer.render_scene(d, rt);
		std::vector<float> clustered = f.renderer.render_target_get_data(rt);

		// The clusters must actually cull (otherwise the comparison proves nothing).
		ClusterBuilderRD *cb = f.renderer.get_cluster_builder();
		CHECK(cb->get_element_count(ClusterBuilderRD::ELEMENT_TYPE_OMNI_LIGHT) == 32);
		CHECK(cb->get_element_count(ClusterBuilderRD::ELEMENT_TYPE_SPOT_LIGHT) == 32);
		std::vector<uint8_t> raw = rd->buffer_get_data(cb->get_cluster_buffer());
		std::vector<uint32_t> words(raw.size() / 4);
		memcpy(words.data(), raw.data(), words.size() * 4);
		uint64_t set_bits = 0;
		for (uint32_t w : words) {
			set_bits += __builtin_popcount(w);
		}
		uint64_t all_bits = uint64_t(cb->get_tiles_x()) * cb->get_tiles_y() * ClusterBuilderRD::Z_SLICES * 64;
		CHECK(set_bits > 0);
		CHECK(set_bits < all_bits / 4);

		f.renderer.set_debug_force_all_lights(true);
		f.renderer.render_scene(d, rt);
		std::vector<float> brute = f.renderer.render_target_get_data(rt);
		f.renderer.set_debug_force_all_lights(false);

		REQUIRE(clustered.size() == brute.size());
		float max_diff = 0.0f;
		int lit = 0;
		for (size_t i = 0; i < clustered.size(); i++) {
			max_diff = std::max(max_diff, std::fabs(clustered[i] - brute[i]));
			if ((i % 4) != 3 && brute[i] > 0.01f) {
				lit++;
			}
		}
		CHECK(lit > 200);
		CHECK_MESSAGE(max_diff < 1e-4f, "clustered and brute-force images differ by ", max_diff);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][ForwardClustered] back faces are culled with Godot's clockwise winding, unshaded outputs albedo") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int W = 32, H = 32;
		// Both quads face up (+Y) towards the camera; the second one is wound the other way round.
		RS::SurfaceData front;
		add_quad(front, Vector3(), Vector3(0, 0, 1), Vector3(1, 0, 0));
		RS::SurfaceData back;
		add_quad(back, Vector3(), Vector3(1, 0, 0), Vector3(0, 0, 1));
		for (Vector3 &n : back.normals) {
			n = -n; // Keep the normal pointing at the camera; only the winding differs.
		}
		RID front_mesh = f.mesh_storage.mesh_create();
		RID back_mesh = f.mesh_storage.mesh_create();
		f.meshes.push_back(front_mesh);
		f.meshes.push_back(back_mesh);
		f.mesh_storage.mesh_add_surface(front_mesh, front);
		f.mesh_storage.mesh_add_surface(back_mesh, back);

		RID mat = f.material_storage.material_create();
		f.materials.push_back(mat);
		RS::MaterialParams mp;
		mp.albedo = Color(1.0f, 0.5f, 0.0f, 1.0f);
		mp.unshaded = true;
		mp.cull_back = true;
		f.material_storage.material_set_params(mat, mp);

		RID rt = f.renderer.render_target_create(W, H);
		RenderSceneData d = make_scene(camera_looking_down(3.0f), 60.0f, W, H, 10.0f);
		d.environment.bg_color = Color(0, 0, 1, 1);
		add_geometry(d, front_mesh, mat, Transform3D());
		f.renderer.render_scene(d, rt);
		Color c = pixel(f.renderer.render_target_get_data(rt), W, W / 2, H / 2);
		CHECK(c.r == doctest::Approx(1.0f).epsilon(0.002));
		CHECK(c.g == doctest::Approx(Color::srgb_to_linear_channel(0.5f)).epsilon(0.002));
		CHECK(c.b == 0.0f);

		d.geometry.clear();
		add_geometry(d, back_mesh, mat, Transform3D());
		f.renderer.render_scene(d, rt);
		c = pixel(f.renderer.render_target_get_data(rt), W, W / 2, H / 2);
		CHECK_MESSAGE(c.b == doctest::Approx(1.0f), "a counter-clockwise quad is a back face and must be culled (background shows)");
		CHECK(c.r == 0.0f);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][ForwardClustered] albedo textures are decoded from sRGB and multiply the albedo colour") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int W = 16, H = 16;
		RID plane = f.mesh_storage.mesh_create();
		f.meshes.push_back(plane);
		f.mesh_storage.mesh_add_surface(plane, make_plane(20.0f));
		RID tex = f.material_storage.texture_2d_create(Image(2, 2, Color(0.5f, 0.25f, 1.0f, 1.0f)));
		REQUIRE(tex.is_valid());
		RID mat = f.material_storage.material_create();
		f.materials.push_back(mat);
		RS::MaterialParams mp;
		mp.albedo = Color(1.0f, 1.0f, 0.5f, 1.0f);
		mp.albedo_texture = tex;
		mp.unshaded = true;
		mp.cull_back = false;
		f.material_storage.material_set_params(mat, mp);

		RID rt = f.renderer.render_target_create(W, H);
		RenderSceneData d = make_scene(camera_looking_down(3.0f), 60.0f, W, H, 10.0f);
		add_geometry(d, plane, mat, Transform3D());
		f.renderer.render_scene(d, rt);
		Color c = pixel(f.renderer.render_target_get_data(rt), W, W / 2, H / 2);
		CHECK(c.r == doctest::Approx(Color::srgb_to_linear_channel(0.5f)).epsilon(0.005));
		CHECK(c.g == doctest::Approx(Color::srgb_to_linear_channel(0.25f)).epsilon(0.005));
		CHECK(c.b == doctest::Approx(Color::srgb_to_linear_channel(0.5f)).epsilon(0.005));

		// Freeing the texture falls back to white without errors.
		f.material_storage.texture_free(tex);
		f.renderer.render_scene(d, rt);
		c = pixel(f.renderer.render_target_get_data(rt), W, W / 2, H / 2);
		CHECK(c.r == doctest::Approx(1.0f).epsilon(0.002));
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][ForwardClustered] RenderingServer with RendererCompositorRD renders the analytic omni light") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RendererCompositorRD *compositor = new RendererCompositorRD;
		REQUIRE(compositor->initialize(64));
		RenderingServerDefault *rs = new RenderingServerDefault(compositor);

		const int W = 33, H = 33;
		RID mesh = rs->mesh_create();
		rs->mesh_add_surface(mesh, make_plane(20.0f));
		RID mat = rs->material_create();
		RS::MaterialParams mp;
		mp.albedo = Color(0.7f, 0.7f, 0.7f, 1.0f);
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		mp.cull_back = false;
		rs->material_set_params(mat, mp);
		rs->mesh_surface_set_material(mesh, 0, mat);

		RID light = rs->omni_light_create();
		rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, 1.5f);
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, 5.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 2.0f);

		RID env = rs->environment_create();
		rs->environment_set_background(env, RS::ENV_BG_COLOR);
		rs->environment_set_bg_color(env, Color(0, 0, 0, 1));
		rs->environment_set_ambient_light(env, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);

		RID scenario = rs->scenario_create();
		rs->scenario_set_environment(scenario, env);
		RID plane_instance = rs->instance_create();
		rs->instance_set_base(plane_instance, mesh);
		rs->instance_set_scenario(plane_instance, scenario);
		RID light_instance = rs->instance_create();
		rs->instance_set_base(light_instance, light);
		rs->instance_set_scenario(light_instance, scenario);
		const float height = 1.5f;
		rs->instance_set_transform(light_instance, Transform3D(Basis(), Vector3(0, height, 0)));

		RID camera = rs->camera_create();
		rs->camera_set_perspective(camera, 60.0f, 0.05f, 20.0f);
		rs->camera_set_transform(camera, camera_looking_down(4.0f));
		RID viewport = rs->viewport_create();
		rs->viewport_set_size(viewport, W, H);
		rs->viewport_attach_camera(viewport, camera);
		rs->viewport_set_scenario(viewport, scenario);

		rs->draw();
		Image img = rs->viewport_get_texture_data(viewport);
		REQUIRE(img.get_width() == W);
		REQUIRE(img.get_height() == H);
		// Centre pixel: straight under the light, cos(theta) = 1, distance = height.
		double expected = Color::srgb_to_linear_channel(0.7f) / Math::PI * (Math::PI * 1.5) * omni_attenuation(height, 5.0, 2.0);
		Color c = img.get_pixel(W / 2, H / 2);
		CHECK(c.r == doctest::Approx(expected).epsilon(0.01));
		CHECK(c.g == doctest::Approx(expected).epsilon(0.01));
		CHECK(img.get_pixel(0, 0).r < c.r);

		rs->free(viewport);
		rs->free(camera);
		rs->free(light_instance);
		rs->free(plane_instance);
		rs->free(scenario);
		rs->free(env);
		rs->free(light);
		rs->free(mat);
		rs->free(mesh);
		delete rs;
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestRenderForwardClustered
