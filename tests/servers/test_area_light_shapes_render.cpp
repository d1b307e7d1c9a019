/**************************************************************************/
/*  test_area_light_shapes_render.cpp                                     */
/**************************************************************************/
/* godot-area: disk, sphere and tube area lights in the Forward+ renderer */
/* (lavapipe, validation on) and in the Embree reference renderer: the    */
/* closed forms over a Lambert plane (a sphere fully above the horizon,   */
/* E = pi L (r/d)^2 cos theta; a disk parallel to the plane, on its axis  */
/* E = pi L r^2 / (r^2 + h^2), off it the configuration factor of a       */
/* differential area to a parallel coaxial disk) for every method and the */
/* reference; every shape x method against the reference (rel-RMSE, mean  */
/* ratio, LDR-FLIP; bounds measured, doc/methods.md "Shapes"); emission   */
/* sides (disk one-sided, sphere and tube all around); the GPU layout     */
/* packing; and the shape code compiled only for views with such lights. */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "modules/metrics/image_metrics.h"
#include "modules/reference/reference_renderer.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace TestAreaLightShapesRender {

using RenderTest::add_geometry;
using RenderTest::add_light;
using RenderTest::camera_looking_down;
using RenderTest::facing_down;
using RenderTest::pixel_on_ground;

struct ShapesFixture : RenderTest::RenderFixture {
	ReferenceRenderer reference{ &light_storage, &mesh_storage, &material_storage };

	bool init() {
		ReferenceRenderOptions options;
		options.threads = 2;
		options.target_relative_error = 0.001f;
		options.max_samples = 65536;
		reference.set_options(options);
		return RenderTest::RenderFixture::init(32);
	}
	RID shape_light(RS::LightAreaShape p_shape, const Vector2 &p_size, float p_energy, RS::LightAreaShadingMethod p_method, int p_samples = 8) {
		RID l = area_light(p_size, p_energy, 1000.0f, 2.0f);
		light_storage.light_area_set_shape(l, p_shape);
		light_storage.light_area_set_shading_method(l, p_method);
		light_storage.light_area_set_stochastic_samples(l, p_samples);
		return l;
	}
	std::vector<float> render_gpu(const RenderSceneData &p_data) { return RenderTest::render_frame(renderer, p_data); }
	std::vector<float> render_reference(const RenderSceneData &p_data) { return RenderTest::render_frame(reference, p_data); }
	RID lambert() {
		RS::MaterialParams mp;
		mp.albedo = Color(0.8f, 0.7f, 0.6f, 1.0f);
		mp.specular = 0.0f; // f0 = f90 = 0: diffuse only.
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		mp.cull_back = false;
		return material(mp);
	}
};

static const RS::LightAreaShadingMethod METHODS[4] = { RS::LIGHT_AREA_SHADING_LTC, RS::LIGHT_AREA_SHADING_LTC_POLYNOMIAL, RS::LIGHT_AREA_SHADING_MRP, RS::LIGHT_AREA_SHADING_STOCHASTIC };
static const char *METHOD_NAMES[4] = { "LTC", "LTC_POLYNOMIAL", "MRP", "STOCHASTIC" };
static const char *SHAPE_NAMES[4] = { "rectangle", "disk", "sphere", "tube" };

// Configuration factor from a differential area to a parallel disk of radius p_r at height p_h whose
// axis passes p_a from the area (Howell's catalogue, B-13): 1/2 (1 - (h^2 + a^2 - r^2) / sqrt((h^2 +
// a^2 + r^2)^2 - 4 a^2 r^2)); on the axis r^2 / (r^2 + h^2).
static double disk_configuration_factor(double p_r, double p_h, double p_a) {
	const double z = p_h * p_h + p_a * p_a + p_r * p_r;
	return 0.5 * (1.0 - (p_h * p_h + p_a * p_a - p_r * p_r) / std::sqrt(z * z - 4.0 * p_a * p_a * p_r * p_r));
}

