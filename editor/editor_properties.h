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
/*   Transform3D -> origin and rotation (degrees) fields. Read-only rows  */
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
};
