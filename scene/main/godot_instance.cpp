/**************************************************************************/
/*  godot_instance.cpp                                                    */
/**************************************************************************/

#include "scene/main/godot_instance.h"

#include "core/error/error_macros.h"
#include "scene/3d/camera_3d.h"
#include "scene/main/demo_scene.gen.h"
#include "scene/main/scene_tree.h"
#include "scene/register_scene_types.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/dummy/rasterizer_dummy.h"
#include "servers/rendering/renderer_rd/renderer_compositor_rd.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/rendering_server_default.h"

GodotInstance *GodotInstance::singleton = nullptr;

namespace {
RendererCompositor *started_compositor = nullptr; // Owned by the server.
} // namespace

RenderingDevice *GodotInstance::acquire_rendering_device(bool *r_created, String *r_error) {
	*r_created = false;
	RenderingDevice *existing = RenderingDevice::get_singleton();
	if (existing && existing->is_initialized()) {
		return existing;
	}
	ERR_FAIL_COND_V_MSG(existing, nullptr, "A RenderingDevice exists but is not initialized; initialize or delete it first.");
	RenderingDevice *device = new RenderingDevice;
	String error;
	if (!device->initialize(&error)) {
		*r_error = "No usable Vulkan device: " + error;
		delete device;
		return nullptr;
	}
	*r_created = true;
	return device;
}

bool GodotInstance::_start_server(RendererCompositor *p_compositor, Backend p_backend) {
	rendering_server = new RenderingServerDefault(p_compositor);
	started_compositor = p_compositor;
	backend = p_backend;
	singleton = this;
	register_scene_types();
	return true;
}

bool GodotInstance::start(Backend p_backend, String *r_error, uint32_t p_max_lights) {
	if (singleton || RenderingServer::get_singleton()) {
		*r_error = "An engine instance is already running in this process (its servers are singletons).";
		return false;
	}
	if (p_backend == BACKEND_DUMMY) {
		return _start_server(new RasterizerDummy, BACKEND_DUMMY);
	}
	if (p_backend != BACKEND_RD) {
		*r_error = "GodotInstance::start: use BACKEND_RD or BACKEND_DUMMY (start_with_compositor() for another compositor).";
		return false;
	}
	bool created = false;
	RenderingDevice *device = acquire_rendering_device(&created, r_error);
	if (!device) {
		return false;
	}
	RendererCompositorRD *compositor = new RendererCompositorRD;
	if (!(p_max_lights > 0 ? compositor->initialize(p_max_lights) : compositor->initialize())) {
		*r_error = "The Forward+ renderer could not be initialized (see the errors above).";
		delete compositor;
		if (created) {
			device->finalize();
			delete device;
		}
		return false;
	}
	owned_device = created ? device : nullptr;
	return _start_server(compositor, BACKEND_RD);
}

bool GodotInstance::start_with_compositor(RendererCompositor *p_compositor, String *r_error) {
	ERR_FAIL_NULL_V_MSG(p_compositor, false, "GodotInstance::start_with_compositor: null compositor.");
	if (singleton || RenderingServer::get_singleton()) {
		delete p_compositor;
		*r_error = "An engine instance is already running in this process (its servers are singletons).";
		return false;
	}
	return _start_server(p_compositor, BACKEND_CUSTOM);
}

void GodotInstance::stop() {
	if (backend == BACKEND_NONE) {
		return;
	}
	set_scene(nullptr);
	delete tree;
	tree = nullptr;
	unregister_scene_types();
	delete rendering_server; // Also deletes the compositor.
	rendering_server = nullptr;
	started_compositor = nullptr;
	if (owned_device) {
		owned_device->finalize();
		delete owned_device;
		owned_device = nullptr;
	}
	backend = BACKEND_NONE;
	singleton = nullptr;
}

GodotInstance::~GodotInstance() {
	stop();
}

RenderingDevice *GodotInstance::get_rendering_device() const {
	return backend == BACKEND_RD ? RenderingDevice::get_singleton() : nullptr;
}

RendererCompositor *GodotInstance::get_compositor() const {
	return is_started() ? started_compositor : nullptr;
}

int GodotInstance::get_validation_error_count() const {
	RenderingDevice *device = get_rendering_device();
	return device ? int(device->get_validation_error_count()) : 0;
}

SceneTree *GodotInstance::get_tree() {
	if (!tree && is_started()) {
		tree = new SceneTree;
	}
	return tree;
}

void GodotInstance::set_scene(Node *p_root) {
	if (scene) {
		Node *parent = scene->get_parent();
		if (parent) {
			parent->remove_child(scene);
		}
		delete scene;
		scene = nullptr;
	}
	if (!p_root) {
		return;
	}
	SceneTree *t = get_tree();
	ERR_FAIL_NULL_MSG(t, "GodotInstance::set_scene: the engine is not started.");
	t->get_root()->add_child(p_root);
	scene = p_root;
}

Image GodotInstance::render(int p_width, int p_height, int p_settle_frames, String *r_error, int *r_frames) {
	SceneTree *t = get_tree();
	if (!t) {
		*r_error = "The engine is not started.";
		return Image();
	}
	if (backend == BACKEND_DUMMY) {
		*r_error = "The dummy backend does not render.";
		return Image();
	}
	if (p_width < 0 || p_height < 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE) {
		*r_error = vformat("Render size %dx%d is out of range (1..%d).", p_width, p_height, Image::MAX_SIZE);
		return Image();
	}
	if (p_width > 0 && p_height > 0 && (p_width != t->get_width() || p_height != t->get_height())) {
		t->set_size(p_width, p_height);
	}
	if (t->get_width() <= 0 || t->get_height() <= 0) {
		*r_error = "The tree has no size: pass width and height.";
		return Image();
	}
	if (!t->get_camera_3d()) {
		*r_error = "The tree has no current Camera3D: add a scene with a Camera3D to the tree's root.";
		return Image();
	}
	if (p_settle_frames < 1 || p_settle_frames > 1000) {
		*r_error = vformat("settle_frames %d is out of range (1..1000).", p_settle_frames);
		return Image();
	}
	Image image = t->render_settled(p_settle_frames, r_frames);
	if (image.is_empty()) {
		*r_error = "The renderer returned no image (see the engine errors above).";
	}
	return image;
}

Node *GodotInstance::load_scene(const String &p_path, String *r_error) {
	if (p_path.empty()) {
		return ResourceFormatText::load_scene_from_string(DEMO_SCENE_TSCN, "demo/demo.tscn (built in)", r_error);
	}
	return ResourceFormatText::load_scene(p_path, r_error);
}
