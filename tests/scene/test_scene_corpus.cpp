/**************************************************************************/
/*  test_scene_corpus.cpp                                                 */
/**************************************************************************/
/* Real Godot 4 scenes load whole (issue 15): a small committed project   */
/* (tests/scene/data/project, written in Godot 4.4's text conventions)    */
/* with placeholders, an instanced scene from a subfolder, an override    */
/* section, a .tres material, uids, groups, unique_id, a script,          */
/* metadata, [connection] and [editable]; and load-once instancing.       */

#include "core/error/error_macros.h"
#include "core/io/missing_resource.h"
#include "scene/3d/mesh_instance_3d.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"
#include "scene/resources/material.h"
#include "scene/resources/primitive_meshes.h"
#include "scene/resources/resource_format_text.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace TestSceneCorpus {

static const String PROJECT = String(GODOT_AREA_ROOT) + "/tests/scene/data/project";

static String read_text(const String &p_path) {
	std::ifstream f(p_path, std::ios::binary);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

struct Capture {
	ErrorHandlerList handler;
	std::vector<String> warnings;
	std::vector<String> errors;
	Capture() {
		handler.callback = [this](ErrorHandlerType p_type, const String &p_text) {
			(p_type == ERR_HANDLER_WARNING ? warnings : errors).push_back(p_text);
		};
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~Capture() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
	int count(const String &p_a, const String &p_b = String()) const {
		int n = 0;
		for (const String &w : warnings) {
			n += w.find(p_a) != String::npos && w.find(p_b) != String::npos;
		}
		return n;
	}
};

TEST_CASE("[ResourceFormatText] A real Godot scene round-trips exactly: placeholders, uids, groups, scripts, connections") {
	SceneTest::DummyServer server;
	String path = PROJECT + "/main.tscn";
	String original = read_text(path);
	REQUIRE(!original.empty());
	Capture capture;
	String error;
	Node *root = ResourceFormatText::load_scene(path, &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(capture.errors.empty());
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved == original);
	if (saved != original) {
		MESSAGE(saved);
	}
	// What is kept is reported, once per distinct problem.
	CHECK(capture.count("main.tscn:20:", "StaticBody3D") == 1);
	// The missing texture is named (by the loader, or, when another test's png hook
	// answered, by the property that could not take it).
	CHECK(capture.count("missing.png") + capture.count("main.tscn:12:", "albedo_texture") >= 1);
	CHECK(ResourceFormatText::get_last_load_problem_count() > 0);
	delete root;
}

TEST_CASE("[ResourceFormatText] A placeholder acts as Node3D and keeps its children, type and properties") {
	SceneTest::DummyServer server;
	Capture capture;
	String error;
	Node *root = ResourceFormatText::load_scene(PROJECT + "/main.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	MissingNode *floor = Object::cast_to<MissingNode>(root->get_node_or_null("Floor"));
	REQUIRE(floor != nullptr);
	CHECK(floor->get_original_class() == "StaticBody3D");
	MeshInstance3D *mesh = Object::cast_to<MeshInstance3D>(root->get_node_or_null("Floor/Mesh"));
	REQUIRE(mesh != nullptr);
	CHECK(mesh->get_global_transform().origin.is_equal_approx(Vector3(0, -0.5f, 0)));
	REQUIRE(mesh->get_mesh().is_valid());
	Ref<BoxMesh> box = mesh->get_mesh();
	REQUIRE(box.is_valid());
	Ref<StandardMaterial3D> mat = box->get_material();
	REQUIRE(mat.is_valid());
	CHECK(mat->get_albedo().is_equal_approx(Color(0.8f, 0.2f, 0.1f, 1)));
	// The unknown child type and its unknown resource are placeholders too.
	CHECK(Object::cast_to<MissingNode>(root->get_node_or_null("Floor/Shape")) != nullptr);
	CHECK(Object::cast_to<MissingNode>(root->get_node_or_null("Player"))->get_original_class() == "CharacterBody3D");
	// The camera under a placeholder keeps its place.
	CHECK(root->get_node_or_null("Player/Camera3D") != nullptr);
	delete root;
}

TEST_CASE("[ResourceFormatText] res:// resolves at project.godot from a subfolder; override sections apply; .tres loads") {
	SceneTest::DummyServer server;
	Capture capture;
	String error;
	Node *root = ResourceFormatText::load_scene(PROJECT + "/main.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	// sub/crate.tscn names res://materials/wood.tres: the project root, not sub/.
	MeshInstance3D *box = Object::cast_to<MeshInstance3D>(root->get_node_or_null("Crate/Box"));
	REQUIRE(box != nullptr);
	Ref<BoxMesh> mesh = box->get_mesh();
	REQUIRE(mesh.is_valid());
	Ref<StandardMaterial3D> wood = mesh->get_material();
	REQUIRE(wood.is_valid());
	CHECK(wood->get_albedo().is_equal_approx(Color(0.6f, 0.4f, 0.2f, 1)));
	CHECK(wood->get_roughness() == doctest::Approx(0.8));
	// [node name="Box" parent="Crate" index="0"] moved the instanced box up.
	CHECK(box->get_transform().origin.is_equal_approx(Vector3(0, 0.5f, 0)));
	CHECK(box->get_global_transform().origin.is_equal_approx(Vector3(2, 0.5f, 0)));
	CHECK(capture.count("no project.godot") == 0);

	// Editing an instance writes only what differs from the instanced scene.
	box->set_transform(Transform3D(Basis(), Vector3(0, 0.75f, 0)));
	Node3D *added = new Node3D;
	added->set_name("Marker");
	box->add_child(added);
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("[node name=\"Box\" parent=\"Crate\" index=\"0\"]\ntransform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.75, 0)\n") != String::npos);
	CHECK(saved.find("[node name=\"Marker\" type=\"Node3D\" parent=\"Crate/Box\"]") != String::npos);
	CHECK(saved.find("mass = 2.0") == String::npos); // The instanced scene's own values stay there.
	CHECK(saved.find("BoxMesh_c1r2t") == String::npos);
	delete root;
}

TEST_CASE("[ResourceFormatText] A scene without project.godot warns once and resolves res:// at its folder") {
	SceneTest::DummyServer server;
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_rootless_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	{
		std::ofstream(dir / "a.tres") << "[gd_resource type=\"StandardMaterial3D\" format=3]\n\n[resource]\nroughness = 0.25\n";
		std::ofstream(dir / "s.tscn") << "[gd_scene format=3]\n\n[ext_resource type=\"Material\" path=\"res://a.tres\" id=\"1_a\"]\n\n[sub_resource type=\"BoxMesh\" id=\"B\"]\nmaterial = ExtResource(\"1_a\")\n\n[node name=\"R\" type=\"MeshInstance3D\"]\nmesh = SubResource(\"B\")\n";
	}
	Capture capture;
	String error;
	for (int i = 0; i < 2; i++) {
		Node *root = ResourceFormatText::load_scene((dir / "s.tscn").string(), &error);
		REQUIRE_MESSAGE(root != nullptr, error.c_str());
		Ref<BoxMesh> mesh = Object::cast_to<MeshInstance3D>(root)->get_mesh();
		Ref<StandardMaterial3D> mat = mesh->get_material();
		REQUIRE(mat.is_valid());
		CHECK(mat->get_roughness() == doctest::Approx(0.25));
		delete root;
	}
	CHECK(capture.count("no project.godot") == 1);
	std::filesystem::remove_all(dir);
}

static int count_loads = 0;

static Node *_count_loader(const String &p_path, String *r_error) {
	count_loads++;
	MeshInstance3D *mi = new MeshInstance3D;
	Ref<BoxMesh> box;
	box.instantiate();
	mi->set_mesh(box);
	Node3D *root = new Node3D;
	root->set_name("Model");
	mi->set_name("Body");
	root->add_child(mi);
	return root;
}

TEST_CASE("[ResourceFormatText] 1,000 instances of one file load it once and share its meshes") {
	SceneTest::DummyServer server;
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_instances_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	{
		std::ofstream(dir / "project.godot") << "config_version=5\n";
		std::ofstream(dir / "model.countscene") << "x";
		std::ofstream f(dir / "many.tscn");
		f << "[gd_scene format=3]\n\n[ext_resource type=\"PackedScene\" path=\"res://model.countscene\" id=\"1_m\"]\n\n[node name=\"Root\" type=\"Node3D\"]\n";
		for (int i = 0; i < 1000; i++) {
			f << "\n[node name=\"M" << i << "\" parent=\".\" instance=ExtResource(\"1_m\")]\ntransform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, " << i << ", 0, 0)\n";
		}
	}
	ResourceFormatText::add_scene_loader("countscene", _count_loader);
	count_loads = 0;
	String error;
	Node *root = ResourceFormatText::load_scene((dir / "many.tscn").string(), &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(count_loads == 1);
	REQUIRE(root->get_child_count() == 1000);
	Ref<Mesh> first = Object::cast_to<MeshInstance3D>(root->get_node_or_null("M0/Body"))->get_mesh();
	REQUIRE(first.is_valid());
	bool all_shared = true;
	for (int i = 0; i < 1000; i++) {
		MeshInstance3D *mi = Object::cast_to<MeshInstance3D>(root->get_node_or_null("M" + itos(i) + "/Body"));
		all_shared = all_shared && mi && mi->get_mesh() == first;
	}
	CHECK(all_shared);
	CHECK(Object::cast_to<Node3D>(root->get_node_or_null("M999"))->get_transform().origin.is_equal_approx(Vector3(999, 0, 0)));
	// A second load while instances live reuses the template.
	Node *again = ResourceFormatText::load_scene((dir / "many.tscn").string(), &error);
	REQUIRE(again != nullptr);
	CHECK(count_loads == 1);
	// The save keeps the instances as instances.
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("[node name=\"M5\" parent=\".\" instance=ExtResource(\"1_m\")]\ntransform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 0, 0)\n") != String::npos);
	CHECK(saved.find("Body") == String::npos);
	delete again;
	delete root;
	// With every instance gone the template is freed; the next load parses again.
	root = ResourceFormatText::load_scene((dir / "many.tscn").string(), &error);
	CHECK(count_loads == 2);
	delete root;
	ResourceFormatText::remove_scene_loader("countscene");
	std::filesystem::remove_all(dir);
}

TEST_CASE("[ResourceFormatText] A value a typed property refuses is kept with its sub-resource") {
	// Issue 15: a MeshInstance3D's ShaderMaterial override and a Sky's PanoramaSkyMaterial were set to
	// null by their setters (not our classes) and the save lost the lines and the sub-resources.
	const char *text = R"([gd_scene format=3]

[sub_resource type="ShaderMaterial" id="ShaderMaterial_a"]
render_priority = 0

[sub_resource type="QuadMesh" id="QuadMesh_a"]

[sub_resource type="PanoramaSkyMaterial" id="PanoramaSkyMaterial_a"]
energy_multiplier = 2.0

[sub_resource type="Sky" id="Sky_a"]
sky_material = SubResource("PanoramaSkyMaterial_a")

[sub_resource type="Environment" id="Environment_a"]
background_mode = 2
sky = SubResource("Sky_a")

[node name="Root" type="Node3D"]

[node name="WorldEnvironment" type="WorldEnvironment" parent="."]
environment = SubResource("Environment_a")

[node name="Quad" type="MeshInstance3D" parent="."]
mesh = SubResource("QuadMesh_a")
surface_material_override/0 = SubResource("ShaderMaterial_a")
)";
	SceneTest::DummyServer server;
	Capture capture;
	String err;
	Node *root = ResourceFormatText::load_scene_from_string(text, "refused.tscn", &err);
	REQUIRE_MESSAGE(root != nullptr, err.c_str());
	CHECK(capture.count("refused.tscn:12:", "sky_material") == 1);
	CHECK(capture.count("refused.tscn:25:", "surface_material_override/0") == 1);
	const String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("[sub_resource type=\"ShaderMaterial\" id=\"ShaderMaterial_a\"]\nrender_priority = 0\n") != String::npos);
	CHECK(saved.find("surface_material_override/0 = SubResource(\"ShaderMaterial_a\")\n") != String::npos);
	CHECK(saved.find("[sub_resource type=\"PanoramaSkyMaterial\" id=\"PanoramaSkyMaterial_a\"]\nenergy_multiplier = 2.0\n") != String::npos);
	CHECK(saved.find("sky_material = SubResource(\"PanoramaSkyMaterial_a\")\n") != String::npos);
	delete root;
}

TEST_CASE("[ResourceFormatText] A default value the file wrote out is written back") {
	// Godot writes some defaults (alpha_scissor_threshold = 0.5, an identity transform) and properties
	// we hide; a load/save keeps those lines (issue 15's survey: 3 + 1 + 4 lines).
	SceneTest::DummyServer server;
	const char *text = R"([gd_scene format=3]

[sub_resource type="StandardMaterial3D" id="StandardMaterial3D_a"]
transparency = 2
alpha_scissor_threshold = 0.5

[node name="Root" type="Node3D"]
transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0)

[node name="Quad" type="MeshInstance3D" parent="."]
material_override = SubResource("StandardMaterial3D_a")

[node name="Lamp" type="OmniLight3D" parent="."]
light_intensity_lumens = 800.0
light_temperature = 5000.0
)";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "defaults.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	const String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK(saved.find("transparency = 2\nalpha_scissor_threshold = 0.5\n") != String::npos);
	CHECK(saved.find("[node name=\"Root\" type=\"Node3D\"]\ntransform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0)\n") != String::npos);
	// Hidden properties (physical light units are off without project settings) the file had.
	CHECK(saved.find("light_intensity_lumens = 800.0\nlight_temperature = 5000.0\n") != String::npos);
	CHECK(saved.find("visible") == String::npos); // Defaults the file did not write stay out.
	delete root;
}

TEST_CASE("[ResourceFormatText] Warnings: one line per distinct problem with a count") {
	SceneTest::DummyServer server;
	String text = "[gd_scene format=3]\n\n[node name=\"Root\" type=\"Node3D\"]\n";
	for (int i = 0; i < 57; i++) {
		text += "\n[node name=\"Body" + itos(i) + "\" type=\"StaticBody3D\" parent=\".\"]\ncollision_layer = 2\n";
	}
	Capture capture;
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "bodies.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(capture.count("StaticBody3D") == 1);
	CHECK(capture.count("bodies.tscn:5:", "\u00d757") == 1);
	CHECK(capture.warnings.size() == 1);
	CHECK(ResourceFormatText::get_last_load_problem_count() == 1);
	delete root;
	// --verbose lists each occurrence as well.
	capture.warnings.clear();
	ResourceFormatText::set_verbose(true);
	root = ResourceFormatText::load_scene_from_string(text, "bodies.tscn", &error);
	ResourceFormatText::set_verbose(false);
	CHECK(capture.count("StaticBody3D") == 58);
	delete root;
}

} // namespace TestSceneCorpus

namespace TestSceneCorpus {

TEST_CASE("[ResourceFormatText] Sections under nodes an instance does not make are kept as text, not a failed load") {
	SceneTest::DummyServer server;
	std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ga_orphans_" + itos((long long)getpid()));
	std::filesystem::create_directories(dir);
	std::ofstream(dir / "project.godot") << "config_version=5\n";
	std::ofstream(dir / "model.countscene") << "x";
	const String text = R"([gd_scene format=3 uid="uid://borphans00001"]

[ext_resource type="PackedScene" uid="uid://dmodel0000001" path="res://model.countscene" id="1_m0d3l"]

[sub_resource type="BoxMesh" id="BoxMesh_h4t00"]
size = Vector3(0.2, 0.2, 0.2)

[node name="Root" type="Node3D"]

[node name="Bot" parent="." instance=ExtResource("1_m0d3l")]

[node name="Hat" type="MeshInstance3D" parent="Bot/Armature/Skeleton3D"]
mesh = SubResource("BoxMesh_h4t00")

[node name="Feather" type="Node3D" parent="Bot/Armature/Skeleton3D/Hat"]
)";
	ResourceFormatText::add_scene_loader("countscene", _count_loader);
	Capture capture;
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, (dir / "orphans.tscn").string(), &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(capture.count("orphans.tscn:12:", "Bot/Armature/Skeleton3D") == 1);
	CHECK(root->get_node_or_null("Bot/Body") != nullptr);
	CHECK(ResourceFormatText::save_scene_to_string(root) == text);
	delete root;
	// A missing parent outside any instance is still malformed.
	Node *bad = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n\n[node name=\"R\" type=\"Node3D\"]\n\n[node name=\"A\" type=\"Node3D\" parent=\"Nope\"]\n", "bad.tscn", &error);
	CHECK(bad == nullptr);
	CHECK(error.find("bad.tscn:5: Parent node \"Nope\"") == 0);
	ResourceFormatText::remove_scene_loader("countscene");
	std::filesystem::remove_all(dir);
}

