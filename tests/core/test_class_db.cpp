/**************************************************************************/
/*  test_class_db.cpp                                                     */
/**************************************************************************/
/* ClassDB: registration, inheritance, properties by name, groups,        */
/* indexed properties, constants and error messages.                      */

#include "core/error/error_macros.h"
#include "core/io/resource.h"
#include "core/object/class_db.h"
#include "core/object/object.h"
#include "core/object/ref_counted.h"

#include <doctest/doctest.h>

namespace TestClassDB {

class TestCDBBase : public Object {
	GDCLASS(TestCDBBase, Object);

	int64_t count = 3;
	String label = "base";

protected:
	static void _bind_methods() {
		ClassDB::bind_method(D_METHOD("set_count", "count"), &TestCDBBase::set_count);
		ClassDB::bind_method(D_METHOD("get_count"), &TestCDBBase::get_count);
		ClassDB::bind_method(D_METHOD("set_label", "label"), &TestCDBBase::set_label);
		ClassDB::bind_method(D_METHOD("get_label"), &TestCDBBase::get_label);
		ADD_PROPERTY(PropertyInfo(Variant::INT, "count", PROPERTY_HINT_RANGE, "0,10,1"), "set_count", "get_count");
		ADD_PROPERTY(PropertyInfo(Variant::STRING, "label"), "set_label", "get_label");
	}

public:
	void set_count(int64_t p_count) { count = p_count; }
	int64_t get_count() const { return count; }
	void set_label(const String &p_label) { label = p_label; }
	String get_label() const { return label; }
};

class TestCDBAbstract : public TestCDBBase {
	GDCLASS(TestCDBAbstract, TestCDBBase);

public:
	virtual int kind() const = 0;
};

class TestCDBLight : public TestCDBAbstract {
	GDCLASS(TestCDBLight, TestCDBAbstract);

public:
	enum Param {
		PARAM_ENERGY,
		PARAM_RANGE,
		PARAM_SIZE,
		PARAM_MAX,
	};

private:
	float params[PARAM_MAX] = { 1.0f, 5.0f, 0.0f };
	Color color = Color(1, 1, 1);
	bool shadow = false;
	Param mode = PARAM_ENERGY;
	Ref<Resource> projector;

protected:
	static void _bind_methods() {
		ClassDB::bind_method(D_METHOD("set_param", "param", "value"), &TestCDBLight::set_param);
		ClassDB::bind_method(D_METHOD("get_param", "param"), &TestCDBLight::get_param);
		ClassDB::bind_method(D_METHOD("set_color", "color"), &TestCDBLight::set_color);
		ClassDB::bind_method(D_METHOD("get_color"), &TestCDBLight::get_color);
		ClassDB::bind_method(D_METHOD("set_shadow", "enabled"), &TestCDBLight::set_shadow);
		ClassDB::bind_method(D_METHOD("has_shadow"), &TestCDBLight::has_shadow);
		ClassDB::bind_method(D_METHOD("set_mode", "mode"), &TestCDBLight::set_mode);
		ClassDB::bind_method(D_METHOD("get_mode"), &TestCDBLight::get_mode);
		ClassDB::bind_method(D_METHOD("set_projector", "projector"), &TestCDBLight::set_projector);
		ClassDB::bind_method(D_METHOD("get_projector"), &TestCDBLight::get_projector);

		ADD_GROUP("Light", "light_");
		ADD_PROPERTY(PropertyInfo(Variant::COLOR, "light_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_color", "get_color");
		ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_energy", PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"), "set_param", "get_param", PARAM_ENERGY);
		ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_size", PROPERTY_HINT_RANGE, "0,1,0.001,suffix:m"), "set_param", "get_param", PARAM_SIZE);
		ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "light_projector", PROPERTY_HINT_RESOURCE_TYPE, "Resource"), "set_projector", "get_projector");
		ADD_GROUP("Shadow", "shadow_");
		ADD_PROPERTY(PropertyInfo(Variant::BOOL, "shadow_enabled"), "set_shadow", "has_shadow");
		ADD_GROUP("", "");
		ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "omni_range", PROPERTY_HINT_RANGE, "0,4096,0.001,or_greater,exp,suffix:m"), "set_param", "get_param", PARAM_RANGE);
		ADD_PROPERTY(PropertyInfo(Variant::INT, "mode", PROPERTY_HINT_ENUM, "Energy,Range,Size"), "set_mode", "get_mode");

		BIND_ENUM_CONSTANT(PARAM_ENERGY);
		BIND_ENUM_CONSTANT(PARAM_RANGE);
		BIND_ENUM_CONSTANT(PARAM_SIZE);
		BIND_ENUM_CONSTANT(PARAM_MAX);
	}

	void _validate_property(PropertyInfo &p_property) const {
		if (!shadow && string_begins_with(p_property.name, "shadow_") && p_property.name != "shadow_enabled") {
			p_property.usage = PROPERTY_USAGE_NO_EDITOR;
		}
		if (p_property.name == "light_size" && mode == PARAM_RANGE) {
			p_property.usage = PROPERTY_USAGE_NONE;
		}
	}

