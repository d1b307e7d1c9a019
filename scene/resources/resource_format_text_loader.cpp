/**************************************************************************/
/*  resource_format_text_loader.cpp                                       */
/**************************************************************************/
/* Loading .tscn scenes and .tres resources (resource_format_text.h).     */

#include "scene/resources/resource_format_text.h"

#include "core/io/missing_resource.h"
#include "core/object/class_db.h"
#include "core/variant/variant_parser.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"
#include "scene/resources/resource_format_text_internal.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <map>
#include <sstream>

using namespace ResourceFormatTextInternal;

namespace {

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
	String defining_sub_resource; // Id of the [sub_resource] whose properties are being read.

	void problem(int p_line, const String &p_key, const String &p_message) {
		_problems().add(p_key, vformat("%s:%d", path.c_str(), p_line), p_message);
	}

	bool fail(int p_line, const String &p_msg) {
		error = vformat("%s:%d: %s", path.c_str(), p_line, p_msg.c_str());
		return false;
	}

	// Tag values use a resolver that only checks ids (instance=ExtResource("id")).
	bool resolve_tag_reference(const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
		if (p_kind != "ExtResource" || !ext_resources.count(p_id)) {
			r_error = vformat("%s(\"%s\") is not a declared ext_resource.", p_kind.c_str(), p_id.c_str());
			return false;
		}
		r_value = p_id;
		return true;
	}

