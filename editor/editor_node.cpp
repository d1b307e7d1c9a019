/**************************************************************************/
/*  editor_node.cpp                                                       */
/**************************************************************************/
/* godot-area: see editor_node.h. Argument parsing is here for every      */
/* build; the window itself only with GLFW + Dear ImGui                    */
/* (GODOT_AREA_EDITOR_WINDOW), see editor_node_window.cpp.                */

#include "editor/editor_node.h"

#include <algorithm>
#include <cstdio>

EditorNode::Layout EditorNode::compute_layout(int p_width, int p_height) {
	Layout l;
	const int w = std::max(p_width, 1), h = std::max(p_height, 1);
	// Docks at their sizes while the viewport keeps its minimum; otherwise scaled down together.
	int left = SCENE_PANEL_WIDTH, right = INSPECTOR_WIDTH;
	if (w - left - right < VIEWPORT_MIN_SIZE) {
		const int room = std::max(0, w - VIEWPORT_MIN_SIZE);
		left = room * SCENE_PANEL_WIDTH / (SCENE_PANEL_WIDTH + INSPECTOR_WIDTH);
		right = room - left;
	}
	int status = std::min(STATUS_HEIGHT, h / 4), output = OUTPUT_HEIGHT;
	if (h - status - output < VIEWPORT_MIN_SIZE) {
		output = std::max(0, h - status - VIEWPORT_MIN_SIZE);
	}
	const int vw = std::max(1, w - left - right), vh = std::max(1, h - status - output);
	l.scene = { 0, 0, left, h - status };
	l.viewport = { left, 0, vw, vh };
	l.output = { left, vh, vw, h - status - vh };
	l.inspector = { left + vw, 0, w - left - vw, h - status };
	l.status = { 0, h - status, w, status };
	return l;
}

bool EditorNode::parse_options(const std::vector<String> &p_args, Options &r_options, String *r_error) {
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		String *target = nullptr;
		if (a == "--select") {
			target = &r_options.select_path;
		} else if (a == "--save-as") {
			target = &r_options.save_path;
		} else if (a == "--test-log") {
			target = &r_options.test_log;
		} else if (a == "--screenshot") {
			target = &r_options.screenshot_prefix;
		} else if (a == "--window-screenshot") {
			target = &r_options.window_screenshot;
		}
		if (target) {
			if (i + 1 >= p_args.size() || p_args[i + 1].empty()) {
				*r_error = vformat("option '%s' needs a value", a.c_str());
				return false;
			}
			*target = p_args[++i];
		} else if (!a.empty() && a[0] == '-') {
			*r_error = vformat("unknown option '%s' for 'editor'", a.c_str());
			return false;
		} else if (r_options.scene_path.empty()) {
			r_options.scene_path = a;
		} else {
			*r_error = vformat("unexpected argument '%s'", a.c_str());
			return false;
		}
	}
	if (r_options.save_path.empty()) {
		r_options.save_path = r_options.scene_path.empty() ? String("demo_edited.tscn") : r_options.scene_path;
	}
	return true;
}

int EditorNode::command(const std::vector<String> &p_args) {
	Options options;
	String error;
	if (!parse_options(p_args, options, &error)) {
		fprintf(stderr, "godot-area editor: %s\n", error.c_str());
		fprintf(stderr, "usage: godot-area editor [SCENE.tscn] [--select NODE_PATH] [--save-as PATH] [--test-log FILE]\n"
						"                         [--screenshot PREFIX] [--window-screenshot PATH]\n");
		return 2;
	}
	return run(options);
}

#ifndef GODOT_AREA_EDITOR_WINDOW
int EditorNode::run(const Options &p_options) {
	fprintf(stderr, "godot-area editor: this build has no editor window: GLFW (libglfw3-dev) and Dear ImGui (libimgui-dev) were not found when it was built. Install them (misc/scripts/install_deps.sh) and rebuild.\n");
	return 1;
}
#endif
