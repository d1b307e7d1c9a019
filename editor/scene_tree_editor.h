/**************************************************************************/
/*  scene_tree_editor.h                                                   */
/**************************************************************************/
/* godot-area: the scene tree panel of the editor window (Godot:          */
/* SceneTreeEditor), drawn with Dear ImGui over the headless SceneTreeDock */
/* model (scene_tree_dock.h): click selects; drag a node onto another to   */
/* reparent it; "Add" instantiates a class by name under the selection;   */
/* "Delete" removes the selection. Every change is one undo action of the  */
/* dock's UndoRedo. Each row shows the node's class icon (EditorIcons:    */
/* the nearest ancestor's when the class has none), like Godot's dock; a  */
/* MissingNode is drawn dimmed with a warning icon and a tooltip naming    */
/* the class it stands in for.                                            */
/* Only built with Dear ImGui (GODOT_AREA_EDITOR_WINDOW).                 */

#pragma once

#include "core/string/ustring.h"

#include <string>

class Node;
class SceneTreeDock;

class SceneTreeEditor {
	SceneTreeDock *dock = nullptr;
	std::string add_class = "AreaLight3D";
	String last_error;
	Node *pending_move = nullptr; // A drop, applied after drawing.
	Node *pending_parent = nullptr;

	void _draw_node(Node *p_node);

public:
	void set_dock(SceneTreeDock *p_dock) { dock = p_dock; }
	// Draws icon p_name (EditorIcons) into the current window at (p_x, p_y), p_size pixels square.
	static void draw_icon(const String &p_name, float p_x, float p_y, float p_size, float p_alpha = 1.0f);
	// Draws the panel's contents into the current ImGui window.
	void draw();
	String get_last_error() const { return last_error; }
};
