/**************************************************************************/
/*  test_light_3d_gizmo.cpp                                               */
/**************************************************************************/
/* Light3DGizmoPlugin (area, omni, spot) and the gizmo overlay: redraw    */
/* geometry, handle drags through a real camera ray, cancel, undo/redo,   */
/* clamping and snapping; overlay pixels where the outline projects and   */
/* none from behind the camera. Dummy RenderingServer (no GPU).           */

#include "editor/gizmo_overlay.h"
#include "editor/plugins/gizmos/light_3d_gizmo_plugin.h"

#include "scene/3d/camera_3d.h"
#include "scene/3d/light_3d.h"
#include "scene/main/scene_tree.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestLight3DGizmo {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

static const int SIZE = 64;

// A 64x64 tree with a camera at (0, 0, 5) looking down -Z.
struct GizmoScene {
	DummyServer server;
	SceneTree *tree = nullptr;
	Camera3D *camera = nullptr;
	Ref<Light3DGizmoPlugin> plugin;

	GizmoScene() {
		tree = new SceneTree;
		tree->set_size(SIZE, SIZE);
		camera = new Camera3D;
		camera->set_position(Vector3(0, 0, 5));
		tree->get_root()->add_child(camera);
		plugin.instantiate();
	}
	template <class T>
	T *add(T *p_node) {
		tree->get_root()->add_child(p_node);
		return p_node;
	}
	// The screen point of p_local in p_node's space.
	Vector2 screen_of(const Node3D *p_node, const Vector3 &p_local) const {
		Vector2 point;
		const bool ok = EditorNode3DGizmoPlugin::project_to_screen(camera, p_node->get_global_transform().xform(p_local), Vector2(SIZE, SIZE), point);
		REQUIRE_MESSAGE(ok, "the test point is in front of the camera");
		return point;
	}
	~GizmoScene() {
		plugin->get_undo_redo()->clear_history();
		plugin.unref();
		delete tree;
	}
};

static bool has_point(const std::vector<Vector3> &p_points, const Vector3 &p_p) {
	for (const Vector3 &q : p_points) {
		if (q.is_equal_approx(p_p)) {
			return true;
		}
	}
	return false;
}

static int count_lit(const Image &p_image, int p_x0, int p_y0, int p_x1, int p_y1) {
	int n = 0;
	for (int y = std::max(p_y0, 0); y <= std::min(p_y1, p_image.get_height() - 1); y++) {
		for (int x = std::max(p_x0, 0); x <= std::min(p_x1, p_image.get_width() - 1); x++) {
			const Color c = p_image.get_pixel(x, y);
			if (c.r > 0.01f || c.g > 0.01f || c.b > 0.01f) {
				n++;
			}
		}
	}
	return n;
}

