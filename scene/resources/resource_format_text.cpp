/**************************************************************************/
/*  resource_format_text.cpp                                              */
/**************************************************************************/

#include "scene/resources/resource_format_text.h"
#include "core/io/file_io.h"

#include "core/error/error_macros.h"
#include "core/object/class_db.h"
#include "core/variant/variant_parser.h"
#include "scene/main/node.h"

#include <algorithm>
#include <cctype>
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

int _load_depth = 0; // Guards against scenes that instance themselves.
const int MAX_LOAD_DEPTH = 16;

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

struct ExtRes {
	String type;
	String path; // As written.
	Variant value; // Loaded resource (null when no loader / failed / scene).
	int line = 0;
};

class SceneLoader {
public:
	String path;
	VariantParser::Stream stream;
	std::map<String, ExtRes> ext_resources;
	std::map<String, Ref<Resource>> sub_resources;
	std::set<String> declared_subs; // Includes ones we could not create.
	std::set<String> skipped_paths; // Node paths (relative to root) skipped with their subtree.
	Node *root = nullptr;
	String error;

	void warn(int p_line, const String &p_msg) {
		WARN_PRINT(vformat("%s:%d: %s", path.c_str(), p_line, p_msg.c_str()));
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
			if (declared_subs.count(p_id)) {
				r_value = Variant(); // Declared but not created (already warned).
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

	void load_ext_resource(ExtRes &r_ext) {
		if (r_ext.type == "PackedScene") {
			return; // Instanced on use.
		}
		String ext = _extension(r_ext.path);
		auto it = _resource_loaders().find(ext);
		if (it == _resource_loaders().end()) {
			warn(r_ext.line, vformat("No loader for %s \"%s\" (extension '%s'); references to it will be null.", r_ext.type.c_str(), r_ext.path.c_str(), ext.c_str()));
			return;
		}
		String err;
		Ref<Resource> res = it->second(ResourceFormatText::resolve_path(r_ext.path, path), r_ext.type, &err);
		if (res.is_null()) {
			warn(r_ext.line, vformat("Could not load %s \"%s\": %s", r_ext.type.c_str(), r_ext.path.c_str(), err.empty() ? "loader returned null" : err.c_str()));
			return;
		}
		res->set_path(r_ext.path);
		r_ext.value = res;
	}

	Node *instance_scene(const ExtRes &p_ext, int p_line) {
		String ext = _extension(p_ext.path);
		String resolved = ResourceFormatText::resolve_path(p_ext.path, path);
		String err;
		Node *node = nullptr;
		auto it = _scene_loaders().find(ext);
		if (it != _scene_loaders().end()) {
			node = it->second(resolved, &err);
		} else if (ext == "tscn") {
			node = ResourceFormatText::load_scene(resolved, &err);
		} else {
			warn(p_line, vformat("No scene loader for \"%s\" (extension '%s'); the node is skipped.", p_ext.path.c_str(), ext.c_str()));
			return nullptr;
		}
		if (!node) {
			warn(p_line, vformat("Could not instance \"%s\": %s", p_ext.path.c_str(), err.empty() ? "loader returned null" : err.c_str()));
		}
		return node;
	}

	// Applies one "key = value" to p_target; problems are warnings.
	void apply_property(Object *p_target, const String &p_key, const Variant &p_value, const String &p_unsupported, int p_line) {
		if (!p_unsupported.empty()) {
			warn(p_line, vformat("Property '%s' of %s has a value of unsupported type %s; skipped.", p_key.c_str(), p_target->get_class().c_str(), p_unsupported.c_str()));
			return;
		}
		String err;
		if (!p_target->try_set(p_key, p_value, &err)) {
			warn(p_line, err);
		}
	}

	bool handle_node_tag(const VariantParser::Tag &p_tag, Object *&r_target) {
		r_target = nullptr;
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

		String my_path = !has_parent ? String() : (parent_path == "." ? name : parent_path + "/" + name);
		if (has_parent && parent_path != ".") {
			for (const String &skipped : skipped_paths) {
				if (parent_path == skipped || string_begins_with(parent_path, skipped + "/")) {
					skipped_paths.insert(my_path);
					return true; // Child of a skipped node: skipped quietly.
				}
			}
		}
		Node *parent = nullptr;
		if (has_parent) {
			parent = parent_path == "." ? root : root->get_node_or_null(parent_path);
			if (!parent) {
				return fail(line, vformat("Parent node \"%s\" of node \"%s\" does not exist.", parent_path.c_str(), name.c_str()));
			}
		}

		Node *node = nullptr;
		if (p_tag.has("instance")) {
			if (p_tag.get("instance").get_type() != Variant::STRING) {
				return fail(line, vformat("Node \"%s\": instance must be ExtResource(\"id\").", name.c_str()));
			}
			String id = p_tag.get("instance").to_string();
			auto it = ext_resources.find(id);
			ERR_FAIL_COND_V(it == ext_resources.end(), false); // Checked when parsing the tag.
			node = instance_scene(it->second, line);
		} else {
			if (!p_tag.has("type") || p_tag.get("type").get_type() != Variant::STRING) {
				return fail(line, vformat("Node \"%s\" needs type=\"...\" or instance=ExtResource(...).", name.c_str()));
			}
			String type = p_tag.get("type").to_string();
			if (!ClassDB::class_exists(type) || !ClassDB::is_parent_class(type, "Node") || !ClassDB::can_instantiate(type)) {
				if (!root) {
					return fail(line, vformat("Root node \"%s\" has unknown or non-instantiable type \"%s\".", name.c_str(), type.c_str()));
				}
				warn(line, vformat("Unknown node type \"%s\" for node \"%s\"; skipping it and its children.", type.c_str(), name.c_str()));
			} else {
				node = Object::cast_to<Node>(ClassDB::instantiate(type));
			}
		}
		if (!node) {
			if (!root) {
				return fail(line, vformat("Could not create the root node \"%s\".", name.c_str()));
			}
			skipped_paths.insert(my_path);
			return true;
		}
		node->set_name(name);
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

	bool handle_sub_resource_tag(const VariantParser::Tag &p_tag, Object *&r_target) {
		r_target = nullptr;
		int line = p_tag.line;
		Variant type_v = p_tag.get("type");
		Variant id_v = p_tag.get("id");
		if (type_v.get_type() != Variant::STRING || (id_v.get_type() != Variant::STRING && id_v.get_type() != Variant::INT)) {
			return fail(line, "[sub_resource] needs type=\"...\" and id=\"...\".");
		}
		String type = type_v.to_string();
		String id = id_v.get_type() == Variant::INT ? itos(id_v.to_int()) : id_v.to_string();
		if (declared_subs.count(id)) {
			return fail(line, vformat("Duplicate sub_resource id \"%s\".", id.c_str()));
		}
		declared_subs.insert(id);
		if (!ClassDB::class_exists(type) || !ClassDB::is_parent_class(type, "Resource") || !ClassDB::can_instantiate(type)) {
			warn(line, vformat("Unknown resource type \"%s\" for sub_resource \"%s\"; references to it will be null.", type.c_str(), id.c_str()));
			return true;
		}
		Ref<Resource> res(Object::cast_to<Resource>(ClassDB::instantiate(type)));
		if (res.is_null()) {
			warn(line, vformat("Could not create sub_resource \"%s\" of type \"%s\".", id.c_str(), type.c_str()));
			return true;
		}
		res->set_scene_unique_id(id);
		sub_resources[id] = res;
		r_target = res.ptr();
		return true;
	}

	bool handle_ext_resource_tag(const VariantParser::Tag &p_tag) {
		int line = p_tag.line;
		Variant type_v = p_tag.get("type");
		Variant path_v = p_tag.get("path");
		Variant id_v = p_tag.get("id");
		if (type_v.get_type() != Variant::STRING || path_v.get_type() != Variant::STRING || (id_v.get_type() != Variant::STRING && id_v.get_type() != Variant::INT)) {
			return fail(line, "[ext_resource] needs type=\"...\", path=\"...\" and id=\"...\".");
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
		return true;
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
		if (!VariantParser::parse_tag(stream, tag, err, tag_func)) {
			return fail(stream.line, err);
		}
		if (tag.name != "gd_scene") {
			return fail(tag.line, vformat("Expected a [gd_scene ...] header, got [%s].", tag.name.c_str()));
		}
		if (tag.has("format")) {
			int64_t format = tag.get("format").get_type() == Variant::INT ? tag.get("format").to_int() : -1;
			if (format < 2 || format > 4) {
				warn(tag.line, vformat("Unsupported scene format %lld (expected 3); trying anyway.", (long long)format));
			}
		}

		Object *target = nullptr;
		String section; // Name of the current section; empty before the first.
		bool skipping = false; // Section whose object could not be created.
		while (true) {
			String assign;
			Variant value;
			String unsupported;
			bool eof = false;
			err.clear();
			bool is_tag = false;
			{
				// Peek: a tag starts with '[' after blanks/comments. parse_tag_assign_eof
				// handles both; tags need the id-only resolver.
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
			if (!VariantParser::parse_tag_assign_eof(stream, tag, assign, value, err, is_tag ? tag_func : res_func, &eof, &unsupported)) {
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
				if (skipping || !target) {
					continue;
				}
				apply_property(target, assign, value, unsupported, line);
				continue;
			}

			section = tag.name;
			target = nullptr;
			skipping = false;
			for (const String &f : tag.unsupported_fields) {
				warn(tag.line, vformat("Field '%s' of [%s] has an unsupported value; ignored.", f.c_str(), tag.name.c_str()));
			}
			if (tag.name == "ext_resource") {
				if (!handle_ext_resource_tag(tag)) {
					return false;
				}
				section = String(); // Properties may not follow.
			} else if (tag.name == "sub_resource") {
				if (!handle_sub_resource_tag(tag, target)) {
					return false;
				}
				skipping = target == nullptr;
			} else if (tag.name == "node") {
				if (!handle_node_tag(tag, target)) {
					return false;
				}
				skipping = target == nullptr;
			} else if (tag.name == "connection" || tag.name == "editable") {
				warn(tag.line, vformat("[%s] is not supported; ignored.", tag.name.c_str()));
				skipping = true;
			} else {
				warn(tag.line, vformat("Unknown section [%s]; ignored with its properties.", tag.name.c_str()));
				skipping = true;
			}
		}
		if (!root) {
			return fail(stream.line, "The scene has no [node] section.");
		}
		return true;
	}
};

// Saver helpers.

struct SaveState {
	std::vector<Ref<Resource>> ext_list;
	std::map<const Object *, String> ext_ids;
	std::vector<Ref<Resource>> sub_list; // Dependency order (dependencies first).
	std::map<const Object *, String> sub_ids;
	std::set<String> used_sub_ids;
	std::set<const Object *> visiting;
	int next_sub = 1;

	static bool is_external(const Resource *p_res) {
		return !p_res->get_path().empty() && p_res->get_path().find("::") == String::npos;
	}

	void collect_properties(const Object *p_obj, std::vector<std::pair<String, Variant>> *r_props) {
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
			bool has_default = false;
			Variant def = ClassDB::class_get_property_default(cls, pi.name, &has_default);
			if (has_default && def == value) {
				continue;
			}
			r_props->push_back(std::make_pair(pi.name, value));
		}
	}

	void find_resources(const Object *p_obj) {
		std::vector<std::pair<String, Variant>> props;
		collect_properties(p_obj, &props);
		for (const auto &P : props) {
			Resource *res = Object::cast_to<Resource>(P.second.get_object());
			if (!res || ext_ids.count(res) || sub_ids.count(res) || visiting.count(res)) {
				continue;
			}
			if (is_external(res)) {
				ext_ids[res] = itos(ext_list.size() + 1);
				ext_list.push_back(Ref<Resource>(res));
				continue;
			}
			visiting.insert(res);
			find_resources(res);
			visiting.erase(res);
			String id = res->get_scene_unique_id();
			if (id.empty() || used_sub_ids.count(id)) {
				do {
					id = res->get_class() + "_" + itos(next_sub++);
				} while (used_sub_ids.count(id));
			}
			used_sub_ids.insert(id);
			sub_ids[res] = id;
			sub_list.push_back(Ref<Resource>(res));
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

	void write_properties(const Object *p_obj, String &r_out) const {
		std::vector<std::pair<String, Variant>> props;
		const_cast<SaveState *>(this)->collect_properties(p_obj, &props);
		VariantWriter::ObjectEncoder enc = [this](const Object *p_o) { return encode(p_o); };
		for (const auto &P : props) {
			String key = P.first;
			if (key.find_first_of(" \t\"=[]") != String::npos) {
				key = VariantWriter::escape_string(key);
			}
			r_out += key + " = " + VariantWriter::write_to_string(P.second, enc) + "\n";
		}
	}
};

void _collect_nodes(const Node *p_node, std::vector<const Node *> *r_nodes) {
	r_nodes->push_back(p_node);
	for (int i = 0; i < p_node->get_child_count(); i++) {
		_collect_nodes(p_node->get_child(i), r_nodes);
	}
}

String _relative_path(const Node *p_root, const Node *p_node) {
	String path;
	for (const Node *n = p_node; n && n != p_root; n = n->get_parent()) {
		path = path.empty() ? n->get_name() : n->get_name() + "/" + path;
	}
	return path;
}

} // namespace

void ResourceFormatText::add_scene_loader(const String &p_extension, const SceneLoaderFunc &p_func) {
	ERR_FAIL_COND_MSG(!p_func, vformat("Scene loader for '%s' is empty.", p_extension.c_str()));
	_scene_loaders()[_lower(p_extension)] = p_func;
}

void ResourceFormatText::remove_scene_loader(const String &p_extension) {
	_scene_loaders().erase(_lower(p_extension));
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

String ResourceFormatText::resolve_path(const String &p_path, const String &p_scene_path) {
	String base = _dir_of(p_scene_path);
	if (string_begins_with(p_path, "res://")) {
		String root = _resource_root().empty() ? base : _resource_root();
		String rest = p_path.substr(6);
		return root.empty() ? rest : root + "/" + rest;
	}
	if (!p_path.empty() && p_path[0] == '/') {
		return p_path;
	}
	return base.empty() ? p_path : base + "/" + p_path;
}

Node *ResourceFormatText::load_scene_from_string(const String &p_text, const String &p_path, String *r_error) {
	if (_load_depth >= MAX_LOAD_DEPTH) {
		String msg = vformat("%s:1: Scenes are nested more than %d deep (does a scene instance itself?).", p_path.c_str(), MAX_LOAD_DEPTH);
		if (r_error) {
			*r_error = msg;
		}
		ERR_PRINT(msg);
		return nullptr;
	}
	_load_depth++;
	SceneLoader loader;
	loader.path = p_path;
	loader.stream = VariantParser::Stream(p_text);
	bool ok = loader.run();
	_load_depth--;
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
	return loader.root;
}

Node *ResourceFormatText::load_scene(const String &p_path, String *r_error) {
	String text, read_error; // Bounded read (core/io/file_io.h): `render /dev/zero` stops with an error.
	if (!file_read_bounded(p_path, text, &read_error)) {
		String msg = vformat("%s:0: Cannot open the scene file: %s", p_path.c_str(), read_error.c_str());
		if (r_error) {
			*r_error = msg;
		}
		ERR_PRINT(msg);
		return nullptr;
	}
	return load_scene_from_string(text, p_path, r_error);
}

String ResourceFormatText::save_scene_to_string(const Node *p_root) {
	ERR_FAIL_NULL_V_MSG(p_root, String(), "Cannot save a null scene root.");
	std::vector<const Node *> nodes;
	_collect_nodes(p_root, &nodes);

	SaveState state;
	for (const Node *n : nodes) {
		state.find_resources(n);
	}

	String out;
	int load_steps = (int)(state.ext_list.size() + state.sub_list.size()) + 1;
	if (load_steps > 1) {
		out += vformat("[gd_scene load_steps=%d format=3]\n", load_steps);
	} else {
		out += "[gd_scene format=3]\n";
	}
	for (const Ref<Resource> &res : state.ext_list) {
		out += "\n[ext_resource type=" + VariantWriter::escape_string(res->get_class()) + " path=" + VariantWriter::escape_string(res->get_path()) + " id=" + VariantWriter::escape_string(state.ext_ids[res.ptr()]) + "]\n";
	}
	for (const Ref<Resource> &res : state.sub_list) {
		out += "\n[sub_resource type=" + VariantWriter::escape_string(res->get_class()) + " id=" + VariantWriter::escape_string(state.sub_ids[res.ptr()]) + "]\n";
		state.write_properties(res.ptr(), out);
	}
	for (const Node *n : nodes) {
		out += "\n[node name=" + VariantWriter::escape_string(n->get_name()) + " type=" + VariantWriter::escape_string(n->get_class());
		if (n != p_root) {
			String parent = n->get_parent() == p_root ? String(".") : _relative_path(p_root, n->get_parent());
			out += " parent=" + VariantWriter::escape_string(parent);
		}
		out += "]\n";
		state.write_properties(n, out);
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
