/**************************************************************************/
/*  shader_rd.cpp                                                         */
/**************************************************************************/

#include "servers/rendering/renderer_rd/shader_rd.h"

#include "core/error/error_macros.h"
#include "servers/rendering/renderer_rd/shaders/shader_sources.gen.h"

#include <glslang/build_info.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

const int MAX_INCLUDE_DEPTH = 16;
std::atomic<uint64_t> version_id_counter{ uint64_t(1) << 48 };

bool read_text_file(const String &p_path, String &r_text) {
	std::ifstream f(p_path, std::ios::binary);
	if (!f) {
		return false;
	}
	std::stringstream ss;
	ss << f.rdbuf();
	r_text = ss.str();
	return true;
}

String dir_of(const String &p_path) {
	size_t pos = p_path.find_last_of('/');
	return pos == String::npos ? String() : p_path.substr(0, pos);
}

bool is_absolute(const String &p_path) {
	return !p_path.empty() && p_path[0] == '/';
}

// "a/b/../c.glsl" -> "a/c.glsl"; "." segments and empty segments dropped. A ".." above the start
// is kept, so it can never name an embedded file.
String normalize_path(const String &p_path) {
	std::vector<String> parts;
	std::istringstream ss(p_path);
	String part;
	while (std::getline(ss, part, '/')) {
		if (part.empty() || part == ".") {
			continue;
		}
		if (part == ".." && !parts.empty() && parts.back() != "..") {
			parts.pop_back();
		} else {
			parts.push_back(part);
		}
	}
	String out = is_absolute(p_path) ? "/" : "";
	for (size_t i = 0; i < parts.size(); i++) {
		out += (i ? "/" : "") + parts[i];
	}
	return out;
}

String join_path(const String &p_dir, const String &p_rel) {
	if (is_absolute(p_rel)) {
		return normalize_path(p_rel);
	}
	return normalize_path(p_dir.empty() ? p_rel : p_dir + "/" + p_rel);
}

// Text of p_path: from the disk for an absolute path, else from the shaders embedded at build time.
bool read_shader_file(const String &p_path, String &r_text) {
	if (is_absolute(p_path)) {
		return read_text_file(p_path, r_text);
	}
	const char *source = ShaderRD::get_embedded_source(p_path);
	if (!source) {
		return false;
	}
	r_text = source;
	return true;
}

// "FOO BAR=2" -> "#define FOO\n#define BAR 2\n"; text containing '#' is used as is.
String format_defines(const String &p_defines) {
	if (p_defines.empty()) {
		return String();
	}
	if (p_defines.find('#') != String::npos) {
		return p_defines.back() == '\n' ? p_defines : p_defines + "\n";
	}
	String out;
	std::istringstream ss(p_defines);
	String token;
	while (ss >> token) {
		size_t eq = token.find('=');
		if (eq == String::npos) {
			out += "#define " + token + "\n";
		} else {
			out += "#define " + token.substr(0, eq) + " " + token.substr(eq + 1) + "\n";
		}
	}
	return out;
}

uint64_t fnv1a(const String &p_data, uint64_t p_seed) {
	uint64_t h = p_seed;
	for (unsigned char c : p_data) {
		h ^= c;
		h *= 1099511628211ull;
	}
	return h;
}

String quote_label(const String &p_label) {
	String out;
	for (char c : p_label) {
		if (c != '"' && c != '\\') {
			out += c;
		}
	}
	return out;
}

} // namespace

const char *ShaderRD::get_embedded_source(const String &p_path) {
	const String path = normalize_path(p_path);
	for (const auto &entry : _shader_sources) {
		if (path == entry.path) {
			return entry.source;
		}
	}
	return nullptr;
}

std::vector<String> ShaderRD::get_embedded_paths() {
	std::vector<String> paths;
	for (const auto &entry : _shader_sources) {
		paths.push_back(entry.path);
	}
	return paths;
}

String ShaderRD::get_cache_dir() {
	const char *env = getenv("GODOT_AREA_SHADER_CACHE");
	if (env && env[0]) {
		return String(env);
	}
	// XDG Base Directory specification: $XDG_CACHE_HOME (must be absolute), else ~/.cache.
	const char *xdg = getenv("XDG_CACHE_HOME");
	if (xdg && xdg[0] == '/') {
		return String(xdg) + "/godot-area/shaders";
	}
	const char *home = getenv("HOME");
	if (home && home[0] == '/') {
		return String(home) + "/.cache/godot-area/shaders";
	}
	return String(std::filesystem::temp_directory_path().string()) + "/godot-area-" + std::to_string(getuid()) + "/shaders";
}

