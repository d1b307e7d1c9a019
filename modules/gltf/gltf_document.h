/**************************************************************************/
/*  gltf_document.h                                                       */
/**************************************************************************/
/* glTF 2.0 import (Godot's GLTFDocument, reduced): meshes (triangles),   */
/* metallic-roughness PBR materials, vertex colours (COLOR_0) and the     */
/* node hierarchy. Parsing uses                                           */
/* tinygltf; the result is plain data, turned into MeshInstance3D nodes   */
/* by gltf_scene_builder.cpp.                                             */

#pragma once

#include "core/math/color.h"
#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/string/ustring.h"

#include <cstdint>
#include <vector>

struct GLTFSurfaceData {
	std::vector<Vector3> vertices;
	std::vector<Vector3> normals; // Generated (flat per face) when the file has none.
	std::vector<Vector2> uvs; // Empty when the file has none.
	std::vector<float> tangents; // 4 per vertex (xyz, handedness w); empty when absent.
	// COLOR_0 (glTF 2.0 spec 3.7.2.1: linear RGB or RGBA, multiplies the base colour; alpha 1 for VEC3);
	// empty when absent.
	std::vector<Color> colors;
	std::vector<uint32_t> indices; // Triangle list, counter-clockwise front faces (glTF's convention).
	int material = -1;
};

struct GLTFMeshData {
	String name;
	std::vector<GLTFSurfaceData> surfaces;
};

struct GLTFImageData {
	String name;
	int width = 0;
	int height = 0;
	std::vector<uint8_t> rgba8; // As stored in the file (sRGB for base colour, linear for normal maps).
};

struct GLTFMaterialData {
	String name;
	// glTF stores linear base colour factors; Godot's StandardMaterial3D albedo_color is sRGB-encoded,
	// so the importer converts with Color::linear_to_srgb() as Godot's importer does.
	Color albedo_linear = Color(1, 1, 1, 1);
	float roughness = 1.0f;
	float metallic = 1.0f; // glTF's default metallicFactor is 1.
	int albedo_image = -1;
	int normal_image = -1;
	float normal_scale = 1.0f;
};

struct GLTFNodeData {
	String name;
	Transform3D transform; // Local to the parent.
	int mesh = -1;
	std::vector<int> children;
};

class GLTFDocument {
	std::vector<GLTFMeshData> meshes;
	std::vector<GLTFMaterialData> materials;
	std::vector<GLTFImageData> images;
	std::vector<GLTFNodeData> nodes;
	std::vector<int> root_nodes;

	// p_model is a tinygltf::Model (kept out of this header so users need not include tinygltf).
	bool _convert(const void *p_model, String *r_error);
	bool _parse(const uint8_t *p_data, size_t p_size, bool p_binary, const String &p_base_dir, String *r_error);

public:
	// Reads a .gltf (JSON) or .glb file. On failure returns false and names the file and problem in r_error.
	bool parse_file(const String &p_path, String *r_error);
	// Parses glTF JSON text; external buffers/images are resolved relative to p_base_dir.
	// External URIs must resolve inside p_base_dir. No exception escapes either call; on failure the document is empty.
	bool parse_string(const String &p_text, const String &p_base_dir, String *r_error);
	// Parses a GLB container held in memory (the fuzz harness uses this).
	bool parse_glb(const uint8_t *p_data, size_t p_size, const String &p_base_dir, String *r_error);

	const std::vector<GLTFMeshData> &get_meshes() const { return meshes; }
	const std::vector<GLTFMaterialData> &get_materials() const { return materials; }
	const std::vector<GLTFImageData> &get_images() const { return images; }
	const std::vector<GLTFNodeData> &get_nodes() const { return nodes; }
	const std::vector<int> &get_root_nodes() const { return root_nodes; }
};

class Node;

// Builds a node tree from a parsed document: a Node3D root named p_root_name, one Node3D per glTF
// node (MeshInstance3D when it has a mesh) with ArrayMesh surfaces and StandardMaterial3D materials.
// Returns null with r_error on failure. The caller owns the result.
Node *gltf_generate_scene(const GLTFDocument &p_doc, const String &p_root_name, String *r_error);
