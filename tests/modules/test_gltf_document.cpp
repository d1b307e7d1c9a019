/**************************************************************************/
/*  test_gltf_document.cpp                                                */
/**************************************************************************/

#include "modules/gltf/gltf_document.h"

#include <doctest/doctest.h>

#include <cstring>

namespace TestGLTFDocument {

// One triangle (positions, normals, u16 indices) in an embedded base64 buffer.
static const char *TRIANGLE_GLTF = R"({
 "asset": {"version": "2.0"},
 "scene": 0,
 "scenes": [{"nodes": [0]}],
 "nodes": [{"name": "Tri", "mesh": 0, "translation": [1, 2, 3], "rotation": [0, 0.7071068, 0, 0.7071068], "scale": [2, 2, 2]}],
 "meshes": [{"name": "TriMesh", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
 "materials": [{"name": "Red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.4}}],
 "buffers": [{"byteLength": 80, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAABAAIAAAA="}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}, {"buffer": 0, "byteOffset": 72, "byteLength": 6}],
 "accessors": [
  {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
  {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
  {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}
 ]
})";

// One triangle in three primitives, each with a COLOR_0 of another encoding (glTF 2.0 spec 3.7.2.1): VEC4 FLOAT
// (material 0), VEC3 UNSIGNED_BYTE normalized (no material), VEC4 UNSIGNED_SHORT without the `normalized`
// flag (material 0). The buffer (128 bytes, base64): positions (0, 0, 0), (1, 0, 0), (0, 1, 0) at 0; floats
// (0.25, 0.5, 0.75, 1), (1, 0, 0, 0.5), (0, 1, 0, 0) at 36; bytes (255, 51, 0), (0, 255, 102), (10, 20, 30) at 84;
// shorts (65535, 32768, 0, 65535), (0, 0, 65535, 0), (1, 2, 3, 4) at 96; u16 indices 0, 1, 2 at 120.
static const char *COLOR_GLTF = R"({
 "asset": {"version": "2.0"},
 "scene": 0,
 "scenes": [{"nodes": [0]}],
 "nodes": [{"name": "Tri", "mesh": 0}],
 "meshes": [{"name": "Colored", "primitives": [
  {"attributes": {"POSITION": 0, "COLOR_0": 1}, "indices": 4, "material": 0},
  {"attributes": {"POSITION": 0, "COLOR_0": 2}, "indices": 4},
  {"attributes": {"POSITION": 0, "COLOR_0": 3}, "indices": 4, "material": 0}]}],
 "materials": [{"name": "White", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}}],
 "buffers": [{"byteLength": 128, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAACAPgAAAD8AAEA/AACAPwAAgD8AAAAAAAAAAAAAAD8AAAAAAACAPwAAAAAAAAAA/zMAAP9mChQeAAAA//8AgAAA//8AAAAA//8AAAEAAgADAAQAAAABAAIAAAA="}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 48},
  {"buffer": 0, "byteOffset": 84, "byteLength": 9}, {"buffer": 0, "byteOffset": 96, "byteLength": 24}, {"buffer": 0, "byteOffset": 120, "byteLength": 6}],
 "accessors": [
  {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
  {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC4"},
  {"bufferView": 2, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC3"},
  {"bufferView": 3, "componentType": 5123, "count": 3, "type": "VEC4"},
  {"bufferView": 4, "componentType": 5123, "count": 3, "type": "SCALAR"}
 ]
})";

TEST_CASE("[GLTF] a triangle mesh, its material and node transform are imported") {
	GLTFDocument doc;
	String error;
	REQUIRE_MESSAGE(doc.parse_string(TRIANGLE_GLTF, ".", &error), error);
	REQUIRE(doc.get_meshes().size() == 1);
	const GLTFSurfaceData &s = doc.get_meshes()[0].surfaces[0];
	REQUIRE(s.vertices.size() == 3);
	CHECK(s.vertices[1].is_equal_approx(Vector3(1, 0, 0)));
	CHECK(s.normals[2].is_equal_approx(Vector3(0, 0, 1)));
	CHECK(s.indices == std::vector<uint32_t>{ 0, 1, 2 });
	CHECK(s.material == 0);
	REQUIRE(doc.get_materials().size() == 1);
	CHECK(doc.get_materials()[0].albedo_linear.is_equal_approx(Color(0.8f, 0.1f, 0.1f, 1)));
	CHECK(Math::is_equal_approx(doc.get_materials()[0].roughness, 0.4f));
	CHECK(Math::is_equal_approx(doc.get_materials()[0].metallic, 0.0f));
	REQUIRE(doc.get_root_nodes() == std::vector<int>{ 0 });
	const GLTFNodeData &n = doc.get_nodes()[0];
	CHECK(n.name == "Tri");
	CHECK(n.mesh == 0);
	// 90 degrees about +Y, then scale 2: local +X maps to -Z * 2, translated by (1, 2, 3).
	CHECK(n.transform.xform(Vector3(1, 0, 0)).is_equal_approx(Vector3(1, 2, 1)));
}

TEST_CASE("[GLTF] malformed or missing files give a clear error") {
	GLTFDocument doc;
	String error;
	CHECK_FALSE(doc.parse_string("{ this is not json", ".", &error));
	CHECK(error.find("invalid glTF") != String::npos);

	error.clear();
	CHECK_FALSE(doc.parse_file("/nonexistent/dir/model.gltf", &error));
	CHECK(error.find("/nonexistent/dir/model.gltf") != String::npos);

	// An index that points past the vertex array is rejected, not read out of bounds.
	String bad = TRIANGLE_GLTF;
	size_t at = bad.find("\"count\": 3, \"type\": \"VEC3\", \"min\"");
	REQUIRE(at != String::npos);
	bad.replace(at, 11, "\"count\": 2,");
	// Normals (count 3) now disagree with positions (count 2) and index 2 is out of range.
	error.clear();
	CHECK_FALSE(doc.parse_string(bad, ".", &error));
	// The first problem found is the index past the two vertices; the message names it and the counts.
	CHECK_MESSAGE(error.find("mesh 0 primitive 0: index 2 is out of range (2 vertices)") != String::npos, error);
}

// TRIANGLE_GLTF with p_from replaced by p_to (which must occur exactly once).
static String _patched(const char *p_from, const char *p_to) {
	String s = TRIANGLE_GLTF;
	size_t at = s.find(p_from);
	REQUIRE_MESSAGE(at != String::npos, p_from);
	REQUIRE_MESSAGE(s.find(p_from, at + 1) == String::npos, p_from);
	s.replace(at, strlen(p_from), p_to);
	return s;
}

// Each case is a reproducer from issue 20 (heap overflow, use-after-free, wrapped sums, a thrown length_error):
// the load fails with an error naming the accessor / view and field, and nothing is read out of bounds (the
// sanitizer job runs this file under ASan+UBSan).
TEST_CASE("[GLTF] out-of-range indices, wrapping offsets and huge counts are rejected with a clear error") {
	struct Case {
		const char *from;
		const char *to;
		const char *expect;
	};
	const Case cases[] = {
		{ "{\"buffer\": 0, \"byteOffset\": 0,", "{\"buffer\": 5, \"byteOffset\": 0,", "bufferView 0 field 'buffer' = 5 is out of range (1 buffers)" },
		{ "{\"buffer\": 0, \"byteOffset\": 0,", "{\"buffer\": -1, \"byteOffset\": 0,", "field 'buffer' = -1 is out of range" },
		{ "\"byteOffset\": 36, \"byteLength\": 36", "\"byteOffset\": 18446744073709551600, \"byteLength\": 36", "lies outside buffer 0 (80 bytes)" },
		{ "\"byteOffset\": 72, \"byteLength\": 6", "\"byteOffset\": 72, \"byteLength\": 4000000000", "lies outside buffer 0" },
		{ "{\"bufferView\": 1, \"componentType\": 5126, \"count\": 3,", "{\"bufferView\": 1, \"componentType\": 5126, \"count\": 3, \"byteOffset\": 18446744073709551612,", "field 'byteOffset'" },
		{ "{\"bufferView\": 1, \"componentType\": 5126, \"count\": 3,", "{\"bufferView\": 1, \"componentType\": 5126, \"count\": 4611686018427387904,", "attribute accessor 1: field 'count' = 4611686018427387904 reads past the end of bufferView 1" },
		{ "{\"bufferView\": 2, \"componentType\": 5123, \"count\": 3,", "{\"bufferView\": 2, \"componentType\": 5123, \"count\": 9223372036854775807,", "index accessor 2: field 'count'" },
		{ "{\"bufferView\": 2, \"componentType\": 5123, \"count\": 3,", "{\"bufferView\": 7, \"componentType\": 5123, \"count\": 3,", "accessor[2] invalid bufferView" }, // tinygltf's own check.
		{ "\"indices\": 2,", "\"indices\": 9,", "primitive indices accessor out of bounds" }, // tinygltf's own check.
		{ "{\"buffer\": 0, \"byteOffset\": 0, \"byteLength\": 36}", "{\"buffer\": 0, \"byteOffset\": 0, \"byteLength\": 36, \"byteStride\": 4}", "field 'byteStride' = 4 is smaller than an element (12 bytes)" },
	};
	for (const Case &c : cases) {
		GLTFDocument doc;
		String error;
		bool ok = true;
		CHECK_NOTHROW(ok = doc.parse_string(_patched(c.from, c.to), ".", &error));
		CHECK_FALSE_MESSAGE(ok, c.to);
		CHECK_MESSAGE(error.find(c.expect) != String::npos, "got: ", error, "\nexpected: ", String(c.expect));
		CHECK(doc.get_meshes().empty());
	}
}

TEST_CASE("[GLTF] an image's buffer view outside its buffer is rejected before decoding") {
	// tinygltf checks the image's view and buffer indices but hands the view's bytes over unchecked.
	String s = _patched("\"materials\":", "\"images\": [{\"bufferView\": 2, \"mimeType\": \"image/png\"}], \"materials\":");
	s.replace(s.find("\"byteOffset\": 72, \"byteLength\": 6"), 33, "\"byteOffset\": 72, \"byteLength\": 100000");
	GLTFDocument doc;
	String error;
	CHECK_FALSE(doc.parse_string(s, ".", &error));
	CHECK_MESSAGE(error.find("image 0: bufferView 2 (byteOffset 72, byteLength 100000) lies outside buffer 0 (80 bytes)") != String::npos, error);
}

TEST_CASE("[GLTF] COLOR_0 (float, normalized byte and short) becomes ARRAY_COLOR with vertex_color_use_as_albedo, as Godot's importer") {
	GLTFDocument doc;
	String error;
	REQUIRE_MESSAGE(doc.parse_string(COLOR_GLTF, ".", &error), error);
	REQUIRE(doc.get_meshes().size() == 1);
	const std::vector<GLTFSurfaceData> &surfaces = doc.get_meshes()[0].surfaces;
	REQUIRE(surfaces.size() == 3);
	REQUIRE(surfaces[0].colors.size() == 3);
	CHECK(surfaces[0].colors[0].is_equal_approx(Color(0.25f, 0.5f, 0.75f, 1.0f)));
	CHECK(surfaces[0].colors[1].is_equal_approx(Color(1, 0, 0, 0.5f)));
	REQUIRE(surfaces[1].colors.size() == 3);
	CHECK(surfaces[1].colors[0].is_equal_approx(Color(1.0f, 0.2f, 0.0f, 1.0f))); // VEC3: alpha 1.
	CHECK(surfaces[1].colors[2].is_equal_approx(Color(10 / 255.0f, 20 / 255.0f, 30 / 255.0f, 1.0f)));
	REQUIRE(surfaces[2].colors.size() == 3);
	CHECK(surfaces[2].colors[0].is_equal_approx(Color(1.0f, 32768 / 65535.0f, 0.0f, 1.0f)));
	CHECK(surfaces[2].colors[1].is_equal_approx(Color(0, 0, 1, 0)));
	CHECK(doc.get_meshes()[0].surfaces[0].material == 0);
	CHECK(doc.get_meshes()[0].surfaces[1].material == -1);

	// A file without COLOR_0 gets no colours.
	GLTFDocument plain;
	REQUIRE_MESSAGE(plain.parse_string(TRIANGLE_GLTF, ".", &error), error);
	CHECK(plain.get_meshes()[0].surfaces[0].colors.empty());

	// Unsupported encodings are refused with the attribute named.
	for (const char *bad : { "\"componentType\": 5121, \"normalized\": true, \"count\": 3, \"type\": \"VEC3\"},\n  {\"bufferView\": 3, \"componentType\": 5123, \"count\": 3, \"type\": \"SCALAR\"",
				 "\"componentType\": 5121, \"normalized\": true, \"count\": 3, \"type\": \"VEC3\"},\n  {\"bufferView\": 3, \"componentType\": 5122, \"count\": 3, \"type\": \"VEC4\"" }) {
		const String good = "\"componentType\": 5121, \"normalized\": true, \"count\": 3, \"type\": \"VEC3\"},\n  {\"bufferView\": 3, \"componentType\": 5123, \"count\": 3, \"type\": \"VEC4\"";
		String text = String(COLOR_GLTF);
		const size_t at = text.find(good);
		REQUIRE(at != String::npos);
		text.replace(at, good.size(), bad);
		GLTFDocument broken;
		CHECK_FALSE(broken.parse_string(text, ".", &error));
		CHECK(error.find("COLOR_0") != String::npos);
	}
}

} // namespace TestGLTFDocument

#include <filesystem>
#include <fstream>

namespace TestGLTFDocument {

TEST_CASE("[GLTF] buffer URIs resolve only inside the glTF file's folder") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_gltf_uri";
	std::filesystem::create_directories(dir / "asset" / "sub");
	// 80 bytes: the same data as the embedded buffer, as a file beside the glTF and one above it.
	const String embedded = TRIANGLE_GLTF;
	const String b64_head = "data:application/octet-stream;base64,";
	size_t uri_at = embedded.find(b64_head);
	REQUIRE(uri_at != String::npos);
	std::vector<uint8_t> bin(80, 0);
	{
		std::ofstream f(dir / "asset" / "tri.bin", std::ios::binary);
		f.write(reinterpret_cast<const char *>(bin.data()), bin.size());
		std::ofstream g(dir / "secret.bin", std::ios::binary);
		g.write(reinterpret_cast<const char *>(bin.data()), bin.size());
	}
	size_t uri_end = embedded.find('"', uri_at);
	auto with_uri = [&](const char *p_uri) {
		String s = embedded;
		s.replace(uri_at, uri_end - uri_at, p_uri);
		return s;
	};
	GLTFDocument doc;
	String error;
	const String asset = (dir / "asset").string();
	CHECK_MESSAGE(doc.parse_string(with_uri("tri.bin"), asset, &error), error);
	error.clear();
	CHECK_FALSE(doc.parse_string(with_uri("../secret.bin"), asset, &error));
	CHECK_MESSAGE(error.find("outside the glTF file's folder") != String::npos, error);
	error.clear();
	// An absolute URI is joined to the folder (tinygltf), so it names a file that does not exist there.
	CHECK_FALSE(doc.parse_string(with_uri((dir / "secret.bin").string().c_str()), asset, &error));
	CHECK_MESSAGE(error.find("File not found : " + (dir / "secret.bin").string()) != String::npos, error);
	error.clear();
	CHECK_FALSE(doc.parse_string(with_uri("sub/../../secret.bin"), asset, &error));
	CHECK_MESSAGE(error.find("outside the glTF file's folder") != String::npos, error);
	std::filesystem::remove_all(dir);
}

} // namespace TestGLTFDocument

#include "modules/gltf/register_types.h"
#include "scene/3d/mesh_instance_3d.h"
#include "scene/resources/material.h"
#include "scene/resources/mesh.h"
#include "scene/resources/resource_format_text.h"
#include "tests/scene/scene_test_fixture.h"

#include <filesystem>
#include <fstream>

namespace TestGLTFDocument {

TEST_CASE("[GLTF][SceneTree] a .tscn instances a glTF file as MeshInstance3D nodes with clockwise front faces") {
	SceneTest::DummyServer server;
	initialize_gltf_module();
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_gltf";
	std::filesystem::create_directories(dir);
	{
		std::ofstream f(dir / "tri.gltf");
		f << TRIANGLE_GLTF;
	}
	const String tscn = "[gd_scene load_steps=2 format=3]\n\n"
						"[ext_resource type=\"PackedScene\" path=\"tri.gltf\" id=\"1\"]\n\n"
						"[node name=\"Root\" type=\"Node3D\"]\n\n"
						"[node name=\"Model\" parent=\".\" instance=ExtResource(\"1\")]\n"
						"transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -5)\n";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(tscn, (dir / "scene.tscn").string(), &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	Node *model = root->get_node_or_null("Model");
	REQUIRE(model != nullptr);
	MeshInstance3D *tri = Object::cast_to<MeshInstance3D>(model->get_node_or_null("Tri"));
	REQUIRE(tri != nullptr);
	Ref<ArrayMesh> mesh = tri->get_mesh();
	REQUIRE(mesh.is_valid());
	REQUIRE(mesh->get_surface_count() == 1);
	RS::SurfaceData s = mesh->surface_get_arrays(0);
	// glTF's counter-clockwise (0, 1, 2) becomes Godot's clockwise (0, 2, 1): cross(b - a, c - a) opposes the normal.
	CHECK(s.indices == std::vector<uint32_t>{ 0, 2, 1 });
	Vector3 face = (s.vertices[s.indices[1]] - s.vertices[s.indices[0]]).cross(s.vertices[s.indices[2]] - s.vertices[s.indices[0]]);
	CHECK(face.dot(s.normals[0]) < 0);
	Ref<StandardMaterial3D> mat = mesh->surface_get_material(0);
	REQUIRE(mat.is_valid());
	// Linear 0.8 in glTF is sRGB ~0.906 in StandardMaterial3D.
	CHECK(Math::is_equal_approx(mat->get_albedo().r, Color::linear_to_srgb_channel(0.8f), 1e-5f));
	CHECK(Math::is_equal_approx(mat->get_roughness(), 0.4f));

	delete root;
	// A missing glTF file is a warning naming it; the rest of the scene still loads and the
	// instance is kept as a placeholder (written back on save) with nothing under it.
	set_error_print_silenced(true);
	Node *partial = ResourceFormatText::load_scene_from_string(tscn, (dir / "missing" / "scene.tscn").string(), &error);
	set_error_print_silenced(false);
	REQUIRE(partial != nullptr);
	REQUIRE(partial->get_node_or_null("Model") != nullptr);
	CHECK(partial->get_node_or_null("Model")->get_class() == "MissingNode");
	CHECK(partial->get_node_or_null("Model")->get_child_count() == 0);
	CHECK(ResourceFormatText::save_scene_to_string(partial).find("instance=ExtResource(") != String::npos);
	delete partial;
	uninitialize_gltf_module();
	std::filesystem::remove_all(dir);
}

TEST_CASE("[GLTF][SceneTree] a primitive with COLOR_0 draws its colours: ARRAY_COLOR and vertex_color_use_as_albedo (linear)") {
	SceneTest::DummyServer server;
	GLTFDocument doc;
	String error;
	REQUIRE_MESSAGE(doc.parse_string(COLOR_GLTF, ".", &error), error);
	Node *root = gltf_generate_scene(doc, "Colored", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	MeshInstance3D *tri = Object::cast_to<MeshInstance3D>(root->get_node_or_null("Tri"));
	REQUIRE(tri != nullptr);
	Ref<ArrayMesh> mesh = tri->get_mesh();
	REQUIRE(mesh.is_valid());
	REQUIRE(mesh->get_surface_count() == 3);
	RS::SurfaceData s = mesh->surface_get_arrays(0);
	REQUIRE(s.colors.size() == 3);
	CHECK(s.colors[0].is_equal_approx(Color(0.25f, 0.5f, 0.75f, 1.0f)));
	for (int i = 0; i < 3; i++) {
		Ref<StandardMaterial3D> mat = mesh->surface_get_material(i);
		REQUIRE(mat.is_valid());
		CHECK(mat->get_flag_vertex_color_use_as_albedo());
		CHECK_FALSE(mat->get_flag_vertex_color_is_srgb()); // glTF colours are linear.
	}
	CHECK(mesh->surface_get_material(0) == mesh->surface_get_material(2)); // The file's material, flagged.
	CHECK(mesh->surface_get_material(1) != mesh->surface_get_material(0)); // A default one for no material.
	delete root;

	// Without COLOR_0 the material keeps its flag off.
	GLTFDocument plain;
	REQUIRE_MESSAGE(plain.parse_string(TRIANGLE_GLTF, ".", &error), error);
	Node *plain_root = gltf_generate_scene(plain, "Plain", &error);
	REQUIRE(plain_root != nullptr);
	Ref<ArrayMesh> plain_mesh = Object::cast_to<MeshInstance3D>(plain_root->get_node_or_null("Tri"))->get_mesh();
	Ref<StandardMaterial3D> plain_mat = plain_mesh->surface_get_material(0);
	REQUIRE(plain_mat.is_valid());
	CHECK_FALSE(plain_mat->get_flag_vertex_color_use_as_albedo());
	CHECK(plain_mesh->surface_get_arrays(0).colors.empty());
	delete plain_root;
}

} // namespace TestGLTFDocument