bool ShaderRD::_expand_includes(const String &p_source, const String &p_file_label, const String &p_base_dir, int p_depth, int p_first_line, String &r_out) {
	std::istringstream in(p_source);
	String line;
	int line_number = p_first_line - 1;
	while (std::getline(in, line)) {
		line_number++;
		String stripped = string_strip_edges(line);
		if (string_begins_with(stripped, "#include")) {
			size_t q1 = stripped.find('"');
			size_t q2 = q1 == String::npos ? String::npos : stripped.find('"', q1 + 1);
			if (q2 == String::npos) {
				last_error = vformat("%s:%d: malformed #include (expected #include \"file\").", p_file_label.c_str(), line_number);
				ERR_PRINT(last_error);
				return false;
			}
			if (p_depth >= MAX_INCLUDE_DEPTH) {
				last_error = vformat("%s:%d: #include nested deeper than %d levels (recursive include?).", p_file_label.c_str(), line_number, MAX_INCLUDE_DEPTH);
				ERR_PRINT(last_error);
				return false;
			}
			String rel = stripped.substr(q1 + 1, q2 - q1 - 1);
			// Relative to the including file (on disk or embedded), then the embedded shaders/ root.
			String candidates[2] = { join_path(p_base_dir, rel), normalize_path(rel) };
			String text;
			String found;
			for (const String &c : candidates) {
				if (read_shader_file(c, text)) {
					found = c;
					break;
				}
			}
			if (found.empty()) {
				last_error = vformat("%s:%d: cannot open included file \"%s\" (looked in %s and in the embedded shaders).", p_file_label.c_str(), line_number, rel.c_str(), p_base_dir.empty() ? "shaders/" : p_base_dir.c_str());
				ERR_PRINT(last_error);
				return false;
			}
			const String label = found;
			r_out += vformat("#line 1 \"%s\"\n", quote_label(label).c_str());
			if (!_expand_includes(text, label, dir_of(found), p_depth + 1, 1, r_out)) {
				return false;
			}
			r_out += vformat("#line %d \"%s\"\n", line_number + 1, quote_label(p_file_label).c_str());
		} else {
			r_out += line + "\n";
		}
	}
	return true;
}

bool ShaderRD::_parse_sections(const String &p_source, const String &p_name, const String &p_base_dir) {
	for (int i = 0; i < RenderingDevice::SHADER_STAGE_MAX; i++) {
		stage_code[i].clear();
		has_stage[i] = false;
	}
	std::vector<String> lines;
	{
		std::istringstream in(p_source);
		String line;
		while (std::getline(in, line)) {
			if (!line.empty() && line.back() == '\r') {
				line.pop_back();
			}
			lines.push_back(line);
		}
	}
	int current = -1;
	bool version_seen = false;
	String body;
	int body_first_line = 0;
	auto flush = [&]() -> bool {
		if (current < 0) {
			return true;
		}
		if (!version_seen) {
			last_error = vformat("%s: the #[%s] section has no #version line.", p_name.c_str(), RenderingDevice::get_shader_stage_name((RenderingDevice::ShaderStage)current));
			ERR_PRINT(last_error);
			return false;
		}
		String expanded = vformat("#line %d \"%s\"\n", body_first_line, quote_label(p_name).c_str());
		if (!_expand_includes(body, p_name, p_base_dir, 0, body_first_line, expanded)) {
			return false;
		}
		stage_code[current] = expanded;
		has_stage[current] = true;
		return true;
	};
	for (size_t i = 0; i < lines.size(); i++) {
		String s = string_strip_edges(lines[i]);
		int stage = -1;
		if (s == "#[vertex]") {
			stage = RenderingDevice::SHADER_STAGE_VERTEX;
		} else if (s == "#[fragment]") {
			stage = RenderingDevice::SHADER_STAGE_FRAGMENT;
		} else if (s == "#[compute]") {
			stage = RenderingDevice::SHADER_STAGE_COMPUTE;
		} else if (string_begins_with(s, "#[") && string_ends_with(s, "]")) {
			last_error = vformat("%s:%zu: unknown section %s (expected #[vertex], #[fragment] or #[compute]).", p_name.c_str(), i + 1, s.c_str());
			ERR_PRINT(last_error);
			return false;
		}
		if (stage >= 0) {
			if (!flush()) {
				return false;
			}
			if (has_stage[stage]) {
				last_error = vformat("%s:%zu: section %s appears twice.", p_name.c_str(), i + 1, s.c_str());
				ERR_PRINT(last_error);
				return false;
			}
			current = stage;
			version_seen = false;
			body.clear();
			continue;
		}
		if (current < 0) {
			continue; // Text before the first section is ignored.
		}
		if (!version_seen) {
			if (string_begins_with(s, "#version")) {
				version_seen = true;
				body_first_line = (int)i + 2;
			} else if (!s.empty() && !string_begins_with(s, "//")) {
				last_error = vformat("%s:%zu: expected #version as the first line of the section.", p_name.c_str(), i + 1);
				ERR_PRINT(last_error);
				return false;
			}
			continue;
		}
		body += lines[i] + "\n";
	}
	if (!flush()) {
		return false;
	}
	bool any = false;
	for (int i = 0; i < RenderingDevice::SHADER_STAGE_MAX; i++) {
		any = any || has_stage[i];
	}
	if (!any) {
		last_error = vformat("%s: no #[vertex], #[fragment] or #[compute] section found.", p_name.c_str());
		ERR_PRINT(last_error);
		return false;
	}
	if (has_stage[RenderingDevice::SHADER_STAGE_COMPUTE] && (has_stage[RenderingDevice::SHADER_STAGE_VERTEX] || has_stage[RenderingDevice::SHADER_STAGE_FRAGMENT])) {
		last_error = vformat("%s: a compute section cannot be combined with vertex/fragment sections.", p_name.c_str());
		ERR_PRINT(last_error);
		return false;
	}
	if (!has_stage[RenderingDevice::SHADER_STAGE_COMPUTE] && !has_stage[RenderingDevice::SHADER_STAGE_VERTEX]) {
		last_error = vformat("%s: a render shader needs a #[vertex] section.", p_name.c_str());
		ERR_PRINT(last_error);
		return false;
	}
	return true;
}