// Sum of the red channel over the 5 x 5 block centred on (p_cx, p_cy), and of the closed form p_expected
// evaluated at the ground point of each pixel.
template <typename F>
static void block_sums(const std::vector<float> &p_img, const RenderSceneData &p_d, int p_cx, int p_cy, const F &p_expected, double &r_got, double &r_expected) {
	r_got = 0.0;
	r_expected = 0.0;
	for (int y = p_cy - 2; y <= p_cy + 2; y++) {
		for (int x = p_cx - 2; x <= p_cx + 2; x++) {
			r_got += p_img[(size_t(y) * p_d.viewport_width + x) * 4];
			r_expected += p_expected(pixel_on_ground(p_d, x, y));
		}
	}
}

TEST_CASE("[AreaLight3D][Render] diffuse sphere and disk lights over a Lambert plane match the closed forms (every method and the reference)") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShapesFixture f;
		REQUIRE(f.init());
		const int S = 33; // Odd: the centre pixel looks straight down at the world origin.
		RID mat = f.lambert();
		RID plane = f.plane(50.0f);
		const Color albedo = Color(0.8f, 0.7f, 0.6f).srgb_to_linear();
		const float energy = 3.0f;

		for (int shape = 0; shape < 2; shape++) {
			const bool sphere = shape == 0;
			// Sphere: radius 0.25 m, centre 1.5 m up. Disk: radius 0.5 m, 1 m up, parallel to the plane.
			const double r = sphere ? 0.25 : 0.5;
			const double h = sphere ? 1.5 : 1.0;
			const double area = sphere ? 4.0 * Math::PI * r * r : Math::PI * r * r;
			const double le = energy * Math::PI / area; // L_e, energy normalised by the emitting area.
			auto expected = [&](const Vector3 &p_ground) -> double {
				const double dx = p_ground.x, dz = p_ground.z;
				double ff;
				if (sphere) {
					const double d2 = dx * dx + dz * dz + h * h;
					ff = r * r / d2 * (h / std::sqrt(d2)); // (r/d)^2 cos theta: wholly above the horizon here.
				} else {
					ff = disk_configuration_factor(r, h, std::sqrt(dx * dx + dz * dz));
				}
				return albedo.r * le * ff; // albedo / pi * E with E = pi L_e FF.
			};
			for (int m = 0; m <= 4; m++) {
				const bool ref = m == 4;
				const std::string what = std::string(SHAPE_NAMES[sphere ? 2 : 1]) + " " + (ref ? "reference" : METHOD_NAMES[m]);
				CAPTURE(what);
				RID light = f.shape_light(sphere ? RS::LIGHT_AREA_SHAPE_SPHERE : RS::LIGHT_AREA_SHAPE_DISK, sphere ? Vector2(float(2 * r), 0) : Vector2(float(2 * r), float(2 * r)), energy, METHODS[ref ? 0 : m], 256);
				RenderSceneData d = RenderTest::make_scene(camera_looking_down(4.0f), 40.0f, S, S, 20.0f);
				add_geometry(d, plane, mat);
				add_light(d, light, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, float(h), 0)));
				const std::vector<float> img = ref ? f.render_reference(d) : f.render_gpu(d);
				REQUIRE(img.size() == size_t(S * S * 4));
				// On the axis (the centre block) and 0.9 m off it (10 pixels to the side).
				const int centres[2][2] = { { S / 2, S / 2 }, { S / 2 + 10, S / 2 } };
				for (const auto &c : centres) {
					double got, want;
					block_sums(img, d, c[0], c[1], expected, got, want);
					INFO("block at pixel (", c[0], ", ", c[1], "): expected ", want / 25.0, ", got ", got / 25.0, " (ratio ", got / want, ")");
					MESSAGE(what, " block (", c[0], ", ", c[1], "): got / closed form = ", got / want);
					CHECK(std::fabs(got - want) <= 0.01 * want);
				}
				// The centre pixel alone (no averaging: the on-axis closed forms exactly).
				const double centre = img[(size_t(S / 2) * S + S / 2) * 4];
				const double on_axis = albedo.r * le * (sphere ? r * r / (h * h) : r * r / (r * r + h * h));
				INFO("centre pixel: expected ", on_axis, ", got ", centre);
				CHECK(std::fabs(centre - on_axis) <= (m == 3 ? 0.03 : 0.01) * on_axis); // MC: one pixel's noise.
			}
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] a disk lights only its front; a sphere and a tube light every side") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShapesFixture f;
		REQUIRE(f.init());
		const int S = 17;
		RID mat = f.lambert();
		RID plane = f.plane(20.0f);
		// The light faces up (+Y), away from the plane below it.
		const Transform3D facing_up(Basis::from_axis_angle(Vector3(1, 0, 0), float(Math::PI) * 0.5f), Vector3(0, 1, 0));
		for (int shape = 1; shape <= 3; shape++) {
			for (int m = 0; m < 4; m++) {
				const std::string what = std::string(SHAPE_NAMES[shape]) + " " + METHOD_NAMES[m];
				CAPTURE(what);
				RID light = f.shape_light(RS::LightAreaShape(shape), Vector2(0.6f, 0.3f), 2.0f, METHODS[m]);
				RenderSceneData d = RenderTest::make_scene(camera_looking_down(3.0f), 60.0f, S, S, 20.0f);
				add_geometry(d, plane, mat);
				add_light(d, light, RS::LIGHT_AREA, facing_up);
				const std::vector<float> img = f.render_gpu(d);
				REQUIRE(img.size() == size_t(S * S * 4));
				double sum = 0.0;
				int non_finite = 0;
				for (size_t i = 0; i < img.size(); i += 4) {
					non_finite += std::isfinite(img[i]) && std::isfinite(img[i + 1]) && std::isfinite(img[i + 2]) ? 0 : 1;
					sum += img[i] + img[i + 1] + img[i + 2];
				}
				CHECK(non_finite == 0);
				if (shape == RS::LIGHT_AREA_SHAPE_DISK) {
					CHECK(sum == 0.0); // Exactly nothing behind a one-sided light.
				} else {
					CHECK(sum > 1.0);
				}
			}
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

struct ErrorStats {
	double relative_rmse = 0.0;
	double mean_ratio = 1.0;
	double flip = 0.0;
	int non_finite = 0;
};

static ErrorStats compare(const std::vector<float> &p_image, const std::vector<float> &p_reference, int p_size) {
	ErrorStats e;
	double se = 0.0, sum_i = 0.0, sum_r = 0.0;
	size_t count = 0;
	Image img(p_size, p_size), ref(p_size, p_size);
	for (int y = 0; y < p_size; y++) {
		for (int x = 0; x < p_size; x++) {
			const size_t o = (size_t(y) * p_size + x) * 4;
			for (int c = 0; c < 3; c++) {
				const float v = p_image[o + c];
				if (!std::isfinite(v)) {
					e.non_finite++;
					continue;
				}
				const double diff = double(v) - p_reference[o + c];
				se += diff * diff;
				sum_i += v;
				sum_r += p_reference[o + c];
				count++;
			}
			img.set_pixel(x, y, Color(p_image[o], p_image[o + 1], p_image[o + 2], 1.0f));
			ref.set_pixel(x, y, Color(p_reference[o], p_reference[o + 1], p_reference[o + 2], 1.0f));
		}
	}
	const double mean_r = count ? sum_r / count : 0.0;
	e.relative_rmse = mean_r > 0.0 ? std::sqrt(se / count) / mean_r : 0.0;
	e.mean_ratio = sum_r > 0.0 ? sum_i / sum_r : 1.0;
	ImageMetrics::Result metrics;
	ImageMetrics::Options options;
	options.hdr_flip = false;
	if (e.non_finite == 0 && ImageMetrics::compare(img, ref, &metrics, nullptr, options)) {
		e.flip = metrics.flip;
	}
	return e;
}

// Measured on lavapipe (doc/methods.md, "Shapes", has the command and the table; deterministic: the MC
// seeds are fixed): each bound is the measured value times about 1.5. The rectangle in the same scene
// measured LTC 0.013 / 0.029, MRP 0.41 / 0.127, MC 0.078 / 0.010 (rel-RMSE / FLIP).
struct ShapeMethodBound {
	float rel_rmse;
	float flip;
};
static const ShapeMethodBound BOUNDS[3][4] = {
	// LTC, LTC polynomial, MRP, MC (64 samples)
	{ { 0.020f, 0.045f }, { 0.022f, 0.045f }, { 1.30f, 0.15f }, { 0.19f, 0.030f } }, // Disk (measured 0.0135 / 0.028, 0.0149 / 0.029, 0.88 / 0.100, 0.125 / 0.020).
	{ { 0.021f, 0.040f }, { 0.022f, 0.040f }, { 1.15f, 0.12f }, { 0.13f, 0.014f } }, // Sphere (0.0137 / 0.025, 0.0148 / 0.026, 0.77 / 0.081, 0.087 / 0.009).
	{ { 0.036f, 0.043f }, { 0.037f, 0.044f }, { 0.41f, 0.13f }, { 0.25f, 0.045f } }, // Tube (0.024 / 0.028, 0.025 / 0.029, 0.27 / 0.086, 0.18 / 0.031; MC was 0.27 / 0.043 sampling the whole capsule).
};

// The glossy scene of the shape x method and convergence tests: a plane of roughness 0.4, metallic 0.5
// seen obliquely, the light p_height above it (turned 0.3 rad about the vertical).
static RenderSceneData glossy_scene(ShapesFixture &f, RID p_light, float p_height, int p_size) {
	RS::MaterialParams mp;
	mp.albedo = Color(0.8f, 0.75f, 0.7f, 1.0f);
	mp.roughness = 0.4f;
	mp.metallic = 0.5f;
	mp.cull_back = false;
	RenderSceneData d = RenderTest::make_scene(Transform3D(Basis::looking_at(Vector3(0, -2.5f, -1.5f)), Vector3(0, 2.5f, 1.5f)), 60.0f, p_size, p_size, 30.0f);
	add_geometry(d, f.plane(30.0f), f.material(mp));
	add_light(d, p_light, RS::LIGHT_AREA, Transform3D(facing_down() * Basis::from_axis_angle(Vector3(0, 1, 0), 0.3f), Vector3(0.1f, p_height, -0.1f)));
	return d;
}

TEST_CASE("[AreaLight3D][Render] each shape x method against the Embree reference, glossy and rough") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShapesFixture f;
		REQUIRE(f.init());
		const int S = 32;
		const Vector2 sizes[4] = { Vector2(0.8f, 0.5f), Vector2(0.8f, 0.5f), Vector2(0.5f, 0), Vector2(1.0f, 0.15f) };
		// The rectangle first: the baseline each shape's errors are read against (not bounded here).
		for (int shape = 0; shape <= 3; shape++) {
			RID light = f.shape_light(RS::LightAreaShape(shape), sizes[shape], 3.0f, RS::LIGHT_AREA_SHADING_LTC, 64);
			RenderSceneData d = glossy_scene(f, light, 0.8f, S);
			const std::vector<float> reference = f.render_reference(d);
			for (int m = 0; m < 4; m++) {
				const std::string what = std::string(SHAPE_NAMES[shape]) + " " + METHOD_NAMES[m];
				CAPTURE(what);
				f.light_storage.light_area_set_shading_method(light, METHODS[m]);
				const ErrorStats e = compare(f.render_gpu(d), reference, S);
				MESSAGE(what, ": rel-RMSE ", e.relative_rmse, ", mean ratio ", e.mean_ratio, ", FLIP ", e.flip);
				CHECK(e.non_finite == 0);
				if (shape == RS::LIGHT_AREA_SHAPE_RECTANGLE) {
					continue;
				}
				CHECK(e.relative_rmse <= BOUNDS[shape - 1][m].rel_rmse);
				CHECK(e.flip <= BOUNDS[shape - 1][m].flip);
				CHECK(e.mean_ratio == doctest::Approx(1.0).epsilon(0.15));
			}
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] the tube's stochastic method samples its visible side and converges with slope -1/2") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShapesFixture f;
		REQUIRE(f.init());
		const int S = 24;
		// A tube (1 m x 0.15 m) and a tube of length 0 (a sphere of diameter 0.3 m: both end caps are the
		// same sphere, each point must count once).
		const Vector2 sizes[2] = { Vector2(1.0f, 0.15f), Vector2(0.0f, 0.3f) };
		for (int c = 0; c < 2; c++) {
			CAPTURE(c);
			RID light = f.shape_light(RS::LIGHT_AREA_SHAPE_TUBE, sizes[c], 3.0f, RS::LIGHT_AREA_SHADING_STOCHASTIC, 4);
			RenderSceneData d = glossy_scene(f, light, 0.6f, S);
			const std::vector<float> reference = f.render_reference(d);
			const int counts[4] = { 4, 16, 64, 256 };
			double log_n[4], log_e[4];
			ErrorStats last;
			for (int k = 0; k < 4; k++) {
				f.light_storage.light_area_set_stochastic_samples(light, counts[k]);
				last = compare(f.render_gpu(d), reference, S);
				MESSAGE(std::string(c == 0 ? "tube" : "tube of length 0"), " MC N = ", counts[k], ": rel-RMSE ", last.relative_rmse, ", mean ratio ", last.mean_ratio, ", FLIP ", last.flip);
				CHECK(last.non_finite == 0);
				log_n[k] = std::log(double(counts[k]));
				log_e[k] = std::log(std::max(last.relative_rmse, 1e-12));
			}
			double mx = 0.0, my = 0.0;
			for (int k = 0; k < 4; k++) {
				mx += log_n[k] / 4.0;
				my += log_e[k] / 4.0;
			}
			double sxy = 0.0, sxx = 0.0;
			for (int k = 0; k < 4; k++) {
				sxy += (log_n[k] - mx) * (log_e[k] - my);
				sxx += (log_n[k] - mx) * (log_n[k] - mx);
			}
			const double slope = sxy / sxx;
			MESSAGE("log-log slope of rel-RMSE vs N: ", slope);
			CHECK(slope < -0.4);
			CHECK(slope > -0.6);
			CHECK(last.mean_ratio == doctest::Approx(1.0).epsilon(0.02)); // Unbiased: a double count would give 2.
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] the GPU light packs the shape into shading_method bits 24-31 and per-shape axes") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	ShapesFixture f;
	REQUIRE(f.init());
	using LS = RendererRD::LightStorage;
	CHECK(LS::pack_area_shading_method(RS::LIGHT_AREA_SHADING_MRP, 32, RS::LIGHT_AREA_SHAPE_TUBE) == (2u | (32u << 8) | (3u << 24)));
	CHECK(LS::unpack_area_shape(LS::pack_area_shading_method(RS::LIGHT_AREA_SHADING_STOCHASTIC, 256, RS::LIGHT_AREA_SHAPE_SPHERE)) == RS::LIGHT_AREA_SHAPE_SPHERE);
	const Transform3D identity;
	for (int shape = 0; shape < 4; shape++) {
		const std::string what = SHAPE_NAMES[shape];
		CAPTURE(what);
		RID l = f.shape_light(RS::LightAreaShape(shape), Vector2(2.0f, 0.5f), 1.0f, RS::LIGHT_AREA_SHADING_STOCHASTIC, 16);
		LS::AreaLightData data;
		REQUIRE(f.light_storage.fill_area_light_data(l, identity, identity, data));
		CHECK((data.shading_method & 0xFFu) == uint32_t(RS::LIGHT_AREA_SHADING_STOCHASTIC));
		CHECK(((data.shading_method >> 8) & 0xFFFFu) == 16u);
		CHECK((data.shading_method >> 24) == uint32_t(shape));
		CHECK(data.half_axis_x[0] == doctest::Approx(1.0)); // size.x / 2 for every shape (sphere: the radius).
		CHECK(data.half_axis_y[1] == doctest::Approx(shape == RS::LIGHT_AREA_SHAPE_SPHERE ? 1.0 : 0.25));
		// L_e = energy * pi / emitting area (white light).
		const double area = RendererLightStorage::compute_area_light_emitting_area(Vector2(2.0f, 0.5f), RS::LightAreaShape(shape));
		CHECK(data.color[0] == doctest::Approx(Math::PI / area).epsilon(1e-5));
	}
}