TEST_CASE("[AreaLight3D][Gizmo] redraw: outline always, range box and two handles when selected") {
	GizmoScene s;
	AreaLight3D *light = s.add(new AreaLight3D);
	light->set_area_size(Vector2(2, 1));
	light->set_param(Light3D::PARAM_RANGE, 3.0f);
	light->set_color(Color(1, 0.5f, 0.25f));
	REQUIRE(s.plugin->has_gizmo(light));
	Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(light);
	REQUIRE(gizmo.is_valid());

	gizmo->redraw();
	REQUIRE(gizmo->get_lines().size() == 1);
	const std::vector<Vector3> &outline = gizmo->get_lines()[0].points;
	CHECK_MESSAGE(outline.size() == 8, "the outline is 4 segments");
	for (const Vector3 &corner : { Vector3(-1, 0.5, 0), Vector3(1, 0.5, 0), Vector3(1, -0.5, 0), Vector3(-1, -0.5, 0) }) {
		CHECK_MESSAGE(has_point(outline, corner), "each corner (±a/2, ±b/2, 0) is in the outline");
	}
	for (const Vector3 &p : outline) {
		CHECK(std::fabs(p.x) == doctest::Approx(1.0));
		CHECK(std::fabs(p.y) == doctest::Approx(0.5));
		CHECK(p.z == doctest::Approx(0.0));
	}
	CHECK_MESSAGE(gizmo->get_lines()[0].modulate.is_equal_approx(Color(1, 0.5f, 0.25f, 1)), "lines are tinted by the light colour");
	CHECK(gizmo->get_handles().empty());
	REQUIRE(gizmo->get_billboards().size() == 1);
	CHECK(gizmo->get_billboards()[0].material->icon_path == Light3DGizmoPlugin::ICON_AREA);

	gizmo->set_selected(true);
	gizmo->redraw();
	REQUIRE(gizmo->get_lines().size() == 2);
	const std::vector<Vector3> &box = gizmo->get_lines()[1].points;
	CHECK(box.size() == 24);
	// (a + 2r) x (b + 2r) x r in front: x = ±4, y = ±3.5, z in {0, -3}.
	CHECK(has_point(box, Vector3(4, 3.5, 0)));
	CHECK(has_point(box, Vector3(-4, -3.5, -3)));
	for (const Vector3 &p : box) {
		CHECK((p.z == doctest::Approx(0.0) || p.z == doctest::Approx(-3.0)));
	}
	Vector3 h;
	REQUIRE(gizmo->get_handle_position(Light3DGizmoPlugin::HANDLE_AREA_WIDTH, false, h));
	CHECK(h.is_equal_approx(Vector3(1, 0, 0)));
	REQUIRE(gizmo->get_handle_position(Light3DGizmoPlugin::HANDLE_AREA_HEIGHT, false, h));
	CHECK(h.is_equal_approx(Vector3(0, 0.5, 0)));
	CHECK(gizmo->get_handle_name(0) == "Width");
	CHECK(gizmo->get_handle_name(1) == "Height");
	CHECK(Vector2(gizmo->get_handle_value(0)).is_equal_approx(Vector2(2, 1)));
}

TEST_CASE("[AreaLight3D][Gizmo] the outline is drawn as the area_shape; sphere and tube bounds all around") {
	GizmoScene s;
	AreaLight3D *light = s.add(new AreaLight3D);
	light->set_param(Light3D::PARAM_RANGE, 3.0f);
	Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(light);
	REQUIRE(gizmo.is_valid());

	// Disk 2 x 1: an ellipse of semi-axes 1 and 0.5 in the XY plane.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_DISK);
	light->set_area_size(Vector2(2, 1));
	gizmo->redraw();
	REQUIRE(gizmo->get_lines().size() == 1);
	const std::vector<Vector3> disk = gizmo->get_lines()[0].points;
	CHECK(disk.size() == 64);
	for (const Vector3 &p : disk) {
		CHECK(p.x * p.x + 4.0f * p.y * p.y == doctest::Approx(1.0).epsilon(1e-4));
		CHECK(p.z == doctest::Approx(0.0));
	}
	CHECK(has_point(disk, Vector3(1, 0, 0)));

	// Sphere of diameter 2: three great circles of radius 1; one handle (its diameter).
	light->set_area_shape(AreaLight3D::AREA_SHAPE_SPHERE);
	gizmo->set_selected(true);
	gizmo->redraw();
	REQUIRE(gizmo->get_lines().size() == 2);
	const std::vector<Vector3> sphere = gizmo->get_lines()[0].points;
	CHECK(sphere.size() == 3 * 64);
	for (const Vector3 &p : sphere) {
		CHECK(p.length() == doctest::Approx(1.0).epsilon(1e-4));
	}
	// The bound: the cube of half side 1 + 3 around the centre, in front of and behind the light.
	const std::vector<Vector3> &bound = gizmo->get_lines()[1].points;
	CHECK(bound.size() == 24);
	CHECK(has_point(bound, Vector3(4, 4, 4)));
	CHECK(has_point(bound, Vector3(-4, -4, -4)));
	CHECK(gizmo->get_handles().size() == 1);
	CHECK(gizmo->get_handle_name(Light3DGizmoPlugin::HANDLE_AREA_WIDTH) == "Diameter");

	// Tube: segment 2 along X, diameter 1: every outline point is on the capsule's surface.
	light->set_area_shape(AreaLight3D::AREA_SHAPE_TUBE);
	gizmo->redraw();
	const std::vector<Vector3> tube = gizmo->get_lines()[0].points;
	CHECK(tube.size() == 2 * 2 * (24 + 12 + 12) + 8);
	for (const Vector3 &p : tube) {
		const float ax = std::max(std::fabs(p.x) - 1.0f, 0.0f);
		CHECK(std::sqrt(ax * ax + p.y * p.y + p.z * p.z) == doctest::Approx(0.5).epsilon(1e-4));
	}
	CHECK(gizmo->get_handle_name(Light3DGizmoPlugin::HANDLE_AREA_WIDTH) == "Length");
	CHECK(gizmo->get_handle_name(Light3DGizmoPlugin::HANDLE_AREA_HEIGHT) == "Diameter");
	CHECK(has_point(gizmo->get_lines()[1].points, Vector3(-4.5f, -3.5f, -3.5f)));
}

TEST_CASE("[AreaLight3D][Gizmo] a handle drag follows the camera ray into light space") {
	GizmoScene s;
	AreaLight3D *light = s.add(new AreaLight3D);
	light->set_area_size(Vector2(2, 1));
	// A rotated, moved light, so the drag really goes through the inverse global transform.
	light->set_position(Vector3(0.5, 0.3, -1));
	light->set_rotation(Vector3(0.3, 0.5, 0.2));
	Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(light);
	gizmo->set_selected(true);

	SUBCASE("width") {
		gizmo->set_handle(0, false, s.camera, s.screen_of(light, Vector3(1.5, 0.2, 0)));
		CHECK(light->get_area_size().x == doctest::Approx(3.0).epsilon(1e-3));
		CHECK(light->get_area_size().y == doctest::Approx(1.0));
	}
	SUBCASE("height") {
		gizmo->set_handle(1, false, s.camera, s.screen_of(light, Vector3(-0.3, 0.8, 0)));
		CHECK(light->get_area_size().x == doctest::Approx(2.0));
		CHECK(light->get_area_size().y == doctest::Approx(1.6).epsilon(1e-3));
	}
	SUBCASE("negative drags clamp to zero") {
		gizmo->set_handle(0, false, s.camera, s.screen_of(light, Vector3(-0.7, 0, 0)));
		CHECK(light->get_area_size().x == 0.0f);
		gizmo->set_handle(1, false, s.camera, s.screen_of(light, Vector3(0, -2, 0)));
		CHECK(light->get_area_size().y == 0.0f);
	}
	SUBCASE("snapping rounds the size to the translate step") {
		s.plugin->set_snap_enabled(true);
		s.plugin->set_translate_snap(0.5);
		gizmo->set_handle(0, false, s.camera, s.screen_of(light, Vector3(0.6, 0, 0)));
		CHECK(light->get_area_size().x == doctest::Approx(1.0)); // 1.2 snapped to 0.5 steps.
	}
	SUBCASE("the redrawn handle sits under the cursor") {
		const Vector2 target = s.screen_of(light, Vector3(1.25, 0, 0));
		gizmo->set_handle(0, false, s.camera, target);
		gizmo->redraw();
		Vector3 h;
		REQUIRE(gizmo->get_handle_position(0, false, h));
		const Vector2 shown = s.screen_of(light, h);
		CHECK((shown - target).length() < 0.01f);
	}
}

TEST_CASE("[AreaLight3D][Gizmo] commit_handle: cancel restores; commit records one undoable action") {
	GizmoScene s;
	AreaLight3D *light = s.add(new AreaLight3D);
	light->set_area_size(Vector2(2, 1));
	Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(light);
	gizmo->set_selected(true);
	UndoRedo *ur = s.plugin->get_undo_redo();

	const Variant restore = gizmo->get_handle_value(0);
	gizmo->set_handle(0, false, s.camera, s.screen_of(light, Vector3(1.5, 0, 0)));
	REQUIRE(light->get_area_size().x == doctest::Approx(3.0).epsilon(1e-3));

	SUBCASE("cancel") {
		gizmo->commit_handle(0, false, restore, true);
		CHECK(light->get_area_size() == Vector2(2, 1));
		CHECK_MESSAGE(ur->get_history_count() == 0, "a cancelled drag leaves no history");
	}
	SUBCASE("commit, undo, redo") {
		gizmo->commit_handle(0, false, restore, false);
		const Vector2 dragged = light->get_area_size();
		CHECK(dragged.x == doctest::Approx(3.0).epsilon(1e-3));
		REQUIRE(ur->get_history_count() == 1);
		CHECK(ur->get_current_action_name() == "Change Area Light Size");
		REQUIRE(ur->undo());
		CHECK(light->get_area_size() == Vector2(2, 1));
		REQUIRE(ur->redo());
		CHECK(light->get_area_size() == dragged);
	}
	SUBCASE("an external history is used when set") {
		UndoRedo editor_history;
		s.plugin->set_undo_redo(&editor_history);
		gizmo->commit_handle(0, false, restore, false);
		CHECK(editor_history.get_history_count() == 1);
		CHECK(ur->get_history_count() == 0);
		editor_history.undo();
		CHECK(light->get_area_size() == Vector2(2, 1));
		s.plugin->set_undo_redo(nullptr);
	}
	SUBCASE("a wrong restore type is rejected") {
		ErrorCatcher errors;
		gizmo->commit_handle(0, false, Variant(1.0), false);
		CHECK(errors.contains("Vector2"));
		CHECK(ur->get_history_count() == 0);
	}
}

