/**************************************************************************/
/*  test_benchmark_methods_shapes.cpp                                     */
/**************************************************************************/
/* godot-area: the shape axis of `bench --sweep methods --shapes`         */
/* (modules/benchmark/methods_sweep.h, issue 21). A tiny run (32 x 18,    */
/* one light count, one frame, 16 x 16 error images) on lavapipe with     */
/* validation on: one timing row per shape x method, one error row per    */
/* shape x method x error scene of that shape, every error row's shape    */
/* the one of its scene, finite non-negative errors, and the CSV has the  */
/* shape columns (the default sweep's CSV does not). No timing            */
/* assertions.                                                            */

#include "modules/benchmark/methods_sweep.h"
#include "servers/rendering_server.h"

#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace TestBenchmarkMethodsShapes {

TEST_CASE("[Benchmark] methods sweep shape axis: one row per shape x method") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	MethodsSweep::Options options;
	options.shapes = true;
	options.width = 32;
	options.height = 18;
	options.light_counts = { 2 };
	options.warmup_frames = 0;
	options.frames = 1;
	options.error_resolution = 16;
	std::vector<MethodsSweep::Row> rows;
	String error;
	REQUIRE_MESSAGE(MethodsSweep::run(options, &rows, &error), error);

	const std::vector<MethodsSweep::Config> configs = MethodsSweep::shape_configs();
	const std::vector<String> scene_ids = MethodsSweep::shape_error_scene_ids();
	REQUIRE(configs.size() == 3);
	const int shapes = int(RS::LIGHT_AREA_SHAPE_MAX);
	std::map<std::string, int> timing, errors;
	std::set<std::string> error_scenes;
	for (const MethodsSweep::Row &r : rows) {
		const std::string key = r.shape + " " + r.config;
		if (r.section == "shape_timing") {
			timing[key]++;
			CHECK(r.lights == 2);
			CHECK_MESSAGE(r.gpu_ms_opaque >= 0.0, key);
			CHECK_MESSAGE(std::isfinite(r.wall_ms), key);
		} else {
			REQUIRE_MESSAGE(r.section == "shape_error", r.section);
			errors[key]++;
			error_scenes.insert(r.scene);
			// The scene ids carry the shape (AccuracyScenes::make_scene): "_disk" etc., none for rectangles.
			const bool tagged = string_ends_with(r.scene, "_disk") || string_ends_with(r.scene, "_sphere") || string_ends_with(r.scene, "_tube");
			CHECK_MESSAGE((r.shape == "rectangle" ? !tagged : string_ends_with(r.scene, "_" + r.shape)), (r.scene + " " + r.shape));
			CHECK_MESSAGE(std::isfinite(r.relative_rmse), key);
			CHECK_MESSAGE(r.relative_rmse >= 0.0, key);
			CHECK_MESSAGE(r.relative_rmse < 2.0, key);
			CHECK_MESSAGE(r.flip >= 0.0, key);
			CHECK_MESSAGE(r.flip <= 1.0, key);
			CHECK_MESSAGE(r.brightness_ratio > 0.0, key);
		}
	}
	CHECK(int(timing.size()) == shapes * int(configs.size()));
	CHECK(int(errors.size()) == shapes * int(configs.size()));
	for (int s = 0; s < shapes; s++) {
		for (const MethodsSweep::Config &c : configs) {
			const std::string key = std::string(MethodsSweep::shape_name(s)) + " " + c.name;
			CHECK_MESSAGE(timing[key] == 1, key);
			CHECK_MESSAGE(errors[key] == int(scene_ids.size()) / shapes, key);
		}
	}
	CHECK(error_scenes.size() == scene_ids.size());
	CHECK(rows.size() == size_t(shapes) * configs.size() * (1 + scene_ids.size() / shapes));

	// The CSV has the shape columns; rows without a shape (the default sweep's) do not get them.
	const std::string path = (std::filesystem::temp_directory_path() / "godot_area_test_methods_shapes.csv").string();
	REQUIRE(MethodsSweep::write_csv(path, rows, &error));
	std::ifstream in(path);
	std::string header, line;
	REQUIRE(bool(std::getline(in, header)));
	CHECK(header.size() > 32);
	CHECK(header.substr(header.size() - 32) == ",shape,rel_rmse,brightness_ratio");
	int lines = 0;
	while (std::getline(in, line)) {
		lines++;
	}
	CHECK(lines == int(rows.size()));
	in.close();
	std::vector<MethodsSweep::Row> plain(1);
	plain[0].section = "timing";
	plain[0].config = "LTC";
	REQUIRE(MethodsSweep::write_csv(path, plain, &error));
	std::ifstream in_plain(path);
	REQUIRE(bool(std::getline(in_plain, header)));
	CHECK(header.find("shape") == std::string::npos);
	in_plain.close();
	std::remove(path.c_str());
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestBenchmarkMethodsShapes
