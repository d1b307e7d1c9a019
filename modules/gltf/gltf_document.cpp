/**************************************************************************/
/*  gltf_document.cpp                                                     */
/**************************************************************************/
/* glTF 2.0 specification, §3.6 (buffers/accessors), §3.7 (geometry),    */
/* §3.9 (metallic-roughness materials), §3.5 (node transforms).          */

#include "modules/gltf/gltf_document.h"

#include "core/error/error_macros.h"

// stb_image's implementation is compiled once, in core/io/image_loader.cpp.
#include <stb/stb_image.h>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include <fstream>

namespace {

bool _load_image(tinygltf::Image *r_image, const int p_index, std::string *r_err, std::string *r_warn, int p_req_w, int p_req_h, const unsigned char *p_bytes, int p_size, void *) {
	int w = 0, h = 0, comp = 0;
	unsigned char *pixels = stbi_load_from_memory(p_bytes, p_size, &w, &h, &comp, 4);
	if (!pixels) {
		if (r_err) {
			*r_err += vformat("Image %d could not be decoded (%s).\n", p_index, stbi_failure_reason());
		}
		return false;
	}
	r_image->width = w;
	r_image->height = h;
	r_image->component = 4;
	r_image->bits = 8;
	r_image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
	r_image->image.assign(pixels, pixels + size_t(w) * h * 4);
	stbi_image_free(pixels);
	return true;
}

// Reads accessor p_index as p_comps floats per element. Returns false (with r_error) for unsupported layouts.
bool _read_floats(const tinygltf::Model &p_model, int p_index, int p_comps, std::vector<float> &r_out, String *r_error) {
	if (p_index < 0 || p_index >= int(p_model.accessors.size())) {
		*r_error = vformat("accessor index %d is out of range", p_index);
		return false;
	}
	const tinygltf::Accessor &acc = p_model.accessors[p_index];
	if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
		*r_error = vformat("accessor %d has component type %d; only FLOAT attributes are supported", p_index, acc.componentType);
		return false;
	}
	if (tinygltf::GetNumComponentsInType(acc.type) != p_comps) {
		*r_error = vformat("accessor %d has %d components, expected %d", p_index, tinygltf::GetNumComponentsInType(acc.type), p_comps);
		return false;
	}
	if (acc.bufferView < 0 || acc.bufferView >= int(p_model.bufferViews.size())) {
		*r_error = vformat("accessor %d has no valid buffer view (sparse accessors are not supported)", p_index);
		return false;
	}
	const tinygltf::BufferView &view = p_model.bufferViews[acc.bufferView];
	const tinygltf::Buffer &buffer = p_model.buffers[view.buffer];
	size_t stride = view.byteStride ? view.byteStride : sizeof(float) * p_comps;
	size_t start = view.byteOffset + acc.byteOffset;
	size_t needed = acc.count == 0 ? 0 : start + stride * (acc.count - 1) + sizeof(float) * p_comps;
	if (needed > buffer.data.size()) {
		*r_error = vformat("accessor %d reads past the end of buffer %d", p_index, view.buffer);
		return false;
	}
	r_out.resize(acc.count * p_comps);
	for (size_t i = 0; i < acc.count; i++) {
		memcpy(&r_out[i * p_comps], buffer.data.data() + start + i * stride, sizeof(float) * p_comps);
	}
	return true;
}

bool _read_indices(const tinygltf::Model &p_model, int p_index, std::vector<uint32_t> &r_out, String *r_error) {
	if (p_index < 0 || p_index >= int(p_model.accessors.size())) {
		*r_error = vformat("index accessor %d is out of range", p_index);
		return false;
	}
	const tinygltf::Accessor &acc = p_model.accessors[p_index];
	int size = 0;
	switch (acc.componentType) {
		case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
			size = 1;
			break;
		case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
			size = 2;
			break;
		case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
			size = 4;
			break;
		default:
			*r_error = vformat("index accessor %d has unsupported component type %d", p_index, acc.componentType);
			return false;
	}
	if (acc.bufferView < 0 || acc.bufferView >= int(p_model.bufferViews.size())) {
		*r_error = vformat("index accessor %d has no valid buffer view", p_index);
		return false;
	}
	const tinygltf::BufferView &view = p_model.bufferViews[acc.bufferView];
	const tinygltf::Buffer &buffer = p_model.buffers[view.buffer];
	size_t stride = view.byteStride ? view.byteStride : size;
	size_t start = view.byteOffset + acc.byteOffset;
	if (acc.count && start + stride * (acc.count - 1) + size > buffer.data.size()) {
		*r_error = vformat("index accessor %d reads past the end of buffer %d", p_index, view.buffer);
		return false;
	}
	r_out.resize(acc.count);
	for (size_t i = 0; i < acc.count; i++) {
		const uint8_t *p = buffer.data.data() + start + i * stride;
		uint32_t v = 0;
		if (size == 1) {
			v = p[0];
		} else if (size == 2) {
			uint16_t s;
			memcpy(&s, p, 2);
			v = s;
		} else {
			memcpy(&v, p, 4);
		}
		r_out[i] = v;
	}
	return true;
}

