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

#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>

namespace {

// Largest glTF/GLB file read (the JSON or GLB container; external buffers are bounded the same way).
constexpr uint64_t MAX_GLTF_FILE_BYTES = uint64_t(1) << 30;
// Largest decoded image (pixels); stb's own limit is per side.
constexpr uint64_t MAX_IMAGE_PIXELS = uint64_t(1) << 28;

bool _decode_image(tinygltf::Image *r_image, const int p_index, std::string *r_err, const unsigned char *p_bytes, int p_size) {
	int w = 0, h = 0, comp = 0;
	if (p_size <= 0 || !stbi_info_from_memory(p_bytes, p_size, &w, &h, &comp)) {
		if (r_err) {
			*r_err += vformat("image %d could not be decoded (%s).\n", p_index, stbi_failure_reason() ? stbi_failure_reason() : "empty");
		}
		return false;
	}
	if (w <= 0 || h <= 0 || uint64_t(w) * uint64_t(h) > MAX_IMAGE_PIXELS) {
		if (r_err) {
			*r_err += vformat("image %d is %d x %d pixels, larger than the %llu-pixel limit.\n", p_index, w, h, (unsigned long long)MAX_IMAGE_PIXELS);
		}
		return false;
	}
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

bool _load_image(tinygltf::Image *r_image, const int p_index, std::string *r_err, std::string *r_warn, int p_req_w, int p_req_h, const unsigned char *p_bytes, int p_size, void *) {
	if (r_image->bufferView >= 0) {
		// tinygltf passes a buffer view's bytes without checking the view against its buffer; such images are
		// decoded in _convert() once the view's bounds are validated.
		return true;
	}
	return _decode_image(r_image, p_index, r_err, p_bytes, p_size);
}

// File access for tinygltf (external buffers and images): a URI must resolve inside the folder of the glTF file
// (glTF 2.0 §3.3.2 allows relative URIs; nothing requires reaching above the asset's folder).
struct ConfinedFs {
	std::filesystem::path root;

	bool contains(const std::string &p_path) const {
		std::error_code ec;
		std::filesystem::path abs = std::filesystem::weakly_canonical(std::filesystem::absolute(p_path, ec), ec);
		if (ec) {
			return false;
		}
		auto r = root.begin(), a = abs.begin();
		for (; r != root.end(); ++r, ++a) {
			if (a == abs.end() || *a != *r) {
				return false;
			}
		}
		return true;
	}
};

bool _fs_exists(const std::string &p_path, void *p_user) {
	// Existence only: _fs_read() refuses a file outside the folder with an error saying so.
	std::error_code ec;
	return std::filesystem::is_regular_file(p_path, ec);
}

std::string _fs_expand(const std::string &p_path, void *) {
	return p_path; // No '~' or environment expansion: a URI is a path relative to the asset.
}

bool _read_bounded(const std::string &p_path, std::vector<unsigned char> *r_out, std::string *r_err) {
	std::ifstream f(p_path, std::ios::binary);
	if (!f) {
		*r_err = "cannot open";
		return false;
	}
	r_out->clear();
	char chunk[65536];
	while (f) {
		f.read(chunk, sizeof(chunk));
		r_out->insert(r_out->end(), chunk, chunk + f.gcount());
		if (r_out->size() > MAX_GLTF_FILE_BYTES) {
			*r_err = vformat("larger than the %llu-byte limit", (unsigned long long)MAX_GLTF_FILE_BYTES);
			return false;
		}
	}
	if (f.bad()) {
		*r_err = "read error";
		return false;
	}
	return true;
}

bool _fs_read(std::vector<unsigned char> *r_out, std::string *r_err, const std::string &p_path, void *p_user) {
	const ConfinedFs *fs = static_cast<const ConfinedFs *>(p_user);
	if (!fs->contains(p_path)) {
		*r_err = vformat("URI resolves outside the glTF file's folder '%s'", fs->root.string().c_str());
		return false;
	}
	return _read_bounded(p_path, r_out, r_err);
}

bool _fs_write(std::string *r_err, const std::string &, const std::vector<unsigned char> &, void *) {
	*r_err = "writing is not supported";
	return false;
}

void _setup_loader(tinygltf::TinyGLTF &r_loader, ConfinedFs &r_fs, const String &p_base_dir) {
	std::error_code ec;
	r_fs.root = std::filesystem::weakly_canonical(std::filesystem::absolute(p_base_dir.empty() ? String(".") : p_base_dir, ec), ec);
	r_loader.SetImageLoader(_load_image, nullptr);
	tinygltf::FsCallbacks cb;
	cb.FileExists = _fs_exists;
	cb.ExpandFilePath = _fs_expand;
	cb.ReadWholeFile = _fs_read;
	cb.WriteWholeFile = _fs_write;
	cb.user_data = &r_fs;
	r_loader.SetFsCallbacks(cb);
}

// Validates that accessor p_acc (elements of p_elem_size bytes) lies inside its buffer view and buffer, with
// every sum and product checked for overflow before it is used (glTF 2.0 §3.6.2.4 "Data alignment" and
// §5.1/§5.11 limits). On success r_start is the first byte and r_stride the distance between elements.
bool _accessor_span(const tinygltf::Model &p_model, int p_index, const char *p_what, size_t p_elem_size, size_t *r_start, size_t *r_stride, String *r_error) {
	const tinygltf::Accessor &acc = p_model.accessors[p_index];
	if (acc.bufferView < 0 || size_t(acc.bufferView) >= p_model.bufferViews.size()) {
		*r_error = vformat("%s accessor %d: field 'bufferView' = %d is out of range (%d buffer views; sparse accessors are not supported)", p_what, p_index, acc.bufferView, int(p_model.bufferViews.size()));
		return false;
	}
	const tinygltf::BufferView &view = p_model.bufferViews[acc.bufferView];
	if (view.buffer < 0 || size_t(view.buffer) >= p_model.buffers.size()) {
		*r_error = vformat("%s accessor %d: bufferView %d field 'buffer' = %d is out of range (%d buffers)", p_what, p_index, acc.bufferView, view.buffer, int(p_model.buffers.size()));
		return false;
	}
	const size_t buffer_size = p_model.buffers[view.buffer].data.size();
	// The view must lie inside its buffer.
	if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset) {
		*r_error = vformat("%s accessor %d: bufferView %d (byteOffset %llu, byteLength %llu) lies outside buffer %d (%llu bytes)", p_what, p_index, acc.bufferView,
				(unsigned long long)view.byteOffset, (unsigned long long)view.byteLength, view.buffer, (unsigned long long)buffer_size);
		return false;
	}
	const size_t stride = view.byteStride ? view.byteStride : p_elem_size;
	if (stride < p_elem_size) {
		*r_error = vformat("%s accessor %d: bufferView %d field 'byteStride' = %d is smaller than an element (%d bytes)", p_what, p_index, acc.bufferView, int(view.byteStride), int(p_elem_size));
		return false;
	}
	if (acc.byteOffset > view.byteLength) {
		*r_error = vformat("%s accessor %d: field 'byteOffset' = %llu is past the end of bufferView %d (%llu bytes)", p_what, p_index, (unsigned long long)acc.byteOffset, acc.bufferView, (unsigned long long)view.byteLength);
		return false;
	}
	if (acc.count > 0) {
		// Bytes the accessor reads inside the view: stride * (count - 1) + element, overflow-checked.
		const size_t room = view.byteLength - acc.byteOffset;
		const size_t last = acc.count - 1;
		if (room < p_elem_size || last > (room - p_elem_size) / stride) {
			*r_error = vformat("%s accessor %d: field 'count' = %llu reads past the end of bufferView %d (%llu bytes from byteOffset %llu, stride %llu)", p_what, p_index,
					(unsigned long long)acc.count, acc.bufferView, (unsigned long long)view.byteLength, (unsigned long long)acc.byteOffset, (unsigned long long)stride);
			return false;
		}
	}
	*r_start = view.byteOffset + acc.byteOffset;
	*r_stride = stride;
	return true;
}

// Reads accessor p_index as p_comps floats per element. Returns false (with r_error) for unsupported layouts.
bool _read_floats(const tinygltf::Model &p_model, int p_index, int p_comps, std::vector<float> &r_out, String *r_error) {
	if (p_index < 0 || p_index >= int(p_model.accessors.size())) {
		*r_error = vformat("accessor index %d is out of range (%d accessors)", p_index, int(p_model.accessors.size()));
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
	size_t start = 0, stride = 0;
	if (!_accessor_span(p_model, p_index, "attribute", sizeof(float) * p_comps, &start, &stride, r_error)) {
		return false;
	}
	const tinygltf::Buffer &buffer = p_model.buffers[p_model.bufferViews[acc.bufferView].buffer];
	// count fits in the buffer (checked above), so count * p_comps floats cannot overflow.
	r_out.resize(acc.count * p_comps);
	for (size_t i = 0; i < acc.count; i++) {
		memcpy(&r_out[i * p_comps], buffer.data.data() + start + i * stride, sizeof(float) * p_comps);
	}
	return true;
}

// Reads a COLOR_0 accessor (glTF 2.0 spec 3.7.2.1): VEC3 or VEC4 of FLOAT, or of UNSIGNED_BYTE / UNSIGNED_SHORT
// read as normalized (value / 255 or / 65535: the spec requires `normalized` for them; files that omit the
// flag, as some exporters do, mean the same). Linear colours; alpha 1 for VEC3.
bool _read_colors(const tinygltf::Model &p_model, int p_index, std::vector<Color> &r_out, String *r_error) {
	if (p_index < 0 || p_index >= int(p_model.accessors.size())) {
		*r_error = vformat("accessor index %d is out of range (%d accessors)", p_index, int(p_model.accessors.size()));
		return false;
	}
	const tinygltf::Accessor &acc = p_model.accessors[p_index];
	const int comps = tinygltf::GetNumComponentsInType(acc.type);
	if (comps != 3 && comps != 4) {
		*r_error = vformat("COLOR_0 accessor %d has %d components; VEC3 or VEC4 expected", p_index, comps);
		return false;
	}
	int size = 0;
	float scale = 1.0f;
	switch (acc.componentType) {
		case TINYGLTF_COMPONENT_TYPE_FLOAT:
			size = 4;
			break;
		case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
			size = 1;
			scale = 1.0f / 255.0f;
			break;
		case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
			size = 2;
			scale = 1.0f / 65535.0f;
			break;
		default:
			*r_error = vformat("COLOR_0 accessor %d has component type %d; FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT expected", p_index, acc.componentType);
			return false;
	}
	size_t start = 0, stride = 0;
	if (!_accessor_span(p_model, p_index, "attribute", size_t(size) * comps, &start, &stride, r_error)) {
		return false;
	}
	const tinygltf::Buffer &buffer = p_model.buffers[p_model.bufferViews[acc.bufferView].buffer];
	r_out.resize(acc.count);
	for (size_t i = 0; i < acc.count; i++) {
		const uint8_t *p = buffer.data.data() + start + i * stride;
		float c[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
		for (int k = 0; k < comps; k++) {
			if (size == 4) {
				memcpy(&c[k], p + k * 4, 4);
			} else if (size == 2) {
				uint16_t v;
				memcpy(&v, p + k * 2, 2);
				c[k] = float(v) * scale;
			} else {
				c[k] = float(p[k]) * scale;
			}
		}
		r_out[i] = Color(c[0], c[1], c[2], c[3]);
	}
	return true;
}

bool _read_indices(const tinygltf::Model &p_model, int p_index, std::vector<uint32_t> &r_out, String *r_error) {
	if (p_index < 0 || p_index >= int(p_model.accessors.size())) {
		*r_error = vformat("field 'indices' = %d is out of range (%d accessors)", p_index, int(p_model.accessors.size()));
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
	size_t start = 0, stride = 0;
	if (!_accessor_span(p_model, p_index, "index", size, &start, &stride, r_error)) {
		return false;
	}
	const tinygltf::Buffer &buffer = p_model.buffers[p_model.bufferViews[acc.bufferView].buffer];
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
	std::vector<unsigned char> bytes;
	std::string read_err;
	if (!_read_bounded(p_path, &bytes, &read_err)) {
		*r_error = vformat("Cannot read glTF file '%s' (%s).", p_path.c_str(), read_err.c_str());
		return false;
	}
	String base_dir = p_path.find('/') == String::npos ? String(".") : p_path.substr(0, p_path.rfind('/'));
	String error;
	bool ok = false;
	if (bytes.size() >= 4 && memcmp(bytes.data(), "glTF", 4) == 0) {
		ok = _parse(bytes.data(), bytes.size(), true, base_dir, &error);
	} else {
		ok = _parse(bytes.data(), bytes.size(), false, base_dir, &error);
	}
	if (!ok) {
		*r_error = vformat("'%s': %s", p_path.c_str(), error.c_str());
	}
	return ok;
}

bool GLTFDocument::parse_string(const String &p_text, const String &p_base_dir, String *r_error) {
	return _parse(reinterpret_cast<const uint8_t *>(p_text.data()), p_text.size(), false, p_base_dir, r_error);
}

bool GLTFDocument::parse_glb(const uint8_t *p_data, size_t p_size, const String &p_base_dir, String *r_error) {
	return _parse(p_data, p_size, true, p_base_dir, r_error);
}

bool GLTFDocument::_parse(const uint8_t *p_data, size_t p_size, bool p_binary, const String &p_base_dir, String *r_error) {
	meshes.clear();
	materials.clear();
	images.clear();
	nodes.clear();
	root_nodes.clear();
	if (p_size > MAX_GLTF_FILE_BYTES) {
		*r_error = vformat("%llu bytes is larger than the %llu-byte limit", (unsigned long long)p_size, (unsigned long long)MAX_GLTF_FILE_BYTES);
		return false;
	}
	// Nothing thrown by tinygltf, its JSON parser or an allocation escapes: it becomes an error.
	try {
		tinygltf::TinyGLTF loader;
		ConfinedFs fs;
		_setup_loader(loader, fs, p_base_dir);
		tinygltf::Model model;
		std::string err, warn;
		bool loaded = p_binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, p_data, (unsigned int)p_size, p_base_dir)
							   : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char *>(p_data), (unsigned int)p_size, p_base_dir);
		if (!loaded) {
			*r_error = String(p_binary ? "invalid glTF binary: " : "invalid glTF: ") + string_strip_edges(err);
			return false;
		}
		if (_convert(&model, r_error)) {
			return true;
		}
	} catch (const std::bad_alloc &) {
		*r_error = "out of memory while reading the file";
	} catch (const std::exception &e) {
		*r_error = vformat("malformed content (%s)", e.what());
	}
	meshes.clear();
	materials.clear();
	images.clear();
	nodes.clear();
	root_nodes.clear();
	return false;
}

bool GLTFDocument::_convert(const void *p_model, String *r_error) {
	const tinygltf::Model &model = *static_cast<const tinygltf::Model *>(p_model);

	for (size_t ii = 0; ii < model.images.size(); ii++) {
		const tinygltf::Image &src = model.images[ii];
		tinygltf::Image decoded;
		const tinygltf::Image *use = &src;
		if (src.bufferView >= 0) {
			// tinygltf checked the view and buffer indices, not the view's bytes against the buffer.
			const tinygltf::BufferView &view = model.bufferViews[src.bufferView];
			const size_t buffer_size = model.buffers[view.buffer].data.size();
			if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset || view.byteLength > size_t(INT32_MAX)) {
				*r_error = vformat("image %d: bufferView %d (byteOffset %llu, byteLength %llu) lies outside buffer %d (%llu bytes)", int(ii), src.bufferView,
						(unsigned long long)view.byteOffset, (unsigned long long)view.byteLength, view.buffer, (unsigned long long)buffer_size);
				return false;
			}
			std::string err;
			if (!_decode_image(&decoded, int(ii), &err, model.buffers[view.buffer].data.data() + view.byteOffset, int(view.byteLength))) {
				*r_error = string_strip_edges(err);
				return false;
			}
			use = &decoded;
		}
		const tinygltf::Image &img = *use;
		GLTFImageData d;
		d.name = src.name;
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
			auto color_it = prim.attributes.find("COLOR_0");
			if (color_it != prim.attributes.end()) {
				if (!_read_colors(model, color_it->second, s.colors, &err)) {
					*r_error = vformat("mesh %d primitive %d: %s", int(mi), int(pi), err.c_str());
					return false;
				}
				if (s.colors.size() != vcount) {
					*r_error = vformat("mesh %d primitive %d: attribute COLOR_0 has a different count than POSITION", int(mi), int(pi));
					return false;
				}
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
