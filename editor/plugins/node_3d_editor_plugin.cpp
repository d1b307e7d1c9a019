/**************************************************************************/
/*  node_3d_editor_plugin.cpp                                             */
/**************************************************************************/
/* godot-area: see node_3d_editor_plugin.h.                               */

#include "editor/plugins/node_3d_editor_plugin.h"

#include "core/error/error_macros.h"
#include "core/io/tonemap.h"
#include "core/math/math_funcs.h"
#include "drivers/png/png_writer.h"
#include "editor/gizmo_overlay.h"
#include "editor/plugins/gizmos/light_3d_gizmo_plugin.h"
#include "editor/plugins/node_3d_editor_gizmos.h"
#include "scene/3d/camera_3d.h"
#include "scene/3d/light_3d.h"
#include "scene/main/scene_tree.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering_server.h"

#include <cmath>
#include <functional>

Node3DEditorViewport::Node3DEditorViewport() {
	gizmo_plugin.instantiate();
}

Node3DEditorViewport::~Node3DEditorViewport() {
	clear();
}

void Node3DEditorViewport::_event(const String &p_text) {
	if (event_callback) {
		event_callback(p_text);
	}
}

bool Node3DEditorViewport::setup(SceneTree *p_tree, Node *p_scene_root, int p_width, int p_height, UndoRedo *p_undo_redo) {
	ERR_FAIL_NULL_V_MSG(p_tree, false, "Node3DEditorViewport::setup: no SceneTree.");
	ERR_FAIL_COND_V_MSG(p_width < 1 || p_height < 1, false, vformat("Node3DEditorViewport::setup: bad size %dx%d.", p_width, p_height));
	clear();
	tree = p_tree;
	scene_root = p_scene_root;
	undo_redo = p_undo_redo;
	width = p_width;
	height = p_height;
	gizmo_plugin->set_undo_redo(p_undo_redo);
	camera = new Camera3D;
	camera->set_name("__EditorCamera3D");
	tree->get_root()->add_child(camera);
	tree->set_size(width, height);
	frame_scene();
	camera->make_current();
	render_dirty = true;
	return true;
}

void Node3DEditorViewport::clear() {
	cancel_drag();
	_free_overlay();
	selected_gizmo.unref();
	selected = nullptr;
	if (camera && tree) {
		tree->get_root()->remove_child(camera);
		delete camera;
	}
	camera = nullptr;
	tree = nullptr;
	scene_root = nullptr;
}

void Node3DEditorViewport::frame_scene() {
	ERR_FAIL_NULL(camera);
	// The scene's own camera (the first Camera3D found) gives the starting view.
	Camera3D *scene_camera = nullptr;
	std::function<void(Node *)> find = [&](Node *p_node) {
		if (!p_node || scene_camera) {
			return;
		}
		if (Camera3D *c = Object::cast_to<Camera3D>(p_node)) {
			scene_camera = c;
			return;
		}
		for (int i = 0; i < p_node->get_child_count(); i++) {
			find(p_node->get_child(i));
		}
	};
	find(scene_root);
	if (scene_camera) {
		Transform3D t = scene_camera->get_global_transform();
		Vector3 forward = -t.basis.get_column(2).normalized();
		distance = 5;
		focus = t.origin + forward * distance;
		pitch = std::asin(Math::clamp(-forward.y, (real_t)-1, (real_t)1));
		yaw = std::atan2(-forward.x, -forward.z);
		camera->set_fov(scene_camera->get_fov());
		camera->set_near(scene_camera->get_near());
		camera->set_far(scene_camera->get_far());
	} else {
		focus = Vector3(0, 0, 0);
		distance = 6;
		pitch = Math::deg_to_rad((real_t)20);
		yaw = 0;
	}
	_update_camera();
}

void Node3DEditorViewport::_update_camera() {
	if (!camera) {
		return;
	}
	pitch = Math::clamp(pitch, Math::deg_to_rad((real_t)-89), Math::deg_to_rad((real_t)89));
	distance = Math::clamp(distance, (real_t)0.05, (real_t)1000);
	// Looking direction: yaw around +Y from -Z, pitch down.
	Vector3 forward(-std::sin(yaw) * std::cos(pitch), -std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
	Vector3 position = focus - forward * distance;
	camera->set_global_transform(Transform3D(Basis(), position).looking_at(focus, Vector3(0, 1, 0)));
	render_dirty = true;
}

void Node3DEditorViewport::orbit(real_t p_dx_pixels, real_t p_dy_pixels) {
	yaw -= p_dx_pixels * (real_t)0.008;
	pitch += p_dy_pixels * (real_t)0.008;
	_update_camera();
}

void Node3DEditorViewport::pan_view(real_t p_dx_pixels, real_t p_dy_pixels) {
	ERR_FAIL_NULL(camera);
	Basis b = camera->get_global_transform().basis;
	// One pixel moves the focus by the size of a pixel at the focus distance.
	real_t scale = 2 * distance * std::tan(Math::deg_to_rad(camera->get_fov()) * (real_t)0.5) / (real_t)height;
	focus += b.get_column(0) * (-p_dx_pixels * scale) + b.get_column(1) * (p_dy_pixels * scale);
	_update_camera();
}

void Node3DEditorViewport::zoom(real_t p_steps) {
	distance *= std::pow((real_t)0.9, p_steps);
	_update_camera();
}

void Node3DEditorViewport::set_selected(Node *p_node) {
	Node3D *n3d = Object::cast_to<Node3D>(p_node);
	if (n3d == selected && (selected_gizmo.is_valid() || !n3d)) {
		return;
	}
	cancel_drag();
	selected = n3d;
	selected_gizmo.unref();
	if (n3d && gizmo_plugin->has_gizmo(n3d)) {
		selected_gizmo = gizmo_plugin->create_gizmo(n3d);
		selected_gizmo->set_selected(true);
	}
	display_dirty = true;
}

std::vector<Node3DEditorViewport::HandleInfo> Node3DEditorViewport::get_handles() const {
	std::vector<HandleInfo> out;
	if (selected_gizmo.is_null() || !selected || !camera) {
		return out;
	}
	selected_gizmo->redraw();
	Transform3D xf = selected->get_global_transform();
	for (const EditorNode3DGizmo::HandleSet &set : selected_gizmo->get_handles()) {
		if (set.secondary || set.billboard) {
			continue;
		}
		for (size_t i = 0; i < set.points.size(); i++) {
			HandleInfo h;
			h.id = set.ids[i];
			h.name = selected_gizmo->get_handle_name(h.id, false);
			if (EditorNode3DGizmoPlugin::project_to_screen(camera, xf.xform(set.points[i]), Vector2(width, height), h.position)) {
				out.push_back(h);
			}
		}
	}
	return out;
}

int Node3DEditorViewport::pick_handle(const Vector2 &p_point) const {
	int best = -1;
	real_t best_d = HANDLE_PICK_RADIUS;
	for (const HandleInfo &h : get_handles()) {
		real_t d = (h.position - p_point).length();
		if (d <= best_d) {
			best_d = d;
			best = h.id;
		}
	}
	return best;
}

Node3D *Node3DEditorViewport::pick_node(const Vector2 &p_point) const {
	Node3D *best = nullptr;
	real_t best_d = PICK_RADIUS;
	bool best_is_light = false;
	std::function<void(Node *)> visit = [&](Node *p_node) {
		Node3D *n3d = Object::cast_to<Node3D>(p_node);
		Vector2 p;
		if (n3d && n3d != camera && n3d->is_visible_in_tree() && EditorNode3DGizmoPlugin::project_to_screen(camera, n3d->get_global_position(), Vector2(width, height), p)) {
			real_t d = (p - p_point).length();
			bool is_light = Object::cast_to<Light3D>(n3d) != nullptr;
			if (d <= PICK_RADIUS && ((is_light && !best_is_light) || (is_light == best_is_light && d < best_d))) {
				best = n3d;
				best_d = d;
				best_is_light = is_light;
			}
		}
		for (int i = 0; i < p_node->get_child_count(); i++) {
			visit(p_node->get_child(i));
		}
	};
	if (scene_root && camera) {
		visit(scene_root);
	}
	return best;
}

bool Node3DEditorViewport::mouse_button(int p_button, bool p_pressed, const Vector2 &p_point, bool p_shift) {
	last_mouse = p_point;
	if (p_button == MOUSE_BUTTON_LEFT) {
		if (p_pressed) {
			int h = pick_handle(p_point);
			press_on_nothing = h < 0;
			press_position = p_point;
			if (h >= 0) {
				drag_handle = h;
				drag_restore = selected_gizmo->get_handle_value(h, false);
				_event(vformat("drag_start handle=%d name=%s value=%s", h, selected_gizmo->get_handle_name(h, false).c_str(), drag_restore.stringify().c_str()));
			}
			return false;
		}
		if (drag_handle >= 0) {
			int h = drag_handle;
			selected_gizmo->set_handle(h, false, camera, p_point);
			drag_handle = -1;
			selected_gizmo->commit_handle(h, false, drag_restore, false);
			drag_restore = Variant();
			render_dirty = true;
			_event(vformat("drag_end handle=%d value=%s", h, selected_gizmo->get_handle_value(h, false).stringify().c_str()));
			return false;
		}
		if (press_on_nothing && (p_point - press_position).length() < 4) {
			press_on_nothing = false;
			Node3D *picked = pick_node(p_point);
			Node3D *old = selected;
			set_selected(picked);
			return old != selected;
		}
		return false;
	}
	if (p_pressed) {
		orbit_button = p_button;
		pan = p_shift;
	} else if (p_button == orbit_button) {
		orbit_button = -1;
	}
	return false;
}

void Node3DEditorViewport::mouse_motion(const Vector2 &p_point) {
	Vector2 delta = p_point - last_mouse;
	last_mouse = p_point;
	if (drag_handle >= 0 && selected_gizmo.is_valid()) {
		selected_gizmo->set_handle(drag_handle, false, camera, p_point);
		display_dirty = true;
		return;
	}
	if (orbit_button >= 0 && (delta.x != 0 || delta.y != 0)) {
		if (pan) {
			pan_view(delta.x, delta.y);
		} else {
			orbit(delta.x, delta.y);
		}
	}
}

void Node3DEditorViewport::cancel_drag() {
	if (drag_handle >= 0 && selected_gizmo.is_valid()) {
		selected_gizmo->commit_handle(drag_handle, false, drag_restore, true);
		_event(vformat("drag_cancel handle=%d", drag_handle));
		render_dirty = true;
	}
	drag_handle = -1;
	drag_restore = Variant();
}

void Node3DEditorViewport::_draw_gizmos(Image &r_image) {
	GizmoOverlay overlay;
	Image &img = r_image;
	if (overlay.setup(camera, img.get_width(), img.get_height())) {
		std::function<void(Node *)> visit = [&](Node *p_node) {
			Node3D *n3d = Object::cast_to<Node3D>(p_node);
			if (n3d && n3d->is_visible_in_tree() && gizmo_plugin->has_gizmo(n3d)) {
				if (n3d == selected && selected_gizmo.is_valid()) {
					selected_gizmo->redraw();
					overlay.draw_gizmo(img, *selected_gizmo.ptr());
				} else {
					Ref<EditorNode3DGizmo> g = gizmo_plugin->create_gizmo(n3d);
					g->set_selected(false);
					g->redraw();
					overlay.draw_gizmo(img, *g.ptr());
				}
			}
			for (int i = 0; i < p_node->get_child_count(); i++) {
				visit(p_node->get_child(i));
			}
		};
		if (scene_root) {
			visit(scene_root);
		}
	}
}

Tonemap::Settings Node3DEditorViewport::get_tonemap() const {
	// The scene's Environment tonemap (WorldEnvironment), as Godot's editor viewport shows it.
	return Environment::get_preview_tonemap(camera ? camera->get_environment() : Ref<Environment>(), tree ? tree->get_world_3d()->get_environment() : Ref<Environment>());
}

void Node3DEditorViewport::_redraw_display() {
	if (gpu_display) {
		// Gizmos only, premultiplied over transparent black: the window composites them over the
		// scene texture in linear light before the tonemap, as the CPU path below blends them.
		overlay = Image(width, height, Color(0, 0, 0, 0));
		_draw_gizmos(overlay);
		RenderingDevice *rd = RenderingDevice::get_singleton();
		ERR_FAIL_NULL_MSG(rd, "Node3DEditorViewport: a GPU display needs the RenderingDevice.");
		const std::vector<float> &floats = overlay.get_data();
		std::vector<uint8_t> bytes((const uint8_t *)floats.data(), (const uint8_t *)(floats.data() + floats.size()));
		if (overlay_texture.is_valid() && (int)rd->texture_get_format(overlay_texture).width == width && (int)rd->texture_get_format(overlay_texture).height == height) {
			rd->texture_update(overlay_texture, 0, bytes);
		} else {
			if (overlay_texture.is_valid()) {
				rd->free(overlay_texture);
			}
			RD::TextureFormat tf;
			tf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
			tf.width = width;
			tf.height = height;
			tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
			overlay_texture = rd->texture_create(tf, { bytes });
			rd->set_resource_name(overlay_texture, "Editor viewport gizmo overlay");
		}
		rd->submit_and_sync();
		display_dirty = false;
		return;
	}
	Image img = rendered;
	if (img.is_empty()) {
		img = Image(width, height, Color(0, 0, 0, 1));
	}
	_draw_gizmos(img);
	display = Tonemap::apply(img, get_tonemap());
	display_dirty = false;
}

void Node3DEditorViewport::set_size(int p_width, int p_height) {
	ERR_FAIL_COND_MSG(p_width < 1 || p_height < 1, vformat("Node3DEditorViewport::set_size: bad size %dx%d.", p_width, p_height));
	if (p_width == width && p_height == height) {
		return;
	}
	width = p_width;
	height = p_height;
	if (tree) {
		tree->set_size(width, height);
	}
	rendered = Image();
	display.clear();
	render_dirty = true;
	display_dirty = true;
}

void Node3DEditorViewport::set_gpu_display(bool p_enabled) {
	gpu_display = p_enabled;
	render_dirty = true;
	display_dirty = true;
	if (!p_enabled) {
		_free_overlay();
	}
}

void Node3DEditorViewport::_free_overlay() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (overlay_texture.is_valid() && rd && rd->is_initialized()) {
		rd->free(overlay_texture);
	}
	overlay_texture = RID();
}

