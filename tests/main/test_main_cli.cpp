/**************************************************************************/
/*  test_main_cli.cpp                                                     */
/**************************************************************************/

#include "core/error/error_macros.h"
#include "core/io/image.h"
#include "main/main.h"
#include "modules/metrics/image_metrics.h"
#include "modules/openexr/image_loader_exr.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <initializer_list>

namespace TestMainCLI {

int run_cli(std::initializer_list<const char *> p_args) {
	std::vector<char *> argv;
	argv.push_back(const_cast<char *>("godot-area"));
	for (const char *a : p_args) {
		argv.push_back(const_cast<char *>(a));
	}
	set_error_print_silenced(true);
	int code = Main::run(int(argv.size()), argv.data());
	set_error_print_silenced(false);
	return code;
}

TEST_CASE("[CLI] bad arguments and files give exit code 2, not a crash") {
	CHECK(run_cli({}) == 2);
	CHECK(run_cli({ "paint" }) == 2);
	CHECK(run_cli({ "render", "--bogus" }) == 2);
	CHECK(run_cli({ "render", "-o" }) == 2);
	CHECK(run_cli({ "render" }) == 2); // Missing -o.
	CHECK(run_cli({ "render", "--width", "0", "-o", "x.exr" }) == 2);
	CHECK(run_cli({ "render", "--width", "12abc", "-o", "x.exr" }) == 2);
	CHECK(run_cli({ "bench", "--frames", "-3" }) == 2);
	CHECK(run_cli({ "reference", "--shadows", "maybe", "-o", "x.exr" }) == 2);
	CHECK(run_cli({ "reference", "--error", "nan", "-o", "x.exr" }) == 2);
	CHECK(run_cli({ "compare", "only_one.exr" }) == 2);
	CHECK(run_cli({ "compare", "/nonexistent/a.exr", "/nonexistent/b.exr" }) == 2);
}

// Runs bin/godot-area in a subprocess (it owns its RenderingDevice and servers for the whole run).
int run_cli_process(const String &p_args) {
	String cmd = String("'") + GODOT_AREA_CLI_PATH + "' " + p_args + " > /dev/null 2>&1";
	int status = std::system(cmd.c_str());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_CASE("[CLI][Render] render and reference of the embedded demo write finite, non-black EXRs that agree") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_cli";
	std::filesystem::create_directories(dir);
	String gpu = (dir / "demo.exr").string(), ref = (dir / "demo_ref.exr").string(), png = (dir / "demo.png").string();
	CHECK(run_cli_process("render --width 64 --height 36 -o '" + gpu + "' --png '" + png + "'") == 0);
	CHECK(run_cli_process("reference --width 64 --height 36 --shadows off -o '" + ref + "'") == 0);
	CHECK(run_cli_process("render /nonexistent/scene.tscn -o '" + gpu + ".x'") == 2);
	Image a, b;
	String error;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(gpu, a, &error), error);
	REQUIRE_MESSAGE(ImageLoaderEXR::load(ref, b, &error), error);
	CHECK(a.get_width() == 64);
	CHECK(a.get_height() == 36);
	CHECK(a.is_finite());
	CHECK(a.has_non_black(0.01f));
	CHECK(std::filesystem::exists(png));
	// Same scene, same BRDF, no shadows on either side. Omni/spot shading is exact; the demo's area
	// lights use LTC on the GPU (an approximation of the specular lobe), so bound image metrics.
	ImageMetrics::Result metrics;
	REQUIRE_MESSAGE(ImageMetrics::compare(a, b, &metrics, &error), error);
	CHECK_MESSAGE(metrics.rmse < 0.005, "RMSE(GPU, reference) = " << metrics.rmse);
	CHECK_MESSAGE(metrics.flip < 0.03, "LDR-FLIP(GPU, reference) = " << metrics.flip);
	CHECK(run_cli_process("compare '" + gpu + "' '" + ref + "'") == 0);
	std::filesystem::remove_all(dir);
}

} // namespace TestMainCLI
