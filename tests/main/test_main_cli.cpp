/**************************************************************************/
/*  test_main_cli.cpp                                                     */
/**************************************************************************/

#include "core/error/error_macros.h"
#include "core/io/image.h"
#include "main/main.h"
#include "modules/metrics/image_metrics.h"
#include "modules/openexr/image_loader_exr.h"

#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <sys/wait.h>

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
	CHECK(run_cli({ "render", "--settle-frames", "0", "-o", "x.exr" }) == 2);
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

TEST_CASE("[CLI][Render] the embedded demo (hero frame) renders within LDR-FLIP 0.05 of the Embree reference") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_cli_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
	String gpu = (dir / "demo.exr").string(), ref = (dir / "demo_ref.exr").string(), png = (dir / "demo.png").string();
	// Both with the scene's area shadows (soft shadows in the default area_shadow_mode); 96x54 keeps the
	// reference to seconds (a relative standard error of 1 % per pixel).
	CHECK(run_cli_process("render --width 96 --height 54 -o '" + gpu + "' --png '" + png + "'") == 0);
	CHECK(run_cli_process("reference --width 96 --height 54 --error 0.01 -o '" + ref + "'") == 0);
	CHECK(run_cli_process("render /nonexistent/scene.tscn -o '" + gpu + ".x'") == 2);
	Image a, b;
	String error;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(gpu, a, &error), error);
	REQUIRE_MESSAGE(ImageLoaderEXR::load(ref, b, &error), error);
	CHECK(a.get_width() == 96);
	CHECK(a.get_height() == 54);
	CHECK(a.is_finite());
	CHECK(a.has_non_black(0.01f));
	CHECK(std::filesystem::exists(png));
	ImageMetrics::Result metrics;
	REQUIRE_MESSAGE(ImageMetrics::compare(a, b, &metrics, &error), error);
	MESSAGE("hero frame 96x54 vs Embree: LDR-FLIP ", metrics.flip, ", HDR-FLIP ", metrics.hdr_flip, ", RMSE ", metrics.rmse, ", relMSE ", metrics.relative_mse);
	// Issue 23 asks for LDR-FLIP < 0.05. With the default area shadows (FIXED 5 x 5, per-sample penumbra
	// filter with its near-layer step) this frame measures 0.047; without the near-layer step the window's
	// mullion, 3.5 cm in front of the WindowPanel light, darkened the floor through the grid's centre
	// column (0.058; FIXED 3 x 3 without the filter: 0.071).
	CHECK_MESSAGE(metrics.flip < 0.05, "LDR-FLIP(GPU, reference) = " << metrics.flip);
	CHECK(run_cli_process("compare '" + gpu + "' '" + ref + "'") == 0);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[CLI][Render] render draws until ADAPTIVE area shadows settle (--settle-frames)") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_cli_settle_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
	// The demo with its four (shadowed) area lights in ADAPTIVE mode.
	std::ifstream in(String(GODOT_AREA_ROOT) + "/demo/demo.tscn");
	REQUIRE(in.good());
	std::stringstream text;
	text << in.rdbuf();
	String scene = text.str();
	for (const char *name : { "TVPanel", "CeilingStripLeft", "CeilingStripRight", "WindowPanel" }) {
		const String anchor = String("[node name=\"") + name + "\" type=\"AreaLight3D\" parent=\".\"]\n";
		size_t at = scene.find(anchor);
		REQUIRE(at != String::npos);
		scene.insert(at + anchor.size(), "area_shadow_mode = 2\n");
	}
	const String scene_path = (dir / "adaptive.tscn").string();
	{
		std::ofstream out(scene_path);
		out << scene;
	}
	const String one = (dir / "one.exr").string(), settled = (dir / "settled.exr").string(), again = (dir / "again.exr").string();
	const String common = "render '" + scene_path + "' --width 160 --height 90 --setting rendering/lights_and_shadows/area_shadow_reprojection_divisor=2 ";
	CHECK(run_cli_process(common + "--settle-frames 1 -o '" + one + "'") == 0);
	CHECK(run_cli_process(common + "-o '" + settled + "'") == 0);
	CHECK(run_cli_process(common + "--settle-frames 1000 -o '" + again + "'") == 0);
	Image a, b, c;
	String error;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(one, a, &error), error);
	REQUIRE_MESSAGE(ImageLoaderEXR::load(settled, b, &error), error);
	REQUIRE_MESSAGE(ImageLoaderEXR::load(again, c, &error), error);
	CHECK(a.is_finite());
	CHECK(b.is_finite());
	// One frame shades with the root quad's four maps; the settled render with the refined tree.
	ImageMetrics::Result first_vs_settled, settled_vs_more;
	REQUIRE_MESSAGE(ImageMetrics::compare(a, b, &first_vs_settled, &error), error);
	REQUIRE_MESSAGE(ImageMetrics::compare(c, b, &settled_vs_more, &error), error);
	MESSAGE("RMSE one frame vs settled: ", first_vs_settled.rmse, "; settled (32-frame cap) vs a 1000-frame cap: ", settled_vs_more.rmse);
	CHECK(first_vs_settled.rmse > 0.0);
	CHECK(settled_vs_more.rmse == 0.0); // It had settled: more allowed frames change nothing.
	std::filesystem::remove_all(dir);
}

// Runs bin/godot-area and returns its exit status; stdout and stderr together in r_output.
int run_cli_capture(const String &p_args, String *r_output) {
	std::filesystem::path log = std::filesystem::temp_directory_path() / ("godot_area_test_cli_capture_" + std::to_string(getpid()) + ".log");
	String cmd = String("'") + GODOT_AREA_CLI_PATH + "' " + p_args + " > '" + log.string() + "' 2>&1";
	int status = std::system(cmd.c_str());
	std::ifstream f(log);
	std::stringstream ss;
	ss << f.rdbuf();
	*r_output = ss.str();
	std::filesystem::remove(log);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_CASE("[CLI] a failed write exits non-zero, names the path and never says \"wrote\"") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	if (!std::filesystem::exists("/dev/full")) {
		MESSAGE("skipped: /dev/full is not available");
		return;
	}
	String out;
	CHECK(run_cli_capture("render --width 16 --height 16 -o /dev/full", &out) == 1);
	CHECK_MESSAGE(out.find("Cannot write \"/dev/full\": write failed (No space left on device)") != String::npos, out);
	CHECK_MESSAGE(out.find("wrote /dev/full") == String::npos, out);
	CHECK(run_cli_capture("reference --width 16 --height 16 --spp 1 --shadows off -o /dev/full", &out) == 1);
	CHECK_MESSAGE(out.find("\"/dev/full\"") != String::npos, out);
	CHECK_MESSAGE(out.find("wrote /dev/full") == String::npos, out);

	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_cli_full_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
	String exr = (dir / "ok.exr").string();
	CHECK(run_cli_capture("render --width 16 --height 16 -o '" + exr + "' --png /dev/full", &out) == 1);
	CHECK_MESSAGE(out.find("Cannot write \"/dev/full\"") != String::npos, out);
	CHECK_MESSAGE(out.find("wrote /dev/full") == String::npos, out);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[CLI] a malformed scene file exits 2 with an error naming file and line") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_cli_bad_scene_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
	const String bad = (dir / "bad.tscn").string();
	{
		std::ofstream f(bad);
		f << "[gd_scene format=3]\n\n[node name=\"Root\" type=\"Node3D\"]\n\n[node name=\"L\" type=\"OmniLight3D\" parent=\".\"]\nomni_range = Vector3(1, 2\n";
	}
	String out;
	CHECK(run_cli_capture("render '" + bad + "' --width 16 --height 16 -o '" + (dir / "x.exr").string() + "'", &out) == 2);
	CHECK_MESSAGE(out.find(bad + ":6:") != String::npos, out);
	CHECK_FALSE(std::filesystem::exists(dir / "x.exr"));
	std::filesystem::remove_all(dir);
}

TEST_CASE("[CLI] --setting rejects an unknown name with a did-you-mean") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	String out;
	CHECK(run_cli_capture("render --width 16 --height 16 -o /tmp/godot_area_never.exr --setting rendering/lights_and_shadows/area_light_error_budge=0.1", &out) == 2);
	CHECK_MESSAGE(out.find("unknown project setting \"rendering/lights_and_shadows/area_light_error_budge\"; did you mean \"rendering/lights_and_shadows/area_light_error_budget\"?") != String::npos, out);
	CHECK(run_cli_capture("info --setting no/such/thing=1", &out) == 2);
	CHECK_MESSAGE(out.find("unknown project setting \"no/such/thing\"") != String::npos, out);
	CHECK_MESSAGE(out.find("did you mean") == String::npos, out); // Nothing close enough to suggest.
	CHECK_FALSE(std::filesystem::exists("/tmp/godot_area_never.exr"));
}

// A lit floor seen by a camera, with p_lights omni lights above it in view.
static String _lights_scene(int p_lights, bool p_bad_property) {
	String text = "[gd_scene format=3]\n\n[sub_resource type=\"PlaneMesh\" id=\"Plane\"]\nsize = Vector2(8, 8)\n\n"
				  "[node name=\"Root\" type=\"Node3D\"]\n\n"
				  "[node name=\"Camera\" type=\"Camera3D\" parent=\".\"]\ntransform = Transform3D(1, 0, 0, 0, 0.7071068, 0.7071068, 0, -0.7071068, 0.7071068, 0, 4, 4)\n\n"
				  "[node name=\"Floor\" type=\"MeshInstance3D\" parent=\".\"]\nmesh = SubResource(\"Plane\")\n";
	if (p_bad_property) {
		text += "no_such_property = 3\n";
	}
	for (int i = 0; i < p_lights; i++) {
		text += vformat("\n[node name=\"L%d\" type=\"OmniLight3D\" parent=\".\"]\ntransform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, %g, 0.5, %g)\nomni_range = 2.0\n",
				i, -3.0 + 0.15 * i, -1.0 + 0.05 * i);
	}
	return text;
}

TEST_CASE("[CLI][Render] lights over capacity warn once with counts; --strict turns warnings into exit 1") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_cli_strict_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
	const String many = (dir / "many.tscn").string(), bad = (dir / "bad.tscn").string(), exr = (dir / "x.exr").string();
	{
		std::ofstream(many) << _lights_scene(40, false);
		std::ofstream(bad) << _lights_scene(1, true);
	}
	const String common = " --width 32 --height 32 --settle-frames 1 -o '" + exr + "'";
	String out;
	// Capacity 32 per type (rendering/limits/cluster_builder/max_clustered_elements): 8 of 40 omni lights dropped.
	CHECK(run_cli_capture("render '" + many + "'" + common + " --setting rendering/limits/cluster_builder/max_clustered_elements=32", &out) == 0);
	CHECK_MESSAGE(out.find("8 visible lights exceed the renderer's capacity of 32 per type and are not drawn (farthest first: 0 of 0 area, 8 of 40 omni, 0 of 0 spot)") != String::npos, out);
	size_t first = out.find("visible lights exceed");
	CHECK_MESSAGE((first != String::npos && out.find("visible lights exceed", first + 1) == String::npos), "the warning must appear once: ", out);
	CHECK(run_cli_capture("render '" + many + "'" + common + " --strict --setting rendering/limits/cluster_builder/max_clustered_elements=32", &out) == 1);
	CHECK_MESSAGE(out.find("--strict:") != String::npos, out);
	// The default capacity (512) holds them all: no warning, and --strict passes.
	CHECK(run_cli_capture("render '" + many + "'" + common + " --strict", &out) == 0);
	CHECK_MESSAGE(out.find("visible lights exceed") == String::npos, out);
	// A property the node does not have is a load warning: exit 0 normally, 1 with --strict.
	CHECK(run_cli_capture("render '" + bad + "'" + common, &out) == 0);
	CHECK_MESSAGE(out.find("no_such_property") != String::npos, out);
	CHECK(run_cli_capture("render '" + bad + "'" + common + " --strict", &out) == 1);
	std::filesystem::remove_all(dir);
}

} // namespace TestMainCLI
