/**************************************************************************/
/*  test_editor_icons.cpp                                                 */
/**************************************************************************/
/* EditorIcons (headless): every editor/icons/<name>.svg parses; class icons   */
/* fall back up the ClassDB inheritance chain; MissingNode shows its      */
/* placeholder; bad SVG input is an error naming the file and element.    */

#include "editor/editor_icons.h"

#include "core/object/class_db.h"
#include "scene/3d/light_3d.h"
#include "scene/main/missing_node.h"

#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>

namespace TestEditorIcons {

// A class of its own with no icon: it must show its nearest ancestor's (SpotLight3D's).
class IconTestSpot : public SpotLight3D {
	GDCLASS(IconTestSpot, SpotLight3D);
};

TEST_CASE("[EditorIcons] every icon in editor/icons parses into shapes") {
	std::vector<String> names = EditorIcons::get_icon_names();
	CHECK(names.size() >= 15);
	for (const String &name : names) {
		CAPTURE(name);
		const EditorIcon *icon = EditorIcons::get_icon(name);
		REQUIRE(icon != nullptr);
		CHECK(!icon->shapes.empty());
		CHECK(icon->view_size.x > 0);
	}
	const EditorIcon *area = EditorIcons::get_icon("AreaLight3D");
	REQUIRE(area);
	CHECK(area->view_size == Vector2(16, 16));
	REQUIRE(area->shapes.size() == 4);
	CHECK(area->shapes[0].type == EditorIconShape::RECT);
	CHECK(area->shapes[0].position == Vector2(2, 1));
	CHECK(area->shapes[0].size == Vector2(12, 7));
	CHECK(area->shapes[0].radius == doctest::Approx(1));
	CHECK(area->shapes[0].fill.r == doctest::Approx(0xfc / 255.0));
	CHECK(area->shapes[0].fill.g == doctest::Approx(0x7f / 255.0));
	const EditorIcon *node = EditorIcons::get_icon("Node");
	REQUIRE(node);
	REQUIRE(node->shapes.size() == 1);
	CHECK(node->shapes[0].type == EditorIconShape::CIRCLE);
	CHECK_FALSE(node->shapes[0].has_fill);
	CHECK(node->shapes[0].has_stroke);
	CHECK(node->shapes[0].stroke_width == doctest::Approx(2));
	CHECK(EditorIcons::get_icon("NoSuchIcon") == nullptr);
}

TEST_CASE("[EditorIcons] class icons fall back up the inheritance chain") {
	GDREGISTER_CLASS(IconTestSpot);
	// Own icons.
	CHECK(EditorIcons::get_class_icon_name("AreaLight3D") == "AreaLight3D");
	CHECK(EditorIcons::get_class_icon_name("OmniLight3D") == "OmniLight3D");
	CHECK(EditorIcons::get_class_icon_name("Node3D") == "Node3D");
	CHECK(EditorIcons::get_class_icon_name("Node") == "Node");
	// No icon of their own: the nearest ancestor's.
	REQUIRE_FALSE(EditorIcons::has_icon("Light3D"));
	REQUIRE_FALSE(EditorIcons::has_icon("VisualInstance3D"));
	CHECK(EditorIcons::get_class_icon_name("Light3D") == "Node3D");
	REQUIRE(ClassDB::class_exists("VisualInstance3D"));
	CHECK(EditorIcons::get_class_icon_name("VisualInstance3D") == "Node3D");
	CHECK(EditorIcons::get_class_icon_name("IconTestSpot") == "SpotLight3D");
	// Nothing on the way to Object, or an unknown class: the fallback.
	CHECK(EditorIcons::get_class_icon_name("Resource") == "Node");
	CHECK(EditorIcons::get_class_icon_name("NotAClass") == "Node");
	CHECK(EditorIcons::get_class_icon_name("NotAClass", "Node3D") == "Node3D");
	CHECK(EditorIcons::get_class_icon_name("NotAClass", "NoSuchIcon") == "");

	SceneTest::DummyServer server;
	IconTestSpot spot;
	CHECK(EditorIcons::get_object_icon_name(&spot) == "SpotLight3D");
	AreaLight3D area;
	CHECK(EditorIcons::get_object_icon_name(&area) == "AreaLight3D");
	CHECK(EditorIcons::get_object_icon_name(nullptr) == "Node");
}

TEST_CASE("[EditorIcons] a MissingNode shows the placeholder, not its original class's icon") {
	MissingNode missing;
	missing.set_original_class("AreaLight3D"); // A class we do have: still a placeholder.
	CHECK(EditorIcons::get_object_icon_name(&missing) == "MissingNode");
	missing.set_original_class("GPUParticles3D");
	CHECK(EditorIcons::get_object_icon_name(&missing) == "MissingNode");
	CHECK(EditorIcons::get_class_icon_name("MissingNode") == "MissingNode");
}

TEST_CASE("[EditorIcons] an AreaLight3D shows the icon of its area_shape") {
	SceneTest::DummyServer server;
	AreaLight3D area;
	const char *expected[] = { "AreaLight3D", "AreaLight3DDisk", "AreaLight3DSphere", "AreaLight3DTube" };
	std::vector<const EditorIcon *> icons;
	for (int shape = 0; shape < 4; shape++) {
		area.set_area_shape(AreaLight3D::AreaShape(shape));
		REQUIRE(int(area.get_area_shape()) == shape);
		const String name = EditorIcons::get_object_icon_name(&area);
		CHECK(name == expected[shape]);
		const EditorIcon *icon = EditorIcons::get_icon(name);
		REQUIRE(icon != nullptr);
		CHECK(icon->view_size == Vector2(16, 16));
		icons.push_back(icon);
	}
	// Four different drawings: the disk starts with its ellipse, the sphere with its ball, the tube
	// with its capsule (a rect rounded to half its height).
	CHECK(icons[1]->shapes[0].type == EditorIconShape::POLYGON);
	CHECK(icons[2]->shapes[0].type == EditorIconShape::CIRCLE);
	CHECK(icons[3]->shapes[0].type == EditorIconShape::RECT);
	CHECK(icons[3]->shapes[0].radius == doctest::Approx(icons[3]->shapes[0].size.y * 0.5f));
	// Back to the rectangle: the class icon again; the class itself keeps its one icon.
	area.set_area_shape(AreaLight3D::AREA_SHAPE_RECTANGLE);
	CHECK(EditorIcons::get_object_icon_name(&area) == "AreaLight3D");
	CHECK(EditorIcons::get_class_icon_name("AreaLight3D") == "AreaLight3D");
	// Other lights are unaffected.
	OmniLight3D omni;
	CHECK(EditorIcons::get_object_icon_name(&omni) == "OmniLight3D");
	SpotLight3D spot;
	CHECK(EditorIcons::get_object_icon_name(&spot) == "SpotLight3D");
}

TEST_CASE("[EditorIcons] bad SVG input is an error naming the file and the element") {
	EditorIcon icon;
	String error;
	const String head = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 16 16\">";
	CHECK(EditorIcons::parse_svg(head + "<circle cx=\"8\" cy=\"8\" r=\"3\" fill=\"#abc\"/></svg>", "ok.svg", icon, &error));
	REQUIRE(icon.shapes.size() == 1);
	CHECK(icon.shapes[0].fill.b == doctest::Approx(0xcc / 255.0));

	CHECK_FALSE(EditorIcons::parse_svg(head + "<path d=\"M0 0L1 1\"/></svg>", "bad_path.svg", icon, &error));
	CHECK(error.find("bad_path.svg") != String::npos);
	CHECK(error.find("<path>") != String::npos);
	CHECK(icon.shapes.empty());

	CHECK_FALSE(EditorIcons::parse_svg(head + "<rect x=\"1\" width=\"abc\" height=\"2\"/></svg>", "bad_width.svg", icon, &error));
	CHECK(error.find("width=\"abc\"") != String::npos);

	CHECK_FALSE(EditorIcons::parse_svg(head + "<rect width=\"2\" height=\"2\" fill=\"red\"/></svg>", "named_colour.svg", icon, &error));
	CHECK(error.find("fill=\"red\"") != String::npos);

	CHECK_FALSE(EditorIcons::parse_svg(head + "<rect width=\"2\" height=\"2\" transform=\"rotate(4)\"/></svg>", "transform.svg", icon, &error));
	CHECK(error.find("transform") != String::npos);

	CHECK_FALSE(EditorIcons::parse_svg(head + "<polygon points=\"1,1 2,2\"/></svg>", "short.svg", icon, &error));
	CHECK(error.find("three") != String::npos);

	CHECK_FALSE(EditorIcons::parse_svg("<rect width=\"2\" height=\"2\"/>", "no_svg.svg", icon, &error));
	CHECK(error.find("no_svg.svg") != String::npos);
}

} // namespace TestEditorIcons
