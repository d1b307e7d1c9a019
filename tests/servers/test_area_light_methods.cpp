/**************************************************************************/
/*  test_area_light_methods.cpp                                           */
/**************************************************************************/
/* godot-area: the per-light area shading methods (LTC, LTC polynomial,   */
/* MRP, stochastic Monte Carlo): the node/server/storage enum and the     */
/* area_stochastic_samples plumbing with the .tscn round trip; MRP and MC */
/* against the Embree reference renderer (same storages, same scene);    */
/* the MC error falling as N^-1/2; exact zero behind the light and no     */
/* NaN in degenerate configurations; lights of different methods in one   */
/* scene; and the per-method shader versions being compiled only when    */
/* a visible light uses the method. Tiny images, validation layer on.     */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "modules/metrics/image_metrics.h"
#include "modules/reference/reference_renderer.h"
#include "scene/3d/light_3d.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "servers/rendering/rendering_server_globals.h"
#include "servers/rendering/storage/light_storage.h"
#include "tests/scene/scene_test_fixture.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace TestAreaLightMethods {

/* Node, server and storage */

TEST_CASE("[AreaLight3D][Methods] shading method enum, validation and area_stochastic_samples reach the server") {
	SceneTest::DummyServer server;
	CHECK((int)AreaLight3D::AREA_SHADING_LTC == 0);
	CHECK((int)AreaLight3D::AREA_SHADING_LTC_POLYNOMIAL == 1);
	CHECK((int)AreaLight3D::AREA_SHADING_MRP == 2);
	CHECK((int)AreaLight3D::AREA_SHADING_STOCHASTIC == 3);
	CHECK((int)AreaLight3D::AREA_SHADING_AUTO == 4);
	CHECK((int)AreaLight3D::AREA_SHADING_LTC_2LOBE == 5); // Appended after AUTO: saved scenes keep their values.
	CHECK((int)RS::LIGHT_AREA_SHADING_LTC_2LOBE == 5);
	CHECK((int)RS::LIGHT_AREA_SHADING_LTC_POLYNOMIAL == 1);
	CHECK((int)RS::LIGHT_AREA_SHADING_MRP == 2);
	CHECK((int)RS::LIGHT_AREA_SHADING_STOCHASTIC == 3);
	CHECK(ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_STOCHASTIC") == 3);

	AreaLight3D *light = new AreaLight3D;
	RID rid = light->get_light();
	CHECK(light->get_area_stochastic_samples() == RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT);
	CHECK(RSG::light_storage->light_area_get_stochastic_samples(rid) == RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT);
	for (int m = 0; m < RS::LIGHT_AREA_SHADING_MAX; m++) {
		light->set("area_shading_method", m);
		CHECK(light->get_area_shading_method() == AreaLight3D::AreaShadingMethod(m));
		CHECK(RSG::light_storage->light_area_get_shading_method(rid) == RS::LightAreaShadingMethod(m));
	}
	light->set("area_stochastic_samples", 32);
	CHECK(light->get_area_stochastic_samples() == 32);
	CHECK(RSG::light_storage->light_area_get_stochastic_samples(rid) == 32);
	{
		SceneTest::ErrorCatcher errors;
		light->set("area_shading_method", -1);
		light->set("area_shading_method", RS::LIGHT_AREA_SHADING_MAX + 1);
		// The last valid value set by the loop above (LTC_2LOBE, the last appended) is kept.
		CHECK(light->get_area_shading_method() == AreaLight3D::AreaShadingMethod(RS::LIGHT_AREA_SHADING_MAX - 1));
		CHECK(errors.contains("area_shading_method"));
		light->set("area_stochastic_samples", 0);
		light->set("area_stochastic_samples", 257);
		CHECK(light->get_area_stochastic_samples() == 32);
		CHECK(errors.contains("area_stochastic_samples"));
		// The storage rejects bad values on its own too (direct server callers).
		RSG::light_storage->light_area_set_shading_method(rid, RS::LightAreaShadingMethod(7));
		RSG::light_storage->light_area_set_stochastic_samples(rid, 1000);
		CHECK(RSG::light_storage->light_area_get_shading_method(rid) == RS::LightAreaShadingMethod(RS::LIGHT_AREA_SHADING_MAX - 1));
		CHECK(RSG::light_storage->light_area_get_stochastic_samples(rid) == 32);
		CHECK(errors.contains("light_area_set_stochastic_samples"));
	}

	std::vector<PropertyInfo> list;
	light->get_property_list(&list);
	const PropertyInfo *samples = nullptr;
	for (const PropertyInfo &p : list) {
		if (p.name == "area_stochastic_samples") {
			samples = &p;
		}
	}
	REQUIRE(samples != nullptr);
	CHECK(samples->type == Variant::INT);
	CHECK(samples->hint == PROPERTY_HINT_RANGE);
	CHECK(samples->hint_string == "1,256");
	delete light;
}

TEST_CASE("[AreaLight3D][Methods] a scene file with every shading method and a sample count round-trips") {
	SceneTest::DummyServer server;
	const String text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Poly" type="AreaLight3D" parent="."]
area_shading_method = 1

[node name="Mrp" type="AreaLight3D" parent="."]
area_shading_method = 2

[node name="Mc" type="AreaLight3D" parent="."]
area_shading_method = 3
area_stochastic_samples = 32

[node name="Ltc" type="AreaLight3D" parent="."]
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "methods.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	const char *names[4] = { "Poly", "Mrp", "Mc", "Ltc" };
	const AreaLight3D::AreaShadingMethod expected[4] = { AreaLight3D::AREA_SHADING_LTC_POLYNOMIAL, AreaLight3D::AREA_SHADING_MRP, AreaLight3D::AREA_SHADING_STOCHASTIC, AreaLight3D::AREA_SHADING_LTC };
	for (int i = 0; i < 4; i++) {
		AreaLight3D *l = Object::cast_to<AreaLight3D>(root->get_node_or_null(names[i]));
		REQUIRE(l != nullptr);
		CHECK(l->get_area_shading_method() == expected[i]);
		CHECK(RSG::light_storage->light_area_get_shading_method(l->get_light()) == RS::LightAreaShadingMethod(expected[i]));
		CHECK(l->get_area_stochastic_samples() == (i == 2 ? 32 : RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT));
	}
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK_MESSAGE(saved == text, (String("saved text:\n") + saved));
	delete root;
}

/* Rendering fixture: RD storages shared by the GPU renderer and the reference renderer */

struct MethodsFixture : RenderTest::RenderFixture {
	ReferenceRenderer reference{ &light_storage, &mesh_storage, &material_storage };
	std::vector<RID> targets;

	bool init() {
		ReferenceRenderOptions options;
		options.threads = 2;
		options.target_relative_error = 0.001f;
		options.max_samples = 65536;
		reference.set_options(options);
		return RenderTest::RenderFixture::init(32);
	}
	// Render targets go first; the base then frees meshes, materials, lights and the renderer.
	~MethodsFixture() {
		for (RID t : targets) {
			if (renderer.owns_render_target(t)) {
				renderer.render_target_free(t);
			} else {
				reference.render_target_free(t);
			}
		}
	}
	RID material(float p_roughness, float p_metallic) {
		RS::MaterialParams mp;
		mp.albedo = Color(0.8f, 0.75f, 0.7f, 1.0f);
		mp.roughness = p_roughness;
		mp.metallic = p_metallic;
		mp.cull_back = false;
		return RenderTest::RenderFixture::material(mp);
	}
	RID area_light(const Vector2 &p_size, float p_energy, RS::LightAreaShadingMethod p_method, int p_samples = 8) {
		RID l = RenderTest::RenderFixture::area_light(p_size, p_energy, 100.0f, 2.0f);
		light_storage.light_area_set_shading_method(l, p_method);
		light_storage.light_area_set_stochastic_samples(l, p_samples);
		return l;
	}
	std::vector<float> render_gpu(const RenderSceneData &p_data) { return RenderTest::render_frame(renderer, p_data); }
	std::vector<float> render_reference(const RenderSceneData &p_data) { return RenderTest::render_frame(reference, p_data); }
};

static RenderSceneData make_scene(const Transform3D &p_cam, float p_fovy, int p_size) {
	return RenderTest::make_scene(p_cam, p_fovy, p_size, p_size, 30.0f);
}

using RenderTest::add_geometry;
using RenderTest::facing_down;

static void add_area(RenderSceneData &r_d, RID p_light, const Transform3D &p_xform) {
	RenderTest::add_light(r_d, p_light, RS::LIGHT_AREA, p_xform);
}

// The facing test scene: a 1 x 0.6 m light 1 m above a rough ground plane, an oblique camera.
static RenderSceneData facing_scene(MethodsFixture &f, RID p_light, float p_roughness, float p_metallic, int p_size) {
	RenderSceneData d = make_scene(Transform3D(Basis::looking_at(Vector3(0, -2.5f, -1.5f)), Vector3(0, 2.5f, 1.5f)), 60.0f, p_size);
	add_geometry(d, f.plane(30.0f), f.material(p_roughness, p_metallic));
	add_area(d, p_light, Transform3D(facing_down() * Basis::from_axis_angle(Vector3(0, 1, 0), 0.3f), Vector3(0.1f, 1.0f, -0.1f)));
	return d;
}

struct ErrorStats {
	double rmse = 0.0; // sqrt(mean over pixels and RGB of (image - reference)^2).
	double relative_rmse = 0.0; // rmse / mean(reference).
	double mean_ratio = 1.0; // mean(image) / mean(reference).
	double flip = 0.0; // Mean LDR-FLIP (modules/metrics).
	int non_finite = 0;
};

static ErrorStats compare(const std::vector<float> &p_image, const std::vector<float> &p_reference, int p_size, float p_scale = 1.0f) {
	ErrorStats e;
	double se = 0.0, sum_i = 0.0, sum_r = 0.0;
	size_t count = 0;
	Image img(p_size, p_size), ref(p_size, p_size);
	for (int y = 0; y < p_size; y++) {
		for (int x = 0; x < p_size; x++) {
			size_t o = (size_t(y) * p_size + x) * 4;
			for (int c = 0; c < 3; c++) {
				float v = p_image[o + c] * p_scale;
				if (!std::isfinite(v)) {
					e.non_finite++;
					continue;
				}
				double diff = double(v) - p_reference[o + c];
				se += diff * diff;
				sum_i += v;
				sum_r += p_reference[o + c];
				count++;
			}
			img.set_pixel(x, y, Color(p_image[o] * p_scale, p_image[o + 1] * p_scale, p_image[o + 2] * p_scale, 1.0f));
			ref.set_pixel(x, y, Color(p_reference[o], p_reference[o + 1], p_reference[o + 2], 1.0f));
		}
	}
	e.rmse = count ? std::sqrt(se / count) : 0.0;
	double mean_r = count ? sum_r / count : 0.0;
	e.relative_rmse = mean_r > 0.0 ? e.rmse / mean_r : 0.0;
	e.mean_ratio = sum_r > 0.0 ? sum_i / sum_r : 1.0;
	ImageMetrics::Result metrics;
	ImageMetrics::Options options;
	options.hdr_flip = false;
	if (e.non_finite == 0 && ImageMetrics::compare(img, ref, &metrics, nullptr, options)) {
		e.flip = metrics.flip;
	}
	return e;
}

/* MRP */

TEST_CASE("[AreaLight3D][Methods] MRP stays within a bounded error of the reference for a facing light") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		MethodsFixture f;
		REQUIRE(f.init());
		const int S = 32;
		// Dielectrics (diffuse + specular), then each lobe alone: a metal (specular only, no diffuse).
		struct Config {
			float roughness;
			float metallic;
		};
		const Config configs[4] = { { 0.8f, 0.0f }, { 0.5f, 0.0f }, { 0.5f, 1.0f }, { 0.8f, 1.0f } };
		for (const Config &config : configs) {
			const float roughness = config.roughness;
			RID light = f.area_light(Vector2(1.0f, 0.6f), 2.0f, RS::LIGHT_AREA_SHADING_MRP);
			RenderSceneData d = facing_scene(f, light, roughness, config.metallic, S);
			std::vector<float> ref = f.render_reference(d);
			std::vector<float> mrp = f.render_gpu(d);
			f.light_storage.light_area_set_shading_method(light, RS::LIGHT_AREA_SHADING_LTC);
			std::vector<float> ltc = f.render_gpu(d);
			ErrorStats e = compare(mrp, ref, S);
			ErrorStats el = compare(ltc, ref, S);
			MESSAGE("roughness ", roughness, ", metallic ", config.metallic, ": MRP relative RMSE ", e.relative_rmse, ", mean ratio ", e.mean_ratio, ", FLIP ", e.flip,
					" | LTC relative RMSE ", el.relative_rmse, ", mean ratio ", el.mean_ratio, ", FLIP ", el.flip);
			CHECK(e.non_finite == 0);
			if (config.metallic == 0.0f) {
				// MRP is approximate (thesis 5.3: no configuration matched the ground truth everywhere); with
				// the diffuse lobe dominant it must still get the light's overall level and shape.
				CHECK(e.relative_rmse < 0.35);
				CHECK(std::fabs(e.mean_ratio - 1.0) < 0.25);
			} else {
				// Specular only: the eq. 5.5 cone is narrower than the GGX lobe at high roughness, so MRP
				// under-estimates rough highlights, as the thesis reports ("the specular reflections do not
				// accurately scale with increasing surface roughness"). Loose guard: lit, not exploding.
				CHECK(e.mean_ratio > 0.1);
				CHECK(e.mean_ratio < 1.5);
			}
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Methods] MRP and MC light nothing behind the light and never produce NaN for lights facing away or at grazing angles") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		MethodsFixture f;
		REQUIRE(f.init());
		const int S = 32;
		RID plane = f.plane(30.0f);
		RID mat = f.material(0.3f, 0.5f);
		RID mat_smooth = f.material(0.0f, 1.0f);
		const RS::LightAreaShadingMethod methods[2] = { RS::LIGHT_AREA_SHADING_MRP, RS::LIGHT_AREA_SHADING_STOCHASTIC };
		for (RS::LightAreaShadingMethod method : methods) {
			INFO("method ", int(method));
			// Vertical light at x = 0 facing +X: the half-space x < 0 is behind it.
			RID light = f.area_light(Vector2(1.5f, 1.0f), 3.0f, method, 4);
			f.light_storage.light_set_param(light, RS::LIGHT_PARAM_RANGE, 4.0f);
			f.light_storage.light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 1.0f);
			RenderSceneData d = make_scene(Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 5, 0)), 60.0f, S);
			add_geometry(d, plane, mat);
			add_area(d, light, Transform3D(Basis::from_axis_angle(Vector3(0, 1, 0), -float(Math::PI) * 0.5f), Vector3(0, 0.6f, 0)));
			std::vector<float> img = f.render_gpu(d);
			int behind_lit = 0, front_lit = 0, nan = 0;
			const float t = std::tan(Math::deg_to_rad(30.0f));
			for (int y = 0; y < S; y++) {
				for (int x = 0; x < S; x++) {
					float wx = ((x + 0.5f) / S * 2.0f - 1.0f) * t * 5.0f; // World x of the pixel's ground point.
					const float *c = &img[(size_t(y) * S + x) * 4];
					bool lit = c[0] != 0.0f || c[1] != 0.0f || c[2] != 0.0f;
					nan += (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])) ? 0 : 1;
					if (wx < -0.05f) {
						behind_lit += lit ? 1 : 0;
					} else if (wx > 0.1f) {
						front_lit += lit ? 1 : 0;
					}
				}
			}
			CHECK(nan == 0);
			CHECK_MESSAGE(behind_lit == 0, "behind a one-sided area light the result must be exactly 0");
			CHECK(front_lit > S * S / 8);

			// Degenerate orientations: tilted so the surface normal points away from the light normal
			// (Drobot's n . n_l > 0 case), perpendicular to the ground (grazing), facing straight up
			// (away from the ground); a grazing camera and a mirror material (roughness 0).
			const float tilts[6] = { 0.0f, 0.6f, 1.2f, 1.5707963f, 2.2f, 3.1415926f };
			RenderSceneData g = make_scene(Transform3D(Basis::looking_at(Vector3(0, -0.15f, -1)), Vector3(0, 0.2f, 3)), 70.0f, S);
			add_geometry(g, plane, mat);
			for (float tilt : tilts) {
				for (RID m : { mat, mat_smooth }) {
					g.geometry[0].material_override = m;
					g.lights.clear();
					add_area(g, light, Transform3D(facing_down() * Basis::from_axis_angle(Vector3(1, 0, 0), tilt), Vector3(0, 0.5f, 0)));
					std::vector<float> gi = f.render_gpu(g);
					int bad = 0;
					for (float v : gi) {
						bad += std::isfinite(v) ? 0 : 1;
					}
					INFO("tilt ", tilt);
					CHECK(bad == 0);
				}
			}
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

