/**************************************************************************/
/*  test_scene_textures.cpp                                               */
/**************************************************************************/
/* Issue 15: a scene's image textures load (PNG through libpng, JPEG      */
/* through stb_image, WebP through libwebp) and draw: an unshaded         */
/* textured quad's pixels equal the image decoded sRGB -> linear within   */
/* 1/255, on the GPU and in the Embree reference; on a receding           */
/* checkerboard the mipmap filter (the default) aliases far less than the */
/* plain linear one, averages in linear space, and the reference (ray     */
/* differentials) agrees with the GPU. The PNG and WebP files are written */
/* by the test (no binary asset).                                         */

#include "core/io/image.h"
#include "core/io/image_loader.h"
#include "core/math/color.h"
#include "drivers/png/png_writer.h"
#include "modules/openexr/image_loader_exr.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>
#include <webp/encode.h>

namespace TestSceneTextures {

static int run_cli(const String &p_args) {
	String cmd = String("'") + GODOT_AREA_CLI_PATH + "' " + p_args + " > /dev/null 2>&1";
	int status = std::system(cmd.c_str());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Quadrant colours (sRGB 8-bit): top-left, top-right, bottom-left, bottom-right.
static const uint8_t QUADRANTS[4][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 }, { 200, 120, 40 } };

static std::vector<uint8_t> quadrant_texels(int p_size) {
	std::vector<uint8_t> rgba((size_t)p_size * p_size * 4);
	for (int y = 0; y < p_size; y++) {
		for (int x = 0; x < p_size; x++) {
			const uint8_t *c = QUADRANTS[(y >= p_size / 2) * 2 + (x >= p_size / 2)];
			uint8_t *t = &rgba[((size_t)y * p_size + x) * 4];
			t[0] = c[0];
			t[1] = c[1];
			t[2] = c[2];
			t[3] = 255;
		}
	}
	return rgba;
}

TEST_CASE("[ImageLoader] PNG texels load as stored (8-bit / 255)") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_imgload_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	String png = (dir / "q.png").string();
	REQUIRE(PNGWriter::save_rgba8(quadrant_texels(8), 8, 8, png));
	Image image;
	String error;
	REQUIRE_MESSAGE(ImageLoader::load_image(png, image, &error), error);
	CHECK(image.get_width() == 8);
	CHECK(image.get_pixel(7, 7).is_equal_approx(Color(200 / 255.0f, 120 / 255.0f, 40 / 255.0f, 1)));
	CHECK_FALSE(ImageLoader::load_image((dir / "none.png").string(), image, &error));
	CHECK(error.find("none.png") != String::npos);
	std::ofstream(dir / "bad.jpg") << "not a jpeg";
	CHECK_FALSE(ImageLoader::load_image((dir / "bad.jpg").string(), image, &error));
	CHECK(error.find("bad.jpg") != String::npos);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[ImageLoader] WebP loads: lossless exactly, lossy close; bad files name the file") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_webp_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	const std::vector<uint8_t> texels = quadrant_texels(16);
	// Written by libwebp's own encoder (no binary asset in the tree).
	auto write = [&](const String &p_name, bool p_lossless) {
		uint8_t *out = nullptr;
		const size_t size = p_lossless ? WebPEncodeLosslessRGBA(texels.data(), 16, 16, 16 * 4, &out) : WebPEncodeRGBA(texels.data(), 16, 16, 16 * 4, 95.0f, &out);
		REQUIRE(size > 0);
		std::ofstream((dir / p_name.c_str()).string(), std::ios::binary).write(reinterpret_cast<const char *>(out), std::streamsize(size));
		WebPFree(out);
		return (dir / p_name.c_str()).string();
	};
	Image image;
	String error;
	REQUIRE_MESSAGE(ImageLoader::load_image(write("lossless.webp", true), image, &error), error);
	REQUIRE(image.get_width() == 16);
	REQUIRE(image.get_height() == 16);
	float worst = 0.0f;
	for (int y = 0; y < 16; y++) {
		for (int x = 0; x < 16; x++) {
			const uint8_t *t = &texels[(size_t(y) * 16 + x) * 4];
			const Color c = image.get_pixel(x, y);
			worst = std::max({ worst, std::fabs(c.r - t[0] / 255.0f), std::fabs(c.g - t[1] / 255.0f), std::fabs(c.b - t[2] / 255.0f), std::fabs(c.a - 1.0f) });
		}
	}
	CHECK(worst == 0.0f); // Lossless: every texel as stored.
	REQUIRE_MESSAGE(ImageLoader::load_image(write("lossy.webp", false), image, &error), error);
	const Color centre = image.get_pixel(12, 12); // Inside the bottom-right quadrant (200, 120, 40).
	CHECK(centre.r == doctest::Approx(200 / 255.0f).epsilon(0.05));
	CHECK(centre.g == doctest::Approx(120 / 255.0f).epsilon(0.05));
	CHECK(centre.b == doctest::Approx(40 / 255.0f).epsilon(0.15));
	std::ofstream(dir / "bad.webp") << "RIFF not really";
	CHECK_FALSE(ImageLoader::load_image((dir / "bad.webp").string(), image, &error));
	CHECK(error.find("bad.webp") != String::npos);
	CHECK(image.is_empty());
	std::filesystem::remove_all(dir);
}

