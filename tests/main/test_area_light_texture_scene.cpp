/**************************************************************************/
/*  test_area_light_texture_scene.cpp                                     */
/**************************************************************************/
/* Issue 21: an upstream-style scene (Godot 4 text conventions, written   */
/* by the test) whose AreaLight3D sets area_texture to a PNG with a red   */
/* half and a green half. It loads, keeps the property (and upstream's    */
/* values of the shared properties) through a save round trip, and both   */
/* the GPU and the Embree reference draw red light on the floor under the */
/* red half and green light under the green half.                         */

#include "core/io/image.h"
#include "drivers/png/png_writer.h"
#include "modules/openexr/image_loader_exr.h"
#include "scene/3d/light_3d.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/rendering_server_globals.h"
#include "servers/rendering/storage/light_storage.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace TestAreaLightTextureScene {

static int run_cli(const String &p_args) {
	String cmd = String("'") + GODOT_AREA_CLI_PATH + "' " + p_args + " > /dev/null 2>&1";
	int status = std::system(cmd.c_str());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// 16 x 8 texels: the left half (u < 0.5) red, the right half green.
static std::vector<uint8_t> split_texels() {
	std::vector<uint8_t> rgba(16 * 8 * 4);
	for (int y = 0; y < 8; y++) {
		for (int x = 0; x < 16; x++) {
			uint8_t *t = &rgba[(size_t(y) * 16 + x) * 4];
			t[0] = x < 8 ? 255 : 0;
			t[1] = x < 8 ? 0 : 255;
			t[2] = 0;
			t[3] = 255;
		}
	}
	return rgba;
}

// The light hangs 0.6 m above the floor facing down (local -Z to world -Y: rotated -90 degrees about X),
// so its local +X is world +X. Seen from the lit side the image is upright: u = 0 (the red half's left
// edge) is at the light's local +X, so red light falls on the floor at x > 0 and green at x < 0. The
// camera looks straight down from 3 m.
static const char *SCENE = R"TSCN([gd_scene load_steps=4 format=3 uid="uid://barealighttex1"]

[ext_resource type="Texture2D" uid="uid://dsplitredgreen1" path="res://textures/split.png" id="1_tex"]

[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_floor"]
albedo_color = Color(0.8, 0.8, 0.8, 1)
roughness = 1.0

[sub_resource type="PlaneMesh" id="PlaneMesh_floor"]
material = SubResource("StandardMaterial3D_floor")
size = Vector2(8, 8)

[node name="Root" type="Node3D"]

[node name="Floor" type="MeshInstance3D" parent="."]
mesh = SubResource("PlaneMesh_floor")

[node name="Screen" type="AreaLight3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 0.6, 0)
light_energy = 4.0
area_size = Vector2(2, 1)
area_texture = ExtResource("1_tex")
area_range = 10.0
area_attenuation = 2.0

[node name="Camera3D" type="Camera3D" parent="."]
transform = Transform3D(1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 3, 0)
)TSCN";

TEST_CASE("[AreaLight3D][Texture] an upstream-style scene with area_texture loads, round-trips and renders the texture's colours on the matching sides") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first");
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_areatex_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir / "textures");
	REQUIRE(PNGWriter::save_rgba8(split_texels(), 16, 8, (dir / "textures" / "split.png").string()));
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	std::ofstream(dir / "screen.tscn") << SCENE;
	const String scene = (dir / "screen.tscn").string();

	{
		// Load: the property and the shared properties hold the file's (and upstream's default) values.
		SceneTest::DummyServer server;
		String error;
		Node *root = ResourceFormatText::load_scene(scene, &error);
		REQUIRE_MESSAGE(root != nullptr, error);
		AreaLight3D *light = Object::cast_to<AreaLight3D>(root->get_node_or_null("Screen"));
		REQUIRE(light != nullptr);
		REQUIRE(light->get_area_texture().is_valid());
		CHECK(light->get_area_texture()->get_width() == 16);
		CHECK(RSG::light_storage->light_area_get_texture(light->get_light()) == light->get_area_texture()->get_rid());
		CHECK(light->get_area_size() == Vector2(2, 1));
		CHECK(light->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(4.0));
		CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.0));
		CHECK(light->get_param(Light3D::PARAM_SPECULAR) == doctest::Approx(1.0)); // Upstream's AreaLight3D default.
		CHECK(light->get_param(Light3D::PARAM_SIZE) == doctest::Approx(0.5));
		// Save: the texture stays an external resource; a default light saves no area_texture.
		const String saved = ResourceFormatText::save_scene_to_string(root);
		CHECK_MESSAGE(saved.find("area_texture = ExtResource(") != String::npos, saved);
		CHECK_MESSAGE(saved.find("res://textures/split.png") != String::npos, saved);
		AreaLight3D *plain = new AreaLight3D;
		plain->set_name("Plain");
		root->add_child(plain);
		CHECK(ResourceFormatText::save_scene_to_string(root).find("area_texture", saved.find("name=\"Plain\"")) == String::npos);
		std::ofstream(dir / "saved.tscn") << saved.c_str();
		delete root;
		Node *again = ResourceFormatText::load_scene((dir / "saved.tscn").string(), &error);
		REQUIRE_MESSAGE(again != nullptr, error);
		AreaLight3D *light2 = Object::cast_to<AreaLight3D>(again->get_node_or_null("Screen"));
		REQUIRE(light2 != nullptr);
		REQUIRE(light2->get_area_texture().is_valid());
		CHECK(light2->get_area_texture()->get_width() == 16);
		CHECK(light2->get_area_size() == Vector2(2, 1));
		CHECK(light2->get_param(Light3D::PARAM_SPECULAR) == doctest::Approx(1.0));
		CHECK(light2->get_param(Light3D::PARAM_SIZE) == doctest::Approx(0.5));
		CHECK(light2->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.0));
		delete again;
	}

	// Render: GPU (LTC, the default) and the reference.
	const String gpu = (dir / "gpu.exr").string(), ref = (dir / "ref.exr").string();
	CHECK(run_cli("render '" + scene + "' --width 48 --height 48 -o '" + gpu + "'") == 0);
	CHECK(run_cli("reference '" + scene + "' --width 48 --height 48 --spp 256 --shadows off -o '" + ref + "'") == 0);
	for (const String &out : { gpu, ref }) {
		Image image;
		String error;
		REQUIRE_MESSAGE(ImageLoaderEXR::load(out, image, &error), error);
		REQUIRE(image.get_width() == 48);
		// The camera looks down with -Z as screen-up: world +X is the right of the image.
		const Color right = image.get_pixel(36, 24), left = image.get_pixel(12, 24);
		CAPTURE(out);
		CAPTURE(right.r);
		CAPTURE(right.g);
		CAPTURE(left.r);
		CAPTURE(left.g);
		CHECK(right.r > 2.0f * right.g); // Under the red half.
		CHECK(left.g > 2.0f * left.r); // Under the green half.
		CHECK(right.b < 0.05f * right.r);
	}
	std::filesystem::remove_all(dir);
}

} // namespace TestAreaLightTextureScene
