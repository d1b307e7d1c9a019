/**************************************************************************/
/*  text_scene_data.h                                                     */
/**************************************************************************/
/* godot-area: what the text scene loader keeps on an object without      */
/* interpreting it, so the saver can write the file back whole (see       */
/* resource_format_text.h): values the engine cannot apply, as written;   */
/* extra header fields (groups, unique_id, index...); for a scene root    */
/* the file header, the ext_resource table and the [connection] /         */
/* [editable] sections; for an instance its scene path and the parsed     */
/* template it was copied from (shared by all instances of that file).    */

#pragma once

#include "core/io/resource.h"
#include "core/object/object.h"

#include <memory>
#include <utility>
#include <vector>

class Node;

struct TextSceneData : public ObjectFileData {
	struct StoredProperty {
		String name;
		String text; // The value exactly as written.
		std::vector<Ref<Resource>> refs; // SubResource("id")s the text names.
	};
	struct ExtEntry {
		String id;
		String type;
		String path; // As written (res://...).
		std::vector<std::pair<String, String>> fields; // All header fields as written (uid included).
	};

	std::vector<String> key_order; // Property names in file order.
	std::vector<StoredProperty> raw; // Properties kept as text.
	std::vector<std::pair<String, String>> header_fields; // [node]/[sub_resource] fields besides name/type/parent/instance/id.

	// Nodes.
	bool override_section = false; // The file had a [node] section without type for it.
	bool inherited = false; // Copied from an instanced scene's template.
	String instance_path; // Instance roots: the instanced file, as written.
	std::shared_ptr<Node> instance_template;

	// Sub-resources: position in the file (-1: not loaded from one).
	int load_order = -1;

	// Scene roots.
	bool is_scene_root = false;
	std::vector<std::pair<String, String>> file_header; // [gd_scene ...] fields as written.
	std::vector<ExtEntry> ext_entries;
	std::vector<String> tail_sections; // [connection], [editable] and unknown sections, as written.

	std::unique_ptr<ObjectFileData> clone() const override { return std::make_unique<TextSceneData>(*this); }
};