RID Node3DEditorViewport::get_scene_texture() const {
	return tree && RenderingServer::get_singleton() ? RenderingServer::get_singleton()->viewport_get_texture(tree->get_viewport_rid()) : RID();
}

bool Node3DEditorViewport::update() {
	ERR_FAIL_NULL_V(tree, false);
	if (tree->get_camera_3d() != camera) {
		camera->make_current(); // A camera added to the scene must not take the editor's view.
		render_dirty = true;
	}
	bool changed = false;
	if ((render_dirty || settling) && drag_handle < 0) {
		if (render_dirty) {
			settle_frames = 0; // A change: ADAPTIVE lights get their settling frames again.
		}
		if (gpu_display) {
			// Drawn and waited for, never read back: the window samples the viewport's texture.
			Node::flush_delete_queue();
			RenderingServer::get_singleton()->draw();
			RenderingDevice *rd = RenderingDevice::get_singleton();
			ERR_FAIL_NULL_V_MSG(rd, false, "Node3DEditorViewport: a GPU display needs the RenderingDevice.");
			rd->submit_and_sync();
		} else {
			rendered = tree->render();
		}
		profile = RenderingServer::get_singleton()->get_frame_profile();
		frames_rendered++;
		// ADAPTIVE area shadows refine over frames: keep drawing while they are still tested (as a running
		// game would), up to SceneTree::DEFAULT_SETTLE_FRAMES frames after the last change.
		settle_frames = RenderingServer::get_singleton()->get_frame_area_shadow_tests() > 0 ? settle_frames + 1 : 0;
		settling = settle_frames > 0 && settle_frames < SceneTree::DEFAULT_SETTLE_FRAMES;
		render_dirty = false;
		display_dirty = true;
	}
	if (display_dirty) {
		_redraw_display();
		changed = true;
	}
	return changed;
}

bool Node3DEditorViewport::save_screenshot(const String &p_path, String *r_error) const {
	if (gpu_display) {
		*r_error = "the viewport is shown from the GPU; write it from the window (it crops its capture)";
		return false;
	}
	if (display.empty()) {
		*r_error = "the viewport has not been drawn yet";
		return false;
	}
	return PNGWriter::save_rgba8(display, width, height, p_path, r_error);
}
