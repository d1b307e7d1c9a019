/**************************************************************************/
/*  test_accuracy_shapes.cpp                                              */
/**************************************************************************/
/* The disk / sphere / tube scenes of the accuracy suite (issue 21): the  */
/* generator (ids, counts, exposure), and the CI subset of 6 scenes for   */
/* LTC, MRP and MC against the Embree reference, bounded per shape and    */
/* method (measured values: doc/methods.md "Shapes").                     */

#include "modules/accuracy/accuracy_scenes.h"
#include "modules/accuracy/accuracy_suite.h"

#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <set>

namespace TestAccuracyShapes {

TEST_CASE("[Accuracy] the shape suite: ids, counts and exposure of the disk, sphere and tube scenes") {
	const std::vector<AccuracyScenes::Scene> all = AccuracyScenes::shape_suite();
	CHECK(all.size() == 3u * 3u * 2u * 5u);
	std::set<std::string> ids;
	int per_shape[RS::LIGHT_AREA_SHAPE_MAX] = {};
	for (const AccuracyScenes::Scene &s : all) {
		ids.insert(s.id.c_str());
		per_shape[s.shape]++;
		CHECK(s.shape != RS::LIGHT_AREA_SHAPE_RECTANGLE);
		CHECK(std::isfinite(s.light_energy));
		CHECK(s.light_energy > 0.0f);
		CHECK(s.light_energy < 1e4f);
	}
	CHECK(ids.size() == all.size());
	CHECK(per_shape[RS::LIGHT_AREA_SHAPE_DISK] == 30);
	CHECK(per_shape[RS::LIGHT_AREA_SHAPE_SPHERE] == 30);
	CHECK(per_shape[RS::LIGHT_AREA_SHAPE_TUBE] == 30);
	const std::vector<AccuracyScenes::Scene> ci = AccuracyScenes::shape_ci_subset();
	REQUIRE(ci.size() == 6u);
	CHECK(ci[2].id == "plane_r1_m0_0.5x0.5_facing_sphere");
	// The rectangle's ids are unchanged by the shape parameter.
	CHECK(AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_FACING).id == "plane_r0.5_m1_1x1_facing");
}

// Measured at 32 x 32 on lavapipe (bin/godot-area bench --accuracy --shapes --ci --resolution 32
// --methods 0,2,3; MC at the default 8 samples; deterministic), worst of the two scenes per shape
// (relative RMSE / mean LDR-FLIP):
//   disk    LTC 0.053 / 0.024   MRP 0.58 / 0.109   MC 0.25 / 0.026
//   sphere  LTC 0.044 / 0.053   MRP 0.52 / 0.25    MC 0.155 / 0.019
//   tube    LTC 0.049 / 0.052   MRP 0.41 / 0.225   MC 0.54 / 0.092
// (the rectangle's MRP on plane_r0.5_m1_1x1 scenes: 0.42-0.46, the same order). Bounds about 1.5x.
// Index: [shape - 1][LTC, MRP, MC].
struct ShapeBound {
	double rel_rmse;
	double flip;
};
static const ShapeBound SHAPE_BOUNDS[3][3] = {
	{ { 0.08, 0.04 }, { 0.87, 0.17 }, { 0.38, 0.04 } }, // Disk.
	{ { 0.066, 0.08 }, { 0.78, 0.38 }, { 0.24, 0.03 } }, // Sphere.
	{ { 0.075, 0.08 }, { 0.62, 0.34 }, { 0.81, 0.14 } }, // Tube.
};

TEST_CASE("[Accuracy] the shape CI subset stays within per-shape bounds (LTC, MRP, MC vs the Embree reference)") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	AccuracySuite::Options options;
	options.shapes = true;
	options.ci_subset = true;
	options.resolution = 32;
	options.methods = { RS::LIGHT_AREA_SHADING_LTC, RS::LIGHT_AREA_SHADING_MRP, RS::LIGHT_AREA_SHADING_STOCHASTIC };
	std::vector<AccuracySuite::Row> rows;
	String error;
	REQUIRE_MESSAGE(AccuracySuite::run(options, &rows, &error), error);
	REQUIRE(rows.size() == 18u);
	const std::vector<AccuracyScenes::Scene> ci = AccuracyScenes::shape_ci_subset();
	for (const AccuracySuite::Row &r : rows) {
		int shape = 0;
		for (const AccuracyScenes::Scene &s : ci) {
			if (s.id == r.scene_id) {
				shape = int(s.shape);
			}
		}
		REQUIRE(shape >= 1);
		const int m = r.method == RS::LIGHT_AREA_SHADING_LTC ? 0 : (r.method == RS::LIGHT_AREA_SHADING_MRP ? 1 : 2);
		MESSAGE(r.scene_id, " ", r.method_name, ": relRMSE ", r.relative_rmse, " ratio ", r.brightness_ratio, " FLIP ", r.flip);
		INFO(r.scene_id, " ", r.method_name);
		REQUIRE(std::isfinite(r.relative_rmse));
		CHECK(r.relative_rmse < SHAPE_BOUNDS[shape - 1][m].rel_rmse);
		CHECK(r.flip < SHAPE_BOUNDS[shape - 1][m].flip);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAccuracyShapes
