/**************************************************************************/
/*  python_session.h                                                      */
/**************************************************************************/
/* godot-area: the engine state behind the Python module `godot_area`     */
/* (modules/python/godot_area_module.cpp). Plain C++, no Python headers,  */
/* so it lives in the engine library: one GodotInstance per              */
/* process, one SceneTree, rendering and per-frame profiles.              */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

#include <utility>
#include <vector>

class SceneTree;

class PythonSession {
public:
	enum Backend {
		BACKEND_NONE,
		BACKEND_RD, // Vulkan Forward+ (lavapipe on machines without a GPU).
		BACKEND_DUMMY, // No GPU: scenes can be built, edited, saved, but not rendered.
	};
	typedef std::vector<std::pair<String, double>> FrameProfile;

private:
	static Backend backend;
	static SceneTree *tree;

public:
	// Starts the engine once per process. A second call with the same backend is a no-op;
	// another backend fails with a message (the engine cannot switch backends live).
	static bool setup(Backend p_backend, String *r_error);
	static bool is_active() { return backend != BACKEND_NONE; }
	static Backend get_backend() { return backend; }
	static String get_backend_name(Backend p_backend);
	// Parses "rd" / "dummy". Returns BACKEND_NONE for anything else.
	static Backend backend_from_name(const String &p_name);
	// The process-wide tree (null before setup()).
	static SceneTree *get_tree() { return tree; }

	// Resizes the tree's viewport when p_width/p_height > 0, draws and returns the image (linear HDR RGBA):
	// until ADAPTIVE area shadows settle, at most p_settle_frames frames (1: exactly one), as the CLI.
	// Fails with a message without a camera, without pixels, on a bad frame count or on the dummy backend.
	static bool render(int p_width, int p_height, Image &r_image, String *r_error, int p_settle_frames = 1);
	// Draws one frame (no read-back) and returns the per-pass times of that frame (ms).
	static bool draw_frame(FrameProfile &r_profile, String *r_error);
	// Vulkan validation errors seen so far (0 without the layer).
	static int get_validation_error_count();

	// Deletes the tree (and every node in it), then tears the engine down. Safe to call twice.
	static void shutdown();
};
