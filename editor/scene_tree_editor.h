/**************************************************************************/
/*  scene_tree_editor.h                                                   */
/**************************************************************************/
/* godot-area: the scene tree panel of the editor window (Godot:          */
/* SceneTreeEditor), drawn with Dear ImGui over the headless SceneTreeDock */
/* model (scene_tree_dock.h): click selects; drag a node onto another to   */
/* reparent it; "Add" instantiates a class by name under the selection;   */
/* "Delete" removes the selection. Every change is one undo action of the  */
/* dock's UndoRedo.                                                       */
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
	// Draws the panel's contents into the current ImGui window.
	void draw();
	String get_last_error() const { return last_error; }
};