TEST_CASE("[Light3D][Gizmo] omni and spot handles: positions, drags and undo") {
	GizmoScene s;
	SUBCASE("omni range") {
		OmniLight3D *omni = s.add(new OmniLight3D);
		omni->set_param(Light3D::PARAM_RANGE, 1.0f);
		Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(omni);
		gizmo->set_selected(true);
		gizmo->redraw();
		Vector3 h;
		REQUIRE(gizmo->get_handle_position(0, false, h));
		CHECK(h.is_equal_approx(Vector3(1, 0, 0)));
		CHECK(gizmo->get_handles()[0].billboard);
		// The camera looks down -Z, so its right axis is +X: drag to 2 m right of the light.
		const Variant restore = gizmo->get_handle_value(0);
		gizmo->set_handle(0, false, s.camera, s.screen_of(omni, Vector3(2, 0, 0)));
		CHECK(omni->get_param(Light3D::PARAM_RANGE) == doctest::Approx(2.0).epsilon(1e-3));
		gizmo->commit_handle(0, false, restore, false);
		s.plugin->get_undo_redo()->undo();
		CHECK(omni->get_param(Light3D::PARAM_RANGE) == doctest::Approx(1.0));
	}
	SUBCASE("spot range and angle") {
		SpotLight3D *spot = s.add(new SpotLight3D);
		spot->set_position(Vector3(0, 0, -1));
		spot->set_rotation(Vector3(real_t(Math::PI / 2), 0, 0)); // Shines up (+Y); its XZ plane faces the camera.
		spot->set_param(Light3D::PARAM_RANGE, 2.0f);
		spot->set_param(Light3D::PARAM_SPOT_ANGLE, 30.0f);
		Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(spot);
		gizmo->set_selected(true);
		gizmo->redraw();
		Vector3 h;
		REQUIRE(gizmo->get_handle_position(0, false, h));
		CHECK(h.is_equal_approx(Vector3(0, 0, -2)));
		REQUIRE(gizmo->get_handle_position(1, false, h));
		CHECK(h.is_equal_approx(Vector3(1, 0, -std::sqrt(3.0f))));

		gizmo->set_handle(0, false, s.camera, s.screen_of(spot, Vector3(0, 0, -3)));
		CHECK(spot->get_param(Light3D::PARAM_RANGE) == doctest::Approx(3.0).epsilon(1e-3));
		// The aperture handle slides on the arc of radius `range` (now 3) in the light's XZ plane.
		const real_t c45 = 3 * std::sqrt(0.5f);
		gizmo->set_handle(1, false, s.camera, s.screen_of(spot, Vector3(c45, 0, -c45)));
		CHECK(spot->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(45.0).epsilon(1e-2));
		gizmo->commit_handle(1, false, Variant(30.0), true);
		CHECK(spot->get_param(Light3D::PARAM_SPOT_ANGLE) == doctest::Approx(30.0));
	}
}

TEST_CASE("[AreaLight3D][Gizmo] the overlay draws the projected outline and nothing from behind the camera") {
	GizmoScene s;
	Image image(SIZE, SIZE, Color(0, 0, 0, 1));

	SUBCASE("outline pixels") {
		AreaLight3D *light = s.add(new AreaLight3D);
		light->set_area_size(Vector2(4, 2));
		light->set_param(Light3D::PARAM_RANGE, 0.5f);
		CHECK(GizmoOverlay::draw(image, *s.tree, false) == 1);
		CHECK(image.is_finite());
		// Top edge of the rectangle: from (-2, 1, 0) to (2, 1, 0). Check near a point a quarter along it
		// (away from the icon at the centre).
		const Vector2 p = s.screen_of(light, Vector3(-1, 1, 0));
		CHECK_MESSAGE(count_lit(image, int(p.x) - 1, int(p.y) - 1, int(p.x) + 1, int(p.y) + 1) > 0, "the top edge is drawn where it projects");
		const Vector2 q = s.screen_of(light, Vector3(2, 0.5, 0));
		CHECK_MESSAGE(count_lit(image, int(q.x) - 1, int(q.y) - 1, int(q.x) + 1, int(q.y) + 1) > 0, "the right edge is drawn where it projects");
		// Inside the rectangle, between the outline and the icon, nothing is drawn.
		const Vector2 in = s.screen_of(light, Vector3(-1.4, 0.5, 0));
		CHECK(count_lit(image, int(in.x), int(in.y), int(in.x), int(in.y)) == 0);
		// The corners of the image stay black.
		CHECK(count_lit(image, 0, 0, 3, 3) == 0);
		CHECK(count_lit(image, SIZE - 4, SIZE - 4, SIZE - 1, SIZE - 1) == 0);
		// The icon covers the projected origin.
		const Vector2 o = s.screen_of(light, Vector3());
		CHECK(count_lit(image, int(o.x) - 2, int(o.y) - 2, int(o.x) + 2, int(o.y) + 2) > 0);
	}
	SUBCASE("selected: handles are drawn as squares") {
		AreaLight3D *light = s.add(new AreaLight3D);
		light->set_area_size(Vector2(4, 2));
		light->set_param(Light3D::PARAM_RANGE, 0.5f);
		CHECK(GizmoOverlay::draw(image, *s.tree, true) == 1);
		const Vector2 h = s.screen_of(light, Vector3(2, 0, 0));
		const Color c = image.get_pixel(int(h.x), int(h.y));
		CHECK_MESSAGE(c.r > 0.9f, "the handle centre is filled white");
	}
	SUBCASE("a light behind the camera draws nothing") {
		AreaLight3D *light = s.add(new AreaLight3D);
		light->set_area_size(Vector2(4, 4));
		light->set_position(Vector3(0, 0, 8)); // 3 m behind the camera.
		CHECK(GizmoOverlay::draw(image, *s.tree, true) == 1);
		CHECK(count_lit(image, 0, 0, SIZE - 1, SIZE - 1) == 0);
	}
	SUBCASE("lines crossing the camera plane are clipped, not mirrored") {
		// A large horizontal rectangle 1 m below the eye, reaching from 10 m in front to 10 m behind.
		AreaLight3D *light = s.add(new AreaLight3D);
		light->set_area_size(Vector2(4, 20));
		light->set_position(Vector3(0, -1, 5));
		light->set_rotation(Vector3(real_t(-Math::PI / 2), 0, 0)); // Local +Y -> world -Z, facing down.
		CHECK(GizmoOverlay::draw(image, *s.tree, true) == 1);
		CHECK_MESSAGE(count_lit(image, 0, SIZE / 2 + 1, SIZE - 1, SIZE - 1) > 0, "the floor-level outline is visible below the horizon");
		CHECK_MESSAGE(count_lit(image, 0, 0, SIZE - 1, SIZE / 2 - 2) == 0, "no mirrored segment from behind the camera shows above the horizon");
	}
}

TEST_CASE("[Gizmo] bad input is reported, not fatal") {
	GizmoScene s;
	ErrorCatcher errors;
	Image empty;
	CHECK(GizmoOverlay::draw(empty, *s.tree) == -1);
	Image image(8, 8);
	CHECK(GizmoOverlay::draw(image, nullptr, s.camera) == -1);
	AreaLight3D *light = s.add(new AreaLight3D);
	Ref<EditorNode3DGizmo> gizmo = s.plugin->create_gizmo(light);
	gizmo->set_handle(0, false, nullptr, Vector2(1, 1));
	CHECK(errors.contains("camera is null"));
	CHECK(light->get_area_size() == Vector2(1, 1));
	Node3D *plain = s.add(new Node3D);
	CHECK(s.plugin->create_gizmo(plain).is_null());
	CHECK(s.plugin->get_material("no_such_material").is_null());
	CHECK(errors.contains("no_such_material"));
}

} // namespace TestLight3DGizmo

namespace TestLight3DGizmo {

// The few SVG elements our icons use: rect, circle, polygon (absolute coordinates, no transforms).
static float svg_attr(const String &p_tag, const String &p_name, float p_default = 0) {
	const String key = " " + p_name + "=\"";
	const size_t at = p_tag.find(key);
	return at == String::npos ? p_default : std::stof(p_tag.substr(at + key.size()));
}

static bool svg_covers(const String &p_svg, float p_u, float p_v) {
	size_t pos = 0;
	while ((pos = p_svg.find('<', pos)) != String::npos) {
		const size_t end = p_svg.find('>', pos);
		const String tag = p_svg.substr(pos, end - pos);
		pos = end;
		if (tag.rfind("<rect", 0) == 0) {
			const float x = svg_attr(tag, "x"), y = svg_attr(tag, "y"), w = svg_attr(tag, "width"), h = svg_attr(tag, "height");
			if (p_u >= x && p_u <= x + w && p_v >= y && p_v <= y + h) {
				return true;
			}
		} else if (tag.rfind("<circle", 0) == 0) {
			const float cx = svg_attr(tag, "cx"), cy = svg_attr(tag, "cy"), r = svg_attr(tag, "r");
			if ((p_u - cx) * (p_u - cx) + (p_v - cy) * (p_v - cy) <= r * r) {
				return true;
			}
		} else if (tag.rfind("<polygon", 0) == 0) {
			const size_t at = tag.find("points=\"") + 8;
			std::vector<float> v;
			for (const String &pair : string_split(tag.substr(at, tag.find('"', at) - at), ' ', false)) {
				for (const String &n : string_split(pair, ',', false)) {
					v.push_back(std::stof(n));
				}
			}
			// Even-odd crossing test.
			bool inside = false;
			const int n = int(v.size() / 2);
			for (int i = 0, j = n - 1; i < n; j = i++) {
				const float xi = v[2 * i], yi = v[2 * i + 1], xj = v[2 * j], yj = v[2 * j + 1];
				if ((yi > p_v) != (yj > p_v) && p_u < (xj - xi) * (p_v - yi) / (yj - yi) + xi) {
					inside = !inside;
				}
			}
			if (inside) {
				return true;
			}
		}
	}
	return false;
}

TEST_CASE("[Gizmo] the overlay's icon shapes match the SVG files") {
	for (const char *icon : { Light3DGizmoPlugin::ICON_AREA, Light3DGizmoPlugin::ICON_OMNI, Light3DGizmoPlugin::ICON_SPOT, Light3DGizmoPlugin::ICON_DIRECTIONAL }) {
		const String path = String(GODOT_AREA_ROOT) + "/" + icon;
		FILE *f = fopen(path.c_str(), "rb");
		REQUIRE_MESSAGE(f != nullptr, "the icon file exists: " << path);
		String svg;
		char buf[4096];
		size_t n;
		while ((n = fread(buf, 1, sizeof(buf), f)) > 0) {
			svg.append(buf, n);
		}
		fclose(f);
		CHECK(svg.find("viewBox=\"0 0 32 32\"") != String::npos);
		int mismatches = 0, covered = 0;
		// Sample points off the integer grid, so no sample lies exactly on a shape edge.
		for (int j = 0; j < 64; j++) {
			for (int i = 0; i < 64; i++) {
				const float u = (i + 0.37f) * 0.5f, v = (j + 0.61f) * 0.5f;
				const bool in_svg = svg_covers(svg, u, v);
				covered += in_svg;
				mismatches += in_svg != GizmoOverlay::icon_covers(icon, u, v);
			}
		}
		CHECK_MESSAGE(mismatches == 0, icon << ": the glyph table and the SVG cover the same points");
		CHECK_MESSAGE(covered > 200, icon << ": the icon is not empty");
	}
}

} // namespace TestLight3DGizmo