TEST_CASE("[ResourceFormatText] A node declared before its parent loads under it, and saving twice gives one text") {
	SceneTest::DummyServer server;
	// Found by fuzz_resource_format_text: under a root of an unknown type, "Omni" (before "Floor") was
	// kept as text and written after the nodes, where the next load found its parent: the second save
	// moved it. It now loads under "Floor" once that is read, with a warning, in both loads.
	const String text = R"([gd_scene format=3]

[node name="Root" type="Node6D"]

[node name="Omni" type="OmniLight3D" parent="Floor"]
omni_range = 5.0

[node name="Bulb" type="Node3D" parent="Floor/Omni"]

[node name="Floor" type="Node3D" parent="."]

[node name="Wall" type="Node3D" parent="."]
)";
	Capture capture;
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "late.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error.c_str());
	CHECK(capture.count("late.tscn:5:", "comes before its parent \"Floor\"") == 1);
	CHECK(capture.count("late.tscn:8:", "comes before its parent \"Floor/Omni\"") == 1);
	Node *omni = root->get_node_or_null("Floor/Omni");
	REQUIRE(omni != nullptr);
	CHECK(omni->get_class() == "OmniLight3D");
	CHECK(omni->get("omni_range").to_float() == doctest::Approx(5.0));
	CHECK(root->get_node_or_null("Floor/Omni/Bulb") != nullptr);
	const String saved = ResourceFormatText::save_scene_to_string(root);
	delete root;
	CHECK(saved.find("[node name=\"Floor\"") < saved.find("[node name=\"Omni\""));
	CHECK(saved.find("[node name=\"Omni\"") < saved.find("[node name=\"Wall\""));
	capture.warnings.clear();
	Node *again = ResourceFormatText::load_scene_from_string(saved, "late.tscn", &error);
	REQUIRE_MESSAGE(again != nullptr, error.c_str());
	CHECK(capture.count("comes before its parent") == 0);
	CHECK(ResourceFormatText::save_scene_to_string(again) == saved);
	delete again;
	// A chain declared deepest first: each waits on its parent's path and is woken when that is loaded
	// (rechecking every waiting path after each node made a 2,000-deep chain take 100 s).
	String chain = "[gd_scene format=3]\n\n[node name=\"R\" type=\"Node3D\"]\n";
	String chain_path = "N0";
	std::vector<String> chain_parents = { "." };
	for (int i = 1; i < 64; i++) {
		chain_parents.push_back(chain_path);
		chain_path += "/N" + itos(i);
	}
	for (int i = 63; i >= 0; i--) {
		chain += "\n[node name=\"N" + itos(i) + "\" type=\"Node3D\" parent=\"" + chain_parents[i] + "\"]\n";
	}
	Node *deep = ResourceFormatText::load_scene_from_string(chain, "chain.tscn", &error);
	REQUIRE_MESSAGE(deep != nullptr, error.c_str());
	CHECK(deep->get_node_or_null(chain_path) != nullptr);
	delete deep;
	// The same under a root of a known type (an error before: the parent did not exist yet).
	Node *known = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n\n[node name=\"R\" type=\"Node3D\"]\n\n[node name=\"A\" type=\"Node3D\" parent=\"B\"]\n\n[node name=\"B\" type=\"Node3D\" parent=\".\"]\n", "known.tscn", &error);
	REQUIRE_MESSAGE(known != nullptr, error.c_str());
	CHECK(known->get_node_or_null("B/A") != nullptr);
	delete known;
	// A parent below a node the file declares (not an instance): nothing can make it, so an error,
	// named at the section's line, even when the root's type is unknown.
	Node *bad = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n\n[node name=\"R\" type=\"Node6D\"]\n\n[node name=\"A\" type=\"Node3D\" parent=\"P/Q\"]\n\n[node name=\"P\" type=\"Node3D\" parent=\".\"]\n", "pq.tscn", &error);
	CHECK(bad == nullptr);
	CHECK(error.find("pq.tscn:5: Parent node \"P/Q\" of node \"A\" does not exist.") == 0);
	// Read again after the last section, a node may name a sub_resource declared below it, even when
	// that sub_resource is the file's last section.
	Node *late_res = ResourceFormatText::load_scene_from_string("[gd_scene format=3]\n\n[node name=\"R\" type=\"Node3D\"]\n\n[node name=\"A\" type=\"MeshInstance3D\" parent=\"B\"]\nmesh = SubResource(\"M\")\n\n[node name=\"B\" type=\"Node3D\" parent=\".\"]\n\n[sub_resource type=\"BoxMesh\" id=\"M\"]\n", "late_res.tscn", &error);
	REQUIRE_MESSAGE(late_res != nullptr, error.c_str());
	Node *a = late_res->get_node_or_null("B/A");
	REQUIRE(a != nullptr);
	CHECK(a->get("mesh").get_type() == Variant::OBJECT);
	delete late_res;
	// A comment closing the file is not part of the section kept as text before it (found by the fuzzer:
	// the saver wrote that section before the unknown one, and the next load gave the comment to that).
	const String kept = "[gd_scene format=3]\n\n[node name=\"R\" type=\"Node6D\"]\n\n[unknown_section a=1]\n\n[node name=\"K\" type=\"Node3D\" parent=\"Made/By/It\"]\nvisible = false\n; the end\n";
	Node *first = ResourceFormatText::load_scene_from_string(kept, "kept.tscn", &error);
	REQUIRE_MESSAGE(first != nullptr, error.c_str());
	const String kept_saved = ResourceFormatText::save_scene_to_string(first);
	delete first;
	CHECK(kept_saved.find("[node name=\"K\"") < kept_saved.find("[unknown_section"));
	Node *second = ResourceFormatText::load_scene_from_string(kept_saved, "kept.tscn", &error);
	REQUIRE_MESSAGE(second != nullptr, error.c_str());
	CHECK(ResourceFormatText::save_scene_to_string(second) == kept_saved);
	delete second;
}

} // namespace TestSceneCorpus