bool ShaderRD::initialize_from_source(const String &p_source, const String &p_name, const std::vector<String> &p_variant_defines, const String &p_general_defines, const String &p_base_dir) {
	clear();
	initialized = false;
	last_error.clear();
	name = p_name;
	variant_defines = p_variant_defines;
	if (variant_defines.empty()) {
		variant_defines.push_back(String());
	}
	general_defines = p_general_defines;
	if (!_parse_sections(p_source, p_name, p_base_dir)) {
		return false;
	}
	initialized = true;
	default_version = version_create();
	return true;
}

bool ShaderRD::initialize(const String &p_path, const std::vector<String> &p_variant_defines, const String &p_general_defines) {
	const String path = normalize_path(p_path);
	String text;
	if (!read_shader_file(path, text)) {
		clear();
		initialized = false;
		last_error = is_absolute(path) ? vformat("ShaderRD: cannot open shader file '%s'.", path.c_str())
									   : vformat("ShaderRD: no shader '%s' is embedded in this build (see servers/rendering/renderer_rd/shaders/).", path.c_str());
		ERR_PRINT(last_error);
		return false;
	}
	return initialize_from_source(text, path, p_variant_defines, p_general_defines, dir_of(path));
}

String ShaderRD::get_stage_source(RenderingDevice::ShaderStage p_stage, int p_variant, const String &p_version_defines) const {
	if (p_stage < 0 || p_stage >= RenderingDevice::SHADER_STAGE_MAX || !has_stage[p_stage] || p_variant < 0 || p_variant >= (int)variant_defines.size()) {
		return String();
	}
	String src = "#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n";
	src += format_defines(general_defines);
	src += format_defines(variant_defines[p_variant]);
	src += format_defines(p_version_defines);
	src += stage_code[p_stage];
	return src;
}

RID ShaderRD::version_create(const String &p_version_defines) {
	ERR_FAIL_COND_V_MSG(!initialized, RID(), "ShaderRD::version_create: the shader is not initialized.");
	uint64_t id = version_id_counter.fetch_add(1);
	Version v;
	v.defines = p_version_defines;
	v.shaders.resize(variant_defines.size());
	v.failed.resize(variant_defines.size(), false);
	versions[id] = v;
	return RID::from_uint64(id);
}

ShaderRD::Version *ShaderRD::_get_version(RID p_version) {
	auto it = versions.find(p_version.get_id());
	return it == versions.end() ? nullptr : &it->second;
}

bool ShaderRD::version_is_valid(RID p_version) const {
	return versions.count(p_version.get_id()) != 0;
}

void ShaderRD::version_free(RID p_version) {
	Version *v = _get_version(p_version);
	ERR_FAIL_NULL_MSG(v, "ShaderRD::version_free: invalid version RID.");
	RenderingDevice *rd = RenderingDevice::get_singleton();
	for (RID s : v->shaders) {
		if (s.is_valid() && rd && rd->is_initialized()) {
			rd->free(s);
		}
	}
	versions.erase(p_version.get_id());
	if (p_version == default_version) {
		default_version = RID();
	}
}

bool ShaderRD::is_compute() const {
	return has_stage[RenderingDevice::SHADER_STAGE_COMPUTE];
}

bool ShaderRD::is_variant_created(int p_variant) const {
	auto it = versions.find(default_version.get_id());
	if (it == versions.end() || p_variant < 0 || p_variant >= (int)it->second.shaders.size()) {
		return false;
	}
	return it->second.shaders[p_variant].is_valid();
}

