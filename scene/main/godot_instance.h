/**************************************************************************/
/*  godot_instance.h                                                      */
/**************************************************************************/
/* GodotInstance: one running engine, as Godot's LibGodot embeds it. It   */
/* owns the RenderingDevice (or borrows the process's existing one), the  */
/* compositor, the RenderingServer and a SceneTree, and builds scenes     */
/* from nodes. The CLI (main/), the editor, the Python module, the        */
/* benchmarks, the accuracy suite and the tests all start the engine      */
/* through it, so every tool renders through the public RenderingServer  */
/* and the scene cull, the path users take.                               */
/*                                                                        */
/*   GodotInstance engine;                                                */
/*   if (!engine.start(GodotInstance::BACKEND_RD, &error)) { ... }        */
/*   engine.set_scene(GodotInstance::load_scene("", &error)); // demo     */
/*   Image image = engine.render(640, 360, 1, &error);                    */
/*                                                                        */
/* The servers are process-wide singletons: one instance is started at a  */
/* time. stop() (or the destructor) deletes the scene, the tree and the   */
/* servers in that order.                                                 */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

#include <cstdint>

class Node;
class RendererCompositor;
class RenderingDevice;
class RenderingServer;
class SceneTree;

class GodotInstance {
public:
	enum Backend {
		BACKEND_NONE,
		BACKEND_RD, // Vulkan Forward+ (RendererCompositorRD).
		BACKEND_DUMMY, // No GPU: scenes load, cull and validate, nothing is drawn.
		BACKEND_CUSTOM, // A compositor given to start_with_compositor() (the Embree reference).
	};

private:
	static GodotInstance *singleton;

	Backend backend = BACKEND_NONE;
	RenderingDevice *owned_device = nullptr;
	RenderingServer *rendering_server = nullptr;
	SceneTree *tree = nullptr;
	Node *scene = nullptr;

	bool _start_server(RendererCompositor *p_compositor, Backend p_backend);

public:
	// The started instance, or null.
	static GodotInstance *get_singleton() { return singleton; }

	// The process's RenderingDevice: the one already initialized (r_created false), else a new one
	// (r_created true; the caller finalizes and deletes it). Null with r_error when Vulkan has no
	// usable device. The only place a RenderingDevice is created.
	static RenderingDevice *acquire_rendering_device(bool *r_created, String *r_error);

	// Starts the servers and registers the scene types. BACKEND_RD: p_max_lights per light type
	// (0 = the renderer's default). Fails with r_error when another instance runs or without Vulkan.
	bool start(Backend p_backend, String *r_error, uint32_t p_max_lights = 0);
	// Same with a compositor made by the caller (owned from here on, also on failure).
	bool start_with_compositor(RendererCompositor *p_compositor, String *r_error);
	// Deletes the scene, the tree and the servers (and the device when this instance created it).
	void stop();
	bool is_started() const { return backend != BACKEND_NONE; }
	Backend get_backend() const { return backend; }

	RenderingServer *get_rendering_server() const { return rendering_server; }
	RenderingDevice *get_rendering_device() const;
	// The compositor the server draws with (null before start()).
	RendererCompositor *get_compositor() const;
	// Vulkan validation errors reported so far (0 without the layer or without a device).
	int get_validation_error_count() const;

	// The tree, created on first use (null before start()).
	SceneTree *get_tree();
	// Replaces the tree's scene (the previous one is deleted); p_root is owned from here on. Null
	// clears the scene.
	void set_scene(Node *p_root);
	Node *get_scene() const { return scene; }
	// Resizes the tree when p_width/p_height > 0, then draws until ADAPTIVE area shadows settle (at most
	// p_settle_frames draws) and returns the linear HDR image. Empty with r_error without a scene
	// camera, without a size, or on the dummy backend.
	Image render(int p_width, int p_height, int p_settle_frames, String *r_error, int *r_frames = nullptr);

	// Loads p_path (.tscn, or .gltf/.glb once modules are registered), or the built-in demo scene
	// when p_path is empty. The caller owns the node.
	static Node *load_scene(const String &p_path, String *r_error);

	GodotInstance() {}
	~GodotInstance();
	GodotInstance(const GodotInstance &) = delete;
	GodotInstance &operator=(const GodotInstance &) = delete;
};
