/**************************************************************************/
/*  test_gltf_document.cpp                                                */
/**************************************************************************/

#include "modules/gltf/gltf_document.h"

#include <doctest/doctest.h>

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
	CHECK_MESSAGE(!error.empty(), "an inconsistent mesh must be reported");
}

} // namespace TestGLTFDocument
