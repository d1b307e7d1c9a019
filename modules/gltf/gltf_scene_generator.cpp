/**************************************************************************/
/*  gltf_scene_generator.cpp                                              */
/**************************************************************************/
/* Turns parsed glTF data into scene nodes (Godot's GLTFDocument::        */
/* generate_scene, reduced). glTF metallic-roughness maps one-to-one onto  */
/* StandardMaterial3D's albedo/metallic/roughness; base colour factors are */
/* linear in glTF and sRGB in Godot, hence linear_to_srgb(). A primitive  */
/* with COLOR_0 gets ARRAY_COLOR and, as Godot's importer does, its       */
/* material vertex_color_use_as_albedo (glTF: COLOR_0 multiplies the base */
/* colour; linear, so not vertex_color_is_srgb); without a material, a    */
/* default StandardMaterial3D with that flag.                             */

#include "modules/gltf/gltf_document.h"

#include "core/error/error_macros.h"
#include "scene/3d/mesh_instance_3d.h"
#include "scene/3d/node_3d.h"
#include "scene/resources/material.h"
#include "scene/resources/mesh.h"
#include "scene/resources/texture.h"

namespace {

Ref<ImageTexture> _make_texture(const GLTFImageData &p_image) {
	if (p_image.width <= 0 || p_image.height <= 0) {
		return Ref<ImageTexture>();
	}
	Image img(p_image.width, p_image.height);
	for (int y = 0; y < p_image.height; y++) {
		for (int x = 0; x < p_image.width; x++) {
			const uint8_t *t = &p_image.rgba8[(size_t(y) * p_image.width + x) * 4];
			img.set_pixel(x, y, Color(t[0] / 255.0f, t[1] / 255.0f, t[2] / 255.0f, t[3] / 255.0f));
		}
	}
	return ImageTexture::create_from_image(img);
}

} // namespace

Node *gltf_generate_scene(const GLTFDocument &p_doc, const String &p_root_name, String *r_error) {
	std::vector<Ref<ImageTexture>> textures;
	for (const GLTFImageData &img : p_doc.get_images()) {
		textures.push_back(_make_texture(img));
	}
	std::vector<Ref<StandardMaterial3D>> materials;
	for (const GLTFMaterialData &m : p_doc.get_materials()) {
		Ref<StandardMaterial3D> mat = Ref<StandardMaterial3D>(new StandardMaterial3D);
		mat->set_name(m.name);
		mat->set_albedo(m.albedo_linear.linear_to_srgb());
		mat->set_roughness(Math::clamp(m.roughness, 0.0f, 1.0f));
		mat->set_metallic(Math::clamp(m.metallic, 0.0f, 1.0f));
		if (m.albedo_image >= 0 && textures[m.albedo_image].is_valid()) {
			mat->set_albedo_texture(textures[m.albedo_image]);
		}
		if (m.normal_image >= 0 && textures[m.normal_image].is_valid()) {
			mat->set_normal_enabled(true);
			mat->set_normal_texture(textures[m.normal_image]);
			mat->set_normal_scale(m.normal_scale);
		}
		materials.push_back(mat);
	}
	Ref<StandardMaterial3D> vertex_color_material; // For primitives with COLOR_0 and no material (made once).
	std::vector<Ref<ArrayMesh>> meshes;
	for (const GLTFMeshData &md : p_doc.get_meshes()) {
		Ref<ArrayMesh> mesh = Ref<ArrayMesh>(new ArrayMesh);
		mesh->set_name(md.name);
		for (const GLTFSurfaceData &s : md.surfaces) {
			RS::SurfaceData arrays;
			arrays.vertices = s.vertices;
			arrays.normals = s.normals;
			arrays.uvs = s.uvs;
			arrays.tangents = s.tangents;
			arrays.colors = s.colors;
			// glTF front faces are counter-clockwise; the engine (as Godot) treats clockwise as front,
			// so every triangle's winding is reversed on import.
			arrays.indices = s.indices;
			for (size_t i = 0; i + 2 < arrays.indices.size(); i += 3) {
				std::swap(arrays.indices[i + 1], arrays.indices[i + 2]);
			}
			if (!mesh->add_surface(arrays)) {
				*r_error = vformat("mesh '%s' has an invalid surface", md.name.c_str());
				return nullptr;
			}
			Ref<StandardMaterial3D> material = s.material >= 0 ? materials[s.material] : Ref<StandardMaterial3D>();
			if (!s.colors.empty()) {
				if (material.is_null()) {
					if (vertex_color_material.is_null()) {
						vertex_color_material = Ref<StandardMaterial3D>(new StandardMaterial3D);
					}
					material = vertex_color_material;
				}
				// A surface of this material without COLOR_0 reads white (the renderers' stand-in), as in Godot.
				material->set_flag_vertex_color_use_as_albedo(true);
			}
			if (material.is_valid()) {
				mesh->surface_set_material(mesh->get_surface_count() - 1, material);
			}
		}
		meshes.push_back(mesh);
	}

	const std::vector<GLTFNodeData> &nodes = p_doc.get_nodes();
	Node3D *root = new Node3D;
	root->set_name(p_root_name);
	// Depth-first, with a guard against cycles (a node listed as a child twice, or of itself).
	std::vector<bool> visited(nodes.size(), false);
	struct Item {
		int index;
		Node *parent;
	};
	std::vector<Item> stack;
	for (auto it = p_doc.get_root_nodes().rbegin(); it != p_doc.get_root_nodes().rend(); ++it) {
		stack.push_back({ *it, root });
	}
	while (!stack.empty()) {
		Item item = stack.back();
		stack.pop_back();
		if (visited[item.index]) {
			delete root;
			*r_error = vformat("node %d appears twice in the hierarchy (cycle or shared child)", item.index);
			return nullptr;
		}
		visited[item.index] = true;
		const GLTFNodeData &nd = nodes[item.index];
		Node3D *node = nullptr;
		if (nd.mesh >= 0) {
			MeshInstance3D *mi = new MeshInstance3D;
			mi->set_mesh(meshes[nd.mesh]);
			node = mi;
		} else {
			node = new Node3D;
		}
		node->set_name(nd.name);
		node->set_transform(nd.transform);
		item.parent->add_child(node);
		for (auto c = nd.children.rbegin(); c != nd.children.rend(); ++c) {
			stack.push_back({ *c, node });
		}
	}
	return root;
}
