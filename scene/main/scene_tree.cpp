/**************************************************************************/
/*  scene_tree.cpp                                                        */
/**************************************************************************/

#include "scene/main/scene_tree.h"

#include "core/error/error_macros.h"
#include "scene/3d/camera_3d.h"
#include "servers/rendering_server.h"

void SceneTree::_camera_set(Camera3D *p_camera) {
	camera = p_camera;
	RS *rs = RS::get_singleton();
	if (rs && viewport.is_valid()) {
		rs->viewport_attach_camera(viewport, camera ? camera->get_camera() : RID());
	}
}

void SceneTree::set_size(int p_width, int p_height) {
	ERR_FAIL_COND_MSG(p_width < 0 || p_height < 0, vformat("SceneTree size must not be negative (got %dx%d).", p_width, p_height));
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "SceneTree::set_size() needs a RenderingServer.");
	width = p_width;
	height = p_height;
	rs->viewport_set_size(viewport, width, height);
	if (camera) {
		camera->_viewport_size_changed();
	}
}

Image SceneTree::render() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_V_MSG(rs, Image(), "SceneTree::render() needs a RenderingServer.");
	Node::flush_delete_queue(); // Nodes queue_free()d since the last frame.
	rs->draw();
	return rs->viewport_get_texture_data(viewport);
}

Image SceneTree::render_settled(int p_max_frames, int *r_frames) {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_V_MSG(rs, Image(), "SceneTree::render_settled() needs a RenderingServer.");
	Node::flush_delete_queue(); // Nodes queue_free()d since the last frame.
	int frames = 0;
	do {
		rs->draw();
		frames++;
	} while (frames < p_max_frames && rs->get_frame_area_shadow_tests() > 0);
	if (r_frames) {
		*r_frames = frames;
	}
	return rs->viewport_get_texture_data(viewport);
}

SceneTree::SceneTree() {
	world_3d.instantiate();
	RS *rs = RS::get_singleton();
	if (rs) {
		viewport = rs->viewport_create();
		rs->viewport_set_scenario(viewport, world_3d->get_scenario());
		rs->viewport_set_active(viewport, true);
	} else {
		ERR_PRINT("SceneTree needs a RenderingServer; create one before the tree.");
	}
	root = new Node;
	root->set_name("root");
	root->_set_tree_root(this);
}

SceneTree::~SceneTree() {
	root->_unset_tree_root();
	delete root;
	root = nullptr;
	camera = nullptr;
	RS *rs = RS::get_singleton();
	if (rs && viewport.is_valid()) {
		rs->free(viewport);
	}
	world_3d.unref();
}
