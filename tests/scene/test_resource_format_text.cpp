/**************************************************************************/
/*  test_resource_format_text.cpp                                         */
/**************************************************************************/
/* The .tscn loader and saver: parsing, round trips, warnings for unknown */
/* types/properties and file:line errors for malformed text.              */

#include "core/error/error_macros.h"
#include "core/io/resource.h"
#include "core/object/class_db.h"
#include "scene/main/node.h"
#include "scene/resources/resource_format_text.h"

#include <doctest/doctest.h>

#include <cstdio>

namespace TestResourceFormatText {

static int live_test_nodes = 0;
static int live_test_resources = 0;

class TscnTestTexture : public Resource {
	GDCLASS(TscnTestTexture, Resource);

public:
	TscnTestTexture() { live_test_resources++; }
	~TscnTestTexture() override { live_test_resources--; }
};

class TscnTestMaterial : public Resource {
	GDCLASS(TscnTestMaterial, Resource);

	Color albedo = Color(1, 1, 1);
	float roughness = 1.0f;
	Ref<Resource> texture;
	Ref<Resource> next_pass;

protected:
	static void _bind_methods() {
		ClassDB::bind_method(D_METHOD("set_albedo", "albedo"), &TscnTestMaterial::set_albedo);
		ClassDB::bind_method(D_METHOD("get_albedo"), &TscnTestMaterial::get_albedo);
		ClassDB::bind_method(D_METHOD("set_roughness", "roughness"), &TscnTestMaterial::set_roughness);
		ClassDB::bind_method(D_METHOD("get_roughness"), &TscnTestMaterial::get_roughness);
		ClassDB::bind_method(D_METHOD("set_texture", "texture"), &TscnTestMaterial::set_texture);
		ClassDB::bind_method(D_METHOD("get_texture"), &TscnTestMaterial::get_texture);
		ClassDB::bind_method(D_METHOD("set_next_pass", "next_pass"), &TscnTestMaterial::set_next_pass);
		ClassDB::bind_method(D_METHOD("get_next_pass"), &TscnTestMaterial::get_next_pass);
		ADD_PROPERTY(PropertyInfo(Variant::COLOR, "albedo_color"), "set_albedo", "get_albedo");
		ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "roughness", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_roughness", "get_roughness");
		ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "albedo_texture", PROPERTY_HINT_RESOURCE_TYPE, "Resource"), "set_texture", "get_texture");
		ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "next_pass", PROPERTY_HINT_RESOURCE_TYPE, "TscnTestMaterial"), "set_next_pass", "get_next_pass");
	}

public:
	void set_albedo(const Color &p_color) { albedo = p_color; }
	Color get_albedo() const { return albedo; }
	void set_roughness(float p_value) { roughness = p_value; }
	float get_roughness() const { return roughness; }
	void set_texture(const Ref<Resource> &p_texture) { texture = p_texture; }
	Ref<Resource> get_texture() const { return texture; }
	void set_next_pass(const Ref<TscnTestMaterial> &p_pass) { next_pass = p_pass; }
	Ref<TscnTestMaterial> get_next_pass() const { return next_pass; }

	TscnTestMaterial() { live_test_resources++; }
	~TscnTestMaterial() override { live_test_resources--; }
};

class TscnTestNode : public Node {
	GDCLASS(TscnTestNode, Node);

public:
	enum Mode {
		MODE_A,
		MODE_B,
		MODE_C,
	};

private:
	float energy = 1.0f;
	Color color = Color(1, 1, 1);
	Mode mode = MODE_A;
	Vector3 offset;
	Transform3D xform;
	String label;
	bool enabled = true;
	Ref<TscnTestMaterial> material;

protected:
	static void _bind_methods() {
		ClassDB::bind_method(D_METHOD("set_energy", "energy"), &TscnTestNode::set_energy);
		ClassDB::bind_method(D_METHOD("get_energy"), &TscnTestNode::get_energy);
		ClassDB::bind_method(D_METHOD("set_color", "color"), &TscnTestNode::set_color);
		ClassDB::bind_method(D_METHOD("get_color"), &TscnTestNode::get_color);
		ClassDB::bind_method(D_METHOD("set_mode", "mode"), &TscnTestNode::set_mode);
		ClassDB::bind_method(D_METHOD("get_mode"), &TscnTestNode::get_mode);
		ClassDB::bind_method(D_METHOD("set_offset", "offset"), &TscnTestNode::set_offset);
		ClassDB::bind_method(D_METHOD("get_offset"), &TscnTestNode::get_offset);
		ClassDB::bind_method(D_METHOD("set_xform", "xform"), &TscnTestNode::set_xform);
		ClassDB::bind_method(D_METHOD("get_xform"), &TscnTestNode::get_xform);
		ClassDB::bind_method(D_METHOD("set_label", "label"), &TscnTestNode::set_label);
		ClassDB::bind_method(D_METHOD("get_label"), &TscnTestNode::get_label);
		ClassDB::bind_method(D_METHOD("set_enabled", "enabled"), &TscnTestNode::set_enabled);
		ClassDB::bind_method(D_METHOD("is_enabled"), &TscnTestNode::is_enabled);
		ClassDB::bind_method(D_METHOD("set_material", "material"), &TscnTestNode::set_material);
		ClassDB::bind_method(D_METHOD("get_material"), &TscnTestNode::get_material);

		ADD_PROPERTY(PropertyInfo(Variant::TRANSFORM3D, "transform", PROPERTY_HINT_NONE, "", PROPERTY_USAGE_NO_EDITOR), "set_xform", "get_xform");
		ADD_GROUP("Light", "light_");
		ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "light_energy", PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"), "set_energy", "get_energy");
		ADD_PROPERTY(PropertyInfo(Variant::COLOR, "light_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_color", "get_color");
		ADD_GROUP("", "");
		ADD_PROPERTY(PropertyInfo(Variant::INT, "mode", PROPERTY_HINT_ENUM, "A,B,C"), "set_mode", "get_mode");
		ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "offset"), "set_offset", "get_offset");
		ADD_PROPERTY(PropertyInfo(Variant::STRING, "label"), "set_label", "get_label");
		ADD_PROPERTY(PropertyInfo(Variant::BOOL, "enabled"), "set_enabled", "is_enabled");
		ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "material", PROPERTY_HINT_RESOURCE_TYPE, "TscnTestMaterial"), "set_material", "get_material");
		ADD_PROPERTY(PropertyInfo(Variant::STRING, "editor_only_label", PROPERTY_HINT_NONE, "", PROPERTY_USAGE_EDITOR), "set_label", "get_label");

		BIND_ENUM_CONSTANT(MODE_A);
		BIND_ENUM_CONSTANT(MODE_B);
		BIND_ENUM_CONSTANT(MODE_C);
	}

public:
	void set_energy(float p_energy) { energy = p_energy; }
	float get_energy() const { return energy; }
	void set_color(const Color &p_color) { color = p_color; }
	Color get_color() const { return color; }
	void set_mode(Mode p_mode) { mode = p_mode; }
	Mode get_mode() const { return mode; }
	void set_offset(const Vector3 &p_offset) { offset = p_offset; }
	Vector3 get_offset() const { return offset; }
	void set_xform(const Transform3D &p_xform) { xform = p_xform; }
	Transform3D get_xform() const { return xform; }
	void set_label(const String &p_label) { label = p_label; }
	String get_label() const { return label; }
	void set_enabled(bool p_enabled) { enabled = p_enabled; }
	bool is_enabled() const { return enabled; }
	void set_material(const Ref<TscnTestMaterial> &p_material) { material = p_material; }
	Ref<TscnTestMaterial> get_material() const { return material; }

	TscnTestNode() { live_test_nodes++; }
	~TscnTestNode() override { live_test_nodes--; }
};

VARIANT_ENUM_CAST(TscnTestNode::Mode);

struct MessageCapture {
	ErrorHandlerList handler;
	std::vector<String> errors;
	std::vector<String> warnings;
	MessageCapture() {
		handler.callback = [this](ErrorHandlerType p_type, const String &p_text) {
			(p_type == ERR_HANDLER_WARNING ? warnings : errors).push_back(p_text);
		};
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~MessageCapture() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
	bool warned(const String &p_a, const String &p_b = String()) const {
		for (const String &w : warnings) {
			if (w.find(p_a) != String::npos && w.find(p_b) != String::npos) {
				return true;
			}
		}
		return false;
	}
};

static void register_tscn_test_types() {
	GDREGISTER_CLASS(Node);
	GDREGISTER_CLASS(TscnTestNode);
	GDREGISTER_CLASS(TscnTestMaterial);
	GDREGISTER_CLASS(TscnTestTexture);
	ResourceFormatText::add_resource_loader("png", [](const String &p_path, const String &p_type, String *r_error) {
		Ref<TscnTestTexture> tex;
		tex.instantiate();
		return Ref<Resource>(tex);
	});
	ResourceFormatText::add_scene_loader("glb", [](const String &p_path, String *r_error) {
		Node *model = new Node;
		model->set_name("ModelRoot");
		Node *mesh = new TscnTestNode;
		mesh->set_name("Mesh");
		model->add_child(mesh);
		return model;
	});
}

static const char *SMALL_SCENE = R"([gd_scene load_steps=5 format=3 uid="uid://b1x2y3"]

[ext_resource type="Texture2D" path="res://textures/checker.png" id="1_tex"]
[ext_resource type="PackedScene" path="res://models/lamp.glb" id="2_lamp"]

[sub_resource type="TscnTestMaterial" id="Mat_inner"]
roughness = 0.25

[sub_resource type="TscnTestMaterial" id="Mat_outer"]
albedo_color = Color(1, 0.5, 0, 1)
albedo_texture = ExtResource("1_tex")
next_pass = SubResource("Mat_inner")

[node name="Main" type="Node"]

[node name="Sun" type="TscnTestNode" parent="."]
transform = Transform3D(1, 0, 0, 0, 0.5, 0.866025, 0, -0.866025, 0.5, 0, 10, 0)
light_energy = 2.5
light_color = Color(1, 0.9, 0.8, 1)
mode = 2
material = SubResource("Mat_outer")

[node name="Group" type="Node" parent="."]

[node name="Fill" type="TscnTestNode" parent="Group"]
label = "fill \"light\""
enabled = false
material = SubResource("Mat_outer")

[node name="Deep" type="TscnTestNode" parent="Group/Fill"]
offset = Vector3(1, 2, 3)

[node name="Lamp" parent="." instance=ExtResource("2_lamp")]
)";

TEST_CASE("[SceneTree][TSCN] Parse a small scene") {
	register_tscn_test_types();
	String err;
	Node *root = ResourceFormatText::load_scene_from_string(SMALL_SCENE, "res_test/small.tscn", &err);
	REQUIRE_MESSAGE(root != nullptr, err.c_str());
	CHECK(err.empty());
	CHECK(root->get_name() == "Main");
	CHECK(root->get_class() == "Node");
	CHECK(root->get_child_count() == 3);

	TscnTestNode *sun = Object::cast_to<TscnTestNode>(root->get_node_or_null("Sun"));
	REQUIRE(sun != nullptr);
	CHECK(sun->get_energy() == doctest::Approx(2.5));
	CHECK(sun->get_color().is_equal_approx(Color(1, 0.9, 0.8, 1)));
	CHECK(sun->get_mode() == TscnTestNode::MODE_C);
	CHECK(sun->get_xform().origin == Vector3(0, 10, 0));
	CHECK(sun->get_xform().basis.rows[1].is_equal_approx(Vector3(0, 0.5, 0.866025)));
	CHECK(sun->is_enabled()); // Not in the file: constructor default.

	TscnTestNode *fill = Object::cast_to<TscnTestNode>(root->get_node_or_null("Group/Fill"));
	REQUIRE(fill != nullptr);
	CHECK(fill->get_label() == "fill \"light\"");
	CHECK_FALSE(fill->is_enabled());
	TscnTestNode *deep = Object::cast_to<TscnTestNode>(root->get_node_or_null("Group/Fill/Deep"));
	REQUIRE(deep != nullptr);
	CHECK(deep->get_offset() == Vector3(1, 2, 3));

	// Sub-resources are shared, nested and hold the ext_resource.
	Ref<TscnTestMaterial> mat = sun->get_material();
	REQUIRE(mat.is_valid());
	CHECK(mat == fill->get_material());
	CHECK(mat->get_scene_unique_id() == "Mat_outer");
	CHECK(mat->get_albedo() == Color(1, 0.5, 0, 1));
	REQUIRE(mat->get_next_pass().is_valid());
	CHECK(mat->get_next_pass()->get_roughness() == doctest::Approx(0.25));
	REQUIRE(mat->get_texture().is_valid());
	CHECK(mat->get_texture()->get_class() == "TscnTestTexture");
	CHECK(mat->get_texture()->get_path() == "res://textures/checker.png");

	// instance=ExtResource(...) goes through the registered "glb" scene loader.
	Node *lamp = root->get_node_or_null("Lamp");
	REQUIRE(lamp != nullptr);
	CHECK(lamp->get_child_count() == 1);
	CHECK(lamp->get_node_or_null("Mesh") != nullptr);

	mat.unref();
	delete root;
	CHECK(live_test_nodes == 0);
	CHECK(live_test_resources == 0);
	CHECK(ResourceFormatText::resolve_path("res://a/b.png", "proj/scenes/x.tscn") == "proj/scenes/a/b.png");
}

TEST_CASE("[SceneTree][TSCN] Round trip save, load, save is identical") {
	register_tscn_test_types();
	Node *root = new Node;
	root->set_name("Root");
	TscnTestNode *a = new TscnTestNode;
	a->set_name("Key");
	a->set_energy(0.1f);
	a->set_color(Color(0.2f, 0.4f, 0.6f));
	a->set_mode(TscnTestNode::MODE_B);
	a->set_xform(Transform3D(Basis::from_euler(Vector3(0.3f, 1.2f, 0.0f)), Vector3(1.5f, 2, -3)));
	a->set_label("multi\nline \\ \"quoted\"");
	Ref<TscnTestMaterial> mat;
	mat.instantiate();
	mat->set_roughness(0.5f);
	Ref<TscnTestMaterial> inner;
	inner.instantiate();
	inner->set_albedo(Color(0, 1, 0));
	mat->set_next_pass(inner);
	Ref<TscnTestTexture> tex;
	tex.instantiate();
	tex->set_path("res://t.png");
	inner->set_texture(tex);
	a->set_material(mat);
	root->add_child(a);
	Node *group = new Node;
	group->set_name("Group");
	root->add_child(group);
	TscnTestNode *b = new TscnTestNode;
	b->set_name("Child");
	b->set_offset(Vector3(0.25f, 0, -1));
	b->set_material(mat);
	group->add_child(b);

	String first = ResourceFormatText::save_scene_to_string(root);
	// Godot 4 conventions for a new file: no load_steps, a uid, "1_xxxxx" ext ids.
	CHECK(first.find("[gd_scene format=3 uid=\"uid://") == 0);
	CHECK(first.find("load_steps") == String::npos);
	CHECK(first.find("[ext_resource type=\"TscnTestTexture\" path=\"res://t.png\" id=\"1_") != String::npos);
	CHECK(first.find("light_energy = 0.1\n") != String::npos);
	CHECK(first.find("mode = 1\n") != String::npos);
	CHECK(first.find("[node name=\"Child\" type=\"TscnTestNode\" parent=\"Group\"]") != String::npos);
	// Defaults and editor-only properties are not written.
	CHECK(first.find("enabled") == String::npos);
	CHECK(first.find("editor_only_label") == String::npos);
	// The inner material is written before the material that uses it.
	size_t inner_pos = first.find("albedo_color = Color(0, 1, 0, 1)");
	size_t outer_pos = first.find("roughness = 0.5");
	REQUIRE(inner_pos != String::npos);
	REQUIRE(outer_pos != String::npos);
	CHECK(inner_pos < outer_pos);

	String path = "/tmp/godot_area_tscn_round_trip_" + itos((long long)(size_t)root) + ".tscn";
	String err;
	REQUIRE(ResourceFormatText::save_scene(root, path, &err));
	ResourceFormatText::set_resource_root("/tmp");
	Node *loaded = ResourceFormatText::load_scene(path, &err);
	ResourceFormatText::set_resource_root(String());
	std::remove(path.c_str());
	REQUIRE_MESSAGE(loaded != nullptr, err.c_str());
	String second = ResourceFormatText::save_scene_to_string(loaded);
	CHECK(second == first);

	TscnTestNode *key = Object::cast_to<TscnTestNode>(loaded->get_node_or_null("Key"));
	REQUIRE(key != nullptr);
	CHECK(key->get_label() == a->get_label());
	CHECK(key->get_xform().is_equal_approx(a->get_xform()));
	CHECK(key->get_material()->get_next_pass()->get_texture().is_valid());

	delete loaded;
	delete root;
	mat.unref();
	inner.unref();
	tex.unref();
	CHECK(live_test_nodes == 0);
	CHECK(live_test_resources == 0);
}

TEST_CASE("[SceneTree][TSCN] Unknown types and properties warn with file:line and the rest loads") {
	register_tscn_test_types();
	const char *text = R"([gd_scene format=3]

[sub_resource type="NoSuchMaterial" id="M1"]
roughness = 1.0

[node name="Root" type="Node"]

[node name="Good" type="TscnTestNode" parent="."]
light_energy = 3.0
light_enrgy = 4.0
light_color = "red"
material = SubResource("M1")
offset = [1, 2, 3]
mode = 1

[node name="Alien" type="FluxCapacitor3D" parent="."]
light_energy = 9.0

[node name="AlienChild" type="TscnTestNode" parent="Alien"]

[node name="After" type="TscnTestNode" parent="."]
label = "still here"
)";
	MessageCapture capture;
	String err;
	Node *root = ResourceFormatText::load_scene_from_string(text, "warn.tscn", &err);
	REQUIRE_MESSAGE(root != nullptr, err.c_str());
	CHECK(capture.errors.empty());
	CHECK(capture.warned("warn.tscn:3:", "NoSuchMaterial"));
	CHECK(capture.warned("warn.tscn:10:", "light_enrgy"));
	CHECK(capture.warned("warn.tscn:11:", "light_color"));
	CHECK(capture.warned("warn.tscn:13:", "Array"));
	CHECK(capture.warned("warn.tscn:16:", "FluxCapacitor3D"));
	TscnTestNode *good = Object::cast_to<TscnTestNode>(root->get_node_or_null("Good"));
	REQUIRE(good != nullptr);
	CHECK(good->get_energy() == doctest::Approx(3.0));
	CHECK(good->get_color() == Color(1, 1, 1));
	CHECK(good->get_mode() == TscnTestNode::MODE_B);
	CHECK(good->get_material().is_null());
	// The unknown type is a placeholder that keeps its child.
	REQUIRE(root->get_node_or_null("Alien") != nullptr);
	CHECK(root->get_node_or_null("Alien")->get_class() == "MissingNode");
	CHECK(root->get_node_or_null("Alien/AlienChild") != nullptr);
	TscnTestNode *after = Object::cast_to<TscnTestNode>(root->get_node_or_null("After"));
	REQUIRE(after != nullptr);
	CHECK(after->get_label() == "still here");
	CHECK(root->get_child_count() == 3);
	// Everything that was not applied is written back.
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("[sub_resource type=\"NoSuchMaterial\" id=\"M1\"]\nroughness = 1.0\n") != String::npos);
	CHECK(saved.find("light_enrgy = 4.0\n") != String::npos);
	CHECK(saved.find("light_color = \"red\"\n") != String::npos);
	CHECK(saved.find("offset = [1, 2, 3]\n") != String::npos);
	CHECK(saved.find("[node name=\"Alien\" type=\"FluxCapacitor3D\" parent=\".\"]\nlight_energy = 9.0\n") != String::npos);
	delete root;
	CHECK(live_test_nodes == 0);
}

// Loads p_text expecting failure; returns the error text.
static String load_error(const String &p_text) {
	MessageCapture capture;
	String err;
	Node *root = ResourceFormatText::load_scene_from_string(p_text, "bad.tscn", &err);
	CHECK(root == nullptr);
	delete root;
	CHECK_FALSE(capture.errors.empty()); // The error is also printed.
	CHECK(live_test_nodes == 0); // Nothing leaked.
	CHECK(live_test_resources == 0);
	return err;
}

static const char *HEADER = "[gd_scene format=3]\n\n[sub_resource type=\"TscnTestMaterial\" id=\"M\"]\n\n[node name=\"Root\" type=\"TscnTestNode\"]\nmaterial = SubResource(\"M\")\n\n[node name=\"A\" type=\"TscnTestNode\" parent=\".\"]\n";

TEST_CASE("[SceneTree][TSCN] Malformed: unterminated string") {
	register_tscn_test_types();
	String err = load_error(String(HEADER) + "label = \"never closed\n\n[node name=\"B\" type=\"Node\" parent=\".\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: Unterminated string") == 0, err.c_str());
	err = load_error(String(HEADER) + "\n\nlabel = \"runs to the end\n");
	CHECK_MESSAGE(err.find("bad.tscn:11: Unterminated string") == 0, err.c_str());
}

TEST_CASE("[SceneTree][TSCN] Malformed: bad bracket header") {
	register_tscn_test_types();
	String err = load_error(String(HEADER) + "\n[node name=\"B\" type=\"Node\" parent=\".\"\nlabel = \"x\"\n");
	CHECK_MESSAGE(err.find("bad.tscn:10: Missing ']'") == 0, err.c_str());
	err = load_error(String(HEADER) + "[node name=\"B\" type \"Node\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: Expected '='") == 0, err.c_str());
	err = load_error("[gd_scene format=3]\n[]\n");
	CHECK_MESSAGE(err.find("bad.tscn:2: Expected a tag name") == 0, err.c_str());
	err = load_error("[gd_resource type=\"Material\" format=3]\n");
	CHECK_MESSAGE(err.find("bad.tscn:1: Expected a [gd_scene") == 0, err.c_str());
}

TEST_CASE("[SceneTree][TSCN] Malformed: bad literal") {
	register_tscn_test_types();
	String err = load_error(String(HEADER) + "light_energy = 1.2.3\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: Invalid number literal '1.2.3'") == 0, err.c_str());
	err = load_error(String(HEADER) + "offset = Vector3(1, 2)\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: Vector3(...) takes 3 numbers") == 0, err.c_str());
	err = load_error(String(HEADER) + "offset = Vector3(1, 2, 3) 4\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: Unexpected text") == 0, err.c_str());
	err = load_error(String(HEADER) + "light_energy 2\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: Expected 'name = value'") == 0, err.c_str());
	err = load_error(String(HEADER) + "material = SubResource(\"Nope\")\n");
	CHECK_MESSAGE(err.find("bad.tscn:9: SubResource(\"Nope\") is not declared") == 0, err.c_str());
}

TEST_CASE("[SceneTree][TSCN] Malformed: a sub_resource naming itself is an error, not a leaked reference cycle") {
	register_tscn_test_types();
	// Found by fuzz_resource_format_text (LeakSanitizer; seed tests/fuzz/corpus/tscn/regress_sub_resource_self_reference.tscn):
	// a property of a sub_resource that named the same sub_resource made it hold itself, never freed.
	// load_error() also checks that no test resource is left alive.
	String err = load_error("[gd_scene format=3]\n\n[sub_resource type=\"TscnTestMaterial\" id=\"M\"]\nnext = SubResource(\"M\")\n\n[node name=\"Root\" type=\"TscnTestNode\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:4: SubResource(\"M\") refers to the sub_resource it is a property of") == 0, err.c_str());
	// The same inside a value kept as text (an Array, a constructor we do not model): the kept text holds
	// the resources it names (seed regress_sub_resource_self_reference_kept_text.tscn, LeakSanitizer).
	err = load_error("[gd_scene format=3]\n\n[sub_resource type=\"TscnTestMaterial\" id=\"M\"]\nextra = [SubResource(\"M\")]\n\n[node name=\"Root\" type=\"TscnTestNode\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:4: extra: SubResource(\"M\") refers to the sub_resource it is a property of") == 0, err.c_str());
	err = load_error("[gd_scene format=3]\n\n[sub_resource type=\"TscnTestMaterial\" id=\"M\"]\nnsform = Transform2D(1, 0, 0,\n next = SubResource(\"M\"))\n\n[node name=\"Root\" type=\"TscnTestNode\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:4: nsform: SubResource(\"M\") refers to the sub_resource it is a property of") == 0, err.c_str());
}

TEST_CASE("[SceneTree][TSCN] A value kept as text keeps the sub_resources it names, blanks before the id or not") {
	register_tscn_test_types();
	// Found by fuzz_resource_format_text (seed regress_kept_text_reference_after_control_char.tscn): a
	// control character between SubResource( and the quote hid the reference from the saver, so the
	// saved file named a sub_resource it no longer declared and did not load.
	for (const char *gap : { "", " ", "\x04", " \t\x01 " }) {
		const String text = String("[gd_scene format=3]\n\n[sub_resource type=\"TscnTestMaterial\" id=\"M\"]\n\n[node name=\"Root\" type=\"TscnTestNode\"]\nextra = [SubResource(") + gap + "\"M\")]\n";
		String error;
		Node *root = ResourceFormatText::load_scene_from_string(text, "kept.tscn", &error);
		REQUIRE_MESSAGE(root != nullptr, error.c_str());
		const String saved = ResourceFormatText::save_scene_to_string(root);
		delete root;
		CHECK_MESSAGE(saved.find("[sub_resource type=\"TscnTestMaterial\" id=\"M\"]") != String::npos, saved.c_str());
		Node *again = ResourceFormatText::load_scene_from_string(saved, "kept.tscn", &error);
		REQUIRE_MESSAGE(again != nullptr, error.c_str());
		CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
		delete again;
	}
}