public:
	int notified = 0;

	virtual int kind() const override { return 1; }
	void set_param(Param p_param, float p_value) {
		ERR_FAIL_INDEX(p_param, PARAM_MAX);
		params[p_param] = p_value;
	}
	float get_param(Param p_param) const {
		ERR_FAIL_INDEX_V(p_param, PARAM_MAX, 0.0f);
		return params[p_param];
	}
	void set_color(const Color &p_color) { color = p_color; }
	Color get_color() const { return color; }
	void set_shadow(bool p_enable) {
		shadow = p_enable;
		notify_property_list_changed();
	}
	bool has_shadow() const { return shadow; }
	void set_mode(Param p_mode) { mode = p_mode; }
	Param get_mode() const { return mode; }
	void set_projector(const Ref<Resource> &p_projector) { projector = p_projector; }
	Ref<Resource> get_projector() const { return projector; }
};

class TestCDBOmni : public TestCDBLight {
	GDCLASS(TestCDBOmni, TestCDBLight);

protected:
	void _notification(int p_what) { omni_notified += p_what; }

public:
	int omni_notified = 0;
	TestCDBOmni() { set_param(PARAM_RANGE, 7.5f); }
};

class TestCDBResource : public Resource {
	GDCLASS(TestCDBResource, Resource);
};

VARIANT_ENUM_CAST(TestCDBLight::Param);

