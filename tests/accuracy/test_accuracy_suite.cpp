/**************************************************************************/
/*  test_accuracy_suite.cpp                                               */
/**************************************************************************/
/* godot-area: the CI subset of the area-light accuracy suite (thesis     */
/* 5.5): generated plane/sphere scenes rendered by the engine (lavapipe)  */
/* and the Embree reference, compared with ImageMetrics, with asserted    */
/* per-class bounds; the suite is deterministic; the scene generator's    */
/* exposure quadrature, the CSV and the summary table.                    */

#include "modules/accuracy/accuracy_command.h"
#include "modules/accuracy/accuracy_scenes.h"
#include "modules/accuracy/accuracy_suite.h"

#include "core/math/math_funcs.h"
#include "servers/rendering/rendering_server_default.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace TestAccuracySuite {

// Configuration factor from a differential area to a parallel rectangle a x b at height h, the area
// on the normal through one corner (Howell's catalogue), times pi: the integral of cos cos / r^2 dA.
static double corner_integral(double p_a, double p_b, double p_h) {
	const double x = p_a / p_h, y = p_b / p_h;
	const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
	return 0.5 * (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy));
}

TEST_CASE("[Accuracy] the scene generator covers the suite and exposes every scene") {
	std::vector<AccuracyScenes::Scene> full = AccuracyScenes::full_suite();
	// Standard camera: 2 receivers x 6 roughness x 2 metallic x 4 sizes x 7 placements; view axis: the plane
	// x 6 x 2 x 2 sizes x 3 placements x 3 elevations.
	CHECK(full.size() == 2u * 6u * 2u * 4u * 7u + 6u * 2u * 2u * 3u * 3u);
	std::set<String> ids;
	int per_placement[AccuracyScenes::PLACEMENT_MAX] = {};
	int low_views = 0;
	for (const AccuracyScenes::Scene &s : full) {
		ids.insert(s.id);
		if (s.view_elevation == 0.0f) {
			per_placement[s.placement]++;
		} else {
			low_views++;
			CHECK(s.view_elevation <= 20.0f);
			// The camera looks at p from the +Z side at that elevation.
			const Transform3D cam = AccuracyScenes::camera_transform(s);
			const float elevation = std::asin(cam.origin.y / cam.origin.length()) * 180.0f / float(Math::PI);
			CHECK(elevation == doctest::Approx(s.view_elevation).epsilon(1e-4));
			CHECK(s.id.find("_v") != String::npos);
		}
		INFO(s.id);
		CHECK(std::isfinite(s.light_energy));
		CHECK(s.light_energy > 0.0f);
		CHECK(s.light_energy < 1e4f); // Not clamped: the target point receives light in every placement.
		const Vector3 target = s.receiver == AccuracyScenes::RECEIVER_SPHERE ? Vector3(0, 1, 0) : Vector3();
		CHECK(s.light_range > (s.light_transform.origin - target).length());
	}
	CHECK(ids.size() == full.size());
	CHECK(low_views == 6 * 2 * 2 * 3 * 3);
	for (int p = 0; p < AccuracyScenes::PLACEMENT_MAX; p++) {
		CHECK(per_placement[p] == 2 * 6 * 2 * 4);
	}
	std::vector<AccuracyScenes::Scene> ci = AccuracyScenes::ci_subset();
	CHECK(ci.size() <= 30u);
	CHECK(ci.size() >= 16u);

	// Vertical (TV / window): upright 1 m behind p, emitting towards the camera (+Z), lower edge 5 cm up.
	AccuracyScenes::Scene tv = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_VERTICAL, 10.0f);
	CHECK(tv.id == "plane_r0.5_m1_1x1_vertical_v10");
	CHECK(tv.light_transform.origin.z == doctest::Approx(-1.0f));
	CHECK(tv.light_transform.origin.y == doctest::Approx(0.55f));
	CHECK((-tv.light_transform.basis.get_column(2)).dot(Vector3(0, 0, 1)) == doctest::Approx(1.0f));
	// A view elevation outside [1, 89] is refused with a message.
	set_error_print_silenced(true);
	AccuracyScenes::Scene bad = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_VERTICAL, 95.0f);
	set_error_print_silenced(false);
	CHECK(bad.id.empty());

	// Horizon placement: the light's centre lies in the target's tangent plane, so part of it is below.
	AccuracyScenes::Scene horizon = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 0.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_HORIZON);
	CHECK(horizon.light_transform.origin.y == doctest::Approx(0.0f));
	CHECK(horizon.light_transform.origin.x == doctest::Approx(-1.2f));
	// Close / far: distance 0.1 and 10 times the light size.
	AccuracyScenes::Scene close = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 0.0f, Vector2(4, 4), AccuracyScenes::PLACEMENT_CLOSE);
	CHECK(close.light_transform.origin.y == doctest::Approx(0.4f));
	AccuracyScenes::Scene far = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_SPHERE, 0.5f, 0.0f, Vector2(2, 0.5f), AccuracyScenes::PLACEMENT_FAR);
	CHECK(far.light_transform.origin.y == doctest::Approx(21.0f));
}

TEST_CASE("[Accuracy] the exposure quadrature matches the closed-form configuration factor") {
	// Rectangle 2 x 1 facing down 1.5 m above the origin, corner straight above the origin.
	const float a = 2.0f, b = 1.0f, h = 1.5f;
	Transform3D light(Basis::from_columns(Vector3(1, 0, 0), Vector3(0, 0, -1), Vector3(0, 1, 0)), Vector3(a * 0.5f, h, -b * 0.5f));
	double q = AccuracyScenes::irradiance_integral(light, Vector2(a, b), Vector3(), Vector3(0, 1, 0), 128);
	CHECK(q == doctest::Approx(corner_integral(a, b, h)).epsilon(0.002));
	// Behind the light (above it) nothing arrives.
	CHECK(AccuracyScenes::irradiance_integral(light, Vector2(a, b), Vector3(0, 3, 0), Vector3(0, -1, 0)) == 0.0);
}

TEST_CASE("[Accuracy] write_csv and summary_table report every row") {
	std::vector<AccuracySuite::Row> rows(3);
	const float roughness[3] = { 0.25f, 0.25f, 1.0f };
	const double flip[3] = { 0.02, 0.06, 0.01 };
	for (int i = 0; i < 3; i++) {
		rows[i].scene_id = "scene" + itos(i);
		rows[i].receiver = "plane";
		rows[i].placement = "facing";
		rows[i].roughness = roughness[i];
		rows[i].method_name = "LTC";
		rows[i].flip = flip[i];
		rows[i].rmse = 0.01 * (i + 1);
		rows[i].relative_rmse = 0.1 * (i + 1);
		rows[i].brightness_ratio = 1.0 + 0.1 * i;
		rows[i].ssim = 0.9;
	}
	rows[2].placement = "horizon"; // A plane crossing: its own class.
	String table = AccuracySuite::summary_table(rows);
	CHECK(table.find("| LTC | 0.25 | 2 | 0.0400 | 0.0600 |") != String::npos);
	CHECK(table.find("| 0.1500 | 0.2000 |") != String::npos); // relRMSE mean and worst of roughness 0.25.
	CHECK(table.find("scene1") != String::npos);
	CHECK(table.find("| LTC | 1 | 1 |") != String::npos);
	CHECK(table.find("| LTC | facing | 2 | 0.1500 | 0.2000 | 1.000..1.100 |") != String::npos);
	CHECK(table.find("| LTC | crossing | 1 | 0.3000 | 0.3000 | 1.200..1.200 |") != String::npos);
	CHECK(table.find("| LTC | facing, roughness >= 0.1 | 2 |") != String::npos);
	// A black reference (NaN relative errors) is skipped from the relative columns and counted.
	rows[0].relative_rmse = std::nan("");
	rows[0].brightness_ratio = std::nan("");
	table = AccuracySuite::summary_table(rows);
	CHECK(table.find("1 black references skipped") != String::npos);
	CHECK(table.find("nan") == String::npos);
	// Classes: crossing (plane horizon), grazing view (elevation <= 25), facing, oblique.
	AccuracySuite::Row c;
	c.receiver = "plane";
	c.placement = "vertical";
	c.view_elevation = 10.0f;
	CHECK(AccuracySuite::scene_class(c) == AccuracySuite::CLASS_GRAZING_VIEW);
	c.view_elevation = 0.0f;
	CHECK(AccuracySuite::scene_class(c) == AccuracySuite::CLASS_OBLIQUE);
	c.placement = "far";
	CHECK(AccuracySuite::scene_class(c) == AccuracySuite::CLASS_FACING);
	c.placement = "horizon";
	CHECK(AccuracySuite::scene_class(c) == AccuracySuite::CLASS_CROSSING);
	c.receiver = "sphere";
	CHECK(AccuracySuite::scene_class(c) == AccuracySuite::CLASS_OBLIQUE);

	const String path = "/tmp/godot_area_test_accuracy_" + std::to_string(getpid()) + ".csv";
	String error;
	REQUIRE(AccuracySuite::write_csv(path, rows, &error));
	std::ifstream in(path);
	std::string line;
	int lines = 0;
	std::getline(in, line);
	CHECK(line.rfind("scene_id,receiver,roughness,metallic,light_width,light_height,placement,method,", 0) == 0);
	CHECK(line.find(",relative_rmse,brightness_ratio,view_elevation") != std::string::npos);
	while (std::getline(in, line)) {
		lines++;
	}
	CHECK(lines == 3);
	std::remove(path.c_str());
	CHECK_FALSE(AccuracySuite::write_csv("/nonexistent_dir/x.csv", rows, &error));
	CHECK(error.find("/nonexistent_dir/x.csv") != String::npos);
}

TEST_CASE("[Accuracy] bad options are rejected with a message") {
	std::vector<AccuracySuite::Row> rows;
	String error;
	AccuracySuite::Options options;
	options.resolution = 0;
	CHECK_FALSE(AccuracySuite::run(options, &rows, &error));
	CHECK(error.find("resolution") != String::npos);
	options.resolution = 8;
	options.filter = "no_such_scene";
	CHECK_FALSE(AccuracySuite::run(options, &rows, &error));
	CHECK(error.find("no_such_scene") != String::npos);
	CHECK(AccuracySuite::method_name(0) == "LTC");
	CHECK(AccuracySuite::method_name(3) == "STOCHASTIC");
	CHECK(AccuracySuite::method_name(99) == "method_99");

	// The suite makes its own servers: an existing RenderingServer is refused, not replaced.
	RenderingServerDefault *rs = RenderingServerDefault::create_dummy();
	options.filter = String();
	CHECK_FALSE(AccuracySuite::run(options, &rows, &error));
	CHECK(error.find("RenderingServer already exists") != String::npos);
	delete rs;

	// Command line: bad arguments exit 2 before anything renders.
	CHECK(accuracy_command({ "--accuracy", "--resolution", "zero" }) == 2);
	CHECK(accuracy_command({ "--accuracy", "--resolution", "5000" }) == 2);
	CHECK(accuracy_command({ "--accuracy", "--methods", "0,x" }) == 2);
	CHECK(accuracy_command({ "--accuracy", "--csv" }) == 2);
	CHECK(accuracy_command({ "--accuracy", "--bogus" }) == 2);
}

// Scene classes of the CI bounds (see doc/accuracy.md, "CI bounds").
enum SceneClass {
	CLASS_DIFFUSE, // roughness 1, metallic 0: exact Lambert polygon integral + a 4 % GGX lobe.
	CLASS_DIFFUSE_HORIZON, // the same, light straddling the horizon and cutting the plane.
	CLASS_EASY, // glossy, facing / close / far: the LTC fit error only.
	CLASS_HARD, // glossy, grazing / horizon / tilted.
	CLASS_MAX,
};

static SceneClass classify(const AccuracySuite::Row &p_row) {
	if (p_row.roughness == 1.0f && p_row.metallic == 0.0f) {
		return p_row.placement == "horizon" ? CLASS_DIFFUSE_HORIZON : CLASS_DIFFUSE;
	}
	if (p_row.placement == "facing" || p_row.placement == "close" || p_row.placement == "far") {
		return CLASS_EASY;
	}
	return CLASS_HARD;
}

struct Bounds {
	double flip; // Mean LDR-FLIP must be below.
	double rmse; // RMSE (linear radiance) must be below.
	double ssim_min; // SSIM must be above.
};

// Measured worst values of each class at 40 x 40 (LTC on lavapipe vs the reference, 2026-11-26):
//   DIFFUSE          FLIP 0.0045, RMSE 0.0054, SSIM 0.99983
//   DIFFUSE_HORIZON  FLIP 0.0066, RMSE 0.21 (a few pixels next to the line where the light cuts the
//                    plane, radiance >> 1: small relative differences there dominate RMSE), SSIM 0.99985
//   EASY             FLIP 0.061 (plane_r0.5_m1_4x4_close), RMSE 0.081 (plane_r0.05_m1_1x1_facing: the
//                    roughness-0.05 highlight, radiance >> 1), SSIM 0.887
//   HARD             FLIP 0.065 (plane_r0.75_m1_4x4_grazing), RMSE 0.047, SSIM 0.827 (plane_r0.5_m1_1x1_grazing)
// The bounds keep about 2x margin on FLIP / RMSE (the LTC fit may be refitted; lavapipe versions
// differ in the last bits), and SSIM a margin of about twice the measured 1 - SSIM. The diffuse
// bounds are an order of magnitude tighter than the glossy ones: the Lambert term is exact, the
// remaining error is the 4 % (f0 = 0.04) GGX lobe at roughness 1 plus pixel-footprint effects.
static const Bounds CLASS_BOUNDS[CLASS_MAX] = {
	{ 0.01, 0.012, 0.999 }, // CLASS_DIFFUSE
	{ 0.015, 0.4, 0.999 }, // CLASS_DIFFUSE_HORIZON
	{ 0.12, 0.16, 0.78 }, // CLASS_EASY
	{ 0.13, 0.1, 0.65 }, // CLASS_HARD
};

TEST_CASE("[Accuracy] the CI subset stays within the per-class error bounds (LTC vs the Embree reference)") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	AccuracySuite::Options options;
	options.ci_subset = true;
	options.resolution = 40;
	std::vector<AccuracySuite::Row> rows;
	String error;
	REQUIRE_MESSAGE(AccuracySuite::run(options, &rows, &error), error);
	CHECK(rows.size() == AccuracyScenes::ci_subset().size());
	int per_class[CLASS_MAX] = {};
	for (const AccuracySuite::Row &r : rows) {
		per_class[classify(r)]++;
		const Bounds &b = CLASS_BOUNDS[classify(r)];
		MESSAGE(r.scene_id, " class ", int(classify(r)), ": FLIP ", r.flip, " RMSE ", r.rmse, " relMSE ", r.relative_mse, " SSIM ", r.ssim, " Pearson ", r.pearson, " ref ", r.reference_ms, " ms");
		INFO(r.scene_id);
		CHECK(std::isfinite(r.flip));
		CHECK(r.flip < b.flip);
		CHECK(r.rmse < b.rmse);
		CHECK(r.ssim > b.ssim_min);
		CHECK(r.pearson > 0.85); // Worst measured: 0.93 (the roughness-0.05 highlight).
	}
	for (int c = 0; c < CLASS_MAX; c++) {
		INFO("class ", c);
		CHECK(per_class[c] >= 2);
	}

	// Radiance errors per AccuracySuite class (issue #18): relative RMSE (worst and mean over the class)
	// and the range of the brightness ratio engine / reference.
	struct RadianceBounds {
		double worst, mean, ratio_min, ratio_max;
	};
	// Measured at 40 x 40 (LTC, surface-horizon clipping, the polygon Fresnel and the full-table
	// free-axis refit, 2026-12-07; doc/accuracy.md section 5.1; with the grazing-block refit and eq.
	// 5.10's Fresnel, 2026-12-02, in parentheses):
	//   facing        worst 0.035 (0.050) sphere_r0.5_m1_4x4_far, mean 0.010 (0.014), ratio 0.961..1.001
	//   oblique       worst 0.029 (0.038) sphere_r0.5_m1_1x1_horizon, mean 0.010 (0.014), ratio 0.961..1.000
	//   grazing view  worst 0.086 (0.121) plane_r0.5_m1_1x1_vertical_v10, mean 0.037 (0.063), ratio 0.989..1.023
	//   crossing      worst 0.076 (0.090) plane_r0.5_m1_1x1_horizon_v10, mean 0.030 (0.035), ratio 0.998..1.001
	// Bounds: about 1.25x the measured worst / mean, so a regression of a class fails here.
	static const RadianceBounds RADIANCE_BOUNDS[AccuracySuite::CLASS_MAX] = {
		{ 0.044, 0.013, 0.94, 1.03 }, // CLASS_FACING
		{ 0.036, 0.013, 0.94, 1.03 }, // CLASS_OBLIQUE
		{ 0.107, 0.047, 0.96, 1.05 }, // CLASS_GRAZING_VIEW
		{ 0.095, 0.037, 0.97, 1.03 }, // CLASS_CROSSING
	};
	double rel_sum[AccuracySuite::CLASS_MAX] = {};
	int rel_count[AccuracySuite::CLASS_MAX] = {};
	for (const AccuracySuite::Row &r : rows) {
		const AccuracySuite::SceneClass c = AccuracySuite::scene_class(r);
		const RadianceBounds &b = RADIANCE_BOUNDS[c];
		INFO(r.scene_id, " (", AccuracySuite::scene_class_name(c), "): relRMSE ", r.relative_rmse, ", brightness ratio ", r.brightness_ratio);
		REQUIRE(std::isfinite(r.relative_rmse)); // Every CI scene is lit.
		CHECK(r.relative_rmse < b.worst);
		CHECK(r.brightness_ratio > b.ratio_min);
		CHECK(r.brightness_ratio < b.ratio_max);
		rel_sum[c] += r.relative_rmse;
		rel_count[c]++;
	}
	for (int c = 0; c < AccuracySuite::CLASS_MAX; c++) {
		INFO(AccuracySuite::scene_class_name(AccuracySuite::SceneClass(c)));
		REQUIRE(rel_count[c] >= 2);
		MESSAGE(AccuracySuite::scene_class_name(AccuracySuite::SceneClass(c)), ": mean relRMSE ", rel_sum[c] / rel_count[c], " over ", rel_count[c], " scenes");
		CHECK(rel_sum[c] / rel_count[c] < RADIANCE_BOUNDS[c].mean);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Accuracy][LTC2] the two-lobe LTC on the CI subset's low views (LTC_2LOBE vs the Embree reference)") {
	// The CI scenes seen 10-20 degrees above the floor (ids ending in _v10 / _v20: a TV over a glossy
	// floor, a floor lit from above, a light crossing the floor's plane), shaded with LTC_2LOBE.
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	AccuracySuite::Options options;
	options.ci_subset = true;
	options.resolution = 40;
	options.methods = { int(RS::LIGHT_AREA_SHADING_LTC_2LOBE) };
	options.filter = "_v"; // Also matches "_vertical": the standard-camera TV scenes are dropped below.
	std::vector<AccuracySuite::Row> all_rows, rows;
	String error;
	REQUIRE_MESSAGE(AccuracySuite::run(options, &all_rows, &error), error);
	for (const AccuracySuite::Row &r : all_rows) {
		if (r.view_elevation > 0.0f) {
			rows.push_back(r);
		}
	}
	REQUIRE(rows.size() == 5);
	// Measured at 40 x 40 (2026-12-08, doc/accuracy.md section 5.2; LTC in parentheses): relRMSE
	// plane_r0.25_m1_1x1_vertical_v10 0.020 (0.032), plane_r0.5_m1_1x1_vertical_v10 0.052 (0.086),
	// plane_r0.5_m0_2x0.5_vertical_v20 0.015 (0.014), plane_r0.25_m1_1x1_facing_v10 0.019 (0.017),
	// plane_r0.5_m1_1x1_horizon_v10 0.033 (0.076); grazing-view mean 0.026 (0.037); brightness ratio
	// 0.985..0.998. Bounds about 1.25x, so a regression of the two-lobe table or shader fails here.
	const double TWO_LOBE_WORST = 0.065, TWO_LOBE_GRAZING_MEAN = 0.033, TWO_LOBE_RATIO_MIN = 0.96, TWO_LOBE_RATIO_MAX = 1.03;
	double grazing_sum = 0.0;
	int grazing = 0;
	for (const AccuracySuite::Row &r : rows) {
		const AccuracySuite::SceneClass c = AccuracySuite::scene_class(r);
		MESSAGE(r.scene_id, " (", String(AccuracySuite::scene_class_name(c)), "): relRMSE ", r.relative_rmse, ", brightness ratio ", r.brightness_ratio);
		INFO(r.scene_id);
		REQUIRE(std::isfinite(r.relative_rmse));
		CHECK(r.method == int(RS::LIGHT_AREA_SHADING_LTC_2LOBE));
		CHECK(r.relative_rmse < TWO_LOBE_WORST);
		CHECK(r.brightness_ratio > TWO_LOBE_RATIO_MIN);
		CHECK(r.brightness_ratio < TWO_LOBE_RATIO_MAX);
		if (c == AccuracySuite::CLASS_GRAZING_VIEW) {
			grazing_sum += r.relative_rmse;
			grazing++;
		}
	}
	REQUIRE(grazing == 4);
	CHECK(grazing_sum / grazing < TWO_LOBE_GRAZING_MEAN);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Accuracy] the suite is deterministic: the same scenes give the same numbers twice") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	AccuracySuite::Options options;
	options.ci_subset = true;
	options.resolution = 24;
	options.filter = "_r0.25_m1_"; // Glossy metal scenes: the integrator's adaptive paths matter.
	std::vector<AccuracySuite::Row> first, second;
	String error;
	REQUIRE_MESSAGE(AccuracySuite::run(options, &first, &error), error);
	REQUIRE_MESSAGE(AccuracySuite::run(options, &second, &error), error);
	REQUIRE(first.size() == second.size());
	CHECK(first.size() >= 2u);
	for (size_t i = 0; i < first.size(); i++) {
		INFO(first[i].scene_id);
		CHECK(first[i].scene_id == second[i].scene_id);
		CHECK(first[i].rmse == second[i].rmse);
		CHECK(first[i].relative_mse == second[i].relative_mse);
		CHECK(first[i].mae == second[i].mae);
		CHECK(first[i].ssim == second[i].ssim);
		CHECK(first[i].flip == second[i].flip);
		CHECK(first[i].reference_samples_per_pixel == second[i].reference_samples_per_pixel);
		CHECK(first[i].flip > 0.0); // LTC is an approximation: a real difference is measured.
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

// Not part of the default run: the full suite (doc/results/accuracy_*.csv) without the CLI, e.g.
//   GODOT_AREA_ACCURACY_CSV=doc/results/accuracy_ltc_96.csv GODOT_AREA_ACCURACY_THUMBNAILS=doc/results/accuracy
//   godot-area-tests --test-case="*full suite*" --no-skip
// Other variables: GODOT_AREA_ACCURACY_RESOLUTION (96), GODOT_AREA_ACCURACY_FILTER, GODOT_AREA_ACCURACY_CI (1 = subset),
// GODOT_AREA_ACCURACY_METHODS (e.g. "0,1,2,3").
TEST_CASE("[Accuracy][Full] the full suite writes its CSV, thumbnails and summary table" * doctest::skip()) {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	auto env = [](const char *p_name) {
		const char *v = getenv(p_name);
		return v ? String(v) : String();
	};
	AccuracySuite::Options options;
	options.progress = true;
	options.csv_path = env("GODOT_AREA_ACCURACY_CSV");
	options.thumbnails_dir = env("GODOT_AREA_ACCURACY_THUMBNAILS");
	options.filter = env("GODOT_AREA_ACCURACY_FILTER");
	options.ci_subset = env("GODOT_AREA_ACCURACY_CI") == "1";
	if (!env("GODOT_AREA_ACCURACY_RESOLUTION").empty()) {
		options.resolution = atoi(env("GODOT_AREA_ACCURACY_RESOLUTION").c_str());
	}
	for (const String &m : string_split(env("GODOT_AREA_ACCURACY_METHODS"), ',', false)) {
		options.methods.push_back(atoi(m.c_str()));
	}
	std::vector<AccuracySuite::Row> rows;
	String error;
	REQUIRE_MESSAGE(AccuracySuite::run(options, &rows, &error), error);
	CHECK(!rows.empty());
	double reference_ms = 0.0;
	int n = 0;
	for (const AccuracySuite::Row &r : rows) {
		if (r.method == rows.front().method) {
			reference_ms += r.reference_ms;
			n++;
		}
	}
	printf("%s\nreference: %.1f ms per image at %dx%d (mean of %d)\n", AccuracySuite::summary_table(rows).c_str(), reference_ms / n, options.resolution, options.resolution, n);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAccuracySuite

namespace TestAccuracySuite {

// Not part of the default run (it makes and finalizes its own RenderingDevice, so it must run alone):
//   godot-area-tests --test-case="*command line*" --no-skip
TEST_CASE("[Accuracy][Full] the command line runs the CI subset on its own device and writes the CSV" * doctest::skip()) {
	const String csv = "/tmp/godot_area_accuracy_command_test_" + std::to_string(getpid()) + ".csv";
	std::remove(csv.c_str());
	CHECK(accuracy_command({ "--accuracy", "--ci", "--filter", "_far", "--resolution", "16", "--csv", csv }) == 0);
	std::ifstream in(csv);
	std::string line;
	int lines = 0;
	while (std::getline(in, line)) {
		lines++;
	}
	CHECK(lines == 1 + 4); // Header + the four "far" scenes of the subset.
	std::remove(csv.c_str());
}

} // namespace TestAccuracySuite
