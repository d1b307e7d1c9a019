/**************************************************************************/
/*  test_editor_inspector.cpp                                             */
/**************************************************************************/
/* EditorInspector (headless): rows made from AreaLight3D's ClassDB       */
/* property list (order, groups, labels, range and enum hints), rows that */
/* follow property-list changes, edits through UndoRedo (undo, redo,      */
/* merge), rejected values. Dummy RenderingServer (no GPU).               */

#include "editor/editor_inspector.h"

#include "core/object/undo_redo.h"
#include "scene/3d/light_3d.h"
#include "scene/resources/texture.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestEditorInspector {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

// A class with a subgroup, a read-only property and one outside its group's prefix.
class InspectorTestObject : public Object {
	GDCLASS(InspectorTestObject, Object);

	int outer_count = 1;
	double outer_inner_width = 0.5;
	int plain = 0;

protected:
	static void _bind_methods() {
		ClassDB::bind_method(D_METHOD("set_outer_count", "count"), &InspectorTestObject::set_outer_count);
		ClassDB::bind_method(D_METHOD("get_outer_count"), &InspectorTestObject::get_outer_count);
		ClassDB::bind_method(D_METHOD("set_outer_inner_width", "width"), &InspectorTestObject::set_outer_inner_width);
		ClassDB::bind_method(D_METHOD("get_outer_inner_width"), &InspectorTestObject::get_outer_inner_width);
		ClassDB::bind_method(D_METHOD("get_outer_total"), &InspectorTestObject::get_outer_total);
		ClassDB::bind_method(D_METHOD("set_plain", "value"), &InspectorTestObject::set_plain);
		ClassDB::bind_method(D_METHOD("get_plain"), &InspectorTestObject::get_plain);
		ADD_GROUP("Outer", "outer_");
		ADD_PROPERTY(PropertyInfo(Variant::INT, "outer_count", PROPERTY_HINT_FLAGS, "Red,Green,Blue:16"), "set_outer_count", "get_outer_count");
		ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "outer_total", PROPERTY_HINT_NONE, "", PROPERTY_USAGE_EDITOR), "", "get_outer_total");
		ADD_PROPERTY(PropertyInfo(Variant::INT, "plain", PROPERTY_HINT_ENUM, "Low:-1,Mid,High:10"), "set_plain", "get_plain");
		ADD_SUBGROUP("Inner", "outer_inner_");
		ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "outer_inner_width", PROPERTY_HINT_RANGE, "-90, 90, 0.5, or_less, radians_as_degrees"), "set_outer_inner_width", "get_outer_inner_width");
		ADD_GROUP("", "");
	}

public:
	void set_outer_count(int p_count) { outer_count = p_count; }
	int get_outer_count() const { return outer_count; }
	void set_outer_inner_width(double p_width) { outer_inner_width = p_width; }
	double get_outer_inner_width() const { return outer_inner_width; }
	double get_outer_total() const { return outer_count * outer_inner_width; }
	void set_plain(int p_value) { plain = p_value; }
	int get_plain() const { return plain; }
};

