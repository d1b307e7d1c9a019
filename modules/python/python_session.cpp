/**************************************************************************/
/*  python_session.cpp                                                    */
/**************************************************************************/

#include "modules/python/python_session.h"

#include "core/error/error_macros.h"
#include "main/main.h"
#include "scene/3d/camera_3d.h"
#include "scene/main/scene_tree.h"
#include "servers/rendering_server.h"

PythonSession::Backend PythonSession::backend = PythonSession::BACKEND_NONE;
SceneTree *PythonSession::tree = nullptr;

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
	if (!Main::setup(p_backend == BACKEND_RD ? Main::BACKEND_RD : Main::BACKEND_DUMMY, r_error)) {
		return false;
	}
	backend = p_backend;
	tree = new SceneTree;
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
	if (p_width < 0 || p_height < 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE) {
		*r_error = vformat("Render size %dx%d is out of range (1..%d).", p_width, p_height, Image::MAX_SIZE);
		return false;
	}
	if (p_width > 0 && p_height > 0 && (p_width != tree->get_width() || p_height != tree->get_height())) {
		tree->set_size(p_width, p_height);
	}
	if (tree->get_width() <= 0 || tree->get_height() <= 0) {
		*r_error = "The tree has no size: pass width and height.";
		return false;
	}
	if (!tree->get_camera_3d()) {
		*r_error = "The tree has no current Camera3D: add a scene with a Camera3D to the tree's root.";
		return false;
	}
	if (p_settle_frames < 1 || p_settle_frames > 1000) {
		*r_error = vformat("settle_frames %d is out of range (1..1000).", p_settle_frames);
		return false;
	}
	r_image = tree->render_settled(p_settle_frames);
	if (r_image.is_empty()) {
		*r_error = "The renderer returned no image (see the engine errors above).";
		return false;
	}
	return true;
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
	return backend == BACKEND_NONE ? 0 : Main::get_validation_error_count();
}

void PythonSession::shutdown() {
	if (backend == BACKEND_NONE) {
		return;
	}
	delete tree;
	tree = nullptr;
	Main::cleanup();
	backend = BACKEND_NONE;
}
