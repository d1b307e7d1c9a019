/**************************************************************************/
/*  main.h                                                                */
/**************************************************************************/
/* The `godot-area` command line (Godot's main/main.cpp, reduced): engine */
/* setup and teardown around one command.                                 */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class Node;
class RenderingDevice;
class RenderingServer;

class Main {
public:
	enum Backend {
		BACKEND_RD, // Vulkan Forward+ renderer.
		BACKEND_DUMMY, // No GPU: scene loading and validation only.
		BACKEND_REFERENCE, // CPU ground truth on Embree (modules/reference).
	};

	// Starts the process's GodotInstance (scene/main/godot_instance.h) and registers the modules.
	// Returns false with r_error when no usable Vulkan device exists.
	// p_reference_options is a ReferenceRenderOptions* (BACKEND_REFERENCE only; null = defaults).
	static bool setup(Backend p_backend, String *r_error, const void *p_reference_options = nullptr);
	static void cleanup();
	// Errors the validation layer reported so far (0 without validation or without a device).
	static int get_validation_error_count();

	// Loads p_path, or the embedded demo scene when p_path is empty. Caller owns the node.
	static Node *load_scene(const String &p_path, String *r_error);

	// Entry point; returns the process exit code.
	static int run(int p_argc, char **p_argv);
};
