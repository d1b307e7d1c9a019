/**************************************************************************/
/*  test_editor_resource_preview.cpp                                      */
/**************************************************************************/
/* EditorResourcePreview (headless): the inspector's texture thumbnail    */
/* (size, aspect, box filter in linear light, alpha over the checker),    */
/* the one-line description of a resource row, loading a typed path for a */
/* resource row, and the inspector refusing a resource of the wrong      */
/* class. Dummy RenderingServer (no GPU).                                 */

#include "core/math/color.h"
#include "core/object/undo_redo.h"
#include "drivers/png/png_writer.h"
#include "editor/editor_inspector.h"
#include "editor/editor_resource_preview.h"
#include "scene/3d/light_3d.h"
#include "scene/resources/material.h"
#include "scene/resources/texture.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace TestEditorResourcePreview {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

TEST_CASE("[EditorResourcePreview] thumbnails keep the aspect ratio within the size, enlarging small images") {
	struct Case {
		int w, h, max, tw, th;
	} cases[] = {
		{ 256, 128, 64, 64, 32 }, // Landscape: the width fills the box.
		{ 100, 300, 60, 20, 60 }, // Portrait.
		{ 2, 2, 64, 64, 64 }, // A 2x2 texture is shown large (nearest), not as two pixels.
		{ 1, 1000, 64, 1, 64 }, // At least one pixel a side.
		{ 64, 64, 64, 64, 64 }, // Same size: one texel per pixel.
	};
	for (const Case &c : cases) {
		CAPTURE(c.w);
		CAPTURE(c.h);
		const Image thumb = EditorResourcePreview::make_texture_thumbnail(Image(c.w, c.h, Color(0.5f, 0.5f, 0.5f, 1.0f)), c.max);
		CHECK(thumb.get_width() == c.tw);
		CHECK(thumb.get_height() == c.th);
	}
	CHECK(EditorResourcePreview::make_texture_thumbnail(Image(), 64).is_empty());
	CHECK(EditorResourcePreview::make_texture_thumbnail(Image(4, 4), 0).is_empty());
}

TEST_CASE("[EditorResourcePreview] a thumbnail pixel is the mean of its texels in linear light, laid over the checker by alpha") {
	// Black and white sRGB texels averaged into one pixel: 0.5 in linear light (an sRGB-space mean
	// would give 0.5 encoded, i.e. 0.214 linear: too dark).
	Image bw(2, 1);
	bw.set_pixel(0, 0, Color(0, 0, 0, 1));
	bw.set_pixel(1, 0, Color(1, 1, 1, 1));
	Image one = EditorResourcePreview::make_texture_thumbnail(bw, 1);
	REQUIRE(one.get_width() == 1);
	CHECK(one.get_pixel(0, 0).r == doctest::Approx(0.5f).epsilon(1e-6));
	CHECK(one.get_pixel(0, 0).a == 1.0f);

	// An opaque sRGB texel comes out as its linear value, and the thumbnail is opaque.
	const Color srgb(0.8f, 0.4f, 0.1f, 1.0f);
	Image solid = EditorResourcePreview::make_texture_thumbnail(Image(8, 8, srgb), 4);
	const Color lin = srgb.srgb_to_linear();
	CHECK(solid.get_pixel(3, 3).r == doctest::Approx(lin.r).epsilon(1e-5));
	CHECK(solid.get_pixel(3, 3).g == doctest::Approx(lin.g).epsilon(1e-5));
	CHECK(solid.get_pixel(3, 3).b == doctest::Approx(lin.b).epsilon(1e-5));

	// Transparent texels show the checkerboard (two greys in cells of CHECKER_CELL pixels); a
	// transparent texel's colour does not leak into the thumbnail.
	const int cell = EditorResourcePreview::CHECKER_CELL;
	Image clear = EditorResourcePreview::make_texture_thumbnail(Image(4 * cell, 4 * cell, Color(1, 0, 0, 0)), 4 * cell);
	const float light = Color::srgb_to_linear_channel(EditorResourcePreview::CHECKER_LIGHT);
	const float dark = Color::srgb_to_linear_channel(EditorResourcePreview::CHECKER_DARK);
	CHECK(clear.get_pixel(0, 0).r == doctest::Approx(light));
	CHECK(clear.get_pixel(cell, 0).r == doctest::Approx(dark));
	CHECK(clear.get_pixel(cell, cell).g == doctest::Approx(light));
	CHECK(clear.get_pixel(0, 0).g == clear.get_pixel(0, 0).r); // Grey: no red from the hidden colour.

	// Half-transparent white over the light cell: halfway between white and the grey, linearly.
	Image half = EditorResourcePreview::make_texture_thumbnail(Image(cell, cell, Color(1, 1, 1, 0.5f)), cell);
	CHECK(half.get_pixel(0, 0).r == doctest::Approx(0.5f + 0.5f * light).epsilon(1e-5));

	// Non-finite texels count as transparent: the thumbnail stays finite.
	Image bad(2, 2, Color(1, 1, 1, 1));
	bad.set_pixel(0, 0, Color(NAN, INFINITY, -1.0f, NAN));
	CHECK(EditorResourcePreview::make_texture_thumbnail(bad, 1).is_finite());
}