TEST_CASE("[CLI][Render] a textured quad's pixels equal the PNG (sRGB -> linear) on the GPU and in the reference") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_texquad_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir / "textures");
	REQUIRE(PNGWriter::save_rgba8(quadrant_texels(8), 8, 8, (dir / "textures" / "quadrants.png").string()));
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	// The quad (1.5 m, facing +Z) at 1 m fills a 75-degree view.
	std::ofstream(dir / "quad.tscn") << R"([gd_scene load_steps=4 format=3 uid="uid://btexquad0001"]

[ext_resource type="Texture2D" uid="uid://dquadrants001" path="res://textures/quadrants.png" id="1_q4d"]

[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_u1"]
shading_mode = 0
albedo_texture = ExtResource("1_q4d")

[sub_resource type="QuadMesh" id="QuadMesh_q1"]
material = SubResource("StandardMaterial3D_u1")
size = Vector2(1.5, 1.5)

[node name="Root" type="Node3D"]

[node name="Quad" type="MeshInstance3D" parent="."]
mesh = SubResource("QuadMesh_q1")

[node name="Camera3D" type="Camera3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1)
)";
	String gpu = (dir / "gpu.exr").string(), ref = (dir / "ref.exr").string();
	String scene = (dir / "quad.tscn").string();
	CHECK(run_cli("render '" + scene + "' --width 64 --height 64 -o '" + gpu + "'") == 0);
	CHECK(run_cli("reference '" + scene + "' --width 64 --height 64 --spp 4 --shadows off -o '" + ref + "'") == 0);
	for (const String &out : { gpu, ref }) {
		Image image;
		String error;
		REQUIRE_MESSAGE(ImageLoaderEXR::load(out, image, &error), error);
		REQUIRE(image.get_width() == 64);
		const int px[4][2] = { { 16, 16 }, { 48, 16 }, { 16, 48 }, { 48, 48 } };
		for (int q = 0; q < 4; q++) {
			Color got = image.get_pixel(px[q][0], px[q][1]);
			for (int c = 0; c < 3; c++) {
				float want = Color::srgb_to_linear_channel(QUADRANTS[q][c] / 255.0f);
				float have = c == 0 ? got.r : (c == 1 ? got.g : got.b);
				CHECK_MESSAGE(std::fabs(have - want) <= 1.0f / 255.0f, out << " quadrant " << q << " channel " << c << ": " << have << " vs " << want);
			}
		}
	}
	std::filesystem::remove_all(dir);
}

// Mean colour of the p_size x p_size block centred at (p_cx, p_cy).
static Color block_mean(const Image &p_image, int p_cx, int p_cy, int p_size) {
	double sum[3] = { 0, 0, 0 };
	for (int y = p_cy - p_size / 2; y < p_cy + p_size / 2; y++) {
		for (int x = p_cx - p_size / 2; x < p_cx + p_size / 2; x++) {
			const Color c = p_image.get_pixel(x, y);
			sum[0] += c.r;
			sum[1] += c.g;
			sum[2] += c.b;
		}
	}
	const double n = double(p_size) * p_size;
	return Color(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n), 1);
}

TEST_CASE("[CLI][Render] uv1_scale, nearest filtering and roughness/metallic textures agree between the GPU and the reference") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_texmaps_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir / "textures");
	REQUIRE(PNGWriter::save_rgba8(quadrant_texels(8), 8, 8, (dir / "textures" / "quadrants.png").string()));
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	// Left: unshaded, the texture tiled 2 x 2 with nearest filtering. Right: a lit metal whose metallic
	// is the red channel and whose roughness is the grey level of the same texture.
	std::ofstream(dir / "maps.tscn") << R"([gd_scene load_steps=6 format=3 uid="uid://btexmaps0001"]

[ext_resource type="Texture2D" uid="uid://dquadrants002" path="res://textures/quadrants.png" id="1_q4d"]