/* Stochastic Monte Carlo */

// Least-squares slope of log(y) against log(x).
static double log_slope(const std::vector<double> &p_x, const std::vector<double> &p_y) {
	double n = double(p_x.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
	for (size_t i = 0; i < p_x.size(); i++) {
		double lx = std::log(p_x[i]), ly = std::log(p_y[i]);
		sx += lx;
		sy += ly;
		sxx += lx * lx;
		sxy += lx * ly;
	}
	return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

TEST_CASE("[AreaLight3D][Methods] stochastic MC is unbiased: its error falls as N^-1/2 and it agrees with the reference at high N") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		MethodsFixture f;
		REQUIRE(f.init());
		const int S = 32;
		const float energy = 2.0f;
		RID light = f.area_light(Vector2(1.0f, 0.6f), energy, RS::LIGHT_AREA_SHADING_STOCHASTIC);
		// Diffuse plus a glossy lobe (MIS of light and GGX VNDF samples).
		RenderSceneData d = facing_scene(f, light, 0.35f, 0.5f, S);
		std::vector<float> ref = f.render_reference(d);

		const int counts[4] = { 4, 16, 64, 256 };
		const int SEEDS = 3;
		std::vector<double> ns, errors;
		ErrorStats last;
		double mean_ref = 0.0;
		for (size_t k = 0; k < ref.size(); k++) {
			mean_ref += (k % 4) < 3 ? ref[k] : 0.0f;
		}
		mean_ref /= double(ref.size() / 4 * 3);
		REQUIRE(mean_ref > 0.0);
		for (int n : counts) {
			f.light_storage.light_area_set_stochastic_samples(light, n);
			double rmse = 0.0;
			for (int s = 0; s < SEEDS; s++) {
				// The per-light random stream is keyed by the light's radiance bits: a 1e-5 change of the
				// energy gives an independent stream; the image is scaled back before comparing.
				float scale_energy = energy * (1.0f + 1e-5f * s);
				f.light_storage.light_set_param(light, RS::LIGHT_PARAM_ENERGY, scale_energy);
				std::vector<float> img = f.render_gpu(d);
				ErrorStats e = compare(img, ref, S, energy / scale_energy);
				CHECK(e.non_finite == 0);
				rmse += e.rmse * e.rmse;
				last = e;
			}
			rmse = std::sqrt(rmse / SEEDS);
			ns.push_back(n);
			errors.push_back(rmse);
			MESSAGE("MC N = ", n, ": RMSE ", rmse, " (relative ", rmse / mean_ref, "; last seed: mean ratio ", last.mean_ratio, ", FLIP ", last.flip, ")");
		}
		f.light_storage.light_set_param(light, RS::LIGHT_PARAM_ENERGY, energy);
		double slope = log_slope(ns, errors);
		MESSAGE("MC log-log slope of RMSE vs N: ", slope);
		CHECK(slope == doctest::Approx(-0.5).epsilon(0.2)); // -0.5 +- 0.1.
		// N = 256: small error, and the mean (where the noise averages out) matches the reference.
		CHECK(errors.back() / mean_ref < 0.08);
		CHECK(std::fabs(last.mean_ratio - 1.0) < 0.01);

		// A glossy metal (specular only, narrow lobe): the MIS of light and VNDF samples stays unbiased.
		RenderSceneData glossy = facing_scene(f, light, 0.15f, 1.0f, S);
		std::vector<float> glossy_ref = f.render_reference(glossy);
		f.light_storage.light_area_set_stochastic_samples(light, 256);
		ErrorStats eg = compare(f.render_gpu(glossy), glossy_ref, S);
		MESSAGE("MC N = 256, glossy metal (roughness 0.15): relative RMSE ", eg.relative_rmse, ", mean ratio ", eg.mean_ratio, ", FLIP ", eg.flip);
		CHECK(eg.non_finite == 0);
		CHECK(std::fabs(eg.mean_ratio - 1.0) < 0.02);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

/* Per-light methods */

TEST_CASE("[AreaLight3D][Methods] lights with different methods in one scene each render as they do alone") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		MethodsFixture f;
		REQUIRE(f.init());
		const int S = 32;
		RenderSceneData base = make_scene(Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 4, 0)), 60.0f, S);
		add_geometry(base, f.plane(30.0f), f.material(0.4f, 0.2f));
		const RS::LightAreaShadingMethod methods[3] = { RS::LIGHT_AREA_SHADING_LTC, RS::LIGHT_AREA_SHADING_MRP, RS::LIGHT_AREA_SHADING_STOCHASTIC };
		const float xs[3] = { -1.2f, 0.0f, 1.2f };
		std::vector<float> sum(size_t(S) * S * 4, 0.0f);
		RenderSceneData all = base;
		for (int i = 0; i < 3; i++) {
			RID light = f.area_light(Vector2(0.8f, 0.5f), 1.5f, methods[i], 8);
			f.light_storage.light_set_color(light, Color(1.0f, 0.8f + 0.05f * i, 0.6f, 1.0f));
			Transform3D xform(facing_down(), Vector3(xs[i], 0.8f, 0.2f * i));
			RenderSceneData single = base;
			add_area(single, light, xform);
			add_area(all, light, xform);
			std::vector<float> img = f.render_gpu(single);
			double total = 0.0;
			for (size_t k = 0; k < sum.size(); k++) {
				sum[k] += img[k];
				total += (k % 4) < 3 ? img[k] : 0.0f;
			}
			INFO("method ", int(methods[i]));
			CHECK(total > 1.0); // Each light lights its part of the plane.
		}
		std::vector<float> combined = f.render_gpu(all);
		CHECK(f.renderer.get_compiled_area_method_mask() == 0b1101u);
		float worst = 0.0f;
		for (size_t k = 0; k < sum.size(); k++) {
			if ((k % 4) == 3) {
				continue;
			}
			float tol = 2e-3f * std::fabs(sum[k]) + 1e-4f; // RGBA16F rounding of three images.
			worst = std::max(worst, std::fabs(combined[k] - sum[k]) / tol);
		}
		MESSAGE("LTC + MRP + MC in one scene vs the sum of single-light renders: worst error / tolerance ", worst);
		CHECK(worst <= 1.0f);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Methods] only the shading methods of visible area lights are compiled") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		MethodsFixture f;
		REQUIRE(f.init());
		const int S = 16;
		RenderSceneData d = make_scene(Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 3, 0)), 60.0f, S);
		add_geometry(d, f.plane(10.0f), f.material(0.5f, 0.0f));
		const ShaderRD &shader = f.renderer.get_scene_shader();
		const uint32_t created_base = shader.get_created_shader_count();
		CHECK(created_base == 2); // Colour and depth.

		// No area lights: no area code at all.
		f.render_gpu(d);
		CHECK(shader.get_created_shader_count() == created_base);
		CHECK(f.renderer.get_compiled_area_method_mask() == 0u);
		CHECK_FALSE(f.renderer.is_scene_shader_variant_compiled(RenderForwardClustered::SCENE_SHADER_COLOR_AREA));

		// Only LTC lights: exactly one version, without MRP or MC code.
		RID ltc = f.area_light(Vector2(1, 1), 1.0f, RS::LIGHT_AREA_SHADING_LTC);
		RID ltc2 = f.area_light(Vector2(0.5f, 1), 1.0f, RS::LIGHT_AREA_SHADING_LTC);
		add_area(d, ltc, Transform3D(facing_down(), Vector3(-0.5f, 1, 0)));
		add_area(d, ltc2, Transform3D(facing_down(), Vector3(0.5f, 1, 0)));
		f.render_gpu(d);
		f.render_gpu(d);
		CHECK(shader.get_created_shader_count() == created_base + 1);
		CHECK(f.renderer.get_area_shader_version_count() == 1);
		CHECK(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_LTC));
		CHECK_FALSE(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_MRP));
		CHECK_FALSE(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_STOCHASTIC));
		CHECK_FALSE(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_LTC_POLYNOMIAL));
		CHECK(RenderForwardClustered::get_area_method_defines(1u << RS::LIGHT_AREA_SHADING_LTC) == "#define AREA_METHOD_LTC\n");
		String ltc_source = shader.get_stage_source(RD::SHADER_STAGE_FRAGMENT, RenderForwardClustered::SCENE_SHADER_COLOR_AREA, RenderForwardClustered::get_area_method_defines(1u));
		CHECK(ltc_source.find("#define AREA_METHOD_MRP") == String::npos);
		CHECK(ltc_source.find("#define AREA_METHOD_STOCHASTIC") == String::npos);

		// One light switched to MRP: a second version (LTC + MRP), compiled once.
		f.light_storage.light_area_set_shading_method(ltc2, RS::LIGHT_AREA_SHADING_MRP);
		f.render_gpu(d);
		f.render_gpu(d);
		CHECK(shader.get_created_shader_count() == created_base + 2);
		CHECK(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_MRP));
		CHECK_FALSE(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_STOCHASTIC));

		// Back to LTC only: the first version is reused, nothing compiles.
		f.light_storage.light_area_set_shading_method(ltc2, RS::LIGHT_AREA_SHADING_LTC);
		f.render_gpu(d);
		CHECK(shader.get_created_shader_count() == created_base + 2);
		CHECK(f.renderer.get_area_shader_version_count() == 2);
		// The storage reports the methods of the last upload (what the renderer keys its versions by).
		CHECK(f.light_storage.get_area_shading_method_mask() == (1u << RS::LIGHT_AREA_SHADING_LTC));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

/* Benchmark (not in the default run; no timing assertions):
 *   godot-area-tests --test-case="*Methods*Benchmark*" --no-skip */

TEST_CASE("[AreaLight3D][Methods][Benchmark] opaque-pass time of LTC, MRP and MC area lights" * doctest::skip()) {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	REQUIRE(rd->get_device_info().timestamps_supported);
	{
		MethodsFixture f;
		REQUIRE(f.init());
		const int W = 256, LIGHTS = 16, FRAMES = 5;
		RenderSceneData base = make_scene(Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 4, 0)), 60.0f, W);
		add_geometry(base, f.plane(50.0f), f.material(0.5f, 0.0f));
		RID rt = f.renderer.render_target_create(W, W);
		f.renderer.set_debug_force_all_lights(true);
		struct Config {
			const char *name;
			RS::LightAreaShadingMethod method;
			int samples;
		};
		const Config configs[5] = { { "LTC", RS::LIGHT_AREA_SHADING_LTC, 1 }, { "MRP", RS::LIGHT_AREA_SHADING_MRP, 1 },
			{ "MC 1", RS::LIGHT_AREA_SHADING_STOCHASTIC, 1 }, { "MC 4", RS::LIGHT_AREA_SHADING_STOCHASTIC, 4 }, { "MC 16", RS::LIGHT_AREA_SHADING_STOCHASTIC, 16 } };
		for (const Config &c : configs) {
			RenderSceneData d = base;
			for (int i = 0; i < LIGHTS; i++) {
				RID l = f.area_light(Vector2(1.0f, 0.5f), 1.0f, c.method, c.samples);
				f.light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, 50.0f);
				float x = -3.0f + 6.0f * (i % 4) / 3.0f, z = -3.0f + 6.0f * (i / 4) / 3.0f;
				add_area(d, l, Transform3D(facing_down(), Vector3(x, 1.0f + 0.1f * i, z)));
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
			double ms = times.empty() ? 0.0 : times[times.size() / 2];
			MESSAGE(LIGHTS, " area lights, ", W, "x", W, ", every light on every pixel: ", String(c.name), " opaque pass ", ms, " ms");
			CHECK(ms > 0.0);
		}
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightMethods
