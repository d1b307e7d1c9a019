/**************************************************************************/
/*  editor_inspector.h                                                    */
/**************************************************************************/
/* godot-area: the inspector's model, without a window. Rows are made     */
/* only from the edited object's ClassDB property list (entries with      */
/* PROPERTY_USAGE_EDITOR; GROUP/SUBGROUP markers name the group of the    */
/* rows after them), so a new bound property shows up without UI code.    */
/* Each edit is one UndoRedo action "Set <property>"; a value the object  */
/* rejects (its setter reports an error) is not recorded.                 */
/*                                                                        */
/*   EditorInspector insp;                                                */
/*   insp.set_undo_redo(&undo_redo);                                      */
/*   insp.edit(light);                                                    */
/*   int r = insp.find_row("area_size");                                  */
/*   insp.set_row_value(r, Vector2(2, 1));    // undoable                 */
/*                                                                        */
/* The window calls refresh() (cheap when nothing changed) each frame:    */
/* rows are rebuilt when the object's property list changed (for example  */
/* area_shadow_grid hides outside the FIXED shadow mode).                 */

#pragma once

#include "core/object/object.h"
#include "core/object/property_info.h"
#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

class UndoRedo;

struct EditorPropertyRow {
	String property; // Property name, for Object::set/get.
	String label; // Godot-style capitalised, group/subgroup prefix stripped ("area_size" in "Area" -> "Size").
	String group; // Group label ("Area"), empty outside groups.
	String subgroup; // Subgroup label, empty outside subgroups.
	Variant::Type type = Variant::NIL;
	PropertyHint hint = PROPERTY_HINT_NONE;
	String hint_string;
	// PROPERTY_HINT_ENUM / ENUM_SUGGESTION / FLAGS: display names and their values.
	std::vector<String> enum_options;
	std::vector<int64_t> enum_values;
	// PROPERTY_HINT_RANGE ("min,max,step,or_greater,or_less,exp,suffix:m").
	bool has_range = false;
	double range_min = 0.0;
	double range_max = 0.0;
	double range_step = 0.0;
	bool or_greater = false;
	bool or_less = false;
	bool exp = false;
	String suffix; // "m", or "°" for degrees hints.
	// PROPERTY_HINT_RESOURCE_TYPE (OBJECT rows): the class a value must be or inherit ("Texture2D").
	String resource_type;
	bool read_only = false; // PROPERTY_USAGE_READ_ONLY or no setter.
};

class EditorInspector {
	Object *edited = nullptr;
	UndoRedo *undo_redo = nullptr;
	std::vector<EditorPropertyRow> rows;
	uint32_t list_changed_count = 0;
	std::vector<String> row_signature; // Names + usage of the last list, to notice changes.
	uint64_t version = 0;
	String last_error;

	// Merging a slider drag: shared state of the last committed edit.
	struct MergeState;
	std::shared_ptr<MergeState> last_edit;
	uint64_t last_edit_ur_version = 0;

	void _build_rows(const std::vector<PropertyInfo> &p_list);

public:
	// Godot-style label of a property name: prefix stripped, '_' -> ' ', words capitalised,
	// known acronyms upper-case ("area_shading_method" with prefix "area_" -> "Shading Method").
	static String make_label(const String &p_property, const String &p_prefix = String());
	// Fills the hint fields of r_row from its hint/hint_string.
	static void parse_hint(EditorPropertyRow &r_row);
	// Layer and mask properties (PROPERTY_HINT_LAYERS_*): how many layers Godot's layer grid
	// shows for the hint (20 for 3D render/physics/navigation, 0 for other hints), the
	// mask as the unsigned 32-bit value it is (a stored -1 is all 32 bits set), and the mask
	// with one layer (0-based bit) toggled, bits outside the grid kept.
	static int get_layer_count(PropertyHint p_hint);
	static uint32_t get_layer_mask(const Variant &p_value);
	static int64_t toggle_layer(const Variant &p_value, int p_bit);

	// Fitting text into a field (labels and value previews that would overflow), with
	// p_measure giving a string's width in pixels: p_text when it fits in p_max_width, else
	// its longest prefix (trailing spaces dropped) followed by "..." that fits, else "" when
	// not even "..." fits. Godot's inspector shows such labels with an ellipsis too.
	static String fit_text(const String &p_text, float p_max_width, const std::function<float(const String &)> &p_measure);
	// Width of the label column: the widest label plus p_padding, kept between p_min_width and
	// p_max_fraction of p_total_width (longer labels are then fitted with fit_text()).
	static float get_label_column_width(const std::vector<float> &p_label_widths, float p_total_width, float p_padding = 8.0f, float p_min_width = 60.0f, float p_max_fraction = 0.45f);
	// Layer grid cell side for p_layers toggles in two rows of p_layers / 2 in p_width pixels
	// with p_spacing between cells, at most p_max_cell; rows of a quarter each (4 rows) when
	// two rows would make cells narrower than p_min_cell. r_rows gets the row count.
	static float get_layer_cell_size(int p_layers, float p_width, float p_spacing, float p_max_cell, float p_min_cell, int &r_rows);

	// The object is not owned. nullptr clears the rows.
	void edit(Object *p_object);
	Object *get_edited_object() const { return edited; }
	// Not owned. Without one, edits apply directly (not undoable).
	void set_undo_redo(UndoRedo *p_undo_redo) { undo_redo = p_undo_redo; }
	UndoRedo *get_undo_redo() const { return undo_redo; }

	// Rebuilds the rows when the object's property list changed since the last build.
	// Returns true when it rebuilt them.
	bool refresh();
	// Bumped whenever the rows are rebuilt (a window can compare it).
	uint64_t get_version() const { return version; }

	int get_row_count() const { return (int)rows.size(); }
	const EditorPropertyRow &get_row(int p_index) const;
	const std::vector<EditorPropertyRow> &get_rows() const { return rows; }
	// Index of the row for p_property, -1 when there is none (hidden or unknown).
	int find_row(const String &p_property) const;
	// Current value read from the object (NIL with an error for a bad index).
	Variant get_row_value(int p_index) const;
	// Sets the property through one UndoRedo action "Set <property>". Returns false, with an
	// error naming the property (also in get_last_error()), when the object rejects the value;
	// the old value stays and the history is unchanged. With p_merge, an edit of the same
	// property right after the previous one (nothing else in the history since) joins that
	// action, so a slider drag is undone in one step.
	bool set_row_value(int p_index, const Variant &p_value, bool p_merge = false);
	// Ends a drag: the next edit starts a new action even with p_merge.
	void end_merge();
	// Message of the last rejected set_row_value(), empty after a successful one.
	String get_last_error() const { return last_error; }

	EditorInspector() {}
	~EditorInspector() {}
	EditorInspector(const EditorInspector &) = delete;
	EditorInspector &operator=(const EditorInspector &) = delete;
};
