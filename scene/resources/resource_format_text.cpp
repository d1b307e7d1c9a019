/**************************************************************************/
/*  resource_format_text.cpp                                              */
/**************************************************************************/

#include "scene/resources/resource_format_text.h"
#include "core/io/file_io.h"

#include "core/error/error_macros.h"
#include "core/io/missing_resource.h"
#include "core/object/class_db.h"
#include "core/variant/variant_parser.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"
#include "scene/resources/text_scene_data.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace {

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

bool _verbose = false;
int _load_depth = 0; // Guards against scenes that instance themselves.
const int MAX_LOAD_DEPTH = 16;
int _last_problem_count = 0;

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
bool _read_file(const String &p_path, String &r_text, String *r_error = nullptr) {
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

// Problems of the outermost load, one entry per distinct problem.
struct ProblemLog {
	struct Entry {
		String where; // "file:line" of the first occurrence.
		String message;
		int count = 0;
	};
	std::vector<Entry> entries;
	std::map<String, size_t> index;

	void add(const String &p_key, const String &p_where, const String &p_message) {
		if (_verbose) {
			WARN_PRINT(p_where + ": " + p_message);
		}
		auto it = index.find(p_key);
		if (it != index.end()) {
			entries[it->second].count++;
			return;
		}
		index[p_key] = entries.size();
		entries.push_back(Entry{ p_where, p_message, 1 });
	}

	void flush() {
		for (const Entry &e : entries) {
			if (e.count == 1) {
				WARN_PRINT(e.where + ": " + e.message);
			} else {
				WARN_PRINT(vformat("%s: %s (\u00d7%d; the first is at this line, --verbose lists all).", e.where.c_str(), e.message.c_str(), e.count));
			}
		}
		entries.clear();
		index.clear();
	}
};

ProblemLog &_problems() {
	static ProblemLog log;
	return log;
}

// Templates of instanced scenes: parsed once, alive while an instance is.
struct TemplateEntry {
	std::weak_ptr<Node> node;
	int64_t mtime = -1;
};

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

// Splits "[name k=v k2=[1, 2] k3="a b"]" into its fields as written.
std::vector<std::pair<String, String>> _split_tag(const String &p_raw) {
	std::vector<std::pair<String, String>> out;
	size_t p = p_raw.find('[');
	if (p == String::npos) {
		return out;
	}
	p++;
	while (p < p_raw.size() && !isspace((unsigned char)p_raw[p]) && p_raw[p] != ']') {
		p++;
	}
	while (p < p_raw.size()) {
		while (p < p_raw.size() && isspace((unsigned char)p_raw[p])) {
			p++;
		}
		if (p >= p_raw.size() || p_raw[p] == ']') {
			break;
		}
		size_t k = p;
		while (p < p_raw.size() && p_raw[p] != '=' && !isspace((unsigned char)p_raw[p])) {
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
				continue;
			}
			if (c == '(' || c == '[' || c == '{') {
				depth++;
			} else if (c == ')' || c == '}' || (c == ']' && depth > 0)) {
				depth--;
			} else if (depth == 0 && (isspace((unsigned char)c) || c == ']')) {
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
	std::vector<String> ids;
	String needle = String(p_kind) + "(\"";
	size_t p = 0;
	while ((p = p_text.find(needle, p)) != String::npos) {
		p += needle.size();
		size_t e = p_text.find('"', p);
		if (e == String::npos) {
			break;
		}
		ids.push_back(p_text.substr(p, e - p));
		p = e;
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

struct ExtRes {
	String type;
	String path; // As written.
	Variant value; // Loaded resource or placeholder (null for scenes).
	int line = 0;
};

class TextLoader {
public:
	String path;
	bool resource_mode = false; // .tres: [gd_resource] ... [resource].
	VariantParser::Stream stream;
	std::map<String, ExtRes> ext_resources;
	std::map<String, Ref<Resource>> sub_resources;
	std::vector<TextSceneData::ExtEntry> ext_entries;
	Node *root = nullptr;
	Ref<Resource> main_resource;
	TextSceneData scene_data; // Moved onto the root at the end.
	String error;

	void problem(int p_line, const String &p_key, const String &p_message) {
		_problems().add(p_key, vformat("%s:%d", path.c_str(), p_line), p_message);
	}

	bool fail(int p_line, const String &p_msg) {
		error = vformat("%s:%d: %s", path.c_str(), p_line, p_msg.c_str());
		return false;
	}

	bool resolve_reference(const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
		if (p_kind == "SubResource") {
			auto it = sub_resources.find(p_id);
			if (it != sub_resources.end()) {
				r_value = it->second;
				return true;
			}
			r_error = vformat("SubResource(\"%s\") is not declared above this line.", p_id.c_str());
			return false;
		}
		auto it = ext_resources.find(p_id);
		if (it == ext_resources.end()) {
			r_error = vformat("ExtResource(\"%s\") is not declared by an [ext_resource] tag.", p_id.c_str());
			return false;
		}
		r_value = it->second.value;
		return true;
	}

	Ref<Resource> make_missing(const String &p_type, const String &p_path) {
		Ref<MissingResource> m;
		m.instantiate();
		m->set_original_class(p_type);
		m->set_path(p_path);
		return m;
	}

	void load_ext_resource(ExtRes &r_ext) {
		if (r_ext.type == "PackedScene") {
			return; // Instanced on use.
		}
		if (r_ext.path.empty()) {
			problem(r_ext.line, "nopath:" + r_ext.type, vformat("%s ext_resource has a uid but no path=; kept as a placeholder.", r_ext.type.c_str()));
			r_ext.value = make_missing(r_ext.type, r_ext.path);
			return;
		}
		String err;
		Ref<Resource> res = ResourceFormatText::load_resource(ResourceFormatText::resolve_path(r_ext.path, path), r_ext.type, &err);
		if (res.is_null()) {
			String ext = _extension(r_ext.path);
			if (err.empty()) {
				problem(r_ext.line, "noloader:" + ext + ":" + r_ext.type, vformat("No loader for %s files (%s \"%s\"); kept as a placeholder and written back on save.", ext.c_str(), r_ext.type.c_str(), r_ext.path.c_str()));
			} else {
				problem(r_ext.line, "loadfail:" + r_ext.path, vformat("Could not load %s \"%s\": %s; kept as a placeholder.", r_ext.type.c_str(), r_ext.path.c_str(), err.c_str()));
			}
			r_ext.value = make_missing(r_ext.type, r_ext.path);
			return;
		}
		if (res->get_path() != r_ext.path) {
			res->set_path(r_ext.path); // The saver finds its ext_resource by this path.
		}
		r_ext.value = res;
	}

	std::shared_ptr<Node> get_template(const ExtRes &p_ext, int p_line) {
		String ext = _extension(p_ext.path);
		String resolved = _canonical(ResourceFormatText::resolve_path(p_ext.path, path));
		int64_t mtime = _mtime(resolved);
		auto &cache = _templates();
		auto it = cache.find(resolved);
		if (it != cache.end()) {
			std::shared_ptr<Node> t = it->second.node.lock();
			if (t && it->second.mtime == mtime) {
				return t;
			}
		}
		if (ext != "tscn" && !_scene_loaders().count(ext)) {
			problem(p_line, "noscene:" + ext, vformat("No scene loader for .%s files (\"%s\"); the instance is kept as a placeholder.", ext.c_str(), p_ext.path.c_str()));
			return nullptr;
		}
		String err;
		Node *node = ResourceFormatText::load_scene(resolved, &err);
		if (!node) {
			problem(p_line, "instfail:" + p_ext.path, vformat("Could not instance \"%s\": %s; kept as a placeholder.", p_ext.path.c_str(), err.empty() ? "the loader returned null" : err.c_str()));
			return nullptr;
		}
		std::shared_ptr<Node> t(node);
		cache[resolved] = TemplateEntry{ t, mtime };
		return t;
	}

	// Keeps "key = raw" on p_target (written back on save).
	void keep_raw(Object *p_target, const String &p_key, const String &p_raw) {
		TextSceneData *d = _data(p_target);
		TextSceneData::StoredProperty sp;
		sp.name = p_key;
		sp.text = p_raw;
		for (const String &id : _referenced_ids(p_raw, "SubResource")) {
			auto it = sub_resources.find(id);
			if (it != sub_resources.end()) {
				sp.refs.push_back(it->second);
			}
		}
		for (auto &P : d->raw) {
			if (P.name == p_key) {
				P = sp;
				return;
			}
		}
		d->raw.push_back(sp);
	}

	void apply_property(Object *p_target, const String &p_key, const Variant &p_value, const String &p_unsupported, const String &p_raw, int p_line) {
		TextSceneData *d = _data(p_target);
		d->key_order.push_back(p_key);
		MissingNode *missing_node = Object::cast_to<MissingNode>(p_target);
		if (Object::cast_to<MissingResource>(p_target) || (missing_node && p_key != "transform" && p_key != "visible")) {
			keep_raw(p_target, p_key, p_raw);
			return; // Counted once for the placeholder itself.
		}
		String cls = p_target->get_class();
		if (!p_unsupported.empty()) {
			keep_raw(p_target, p_key, p_raw);
			problem(p_line, "unsup:" + cls + ":" + p_key, vformat("%s.%s: %s values are not supported; kept as text and written back on save.", cls.c_str(), p_key.c_str(), p_unsupported.c_str()));
			return;
		}
		String err;
		bool applied = p_target->try_set(p_key, p_value, &err);
		if (applied && p_key.find('/') != String::npos && !_lists_property(p_target, p_key)) {
			// A dynamic property the object accepted but does not have (e.g. the surface
			// override of a mesh that could not load): keep it so the save writes it back.
			keep_raw(p_target, p_key, p_raw);
			problem(p_line, "notlisted:" + cls + ":" + p_key, vformat("%s.%s does not exist on this object (its mesh or owner did not load); kept as text and written back on save.", cls.c_str(), p_key.c_str()));
			return;
		}
		if (!applied) {
			keep_raw(p_target, p_key, p_raw);
			bool known = p_target->has_property(p_key);
			if (!known) {
				problem(p_line, "unknown:" + cls + ":" + p_key, vformat("%s has no property '%s'; kept as text and written back on save.", cls.c_str(), p_key.c_str()));
			} else {
				problem(p_line, "bad:" + cls + ":" + p_key, vformat("%s (kept as text and written back on save).", err.c_str()));
			}
		}
	}

	// The header fields that are not name/type/parent/instance, as written.
	static std::vector<std::pair<String, String>> extra_fields(const String &p_raw_tag) {
		std::vector<std::pair<String, String>> out;
		for (const auto &F : _split_tag(p_raw_tag)) {
			if (F.first != "name" && F.first != "type" && F.first != "parent" && F.first != "instance") {
				out.push_back(F);
			}
		}
		return out;
	}

	bool orphan = false; // Set by handle_node_tag for a section kept as text.

	// True when p_path starts at a node that came from an instanced scene (or a placeholder).
	bool under_instance(const String &p_path) const {
		String path = p_path;
		while (!path.empty()) {
			size_t slash = path.rfind('/');
			path = slash == String::npos ? String() : path.substr(0, slash);
			Node *n = path.empty() ? root : root->get_node_or_null(path);
			if (n) {
				const TextSceneData *d = _data_or_null(n);
				return Object::cast_to<MissingNode>(n) || (d && (d->inherited || !d->instance_path.empty()));
			}
		}
		return false;
	}

	bool handle_node_tag(const VariantParser::Tag &p_tag, const String &p_raw_tag, Object *&r_target) {
		r_target = nullptr;
		orphan = false;
		int line = p_tag.line;
		Variant name_v = p_tag.get("name");
		if (name_v.get_type() != Variant::STRING || name_v.to_string().empty()) {
			return fail(line, "[node] needs a non-empty name=\"...\".");
		}
		String name = name_v.to_string();
		bool has_parent = p_tag.has("parent");
		String parent_path = has_parent ? p_tag.get("parent").to_string() : String();
		if (has_parent && p_tag.get("parent").get_type() != Variant::STRING) {
			return fail(line, vformat("Node \"%s\": parent must be a string.", name.c_str()));
		}
		if (!root && has_parent) {
			return fail(line, vformat("Node \"%s\" has a parent, but no root node was declared before it.", name.c_str()));
		}
		if (root && !has_parent) {
			return fail(line, vformat("Node \"%s\" has no parent=\"...\" (only the first node, the root, may omit it).", name.c_str()));
		}
		Node *parent = nullptr;
		if (has_parent) {
			parent = parent_path == "." ? root : root->get_node_or_null(parent_path);
			if (!parent) {
				// Godot allows sections under nodes an instance makes (a glTF's skeleton...). When
				// the instance has no such node, or the parent is missing, keep the section as text.
				if (!under_instance(parent_path)) {
					return fail(line, vformat("Parent node \"%s\" of node \"%s\" does not exist.", parent_path.c_str(), name.c_str()));
				}
				problem(line, "orphan:" + parent_path, vformat("Parent node \"%s\" of node \"%s\" is not in the instanced scene as loaded here; the section is kept as text and written back on save.", parent_path.c_str(), name.c_str()));
				orphan = true;
				return true;
			}
		}
		std::vector<std::pair<String, String>> extras = extra_fields(p_raw_tag);

		Node *node = nullptr;
		if (p_tag.has("instance")) {
			if (p_tag.get("instance").get_type() != Variant::STRING) {
				return fail(line, vformat("Node \"%s\": instance must be ExtResource(\"id\").", name.c_str()));
			}
			String id = p_tag.get("instance").to_string();
			auto it = ext_resources.find(id);
			ERR_FAIL_COND_V(it == ext_resources.end(), false); // Checked when parsing the tag.
			std::shared_ptr<Node> tmpl = get_template(it->second, line);
			if (tmpl) {
				node = _duplicate(tmpl.get());
			}
			if (!node) {
				node = new MissingNode;
			}
			TextSceneData *d = _data(node);
			d->inherited = false;
			d->instance_path = it->second.path;
			d->instance_template = tmpl;
		} else if (p_tag.has("type")) {
			if (p_tag.get("type").get_type() != Variant::STRING) {
				return fail(line, vformat("Node \"%s\": type must be a string.", name.c_str()));
			}
			String type = p_tag.get("type").to_string();
			if (!ClassDB::class_exists(type) || !ClassDB::is_parent_class(type, "Node") || !ClassDB::can_instantiate(type)) {
				problem(line, "type:" + type, vformat("Unknown node type \"%s\": kept as a placeholder (acts as Node3D, keeps its children; type and properties written back on save).", type.c_str()));
				MissingNode *m = new MissingNode;
				m->set_original_class(type);
				node = m;
			} else {
				node = Object::cast_to<Node>(ClassDB::instantiate(type));
			}
		} else {
			// An override section: applies to a node an instance already made.
			Node *existing = parent ? parent->get_node_or_null(name) : nullptr;
			if (existing && existing->get_parent() == parent) {
				TextSceneData *d = _data(existing);
				d->override_section = true;
				d->header_fields = extras;
				r_target = existing;
				return true;
			}
			if (!root) {
				return fail(line, vformat("Root node \"%s\" needs type=\"...\" or instance=ExtResource(...).", name.c_str()));
			}
			problem(line, "override:" + parent_path + "/" + name, vformat("Override section for \"%s/%s\": the instance has no such node; kept as a placeholder and written back on save.", parent_path.c_str(), name.c_str()));
			node = new MissingNode;
			_data(node)->override_section = true;
		}
		if (!node) {
			return fail(line, vformat("Could not create the node \"%s\".", name.c_str()));
		}
		node->set_name(name);
		_data(node)->header_fields = extras;
		if (!root) {
			root = node;
		} else {
			parent->add_child(node);
			if (node->get_parent() != parent) {
				delete node;
				return fail(line, vformat("Could not add node \"%s\" to \"%s\".", name.c_str(), parent_path.c_str()));
			}
		}
		r_target = node;
		return true;
	}

	bool handle_sub_resource_tag(const VariantParser::Tag &p_tag, const String &p_raw_tag, Object *&r_target) {
		r_target = nullptr;
		int line = p_tag.line;
		Variant type_v = p_tag.get("type");
		Variant id_v = p_tag.get("id");
		if (type_v.get_type() != Variant::STRING || (id_v.get_type() != Variant::STRING && id_v.get_type() != Variant::INT)) {
			return fail(line, "[sub_resource] needs type=\"...\" and id=\"...\".");
		}
		String type = type_v.to_string();
		String id = id_v.get_type() == Variant::INT ? itos(id_v.to_int()) : id_v.to_string();
		if (sub_resources.count(id)) {
			return fail(line, vformat("Duplicate sub_resource id \"%s\".", id.c_str()));
		}
		Ref<Resource> res;
		if (ClassDB::class_exists(type) && ClassDB::is_parent_class(type, "Resource") && ClassDB::can_instantiate(type)) {
			res = Ref<Resource>(Object::cast_to<Resource>(ClassDB::instantiate(type)));
		}
		if (res.is_null()) {
			problem(line, "res:" + type, vformat("Unknown resource type \"%s\": kept as a placeholder and written back on save.", type.c_str()));
			res = make_missing(type, String());
		}
		res->set_scene_unique_id(id);
		TextSceneData *d = _data(res.ptr());
		d->load_order = (int)sub_resources.size();
		for (const auto &F : _split_tag(p_raw_tag)) {
			if (F.first != "type" && F.first != "id") {
				d->header_fields.push_back(F);
			}
		}
		sub_resources[id] = res;
		r_target = res.ptr();
		return true;
	}

	bool handle_ext_resource_tag(const VariantParser::Tag &p_tag, const String &p_raw_tag) {
		int line = p_tag.line;
		Variant type_v = p_tag.get("type");
		Variant path_v = p_tag.get("path", String());
		Variant id_v = p_tag.get("id");
		if (type_v.get_type() != Variant::STRING || path_v.get_type() != Variant::STRING || (id_v.get_type() != Variant::STRING && id_v.get_type() != Variant::INT) ||
				(path_v.to_string().empty() && !p_tag.has("uid"))) {
			return fail(line, "[ext_resource] needs type=\"...\", path=\"...\" (or uid=\"...\") and id=\"...\".");
		}
		String id = id_v.get_type() == Variant::INT ? itos(id_v.to_int()) : id_v.to_string();
		if (ext_resources.count(id)) {
			return fail(line, vformat("Duplicate ext_resource id \"%s\".", id.c_str()));
		}
		ExtRes ext;
		ext.type = type_v.to_string();
		ext.path = path_v.to_string();
		ext.line = line;
		load_ext_resource(ext);
		ext_resources[id] = ext;
		TextSceneData::ExtEntry entry;
		entry.id = id;
		entry.type = ext.type;
		entry.path = ext.path;
		entry.fields = _split_tag(p_raw_tag);
		scene_data.ext_entries.push_back(entry);
		return true;
	}

	// The raw text of the section that starts at p_start (tag and its properties).
	String section_text(size_t p_start, size_t p_end) const {
		size_t s = p_start;
		while (s < p_end && (unsigned char)stream.text[s] <= 32) {
			s++;
		}
		return _trim_right(stream.text.substr(s, p_end - s));
	}

	bool run() {
		VariantParser::ResourceFunc res_func = [this](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			return resolve_reference(p_kind, p_id, r_value, r_error);
		};
		// Tag values use a resolver that only checks ids (instance=ExtResource("id")).
		VariantParser::ResourceFunc tag_func = [this](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			if (p_kind != "ExtResource" || !ext_resources.count(p_id)) {
				r_error = vformat("%s(\"%s\") is not a declared ext_resource.", p_kind.c_str(), p_id.c_str());
				return false;
			}
			r_value = p_id;
			return true;
		};

		VariantParser::Tag tag;
		String err;
		size_t p0 = stream.pos;
		if (!VariantParser::parse_tag(stream, tag, err, tag_func)) {
			return fail(stream.line, err);
		}
		const char *header = resource_mode ? "gd_resource" : "gd_scene";
		if (tag.name != header) {
			return fail(tag.line, vformat("Expected a [%s ...] header, got [%s].", header, tag.name.c_str()));
		}
		scene_data.file_header = _split_tag(stream.text.substr(p0, stream.pos - p0));
		if (tag.has("format")) {
			int64_t format = tag.get("format").get_type() == Variant::INT ? tag.get("format").to_int() : -1;
			if (format < 2 || format > 4) {
				problem(tag.line, "format", vformat("Unsupported format %lld (expected 3); trying anyway.", (long long)format));
			}
		}
		String resource_type = resource_mode ? tag.get("type").to_string() : String();

		Object *target = nullptr;
		String section; // Name of the current section; empty before the first.
		size_t tail_start = String::npos; // Start of a section kept as text.
		bool orphan_start = false;
		auto close_tail = [&](size_t p_end) {
			if (tail_start != String::npos) {
				String text = section_text(tail_start, p_end);
				for (const String &id : _referenced_ids(text, "SubResource")) {
					auto it = sub_resources.find(id);
					if (it != sub_resources.end()) {
						scene_data.section_refs.push_back(it->second); // Saved with the text that names it.
					}
				}
				(orphan_start ? scene_data.orphan_sections : scene_data.tail_sections).push_back(text);
				tail_start = String::npos;
				orphan_start = false;
			}
		};
		while (true) {
			String assign;
			Variant value;
			String unsupported;
			bool eof = false;
			err.clear();
			bool is_tag = false;
			size_t start = stream.pos;
			{
				// Peek: a tag starts with '[' after blanks/comments. Tags need the id-only resolver.
				size_t p = stream.pos;
				while (p < stream.text.size()) {
					char c = stream.text[p];
					if (c == ';') {
						while (p < stream.text.size() && stream.text[p] != '\n') {
							p++;
						}
					} else if ((unsigned char)c <= 32) {
						p++;
					} else {
						break;
					}
				}
				is_tag = p < stream.text.size() && stream.text[p] == '[';
			}
			if (is_tag || stream.pos >= stream.text.size()) {
				close_tail(stream.pos);
			}
			if (!VariantParser::parse_tag_assign_eof(stream, tag, assign, value, err, is_tag ? tag_func : res_func, &eof, &unsupported)) {
				if (tail_start != String::npos && !is_tag) {
					// A property of a kept section that we cannot parse: keep the text.
					while (stream.pos < stream.text.size() && stream.text[stream.pos] != '\n') {
						stream.pos++;
					}
					continue;
				}
				return fail(stream.line, err);
			}
			if (eof) {
				break;
			}
			if (!assign.empty()) {
				int line = tag.line;
				if (section.empty()) {
					return fail(line, vformat("Property '%s' appears before any [node] or [sub_resource] section.", assign.c_str()));
				}
				if (!target) {
					continue; // Part of a section kept as text.
				}
				String raw = _trim_right(stream.text.substr(_value_start(stream.text, start), stream.pos - _value_start(stream.text, start)));
				apply_property(target, assign, value, unsupported, raw, line);
				continue;
			}

			String raw_tag = section_text(start, stream.pos);
			section = tag.name;
			target = nullptr;
			if (tag.name == "ext_resource") {
				if (!handle_ext_resource_tag(tag, raw_tag)) {
					return false;
				}
				section = String(); // Properties may not follow.
			} else if (tag.name == "sub_resource") {
				if (!handle_sub_resource_tag(tag, raw_tag, target)) {
					return false;
				}
			} else if (tag.name == "node" && !resource_mode) {
				if (!handle_node_tag(tag, raw_tag, target)) {
					return false;
				}
				if (orphan) {
					tail_start = start; // Kept with its properties, written after the nodes.
					orphan_start = true;
				}
			} else if (tag.name == "resource" && resource_mode) {
				if (ClassDB::class_exists(resource_type) && ClassDB::is_parent_class(resource_type, "Resource") && ClassDB::can_instantiate(resource_type)) {
					main_resource = Ref<Resource>(Object::cast_to<Resource>(ClassDB::instantiate(resource_type)));
				}
				if (main_resource.is_null()) {
					problem(tag.line, "res:" + resource_type, vformat("Unknown resource type \"%s\": kept as a placeholder.", resource_type.c_str()));
					main_resource = make_missing(resource_type, String());
				}
				target = main_resource.ptr();
			} else {
				if (tag.name != "connection" && tag.name != "editable") {
					problem(tag.line, "section:" + tag.name, vformat("Unknown section [%s]: kept as text and written back on save.", tag.name.c_str()));
				}
				tail_start = start;
			}
		}
		close_tail(stream.pos);
		if (resource_mode) {
			if (main_resource.is_null()) {
				return fail(stream.line, "The resource file has no [resource] section.");
			}
			return true;
		}
		if (!root) {
			return fail(stream.line, "The scene has no [node] section.");
		}
		return true;
	}
};

// Saver.

struct SaveState {
	std::vector<TextSceneData::ExtEntry> ext_list;
	std::map<String, size_t> ext_by_path;
	std::map<const Object *, String> ext_ids;
	std::vector<Ref<Resource>> sub_list; // Dependency order (dependencies first).
	std::map<const Object *, String> sub_ids;
	std::set<String> used_sub_ids;
	std::set<const Object *> visiting;
	int next_sub = 1;

	static bool is_external(const Resource *p_res) {
		return !p_res->get_path().empty() && p_res->get_path().find("::") == String::npos;
	}

	static String class_of(const Object *p_obj) {
		if (const MissingResource *m = Object::cast_to<MissingResource>(p_obj)) {
			return m->get_original_class();
		}
		if (const MissingNode *m = Object::cast_to<MissingNode>(p_obj)) {
			return m->get_original_class();
		}
		return p_obj->get_class();
	}

	// Stored properties of p_obj that differ from p_base (a template node) or,
	// without one, from the class default.
	static void collect_properties(const Object *p_obj, const Object *p_base, std::vector<std::pair<String, Variant>> *r_props) {
		std::vector<PropertyInfo> plist;
		p_obj->get_property_list(&plist);
		String cls = p_obj->get_class();
		for (const PropertyInfo &pi : plist) {
			if (pi.is_group_marker() || !(pi.usage & PROPERTY_USAGE_STORAGE)) {
				continue;
			}
			bool valid = false;
			Variant value = p_obj->get(pi.name, &valid);
			if (!valid) {
				continue;
			}
			if (value.get_type() == Variant::OBJECT && !Object::cast_to<Resource>(value.get_object())) {
				continue; // Only resources can be saved.
			}
			if (p_base) {
				bool base_valid = false;
				Variant base = p_base->get(pi.name, &base_valid);
				if (base_valid && base == value) {
					continue;
				}
				if (!base_valid && value.get_type() == Variant::NIL) {
					continue;
				}
			} else {
				bool has_default = false;
				Variant def = ClassDB::class_get_property_default(cls, pi.name, &has_default);
				if (has_default && def == value) {
					continue;
				}
				if (!has_default && value.get_type() == Variant::NIL) {
					continue;
				}
			}
			r_props->push_back(std::make_pair(pi.name, value));
		}
	}

	String ext_id_for(const String &p_path, const String &p_type) {
		auto it = ext_by_path.find(p_path);
		if (it != ext_by_path.end()) {
			return ext_list[it->second].id;
		}
		TextSceneData::ExtEntry e;
		std::set<String> used;
		for (const auto &x : ext_list) {
			used.insert(x.id);
		}
		int n = (int)ext_list.size() + 1;
		do {
			e.id = itos(n++) + "_" + _hash_suffix(p_path, 5);
		} while (used.count(e.id));
		e.type = p_type;
		e.path = p_path;
		ext_by_path[p_path] = ext_list.size();
		ext_list.push_back(e);
		return e.id;
	}

	void find_resource(Resource *p_res) {
		if (!p_res || ext_ids.count(p_res) || sub_ids.count(p_res) || visiting.count(p_res)) {
			return;
		}
		if (is_external(p_res)) {
			ext_ids[p_res] = ext_id_for(p_res->get_path(), class_of(p_res));
			return;
		}
		visiting.insert(p_res);
		find_resources(p_res, nullptr);
		visiting.erase(p_res);
		String id = p_res->get_scene_unique_id();
		if (id.empty() || used_sub_ids.count(id)) {
			do {
				id = class_of(p_res) + "_" + _hash_suffix(class_of(p_res) + itos(next_sub++), 5);
			} while (used_sub_ids.count(id));
		}
		used_sub_ids.insert(id);
		sub_ids[p_res] = id;
		sub_list.push_back(Ref<Resource>(p_res));
	}

	void find_resources(const Object *p_obj, const Object *p_base) {
		std::vector<std::pair<String, Variant>> props;
		collect_properties(p_obj, p_base, &props);
		for (const auto &P : props) {
			find_resource(Object::cast_to<Resource>(P.second.get_object()));
		}
		if (const TextSceneData *d = _data_or_null(p_obj)) {
			for (const auto &sp : d->raw) {
				for (const Ref<Resource> &r : sp.refs) {
					find_resource(const_cast<Resource *>(r.ptr()));
				}
			}
		}
	}

	String encode(const Object *p_obj) const {
		auto e = ext_ids.find(p_obj);
		if (e != ext_ids.end()) {
			return "ExtResource(\"" + e->second + "\")";
		}
		auto s = sub_ids.find(p_obj);
		if (s != sub_ids.end()) {
			return "SubResource(\"" + s->second + "\")";
		}
		return "null";
	}

	// "key = value" lines: applied properties, then those kept as text, in the
	// order the file had them.
	void write_properties(const Object *p_obj, const Object *p_base, String &r_out) const {
		std::vector<std::pair<String, Variant>> props;
		collect_properties(p_obj, p_base, &props);
		VariantWriter::ObjectEncoder enc = [this](const Object *p_o) { return encode(p_o); };
		std::vector<std::pair<String, String>> lines;
		std::set<String> written;
		for (const auto &P : props) {
			lines.push_back(std::make_pair(P.first, VariantWriter::write_to_string(P.second, enc)));
			written.insert(P.first);
		}
		const TextSceneData *d = _data_or_null(p_obj);
		if (d) {
			for (const auto &sp : d->raw) {
				if (!written.count(sp.name)) {
					lines.push_back(std::make_pair(sp.name, sp.text));
				}
			}
			std::map<String, size_t> order;
			for (size_t i = 0; i < d->key_order.size(); i++) {
				order.emplace(d->key_order[i], i);
			}
			std::stable_sort(lines.begin(), lines.end(), [&](const std::pair<String, String> &a, const std::pair<String, String> &b) {
				auto ia = order.find(a.first);
				auto ib = order.find(b.first);
				size_t ka = ia == order.end() ? order.size() : ia->second;
				size_t kb = ib == order.end() ? order.size() : ib->second;
				return ka < kb;
			});
		}
		for (const auto &L : lines) {
			String key = L.first;
			if (key.find_first_of(" \t\"=[]") != String::npos) {
				key = VariantWriter::escape_string(key);
			}
			r_out += key + " = " + L.second + "\n";
		}
	}
};

// The instance root above p_node (not itself inherited) and p_node's counterpart in its template.
const Node *_template_counterpart(const Node *p_node) {
	String rel = p_node->get_name();
	for (const Node *a = p_node->get_parent(); a; a = a->get_parent()) {
		const TextSceneData *d = _data_or_null(a);
		if (d && !d->inherited && !d->instance_path.empty()) {
			return d->instance_template ? d->instance_template->get_node_or_null(rel) : nullptr;
		}
		rel = a->get_name() + "/" + rel;
	}
	return nullptr;
}

struct NodeOut {
	const Node *node;
	const Node *base; // Template node to diff against (instances and overrides).
	bool override_only; // Inherited node: written only if something differs.
};

void _collect_nodes(const Node *p_node, std::vector<NodeOut> *r_nodes) {
	const TextSceneData *d = _data_or_null(p_node);
	NodeOut o{ p_node, nullptr, false };
	if (d && d->inherited) {
		o.base = _template_counterpart(p_node);
		o.override_only = true;
	} else if (d && !d->instance_path.empty() && d->instance_template) {
		o.base = d->instance_template.get();
	}
	r_nodes->push_back(o);
	for (int i = 0; i < p_node->get_child_count(); i++) {
		_collect_nodes(p_node->get_child(i), r_nodes);
	}
}

String _write_fields(const std::vector<std::pair<String, String>> &p_fields) {
	String out;
	for (const auto &F : p_fields) {
		out += " " + F.first + "=" + F.second;
	}
	return out;
}

} // namespace

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

namespace {

// Runs p_func as (part of) a load: the outermost load flushes the problem log
// and the resource cache.
template <class F>
auto _as_load(const String &p_path, String *r_error, F p_func) -> decltype(p_func()) {
	if (_load_depth >= MAX_LOAD_DEPTH) {
		String msg = vformat("%s:1: Scenes are nested more than %d deep (does a scene instance itself?).", p_path.c_str(), MAX_LOAD_DEPTH);
		if (r_error) {
			*r_error = msg;
		}
		ERR_PRINT(msg);
		return decltype(p_func())();
	}
	_load_depth++;
	auto result = p_func();
	_load_depth--;
	if (_load_depth == 0) {
		_last_problem_count = (int)_problems().entries.size();
		_problems().flush();
		_resource_cache().clear();
	}
	return result;
}

} // namespace

Node *ResourceFormatText::load_scene_from_string(const String &p_text, const String &p_path, String *r_error) {
	return _as_load(p_path, r_error, [&]() -> Node * {
		TextLoader loader;
		loader.path = p_path;
		loader.stream = VariantParser::Stream(p_text);
		bool ok = loader.run();
		if (!ok) {
			delete loader.root; // Deletes the partial tree.
			if (r_error) {
				*r_error = loader.error;
			}
			ERR_PRINT(loader.error);
			return nullptr;
		}
		if (r_error) {
			r_error->clear();
		}
		TextSceneData *d = _data(loader.root);
		d->file_header = loader.scene_data.file_header;
		d->ext_entries = loader.scene_data.ext_entries;
		d->tail_sections = loader.scene_data.tail_sections;
		d->orphan_sections = loader.scene_data.orphan_sections;
		d->section_refs = loader.scene_data.section_refs;
		d->is_scene_root = true;
		return loader.root;
	});
}

Node *ResourceFormatText::load_scene(const String &p_path, String *r_error) {
	String ext = _extension(p_path);
	auto it = _scene_loaders().find(ext);
	if (it != _scene_loaders().end()) {
		return _as_load(p_path, r_error, [&]() -> Node * {
			String err;
			Node *node = it->second(p_path, &err);
			if (r_error) {
				*r_error = node ? String() : (err.empty() ? p_path + ": the loader returned null." : err);
			}
			return node;
		});
	}
	String text, read_error;
	if (!_read_file(p_path, text, &read_error)) {
		String msg = vformat("%s:0: Cannot open the scene file: %s", p_path.c_str(), read_error.c_str());
		if (r_error) {
			*r_error = msg;
		}
		ERR_PRINT(msg);
		return nullptr;
	}
	return load_scene_from_string(text, p_path, r_error);
}

Ref<Resource> ResourceFormatText::load_resource_from_string(const String &p_text, const String &p_path, String *r_error) {
	return _as_load(p_path, r_error, [&]() -> Ref<Resource> {
		TextLoader loader;
		loader.path = p_path;
		loader.resource_mode = true;
		loader.stream = VariantParser::Stream(p_text);
		if (!loader.run()) {
			if (r_error) {
				*r_error = loader.error;
			}
			return Ref<Resource>();
		}
		if (r_error) {
			r_error->clear();
		}
		return loader.main_resource;
	});
}

Ref<Resource> ResourceFormatText::load_resource(const String &p_path, const String &p_type_hint, String *r_error) {
	String key = _canonical(p_path);
	auto cached = _resource_cache().find(key);
	if (cached != _resource_cache().end()) {
		return cached->second;
	}
	String ext = _extension(p_path);
	Ref<Resource> res;
	auto it = _resource_loaders().find(ext);
	if (it != _resource_loaders().end()) {
		res = _as_load(p_path, r_error, [&]() { return it->second(p_path, p_type_hint, r_error); });
	} else if (ext == "tres") {
		String text;
		if (!_read_file(p_path, text)) {
			if (r_error) {
				*r_error = "cannot open the file";
			}
			return Ref<Resource>();
		}
		res = load_resource_from_string(text, p_path, r_error);
	} else {
		if (r_error) {
			r_error->clear(); // No loader: not an error of the file.
		}
		return Ref<Resource>();
	}
	if (res.is_valid()) {
		// The path as the scene wrote it is set by the caller's ext_resource; keep a file path here.
		if (res->get_path().empty()) {
			res->set_path(p_path);
		}
		_resource_cache()[key] = res;
	}
	return res;
}

String ResourceFormatText::save_scene_to_string(const Node *p_root) {
	ERR_FAIL_NULL_V_MSG(p_root, String(), "Cannot save a null scene root.");
	std::vector<NodeOut> nodes;
	_collect_nodes(p_root, &nodes);
	const TextSceneData *root_data = _data_or_null(p_root);

	SaveState state;
	if (root_data) {
		for (const auto &e : root_data->ext_entries) {
			state.ext_by_path[e.path] = state.ext_list.size();
			state.ext_list.push_back(e); // All kept: text kept as-is may name them.
		}
	}
	// Resources that came from the file first, in file order, then new ones.
	std::vector<std::pair<int, Resource *>> loaded;
	for (const NodeOut &o : nodes) {
		const TextSceneData *d = _data_or_null(o.node);
		if (d && !d->instance_path.empty() && !d->inherited) {
			state.ext_id_for(d->instance_path, "PackedScene");
		}
		std::vector<std::pair<String, Variant>> props;
		SaveState::collect_properties(o.node, o.base, &props);
		for (const auto &P : props) {
			Resource *r = Object::cast_to<Resource>(P.second.get_object());
			const TextSceneData *rd = r ? _data_or_null(r) : nullptr;
			if (rd && rd->load_order >= 0 && !SaveState::is_external(r)) {
				loaded.push_back(std::make_pair(rd->load_order, r));
			}
		}
		if (d) {
			for (const auto &sp : d->raw) {
				for (const Ref<Resource> &r : sp.refs) {
					const TextSceneData *rd = _data_or_null(r.ptr());
					if (rd && rd->load_order >= 0) {
						loaded.push_back(std::make_pair(rd->load_order, const_cast<Resource *>(r.ptr())));
					}
				}
			}
		}
	}
	if (root_data) {
		for (const Ref<Resource> &r : root_data->section_refs) {
			const TextSceneData *rd = _data_or_null(r.ptr());
			loaded.push_back(std::make_pair(rd ? rd->load_order : 0, const_cast<Resource *>(r.ptr())));
		}
	}
	std::stable_sort(loaded.begin(), loaded.end(), [](const std::pair<int, Resource *> &a, const std::pair<int, Resource *> &b) { return a.first < b.first; });
	for (const auto &L : loaded) {
		state.find_resource(L.second);
	}
	for (const NodeOut &o : nodes) {
		state.find_resources(o.node, o.base);
	}

	String out;
	int load_steps = (int)(state.ext_list.size() + state.sub_list.size()) + 1;
	if (root_data && !root_data->file_header.empty()) {
		out += "[gd_scene";
		for (const auto &F : root_data->file_header) {
			if (F.first == "load_steps") {
				if (load_steps > 1) {
					out += " load_steps=" + itos(load_steps);
				}
			} else {
				out += " " + F.first + "=" + F.second;
			}
		}
		out += "]\n";
	} else {
		TextSceneData *d = _data(const_cast<Node *>(p_root));
		if (d->file_header.empty()) {
			d->file_header.push_back(std::make_pair(String("format"), String("3")));
			d->file_header.push_back(std::make_pair(String("uid"), "\"uid://" + _hash_suffix(p_root->get_name() + itos((long long)(size_t)p_root), 13) + "\""));
		}
		out += "[gd_scene" + _write_fields(d->file_header) + "]\n";
	}
	if (!state.ext_list.empty()) {
		out += "\n"; // Godot writes the ext_resource lines as one block.
	}
	for (const auto &e : state.ext_list) {
		if (!e.fields.empty()) {
			out += "[ext_resource" + _write_fields(e.fields) + "]\n";
		} else {
			out += "[ext_resource type=" + VariantWriter::escape_string(e.type) + " path=" + VariantWriter::escape_string(e.path) + " id=" + VariantWriter::escape_string(e.id) + "]\n";
		}
	}
	for (const Ref<Resource> &res : state.sub_list) {
		out += "\n[sub_resource type=" + VariantWriter::escape_string(SaveState::class_of(res.ptr())) + " id=" + VariantWriter::escape_string(state.sub_ids[res.ptr()]);
		if (const TextSceneData *d = _data_or_null(res.ptr())) {
			out += _write_fields(d->header_fields);
		}
		out += "]\n";
		state.write_properties(res.ptr(), nullptr, out);
	}
	for (const NodeOut &o : nodes) {
		const Node *n = o.node;
		const TextSceneData *d = _data_or_null(n);
		String props;
		state.write_properties(n, o.base, props);
		if (o.override_only && props.empty() && !(d && d->override_section)) {
			continue; // An instanced node nothing changed.
		}
		out += "\n[node name=" + VariantWriter::escape_string(n->get_name());
		bool is_instance = d && !d->inherited && !d->instance_path.empty();
		String type = SaveState::class_of(n);
		if (!o.override_only && !is_instance && !type.empty()) {
			out += " type=" + VariantWriter::escape_string(type);
		}
		if (n != p_root) {
			String parent = n->get_parent() == p_root ? String(".") : _relative_path(p_root, n->get_parent());
			out += " parent=" + VariantWriter::escape_string(parent);
		}
		if (d) {
			out += _write_fields(d->header_fields);
		}
		if (is_instance) {
			out += " instance=ExtResource(" + VariantWriter::escape_string(state.ext_id_for(d->instance_path, "PackedScene")) + ")";
		}
		out += "]\n" + props;
	}
	if (root_data) {
		for (const String &s : root_data->orphan_sections) {
			out += "\n" + s + "\n";
		}
		for (const String &s : root_data->tail_sections) {
			out += "\n" + s + "\n";
		}
	}
	return out;
}

bool ResourceFormatText::save_scene(const Node *p_root, const String &p_path, String *r_error) {
	if (!p_root) {
		if (r_error) {
			*r_error = "Cannot save a null scene root.";
		}
		ERR_PRINT("Cannot save a null scene root.");
		return false;
	}
	String text = save_scene_to_string(p_root);
	String write_error; // Atomic and checked through close (core/io/file_io.h).
	if (!file_write_atomic(p_path, text, &write_error)) {
		String msg = vformat("%s: Cannot write the scene file: %s", p_path.c_str(), write_error.c_str());
		if (r_error) {
			*r_error = msg;
		}
		ERR_PRINT(msg);
		return false;
	}
	return true;
}