TEST_CASE("[EditorInspector] AreaLight3D rows follow its ClassDB property list, in order, with hints") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	EditorInspector inspector;
	inspector.edit(light);
	CHECK(inspector.get_edited_object() == light);

	// Every entry with EDITOR usage, in the order ClassDB gives, and nothing else.
	std::vector<PropertyInfo> list;
	ClassDB::get_property_list("AreaLight3D", &list, false, light);
	std::vector<String> expected;
	for (const PropertyInfo &pi : list) {
		if (!pi.is_group_marker() && (pi.usage & PROPERTY_USAGE_EDITOR)) {
			expected.push_back(pi.name);
		}
	}
	std::vector<String> got;
	for (int i = 0; i < inspector.get_row_count(); i++) {
		got.push_back(inspector.get_row(i).property);
	}
	CHECK(got == expected);
	CHECK(inspector.get_row_count() >= 10);

	// Hidden properties are not rows.
	CHECK(inspector.find_row("name") == -1);
	CHECK(inspector.find_row("light_projector") == -1); // Hidden on area lights (upstream: area_texture instead).
	CHECK(inspector.find_row("light_size") >= 0); // Shown on area lights, as upstream Godot 4.7 does.
	CHECK(inspector.find_row("shadow_bias") == -1); // Shadows are off.
	CHECK(inspector.find_row("area_shadow_mode") == -1);
	CHECK(inspector.find_row("no_such_property") == -1);

	const int size_row = inspector.find_row("area_size");
	REQUIRE(size_row >= 0);
	const EditorPropertyRow &size = inspector.get_row(size_row);
	CHECK(size.label == "Size");
	CHECK(size.group == "Area");
	CHECK(size.subgroup == "");
	CHECK(size.type == Variant::VECTOR2);
	CHECK(size.hint == PROPERTY_HINT_RANGE);
	CHECK(size.has_range);
	CHECK(size.range_min == doctest::Approx(0.0));
	CHECK(size.range_max == doctest::Approx(4096.0));
	CHECK(size.range_step == doctest::Approx(0.001));
	CHECK(size.or_greater);
	CHECK_FALSE(size.or_less);
	CHECK_FALSE(size.exp);
	CHECK(size.suffix == "m");
	CHECK_FALSE(size.read_only);
	CHECK(inspector.get_row_value(size_row) == Variant(Vector2(1, 1)));

	const EditorPropertyRow &range = inspector.get_row(inspector.find_row("area_range"));
	CHECK(range.exp);
	CHECK(range.label == "Range");

	const int method_row = inspector.find_row("area_shading_method");
	REQUIRE(method_row >= 0);
	const EditorPropertyRow &method = inspector.get_row(method_row);
	CHECK(method.label == "Shading Method");
	CHECK(method.type == Variant::INT);
	CHECK(method.hint == PROPERTY_HINT_ENUM);
	CHECK(method.enum_options == std::vector<String>({ "LTC", "LTC Polynomial", "MRP", "Stochastic", "Auto", "LTC 2-Lobe" }));
	REQUIRE(method.enum_values.size() == 6);
	// The values are the bound constants LTC..AUTO, then LTC_2LOBE (appended after AUTO).
	CHECK(method.enum_values[0] == ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_LTC"));
	CHECK(method.enum_values[4] == ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_AUTO"));
	CHECK(method.enum_values[4] == (int64_t)AreaLight3D::AREA_SHADING_AUTO);
	CHECK(method.enum_values[5] == ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_LTC_2LOBE"));

	const int color_row = inspector.find_row("light_color");
	REQUIRE(color_row >= 0);
	const EditorPropertyRow &color = inspector.get_row(color_row);
	CHECK(color.type == Variant::COLOR);
	CHECK(color.group == "Light");
	CHECK(color.label == "Color");
	CHECK(color.hint == PROPERTY_HINT_COLOR_NO_ALPHA);

	const EditorPropertyRow &energy = inspector.get_row(inspector.find_row("light_indirect_energy"));
	CHECK(energy.label == "Indirect Energy");
	CHECK(energy.type == Variant::FLOAT);

	const EditorPropertyRow &editor_only = inspector.get_row(inspector.find_row("editor_only"));
	CHECK(editor_only.group == "Editor");
	CHECK(editor_only.label == "Editor Only"); // Empty prefix: nothing stripped.

	// Groups come in the order of their markers: Light before Area.
	CHECK(inspector.find_row("light_color") < inspector.find_row("area_size"));

	inspector.edit(nullptr);
	CHECK(inspector.get_row_count() == 0);
	delete light;
}

TEST_CASE("[EditorInspector] Rows follow changes of the property list") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	UndoRedo undo_redo;
	EditorInspector inspector;
	inspector.set_undo_redo(&undo_redo);
	inspector.edit(light);
	CHECK_FALSE(inspector.refresh()); // Nothing changed.
	const int count_off = inspector.get_row_count();
	const uint64_t version = inspector.get_version();

	REQUIRE(inspector.set_row_value(inspector.find_row("shadow_enabled"), true));
	CHECK(inspector.refresh());
	CHECK(inspector.get_version() != version);
	CHECK(inspector.get_row_count() > count_off);
	CHECK(inspector.find_row("shadow_bias") >= 0);
	CHECK(inspector.find_row("area_shadow_mode") >= 0);
	CHECK(inspector.find_row("area_shadow_grid") >= 0); // FIXED mode shows the grid.
	CHECK(inspector.get_row(inspector.find_row("area_shadow_mode")).enum_options.size() == 4);

	// The grid only applies to FIXED: ADAPTIVE hides it.
	REQUIRE(inspector.set_row_value(inspector.find_row("area_shadow_mode"), (int64_t)AreaLight3D::AREA_SHADOW_ADAPTIVE));
	CHECK(inspector.refresh());
	CHECK(inspector.find_row("area_shadow_grid") == -1);
	CHECK(inspector.find_row("area_shadow_mode") >= 0);

	// Undo brings the grid row back.
	REQUIRE(undo_redo.undo());
	CHECK(inspector.refresh());
	CHECK(inspector.find_row("area_shadow_grid") >= 0);

	undo_redo.clear_history();
	delete light;
}

TEST_CASE("[EditorInspector] Editing a row sets the property; undo restores it; redo") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	UndoRedo undo_redo;
	EditorInspector inspector;
	inspector.set_undo_redo(&undo_redo);
	inspector.edit(light);

	const int size_row = inspector.find_row("area_size");
	REQUIRE(size_row >= 0);
	CHECK(inspector.set_row_value(size_row, Vector2(2, 0.5f)));
	CHECK(light->get_area_size().is_equal_approx(Vector2(2, 0.5f)));
	CHECK(inspector.get_row_value(size_row) == Variant(Vector2(2, 0.5f)));
	CHECK(undo_redo.get_history_count() == 1);
	CHECK(undo_redo.get_current_action_name() == "Set area_size");
	CHECK(inspector.get_last_error().empty());

	const int method_row = inspector.find_row("area_shading_method");
	CHECK(inspector.set_row_value(method_row, (int64_t)AreaLight3D::AREA_SHADING_AUTO));
	CHECK(light->get_area_shading_method() == AreaLight3D::AREA_SHADING_AUTO);

	const int color_row = inspector.find_row("light_color");
	CHECK(inspector.set_row_value(color_row, Color(1, 0.5f, 0.25f)));
	CHECK(light->get_color().is_equal_approx(Color(1, 0.5f, 0.25f)));
	CHECK(undo_redo.get_history_count() == 3);

	REQUIRE(undo_redo.undo());
	CHECK(light->get_color().is_equal_approx(Color(1, 1, 1)));
	REQUIRE(undo_redo.undo());
	CHECK(light->get_area_shading_method() == AreaLight3D::AREA_SHADING_LTC);
	REQUIRE(undo_redo.undo());
	CHECK(light->get_area_size().is_equal_approx(Vector2(1, 1)));
	CHECK_FALSE(undo_redo.has_undo());

	REQUIRE(undo_redo.redo());
	CHECK(light->get_area_size().is_equal_approx(Vector2(2, 0.5f)));
	REQUIRE(undo_redo.redo());
	CHECK(light->get_area_shading_method() == AreaLight3D::AREA_SHADING_AUTO);

	// An INT value for a FLOAT property converts, as Object::set does.
	const int energy_row = inspector.find_row("light_energy");
	CHECK(inspector.set_row_value(energy_row, (int64_t)3));
	CHECK(light->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(3.0));

	undo_redo.clear_history();
	delete light;
}

TEST_CASE("[EditorInspector] A rejected value keeps the old value and leaves the history unchanged") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	UndoRedo undo_redo;
	EditorInspector inspector;
	inspector.set_undo_redo(&undo_redo);
	inspector.edit(light);
	REQUIRE(inspector.set_row_value(inspector.find_row("area_range"), 7.0));
	const int history = undo_redo.get_history_count();
	const uint64_t version = undo_redo.get_version();

	{
		ErrorCatcher errors;
		CHECK_FALSE(inspector.set_row_value(inspector.find_row("area_size"), Vector2(NAN, 1))); // Negative components are clamped (upstream); NaN is refused.
		CHECK(errors.contains("area_size"));
		CHECK(inspector.get_last_error().find("area_size") != String::npos);
	}
	CHECK(light->get_area_size().is_equal_approx(Vector2(1, 1)));
	CHECK(undo_redo.get_history_count() == history);
	CHECK(undo_redo.get_version() == version);

	{
		ErrorCatcher errors;
		// A value of the wrong type.
		CHECK_FALSE(inspector.set_row_value(inspector.find_row("area_size"), String("big")));
		CHECK(inspector.get_last_error().find("area_size") != String::npos);
		// Out of the enum.
		CHECK_FALSE(inspector.set_row_value(inspector.find_row("area_shading_method"), (int64_t)99));
		CHECK(errors.contains("area_shading_method"));
		// Bad row index.
		CHECK_FALSE(inspector.set_row_value(-1, 1.0));
		CHECK_FALSE(inspector.set_row_value(inspector.get_row_count(), 1.0));
		CHECK(inspector.get_row_value(9999).is_nil());
	}
	CHECK(light->get_area_size().is_equal_approx(Vector2(1, 1)));
	CHECK(light->get_area_shading_method() == AreaLight3D::AREA_SHADING_LTC);
	CHECK(undo_redo.get_history_count() == history);

	// A good value afterwards clears the error; undo takes it back to the last accepted one.
	CHECK(inspector.set_row_value(inspector.find_row("area_size"), Vector2(3, 3)));
	CHECK(inspector.get_last_error().empty());
	REQUIRE(undo_redo.undo());
	CHECK(light->get_area_size().is_equal_approx(Vector2(1, 1)));
	REQUIRE(undo_redo.undo());
	CHECK(light->get_param(Light3D::PARAM_RANGE) != doctest::Approx(7.0));

	undo_redo.clear_history();
	delete light;
}

TEST_CASE("[EditorInspector] A slider drag merges into one action") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	UndoRedo undo_redo;
	EditorInspector inspector;
	inspector.set_undo_redo(&undo_redo);
	inspector.edit(light);
	const int row = inspector.find_row("area_attenuation");
	const int other = inspector.find_row("light_energy");
	const double start = light->get_param(Light3D::PARAM_ATTENUATION);

	CHECK(inspector.set_row_value(row, 1.5, true));
	CHECK(inspector.set_row_value(row, 2.0, true));
	CHECK(inspector.set_row_value(row, 2.5, true));
	CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.5));
	CHECK(undo_redo.get_history_count() == 1);
	CHECK(undo_redo.get_current_action_name() == "Set area_attenuation");

	REQUIRE(undo_redo.undo());
	CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(start));
	REQUIRE(undo_redo.redo());
	CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.5)); // The drag's last value.

	// After undo/redo (history changed) or another property, a merged edit starts a new action.
	CHECK(inspector.set_row_value(row, 3.0, true));
	CHECK(undo_redo.get_history_count() == 2);
	CHECK(inspector.set_row_value(other, 2.0, true));
	CHECK(undo_redo.get_history_count() == 3);
	// end_merge() ends a drag.
	CHECK(inspector.set_row_value(other, 3.0, true));
	CHECK(undo_redo.get_history_count() == 3);
	inspector.end_merge();
	CHECK(inspector.set_row_value(other, 4.0, true));
	CHECK(undo_redo.get_history_count() == 4);
	// A rejected value in a drag changes nothing.
	{
		ErrorCatcher errors;
		CHECK_FALSE(inspector.set_row_value(inspector.find_row("area_size"), Vector2(INFINITY, -2), true));
	}
	CHECK(undo_redo.get_history_count() == 4);

	REQUIRE(undo_redo.undo());
	CHECK(light->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(3.0));
	REQUIRE(undo_redo.undo());
	CHECK(light->get_param(Light3D::PARAM_ENERGY) == doctest::Approx(1.0));
	REQUIRE(undo_redo.undo());
	CHECK(light->get_param(Light3D::PARAM_ATTENUATION) == doctest::Approx(2.5));

	undo_redo.clear_history();
	delete light;
}

TEST_CASE("[EditorInspector] Without an UndoRedo, edits apply directly") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	EditorInspector inspector;
	inspector.edit(light);
	CHECK(inspector.set_row_value(inspector.find_row("area_size"), Vector2(4, 2)));
	CHECK(light->get_area_size().is_equal_approx(Vector2(4, 2)));
	delete light;
}

TEST_CASE("[EditorInspector] Subgroups, read-only rows, prefixes and hint parsing") {
	GDREGISTER_CLASS(InspectorTestObject);
	InspectorTestObject object;
	UndoRedo undo_redo;
	EditorInspector inspector;
	inspector.set_undo_redo(&undo_redo);
	inspector.edit(&object);
	REQUIRE(inspector.get_row_count() == 4);

	const EditorPropertyRow &count = inspector.get_row(0);
	CHECK(count.property == "outer_count");
	CHECK(count.group == "Outer");
	CHECK(count.label == "Count");
	CHECK(count.hint == PROPERTY_HINT_FLAGS);
	CHECK(count.enum_options == std::vector<String>({ "Red", "Green", "Blue" }));
	CHECK(count.enum_values == std::vector<int64_t>({ 1, 2, 16 }));

	const EditorPropertyRow &total = inspector.get_row(1);
	CHECK(total.property == "outer_total");
	CHECK(total.read_only); // No setter.
	{
		ErrorCatcher errors;
		CHECK_FALSE(inspector.set_row_value(1, 2.0));
		CHECK(errors.contains("read-only"));
	}
	CHECK(undo_redo.get_history_count() == 0);

	// Outside the group's prefix: shown outside the group, nothing stripped.
	const EditorPropertyRow &plain = inspector.get_row(2);
	CHECK(plain.property == "plain");
	CHECK(plain.group == "");
	CHECK(plain.label == "Plain");
	CHECK(plain.enum_options == std::vector<String>({ "Low", "Mid", "High" }));
	CHECK(plain.enum_values == std::vector<int64_t>({ -1, 0, 10 }));

	const EditorPropertyRow &width = inspector.get_row(3);
	CHECK(width.group == "Outer");
	CHECK(width.subgroup == "Inner");
	CHECK(width.label == "Width"); // Subgroup prefix stripped.
	CHECK(width.has_range);
	CHECK(width.range_min == doctest::Approx(-90.0));
	CHECK(width.range_max == doctest::Approx(90.0));
	CHECK(width.range_step == doctest::Approx(0.5));
	CHECK(width.or_less);
	CHECK_FALSE(width.or_greater);
	CHECK(width.suffix == "\u00b0");

	CHECK(inspector.set_row_value(3, 0.25));
	CHECK(object.get_outer_inner_width() == doctest::Approx(0.25));
	REQUIRE(undo_redo.undo());
	CHECK(object.get_outer_inner_width() == doctest::Approx(0.5));

	CHECK(EditorInspector::make_label("shadow_normal_bias", "shadow_") == "Normal Bias");
	CHECK(EditorInspector::make_label("fov_gi_mode") == "FOV GI Mode");
	CHECK(EditorInspector::make_label("area_", "area_") == "Area"); // Never strips everything.
	EditorPropertyRow row;
	row.type = Variant::INT;
	row.hint = PROPERTY_HINT_RANGE;
	row.hint_string = "1,256";
	EditorInspector::parse_hint(row);
	CHECK(row.has_range);
	CHECK(row.range_step == doctest::Approx(1.0));
	undo_redo.clear_history();
}

// An AreaLight3D in an inspector with undo/redo, on the dummy server; no errors may be printed.
struct AreaLightInspector {
	DummyServer server;
	ErrorCatcher errors;
	AreaLight3D *light = new AreaLight3D;
	UndoRedo undo_redo;
	EditorInspector inspector;

	AreaLightInspector() {
		inspector.set_undo_redo(&undo_redo);
		inspector.edit(light);
	}
	~AreaLightInspector() {
		inspector.edit(nullptr);
		delete light;
	}
	// Sets the row p_name to p_value through the inspector (as a user would) and refreshes the rows.
	bool set(const char *p_name, int64_t p_value) {
		const bool ok = inspector.set_row_value(inspector.find_row(p_name), p_value);
		inspector.refresh();
		return ok;
	}
};

TEST_CASE("[EditorInspector] AreaLight3D shows area_texture for rectangles, for other shapes only while set") {
	AreaLightInspector t;
	CHECK(t.inspector.find_row("area_texture") >= 0); // Rectangle (the default): upstream's textured light.
	const AreaLight3D::AreaShape shapes[3] = { AreaLight3D::AREA_SHAPE_DISK, AreaLight3D::AREA_SHAPE_SPHERE, AreaLight3D::AREA_SHAPE_TUBE };
	for (AreaLight3D::AreaShape shape : shapes) {
		CAPTURE(int(shape));
		REQUIRE(t.set("area_shape", shape));
		CHECK(t.inspector.find_row("area_texture") == -1); // Nothing to texture.
	}
	// A tube holding a texture (from a scene file, or set before the shape changed) shows it, so it can be
	// cleared; clearing it hides the row again.
	Ref<ImageTexture> texture = ImageTexture::create_from_image(Image(2, 2, Color(1, 1, 1, 1)));
	REQUIRE(texture.is_valid());
	t.light->set_area_texture(texture);
	t.inspector.refresh();
	CHECK(t.inspector.find_row("area_texture") >= 0);
	t.light->set_area_texture(Ref<Texture2D>());
	t.inspector.refresh();
	CHECK(t.inspector.find_row("area_texture") == -1);
	// Hidden from the inspector only: still a stored property (Godot's NO_EDITOR).
	std::vector<PropertyInfo> list;
	t.light->get_property_list(&list);
	bool stored = false;
	for (const PropertyInfo &pi : list) {
		stored = stored || (pi.name == "area_texture" && pi.usage == PROPERTY_USAGE_NO_EDITOR);
	}
	CHECK(stored);
	REQUIRE(t.set("area_shape", AreaLight3D::AREA_SHAPE_RECTANGLE));
	CHECK(t.inspector.find_row("area_texture") >= 0);
	CHECK(t.errors.messages.empty());
}

TEST_CASE("[EditorInspector] AreaLight3D hides the projector, and the stochastic samples unless a method takes them") {
	AreaLightInspector t;
	EditorInspector &inspector = t.inspector;
	// Exactly what _validate_property says: the rows are the EDITOR entries of the property list.
	CHECK(inspector.find_row("light_projector") == -1);
	CHECK(inspector.find_row("area_stochastic_samples") == -1); // LTC by default.
	REQUIRE(t.set("area_shading_method", AreaLight3D::AREA_SHADING_STOCHASTIC));
	CHECK(inspector.find_row("area_stochastic_samples") >= 0);
	REQUIRE(t.set("area_shading_method", AreaLight3D::AREA_SHADING_AUTO));
	CHECK(inspector.find_row("area_stochastic_samples") >= 0); // AUTO may pick the stochastic method.
	REQUIRE(t.set("area_shading_method", AreaLight3D::AREA_SHADING_MRP));
	CHECK(inspector.find_row("area_stochastic_samples") == -1);
	// Hidden from the inspector, still saved (a scene's value is not dropped).
	std::vector<PropertyInfo> list;
	t.light->get_property_list(&list);
	int stored = 0;
	for (const PropertyInfo &pi : list) {
		if (pi.name == "light_projector" || pi.name == "area_stochastic_samples") {
			stored += (pi.usage & PROPERTY_USAGE_STORAGE) ? 1 : 0;
		}
	}
	CHECK(stored == 2);
	// Omni lights keep their projector row.
	OmniLight3D *omni = new OmniLight3D;
	inspector.edit(omni);
	CHECK(inspector.find_row("light_projector") >= 0);
	inspector.edit(nullptr);
	delete omni;
	CHECK(t.errors.messages.empty());
}

TEST_CASE("[EditorInspector] Layer masks: 20-layer grid, unsigned values, one bit toggled") {
	DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	EditorInspector inspector;
	inspector.edit(light);
	const int row = inspector.find_row("light_cull_mask");
	REQUIRE(row >= 0);
	CHECK(EditorInspector::get_layer_count(inspector.get_row(row).hint) == 20);
	CHECK(EditorInspector::get_layer_count(PROPERTY_HINT_RANGE) == 0);
	// The default mask is all layers: shown as 0xFFFFFFFF, never as a signed -1.
	CHECK(EditorInspector::get_layer_mask(inspector.get_row_value(row)) == 0xFFFFFFFFu);
	CHECK(EditorInspector::get_layer_mask(Variant((int64_t)-1)) == 0xFFFFFFFFu);
	// Toggling layer 2 (bit 1) clears only that bit; the light takes the value.
	const int64_t toggled = EditorInspector::toggle_layer(inspector.get_row_value(row), 1);
	CHECK(toggled == (int64_t)0xFFFFFFFDu);
	REQUIRE(inspector.set_row_value(row, toggled));
	CHECK(light->get_cull_mask() == 0xFFFFFFFDu);
	CHECK(EditorInspector::toggle_layer(Variant(toggled), 1) == (int64_t)0xFFFFFFFFu);
	CHECK(EditorInspector::toggle_layer(Variant((int64_t)0), 19) == (int64_t)(1 << 19));
	inspector.edit(nullptr);
	delete light;
}

// A proportional test font: 'i' and 'l' 3 px, ' ' and '.' 4 px, everything else 7 px.
static float _test_width(const String &p_text) {
	float w = 0;
	for (char c : p_text) {
		w += (c == 'i' || c == 'l') ? 3.0f : ((c == ' ' || c == '.') ? 4.0f : 7.0f);
	}
	return w;
}

TEST_CASE("[EditorInspector] Labels and values that overflow their field get an ellipsis") {
	// Fits: unchanged.
	CHECK(EditorInspector::fit_text("Size", 28, _test_width) == "Size");
	CHECK(EditorInspector::fit_text("", 0, _test_width) == "");
	// A long property label in a narrow column: the longest prefix that fits, then "...".
	const String label = EditorInspector::make_label("area_stochastic_samples", "area_"); // "Stochastic Samples"
	CHECK(label == "Stochastic Samples");
	for (float width : { 20.0f, 40.0f, 60.0f, 80.0f, 100.0f }) {
		CAPTURE(width);
		String fitted = EditorInspector::fit_text(label, width, _test_width);
		CHECK(_test_width(fitted) <= width);
		CHECK(string_ends_with(fitted, "..."));
		const String prefix = fitted.substr(0, fitted.size() - 3);
		CHECK(string_begins_with(label, prefix));
		CHECK((prefix.empty() || prefix.back() != ' ')); // No "Stochastic ..." with a dangling space.
		// Longest: one more character of the label would not fit.
		size_t next = prefix.size() + 1;
		while (next < label.size() && label[next - 1] == ' ') {
			next++; // A cut after a space is the same cut.
		}
		if (next <= label.size()) {
			CHECK(_test_width(string_strip_edges(label.substr(0, next)) + "...") > width);
		}
	}
	CHECK(EditorInspector::fit_text(label, 60, _test_width) == "Stocha...");
	// Not even the ellipsis fits: nothing rather than an overflow.
	CHECK(EditorInspector::fit_text(label, 11, _test_width) == "");
	// A long enum value (a combo preview) is cut the same way; UTF-8 is never split.
	CHECK(EditorInspector::fit_text("PCSS Baseline", 50, _test_width) == "PCSS...");
	// "Lumi" + the first byte of the two-byte 'e grave' + "..." would fit 45 px: cut before it.
	CHECK(EditorInspector::fit_text("Lumi\xc3\xa8re Diffuse", 45, _test_width) == "Lumi...");
	CHECK(EditorInspector::fit_text("Lumi\xc3\xa8re Diffuse", 50, _test_width) == "Lumi\xc3\xa8...");
}

TEST_CASE("[EditorInspector] The label column is sized to the labels, within limits") {
	// Short labels: just wide enough (widest + padding), never under the minimum.
	CHECK(EditorInspector::get_label_column_width({ 30, 50, 42 }, 400, 8, 60, 0.45f) == doctest::Approx(60));
	CHECK(EditorInspector::get_label_column_width({ 30, 90, 42 }, 400, 8, 60, 0.45f) == doctest::Approx(98));
	// A long label: capped at 45 % of the panel (that label is then fitted with an ellipsis).
	CHECK(EditorInspector::get_label_column_width({ 30, 300 }, 400, 8, 60, 0.45f) == doctest::Approx(180));
	// A very narrow panel keeps the minimum.
	CHECK(EditorInspector::get_label_column_width({ 300 }, 100, 8, 60, 0.45f) == doctest::Approx(60));
	// The real rows of an area light: every label fits or is fitted into the column.
	SceneTest::DummyServer server;
	AreaLight3D light;
	EditorInspector inspector;
	inspector.edit(&light);
	std::vector<float> widths;
	for (int i = 0; i < inspector.get_row_count(); i++) {
		widths.push_back(_test_width(inspector.get_row(i).label));
	}
	const float column = EditorInspector::get_label_column_width(widths, 200, 8, 60, 0.45f);
	CHECK(column <= 90.0f);
	int cut = 0;
	for (int i = 0; i < inspector.get_row_count(); i++) {
		String fitted = EditorInspector::fit_text(inspector.get_row(i).label, column - 8, _test_width);
		CHECK(_test_width(fitted) <= column - 8);
		cut += fitted != inspector.get_row(i).label;
	}
	CHECK(cut > 0); // "Volumetric Fog Energy" and friends do not fit 82 px of this font.
	inspector.edit(nullptr);
}

TEST_CASE("[EditorInspector] The layer grid shrinks to its field, in two or four rows") {
	int rows = 0;
	// Wide field: two rows of 10, cells at their maximum.
	CHECK(EditorInspector::get_layer_cell_size(20, 400, 2, 18, 12, rows) == doctest::Approx(18));
	CHECK(rows == 2);
	// Narrower: still two rows, cells shrink so 10 cells + 9 gaps fill the width exactly.
	float cell = EditorInspector::get_layer_cell_size(20, 150, 2, 18, 12, rows);
	CHECK(rows == 2);
	CHECK(cell * 10 + 2 * 9 == doctest::Approx(150));
	// Too narrow for two rows: four rows of 5.
	cell = EditorInspector::get_layer_cell_size(20, 100, 2, 18, 12, rows);
	CHECK(rows == 4);
	CHECK(cell * 5 + 2 * 4 <= 100.0f + 1e-4f);
	CHECK(cell >= 12);
	// Bad input is refused with an error.
	ErrorCatcher errors;
	CHECK(EditorInspector::get_layer_cell_size(7, 100, 2, 18, 12, rows) == 0);
	CHECK(rows == 0);
	CHECK(errors.contains("multiple of 4"));
}

} // namespace TestEditorInspector
