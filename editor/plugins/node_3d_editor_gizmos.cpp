/**************************************************************************/
/*  node_3d_editor_gizmos.cpp                                             */
/**************************************************************************/
/* godot-area: EditorNode3DGizmo and EditorNode3DGizmoPlugin (see the     */
/* header).                                                               */

#include "editor/plugins/node_3d_editor_gizmos.h"

#include "core/error/error_macros.h"
#include "scene/3d/camera_3d.h"
#include "scene/main/scene_tree.h"

#include <cmath>

// ---------------------------------------------------------------------------------------------
// EditorNode3DGizmo

void EditorNode3DGizmo::clear() {
	lines.clear();
	handles.clear();
	billboards.clear();
}

void EditorNode3DGizmo::add_lines(const std::vector<Vector3> &p_lines, const Ref<EditorGizmoMaterial> &p_material, bool p_billboard, const Color &p_modulate) {
	ERR_FAIL_COND_MSG(p_material.is_null(), "EditorNode3DGizmo::add_lines(): the material is null (create it in the plugin first).");
	LineSet set;
	set.points = p_lines;
	if (set.points.size() % 2 != 0) {
		ERR_PRINT(vformat("EditorNode3DGizmo::add_lines(): %d points is odd (lines take pairs); the last point is dropped.", (int)set.points.size()));
		set.points.pop_back();
	}
	if (set.points.empty()) {
		return;
	}
	set.material = p_material;
	set.billboard = p_billboard;
	set.modulate = p_modulate;
	lines.push_back(set);
}

void EditorNode3DGizmo::add_handles(const std::vector<Vector3> &p_handles, const Ref<EditorGizmoMaterial> &p_material, const std::vector<int> &p_ids, bool p_billboard, bool p_secondary) {
	ERR_FAIL_COND_MSG(p_material.is_null(), "EditorNode3DGizmo::add_handles(): the material is null (create it with create_handle_material()).");
	ERR_FAIL_COND_MSG(!p_ids.empty() && p_ids.size() != p_handles.size(), vformat("EditorNode3DGizmo::add_handles(): %d ids for %d handles; give one id per handle or none.", (int)p_ids.size(), (int)p_handles.size()));
	HandleSet set;
	set.points = p_handles;
	set.ids = p_ids;
	if (set.ids.empty()) {
		for (int i = 0; i < (int)p_handles.size(); i++) {
			set.ids.push_back(i);
		}
	}
	set.material = p_material;
	set.billboard = p_billboard;
	set.secondary = p_secondary;
	handles.push_back(set);
}

void EditorNode3DGizmo::add_unscaled_billboard(const Ref<EditorGizmoMaterial> &p_material, real_t p_scale, const Color &p_modulate) {
	ERR_FAIL_COND_MSG(p_material.is_null(), "EditorNode3DGizmo::add_unscaled_billboard(): the material is null (create it with create_icon_material()).");
	ERR_FAIL_COND_MSG(!(p_scale > 0) || !Math::is_finite(p_scale), vformat("EditorNode3DGizmo::add_unscaled_billboard(): the scale must be finite and > 0 (got %s).", rtos(p_scale).c_str()));
	Billboard b;
	b.material = p_material;
	b.scale = p_scale;
	b.modulate = p_modulate;
	billboards.push_back(b);
}

bool EditorNode3DGizmo::get_handle_position(int p_id, bool p_secondary, Vector3 &r_position) const {
	for (const HandleSet &set : handles) {
		if (set.secondary != p_secondary) {
			continue;
		}
		for (int i = 0; i < (int)set.ids.size(); i++) {
			if (set.ids[i] == p_id) {
				r_position = set.points[i];
				return true;
			}
		}
	}
	return false;
}

void EditorNode3DGizmo::redraw() {
	clear();
	ERR_FAIL_NULL_MSG(plugin, "EditorNode3DGizmo::redraw(): the gizmo has no plugin.");
	ERR_FAIL_NULL_MSG(node, "EditorNode3DGizmo::redraw(): the gizmo has no node.");
	plugin->redraw(this);
}

String EditorNode3DGizmo::get_handle_name(int p_id, bool p_secondary) const {
	ERR_FAIL_NULL_V_MSG(plugin, String(), "EditorNode3DGizmo::get_handle_name(): the gizmo has no plugin.");
	return plugin->get_handle_name(this, p_id, p_secondary);
}

Variant EditorNode3DGizmo::get_handle_value(int p_id, bool p_secondary) const {
	ERR_FAIL_NULL_V_MSG(plugin, Variant(), "EditorNode3DGizmo::get_handle_value(): the gizmo has no plugin.");
	return plugin->get_handle_value(this, p_id, p_secondary);
}

void EditorNode3DGizmo::set_handle(int p_id, bool p_secondary, Camera3D *p_camera, const Vector2 &p_point) {
	ERR_FAIL_NULL_MSG(plugin, "EditorNode3DGizmo::set_handle(): the gizmo has no plugin.");
	plugin->set_handle(this, p_id, p_secondary, p_camera, p_point);
}

void EditorNode3DGizmo::commit_handle(int p_id, bool p_secondary, const Variant &p_restore, bool p_cancel) {
	ERR_FAIL_NULL_MSG(plugin, "EditorNode3DGizmo::commit_handle(): the gizmo has no plugin.");
	plugin->commit_handle(this, p_id, p_secondary, p_restore, p_cancel);
}

// ---------------------------------------------------------------------------------------------
// EditorNode3DGizmoPlugin

Ref<EditorNode3DGizmo> EditorNode3DGizmoPlugin::create_gizmo(Node3D *p_node) {
	if (!p_node || !has_gizmo(p_node)) {
		return Ref<EditorNode3DGizmo>();
	}
	Ref<EditorNode3DGizmo> gizmo;
	gizmo.instantiate();
	gizmo->set_node_3d(p_node);
	gizmo->set_plugin(this);
	return gizmo;
}

void EditorNode3DGizmoPlugin::_add_material(const String &p_name, const Ref<EditorGizmoMaterial> &p_unselected, const Ref<EditorGizmoMaterial> &p_selected) {
	if (materials.count(p_name)) {
		WARN_PRINT(vformat("EditorNode3DGizmoPlugin: material '%s' is created twice; the new one replaces the old.", p_name.c_str()));
	}
	materials[p_name] = { p_unselected, p_selected };
}

void EditorNode3DGizmoPlugin::create_material(const String &p_name, const Color &p_color, bool p_billboard, bool p_on_top) {
	ERR_FAIL_COND_MSG(p_name.empty(), "EditorNode3DGizmoPlugin::create_material(): the name must not be empty.");
	Ref<EditorGizmoMaterial> m[2];
	for (int i = 0; i < 2; i++) {
		m[i].instantiate();
		m[i]->name = p_name;
		m[i]->kind = EditorGizmoMaterial::KIND_LINES;
		m[i]->color = p_color;
		m[i]->billboard = p_billboard;
		m[i]->on_top = p_on_top;
		m[i]->selected_variant = i == 1;
	}
	// Unselected gizmos are dimmed so the selected one stands out.
	m[0]->color.a *= 0.4f;
	_add_material(p_name, m[0], m[1]);
}

void EditorNode3DGizmoPlugin::create_icon_material(const String &p_name, const String &p_icon_path, bool p_on_top, const Color &p_albedo) {
	ERR_FAIL_COND_MSG(p_name.empty(), "EditorNode3DGizmoPlugin::create_icon_material(): the name must not be empty.");
	Ref<EditorGizmoMaterial> m[2];
	for (int i = 0; i < 2; i++) {
		m[i].instantiate();
		m[i]->name = p_name;
		m[i]->kind = EditorGizmoMaterial::KIND_ICON;
		m[i]->color = p_albedo;
		m[i]->icon_path = p_icon_path;
		m[i]->billboard = true;
		m[i]->on_top = p_on_top;
		m[i]->selected_variant = i == 1;
	}
	// As Godot: the unselected icon is slightly translucent.
	m[0]->color.a *= 0.85f;
	_add_material(p_name, m[0], m[1]);
}

void EditorNode3DGizmoPlugin::create_handle_material(const String &p_name, bool p_billboard, const String &p_icon_path) {
	ERR_FAIL_COND_MSG(p_name.empty(), "EditorNode3DGizmoPlugin::create_handle_material(): the name must not be empty.");
	Ref<EditorGizmoMaterial> m[2];
	for (int i = 0; i < 2; i++) {
		m[i].instantiate();
		m[i]->name = p_name;
		m[i]->kind = EditorGizmoMaterial::KIND_HANDLES;
		m[i]->color = Color(1, 1, 1, 1);
		m[i]->icon_path = p_icon_path;
		m[i]->billboard = p_billboard;
		m[i]->on_top = true; // Handles are always drawn on top, as Godot's.
		m[i]->selected_variant = i == 1;
	}
	_add_material(p_name, m[0], m[1]);
}

Ref<EditorGizmoMaterial> EditorNode3DGizmoPlugin::get_material(const String &p_name, const EditorNode3DGizmo *p_gizmo) const {
	auto it = materials.find(p_name);
	ERR_FAIL_COND_V_MSG(it == materials.end(), Ref<EditorGizmoMaterial>(), vformat("EditorNode3DGizmoPlugin::get_material(): no material named '%s' (create it in the plugin's constructor).", p_name.c_str()));
	const bool selected = p_gizmo == nullptr || p_gizmo->is_selected();
	return it->second[selected ? 1 : 0];
}

void EditorNode3DGizmoPlugin::set_translate_snap(real_t p_step) {
	ERR_FAIL_COND_MSG(!(p_step > 0) || !Math::is_finite(p_step), vformat("EditorNode3DGizmoPlugin: the translate snap must be finite and > 0 (got %s).", rtos(p_step).c_str()));
	translate_snap = p_step;
}

void EditorNode3DGizmoPlugin::set_rotate_snap(real_t p_degrees) {
	ERR_FAIL_COND_MSG(!(p_degrees > 0) || !Math::is_finite(p_degrees), vformat("EditorNode3DGizmoPlugin: the rotate snap must be finite and > 0 degrees (got %s).", rtos(p_degrees).c_str()));
	rotate_snap = p_degrees;
}

real_t EditorNode3DGizmoPlugin::snapped(real_t p_value, real_t p_step) {
	if (!(p_step > 0)) {
		return p_value;
	}
	return std::floor(p_value / p_step + real_t(0.5)) * p_step;
}

Projection EditorNode3DGizmoPlugin::get_clip_from_view(const Camera3D *p_camera, const Vector2 &p_viewport_size) {
	ERR_FAIL_NULL_V_MSG(p_camera, Projection(), "EditorNode3DGizmoPlugin::get_clip_from_view(): the camera is null.");
	ERR_FAIL_COND_V_MSG(!(p_viewport_size.x > 0) || !(p_viewport_size.y > 0), Projection(), "EditorNode3DGizmoPlugin::get_clip_from_view(): the viewport size must be positive.");
	const real_t aspect = p_viewport_size.x / p_viewport_size.y;
	// Same matrix as RendererSceneCull (camera_set_perspective with Camera3D's vertical fov) followed by
	// the RD renderer's Vulkan correction (depth 0..1, y down).
	Projection gl = Projection::create_perspective(p_camera->get_vertical_fov(aspect), aspect, p_camera->get_near(), p_camera->get_far());
	return Projection::create_depth_correction(true) * gl;
}

bool EditorNode3DGizmoPlugin::get_camera_ray(const Camera3D *p_camera, const Vector2 &p_point, const Vector2 &p_viewport_size, Vector3 &r_origin, Vector3 &r_direction) {
	ERR_FAIL_NULL_V_MSG(p_camera, false, "EditorNode3DGizmoPlugin::get_camera_ray(): the camera is null.");
	ERR_FAIL_COND_V_MSG(!(p_viewport_size.x > 0) || !(p_viewport_size.y > 0), false, "EditorNode3DGizmoPlugin::get_camera_ray(): the viewport size must be positive.");
	ERR_FAIL_COND_V_MSG(!p_point.is_finite(), false, "EditorNode3DGizmoPlugin::get_camera_ray(): the screen point must be finite.");
	const Projection view_from_clip = get_clip_from_view(p_camera, p_viewport_size).inverse();
	// Pixel coordinates to Vulkan NDC: x right, y down, both -1..1 across the viewport edges.
	const real_t ndc_x = real_t(2) * p_point.x / p_viewport_size.x - real_t(1);
	const real_t ndc_y = real_t(2) * p_point.y / p_viewport_size.y - real_t(1);
	// Unproject at the near (depth 0) and far (depth 1) planes.
	const Vector3 near_view = view_from_clip.xform(Vector3(ndc_x, ndc_y, 0));
	const Vector3 far_view = view_from_clip.xform(Vector3(ndc_x, ndc_y, 1));
	const Transform3D world_from_view = p_camera->get_camera_transform();
	r_origin = world_from_view.xform(near_view);
	r_direction = (world_from_view.xform(far_view) - r_origin).normalized();
	return r_origin.is_finite() && r_direction.is_finite() && r_direction.length_squared() > 0;
}

bool EditorNode3DGizmoPlugin::get_camera_ray(const Camera3D *p_camera, const Vector2 &p_point, Vector3 &r_origin, Vector3 &r_direction) {
	ERR_FAIL_NULL_V_MSG(p_camera, false, "EditorNode3DGizmoPlugin::get_camera_ray(): the camera is null.");
	SceneTree *tree = p_camera->get_tree();
	ERR_FAIL_NULL_V_MSG(tree, false, "EditorNode3DGizmoPlugin::get_camera_ray(): the camera is not inside a SceneTree, so the viewport size is unknown.");
	ERR_FAIL_COND_V_MSG(tree->get_width() <= 0 || tree->get_height() <= 0, false, "EditorNode3DGizmoPlugin::get_camera_ray(): the SceneTree has no size (call SceneTree::set_size()).");
	return get_camera_ray(p_camera, p_point, Vector2(tree->get_width(), tree->get_height()), r_origin, r_direction);
}

bool EditorNode3DGizmoPlugin::project_to_screen(const Camera3D *p_camera, const Vector3 &p_world, const Vector2 &p_viewport_size, Vector2 &r_point) {
	ERR_FAIL_NULL_V_MSG(p_camera, false, "EditorNode3DGizmoPlugin::project_to_screen(): the camera is null.");
	ERR_FAIL_COND_V_MSG(!(p_viewport_size.x > 0) || !(p_viewport_size.y > 0), false, "EditorNode3DGizmoPlugin::project_to_screen(): the viewport size must be positive.");
	const Vector3 view = p_camera->get_camera_transform().xform_inv(p_world);
	if (!(view.z <= -p_camera->get_near())) {
		return false; // Behind the near plane (or NaN).
	}
	const Vector3 ndc = get_clip_from_view(p_camera, p_viewport_size).xform(view);
	r_point = Vector2((ndc.x + 1) * real_t(0.5) * p_viewport_size.x, (ndc.y + 1) * real_t(0.5) * p_viewport_size.y);
	return r_point.is_finite();
}
