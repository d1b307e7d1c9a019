/**************************************************************************/
/*  editor_node.h                                                         */
/**************************************************************************/
/* godot-area: `godot-area editor [SCENE.tscn]`, the editor window        */
/* (Godot: EditorNode). A resizable GLFW window presented through a      */
/* Vulkan swapchain on the RenderingDevice's own device, Dear ImGui for   */
/* the panels (compute_layout: docks at fixed sizes, the viewport takes   */
/* the rest; the viewport is sampled on the GPU, viewport_blit_vk.h):     */
/*   Scene (left)      SceneTreeEditor over SceneTreeDock                 */
/*   Viewport (centre) Node3DEditorViewport: the Forward+ frame + gizmos  */
/*   Output (below)    GPU time per pass, camera help                     */
/*   Inspector (right) EditorProperties widgets over EditorInspector rows */
/*   status line       GPU ms per pass of the last frame, last action     */
/* One UndoRedo history is shared by the dock, the inspector and the      */
/* gizmo plugin. Keys: Ctrl+Z undo, Ctrl+Shift+Z / Ctrl+Y redo, Ctrl+S    */
/* save (.tscn), F12 viewport screenshot (PNG), F11 window screenshot,    */
/* Esc cancels a handle drag, Ctrl+Q quits.                               */
/*                                                                        */
/* Options (for tests and scripted use):                                  */
/*   --select NODE_PATH   select a node (relative to the scene root)      */
/*   --save-as PATH       where Ctrl+S writes (default: the opened file;  */
/*                        the embedded demo saves to ./demo_edited.tscn)  */
/*   --test-log FILE      one line per event, flushed at once:            */
/*                        ready, select, handle, drag_start, drag_end,    */
/*                        undo, redo, property, save, screenshot, exit    */
/*   --screenshot PREFIX  F12 writes PREFIX_<n>.png (n = 0, 1, ...): the  */
/*                        viewport cropped from the next presented frame */
/*   --window-screenshot PATH  after the first presented frame (and on   */
/*                        F11), write the whole window (the swapchain     */
/*                        image read back) as a PNG                       */
/* Exit code: 0, 1 on a runtime failure or Vulkan validation errors, 2 on */
/* bad arguments.                                                         */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class EditorNode {
public:
	// The window opens at WINDOW_WIDTH x WINDOW_HEIGHT and can be resized: the docks keep their
	// sizes (Scene left, Inspector right, Output below the viewport, the status line) and the 3D
	// viewport takes the rest, as in Godot's editor.
	static constexpr int WINDOW_WIDTH = 1040;
	static constexpr int WINDOW_HEIGHT = 600;
	static constexpr int SCENE_PANEL_WIDTH = 240;
	static constexpr int INSPECTOR_WIDTH = 320;
	static constexpr int OUTPUT_HEIGHT = 216;
	static constexpr int STATUS_HEIGHT = 24;
	static constexpr int VIEWPORT_WIDTH = WINDOW_WIDTH - SCENE_PANEL_WIDTH - INSPECTOR_WIDTH; // 480 at first.
	static constexpr int VIEWPORT_HEIGHT = WINDOW_HEIGHT - STATUS_HEIGHT - OUTPUT_HEIGHT; // 360 at first.
	static constexpr int VIEWPORT_MIN_SIZE = 64;

	struct Rect {
		int x = 0, y = 0, width = 0, height = 0;
	};
	struct Layout {
		Rect scene, viewport, output, inspector, status;
	};
	// The panels for a p_width x p_height window. Docks shrink (never below what keeps the
	// viewport VIEWPORT_MIN_SIZE on a side) when the window is too small for them; panels never
	// overlap and together cover the window.
	static Layout compute_layout(int p_width, int p_height);

	struct Options {
		String scene_path; // Empty: the embedded demo scene.
		String save_path;
		String select_path;
		String test_log;
		String screenshot_prefix;
		String window_screenshot;
	};
	// Parses the arguments after `editor`. False with r_error on a bad argument.
	static bool parse_options(const std::vector<String> &p_args, Options &r_options, String *r_error);
	// Runs the editor until the window closes. Returns the process exit code.
	static int run(const Options &p_options);
	// `godot-area editor ...`: parse_options() then run().
	static int command(const std::vector<String> &p_args);
};
