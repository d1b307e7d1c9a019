/**************************************************************************/
/*  test_area_light_render.cpp                                            */
/**************************************************************************/
/* godot-area: area lights shaded with LTC in the Forward+ renderer on    */
/* lavapipe (validation on): the closed-form configuration factor under a */
/* corner of the light, the specular highlight's shape, exact zero behind */
/* the light and for a zero-size light, and the area-light shader variant */
/* being compiled only for scenes with area lights. Scenes are built as   */
/* RenderSceneData (RenderForwardClustered + RD storages, no scene cull). */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "servers/rendering/renderer_rd/renderer_compositor_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "servers/rendering/rendering_server_default.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace TestAreaLightRender {

// Storages + renderer, plane/material/area light helpers: tests/servers/render_test_fixture.h.
using AreaFixture = RenderTest::RenderFixture;
using RenderTest::add_geometry;
using RenderTest::add_light;
using RenderTest::camera_looking_down;
using RenderTest::facing_down;
using RenderTest::make_scene;
using RenderTest::pixel_on_ground;

static const float *pixel(const std::vector<float> &p_img, int p_w, int p_x, int p_y) {
	return &p_img[(size_t(p_y) * p_w + p_x) * 4];
}

// Configuration factor from a differential area to a parallel rectangle a x b at distance h, the
// differential area lying on the normal through one corner of the rectangle (Howell's catalogue, B-3).
static double corner_configuration_factor(double p_a, double p_b, double p_h) {
	double x = p_a / p_h, y = p_b / p_h;
	double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
	return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * Math::PI);
}

TEST_CASE("[AreaLight3D][Render] a Lambertian plane under a corner of a parallel rectangle light matches the configuration factor") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 65, H = 65; // Odd: the centre pixel looks straight down at the world origin.
		RS::MaterialParams mp;
		mp.albedo = Color(0.8f, 0.7f, 0.6f, 1.0f);
		mp.specular = 0.0f; // f0 = 0 and f90 = 0: no specular at all.
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID plane = f.plane(50.0f);

		const float a = 2.0f, b = 1.0f, h = 1.5f, energy = 3.0f;
		const Color light_color(1.0f, 0.9f, 0.7f, 1.0f);
		RID light = f.area_light(Vector2(a, b), energy, 1000.0f, 2.0f);
		f.light_storage.light_set_color(light, light_color);

		RenderSceneData d = make_scene(camera_looking_down(4.0f), 60.0f, W, H, 20.0f);
		add_geometry(d, plane, mat);
		// Rectangle spans world x in [0, a] and z in [0, b] at height h: its corner is right above the origin.
		add_light(d, light, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(a * 0.5f, h, b * 0.5f)));

		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.render_scene(d, rt);
		std::vector<float> img = f.renderer.render_target_get_data(rt);
		REQUIRE(img.size() == size_t(W * H * 4));
		CHECK(f.renderer.is_scene_shader_variant_compiled(RenderForwardClustered::SCENE_SHADER_COLOR_AREA));

		// Contract units: L_e = colour * energy * pi / (a b); radiance = albedo / pi * L_e * pi * F.
		Color albedo = mp.albedo.srgb_to_linear();
		Color lc = light_color.srgb_to_linear();
		double le = energy * Math::PI / (a * b);
		double ff = corner_configuration_factor(a, b, h);
		const float *px = pixel(img, W, W / 2, H / 2);
		double expected[3] = { albedo.r * lc.r * le * ff, albedo.g * lc.g * le * ff, albedo.b * lc.b * le * ff };
		for (int c = 0; c < 3; c++) {
			INFO("channel ", c, ": expected ", expected[c], ", got ", px[c]);
			CHECK(std::fabs(px[c] - expected[c]) <= 0.005 * expected[c]);
		}

		// Under the centre: four corner factors of (a/2, b/2).
		d.lights.clear();
		add_light(d, light, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, h, 0)));
		f.renderer.render_scene(d, rt);
		img = f.renderer.render_target_get_data(rt);
		double ff_centre = 4.0 * corner_configuration_factor(a * 0.5, b * 0.5, h);
		px = pixel(img, W, W / 2, H / 2);
		double expected_r = albedo.r * lc.r * le * ff_centre;
		INFO("centre: expected ", expected_r, ", got ", px[0]);
		CHECK(std::fabs(px[0] - expected_r) <= 0.005 * expected_r);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] RenderingServer with RendererCompositorRD renders an area light with the configuration factor") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RendererCompositorRD *compositor = new RendererCompositorRD;
		REQUIRE(compositor->initialize(64));
		RenderingServerDefault *rs = new RenderingServerDefault(compositor);
		const int W = 33, H = 33;
		RS::SurfaceData s;
		Vector3 u(0, 0, 20), v(20, 0, 0);
		Vector3 corners[4] = { -u - v, u - v, u + v, -u + v };
		for (int i = 0; i < 4; i++) {
			s.vertices.push_back(corners[i]);
			s.normals.push_back(Vector3(0, 1, 0));
		}
		s.indices = { 0, 2, 1, 0, 3, 2 };
		RID mesh = rs->mesh_create();
		rs->mesh_add_surface(mesh, s);
		RID mat = rs->material_create();
		RS::MaterialParams mp;
		mp.albedo = Color(0.7f, 0.7f, 0.7f, 1.0f);
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		mp.cull_back = false;
		rs->material_set_params(mat, mp);
		rs->mesh_surface_set_material(mesh, 0, mat);

		const float a = 1.0f, b = 2.0f, h = 1.2f;
		RID light = rs->area_light_create();
		rs->light_area_set_size(light, Vector2(a, b));
		rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, 2.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, 500.0f);
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
		// Corner of the rectangle right above the origin.
		rs->instance_set_transform(light_instance, Transform3D(facing_down(), Vector3(a * 0.5f, h, b * 0.5f)));
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
		double expected = Color::srgb_to_linear_channel(0.7f) * (2.0 * Math::PI / (a * b)) * corner_configuration_factor(a, b, h);
		Color c = img.get_pixel(W / 2, H / 2);
		CHECK(c.r == doctest::Approx(expected).epsilon(0.005));

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

TEST_CASE("[AreaLight3D][Render] the specular highlight of a 4:1 light is elongated along the light's long axis") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RS::MaterialParams mp;
		mp.albedo = Color(1, 1, 1, 1);
		mp.metallic = 1.0f; // Pure specular: no diffuse term.
		mp.roughness = 0.3f;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID plane = f.plane(50.0f);

		RenderSceneData d = make_scene(camera_looking_down(4.0f), 70.0f, W, H, 20.0f);
		add_geometry(d, plane, mat);

		struct Extents {
			float x, z;
			int count;
		};
		auto measure = [&](const Vector2 &p_size) {
			RID light = f.area_light(p_size, 2.0f, 100.0f, 2.0f);
			d.lights.clear();
			add_light(d, light, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, 1.5f, 0)));
			RID rt = f.renderer.render_target_create(W, H);
			f.renderer.render_scene(d, rt);
			std::vector<float> img = f.renderer.render_target_get_data(rt);
			f.renderer.render_target_free(rt);
			float peak = 0.0f;
			for (size_t i = 0; i < img.size(); i += 4) {
				peak = std::max(peak, img[i]);
			}
			Extents e = { 0.0f, 0.0f, 0 };
			float min_x = 1e9f, max_x = -1e9f, min_z = 1e9f, max_z = -1e9f;
			for (int y = 0; y < H; y++) {
				for (int x = 0; x < W; x++) {
					if (pixel(img, W, x, y)[0] >= 0.5f * peak) {
						Vector3 p = pixel_on_ground(d, x, y);
						min_x = std::min(min_x, p.x);
						max_x = std::max(max_x, p.x);
						min_z = std::min(min_z, p.z);
						max_z = std::max(max_z, p.z);
						e.count++;
					}
				}
			}
			e.x = max_x - min_x;
			e.z = max_z - min_z;
			CHECK(peak > 0.01f);
			return e;
		};
		// Light long axis = local X = world X.
		Extents wide = measure(Vector2(2.0f, 0.5f));
		MESSAGE("4:1 light: highlight extent x ", wide.x, " m, z ", wide.z, " m, ", wide.count, " pixels");
		CHECK(wide.count > 10);
		CHECK_MESSAGE(wide.x > 2.0f * wide.z, "the highlight must be clearly elongated along the light's long axis (x)");
		// Rotated light (1:4): elongated along z instead.
		Extents tall = measure(Vector2(0.5f, 2.0f));
		MESSAGE("1:4 light: highlight extent x ", tall.x, " m, z ", tall.z, " m");
		CHECK(tall.z > 2.0f * tall.x);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

// The engine's specular lobe for f0 = f90 = 1 (brdf_inc.glsl: D_GGX * V_SmithGGXCorrelatedFast), written
// independently here: the quadrature reference for the LTC fit.
static double engine_ggx(const Vector3 &p_n, const Vector3 &p_v, const Vector3 &p_l, double p_roughness) {
	double alpha = p_roughness * p_roughness;
	Vector3 h = (p_v + p_l).normalized();
	double noh = std::max(0.0, double(p_n.dot(h)));
	double nol = std::max(0.0, double(p_n.dot(p_l)));
	double nov = std::max(1e-4, double(p_n.dot(p_v)));
	double a2 = alpha * alpha;
	double f = noh * noh * (a2 - 1.0) + 1.0;
	double d = a2 / (Math::PI * f * f);
	double vis = 0.5 / (2.0 * nol * nov * (1.0 - alpha) + (nol + nov) * alpha);
	return d * vis;
}

TEST_CASE("[AreaLight3D][Render] LTC specular at an oblique view follows the numerically integrated GGX lobe") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 33, H = 33;
		RID plane = f.plane(50.0f);
		const Transform3D cam(Basis::looking_at(Vector3(0, -2, -3)), Vector3(0, 2, 3));
		RenderSceneData d = make_scene(cam, 40.0f, W, H, 20.0f);
		const Vector3 point = pixel_on_ground(d, W / 2, H / 2); // The origin.
		const Vector3 n(0, 1, 0);
		const Vector3 v = (cam.origin - point).normalized();
		const Vector3 mirror(-v.x, v.y, -v.z);
		const float a = 1.0f, b = 0.6f, energy = 1.0f;
		// The light sits on (or next to) the mirror direction, 2 m away, facing the shading point.
		const Vector3 offsets[2] = { Vector3(), Vector3(0.7f, 0, 0) };
		const float roughnesses[2] = { 0.5f, 0.3f };
		for (float roughness : roughnesses) {
			RS::MaterialParams mp;
			mp.albedo = Color(1, 1, 1, 1);
			mp.metallic = 1.0f; // f0 = 1, f90 = 1: F = 1, no diffuse.
			mp.roughness = roughness;
			mp.cull_back = false;
			RID mat = f.material(mp);
			d.geometry.clear();
			add_geometry(d, plane, mat);
			for (const Vector3 &offset : offsets) {
				Vector3 centre = point + mirror * 2.0f + offset;
				Basis basis = Basis::looking_at(point - centre, Vector3(1, 0, 0).cross(point - centre).normalized());
				RID light = f.area_light(Vector2(a, b), energy, 100.0f, 2.0f);
				d.lights.clear();
				add_light(d, light, RS::LIGHT_AREA, Transform3D(basis, centre));
				RID rt = f.renderer.render_target_create(W, H);
				f.renderer.render_scene(d, rt);
				std::vector<float> img = f.renderer.render_target_get_data(rt);
				f.renderer.render_target_free(rt);
				double got = pixel(img, W, W / 2, H / 2)[0];

				// Midpoint quadrature of  L_e * integral f cos(theta_i) dw,  dw = cos(theta_l) dA / dist^2.
				Vector3 ax = basis.xform(Vector3(1, 0, 0)), ay = basis.xform(Vector3(0, 1, 0)), ln = basis.xform(Vector3(0, 0, -1));
				const int S = 300;
				double sum = 0.0;
				double da = (a / S) * (b / S);
				for (int i = 0; i < S; i++) {
					for (int j = 0; j < S; j++) {
						Vector3 q = centre + ax * (a * ((i + 0.5f) / S - 0.5f)) + ay * (b * ((j + 0.5f) / S - 0.5f));
						Vector3 to = q - point;
						double dist2 = to.length_squared();
						Vector3 l = to.normalized();
						double cos_i = n.dot(l);
						double cos_l = -ln.dot(l);
						if (cos_i <= 0.0 || cos_l <= 0.0) {
							continue;
						}
						sum += engine_ggx(n, v, l, roughness) * cos_i * cos_l * da / dist2;
					}
				}
				double le = energy * Math::PI / (a * b);
				// The light's specular multiplier (LIGHT_PARAM_SPECULAR, Godot's default 0.5) scales the lobe as for omni/spot.
				double expected = le * sum * f.light_storage.light_get_param(light, RS::LIGHT_PARAM_SPECULAR);
				MESSAGE("LTC specular, roughness ", roughness, ", offset ", offset.x, ": GPU ", got, ", quadrature ", expected, ", ratio ", got / expected);
				CHECK(expected > 0.05);
				// The LTC fit itself is approximate (ltc_lut_data.inc: mean L1 lobe distance ~0.05 below 60 degrees).
				CHECK(std::fabs(got / expected - 1.0) < 0.10);
			}
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] a long thin light with nearly antipodal corners renders smoothly and finite (thesis 5.4.4)") {
	// Corners 50 m away on either side of a shading point 0.3 m below the light project to nearly
	// antipodal points, where an acos-based edge integral is ill-conditioned (thesis section 5.4.4).
	// Regression guard for the edge integral (atan2 angle + midpoint split): no NaN, and neighbouring
	// pixels along the light agree. (The atan2 formulation alone already passes this configuration.)
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RS::MaterialParams mp;
		mp.albedo = Color(0.5f, 0.5f, 0.5f, 1);
		mp.metallic = 0.5f;
		mp.roughness = 0.15f;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID plane = f.plane(200.0f);
		RenderSceneData d = make_scene(camera_looking_down(3.0f), 60.0f, W, H, 20.0f);
		add_geometry(d, plane, mat);
		RID light = f.area_light(Vector2(100.0f, 0.05f), 1.0f, 1000.0f, 2.0f);
		add_light(d, light, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, 0.3f, 0)));
		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.render_scene(d, rt);
		std::vector<float> img = f.renderer.render_target_get_data(rt);
		f.renderer.render_target_free(rt);
		int nan = 0;
		for (float v : img) {
			nan += std::isfinite(v) ? 0 : 1;
		}
		CHECK(nan == 0);
		// Rows whose ground points lie under the light (|z| small): the light is effectively infinite
		// along x there, so neighbouring pixels along the row must agree closely.
		float worst = 0.0f;
		int rows = 0;
		for (int y = 0; y < H; y++) {
			if (std::fabs(pixel_on_ground(d, W / 2, y).z) > 0.1f) {
				continue;
			}
			rows++;
			for (int x = 1; x < W - 1; x++) {
				float c = pixel(img, W, x, y)[0];
				float avg = 0.5f * (pixel(img, W, x - 1, y)[0] + pixel(img, W, x + 1, y)[0]);
				REQUIRE(avg > 0.0f);
				worst = std::max(worst, std::fabs(c - avg) / avg);
			}
		}
		MESSAGE("long thin light: worst neighbour deviation along the light ", worst * 100.0f, " %");
		CHECK(rows > 0);
		CHECK(worst < 0.02f);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] nothing behind the light is lit and a zero-size light renders exactly black") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RS::MaterialParams mp; // Default Burley + GGX.
		mp.roughness = 0.5f;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID plane = f.plane(50.0f);
		RenderSceneData d = make_scene(camera_looking_down(5.0f), 60.0f, W, H, 20.0f);
		add_geometry(d, plane, mat);

		// Vertical light at x = 0 facing +X (local -Z -> world +X).
		RID light = f.area_light(Vector2(1.5f, 1.0f), 3.0f, 4.0f, 1.0f);
		Transform3D xform(Basis::from_axis_angle(Vector3(0, 1, 0), -float(Math::PI) * 0.5f), Vector3(0, 0.6f, 0));
		add_light(d, light, RS::LIGHT_AREA, xform);
		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.render_scene(d, rt);
		std::vector<float> img = f.renderer.render_target_get_data(rt);
		int behind = 0, behind_lit = 0, front_lit = 0;
		for (int y = 0; y < H; y++) {
			for (int x = 0; x < W; x++) {
				Vector3 p = pixel_on_ground(d, x, y);
				const float *c = pixel(img, W, x, y);
				bool lit = c[0] != 0.0f || c[1] != 0.0f || c[2] != 0.0f;
				if (p.x < -0.01f) {
					behind++;
					behind_lit += lit ? 1 : 0;
				} else if (p.x > 0.05f && lit) {
					front_lit++;
				}
			}
		}
		CHECK(behind > W * H / 4);
		CHECK_MESSAGE(behind_lit == 0, "the half-space behind a one-sided area light must receive exactly 0");
		CHECK(front_lit > W * H / 8);

		// Zero size (both and one side): exactly black, no NaN.
		const Vector2 sizes[3] = { Vector2(0, 0), Vector2(0, 1), Vector2(2, 0) };
		for (const Vector2 &size : sizes) {
			f.light_storage.light_area_set_size(light, size);
			f.renderer.render_scene(d, rt);
			img = f.renderer.render_target_get_data(rt);
			int nonzero = 0, nan = 0;
			for (float v : img) {
				nan += std::isnan(v) ? 1 : 0;
			}
			for (size_t i = 0; i < img.size(); i += 4) {
				nonzero += (img[i] != 0.0f || img[i + 1] != 0.0f || img[i + 2] != 0.0f) ? 1 : 0;
			}
			INFO("size (", size.x, ", ", size.y, ")");
			CHECK(nan == 0);
			CHECK(nonzero == 0);
		}
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] a scene without area lights never compiles the area-light shader variant") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 32, H = 32;
		RS::MaterialParams mp;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID plane = f.plane(20.0f);
		RenderSceneData d = make_scene(camera_looking_down(3.0f), 60.0f, W, H, 10.0f);
		add_geometry(d, plane, mat);
		RID omni = f.light_storage.light_create(RS::LIGHT_OMNI);
		f.lights.push_back(omni);
		add_light(d, omni, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(0, 1, 0)));

		const ShaderRD &shader = f.renderer.get_scene_shader();
		uint32_t created_before = shader.get_created_shader_count();
		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.render_scene(d, rt);
		f.renderer.render_scene(d, rt);
		CHECK(shader.get_created_shader_count() == created_before);
		CHECK(created_before == 2); // Colour and depth variants only.
		CHECK_FALSE(f.renderer.is_scene_shader_variant_compiled(RenderForwardClustered::SCENE_SHADER_COLOR_AREA));
		CHECK(f.renderer.get_last_frame_profile().size() == (rd->get_device_info().timestamps_supported ? 3u : 0u));

		// The first frame with an area light compiles it (once).
		RID area = f.area_light(Vector2(1, 1), 1.0f, 5.0f, 1.0f);
		add_light(d, area, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, 1, 0)));
		f.renderer.render_scene(d, rt);
		f.renderer.render_scene(d, rt);
		CHECK(f.renderer.is_scene_shader_variant_compiled(RenderForwardClustered::SCENE_SHADER_COLOR_AREA));
		CHECK(shader.get_created_shader_count() == created_before + 1);
		// Per-pass timestamps are unchanged by the area variant.
		std::vector<std::pair<String, double>> profile = f.renderer.get_last_frame_profile();
		if (rd->get_device_info().timestamps_supported) {
			REQUIRE(profile.size() == 3);
			CHECK(profile[2].first == "opaque");
		}
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightRender

namespace TestAreaLightRender {

// Not part of the default run (no timing assertions in the suite): run with
//   godot-area-tests --test-case="*Benchmark*" --no-skip
// It prints the opaque-pass GPU time of LTC area lights vs spot lights (same count, same scene, every
// light shading every pixel through the brute-force path so both do the same amount of light loops).
TEST_CASE("[AreaLight3D][Render][Benchmark] opaque-pass time of LTC area lights vs spot lights" * doctest::skip()) {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	REQUIRE(rd->get_device_info().timestamps_supported);
	{
		AreaFixture f;
		REQUIRE(f.init());
		const int W = 256, H = 256, LIGHTS = 16, FRAMES = 7;
		RS::MaterialParams mp;
		mp.roughness = 0.5f;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID plane = f.plane(50.0f);
		RenderSceneData base = make_scene(camera_looking_down(4.0f), 60.0f, W, H, 20.0f);
		add_geometry(base, plane, mat);
		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.set_debug_force_all_lights(true);

		auto median_opaque = [&](RS::LightType p_type) {
			RenderSceneData d = base;
			for (int i = 0; i < LIGHTS; i++) {
				RID l = p_type == RS::LIGHT_AREA ? f.area_light(Vector2(1.0f, 0.5f), 1.0f, 50.0f, 1.0f) : f.light_storage.light_create(RS::LIGHT_SPOT);
				if (p_type == RS::LIGHT_SPOT) {
					f.lights.push_back(l);
					f.light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, 50.0f);
					f.light_storage.light_set_param(l, RS::LIGHT_PARAM_SPOT_ANGLE, 80.0f);
				}
				float x = -3.0f + 6.0f * (i % 4) / 3.0f, z = -3.0f + 6.0f * (i / 4) / 3.0f;
				add_light(d, l, p_type, Transform3D(facing_down(), Vector3(x, 1.0f + 0.1f * i, z)));
			}
			std::vector<double> times;
			for (int k = 0; k < FRAMES; k++) {
				f.renderer.render_scene(d, rt);
				for (const auto &p : f.renderer.get_last_frame_profile()) {
					if (p.first == "opaque") {
						times.push_back(p.second);
					}
				}
			}
			std::sort(times.begin(), times.end());
			return times.empty() ? 0.0 : times[times.size() / 2];
		};
		double spot_ms = median_opaque(RS::LIGHT_SPOT);
		double area_ms = median_opaque(RS::LIGHT_AREA);
		MESSAGE(LIGHTS, " lights, ", W, "x", H, ", every light on every pixel: opaque pass spot ", spot_ms, " ms, LTC area ", area_ms, " ms, ratio ", area_ms / spot_ms);
		CHECK(spot_ms > 0.0);
		CHECK(area_ms > 0.0);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightRender
