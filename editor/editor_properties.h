/**************************************************************************/
/*  editor_properties.h                                                   */
/**************************************************************************/
/* godot-area: the inspector's property widgets (Godot: EditorProperty*   */
/* in editor_properties.cpp), drawn with Dear ImGui from an               */
/* EditorPropertyRow of the headless inspector model (editor_inspector.h) */
/* so no widget knows any particular property:                            */
/*   bool -> checkbox; int/float with a range hint -> slider (or drag     */
/*   when or_greater/or_less), exp ranges logarithmic; enums -> combo;    */
/*   flags -> checkboxes; layers/masks -> Godot's layer grid (numbered   */
/*   toggles, unsigned mask); String -> text field (enum suggestions ->   */
/*   combo); Vector2/3 -> drag fields; Color -> colour editor;            */
/*   Transform3D -> origin and rotation (degrees) fields; resources ->    */
/*   preview, path + Load, Clear. Read-only rows                          */
/*   are drawn disabled.                                                  */
/* Only built with Dear ImGui (GODOT_AREA_EDITOR_WINDOW).                 */

#pragma once

#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <functional>

struct EditorPropertyRow;

class EditorProperties {
public:
	struct Result {
		bool changed = false; // r_value holds a new value.
		bool active = false; // The widget is being dragged (merge edits into one undo action).
		bool deactivated = false; // A drag just ended.
	};
	// Draws p_row's widget for p_value, its label fitted into a p_label_width column on the left
	// (EditorInspector::fit_text: an ellipsis when cut, the whole label in the tooltip); a change
	// is returned in r_value.
	static Result draw_row(const EditorPropertyRow &p_row, const Variant &p_value, Variant &r_value, float p_label_width);
	// Width of p_row's whole label in the current font (for EditorInspector::get_label_column_width).
	static float measure_label(const EditorPropertyRow &p_row);
	// Called for each layer-grid cell drawn (property, bit, centre in window pixels), for test logs.
	static std::function<void(const String &, int, float, float)> layer_cell_callback;
	// Resource rows (OBJECT with a RESOURCE_TYPE hint, Godot's EditorResourcePicker) show what the
	// value is, a path field with Load, and Clear. The window sets these two: the first draws the
	// value's preview at the cursor (a texture's thumbnail), the second loads the file a user
	// typed as p_type (paths resolved as the scene's ext_resources are); it returns null with
	// r_error naming the file and the problem, which the row then shows.
	static std::function<void(const EditorPropertyRow &, const Variant &)> resource_preview_callback;
	static std::function<Variant(const String &p_path, const String &p_type, String *r_error)> resource_load_callback;
};
