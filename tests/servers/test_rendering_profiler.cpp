/**************************************************************************/
/*  test_rendering_profiler.cpp                                           */
/**************************************************************************/
/* godot-area: tests for RenderingProfiler statistics and CSV output.     */

#include "servers/rendering/rendering_profiler.h"

#include "core/error/error_macros.h"
#include "core/string/ustring.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace TestRenderingProfiler {

TEST_CASE("[RenderingProfiler] statistics on known data") {
	// 1..20 shuffled: median 10.5, mean 10.5, p95 at rank 0.95*19 = 18.05 -> 19.05.
	std::vector<double> samples = { 7, 3, 20, 1, 15, 11, 2, 19, 8, 4, 13, 17, 5, 9, 12, 6, 16, 10, 18, 14 };
	const RenderingProfiler::Stats stats = RenderingProfiler::compute_stats(samples);
	CHECK(stats.count == 20);
	CHECK(stats.median == doctest::Approx(10.5));
	CHECK(stats.mean == doctest::Approx(10.5));
	CHECK(stats.min == doctest::Approx(1.0));
	CHECK(stats.max == doctest::Approx(20.0));
	CHECK(stats.p95 == doctest::Approx(19.05));

	SUBCASE("odd count median is the middle sample") {
		const RenderingProfiler::Stats odd = RenderingProfiler::compute_stats({ 5.0, 1.0, 3.0 });
		CHECK(odd.median == doctest::Approx(3.0));
		CHECK(odd.p95 == doctest::Approx(4.8)); // rank 1.9 between 3 and 5.
	}
	SUBCASE("empty and non-finite input") {
		CHECK(RenderingProfiler::compute_stats({}).count == 0);
		const RenderingProfiler::Stats with_nan = RenderingProfiler::compute_stats({ 2.0, std::nan(""), 4.0 });
		CHECK(with_nan.count == 2);
		CHECK(with_nan.mean == doctest::Approx(3.0));
	}
}

TEST_CASE("[RenderingProfiler] warm-up frames are discarded") {
	RenderingProfiler profiler;
	CHECK(profiler.get_warmup_frames() == 20);
	// 20 warm-up frames that are very slow, then 10 measured frames with known times.
	for (int i = 0; i < 20; i++) {
		profiler.record_frame(1000.0, { { "opaque", 500.0 }, { "shadow", 400.0 } });
	}
	for (int i = 0; i < 10; i++) {
		profiler.record_frame(10.0 + i, { { "opaque", 1.0 + i }, { "shadow", 2.0 } });
	}
	CHECK(profiler.get_recorded_frame_count() == 30);
	CHECK(profiler.get_measured_frame_count() == 10);

	const RenderingProfiler::Stats cpu = profiler.get_cpu_stats();
	CHECK(cpu.count == 10);
	CHECK(cpu.max == doctest::Approx(19.0));
	CHECK(cpu.median == doctest::Approx(14.5));

	const RenderingProfiler::Stats opaque = profiler.get_pass_stats("opaque");
	CHECK(opaque.count == 10);
	CHECK(opaque.min == doctest::Approx(1.0));
	CHECK(opaque.max == doctest::Approx(10.0));
	CHECK(opaque.mean == doctest::Approx(5.5));

	const RenderingProfiler::Stats total = profiler.get_gpu_total_stats();
	CHECK(total.mean == doctest::Approx(7.5));
	CHECK(profiler.get_pass_stats("missing").count == 0);

	SUBCASE("zero warm-up keeps every frame") {
		profiler.set_warmup_frames(0);
		CHECK(profiler.get_measured_frame_count() == 30);
		CHECK(profiler.get_cpu_stats().max == doctest::Approx(1000.0));
	}
	SUBCASE("repeated pass in one frame is summed") {
		profiler.clear();
		profiler.set_warmup_frames(0);
		profiler.begin_frame();
		profiler.add_pass_time("shadow", 1.5);
		profiler.add_pass_time("shadow", 2.5);
		profiler.end_frame();
		CHECK(profiler.get_pass_stats("shadow").max == doctest::Approx(4.0));
		CHECK(profiler.get_cpu_stats().count == 0);
	}
}

TEST_CASE("[RenderingProfiler] CSV has header and one row per measured frame") {
	RenderingProfiler profiler;
	profiler.set_warmup_frames(2);
	for (int i = 0; i < 7; i++) {
		if (i == 4) {
			profiler.record_frame(5.0, { { "depth", 0.5 } }); // "opaque, lit" absent this frame.
		} else {
			profiler.record_frame(5.0, { { "depth", 0.5 }, { "opaque, lit", 2.0 } });
		}
	}
	const std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_profiler";
	std::filesystem::create_directories(dir);
	const std::filesystem::path path = dir / "bench.csv";
	String error;
	REQUIRE(profiler.write_csv(path.string(), &error));
	CHECK(error.empty());

	std::ifstream file(path);
	std::vector<String> lines;
	String line;
	while (std::getline(file, line)) {
		lines.push_back(line);
	}
	file.close();
	REQUIRE(lines.size() == 6); // Header + 5 measured frames.
	CHECK(lines[0] == "frame,cpu_ms,depth,\"opaque, lit\",gpu_total_ms");
	CHECK(string_begins_with(lines[1], "2,5.000000,0.500000,2.000000,2.500000"));
	CHECK(lines[3] == "4,5.000000,0.500000,,0.500000");
	CHECK(string_begins_with(lines[5], "6,"));

	const String table = profiler.summary_table();
	CHECK(table.find("depth") != String::npos);
	CHECK(table.find("GPU total") != String::npos);
	CHECK(table.find("5 measured") != String::npos);

	std::filesystem::remove_all(dir);

	SUBCASE("unwritable path fails with a message naming the file") {
		set_error_print_silenced(true);
		String write_error;
		const String bad_path = (dir / "no_such_dir" / "x.csv").string();
		CHECK_FALSE(profiler.write_csv(bad_path, &write_error));
		set_error_print_silenced(false);
		CHECK(write_error.find(bad_path) != String::npos);
	}
}

} // namespace TestRenderingProfiler