	bool resolve_reference(const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
		if (p_kind == "SubResource") {
			if (!defining_sub_resource.empty() && p_id == defining_sub_resource) {
				// A resource holding a reference to itself is a reference cycle: never freed.
				r_error = vformat("SubResource(\"%s\") refers to the sub_resource it is a property of.", p_id.c_str());
				return false;
			}
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

	// Whether a property read back after a set holds what was set: the same object for a resource, the
	// same number (to float precision) for a float; other types are taken as set.
	static bool _value_taken(const Variant &p_set, const Variant &p_got) {
		if (p_set.get_type() == Variant::OBJECT) {
			return p_set.get_object() == p_got.get_object();
		}
		if (p_set.get_type() == Variant::FLOAT && p_got.get_type() == Variant::FLOAT) {
			const double a = p_set.to_float(), b = p_got.to_float();
			return std::fabs(a - b) <= 1e-6 * std::max(1.0, std::fabs(a));
		}
		return true;
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
		if (applied && !_value_taken(p_value, p_target->get(p_key))) {
			// The setter refused the value without failing (a typed property given a placeholder or
			// another class, a value outside our range): keep the text so nothing is lost on save.
			keep_raw(p_target, p_key, p_raw);
			problem(p_line, "refused:" + cls + ":" + p_key, vformat("%s.%s: the value was not accepted here; kept as text and written back on save.", cls.c_str(), p_key.c_str()));
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

	bool orphan = false; // Set by handle_node_tag for a [node] whose parent is not loaded yet.
	// A [node] section whose parent is not loaded when it is read: retried after the last section
	// (Godot expects a parent first, but a file may name one declared below), else kept as text when
	// an instance may make that parent (resolve_deferred_nodes()).
	struct DeferredNode {
		size_t start = 0; // The section's text: [start, end) of stream.text.
		size_t end = 0;
		int start_line = 1; // stream.line at start.
		int tag_line = 1;
		String name;
		String parent_path;
	};
	std::vector<DeferredNode> deferred_nodes;
	DeferredNode deferring; // Set with orphan.

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
				// Declared further down, or made by an instance: decided after the last section.
				deferring = DeferredNode();
				deferring.tag_line = line;
				deferring.name = name;
				deferring.parent_path = parent_path;
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
			if (type.empty()) {
				return fail(line, vformat("Node \"%s\": type is empty (name a class, or use instance=ExtResource(...)).", name.c_str()));
			}
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
		defining_sub_resource = id;
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

	// The text of a section kept as it is, for the saver; the sub_resources it names are saved with it.
	String keep_section_text(size_t p_start, size_t p_end) {
		String text = section_text(p_start, p_end);
		for (const String &id : _referenced_ids(text, "SubResource")) {
			auto it = sub_resources.find(id);
			if (it != sub_resources.end()) {
				scene_data.section_refs.push_back(it->second);
			}
		}
		return text;
	}

	// The first position from p_pos that is not a blank or part of a ';' comment.
	size_t skip_blanks(size_t p_pos) const {
		size_t p = p_pos;
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
		return p;
	}

	// Reads a deferred [node] section again, now that its parent is loaded.
	bool load_deferred_node(const DeferredNode &p_node, Node *&r_node) {
		r_node = nullptr;
		const size_t saved_pos = stream.pos;
		const int saved_line = stream.line;
		const String saved_defining = defining_sub_resource; // The file may end in a [sub_resource].
		defining_sub_resource = String();
		stream.pos = p_node.start;
		stream.line = p_node.start_line;
		VariantParser::Tag tag;
		String err;
		VariantParser::ResourceFunc tag_func = [this](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			return resolve_tag_reference(p_kind, p_id, r_value, r_error);
		};
		VariantParser::ResourceFunc res_func = [this](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			return resolve_reference(p_kind, p_id, r_value, r_error);
		};
		const size_t p0 = stream.pos;
		if (!VariantParser::parse_tag(stream, tag, err, tag_func)) {
			return fail(stream.line, err);
		}
		Object *target = nullptr;
		if (!handle_node_tag(tag, section_text(p0, stream.pos), target)) {
			return false;
		}
		r_node = Object::cast_to<Node>(target);
		while (target && skip_blanks(stream.pos) < p_node.end) {
			const size_t start = stream.pos;
			String assign;
			Variant value;
			String unsupported;
			bool eof = false;
			if (!VariantParser::parse_tag_assign_eof(stream, tag, assign, value, err, res_func, &eof, &unsupported)) {
				return fail(stream.line, err);
			}
			if (eof || assign.empty()) {
				break;
			}
			String raw = _trim_right(stream.text.substr(_value_start(stream.text, start), stream.pos - _value_start(stream.text, start)));
			apply_property(target, assign, value, unsupported, raw, tag.line);
		}
		stream.pos = saved_pos;
		stream.line = saved_line;
		defining_sub_resource = saved_defining;
		return true;
	}

	// The [node] sections read before their parent: each is loaded under the parent once that exists
	// (a warning: Godot expects the parent first); one whose parent an instance may make (a glTF's
	// skeleton...) and does not is kept as text and written back on save; any other is an error. Each
	// waits on its parent's path and is woken when a node at or above that path is loaded, so a file
	// that declares a long chain child first loads in time linear in its sections, not quadratic.
	bool resolve_deferred_nodes() {
		if (deferred_nodes.empty()) {
			return true;
		}
		std::map<String, std::vector<size_t>> waiting; // Parent path -> deferred sections, in file order.
		std::deque<size_t> ready;
		for (size_t i = 0; i < deferred_nodes.size(); i++) {
			if (root->get_node_or_null(deferred_nodes[i].parent_path)) {
				ready.push_back(i);
			} else {
				waiting[deferred_nodes[i].parent_path].push_back(i);
			}
		}
		std::vector<bool> loaded(deferred_nodes.size(), false);
		while (!ready.empty()) {
			const DeferredNode &node = deferred_nodes[ready.front()];
			loaded[ready.front()] = true;
			ready.pop_front();
			orphan = false;
			Node *made = nullptr;
			if (!load_deferred_node(node, made)) {
				return false;
			}
			if (orphan || !made) {
				return fail(node.tag_line, vformat("Could not add node \"%s\" to \"%s\".", node.name.c_str(), node.parent_path.c_str()));
			}
			problem(node.tag_line, "late:" + node.parent_path + "/" + node.name, vformat("Node \"%s\" comes before its parent \"%s\" in the file (Godot expects the parent first): loaded under it, and saved after it.", node.name.c_str(), node.parent_path.c_str()));
			// Wake the sections waiting on this node's path, and, when it came with children (an
			// instance), those waiting on a path below it that now exists.
			const String path = _relative_path(root, made);
			auto exact = waiting.find(path);
			if (exact != waiting.end()) {
				ready.insert(ready.end(), exact->second.begin(), exact->second.end());
				waiting.erase(exact);
			}
			if (made->get_child_count() > 0) {
				const String prefix = path + "/";
				for (auto it = waiting.lower_bound(prefix); it != waiting.end() && it->first.compare(0, prefix.size(), prefix) == 0;) {
					if (root->get_node_or_null(it->first)) {
						ready.insert(ready.end(), it->second.begin(), it->second.end());
						it = waiting.erase(it);
					} else {
						++it;
					}
				}
			}
		}
		for (size_t i = 0; i < deferred_nodes.size(); i++) {
			if (loaded[i]) {
				continue;
			}
			const DeferredNode &node = deferred_nodes[i];
			if (!under_instance(node.parent_path)) {
				return fail(node.tag_line, vformat("Parent node \"%s\" of node \"%s\" does not exist.", node.parent_path.c_str(), node.name.c_str()));
			}
			problem(node.tag_line, "orphan:" + node.parent_path, vformat("Parent node \"%s\" of node \"%s\" is not in the instanced scene as loaded here; the section is kept as text and written back on save.", node.parent_path.c_str(), node.name.c_str()));
			scene_data.orphan_sections.push_back(keep_section_text(node.start, node.end));
		}
		deferred_nodes.clear();
		return true;
	}

	bool run() {
		// A text scene holds no binary data; a NUL byte would also cut the header text kept for the save
		// (found by fuzz_resource_format_text).
		const size_t nul = stream.text.find('\0');
		if (nul != String::npos) {
			return fail(1 + (int)std::count(stream.text.begin(), stream.text.begin() + nul, '\n'), "NUL byte: a text scene or resource holds no binary data.");
		}
		VariantParser::ResourceFunc res_func = [this](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			return resolve_reference(p_kind, p_id, r_value, r_error);
		};
		VariantParser::ResourceFunc tag_func = [this](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			return resolve_tag_reference(p_kind, p_id, r_value, r_error);
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
		size_t tail_start = String::npos; // Start of a section kept as text (or deferred).
		int tail_line = 1;
		bool orphan_start = false;
		auto close_tail = [&](size_t p_end) {
			if (tail_start != String::npos) {
				if (orphan_start) {
					deferring.start = tail_start;
					deferring.end = p_end;
					deferring.start_line = tail_line;
					deferred_nodes.push_back(deferring);
				} else {
					scene_data.tail_sections.push_back(keep_section_text(tail_start, p_end));
				}
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
			int start_line = stream.line;
			// Peek: a tag starts with '[' after blanks/comments. Tags need the id-only resolver. A section
			// kept as text ends before the blanks and comments that follow it: a comment belongs to the
			// section after it (found by fuzz_resource_format_text: a comment closing the file went with
			// a kept section, which the saver then wrote before other sections, where the next load gave
			// the comment to the section after it).
			const size_t next = skip_blanks(stream.pos);
			is_tag = next < stream.text.size() && stream.text[next] == '[';
			if (is_tag || next >= stream.text.size()) {
				close_tail(stream.pos);
			}
			if (!VariantParser::parse_tag_assign_eof(stream, tag, assign, value, err, is_tag ? tag_func : res_func, &eof, &unsupported)) {
				if (tail_start != String::npos && !is_tag) {
					// A property of a kept section that we cannot parse: its line is kept as text and reading
					// goes on with the next line, however far the parser read (an unclosed '[' reads on into
					// the next lines). So a kept section ends where it ends whatever follows it in the file,
					// as the saver writes it elsewhere (found by fuzz_resource_format_text: a failed value
					// swallowed a broken tag line in one place and not in the other).
					size_t p = next;
					stream.line = start_line + (int)std::count(stream.text.begin() + start, stream.text.begin() + p, '\n');
					while (p < stream.text.size() && stream.text[p] != '\n') {
						p++;
					}
					stream.pos = p;
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
				if (!defining_sub_resource.empty()) {
					// A value kept as text still holds the resources it names (keep_raw): one naming the
					// sub_resource it belongs to would be a reference cycle, never freed.
					for (const String &id : _referenced_ids(raw, "SubResource")) {
						if (id == defining_sub_resource) {
							return fail(line, vformat("%s: SubResource(\"%s\") refers to the sub_resource it is a property of.", assign.c_str(), id.c_str()));
						}
					}
				}
				apply_property(target, assign, value, unsupported, raw, line);
				continue;
			}

			String raw_tag = section_text(start, stream.pos);
			section = tag.name;
			target = nullptr;
			defining_sub_resource = String();
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
					tail_start = start; // Read again (or kept as text) after the last section.
					tail_line = start_line;
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
		if (!resolve_deferred_nodes()) {
			return false;
		}
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
		if (_load_depth > 0) {
			_resource_cache()[key] = res; // Shared within the scene being loaded; a load on its own keeps nothing.
		}
	}
	return res;
}