TEST_CASE("[SceneTree][TSCN] A value that fails in a section kept as text costs its own line, not the next section") {
	register_tscn_test_types();
	// An unclosed '[' reads on into the next lines; the kept section used to swallow the [node] after it
	// (the node was lost into kept text), and where the save moved the section the next load differed
	// (found by fuzz_resource_format_text, seed regress_kept_value_reads_into_next_tag.tscn).
	const String text = "[gd_scene format=3]\n\n[node name=\"R\" type=\"TscnTestNode\"]\n\n[unknown_section a=1]\nx = [1,\n[node name=\"A\" type=\"TscnTestNode\" parent=\".\"]\n";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "kept.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(root->get_node_or_null("A") != nullptr);
	const String saved = ResourceFormatText::save_scene_to_string(root);
	delete root;
	CHECK_MESSAGE(saved.find("x = [1,") != String::npos, saved.c_str());
	Node *again = ResourceFormatText::load_scene_from_string(saved, "kept.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error.c_str());
	CHECK(again->get_node_or_null("A") != nullptr);
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
	delete again;
	// A broken tag line after such a value is an error at its own line, wherever the section stands.
	String err = load_error(text + "\n[unknown_section b=2]\nx = [2,\n[node\xdc\xdc]\n");
	CHECK_MESSAGE(err.find("bad.tscn:11:") == 0, err.c_str());
}

TEST_CASE("[SceneTree][TSCN] A line break in a header's string is written escaped: a header is one line") {
	register_tscn_test_types();
	// Found by fuzz_resource_format_text (seed regress_line_break_in_header_string.tscn): type="Pl\neMesh"
	// made a placeholder whose class held a line break, written raw, and the header no longer loaded.
	const String text = "[gd_scene format=3]\n\n[sub_resource type=\"Pl\\neMesh\" id=\"M\"]\n\n[node name=\"R\" type=\"TscnTestNode\"]\nextra = [SubResource(\"M\")]\n\n[node name=\"C\" type=\"Od\\nd\" parent=\".\"]\n";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "esc.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	const String saved = ResourceFormatText::save_scene_to_string(root);
	delete root;
	CHECK_MESSAGE(saved.find("[sub_resource type=\"Pl\\neMesh\"") != String::npos, saved.c_str());
	CHECK_MESSAGE(saved.find("type=\"Od\\nd\"") != String::npos, saved.c_str());
	Node *again = ResourceFormatText::load_scene_from_string(saved, "esc.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error.c_str());
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
	delete again;
}

TEST_CASE("[SceneTree][TSCN] Malformed: an empty node type is an error, for the root and for a child") {
	register_tscn_test_types();
	// Found by fuzz_resource_format_text (save(load(x)) did not load; seed
	// tests/fuzz/corpus/tscn/regress_empty_node_type.tscn): type="" made a placeholder of no class, saved
	// without a type, which then failed to load as a root without a type.
	String err = load_error("[gd_scene][node name=\"t\"type=\"\"]");
	CHECK_MESSAGE(err.find("bad.tscn:1: Node \"t\": type is empty") == 0, err.c_str());
	err = load_error(String(HEADER) + "\n[node name=\"B\" type=\"\" parent=\".\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:10: Node \"B\": type is empty") == 0, err.c_str());
}

TEST_CASE("[SceneTree][TSCN] A '[' in a comment before a section is not the section's header") {
	register_tscn_test_types();
	// Found by fuzz_resource_format_text (save(load(x)) did not load; seed
	// tests/fuzz/corpus/tscn/regress_comment_bracket.tscn): the header fields written back on save were split
	// from the first '[' of the raw text, which was the one inside the comment.
	for (const char *text : { "[gd_scene format=3];[\n[node name=\"o\" type=\"TscnTestNode\"]\n", ";[ x\n[gd_scene format=3]\n; [node name=\"x\"]\n[node name=\"o\" type=\"TscnTestNode\"]\n" }) {
		CAPTURE(text);
		String err;
		Node *root = ResourceFormatText::load_scene_from_string(text, "comment.tscn", &err);
		REQUIRE_MESSAGE(root, err.c_str());
		const String saved = ResourceFormatText::save_scene_to_string(root);
		delete root;
		CHECK_MESSAGE(saved.find("[node name=\"o\" type=\"TscnTestNode\"]\n") != String::npos, saved.c_str());
		Node *again = ResourceFormatText::load_scene_from_string(saved, "comment.tscn", &err);
		REQUIRE_MESSAGE(again, err.c_str());
		CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
		delete again;
	}
}

TEST_CASE("[SceneTree][TSCN] A NUL byte is an error; a header without format saves with format=3, then stays") {
	register_tscn_test_types();
	// Both found by fuzz_resource_format_text (seeds tests/fuzz/corpus/tscn/regress_nul_in_header.tscn and
	// regress_load_steps_only_header.tscn).
	String err = load_error(String("[gd_scene format=3]\n\n[node name=\"R\" type=\"TscnTestNode\"]\nlabel = \"a", 67) + String(1, '\0') + "b\"\n");
	CHECK_MESSAGE(err.find("bad.tscn:4: NUL byte") == 0, err.c_str());
	String error;
	Node *root = ResourceFormatText::load_scene_from_string("[gd_scene load_steps=3]\n\n[node name=\"R\" type=\"TscnTestNode\"]\n", "old.tscn", &error);
	REQUIRE_MESSAGE(root, error.c_str());
	const String saved = ResourceFormatText::save_scene_to_string(root);
	delete root;
	CHECK_MESSAGE(saved.find("[gd_scene format=3]\n") == 0, saved.c_str()); // load_steps dropped (nothing to load).
	Node *again = ResourceFormatText::load_scene_from_string(saved, "old.tscn", &error);
	REQUIRE_MESSAGE(again, error.c_str());
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
	delete again;
}

TEST_CASE("[SceneTree][TSCN] A header field right after a quoted value is its own field when saved back") {
	register_tscn_test_types();
	// Found by fuzz_resource_format_text (seed tests/fuzz/corpus/tscn/regress_field_after_quote.tscn): the
	// header fields kept for the save read name="L0"e as one value, and wrote the next field without a name.
	String error;
	Node *root = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n[node name=\"R\" type=\"TscnTestNode\"]\n[node name=\"L0\"e =\"\" parent=\".\"]\n", "field.tscn", &error);
	if (!root) {
		CHECK_MESSAGE(error.find("field.tscn:3:") == 0, error.c_str()); // Refused with a line is fine too.
		return;
	}
	const String saved = ResourceFormatText::save_scene_to_string(root);
	delete root;
	CHECK_MESSAGE(saved.find(" =\"\"") == String::npos, saved.c_str()); // No field without a name.
	Node *again = ResourceFormatText::load_scene_from_string(saved, "field.tscn", &error);
	REQUIRE_MESSAGE(again, error.c_str() << "\n"
										 << saved.c_str());
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
	delete again;
	// A control character between fields is a blank to the tag parser, and so to the split (seed
	// regress_control_char_in_header.tscn).
	root = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n[node name=\"R\" type=\"TscnTestNode\"]\n[node name=\"C\"\x1c\x1cparent=\x07\".\" type= \"TscnTestNode\"]\n", "field.tscn", &error);
	REQUIRE_MESSAGE(root, error.c_str());
	const String saved_c = ResourceFormatText::save_scene_to_string(root);
	delete root;
	again = ResourceFormatText::load_scene_from_string(saved_c, "field.tscn", &error);
	REQUIRE_MESSAGE(again, error.c_str());
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved_c);
	delete again;
	// And between '[' and the tag's name (seed regress_control_char_after_bracket.tscn: the split took
	// the name for the first key and wrote [ext_resource ext_resource="PackedScene" ...]).
	root = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n[\x05"
													  "ext_resource type=\"PackedScene\" path=\"nowhere.tscn\" id=\"1_x\"]\n[\x01\tnode name=\"R\" type=\"TscnTestNode\" unique_id=7]\n",
			"field.tscn", &error);
	REQUIRE_MESSAGE(root, error.c_str());
	const String saved_b = ResourceFormatText::save_scene_to_string(root);
	delete root;
	CHECK_MESSAGE(saved_b.find("[ext_resource type=\"PackedScene\" path=\"nowhere.tscn\" id=\"1_x\"]") != String::npos, saved_b.c_str());
	CHECK_MESSAGE(saved_b.find("[node name=\"R\" type=\"TscnTestNode\" unique_id=7]") != String::npos, saved_b.c_str());
	again = ResourceFormatText::load_scene_from_string(saved_b, "field.tscn", &error);
	REQUIRE_MESSAGE(again, error.c_str());
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved_b);
	delete again;
}

