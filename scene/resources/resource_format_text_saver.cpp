/**************************************************************************/
/*  resource_format_text_saver.cpp                                        */
/**************************************************************************/
/* Saving scenes as Godot 4 .tscn text (resource_format_text.h).          */

#include "scene/resources/resource_format_text.h"

#include "core/io/file_io.h"
#include "core/io/missing_resource.h"
#include "core/object/class_db.h"
#include "core/variant/variant_parser.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"
#include "scene/resources/resource_format_text_internal.h"

#include <algorithm>
#include <sstream>

using namespace ResourceFormatTextInternal;

namespace {

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
		// A value the loaded file wrote out is written back even when it equals the default (Godot
		// writes some defaults, e.g. alpha_scissor_threshold = 0.5): the round trip keeps every line.
		const TextSceneData *d = _data_or_null(p_obj);
		auto in_file = [d](const String &p_name) { return d && std::find(d->key_order.begin(), d->key_order.end(), p_name) != d->key_order.end(); };
		for (const PropertyInfo &pi : plist) {
			// A property hidden here (e.g. physical light units, off without project settings) is still
			// written when the file had it.
			if (pi.is_group_marker() || (!(pi.usage & PROPERTY_USAGE_STORAGE) && !in_file(pi.name))) {
				continue;
			}
			if (d && std::any_of(d->raw.begin(), d->raw.end(), [&pi](const TextSceneData::StoredProperty &p_sp) { return p_sp.name == pi.name; })) {
				continue; // Kept as text (the object refused the file's value): the text is written.
			}
			const bool from_file = in_file(pi.name);
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
				if (base_valid && base == value && !from_file) {
					continue;
				}
				if (!base_valid && value.get_type() == Variant::NIL) {
					continue;
				}
			} else {
				bool has_default = false;
				Variant def = ClassDB::class_get_property_default(cls, pi.name, &has_default);
				if (has_default && def == value && !from_file) {
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
		// Godot 4 always writes the format; a header without one (load_steps only, or none) gets it, so
		// the file saved is one that saves back the same (found by fuzz_resource_format_text).
		bool has_format = false;
		for (const auto &F : root_data->file_header) {
			has_format = has_format || F.first == "format";
		}
		if (!has_format) {
			out += " format=3";
		}
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
			out += "[ext_resource type=" + VariantWriter::escape_tag_string(e.type) + " path=" + VariantWriter::escape_tag_string(e.path) + " id=" + VariantWriter::escape_tag_string(e.id) + "]\n";
		}
	}
	for (const Ref<Resource> &res : state.sub_list) {
		out += "\n[sub_resource type=" + VariantWriter::escape_tag_string(SaveState::class_of(res.ptr())) + " id=" + VariantWriter::escape_tag_string(state.sub_ids[res.ptr()]);
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
		out += "\n[node name=" + VariantWriter::escape_tag_string(n->get_name());
		bool is_instance = d && !d->inherited && !d->instance_path.empty();
		String type = SaveState::class_of(n);
		if (!o.override_only && !is_instance && !type.empty()) {
			out += " type=" + VariantWriter::escape_tag_string(type);
		}
		if (n != p_root) {
			String parent = n->get_parent() == p_root ? String(".") : _relative_path(p_root, n->get_parent());
			out += " parent=" + VariantWriter::escape_tag_string(parent);
		}
		if (d) {
			out += _write_fields(d->header_fields);
		}
		if (is_instance) {
			out += " instance=ExtResource(" + VariantWriter::escape_tag_string(state.ext_id_for(d->instance_path, "PackedScene")) + ")";
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
