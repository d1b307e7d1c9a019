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
	CHECK(method.enum_options == std::vector<String>({ "LTC", "LTC Polynomial", "MRP", "Stochastic", "Auto" }));
	REQUIRE(method.enum_values.size() == 5);
	// The values are the bound constants LTC..AUTO.
	CHECK(method.enum_values[0] == ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_LTC"));
	CHECK(method.enum_values[4] == ClassDB::get_integer_constant("AreaLight3D", "AREA_SHADING_AUTO"));
	CHECK(method.enum_values[4] == (int64_t)AreaLight3D::AREA_SHADING_AUTO);

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

} // namespace TestEditorInspector
