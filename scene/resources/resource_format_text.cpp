/**************************************************************************/
/*  resource_format_text.cpp                                              */
/**************************************************************************/
/* The loader registries, paths and the helpers the loader and the saver  */
/* share (resource_format_text_internal.h).                               */

#include "scene/resources/resource_format_text.h"

#include "core/io/file_io.h"
#include "core/object/class_db.h"
#include "core/variant/variant_parser.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"
#include "scene/resources/resource_format_text_internal.h"

#include <cctype>
#include <filesystem>

namespace ResourceFormatTextInternal {

std::map<String, ResourceFormatText::SceneLoaderFunc> &_scene_loaders() {
	static std::map<String, ResourceFormatText::SceneLoaderFunc> loaders;
	return loaders;
}

std::map<String, ResourceFormatText::ResourceLoaderFunc> &_resource_loaders() {
	static std::map<String, ResourceFormatText::ResourceLoaderFunc> loaders;
	return loaders;
}

String &_resource_root() {
	static String root;
	return root;
}

String _lower(const String &p_s) {
	String out = p_s;
	for (char &c : out) {
		c = (char)tolower((unsigned char)c);
	}
	return out;
}

String _extension(const String &p_path) {
	size_t dot = p_path.rfind('.');
	size_t slash = p_path.find_last_of("/\\");
	if (dot == String::npos || (slash != String::npos && dot < slash)) {
		return String();
	}
	return _lower(p_path.substr(dot + 1));
}

String _dir_of(const String &p_path) {
	size_t slash = p_path.find_last_of('/');
	return slash == String::npos ? String() : p_path.substr(0, slash);
}

// Bounded read (core/io/file_io.h): `render /dev/zero` stops with an error instead of filling memory.
bool _read_file(const String &p_path, String &r_text, String *r_error) {
	return file_read_bounded(p_path, r_text, r_error);
}

String _canonical(const String &p_path) {
	std::error_code ec;
	std::filesystem::path c = std::filesystem::weakly_canonical(std::filesystem::path(p_path), ec);
	return ec ? p_path : c.string();
}

int64_t _mtime(const String &p_path) {
	std::error_code ec;
	auto t = std::filesystem::last_write_time(std::filesystem::path(p_path), ec);
	return ec ? -1 : (int64_t)t.time_since_epoch().count();
}

// Godot-style random-looking ids ("1_ab3cd", "BoxMesh_x7k2p"), derived from a
// hash so that saving the same content twice gives the same text.
String _hash_suffix(const String &p_seed, int p_len) {
	uint64_t h = 1469598103934665603ull;
	for (char c : p_seed) {
		h = (h ^ (uint8_t)c) * 1099511628211ull;
	}
	static const char *chars = "abcdefghijklmnopqrstuvwxyz0123456789";
	String out;
	for (int i = 0; i < p_len; i++) {
		out += chars[h % 36];
		h = h / 36 + (h << 7) * 31;
	}
	return out;
}

ProblemLog &_problems() {
	static ProblemLog log;
	return log;
}

std::map<String, TemplateEntry> &_templates() {
	static std::map<String, TemplateEntry> cache;
	return cache;
}

// Resources loaded from files during the outermost load (a texture used by
// many materials is read once).
std::map<String, Ref<Resource>> &_resource_cache() {
	static std::map<String, Ref<Resource>> cache;
	return cache;
}

std::set<String> &_warned_rootless() {
	static std::set<String> dirs;
	return dirs;
}

// The file data of p_obj, created on demand.
TextSceneData *_data(Object *p_obj) {
	TextSceneData *d = dynamic_cast<TextSceneData *>(p_obj->get_file_data());
	if (!d) {
		p_obj->set_file_data(std::make_unique<TextSceneData>());
		d = static_cast<TextSceneData *>(p_obj->get_file_data());
	}
	return d;
}

const TextSceneData *_data_or_null(const Object *p_obj) {
	return dynamic_cast<const TextSceneData *>(p_obj->get_file_data());
}

// Position right after "key =" (and blanks) of an assignment starting at or after p_pos.
size_t _value_start(const String &p_text, size_t p_pos) {
	size_t p = p_pos;
	while (p < p_text.size()) {
		char c = p_text[p];
		if (c == ';') {
			while (p < p_text.size() && p_text[p] != '\n') {
				p++;
			}
		} else if ((unsigned char)c <= 32) {
			p++;
		} else {
			break;
		}
	}
	if (p < p_text.size() && p_text[p] == '"') {
		p++;
		while (p < p_text.size() && p_text[p] != '"') {
			p += p_text[p] == '\\' ? 2 : 1;
		}
	}
	while (p < p_text.size() && p_text[p] != '=') {
		p++;
	}
	p++;
	while (p < p_text.size() && (p_text[p] == ' ' || p_text[p] == '\t')) {
		p++;
	}
	return p;
}

String _trim_right(const String &p_s) {
	size_t e = p_s.size();
	while (e > 0 && (unsigned char)p_s[e - 1] <= 32) {
		e--;
	}
	return p_s.substr(0, e);
}

// Blank as the tag parser reads it (core/variant/variant_parser.cpp): any byte up to the space, control
// characters included.
static bool _is_blank(char p_c) {
	return (unsigned char)p_c <= 32;
}

// Splits "[name k=v k2=[1, 2] k3="a b"]" into its fields as written. Blanks and ';' comments before
// the tag are skipped: a '[' inside such a comment is not the tag (found by fuzz_resource_format_text).
std::vector<std::pair<String, String>> _split_tag(const String &p_raw) {
	std::vector<std::pair<String, String>> out;
	size_t p = 0;
	while (p < p_raw.size() && p_raw[p] != '[') {
		if (p_raw[p] == ';') {
			while (p < p_raw.size() && p_raw[p] != '\n') {
				p++;
			}
		} else if (_is_blank(p_raw[p])) {
			p++;
		} else {
			return out;
		}
	}
	if (p >= p_raw.size()) {
		return out;
	}
	p++;
	// Blanks may stand between '[' and the tag's name, as the tag parser reads it (found by
	// fuzz_resource_format_text: "[\x05ext_resource type=..." was split with the name as the first key).
	while (p < p_raw.size() && _is_blank(p_raw[p])) {
		p++;
	}
	while (p < p_raw.size() && !_is_blank(p_raw[p]) && p_raw[p] != ']') {
		p++;
	}
	while (p < p_raw.size()) {
		while (p < p_raw.size() && _is_blank(p_raw[p])) {
			p++;
		}
		if (p >= p_raw.size() || p_raw[p] == ']') {
			break;
		}
		size_t k = p;
		while (p < p_raw.size() && p_raw[p] != '=' && !_is_blank(p_raw[p])) {
			p++;
		}
		String key = p_raw.substr(k, p - k);
		while (p < p_raw.size() && p_raw[p] != '=') {
			p++;
		}
		if (p >= p_raw.size()) {
			break; // A key without "=value" ends the tag (found by fuzz_resource_format_text).
		}
		p++;
		while (p < p_raw.size() && _is_blank(p_raw[p])) {
			p++; // name= "a" and name=\x07"a": the value starts after the blanks, as the tag parser reads it.
		}
		size_t v = p;
		int depth = 0;
		while (p < p_raw.size()) {
			char c = p_raw[p];
			if (c == '"') {
				p++;
				while (p < p_raw.size() && p_raw[p] != '"') {
					p += p_raw[p] == '\\' ? 2 : 1;
				}
				p++;
				if (depth == 0) {
					break; // A string value ends at its quote, as the tag parser reads it: name="a"b= is two fields.
				}
				continue;
			}
			if (c == '(' || c == '[' || c == '{') {
				depth++;
			} else if (c == ')' || c == '}' || (c == ']' && depth > 0)) {
				depth--;
			} else if (depth == 0 && (_is_blank(c) || c == ']')) {
				break;
			}
			p++;
		}
		p = std::min(p, p_raw.size()); // An escape or quote at the very end may step past it.
		out.push_back(std::make_pair(key, p_raw.substr(v, p - v)));
	}
	return out;
}

// The ids named by SubResource("id") / ExtResource("id") in raw text.
std::vector<String> _referenced_ids(const String &p_text, const char *p_kind) {
	// As the parser reads them: blanks (any byte up to ' ') may stand between the name, '(' and the
	// quoted id, and the id's escapes are resolved (found by fuzz_resource_format_text: a control
	// character before the quote hid a reference, and the saved file named a sub_resource it lacked).
	std::vector<String> ids;
	const String kind = p_kind;
	auto skip_blanks = [&](size_t p_pos) {
		while (p_pos < p_text.size() && (unsigned char)p_text[p_pos] <= 32) {
			p_pos++;
		}
		return p_pos;
	};
	VariantParser::Stream stream; // Copies the text only when it names one.
	size_t p = 0;
	while ((p = p_text.find(kind, p)) != String::npos) {
		p = skip_blanks(p + kind.size());
		if (p >= p_text.size() || p_text[p] != '(') {
			continue;
		}
		p = skip_blanks(p + 1);
		if (p >= p_text.size() || p_text[p] != '"') {
			continue;
		}
		if (stream.text.empty()) {
			stream.text = p_text;
		}
		stream.pos = p + 1;
		String id, error;
		if (!VariantParser::parse_string_literal(stream, id, error)) {
			break;
		}
		ids.push_back(id);
		p = stream.pos;
	}
	return ids;
}

String _relative_path(const Node *p_root, const Node *p_node) {
	String path;
	for (const Node *n = p_node; n && n != p_root; n = n->get_parent()) {
		path = path.empty() ? n->get_name() : n->get_name() + "/" + path;
	}
	return path;
}

// Copies p_src's tree for one more instance: same classes, the stored
// properties (resources shared, not copied), placeholders keep their type.
// Every copied node is marked as coming from the template.
Node *_duplicate(const Node *p_src) {
	Node *node = nullptr;
	if (const MissingNode *m = Object::cast_to<MissingNode>(p_src)) {
		MissingNode *copy = new MissingNode;
		copy->set_original_class(m->get_original_class());
		node = copy;
	} else {
		node = Object::cast_to<Node>(ClassDB::instantiate(p_src->get_class()));
	}
	ERR_FAIL_NULL_V_MSG(node, nullptr, vformat("Cannot duplicate a node of class %s.", p_src->get_class().c_str()));
	node->set_name(p_src->get_name());
	std::vector<PropertyInfo> plist;
	p_src->get_property_list(&plist);
	for (const PropertyInfo &pi : plist) {
		if (pi.is_group_marker() || !(pi.usage & PROPERTY_USAGE_STORAGE)) {
			continue;
		}
		bool valid = false;
		Variant v = p_src->get(pi.name, &valid);
		if (valid) {
			node->try_set(pi.name, v);
		}
	}
	_data(node)->inherited = true;
	for (int i = 0; i < p_src->get_child_count(); i++) {
		Node *child = _duplicate(p_src->get_child(i));
		if (child) {
			node->add_child(child);
		}
	}
	return node;
}

bool _lists_property(const Object *p_obj, const String &p_name) {
	std::vector<PropertyInfo> plist;
	p_obj->get_property_list(&plist);
	for (const PropertyInfo &pi : plist) {
		if (pi.name == p_name) {
			return true;
		}
	}
	return false;
}

} // namespace ResourceFormatTextInternal

