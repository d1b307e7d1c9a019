/**************************************************************************/
/*  test_benchmark_dolly.cpp                                              */
/**************************************************************************/
/* godot-area: smoke test of the adaptive-shadow dolly benchmark          */
/* (`bench --sweep dolly`, modules/benchmark/dolly_sweep.h): two camera   */
/* positions at 32 x 18 on lavapipe (validation on) with every default    */
/* mode; the CSV has the documented columns, finite values, and the fixed */
/* modes shade with exactly 25 and 81 maps. Plus the GPU-free parts: mode */
/* names and the camera path. No timing assertions.                      */

#include "modules/benchmark/dolly_sweep.h"

#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace TestBenchmarkDolly {

static std::vector<std::string> split_csv_line(const std::string &p_line) {
	std::vector<std::string> cells;
	size_t start = 0;
	while (true) {
		size_t comma = p_line.find(',', start);
		cells.push_back(p_line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
		if (comma == std::string::npos) {
			break;
		}
		start = comma + 1;
	}
	return cells;
}

TEST_CASE("[Benchmark] dolly sweep: mode names and the camera path") {
	DollySweep::ModeSpec mode;
	CHECK(DollySweep::parse_mode("adaptive", mode));
	CHECK(mode.mode == RS::LIGHT_AREA_SHADOW_ADAPTIVE);
	CHECK(DollySweep::parse_mode("Fixed81", mode));
	CHECK(mode.mode == RS::LIGHT_AREA_SHADOW_FIXED);
	CHECK(mode.grid == 9);
	CHECK(mode.name == "FIXED_81");
	CHECK_FALSE(DollySweep::parse_mode("fixed26", mode));
	CHECK_FALSE(DollySweep::parse_mode("fixed", mode));
	CHECK_FALSE(DollySweep::parse_mode("random", mode));

	DollySweep::Options options;
	options.positions = 5;
	float last = 1e9f;
	for (int i = 0; i < options.positions; i++) {
		float d = (DollySweep::get_camera_position(options, i) - DollySweep::get_target()).length();
		CHECK(d < last); // Far to near.
		last = d;
	}
	CHECK((DollySweep::get_camera_position(options, 0) - DollySweep::get_target()).length() == doctest::Approx(options.far_distance).epsilon(1e-4));
	CHECK(last == doctest::Approx(options.near_distance).epsilon(1e-4));
}

TEST_CASE("[Benchmark] dolly sweep smoke run: CSV columns, finite values, fixed map counts") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	DollySweep::Options options;
	options.positions = 2;
	options.ref_width = 32;
	options.ref_height = 18;
	options.supersample = 1;
	options.atlas = 1024;
	options.frames = 1;
	options.converge_max = 3;
	options.converge_stable = 2;
	options.reference_error = 0.1f;
	std::vector<DollySweep::Row> rows;
	String error;
	REQUIRE_MESSAGE(DollySweep::run(options, rows, &error), error);
	REQUIRE(rows.size() == 8); // 4 modes x 2 positions.

	const std::string path = (std::filesystem::temp_directory_path() / "godot_area_test_dolly.csv").string();
	REQUIRE(DollySweep::write_csv(path, rows, &error));
	std::ifstream in(path);
	std::string header;
	REQUIRE(bool(std::getline(in, header)));
	const std::vector<std::string> columns = split_csv_line(header);
	const std::vector<std::string> expected = { "mode", "position", "distance", "width", "height", "atlas", "subdivision", "tile", "maps", "draws",
		"converge_frames", "shadow_maps_ms", "reprojection_ms", "banding_ms", "total_ms", "cpu_ms", "visibility_rmse", "penumbra_rmse" };
	CHECK(columns == expected);
	int lines = 0;
	std::string line;
	std::vector<std::string> modes;
	while (std::getline(in, line)) {
		std::vector<std::string> cells = split_csv_line(line);
		REQUIRE(cells.size() == expected.size());
		lines++;
		modes.push_back(cells[0]);
		for (size_t c = 1; c < cells.size(); c++) {
			double v = std::strtod(cells[c].c_str(), nullptr);
			const std::string what = expected[c] + " = " + cells[c];
			CHECK_MESSAGE(std::isfinite(v), what);
		}
		const int maps = std::stoi(cells[8]);
		const double rmse = std::strtod(cells[16].c_str(), nullptr);
		if (cells[0] == "FIXED_25") {
			CHECK(maps == 25);
		} else if (cells[0] == "FIXED_81") {
			CHECK(maps == 81);
		} else {
			CHECK(maps >= 1);
			CHECK(maps <= 81);
		}
		CHECK(rmse >= 0.0);
		CHECK(rmse <= 1.5);
		CHECK(std::strtod(cells[14].c_str(), nullptr) >= -1.0); // total_ms (-1 only without timestamps).
	}
	CHECK(lines == 8);
	CHECK(modes.front() == "ADAPTIVE");
	CHECK(modes.back() == "FIXED_81");
	std::remove(path.c_str());

	DollySweep::Targets targets = DollySweep::compute_targets(rows);
	CHECK(targets.far_count == 1);
	CHECK(targets.near_error_ratio >= 0.0);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestBenchmarkDolly
