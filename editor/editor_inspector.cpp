/**************************************************************************/
/*  editor_inspector.cpp                                                  */
/**************************************************************************/
/* godot-area: EditorInspector (see editor_inspector.h).                  */

#include "editor/editor_inspector.h"

#include "core/error/error_macros.h"
#include "core/object/class_db.h"
#include "core/object/undo_redo.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

// What a mergeable edit's "do" operation sets; a merged edit updates value.
struct EditorInspector::MergeState {
	UndoRedo *undo_redo = nullptr;
	Object *object = nullptr;
	String property;
	Variant value;
};

static bool _is_acronym(const String &p_word, String *r_upper) {
	static const char *acronyms[] = { "aabb", "ao", "fov", "gi", "hdr", "id", "lod", "ltc", "mrp", "pcss", "rid", "sdfgi", "srgb", "ssao", "ssil", "ssr", "ui", "uv", "uv2", "2d", "3d", nullptr };
	for (const char **a = acronyms; *a; a++) {
		if (p_word == *a) {
			String up = p_word;
			for (char &c : up) {
				c = (char)toupper((unsigned char)c);
			}
			*r_upper = up;
			return true;
		}
	}
	return false;
}

String EditorInspector::make_label(const String &p_property, const String &p_prefix) {
	String name = p_property;
	if (!p_prefix.empty() && name.size() > p_prefix.size() && name.compare(0, p_prefix.size(), p_prefix) == 0) {
		name = name.substr(p_prefix.size());
	}
	String label;
	for (const String &word : string_split(name, '_', false)) {
		if (!label.empty()) {
			label += " ";
		}
		String upper;
		if (_is_acronym(word, &upper)) {
			label += upper;
		} else {
			String w = word;
			w[0] = (char)toupper((unsigned char)w[0]);
			label += w;
		}
	}
	return label;
}

void EditorInspector::parse_hint(EditorPropertyRow &r_row) {
	r_row.enum_options.clear();
	r_row.enum_values.clear();
	r_row.has_range = false;
	r_row.range_min = r_row.range_max = r_row.range_step = 0.0;
	r_row.or_greater = r_row.or_less = r_row.exp = false;
	r_row.suffix.clear();
	r_row.resource_type.clear();

	switch (r_row.hint) {
		case PROPERTY_HINT_RESOURCE_TYPE: {
			r_row.resource_type = r_row.hint_string;
		} break;
		case PROPERTY_HINT_RANGE: {
			std::vector<String> parts = string_split(r_row.hint_string, ',', false);
			int numbers = 0;
			double values[3] = { 0.0, 0.0, 0.0 };
			for (String part : parts) {
				// Trim spaces ("0, 1, 0.01").
				while (!part.empty() && isspace((unsigned char)part.front())) {
					part.erase(part.begin());
				}
				while (!part.empty() && isspace((unsigned char)part.back())) {
					part.pop_back();
				}
				if (part.empty()) {
					continue;
				}
				char *end = nullptr;
				double v = strtod(part.c_str(), &end);
				if (numbers < 3 && end && *end == '\0') {
					values[numbers++] = v;
				} else if (part == "or_greater") {
					r_row.or_greater = true;
				} else if (part == "or_less") {
					r_row.or_less = true;
				} else if (part == "exp") {
					r_row.exp = true;
				} else if (part == "degrees" || part == "radians" || part == "radians_as_degrees") {
					r_row.suffix = "\u00b0";
				} else if (part.compare(0, 7, "suffix:") == 0) {
					r_row.suffix = part.substr(7);
				}
			}
			if (numbers >= 2) {
				r_row.has_range = true;
				r_row.range_min = values[0];
				r_row.range_max = values[1];
				r_row.range_step = numbers >= 3 ? values[2] : (r_row.type == Variant::INT ? 1.0 : 0.001);
			} else {
				WARN_PRINT(vformat("Inspector: property '%s' has a range hint \"%s\" without min and max; it is shown without a range.", r_row.property.c_str(), r_row.hint_string.c_str()));
			}
		} break;
		case PROPERTY_HINT_ENUM:
		case PROPERTY_HINT_ENUM_SUGGESTION:
		case PROPERTY_HINT_FLAGS: {
			const bool flags = r_row.hint == PROPERTY_HINT_FLAGS;
			int64_t next = flags ? 1 : 0;
			for (const String &part : string_split(r_row.hint_string, ',', false)) {
				String option = part;
				int64_t value = next;
				size_t colon = part.rfind(':');
				if (colon != String::npos) {
					char *end = nullptr;
					String number = part.substr(colon + 1);
					long long v = strtoll(number.c_str(), &end, 10);
					if (!number.empty() && end && *end == '\0') {
						option = part.substr(0, colon);
						value = (int64_t)v;
					}
				}
				r_row.enum_options.push_back(option);
				r_row.enum_values.push_back(value);
				next = flags ? value * 2 : value + 1;
			}
		} break;
		default:
			break;
	}
}

void EditorInspector::_build_rows(const std::vector<PropertyInfo> &p_list) {
	rows.clear();
	String group, group_prefix, subgroup, subgroup_prefix;
	for (const PropertyInfo &pi : p_list) {
		if (pi.usage & PROPERTY_USAGE_CATEGORY) {
			group = group_prefix = subgroup = subgroup_prefix = String();
			continue;
		}
		if (pi.usage & PROPERTY_USAGE_GROUP) {
			group = pi.name;
			group_prefix = pi.hint_string;
			subgroup = subgroup_prefix = String();
			continue;
		}
		if (pi.usage & PROPERTY_USAGE_SUBGROUP) {
			subgroup = pi.name;
			subgroup_prefix = pi.hint_string;
			continue;
		}
		if (!(pi.usage & PROPERTY_USAGE_EDITOR)) {
			continue;
		}
		EditorPropertyRow row;
		row.property = pi.name;
		// As Godot: a property that does not start with the group's prefix is shown outside it.
		const bool in_group = !group.empty() && (group_prefix.empty() || pi.name.compare(0, group_prefix.size(), group_prefix) == 0);
		const bool in_subgroup = in_group && !subgroup.empty() && (subgroup_prefix.empty() || pi.name.compare(0, subgroup_prefix.size(), subgroup_prefix) == 0);
		if (in_group) {
			row.group = group;
		}
		if (in_subgroup) {
			row.subgroup = subgroup;
		}
		String prefix = in_subgroup && !subgroup_prefix.empty() ? subgroup_prefix : (in_group ? group_prefix : String());
		row.label = make_label(pi.name, prefix);
		row.type = pi.type;
		row.hint = pi.hint;
		row.hint_string = pi.hint_string;
		parse_hint(row);
		row.read_only = (pi.usage & PROPERTY_USAGE_READ_ONLY) != 0;
		const ClassDB::PropertySetGet *psg = ClassDB::get_property_setget(edited->get_class(), pi.name);
		if (psg && psg->setter.empty()) {
			row.read_only = true;
		}
		rows.push_back(row);
	}
	version++;
}

static std::vector<String> _list_signature(const std::vector<PropertyInfo> &p_list) {
	std::vector<String> sig;
	sig.reserve(p_list.size());
	for (const PropertyInfo &pi : p_list) {
		sig.push_back(pi.name + "|" + itos((int64_t)pi.usage) + "|" + itos((int64_t)pi.hint) + "|" + pi.hint_string);
	}
	return sig;
}

int EditorInspector::get_layer_count(PropertyHint p_hint) {
	switch (p_hint) {
		case PROPERTY_HINT_LAYERS_2D_RENDER:
		case PROPERTY_HINT_LAYERS_2D_PHYSICS:
		case PROPERTY_HINT_LAYERS_2D_NAVIGATION:
		case PROPERTY_HINT_LAYERS_3D_RENDER:
		case PROPERTY_HINT_LAYERS_3D_PHYSICS:
		case PROPERTY_HINT_LAYERS_3D_NAVIGATION:
			return 20; // Godot's layer grid: 20 named layers (the project settings' layer_names).
		default:
			return 0;
	}
}

uint32_t EditorInspector::get_layer_mask(const Variant &p_value) {
	return (uint32_t)(uint64_t)p_value.to_int();
}

int64_t EditorInspector::toggle_layer(const Variant &p_value, int p_bit) {
	ERR_FAIL_INDEX_V_MSG(p_bit, 32, (int64_t)get_layer_mask(p_value), vformat("Layer bit %d is out of range (0..31).", p_bit));
	return (int64_t)(get_layer_mask(p_value) ^ (uint32_t(1) << p_bit));
}

String EditorInspector::fit_text(const String &p_text, float p_max_width, const std::function<float(const String &)> &p_measure) {
	if (p_measure(p_text) <= p_max_width) {
		return p_text;
	}
	static const String ellipsis = "...";
	if (p_measure(ellipsis) > p_max_width) {
		return String();
	}
	// Widths grow with the prefix length: binary search for the longest prefix that fits.
	size_t lo = 0, hi = p_text.size();
	while (lo < hi) {
		size_t mid = (lo + hi + 1) / 2;
		String candidate = string_strip_edges(p_text.substr(0, mid)) + ellipsis;
		if (p_measure(candidate) <= p_max_width) {
			lo = mid;
		} else {
			hi = mid - 1;
		}
	}
	// Never cut a UTF-8 sequence: back up to a character boundary.
	while (lo > 0 && lo < p_text.size() && (uint8_t(p_text[lo]) & 0xC0) == 0x80) {
		lo--;
	}
	String prefix = p_text.substr(0, lo);
	while (!prefix.empty() && prefix.back() == ' ') {
		prefix.pop_back();
	}
	return prefix + ellipsis;
}

float EditorInspector::get_label_column_width(const std::vector<float> &p_label_widths, float p_total_width, float p_padding, float p_min_width, float p_max_fraction) {
	float widest = 0;
	for (float w : p_label_widths) {
		widest = std::max(widest, w);
	}
	const float max_width = std::max(p_min_width, p_total_width * p_max_fraction);
	return std::min(max_width, std::max(p_min_width, widest + p_padding));
}

float EditorInspector::get_layer_cell_size(int p_layers, float p_width, float p_spacing, float p_max_cell, float p_min_cell, int &r_rows) {
	r_rows = 0;
	ERR_FAIL_COND_V_MSG(p_layers <= 0 || p_layers % 4 != 0, 0.0f, vformat("A layer grid needs a multiple of 4 layers; got %d.", p_layers));
	for (int rows = 2; rows <= 4; rows += 2) {
		const int columns = p_layers / rows;
		const float cell = std::min(p_max_cell, (p_width - p_spacing * (columns - 1)) / columns);
		if (cell >= p_min_cell || rows == 4) {
			r_rows = rows;
			return std::max(cell, 1.0f);
		}
	}
	return 0.0f;
}

void EditorInspector::edit(Object *p_object) {
	edited = p_object;
	last_edit.reset();
	last_error.clear();
	rows.clear();
	row_signature.clear();
	if (!edited) {
		version++;
		return;
	}
	std::vector<PropertyInfo> list;
	edited->get_property_list(&list);
	row_signature = _list_signature(list);
	list_changed_count = edited->get_property_list_changed_count();
	_build_rows(list);
}

bool EditorInspector::refresh() {
	if (!edited) {
		return false;
	}
	std::vector<PropertyInfo> list;
	edited->get_property_list(&list);
	std::vector<String> sig = _list_signature(list);
	const uint32_t count = edited->get_property_list_changed_count();
	if (sig == row_signature && count == list_changed_count) {
		return false;
	}
	row_signature = sig;
	list_changed_count = count;
	_build_rows(list);
	return true;
}

const EditorPropertyRow &EditorInspector::get_row(int p_index) const {
	static const EditorPropertyRow empty;
	ERR_FAIL_INDEX_V_MSG(p_index, (int)rows.size(), empty, vformat("Inspector: row %d does not exist (%d rows).", p_index, (int)rows.size()));
	return rows[p_index];
}

int EditorInspector::find_row(const String &p_property) const {
	for (size_t i = 0; i < rows.size(); i++) {
		if (rows[i].property == p_property) {
			return (int)i;
		}
	}
	return -1;
}

Variant EditorInspector::get_row_value(int p_index) const {
	ERR_FAIL_NULL_V_MSG(edited, Variant(), "Inspector: no object is being edited.");
	ERR_FAIL_INDEX_V_MSG(p_index, (int)rows.size(), Variant(), vformat("Inspector: row %d does not exist (%d rows).", p_index, (int)rows.size()));
	return edited->get(rows[p_index].property);
}

void EditorInspector::end_merge() {
	last_edit.reset();
}

bool EditorInspector::set_row_value(int p_index, const Variant &p_value, bool p_merge) {
	ERR_FAIL_NULL_V_MSG(edited, false, "Inspector: no object is being edited.");
	ERR_FAIL_INDEX_V_MSG(p_index, (int)rows.size(), false, vformat("Inspector: row %d does not exist (%d rows).", p_index, (int)rows.size()));
	const EditorPropertyRow &row = rows[p_index];
	const String property = row.property;
	const String what = vformat("%s.%s", edited->get_class().c_str(), property.c_str());
	if (row.read_only) {
		last_error = vformat("Inspector: property '%s' is read-only.", what.c_str());
		ERR_PRINT(last_error);
		return false;
	}

	const Object *value_object = p_value.get_type() == Variant::OBJECT ? p_value.get_object() : nullptr;
	if (row.type == Variant::OBJECT && !row.resource_type.empty() && value_object && !ClassDB::is_parent_class(value_object->get_class(), row.resource_type)) {
		last_error = vformat("Inspector: property '%s' takes a %s; got a %s. The old value is kept.", what.c_str(), row.resource_type.c_str(), value_object->get_class().c_str());
		ERR_PRINT(last_error);
		return false;
	}

	const Variant old_value = edited->get(property);

	// Apply now and watch for errors: a setter that rejects a value reports an error and keeps
	// the old one. Only an accepted value becomes an action.
	std::vector<String> errors;
	ErrorHandlerList handler;
	handler.callback = [&errors](ErrorHandlerType p_type, const String &p_text) {
		if (p_type == ERR_HANDLER_ERROR) {
			errors.push_back(p_text);
		}
	};
	add_error_handler(&handler);
	String set_error;
	const bool set_ok = edited->try_set(property, p_value, &set_error);
	remove_error_handler(&handler);

	if (!set_ok || !errors.empty()) {
		String reason = !set_ok ? set_error : errors.front();
		if (!(edited->get(property) == old_value)) {
			edited->try_set(property, old_value); // Keep the old value whatever the setter did.
		}
		last_error = vformat("Inspector: %s rejected the value %s for property '%s': %s", edited->get_class().c_str(), p_value.stringify().c_str(), property.c_str(), reason.c_str());
		ERR_PRINT(last_error);
		return false;
	}
	last_error.clear();

	if (!undo_redo) {
		return true;
	}

	if (p_merge && last_edit && last_edit->undo_redo == undo_redo && last_edit->object == edited && last_edit->property == property && undo_redo->get_version() == last_edit_ur_version && !undo_redo->has_redo()) {
		// Same drag: the last action now ends at the new value; its undo value is unchanged.
		last_edit->value = p_value;
		return true;
	}

	const String action = "Set " + property;
	undo_redo->create_action(action);
	if (p_merge) {
		std::shared_ptr<MergeState> state = std::make_shared<MergeState>();
		state->undo_redo = undo_redo;
		state->object = edited;
		state->property = property;
		state->value = p_value;
		undo_redo->add_do_method([state]() { state->object->set(state->property, state->value); });
		Object *object = edited;
		undo_redo->add_undo_method([object, property, old_value]() { object->set(property, old_value); });
		undo_redo->commit_action(false);
		last_edit = state;
		last_edit_ur_version = undo_redo->get_version();
	} else {
		undo_redo->add_do_property(edited, property, p_value);
		undo_redo->add_undo_property(edited, property, old_value);
		undo_redo->commit_action(false);
		last_edit.reset();
	}
	return true;
}
