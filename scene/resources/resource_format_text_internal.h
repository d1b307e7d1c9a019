/**************************************************************************/
/*  resource_format_text_internal.h                                       */
/**************************************************************************/
/* What the .tscn/.tres loader (resource_format_text_loader.cpp) and      */
/* saver (resource_format_text_saver.cpp) share: the loader registries,   */
/* path helpers, the problem log of the outermost load, the caches of     */
/* instanced templates and loaded resources, and the raw-text helpers.    */
/* Internal to scene/resources: the public API is resource_format_text.h. */

#pragma once

#include "core/error/error_macros.h"
#include "core/variant/variant.h"
#include "scene/resources/resource_format_text.h"
#include "scene/resources/text_scene_data.h"

#include <map>
#include <memory>
#include <set>
#include <vector>

class Object;

namespace ResourceFormatTextInternal {

std::map<String, ResourceFormatText::SceneLoaderFunc> &_scene_loaders();
std::map<String, ResourceFormatText::ResourceLoaderFunc> &_resource_loaders();
String &_resource_root();
inline bool _verbose = false;
inline int _load_depth = 0; // Guards against scenes that instance themselves.
inline constexpr int MAX_LOAD_DEPTH = 16;
inline int _last_problem_count = 0;

String _lower(const String &p_s);
String _extension(const String &p_path);
String _dir_of(const String &p_path);

// Bounded read (core/io/file_io.h): `render /dev/zero` stops with an error instead of filling memory.
bool _read_file(const String &p_path, String &r_text, String *r_error = nullptr);
String _canonical(const String &p_path);
int64_t _mtime(const String &p_path);

// Godot-style random-looking ids ("1_ab3cd", "BoxMesh_x7k2p"), derived from a
// hash so that saving the same content twice gives the same text.
String _hash_suffix(const String &p_seed, int p_len);

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
ProblemLog &_problems();

// Templates of instanced scenes: parsed once, alive while an instance is.
struct TemplateEntry {
	std::weak_ptr<Node> node;
	int64_t mtime = -1;
};

std::map<String, TemplateEntry> &_templates();

// Resources loaded from files during the outermost load (a texture used by
// many materials is read once).
std::map<String, Ref<Resource>> &_resource_cache();
std::set<String> &_warned_rootless();

// The file data of p_obj, created on demand.
TextSceneData *_data(Object *p_obj);
const TextSceneData *_data_or_null(const Object *p_obj);

// Position right after "key =" (and blanks) of an assignment starting at or after p_pos.
size_t _value_start(const String &p_text, size_t p_pos);
String _trim_right(const String &p_s);

// Splits "[name k=v k2=[1, 2] k3="a b"]" into its fields as written.
std::vector<std::pair<String, String>> _split_tag(const String &p_raw);

// The ids named by SubResource("id") / ExtResource("id") in raw text.
std::vector<String> _referenced_ids(const String &p_text, const char *p_kind);
String _relative_path(const Node *p_root, const Node *p_node);

// Copies p_src's tree for one more instance: same classes, the stored
// properties (resources shared, not copied), placeholders keep their type.
// Every copied node is marked as coming from the template.
Node *_duplicate(const Node *p_src);
bool _lists_property(const Object *p_obj, const String &p_name);
struct ExtRes {
	String type;
	String path; // As written.
	Variant value; // Loaded resource or placeholder (null for scenes).
	int line = 0;
};

} // namespace ResourceFormatTextInternal