RID ShaderRD::version_get_shader(int p_variant) {
	return version_get_shader(default_version, p_variant);
}

RID ShaderRD::version_get_shader(RID p_version, int p_variant) {
	ERR_FAIL_COND_V_MSG(!initialized, RID(), vformat("ShaderRD(%s): not initialized. %s", name.c_str(), last_error.c_str()));
	Version *v = _get_version(p_version);
	ERR_FAIL_NULL_V_MSG(v, RID(), vformat("ShaderRD(%s): invalid version RID.", name.c_str()));
	ERR_FAIL_INDEX_V_MSG(p_variant, (int)variant_defines.size(), RID(), vformat("ShaderRD(%s): variant index out of range.", name.c_str()));
	if (v->shaders[p_variant].is_valid()) {
		return v->shaders[p_variant];
	}
	if (v->failed[p_variant]) {
		return RID();
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !rd->is_initialized(), RID(), "ShaderRD: the RenderingDevice is not initialized.");

	String cache_dir = get_cache_dir();
	static const String compiler_tag = vformat("glslang-%d.%d.%d|vulkan1.1|spv1.3|rd1", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR, GLSLANG_VERSION_PATCH);
	std::vector<RenderingDevice::ShaderStageSPIRVData> stages;
	bool compiled_any = false;
	for (int st = 0; st < RenderingDevice::SHADER_STAGE_MAX; st++) {
		if (!has_stage[st]) {
			continue;
		}
		RenderingDevice::ShaderStage stage = (RenderingDevice::ShaderStage)st;
		String source = get_stage_source(stage, p_variant, v->defines);
		String keyed = compiler_tag + "|" + RenderingDevice::get_shader_stage_name(stage) + "|" + source;
		String hash = vformat("%016llx%016llx", (unsigned long long)fnv1a(keyed, 14695981039346656037ull), (unsigned long long)fnv1a(keyed, 0x9E3779B97F4A7C15ull));
		String cache_file = cache_dir + "/" + hash + ".spv";

		std::vector<uint32_t> spirv;
		{
			std::ifstream f(cache_file, std::ios::binary | std::ios::ate);
			if (f) {
				std::streamsize size = f.tellg();
				if (size >= 20 && (size % 4) == 0) {
					spirv.resize(size / 4);
					f.seekg(0);
					if (!f.read((char *)spirv.data(), size) || spirv[0] != 0x07230203) {
						spirv.clear();
					}
				}
			}
		}
		if (spirv.empty()) {
			String err;
			spirv = rd->shader_compile_spirv_from_source(stage, source, name, &err);
			if (spirv.empty()) {
				last_error = vformat("ShaderRD '%s' variant %d (%s): %s", name.c_str(), p_variant, variant_defines[p_variant].c_str(), err.c_str());
				ERR_PRINT(last_error);
				v->failed[p_variant] = true;
				return RID();
			}
			compiled_any = true;
			std::error_code ec;
			std::filesystem::create_directories(cache_dir, ec);
			static std::atomic<uint32_t> tmp_counter{ 0 };
			String tmp = cache_file + vformat(".tmp.%d.%u", (int)getpid(), tmp_counter.fetch_add(1));
			{
				std::ofstream out(tmp, std::ios::binary);
				if (out) {
					out.write((const char *)spirv.data(), spirv.size() * sizeof(uint32_t));
				}
			}
			std::filesystem::rename(tmp, cache_file, ec);
			if (ec) {
				std::filesystem::remove(tmp, ec);
				WARN_PRINT_ONCE(vformat("ShaderRD: could not write the SPIR-V cache in '%s'.", cache_dir.c_str()));
			}
		}
		RenderingDevice::ShaderStageSPIRVData sd;
		sd.shader_stage = stage;
		sd.spirv = std::move(spirv);
		stages.push_back(std::move(sd));
	}
	if (compiled_any) {
		compile_count++;
	} else {
		cache_hit_count++;
	}
	RID shader = rd->shader_create_from_spirv(stages, vformat("%s:%d", name.c_str(), p_variant));
	if (shader.is_null()) {
		last_error = vformat("ShaderRD '%s' variant %d: the SPIR-V could not be turned into a shader (see the error above).", name.c_str(), p_variant);
		v->failed[p_variant] = true;
		return RID();
	}
	created_shader_count++;
	v->shaders[p_variant] = shader;
	return shader;
}

void ShaderRD::clear() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	bool can_free = rd && rd->is_initialized();
	for (auto &kv : versions) {
		for (RID s : kv.second.shaders) {
			if (s.is_valid() && can_free) {
				rd->free(s);
			}
		}
	}
	versions.clear();
	default_version = RID();
}

ShaderRD::~ShaderRD() {
	clear();
}