[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_tiled"]
shading_mode = 0
albedo_texture = ExtResource("1_q4d")
uv1_scale = Vector3(2, 2, 1)
texture_filter = 0

[sub_resource type="QuadMesh" id="QuadMesh_tiled"]
material = SubResource("StandardMaterial3D_tiled")
size = Vector2(1.5, 1.5)

[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_maps"]
albedo_color = Color(0.9, 0.9, 0.9, 1)
metallic = 1.0
metallic_texture = ExtResource("1_q4d")
roughness_texture = ExtResource("1_q4d")
roughness_texture_channel = 4

[sub_resource type="QuadMesh" id="QuadMesh_maps"]
material = SubResource("StandardMaterial3D_maps")
size = Vector2(1.5, 1.5)

[node name="Root" type="Node3D"]

[node name="Tiled" type="MeshInstance3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, -0.75, 0, 0)
mesh = SubResource("QuadMesh_tiled")

[node name="Maps" type="MeshInstance3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0.75, 0, 0)
mesh = SubResource("QuadMesh_maps")

[node name="OmniLight3D" type="OmniLight3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0.75, 0, 0.6)
light_energy = 2.0
omni_range = 10.0

[node name="Camera3D" type="Camera3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1)
fov = 73.7398
)";
	String gpu = (dir / "gpu.exr").string(), ref = (dir / "ref.exr").string();
	String scene = (dir / "maps.tscn").string();
	CHECK(run_cli("render '" + scene + "' --width 128 --height 64 -o '" + gpu + "'") == 0);
	CHECK(run_cli("reference '" + scene + "' --width 128 --height 64 --spp 4 --shadows off -o '" + ref + "'") == 0);
	Image images[2];
	for (int i = 0; i < 2; i++) {
		String error;
		REQUIRE_MESSAGE(ImageLoaderEXR::load(i == 0 ? gpu : ref, images[i], &error), error);
		REQUIRE(images[i].get_width() == 128);
		// The tiled quad fills x 0..63 (fov 2 atan(0.75) at 1 m: a 3 m x 1.5 m view): UV x = (x + 0.5) / 64, scaled by 2.
		// At x = 16 the scaled U is 0.516, texel coordinate 4.13: nearest reads texel 4 (the right
		// quadrant's green) where linear filtering would blend in 37 % of texel 3's red.
		// Tolerance: the GPU target is half float (2^-11 relative).
		const String who = i == 0 ? "GPU" : "reference";
		const Color got = images[i].get_pixel(16, 8);
		CHECK_MESSAGE((std::fabs(got.r) < 2e-3f && std::fabs(got.g - 1.0f) < 2e-3f && std::fabs(got.b) < 2e-3f), who << ": " << got.r << " " << got.g << " " << got.b);
		// x = 8 and x = 40 read the same tile position (the texture repeats twice).
		const Color a = images[i].get_pixel(8, 40), b = images[i].get_pixel(40, 40);
		CHECK_MESSAGE((std::fabs(a.r - b.r) < 2e-3f && std::fabs(a.g - b.g) < 2e-3f && std::fabs(a.b - b.b) < 2e-3f), who);
	}
	// The lit quad (x 64..127): quadrant means, GPU against the reference; metallic 1 (top left) and
	// metallic 0 (top right) must differ.
	const int centres[4][2] = { { 80, 16 }, { 112, 16 }, { 80, 48 }, { 112, 48 } };
	Color means[2][4];
	for (int i = 0; i < 2; i++) {
		for (int q = 0; q < 4; q++) {
			means[i][q] = block_mean(images[i], centres[q][0], centres[q][1], 12);
		}
	}
	for (int q = 0; q < 4; q++) {
		for (int c = 0; c < 3; c++) {
			const float g = c == 0 ? means[0][q].r : (c == 1 ? means[0][q].g : means[0][q].b);
			const float r = c == 0 ? means[1][q].r : (c == 1 ? means[1][q].g : means[1][q].b);
			CHECK_MESSAGE(std::fabs(g - r) <= 0.02f * r + 2e-3f, "quadrant " << q << " channel " << c << ": GPU " << g << " reference " << r);
		}
	}
	CHECK(std::fabs(means[0][0].r - means[0][1].r) > 0.05f * std::max(means[0][0].r, means[0][1].r));
	std::filesystem::remove_all(dir);
}

// A 100 m plane tiled 64 x 64 times with a 16 x 16 one-texel black and white checker (unshaded),
// seen from 1 m above it, looking 10 degrees down: towards the horizon each pixel covers many texels.
static String checker_plane_scene(int p_texture_filter) {
	return vformat(R"([gd_scene format=3 uid="uid://bmipplane%d"]

[ext_resource type="Texture2D" path="res://checker.png" id="1_c"]

[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_c"]
shading_mode = 0
albedo_texture = ExtResource("1_c")
uv1_scale = Vector3(64, 64, 1)
texture_filter = %d

[sub_resource type="PlaneMesh" id="PlaneMesh_c"]
material = SubResource("StandardMaterial3D_c")
size = Vector2(100, 100)

[node name="Root" type="Node3D"]

[node name="Plane" type="MeshInstance3D" parent="."]
mesh = SubResource("PlaneMesh_c")

[node name="Camera3D" type="Camera3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 0.984808, 0.173648, 0, -0.173648, 0.984808, 0, 1, 0)
)",
			p_texture_filter, p_texture_filter);
}

// Rows p_row0..p_row1 - 1 of the green channel: the RMS deviation from p_value and the mean.
static void band_stats(const Image &p_image, int p_row0, int p_row1, float p_value, double &r_rms, double &r_mean) {
	double sq = 0.0, sum = 0.0;
	int n = 0;
	for (int y = p_row0; y < p_row1; y++) {
		for (int x = 0; x < p_image.get_width(); x++) {
			const double g = p_image.get_pixel(x, y).g;
			sq += (g - p_value) * (g - p_value);
			sum += g;
			n++;
		}
	}
	r_rms = std::sqrt(sq / n);
	r_mean = sum / n;
}

TEST_CASE("[CLI][Render] mipmaps: a receding checkerboard aliases less, averages in linear space, and the reference agrees") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_texmips_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	std::vector<uint8_t> checker(16 * 16 * 4, 255);
	for (int i = 0; i < 16 * 16; i++) {
		const uint8_t v = ((i % 16) + (i / 16)) % 2 ? 255 : 0;
		checker[i * 4 + 0] = checker[i * 4 + 1] = checker[i * 4 + 2] = v;
	}
	REQUIRE(PNGWriter::save_rgba8(checker, 16, 16, (dir / "checker.png").string()));
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	std::ofstream(dir / "linear.tscn") << checker_plane_scene(1); // TEXTURE_FILTER_LINEAR: no mipmaps.
	std::ofstream(dir / "mipmaps.tscn") << checker_plane_scene(3); // TEXTURE_FILTER_LINEAR_WITH_MIPMAPS.
	Image images[3]; // GPU linear, GPU mipmaps, reference mipmaps.
	const char *names[3] = { "linear", "mipmaps", "mipmaps_ref" };
	for (int i = 0; i < 3; i++) {
		const String scene = (dir / (i == 0 ? "linear.tscn" : "mipmaps.tscn")).string();
		const String out = (dir / (String(names[i]) + ".exr").c_str()).string();
		const String cmd = i < 2 ? "render '" + scene + "' --width 128 --height 64 -o '" + out + "'" : "reference '" + scene + "' --width 128 --height 64 --shadows off -o '" + out + "'";
		REQUIRE(run_cli(cmd) == 0);
		String error;
		REQUIRE_MESSAGE(ImageLoaderEXR::load(out, images[i], &error), error);
		REQUIRE(images[i].get_width() == 128);
	}
	// The horizon is at row 24.6 (tan 10 deg / tan 37.5 deg above the centre); in rows 26..38 every pixel
	// covers four or more texels, whose box-filtered truth is linear 0.5 (the checker's mean: sRGB 0 and 1).
	double rms[3], mean[3];
	for (int i = 0; i < 3; i++) {
		band_stats(images[i], 26, 39, 0.5f, rms[i], mean[i]);
	}
	MESSAGE("far band RMS from 0.5: linear " << rms[0] << ", mipmaps " << rms[1] << ", reference " << rms[2] << "; means " << mean[0] << " " << mean[1] << " " << mean[2]);
	CHECK(rms[0] > 0.2); // Without mipmaps the far rows alias (each pixel reads one or two texels).
	CHECK(rms[1] < 0.02); // With them the far rows are the flat mean.
	CHECK(rms[1] < 0.1 * rms[0]);
	CHECK(std::fabs(mean[1] - 0.5) < 0.01); // Averaged in linear space (sRGB-space levels would give 0.214).
	CHECK(rms[2] < 0.02);
	CHECK(std::fabs(mean[2] - mean[1]) < 0.01);
	// Rows 26..63 (far band, the transition between levels, the magnified foreground): the reference's
	// ray differentials pick the GPU's levels (row means within 0.04; both sample the same texels).
	double worst = 0.0;
	for (int y = 26; y < 64; y++) {
		double r_gpu, r_ref, m_gpu, m_ref;
		band_stats(images[1], y, y + 1, 0.5f, r_gpu, m_gpu);
		band_stats(images[2], y, y + 1, 0.5f, r_ref, m_ref);
		worst = std::max(worst, std::fabs(m_gpu - m_ref));
	}
	MESSAGE("largest row-mean difference GPU vs reference: " << worst);
	CHECK(worst < 0.04);
	std::filesystem::remove_all(dir);
}

} // namespace TestSceneTextures