// True when the SPIR-V binary holds the debug name p_name (OpName strings are kept).
static bool spirv_has_name(const std::vector<uint32_t> &p_spirv, const char *p_name) {
	const char *bytes = reinterpret_cast<const char *>(p_spirv.data());
	const size_t size = p_spirv.size() * 4, len = std::strlen(p_name);
	for (size_t i = 0; i + len <= size; i++) {
		if (std::memcmp(bytes + i, p_name, len) == 0) {
			return true;
		}
	}
	return false;
}

TEST_CASE("[AreaLight3D][Render] a view of rectangles compiles no shape code; a disk, sphere or tube compiles it once") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShapesFixture f;
		REQUIRE(f.init());
		const int S = 16;
		RenderSceneData d = RenderTest::make_scene(camera_looking_down(3.0f), 60.0f, S, S, 20.0f);
		add_geometry(d, f.plane(10.0f), f.lambert());
		RID rect = f.shape_light(RS::LIGHT_AREA_SHAPE_RECTANGLE, Vector2(1, 1), 1.0f, RS::LIGHT_AREA_SHADING_LTC);
		add_light(d, rect, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, 1, 0)));
		f.render_gpu(d);
		CHECK(f.renderer.is_area_method_compiled(RS::LIGHT_AREA_SHADING_LTC));
		CHECK_FALSE(f.renderer.is_area_shape_code_compiled());
		CHECK(f.light_storage.get_area_shape_mask() == 1u);
		CHECK(RenderForwardClustered::get_area_method_defines(1u).find("USE_AREA_SHAPES") == String::npos);

		// What glslang compiles: the rectangle-only version has none of the shape functions.
		const ShaderRD &shader = f.renderer.get_scene_shader();
		for (int m = 0; m < 4; m++) {
			const std::string what = METHOD_NAMES[m];
			CAPTURE(what);
			const uint32_t key = 1u << uint32_t(METHODS[m]);
			String error;
			const std::vector<uint32_t> plain = rd->shader_compile_spirv_from_source(RD::SHADER_STAGE_FRAGMENT, shader.get_stage_source(RD::SHADER_STAGE_FRAGMENT, RenderForwardClustered::SCENE_SHADER_COLOR_AREA, RenderForwardClustered::get_area_method_defines(key)), "rect_only", &error);
			INFO(error.c_str());
			REQUIRE(!plain.empty());
			const std::vector<uint32_t> shapes = rd->shader_compile_spirv_from_source(RD::SHADER_STAGE_FRAGMENT, shader.get_stage_source(RD::SHADER_STAGE_FRAGMENT, RenderForwardClustered::SCENE_SHADER_COLOR_AREA, RenderForwardClustered::get_area_method_defines(key | RenderForwardClustered::AREA_VERSION_SHAPES)), "shapes", &error);
			REQUIRE(!shapes.empty());
			CHECK_FALSE(spirv_has_name(plain, "light_process_area_shape"));
			CHECK(spirv_has_name(shapes, "light_process_area_shape"));
			CHECK(shapes.size() > plain.size());
		}

		// A sphere joins: the shape version is compiled, once.
		RID sphere = f.shape_light(RS::LIGHT_AREA_SHAPE_SPHERE, Vector2(0.3f, 0), 1.0f, RS::LIGHT_AREA_SHADING_LTC);
		add_light(d, sphere, RS::LIGHT_AREA, Transform3D(Basis(), Vector3(1, 0.5f, 0)));
		const uint32_t created = shader.get_created_shader_count();
		f.render_gpu(d);
		f.render_gpu(d);
		CHECK(f.renderer.is_area_shape_code_compiled());
		CHECK(shader.get_created_shader_count() == created + 1);
		CHECK(f.light_storage.get_area_shape_mask() == ((1u << RS::LIGHT_AREA_SHAPE_RECTANGLE) | (1u << RS::LIGHT_AREA_SHAPE_SPHERE)));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightShapesRender

namespace TestAreaLightShapesRender {

/* Benchmark (not in the default run; no timing assertions; doc/methods.md "Shapes"):
 *   godot-area-tests --test-case="*Shapes][Benchmark*" --no-skip
 * 16 lights of one shape and method cover every pixel of a 128 x 128 floor (every light shaded on every
 * pixel); the configurations are interleaved frame by frame in one process, the median of 7 rounds. */
TEST_CASE("[AreaLight3D][Shapes][Benchmark] opaque-pass time per shape x method" * doctest::skip()) {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	REQUIRE(rd->get_device_info().timestamps_supported);
	{
		ShapesFixture f;
		REQUIRE(f.init());
		const int W = 128, LIGHTS = 16, ROUNDS = 7;
		RS::MaterialParams mp;
		mp.roughness = 0.5f;
		RID mat = f.material(mp);
		RenderSceneData base = RenderTest::make_scene(camera_looking_down(4.0f), 60.0f, W, W, 20.0f);
		add_geometry(base, f.plane(50.0f), mat);
		RID rt = f.renderer.render_target_create(W, W);
		f.renderer.set_debug_force_all_lights(true);
		const Vector2 sizes[4] = { Vector2(1.0f, 0.5f), Vector2(1.0f, 0.5f), Vector2(0.5f, 0), Vector2(1.0f, 0.15f) };
		std::vector<RenderSceneData> scenes;
		std::vector<std::string> names;
		for (int shape = 0; shape < 4; shape++) {
			for (int m = 0; m < 4; m++) {
				RenderSceneData d = base;
				for (int i = 0; i < LIGHTS; i++) {
					RID l = f.shape_light(RS::LightAreaShape(shape), sizes[shape], 1.0f, METHODS[m], 8);
					f.light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, 50.0f);
					const float x = -3.0f + 6.0f * (i % 4) / 3.0f, z = -3.0f + 6.0f * (i / 4) / 3.0f;
					add_light(d, l, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(x, 1.0f + 0.1f * i, z)));
				}
				scenes.push_back(d);
				names.push_back(std::string(SHAPE_NAMES[shape]) + " " + METHOD_NAMES[m] + (m == 3 ? " 8" : ""));
				f.renderer.render_scene(d, rt); // Compile and warm up.
			}
		}
		std::vector<std::vector<double>> times(scenes.size());
		for (int k = 0; k < ROUNDS; k++) {
			for (size_t c = 0; c < scenes.size(); c++) {
				f.renderer.render_scene(scenes[c], rt);
				for (const auto &p : f.renderer.get_last_frame_profile()) {
					if (p.first == "opaque") {
						times[c].push_back(p.second);
					}
				}
			}
		}
		for (size_t c = 0; c < scenes.size(); c++) {
			std::sort(times[c].begin(), times[c].end());
			const double ms = times[c].empty() ? 0.0 : times[c][times[c].size() / 2];
			MESSAGE(names[c], ": opaque pass ", ms, " ms (", LIGHTS, " lights on every pixel of ", W, "x", W, ")");
			CHECK(ms > 0.0);
		}
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightShapesRender
