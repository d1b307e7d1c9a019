/**************************************************************************/
/*  test_demo_renders.cpp                                                 */
/**************************************************************************/
/* godot-area: render --compare-punctual (equal-power SpotLight3D stand-  */
/* ins, main/demo_renders.h), render --frames N --path SPEC (numbered     */
/* frames, APNG), and the hero demo against the Embree reference.         */

#include "core/io/image.h"
#include "drivers/png/png_reader.h"
#include "main/demo_renders.h"
#include "modules/metrics/image_metrics.h"
#include "modules/openexr/image_loader_exr.h"
#include "scene/3d/light_3d.h"
#include "scene/resources/resource_format_text.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace TestDemoRenders {

int run_cli(const String &p_args, String *r_output = nullptr) {
	std::filesystem::path log = std::filesystem::temp_directory_path() / "godot_area_test_demo_renders.log";
	String cmd = String("'") + GODOT_AREA_CLI_PATH + "' " + p_args + " > '" + log.string() + "' 2>&1";
	int status = std::system(cmd.c_str());
	std::ifstream f(log);
	std::stringstream ss;
	ss << f.rdbuf();
	if (r_output) {
		*r_output = ss.str();
	}
	std::filesystem::remove(log);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

double mean_luminance(const Image &p_image) {
	double sum = 0;
	for (int y = 0; y < p_image.get_height(); y++) {
		for (int x = 0; x < p_image.get_width(); x++) {
			const Color c = p_image.get_pixel(x, y);
			sum += 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
		}
	}
	return sum / (double(p_image.get_width()) * p_image.get_height());
}

TEST_CASE("[DemoRenders] the spot stand-in's power, integrated numerically, equals the area light's") {
	// Area light of energy E (colour 1): power pi^2 E (normalized) or pi^2 E A. Spot of energy E': intensity
	// E' pi cone(t); integrate over the sphere with the midpoint rule, independent of the closed form.
	struct Case {
		float energy, w, h;
		bool normalize;
		float angle, k;
	};
	for (const Case &c : { Case{ 3.0f, 1.6f, 0.9f, true, 90.0f, 1.0f }, Case{ 2.0f, 0.5f, 2.0f, false, 90.0f, 1.0f }, Case{ 1.0f, 1.0f, 1.0f, true, 45.0f, 1.0f }, Case{ 5.0f, 1.0f, 1.0f, true, 60.0f, 2.5f } }) {
		const float spot = DemoRenders::spot_energy_for_area_light(c.energy, c.w, c.h, c.normalize, c.angle, c.k);
		const double cos_a = std::cos(c.angle * M_PI / 180.0);
		double power = 0;
		const int n = 20000;
		for (int i = 0; i < n; i++) {
			const double t = (i + 0.5) * M_PI / n, ct = std::cos(t);
			const double cone = ct <= cos_a ? 0.0 : 1.0 - std::pow(std::max(1e-4, (1.0 - ct) / (1.0 - cos_a)), double(c.k));
			power += spot * M_PI * cone * 2.0 * M_PI * std::sin(t) * (M_PI / n);
		}
		const double area_power = M_PI * M_PI * c.energy * (c.normalize ? 1.0 : c.w * c.h);
		CHECK_MESSAGE(std::fabs(power / area_power - 1.0) < 2e-3, "angle ", c.angle, " k ", c.k, ": spot power ", power, " area power ", area_power);
	}
	// The demo's conversion: a 90-degree linear-rim spot has the area light's cos-law intensity, so E' = E.
	CHECK(DemoRenders::spot_energy_for_area_light(8.0f, 1.6f, 0.9f, true) == doctest::Approx(8.0f));
}

TEST_CASE("[DemoRenders] replace_area_lights_with_spots keeps name, place, colour, range and falloff") {
	SceneTest::DummyServer server;
	const String text = "[gd_scene format=3]\n\n[node name=\"Root\" type=\"Node3D\"]\n\n"
						"[node name=\"Group\" type=\"Node3D\" parent=\".\"]\n\n"
						"[node name=\"Omni\" type=\"OmniLight3D\" parent=\"Group\"]\n\n"
						"[node name=\"Panel\" type=\"AreaLight3D\" parent=\"Group\"]\n"
						"transform = Transform3D(1, 0, 0, 0, 0, 1, 0, -1, 0, 1, 2.5, -3)\nlight_color = Color(1, 0.5, 0.25, 1)\nlight_energy = 4.0\n"
						"light_specular = 0.7\nshadow_enabled = true\narea_size = Vector2(2, 0.5)\narea_range = 6.0\narea_attenuation = 2.0\narea_normalize_energy = false\n\n"
						"[node name=\"After\" type=\"Node3D\" parent=\"Group\"]\n";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "replace.tscn", &error);
	REQUIRE_MESSAGE(root, error);
	std::vector<String> report;
	CHECK(DemoRenders::replace_area_lights_with_spots(root, &report) == 1);
	REQUIRE(report.size() == 1);
	CHECK_MESSAGE(report[0].find("Panel") != String::npos, report[0]);
	Node *group = root->get_node("Group");
	REQUIRE(group);
	REQUIRE(group->get_child_count() == 3);
	SpotLight3D *spot = Object::cast_to<SpotLight3D>(group->get_child(1)); // Same index as the area light.
	REQUIRE(spot);
	CHECK(spot->get_name() == "Panel");
	CHECK(spot->get_transform().origin.is_equal_approx(Vector3(1, 2.5, -3)));
	CHECK(spot->get_transform().basis.get_column(2).is_equal_approx(Vector3(0, 1, 0))); // Emits along -Z = world -Y.
	CHECK(spot->get_color().is_equal_approx(Color(1, 0.5, 0.25, 1)));
	CHECK(spot->get_param(Light3D::PARAM_RANGE) == doctest::Approx(6.0f));
	CHECK(spot->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.0f));
	CHECK(spot->get_param(Light3D::PARAM_SPECULAR) == doctest::Approx(0.7f));
	CHECK(spot->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(90.0f));
	CHECK(spot->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(4.0f * 2.0f * 0.5f)); // Not normalized: E * A.
	CHECK(Object::cast_to<OmniLight3D>(group->get_child(0)));
	CHECK(group->get_child(2)->get_name() == "After");
	delete root;
}

TEST_CASE("[DemoRenders] camera paths parse, and orbit and dolly move the camera as documented") {
	DemoRenders::CameraPath path;
	String error;
	CHECK_FALSE(DemoRenders::parse_camera_path("spiral:3", path, &error));
	CHECK_MESSAGE(error.find("spiral:3") != String::npos, error);
	CHECK_FALSE(DemoRenders::parse_camera_path("orbit:30", path, &error)); // No pivot.
	CHECK_FALSE(DemoRenders::parse_camera_path("orbit:nan@0,0,0", path, &error));
	CHECK_FALSE(DemoRenders::parse_camera_path("dolly:1,2", path, &error));
	REQUIRE(DemoRenders::parse_camera_path("orbit:90@1,0,0", path, &error));
	const Transform3D start(Basis(), Vector3(1, 1, 2)); // 2 m from the pivot's axis, looking along -Z at it.
	CHECK(path.sample(start, 0.5f).origin.is_equal_approx(start.origin));
	const Transform3D first = path.sample(start, 0.0f), last = path.sample(start, 1.0f);
	CHECK(first.origin.is_equal_approx(Vector3(1 - std::sqrt(2.0f), 1, std::sqrt(2.0f)))); // -45 degrees about +Y.
	CHECK(last.origin.is_equal_approx(Vector3(1 + std::sqrt(2.0f), 1, std::sqrt(2.0f))));
	// Still looking at the axis: the forward vector (-Z column) points from the camera to the pivot's axis.
	CHECK((-first.basis.get_column(2)).is_equal_approx((Vector3(1, 1, 0) - first.origin).normalized()));
	REQUIRE(DemoRenders::parse_camera_path("dolly:0, 0.5, -2", path, &error));
	CHECK(path.sample(start, 1.0f).origin.is_equal_approx(Vector3(1, 1.5, 0)));
	CHECK(path.sample(start, 0.25f).origin.is_equal_approx(Vector3(1, 1.125, 1.5)));
	CHECK(DemoRenders::numbered_path("out/frame.exr", 3) == "out/frame00000003.exr");
	CHECK(DemoRenders::numbered_path("a.dir/frame", 12) == "a.dir/frame00000012");
	CHECK(DemoRenders::suffixed_path("out/demo.png", "_punctual") == "out/demo_punctual.png");
}

TEST_CASE("[CLI][Render] --compare-punctual: a small far panel and its spot stand-in light a floor equally") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_compare_punctual";
	std::filesystem::create_directories(dir);
	// A 0.3 m panel 4 m above a Lambert floor (far field: the floor sees it as a point), no specular.
	const String scene = (dir / "far.tscn").string();
	std::ofstream(scene) << "[gd_scene format=3]\n\n[sub_resource type=\"PlaneMesh\" id=\"Plane\"]\nsize = Vector2(6, 6)\n\n"
							"[sub_resource type=\"StandardMaterial3D\" id=\"Mat\"]\nspecular_mode = 2\ndiffuse_mode = 1\n\n"
							"[node name=\"Root\" type=\"Node3D\"]\n\n"
							"[node name=\"Camera\" type=\"Camera3D\" parent=\".\"]\ntransform = Transform3D(1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 3, 0)\n\n"
							"[node name=\"Floor\" type=\"MeshInstance3D\" parent=\".\"]\nmesh = SubResource(\"Plane\")\nmaterial_override = SubResource(\"Mat\")\n\n"
							"[node name=\"Panel\" type=\"AreaLight3D\" parent=\".\"]\ntransform = Transform3D(1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 4, 0)\n"
							"light_energy = 2.0\narea_size = Vector2(0.3, 0.3)\narea_range = 20.0\narea_attenuation = 2.0\n";
	const String exr = (dir / "far.exr").string(), png = (dir / "far.png").string();
	String out;
	REQUIRE_MESSAGE(run_cli("render '" + scene + "' --width 48 --height 48 --compare-punctual -o '" + exr + "' --png '" + png + "'", &out) == 0, out);
	CHECK_MESSAGE(out.find("Panel: AreaLight3D 0.3x0.3 m, light_energy 2 -> SpotLight3D light_energy 2") != String::npos, out);
	Image area, spot;
	String error;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(exr, area, &error), error);
	REQUIRE_MESSAGE(ImageLoaderEXR::load((dir / "far_punctual.exr").string(), spot, &error), error);
	const double a = mean_luminance(area), s = mean_luminance(spot);
	MESSAGE("mean floor radiance: area ", a, ", spot stand-in ", s);
	CHECK(a > 0.01);
	CHECK(std::fabs(s / a - 1.0) < 0.02);
	std::vector<uint8_t> rgba;
	int w = 0, h = 0;
	REQUIRE_MESSAGE(PNGReader::load((dir / "far_side_by_side.png").string(), rgba, w, h, &error), error);
	CHECK(w == 2 * 48 + 8);
	CHECK(h == 48);
	CHECK(std::filesystem::exists(dir / "far_punctual.png"));
	// A scene without area lights has nothing to compare.
	const String none = (dir / "none.tscn").string();
	std::ofstream(none) << "[gd_scene format=3]\n\n[node name=\"Root\" type=\"Node3D\"]\n\n[node name=\"Camera\" type=\"Camera3D\" parent=\".\"]\n";
	CHECK(run_cli("render '" + none + "' --width 8 --height 8 --compare-punctual -o '" + (dir / "none.exr").string() + "'", &out) == 1);
	CHECK_MESSAGE(out.find("no AreaLight3D") != String::npos, out);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[CLI][Render] StandardMaterial3D emission: srgb_to_linear(emission) * emission_energy_multiplier, only when enabled") {
	// The demo's emitters rely on Godot's meaning; a black, unlit plane filling the view shows emission alone.
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_emission";
	std::filesystem::create_directories(dir);
	for (bool enabled : { true, false }) {
		const String scene = (dir / "emissive.tscn").string(), exr = (dir / "emissive.exr").string();
		std::ofstream(scene) << "[gd_scene format=3]\n\n[sub_resource type=\"PlaneMesh\" id=\"Plane\"]\nsize = Vector2(20, 20)\n\n"
								"[sub_resource type=\"StandardMaterial3D\" id=\"Mat\"]\nalbedo_color = Color(0, 0, 0, 1)\n"
							 << "emission_enabled = " << (enabled ? "true" : "false") << "\nemission = Color(0.5, 0.25, 1, 1)\nemission_energy_multiplier = 3.0\n\n"
							 << "[sub_resource type=\"Environment\" id=\"Env\"]\nbackground_mode = 1\nbackground_color = Color(0, 0, 0, 1)\nambient_light_source = 1\n\n"
								"[node name=\"Root\" type=\"Node3D\"]\n\n"
								"[node name=\"Env\" type=\"WorldEnvironment\" parent=\".\"]\nenvironment = SubResource(\"Env\")\n\n"
								"[node name=\"Camera\" type=\"Camera3D\" parent=\".\"]\ntransform = Transform3D(1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 2, 0)\n\n"
								"[node name=\"Floor\" type=\"MeshInstance3D\" parent=\".\"]\nmesh = SubResource(\"Plane\")\nmaterial_override = SubResource(\"Mat\")\n";
		String out;
		REQUIRE_MESSAGE(run_cli("render '" + scene + "' --width 16 --height 16 --strict -o '" + exr + "'", &out) == 0, out);
		Image image;
		String error;
		REQUIRE_MESSAGE(ImageLoaderEXR::load(exr, image, &error), error);
		const Color c = image.get_pixel(8, 8);
		const Color expected = enabled ? Color(0.5f, 0.25f, 1.0f).srgb_to_linear() * 3.0f : Color(0, 0, 0);
		CHECK_MESSAGE(std::fabs(c.r - expected.r) < 2e-3f * std::max(1.0f, expected.r), "enabled ", enabled, ": ", c.r, " vs ", expected.r);
		CHECK_MESSAGE(std::fabs(c.g - expected.g) < 2e-3f * std::max(1.0f, expected.g), "enabled ", enabled, ": ", c.g, " vs ", expected.g);
		CHECK_MESSAGE(std::fabs(c.b - expected.b) < 2e-3f * std::max(1.0f, expected.b), "enabled ", enabled, ": ", c.b, " vs ", expected.b);
	}
	std::filesystem::remove_all(dir);
}

uint32_t _be32(const uint8_t *p) {
	return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

TEST_CASE("[CLI][Render] --frames N --path writes numbered frames along the path and a looping APNG") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_frames";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const String exr = (dir / "f.exr").string(), png = (dir / "f.png").string(), apng = (dir / "anim.png").string();
	String out;
	REQUIRE_MESSAGE(run_cli("render --frames 3 --path orbit:24@-0.5,0.8,-1.5 --width 48 --height 27 -o '" + exr + "' --png '" + png + "' --apng '" + apng + "' --frame-ms 100", &out) == 0, out);
	Image first, last;
	String error;
	REQUIRE_MESSAGE(ImageLoaderEXR::load((dir / "f00000000.exr").string(), first, &error), error);
	REQUIRE_MESSAGE(ImageLoaderEXR::load((dir / "f00000002.exr").string(), last, &error), error);
	CHECK(std::filesystem::exists(dir / "f00000001.exr"));
	CHECK(std::filesystem::exists(dir / "f00000002.png"));
	CHECK_FALSE(std::filesystem::exists(dir / "f00000003.exr"));
	ImageMetrics::Result moved;
	REQUIRE_MESSAGE(ImageMetrics::compare(first, last, &moved, &error), error);
	CHECK_MESSAGE(moved.rmse > 0.005, "the camera moved, the frames must differ: RMSE ", moved.rmse);
	CHECK_MESSAGE(out.find("frame 2:") != String::npos, out);
	CHECK_MESSAGE(out.find("GPU total") != String::npos, out);

	// The APNG: a PNG whose default image (what libpng reads) is frame 0, then acTL with 3 frames, one fcTL per
	// frame, fdAT for frames 1 and 2, sequence numbers 0, 1, 2... in order.
	std::vector<uint8_t> apng_rgba, frame0_rgba;
	int w = 0, h = 0, w0 = 0, h0 = 0;
	REQUIRE_MESSAGE(PNGReader::load(apng, apng_rgba, w, h, &error), error);
	REQUIRE_MESSAGE(PNGReader::load((dir / "f00000000.png").string(), frame0_rgba, w0, h0, &error), error);
	CHECK(w == 48);
	CHECK(h == 27);
	CHECK(apng_rgba == frame0_rgba);
	std::ifstream f(apng, std::ios::binary);
	std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	REQUIRE(bytes.size() > 8);
	int fctl = 0, fdat = 0, actl_frames = -1, delay_num = -1;
	uint32_t expected_sequence = 0;
	bool sequence_ok = true;
	for (size_t at = 8; at + 12 <= bytes.size();) {
		const uint32_t length = _be32(&bytes[at]);
		const String type(reinterpret_cast<const char *>(&bytes[at + 4]), 4);
		const uint8_t *data = &bytes[at + 8];
		if (type == "acTL") {
			actl_frames = int(_be32(data));
		} else if (type == "fcTL" || type == "fdAT") {
			sequence_ok = sequence_ok && _be32(data) == expected_sequence++;
			if (type == "fcTL") {
				fctl++;
				delay_num = (data[20] << 8) | data[21];
			} else {
				fdat++;
			}
		}
		at += 12 + length;
	}
	CHECK(actl_frames == 3);
	CHECK(fctl == 3);
	CHECK(fdat >= 2);
	CHECK(sequence_ok);
	CHECK(delay_num == 100);

	// Options that need --frames, or cannot go with it, are rejected before anything renders.
	CHECK(run_cli("render --path orbit:10@0,0,0 -o '" + exr + "'", &out) == 2);
	CHECK_MESSAGE(out.find("--path needs --frames N") != String::npos, out);
	CHECK(run_cli("render --frames 2 --path spiral:2 -o '" + exr + "'", &out) == 2);
	CHECK(run_cli("render --frames 0 -o '" + exr + "'", &out) == 2);
	CHECK(run_cli("render --frames 2 --compare-punctual -o '" + exr + "'", &out) == 2);
	std::filesystem::remove_all(dir);
}

} // namespace TestDemoRenders