TEST_CASE("[SceneTree][TSCN] Malformed: missing parent or root") {
	register_tscn_test_types();
	String err = load_error(String(HEADER) + "\n[node name=\"B\" type=\"Node\" parent=\"Nowhere/Else\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:10: Parent node \"Nowhere/Else\"") == 0, err.c_str());
	err = load_error(String(HEADER) + "\n[node name=\"Second\" type=\"Node\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:10:") == 0, err.c_str());
	CHECK(err.find("no parent") != String::npos);
	err = load_error("[gd_scene format=3]\n\n[node name=\"Orphan\" type=\"Node\" parent=\".\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:3:") == 0, err.c_str());
	err = load_error("[gd_scene format=3]\n\nlight_energy = 2.0\n");
	CHECK_MESSAGE(err.find("bad.tscn:3: Property 'light_energy' appears before") == 0, err.c_str());
	err = load_error("[gd_scene format=3]\n\n[node name=\"R\"]\n");
	CHECK_MESSAGE(err.find("bad.tscn:3: Root node") == 0, err.c_str());
	err = load_error("[gd_scene format=3]\n");
	CHECK(err.find("no [node]") != String::npos);
	err = load_error("");
	CHECK(err.find("bad.tscn:1:") == 0);
}

TEST_CASE("[SceneTree][TSCN] Missing file gives an error, not a crash") {
	register_tscn_test_types();
	MessageCapture capture;
	String err;
	CHECK(ResourceFormatText::load_scene("/nonexistent/dir/scene.tscn", &err) == nullptr);
	CHECK(err.find("/nonexistent/dir/scene.tscn") == 0);
	CHECK(ResourceFormatText::save_scene(nullptr, "/tmp/x.tscn", &err) == false);
}

} // namespace TestResourceFormatText
