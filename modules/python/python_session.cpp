/**************************************************************************/
/*  python_session.cpp                                                    */
/**************************************************************************/

#include "modules/python/python_session.h"

#include "core/error/error_macros.h"
#include "modules/register_module_types.h"
#include "scene/3d/camera_3d.h"
#include "scene/main/godot_instance.h"
#include "scene/main/scene_tree.h"
#include "servers/rendering_server.h"

PythonSession::Backend PythonSession::backend = PythonSession::BACKEND_NONE;
SceneTree *PythonSession::tree = nullptr;

namespace {
GodotInstance *engine = nullptr;
} // namespace

String PythonSession::get_backend_name(Backend p_backend) {
	switch (p_backend) {
		case BACKEND_RD:
			return "rd";
		case BACKEND_DUMMY:
			return "dummy";
		default:
			return "none";
	}
}

PythonSession::Backend PythonSession::backend_from_name(const String &p_name) {
	if (p_name == "rd") {
		return BACKEND_RD;
	}
	if (p_name == "dummy") {
		return BACKEND_DUMMY;
	}
	return BACKEND_NONE;
}

bool PythonSession::setup(Backend p_backend, String *r_error) {
	if (p_backend != BACKEND_RD && p_backend != BACKEND_DUMMY) {
		*r_error = "Unknown backend: use 'rd' (Vulkan) or 'dummy' (no rendering).";
		return false;
	}
	if (backend == p_backend) {
		return true;
	}
	if (backend != BACKEND_NONE) {
		*r_error = vformat("The engine already runs on the '%s' backend; it cannot switch to '%s' in the same process.",
				get_backend_name(backend).c_str(), get_backend_name(p_backend).c_str());
		return false;
	}
	engine = new GodotInstance;
	if (!engine->start(p_backend == BACKEND_RD ? GodotInstance::BACKEND_RD : GodotInstance::BACKEND_DUMMY, r_error)) {
		delete engine;
		engine = nullptr;
		return false;
	}
	initialize_modules();
	backend = p_backend;
	tree = engine->get_tree();
	return true;
}

bool PythonSession::render(int p_width, int p_height, Image &r_image, String *r_error, int p_settle_frames) {
	if (!tree) {
		*r_error = "The engine is not initialized.";
		return false;
	}
	if (backend != BACKEND_RD) {
		*r_error = "The 'dummy' backend does not render; start the engine with init('rd').";
		return false;
	}
	r_image = engine->render(p_width, p_height, p_settle_frames, r_error);
	return !r_image.is_empty();
}

bool PythonSession::draw_frame(FrameProfile &r_profile, String *r_error) {
	RenderingServer *rs = RenderingServer::get_singleton();
	if (!tree || !rs) {
		*r_error = "The engine is not initialized.";
		return false;
	}
	Node::flush_delete_queue(); // Nodes queue_free()d since the last frame.
	rs->draw();
	r_profile = rs->get_frame_profile();
	return true;
}

int PythonSession::get_validation_error_count() {
	return engine ? engine->get_validation_error_count() : 0;
}

void PythonSession::shutdown() {
	if (backend == BACKEND_NONE) {
		return;
	}
	uninitialize_modules();
	tree = nullptr;
	delete engine; // Deletes the tree and every node in it, then the servers.
	engine = nullptr;
	backend = BACKEND_NONE;
}