struct ErrorCapture {
	ErrorHandlerList handler;
	std::vector<String> messages;
	ErrorCapture() {
		handler.callback = [this](ErrorHandlerType p_type, const String &p_text) { messages.push_back(p_text); };
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~ErrorCapture() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
	bool any_contains(const String &p_a, const String &p_b = String()) const {
		for (const String &m : messages) {
			if (m.find(p_a) != String::npos && m.find(p_b) != String::npos) {
				return true;
			}
		}
		return false;
	}
};

static void register_test_classes() {
	GDREGISTER_CLASS(TestCDBBase);
	GDREGISTER_ABSTRACT_CLASS(TestCDBAbstract);
	GDREGISTER_CLASS(TestCDBLight);
	GDREGISTER_CLASS(TestCDBOmni);
	GDREGISTER_CLASS(TestCDBResource);
}

TEST_CASE("[ClassDB] Registration, inheritance and instantiation") {
	register_test_classes();
	CHECK(ClassDB::class_exists("TestCDBOmni"));
	CHECK(ClassDB::class_exists("Object"));
	CHECK_FALSE(ClassDB::class_exists("NoSuchClass"));
	CHECK(ClassDB::get_parent_class("TestCDBOmni") == "TestCDBLight");
	CHECK(ClassDB::get_parent_class("TestCDBAbstract") == "TestCDBBase");
	CHECK(ClassDB::is_parent_class("TestCDBOmni", "TestCDBBase"));
	CHECK(ClassDB::is_parent_class("TestCDBOmni", "Object"));
	CHECK_FALSE(ClassDB::is_parent_class("TestCDBBase", "TestCDBOmni"));
	CHECK(ClassDB::is_parent_class("TestCDBResource", "RefCounted"));

	Object *obj = ClassDB::instantiate("TestCDBOmni");
	REQUIRE(obj != nullptr);
	CHECK(obj->get_class() == "TestCDBOmni");
	CHECK(obj->is_class("TestCDBLight"));
	CHECK(obj->is_class("Object"));
	CHECK_FALSE(obj->is_class("TestCDBResource"));
	CHECK(Object::cast_to<TestCDBLight>(obj) != nullptr);
	CHECK(TestCDBOmni::get_class_static() == "TestCDBOmni");
	CHECK(TestCDBOmni::get_parent_class_static() == "TestCDBLight");
	delete obj;

	SUBCASE("Abstract and unknown classes fail with a message") {
		ErrorCapture capture;
		CHECK(ClassDB::instantiate("TestCDBAbstract") == nullptr);
		CHECK(capture.any_contains("TestCDBAbstract", "abstract"));
		CHECK(ClassDB::instantiate("NoSuchClass") == nullptr);
		CHECK(capture.any_contains("NoSuchClass", "not registered"));
		CHECK_FALSE(ClassDB::can_instantiate("TestCDBAbstract"));
		CHECK(ClassDB::can_instantiate("TestCDBLight"));
	}
}

TEST_CASE("[ClassDB] Set and get properties by name") {
	register_test_classes();
	TestCDBOmni omni;
	bool valid = false;

	omni.set("light_energy", 2.5, &valid);
	CHECK(valid);
	CHECK(omni.get_param(TestCDBLight::PARAM_ENERGY) == doctest::Approx(2.5));
	CHECK(omni.get("light_energy").to_float() == doctest::Approx(2.5));

	omni.set("light_energy", 4, &valid); // int converts to float.
	CHECK(valid);
	CHECK(omni.get_param(TestCDBLight::PARAM_ENERGY) == doctest::Approx(4.0));

	omni.set("count", 7, &valid); // Inherited from TestCDBBase.
	CHECK(valid);
	CHECK(omni.get_count() == 7);
	CHECK(omni.get("count") == Variant(7));

	omni.set("label", "hello", &valid);
	CHECK(valid);
	CHECK(omni.get_label() == "hello");

	omni.set("light_color", Color(1, 0.5, 0.25), &valid);
	CHECK(valid);
	CHECK(omni.get_color() == Color(1, 0.5, 0.25));

	omni.set("shadow_enabled", true, &valid);
	CHECK(valid);
	CHECK(omni.has_shadow());
	CHECK(omni.get_property_list_changed_count() == 1);

	omni.set("mode", TestCDBLight::PARAM_SIZE, &valid); // Enum through Variant INT.
	CHECK(valid);
	CHECK(omni.get_mode() == TestCDBLight::PARAM_SIZE);
	CHECK(omni.get("mode") == Variant(2));

	Ref<TestCDBResource> res;
	res.instantiate();
	omni.set("light_projector", res, &valid);
	CHECK(valid);
	CHECK(omni.get_projector() == res.ptr());
	CHECK(res->get_reference_count() == 2);
	CHECK(omni.get("light_projector").get_object() == res.ptr());
	omni.set("light_projector", Variant(), &valid); // null clears.
	CHECK(valid);
	CHECK(omni.get_projector().is_null());
	CHECK(res->get_reference_count() == 1);

	SUBCASE("Indexed properties share one setter") {
		omni.set("omni_range", 12.0, &valid);
		CHECK(valid);
		omni.set("light_size", 0.25, &valid);
		CHECK(omni.get_param(TestCDBLight::PARAM_RANGE) == doctest::Approx(12.0));
		CHECK(omni.get_param(TestCDBLight::PARAM_SIZE) == doctest::Approx(0.25));
		CHECK(ClassDB::get_property_setter("TestCDBOmni", "omni_range") == "set_param");
		CHECK(ClassDB::get_property_getter("TestCDBOmni", "light_size") == "get_param");
	}

	SUBCASE("Calling methods by name") {
		bool ok = false;
		omni.call("set_param", { Variant(TestCDBLight::PARAM_RANGE), Variant(3.0) }, &ok);
		CHECK(ok);
		CHECK(omni.call("get_param", { Variant(1) }).to_float() == doctest::Approx(3.0));
		MethodBind *mb = ClassDB::get_method("TestCDBOmni", "set_param");
		REQUIRE(mb != nullptr);
		REQUIRE(mb->get_argument_count() == 2);
		CHECK(mb->get_argument_names()[0] == "param");
		CHECK(mb->get_argument_names()[1] == "value");
		CHECK(mb->get_argument_type(0) == Variant::INT);
		CHECK(mb->get_argument_type(1) == Variant::FLOAT);
		CHECK(omni.has_method("get_label"));
		CHECK_FALSE(omni.has_method("nope"));
	}
}

TEST_CASE("[ClassDB] Wrong property name or type reports an error naming it") {
	register_test_classes();
	TestCDBOmni omni;
	ErrorCapture capture;
	bool valid = true;

	omni.set("light_enrgy", 2.0, &valid);
	CHECK_FALSE(valid);
	CHECK(capture.any_contains("light_enrgy", "TestCDBOmni"));

	valid = true;
	omni.set("light_energy", "bright", &valid);
	CHECK_FALSE(valid);
	CHECK(capture.any_contains("light_energy", "expected float, got String"));
	CHECK(omni.get_param(TestCDBLight::PARAM_ENERGY) == doctest::Approx(1.0));

	valid = true;
	omni.set("light_color", Vector3(1, 2, 3), &valid);
	CHECK_FALSE(valid);
	CHECK(capture.any_contains("light_color", "Vector3"));

	Object other;
	valid = true;
	omni.set("light_projector", Variant(&other), &valid); // Not a Resource.
	CHECK_FALSE(valid);
	CHECK(capture.any_contains("light_projector"));

	valid = true;
	Variant v = omni.get("nonexistent", &valid);
	CHECK_FALSE(valid);
	CHECK(v.get_type() == Variant::NIL);
	CHECK(capture.any_contains("nonexistent", "TestCDBOmni"));

	String err;
	CHECK_FALSE(omni.try_set("light_energy", Vector2(), &err));
	CHECK(err.find("light_energy") != String::npos);
}

TEST_CASE("[ClassDB] Property list is ordered base first with groups") {
	register_test_classes();
	TestCDBOmni omni;
	std::vector<PropertyInfo> list;
	omni.get_property_list(&list);
	std::vector<String> names;
	for (const PropertyInfo &pi : list) {
		names.push_back(pi.is_group_marker() ? "[" + pi.name + ":" + pi.hint_string + "]" : pi.name);
	}
	std::vector<String> expected = { "count", "label", "[Light:light_]", "light_color", "light_energy", "light_size", "light_projector",
		"[Shadow:shadow_]", "shadow_enabled", "[:]", "omni_range", "mode" };
	CHECK(names == expected);

	const PropertyInfo *energy = nullptr;
	const PropertyInfo *projector = nullptr;
	for (const PropertyInfo &pi : list) {
		if (pi.name == "light_energy") {
			energy = &pi;
		}
		if (pi.name == "light_projector") {
			projector = &pi;
		}
	}
	REQUIRE(energy != nullptr);
	CHECK(energy->type == Variant::FLOAT);
	CHECK(energy->hint == PROPERTY_HINT_RANGE);
	CHECK(energy->hint_string == "0,16,0.001,or_greater");
	CHECK(energy->usage == PROPERTY_USAGE_DEFAULT);
	REQUIRE(projector != nullptr);
	CHECK(projector->class_name == "Resource");

	SUBCASE("_validate_property hides properties") {
		omni.set_mode(TestCDBLight::PARAM_RANGE);
		list.clear();
		omni.get_property_list(&list);
		for (const PropertyInfo &pi : list) {
			if (pi.name == "light_size") {
				CHECK(pi.usage == PROPERTY_USAGE_NONE);
			}
		}
		PropertyInfo info;
		REQUIRE(ClassDB::get_property_info("TestCDBOmni", "light_size", &info));
		CHECK(info.usage == PROPERTY_USAGE_DEFAULT); // The registry itself is untouched.
	}
}

TEST_CASE("[ClassDB] Integer constants, defaults and notifications") {
	register_test_classes();
	bool ok = false;
	CHECK(ClassDB::get_integer_constant("TestCDBLight", "PARAM_SIZE", &ok) == 2);
	CHECK(ok);
	CHECK(ClassDB::get_integer_constant("TestCDBOmni", "PARAM_RANGE", &ok) == 1); // Inherited.
	CHECK(ok);
	ClassDB::get_integer_constant("TestCDBOmni", "PARAM_NOPE", &ok);
	CHECK_FALSE(ok);
	CHECK(ClassDB::get_integer_constant_enum("TestCDBLight", "PARAM_ENERGY") == "Param");
	std::vector<String> constants;
	ClassDB::get_enum_constants("TestCDBLight", "Param", &constants);
	CHECK(constants == std::vector<String>{ "PARAM_ENERGY", "PARAM_RANGE", "PARAM_SIZE", "PARAM_MAX" });

	bool valid = false;
	CHECK(ClassDB::class_get_property_default("TestCDBOmni", "omni_range", &valid) == Variant(7.5));
	CHECK(valid);
	CHECK(ClassDB::class_get_property_default("TestCDBLight", "omni_range", &valid) == Variant(5.0));
	CHECK(ClassDB::class_get_property_default("TestCDBLight", "count", &valid) == Variant(3));
	ClassDB::class_get_property_default("TestCDBAbstract", "count", &valid);
	CHECK_FALSE(valid);
	ClassDB::class_get_property_default("TestCDBLight", "nope", &valid);
	CHECK_FALSE(valid);

	TestCDBOmni omni;
	omni.notification(5);
	CHECK(omni.omni_notified == 5);
}

// Integer setters of several widths, as the engine's properties have (int area_shadow_grid, uint32 layers).
class TestCDBIntWidths : public Object {
	GDCLASS(TestCDBIntWidths, Object);

public:
	int grid = 4;
	uint32_t layers = 1;
	int64_t big = 0;

	void set_grid(int p_grid) { grid = p_grid; }
	int get_grid() const { return grid; }
	void set_layers(uint32_t p_layers) { layers = p_layers; }
	uint32_t get_layers() const { return layers; }
	void set_big(int64_t p_big) { big = p_big; }
	int64_t get_big() const { return big; }

protected:
	static void _bind_methods() {
		ClassDB::bind_method(D_METHOD("set_grid", "grid"), &TestCDBIntWidths::set_grid);
		ClassDB::bind_method(D_METHOD("get_grid"), &TestCDBIntWidths::get_grid);
		ClassDB::bind_method(D_METHOD("set_layers", "layers"), &TestCDBIntWidths::set_layers);
		ClassDB::bind_method(D_METHOD("get_layers"), &TestCDBIntWidths::get_layers);
		ClassDB::bind_method(D_METHOD("set_big", "big"), &TestCDBIntWidths::set_big);
		ClassDB::bind_method(D_METHOD("get_big"), &TestCDBIntWidths::get_big);
		ADD_PROPERTY(PropertyInfo(Variant::INT, "grid"), "set_grid", "get_grid");
		ADD_PROPERTY(PropertyInfo(Variant::INT, "layers"), "set_layers", "get_layers");
		ADD_PROPERTY(PropertyInfo(Variant::INT, "big"), "set_big", "get_big");
	}
};

TEST_CASE("[ClassDB] an int64 value outside the setter's integer type is rejected, not wrapped") {
	if (!ClassDB::class_exists("TestCDBIntWidths")) {
		GDREGISTER_CLASS(TestCDBIntWidths);
	}
	TestCDBIntWidths obj;
	String error;
	// Issue 20: 4294967301 = 2^32 + 5 reached an int setter as 5.
	CHECK_FALSE(ClassDB::set_property(&obj, "grid", Variant(int64_t(4294967301LL)), nullptr, &error));
	CHECK(obj.grid == 4);
	CHECK_MESSAGE(error.find("Value 4294967301 in argument 'grid' of 'set_grid' is out of range: the setter takes -2147483648..2147483647.") != String::npos, error);
	error.clear();
	CHECK_FALSE(ClassDB::set_property(&obj, "grid", Variant(int64_t(2147483648LL)), nullptr, &error));
	CHECK(obj.grid == 4);
	CHECK_FALSE(ClassDB::set_property(&obj, "grid", Variant(3e10), nullptr, &error)); // A float that does not fit either.
	CHECK(obj.grid == 4);
	CHECK(ClassDB::set_property(&obj, "grid", Variant(int64_t(INT32_MIN)), nullptr, &error));
	CHECK(obj.grid == INT32_MIN);
	CHECK_FALSE(ClassDB::set_property(&obj, "layers", Variant(int64_t(-1)), nullptr, &error));
	CHECK(obj.layers == 1);
	CHECK(ClassDB::set_property(&obj, "layers", Variant(int64_t(UINT32_MAX)), nullptr, &error));
	CHECK(obj.layers == UINT32_MAX);
	CHECK(ClassDB::set_property(&obj, "big", Variant(int64_t(INT64_MIN)), nullptr, &error));
	CHECK(obj.big == INT64_MIN);
	// Direct narrowing saturates instead of wrapping.
	CHECK(int(Variant(int64_t(2147483648LL))) == INT32_MAX);
	CHECK(uint32_t(Variant(int64_t(-5))) == 0u);
}

} // namespace TestClassDB
