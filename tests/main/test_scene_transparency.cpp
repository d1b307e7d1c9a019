/**************************************************************************/
/*  test_scene_transparency.cpp                                           */
/**************************************************************************/
/* Issue 15: BaseMaterial3D transparency. ALPHA_SCISSOR cuts holes        */
/* (what is behind shows through: the surface is not in the depth         */
/* pre-pass); ALPHA blends back to front after the opaque pass whatever   */
/* the scene order (Godot's mix: c * a + behind * (1 - a)). Unshaded      */
/* pixels are checked against the closed form, lit ones against the       */
/* Embree reference (cut-out geometry, the ray continued past a blended   */
/* surface).                                                              */

#include "core/io/image.h"
#include "core/math/color.h"
#include "drivers/png/png_writer.h"
#include "modules/openexr/image_loader_exr.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace TestSceneTransparency {

static int run_cli(const String &p_args) {
	String cmd = String("'") + GODOT_AREA_CLI_PATH + "' " + p_args + " > /dev/null 2>&1";
	int status = std::system(cmd.c_str());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Renders p_scene (text) on the GPU and in the reference at 64 x 64; r_images[0] GPU, [1] reference.
static void render_both(const String &p_name, const String &p_scene, Image r_images[2], bool p_png = false) {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_transp_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	if (p_png) {
		// 8 x 8: the left half green with alpha 0, the right half red and opaque.
		std::vector<uint8_t> texels(8 * 8 * 4, 0);
		for (int i = 0; i < 64; i++) {
			const bool right = (i % 8) >= 4;
			texels[i * 4 + 0] = right ? 255 : 0;
			texels[i * 4 + 1] = right ? 0 : 255;
			texels[i * 4 + 3] = right ? 255 : 0;
		}
		REQUIRE(PNGWriter::save_rgba8(texels, 8, 8, (dir / "cutout.png").string()));
	}
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	const String scene = (dir / (p_name + ".tscn").c_str()).string();
	std::ofstream(scene.c_str()) << p_scene.c_str();
	const String gpu = (dir / (p_name + "_gpu.exr").c_str()).string(), ref = (dir / (p_name + "_ref.exr").c_str()).string();
	CHECK(run_cli("render '" + scene + "' --width 64 --height 64 -o '" + gpu + "'") == 0);
	CHECK(run_cli("reference '" + scene + "' --width 64 --height 64 --shadows off -o '" + ref + "'") == 0);
	for (int i = 0; i < 2; i++) {
		String error;
		REQUIRE_MESSAGE(ImageLoaderEXR::load(i == 0 ? gpu : ref, r_images[i], &error), error);
		REQUIRE(r_images[i].get_width() == 64);
	}
	std::filesystem::remove_all(dir);
}

static void check_pixel(const Image &p_image, int p_x, int p_y, const Color &p_want, float p_tolerance, const char *p_who) {
	const Color got = p_image.get_pixel(p_x, p_y);
	CHECK_MESSAGE((std::fabs(got.r - p_want.r) <= p_tolerance && std::fabs(got.g - p_want.g) <= p_tolerance && std::fabs(got.b - p_want.b) <= p_tolerance),
			p_who << " pixel (" << p_x << ", " << p_y << "): " << got.r << " " << got.g << " " << got.b << ", want " << p_want.r << " " << p_want.g << " " << p_want.b);
}

// An unshaded quad (size p_size, at depth p_z, facing the camera) with the given material lines.
static String quad(const String &p_name, float p_size, float p_z, const String &p_material) {
	return vformat(R"(
[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_%s"]
%s

[sub_resource type="QuadMesh" id="QuadMesh_%s"]
material = SubResource("StandardMaterial3D_%s")
size = Vector2(%s, %s)
)",
			p_name.c_str(), p_material.c_str(), p_name.c_str(), p_name.c_str(), rtos(p_size).c_str(), rtos(p_size).c_str());
}

static String node(const String &p_name, float p_z) {
	return vformat(R"(
[node name="%s" type="MeshInstance3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, %s)
mesh = SubResource("QuadMesh_%s")
)",
			p_name.c_str(), rtos(p_z).c_str(), p_name.c_str());
}

TEST_CASE("[CLI][Render] alpha blend: back to front whatever the scene order, Godot's mix, GPU and reference") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	// A white backdrop at 3 m; half-transparent red at 1 m and blue at 2 m, the near one listed first
	// (drawn in scene order, the blue would land over the red).
	String scene = "[gd_scene format=3]\n";
	scene += quad("Near", 1.0f, -1.0f, "shading_mode = 0\ntransparency = 1\nalbedo_color = Color(1, 0, 0, 0.5)");
	scene += quad("Far", 1.0f, -2.0f, "shading_mode = 0\ntransparency = 1\nalbedo_color = Color(0, 0, 1, 0.5)");
	scene += quad("Back", 4.0f, -3.0f, "shading_mode = 0");
	scene += "\n[node name=\"Root\" type=\"Node3D\"]\n";
	scene += node("Near", -1.0f) + node("Far", -2.0f) + node("Back", -3.0f);
	scene += "\n[node name=\"Camera3D\" type=\"Camera3D\" parent=\".\"]\n";
	Image images[2];
	render_both("blend", scene, images);
	for (int i = 0; i < 2; i++) {
		const char *who = i == 0 ? "GPU" : "reference";
		// Centre: white, then blue at 0.5, then red at 0.5: (0.75, 0.25, 0.5). Unsorted: (0.5, 0.25, 0.75).
		check_pixel(images[i], 32, 32, Color(0.75f, 0.25f, 0.5f), 2e-3f, who);
		// Only the near quad over white (the far one covers pixels 22..42): (1, 0.5, 0.5).
		check_pixel(images[i], 15, 32, Color(1.0f, 0.5f, 0.5f), 2e-3f, who);
		check_pixel(images[i], 6, 32, Color(1.0f, 1.0f, 1.0f), 2e-3f, who); // The backdrop alone.
	}
}

TEST_CASE("[CLI][Render] alpha scissor: holes show what is behind, GPU and reference") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	String scene = "[gd_scene format=3]\n\n[ext_resource type=\"Texture2D\" path=\"res://cutout.png\" id=\"1_cut\"]\n";
	scene += quad("Cut", 1.0f, -1.0f, "shading_mode = 0\ntransparency = 2\nalpha_scissor_threshold = 0.5\nalbedo_texture = ExtResource(\"1_cut\")\ntexture_filter = 0");
	scene += quad("Back", 4.0f, -3.0f, "shading_mode = 0\nalbedo_color = Color(1, 1, 0, 1)");
	scene += "\n[node name=\"Root\" type=\"Node3D\"]\n";
	scene += node("Cut", -1.0f) + node("Back", -3.0f);
	scene += "\n[node name=\"Camera3D\" type=\"Camera3D\" parent=\".\"]\n";
	Image images[2];
	render_both("scissor", scene, images, true);
	for (int i = 0; i < 2; i++) {
		const char *who = i == 0 ? "GPU" : "reference";
		check_pixel(images[i], 20, 32, Color(1, 1, 0), 2e-3f, who); // Left half (alpha 0): the yellow backdrop.
		check_pixel(images[i], 44, 32, Color(1, 0, 0), 2e-3f, who); // Right half: the quad's red.
	}
}

TEST_CASE("[CLI][Render] a lit alpha-blended quad over a lit floor agrees between the GPU and the reference") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	String scene = "[gd_scene format=3]\n";
	scene += quad("Glass", 1.0f, -1.5f, "transparency = 1\nalbedo_color = Color(0.2, 0.6, 0.9, 0.4)\nroughness = 0.4");
	scene += quad("Back", 4.0f, -3.0f, "albedo_color = Color(0.8, 0.8, 0.8, 1)");
	scene += "\n[node name=\"Root\" type=\"Node3D\"]\n";
	scene += node("Glass", -1.5f) + node("Back", -3.0f);
	scene += "\n[node name=\"OmniLight3D\" type=\"OmniLight3D\" parent=\".\"]\ntransform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0.3, 0.4, -0.5)\nlight_energy = 2.0\nomni_range = 10.0\n";
	scene += "\n[node name=\"Camera3D\" type=\"Camera3D\" parent=\".\"]\n";
	Image images[2];
	render_both("lit", scene, images);
	// Block means (8 x 8) over the glass (centre) and the floor beside it.
	const int blocks[2][2] = { { 32, 32 }, { 10, 32 } };
	for (int b = 0; b < 2; b++) {
		double mean[2][3] = {};
		for (int i = 0; i < 2; i++) {
			for (int y = blocks[b][1] - 4; y < blocks[b][1] + 4; y++) {
				for (int x = blocks[b][0] - 4; x < blocks[b][0] + 4; x++) {
					const Color c = images[i].get_pixel(x, y);
					mean[i][0] += c.r / 64.0;
					mean[i][1] += c.g / 64.0;
					mean[i][2] += c.b / 64.0;
				}
			}
		}
		for (int c = 0; c < 3; c++) {
			CHECK_MESSAGE(std::fabs(mean[0][c] - mean[1][c]) <= 0.02 * mean[1][c] + 2e-3, "block " << b << " channel " << c << ": GPU " << mean[0][c] << " reference " << mean[1][c]);
		}
	}
}

} // namespace TestSceneTransparency