TEST_CASE("[EditorResourcePreview] a resource row says what it holds") {
	DummyServer server;
	CHECK(EditorResourcePreview::describe(Variant()) == "<empty>");
	Ref<ImageTexture> texture = ImageTexture::create_from_image(Image(256, 128));
	CHECK(EditorResourcePreview::describe(Variant(texture.ptr())) == "ImageTexture 256x128 (built-in)");
	texture->set_path("res://textures/tv.png");
	CHECK(EditorResourcePreview::describe(Variant(texture.ptr())) == "ImageTexture 256x128 res://textures/tv.png");
	Ref<StandardMaterial3D> material;
	material.instantiate();
	CHECK(EditorResourcePreview::describe(Variant(material.ptr())) == "StandardMaterial3D (built-in)");
}

TEST_CASE("[EditorResourcePreview] a typed path loads for a resource row; a missing file or a wrong type says why") {
	DummyServer server;
	const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_resource_row_" + std::to_string(getpid()));
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir / "textures");
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	std::vector<uint8_t> rgba(4 * 3 * 4, 255);
	REQUIRE(PNGWriter::save_rgba8(rgba, 4, 3, (dir / "textures" / "tv.png").string()));
	std::ofstream(dir / "textures" / "mat.tres") << "[gd_resource type=\"StandardMaterial3D\" format=3]\n\n[resource]\nroughness = 0.25\n";
	const String scene = (dir / "levels" / "room.tscn").string(); // res:// resolves against project.godot's folder.

	String error;
	Variant v = EditorResourcePreview::load_for_property("res://textures/tv.png", scene, "Texture2D", &error);
	REQUIRE_MESSAGE(v.get_object() != nullptr, error);
	const Texture2D *tex = Object::cast_to<Texture2D>(v.get_object());
	REQUIRE(tex != nullptr);
	CHECK(tex->get_width() == 4);
	CHECK(tex->get_height() == 3);
	CHECK(tex->get_path() == "res://textures/tv.png"); // Saved back as typed.

	error.clear();
	CHECK(EditorResourcePreview::load_for_property("res://textures/missing.png", scene, "Texture2D", &error).get_object() == nullptr);
	CHECK(error.find("missing.png") != String::npos);
	error.clear();
	CHECK(EditorResourcePreview::load_for_property("res://textures/mat.tres", scene, "Texture2D", &error).get_object() == nullptr);
	CHECK(error.find("StandardMaterial3D") != String::npos);
	CHECK(error.find("Texture2D") != String::npos);
	error.clear();
	CHECK(EditorResourcePreview::load_for_property("res://textures/notes.txt", scene, "Texture2D", &error).get_object() == nullptr);
	CHECK(error.find("notes.txt") != String::npos);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[EditorInspector] a resource row takes its hint's class: the wrong class is refused, null clears, undo restores") {
	DummyServer server;
	ErrorCatcher errors;
	AreaLight3D *light = new AreaLight3D;
	UndoRedo undo_redo;
	EditorInspector inspector;
	inspector.set_undo_redo(&undo_redo);
	inspector.edit(light);
	const int row = inspector.find_row("area_texture");
	REQUIRE(row >= 0);
	CHECK(inspector.get_row(row).type == Variant::OBJECT);
	CHECK(inspector.get_row(row).resource_type == "Texture2D");

	Ref<ImageTexture> texture = ImageTexture::create_from_image(Image(2, 2, Color(1, 0, 0, 1)));
	REQUIRE(inspector.set_row_value(row, Variant(texture.ptr())));
	CHECK(light->get_area_texture() == texture);
	CHECK(undo_redo.get_history_count() == 1);

	Ref<StandardMaterial3D> material;
	material.instantiate();
	errors.messages.clear();
	CHECK_FALSE(inspector.set_row_value(row, Variant(material.ptr())));
	CHECK(light->get_area_texture() == texture); // Kept.
	CHECK(undo_redo.get_history_count() == 1); // Nothing recorded.
	CHECK(inspector.get_last_error().find("Texture2D") != String::npos);
	CHECK(inspector.get_last_error().find("StandardMaterial3D") != String::npos);
	CHECK(errors.contains("area_texture"));

	REQUIRE(inspector.set_row_value(row, Variant())); // Clear.
	CHECK(light->get_area_texture().is_null());
	REQUIRE(undo_redo.undo());
	CHECK(light->get_area_texture() == texture);
	inspector.edit(nullptr);
	delete light;
}

} // namespace TestEditorResourcePreview