Basis _basis_from_quaternion(double p_x, double p_y, double p_z, double p_w) {
	double l = std::sqrt(p_x * p_x + p_y * p_y + p_z * p_z + p_w * p_w);
	if (l == 0) {
		return Basis();
	}
	double x = p_x / l, y = p_y / l, z = p_z / l, w = p_w / l;
	return Basis(1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
			2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
			2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y));
}

} // namespace

bool GLTFDocument::parse_file(const String &p_path, String *r_error) {
	std::ifstream f(p_path, std::ios::binary);
	if (!f) {
		*r_error = vformat("Cannot open glTF file '%s'.", p_path.c_str());
		return false;
	}
	String data((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	String base_dir = p_path.find('/') == String::npos ? String(".") : p_path.substr(0, p_path.rfind('/'));
	String error;
	bool ok = false;
	if (data.size() >= 4 && data.compare(0, 4, "glTF") == 0) {
		tinygltf::TinyGLTF loader;
		loader.SetImageLoader(_load_image, nullptr);
		tinygltf::Model model;
		std::string err, warn;
		if (!loader.LoadBinaryFromMemory(&model, &err, &warn, (const unsigned char *)data.data(), (unsigned int)data.size(), base_dir)) {
			error = "invalid glTF binary: " + string_strip_edges(err);
		} else {
			ok = _convert(&model, &error);
		}
	} else {
		ok = parse_string(data, base_dir, &error);
	}
	if (!ok) {
		*r_error = vformat("'%s': %s", p_path.c_str(), error.c_str());
	}
	return ok;
}

bool GLTFDocument::parse_string(const String &p_text, const String &p_base_dir, String *r_error) {
	tinygltf::TinyGLTF loader;
	loader.SetImageLoader(_load_image, nullptr);
	tinygltf::Model model;
	std::string err, warn;
	if (!loader.LoadASCIIFromString(&model, &err, &warn, p_text.c_str(), (unsigned int)p_text.size(), p_base_dir)) {
		*r_error = "invalid glTF: " + string_strip_edges(err);
		return false;
	}
	return _convert(&model, r_error);
}

bool GLTFDocument::_convert(const void *p_model, String *r_error) {
	const tinygltf::Model &model = *static_cast<const tinygltf::Model *>(p_model);
	meshes.clear();
	materials.clear();
	images.clear();
	nodes.clear();
	root_nodes.clear();

	for (const tinygltf::Image &img : model.images) {
		GLTFImageData d;
		d.name = img.name;
		if (img.component == 4 && img.bits == 8) {
			d.width = img.width;
			d.height = img.height;
			d.rgba8 = img.image;
		}
		images.push_back(d);
	}
	auto texture_image = [&](int p_texture) -> int {
		if (p_texture < 0 || p_texture >= int(model.textures.size())) {
			return -1;
		}
		int source = model.textures[p_texture].source;
		return (source >= 0 && source < int(images.size()) && images[source].width > 0) ? source : -1;
	};
	for (const tinygltf::Material &m : model.materials) {
		GLTFMaterialData d;
		d.name = m.name;
		const std::vector<double> &bc = m.pbrMetallicRoughness.baseColorFactor;
		if (bc.size() == 4) {
			d.albedo_linear = Color(float(bc[0]), float(bc[1]), float(bc[2]), float(bc[3]));
		}
		d.roughness = float(m.pbrMetallicRoughness.roughnessFactor);
		d.metallic = float(m.pbrMetallicRoughness.metallicFactor);
		d.albedo_image = texture_image(m.pbrMetallicRoughness.baseColorTexture.index);
		d.normal_image = texture_image(m.normalTexture.index);
		d.normal_scale = float(m.normalTexture.scale);
		materials.push_back(d);
	}
	for (size_t mi = 0; mi < model.meshes.size(); mi++) {
		const tinygltf::Mesh &mesh = model.meshes[mi];
		GLTFMeshData md;
		md.name = mesh.name;
		for (size_t pi = 0; pi < mesh.primitives.size(); pi++) {
			const tinygltf::Primitive &prim = mesh.primitives[pi];
			String err;
			if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
				WARN_PRINT(vformat("glTF mesh %d primitive %d: mode %d is not triangles; skipped.", int(mi), int(pi), prim.mode));
				continue;
			}
			auto pos_it = prim.attributes.find("POSITION");
			if (pos_it == prim.attributes.end()) {
				*r_error = vformat("mesh %d primitive %d has no POSITION attribute", int(mi), int(pi));
				return false;
			}
			GLTFSurfaceData s;
			std::vector<float> f;
			if (!_read_floats(model, pos_it->second, 3, f, &err)) {
				*r_error = vformat("mesh %d primitive %d: %s", int(mi), int(pi), err.c_str());
				return false;
			}
			for (size_t i = 0; i + 2 < f.size(); i += 3) {
				s.vertices.push_back(Vector3(f[i], f[i + 1], f[i + 2]));
			}
			size_t vcount = s.vertices.size();
			if (prim.indices >= 0) {
				if (!_read_indices(model, prim.indices, s.indices, &err)) {
					*r_error = vformat("mesh %d primitive %d: %s", int(mi), int(pi), err.c_str());
					return false;
				}
			} else {
				for (uint32_t i = 0; i < vcount; i++) {
					s.indices.push_back(i);
				}
			}
			if (s.indices.size() % 3 != 0) {
				*r_error = vformat("mesh %d primitive %d: index count %d is not a multiple of 3", int(mi), int(pi), int(s.indices.size()));
				return false;
			}
			for (uint32_t idx : s.indices) {
				if (idx >= vcount) {
					*r_error = vformat("mesh %d primitive %d: index %u is out of range (%d vertices)", int(mi), int(pi), idx, int(vcount));
					return false;
				}
			}
			auto attr = [&](const char *p_name, int p_comps, std::vector<float> &r_out) -> bool {
				auto it = prim.attributes.find(p_name);
				if (it == prim.attributes.end()) {
					r_out.clear();
					return true;
				}
				if (!_read_floats(model, it->second, p_comps, r_out, &err)) {
					return false;
				}
				if (r_out.size() != vcount * p_comps) {
					err = vformat("attribute %s has a different count than POSITION", p_name);
					return false;
				}
				return true;
			};
			std::vector<float> n, uv, t;
			if (!attr("NORMAL", 3, n) || !attr("TEXCOORD_0", 2, uv) || !attr("TANGENT", 4, t)) {
				*r_error = vformat("mesh %d primitive %d: %s", int(mi), int(pi), err.c_str());
				return false;
			}
			if (!n.empty()) {
				for (size_t i = 0; i < vcount; i++) {
					s.normals.push_back(Vector3(n[i * 3], n[i * 3 + 1], n[i * 3 + 2]).normalized());
				}
			} else {
				// glTF §3.7.2.1: without normals, flat normals are used. Accumulate face normals per vertex.
				s.normals.assign(vcount, Vector3());
				for (size_t i = 0; i < s.indices.size(); i += 3) {
					const Vector3 &a = s.vertices[s.indices[i]], &b = s.vertices[s.indices[i + 1]], &c = s.vertices[s.indices[i + 2]];
					Vector3 fn = (b - a).cross(c - a);
					for (int k = 0; k < 3; k++) {
						s.normals[s.indices[i + k]] += fn;
					}
				}
				for (Vector3 &v : s.normals) {
					v = v.length_squared() > 0 ? v.normalized() : Vector3(0, 1, 0);
				}
			}
			for (size_t i = 0; i < uv.size(); i += 2) {
				s.uvs.push_back(Vector2(uv[i], uv[i + 1]));
			}
			s.tangents = t;
			s.material = (prim.material >= 0 && prim.material < int(materials.size())) ? prim.material : -1;
			md.surfaces.push_back(std::move(s));
		}
		meshes.push_back(std::move(md));
	}
	for (size_t ni = 0; ni < model.nodes.size(); ni++) {
		const tinygltf::Node &node = model.nodes[ni];
		GLTFNodeData d;
		d.name = node.name.empty() ? vformat("Node%d", int(ni)) : node.name;
		if (node.matrix.size() == 16) {
			const std::vector<double> &m = node.matrix; // Column-major.
			d.transform.basis = Basis::from_columns(Vector3(m[0], m[1], m[2]), Vector3(m[4], m[5], m[6]), Vector3(m[8], m[9], m[10]));
			d.transform.origin = Vector3(m[12], m[13], m[14]);
		} else {
			Basis b;
			if (node.rotation.size() == 4) {
				b = _basis_from_quaternion(node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]);
			}
			if (node.scale.size() == 3) {
				b = b * Basis::from_scale(Vector3(node.scale[0], node.scale[1], node.scale[2]));
			}
			d.transform.basis = b;
			if (node.translation.size() == 3) {
				d.transform.origin = Vector3(node.translation[0], node.translation[1], node.translation[2]);
			}
		}
		d.mesh = (node.mesh >= 0 && node.mesh < int(meshes.size())) ? node.mesh : -1;
		for (int c : node.children) {
			if (c < 0 || c >= int(model.nodes.size()) || c == int(ni)) {
				*r_error = vformat("node %d has an invalid child index %d", int(ni), c);
				return false;
			}
			d.children.push_back(c);
		}
		nodes.push_back(d);
	}
	// Roots: the default scene's nodes, else every node that is nobody's child.
	int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
	if (scene < int(model.scenes.size())) {
		for (int n : model.scenes[scene].nodes) {
			if (n >= 0 && n < int(nodes.size())) {
				root_nodes.push_back(n);
			}
		}
	} else {
		std::vector<bool> is_child(nodes.size(), false);
		for (const GLTFNodeData &n : nodes) {
			for (int c : n.children) {
				is_child[c] = true;
			}
		}
		for (size_t i = 0; i < nodes.size(); i++) {
			if (!is_child[i]) {
				root_nodes.push_back(int(i));
			}
		}
	}
	return true;
}