using namespace ResourceFormatTextInternal;

void ResourceFormatText::add_scene_loader(const String &p_extension, const SceneLoaderFunc &p_func) {
	ERR_FAIL_COND_MSG(!p_func, vformat("Scene loader for '%s' is empty.", p_extension.c_str()));
	_scene_loaders()[_lower(p_extension)] = p_func;
}

void ResourceFormatText::remove_scene_loader(const String &p_extension) {
	_scene_loaders().erase(_lower(p_extension));
}

bool ResourceFormatText::has_scene_loader(const String &p_extension) {
	String ext = _lower(p_extension);
	return ext == "tscn" || _scene_loaders().count(ext);
}

void ResourceFormatText::add_resource_loader(const String &p_extension, const ResourceLoaderFunc &p_func) {
	ERR_FAIL_COND_MSG(!p_func, vformat("Resource loader for '%s' is empty.", p_extension.c_str()));
	_resource_loaders()[_lower(p_extension)] = p_func;
}

void ResourceFormatText::remove_resource_loader(const String &p_extension) {
	_resource_loaders().erase(_lower(p_extension));
}

void ResourceFormatText::set_resource_root(const String &p_dir) {
	_resource_root() = p_dir;
}

String ResourceFormatText::get_resource_root() {
	return _resource_root();
}

void ResourceFormatText::set_verbose(bool p_verbose) {
	_verbose = p_verbose;
}

bool ResourceFormatText::is_verbose() {
	return _verbose;
}

int ResourceFormatText::get_last_load_problem_count() {
	return _last_problem_count;
}

String ResourceFormatText::find_project_root(const String &p_file) {
	static std::map<String, String> cache;
	std::error_code ec;
	std::filesystem::path dir = std::filesystem::absolute(std::filesystem::path(p_file), ec).parent_path();
	String key = dir.string();
	auto it = cache.find(key);
	if (it != cache.end()) {
		return it->second;
	}
	String found;
	for (std::filesystem::path d = dir; !d.empty(); d = d.parent_path()) {
		if (std::filesystem::exists(d / "project.godot", ec)) {
			found = d.string();
			break;
		}
		if (d == d.parent_path()) {
			break;
		}
	}
	cache[key] = found;
	return found;
}

String ResourceFormatText::resolve_path(const String &p_path, const String &p_scene_path) {
	String base = _dir_of(p_scene_path);
	if (string_begins_with(p_path, "res://")) {
		String root = _resource_root();
		if (root.empty()) {
			root = find_project_root(p_scene_path);
		}
		if (root.empty()) {
			root = base;
			if (_warned_rootless().insert(base).second) {
				WARN_PRINT(vformat("%s: no project.godot in this folder or above it; res:// paths resolve against the scene's folder \"%s\".", p_scene_path.c_str(), base.empty() ? "." : base.c_str()));
			}
		}
		String rest = p_path.substr(6);
		return root.empty() ? rest : root + "/" + rest;
	}
	if (!p_path.empty() && p_path[0] == '/') {
		return p_path;
	}
	return base.empty() ? p_path : base + "/" + p_path;
}
