/**************************************************************************/
/*  node_3d_editor_gizmos.h                                               */
/**************************************************************************/
/* godot-area: Godot's EditorNode3DGizmo and EditorNode3DGizmoPlugin,     */
/* reduced to what a headless engine needs. A plugin decides which nodes  */
/* get a gizmo (has_gizmo), fills a gizmo with lines, handles and         */
/* billboard icons (redraw) and edits the node when a handle is dragged   */
/* (set_handle) or released (commit_handle, through UndoRedo).            */
/*                                                                        */
/* A gizmo only records geometry, in its node's LOCAL space (billboard    */
/* sets in camera-facing space around the node's origin); the overlay     */
/* (editor/gizmo_overlay.h) and the tests read it back. Materials are     */
/* EditorGizmoMaterial records (colour, kind, icon path) standing in for  */
/* Godot's StandardMaterial3D: we have no editor viewport to shade them.  */
/*                                                                        */
/* Screen points are pixels with a top-left origin; pixel (x, y) has its  */
/* centre at (x + 0.5, y + 0.5), as in the renderer. Camera rays use the  */
/* same perspective as the RenderingServer camera (see get_camera_ray).   */

#pragma once

#include "core/math/color.h"
#include "core/math/projection.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"
#include "core/object/ref_counted.h"
#include "core/object/undo_redo.h"
#include "core/variant/variant.h"

#include <map>
#include <vector>

class Camera3D;
class Node3D;
class EditorNode3DGizmoPlugin;

// What a gizmo part is drawn with (Godot: a StandardMaterial3D per name and selection state).
class EditorGizmoMaterial : public RefCounted {
	GDCLASS(EditorGizmoMaterial, RefCounted);

public:
	enum Kind {
		KIND_LINES,
		KIND_HANDLES,
		KIND_ICON,
	};

	String name;
	Kind kind = KIND_LINES;
	Color color = Color(1, 1, 1, 1); // sRGB, straight alpha.
	String icon_path; // Icons (and textured handles): an SVG under editor/icons/.
	bool billboard = false;
	bool on_top = false;
	bool selected_variant = false; // The variant used while the gizmo is selected.
};

class EditorNode3DGizmo : public RefCounted {
	GDCLASS(EditorNode3DGizmo, RefCounted);

public:
	struct LineSet {
		std::vector<Vector3> points; // Pairs: segment i is points[2i] -> points[2i + 1].
		Ref<EditorGizmoMaterial> material;
		bool billboard = false; // Points are (right, up, back) offsets in camera space from the node origin.
		Color modulate = Color(1, 1, 1, 1);
	};
	struct HandleSet {
		std::vector<Vector3> points;
		std::vector<int> ids; // Same length as points.
		Ref<EditorGizmoMaterial> material;
		bool billboard = false;
		bool secondary = false;
	};
	struct Billboard {
		Ref<EditorGizmoMaterial> material;
		real_t scale = 1.0; // Godot's default_scale: size relative to the viewport, independent of distance.
		Color modulate = Color(1, 1, 1, 1);
	};

private:
	Node3D *node = nullptr;
	EditorNode3DGizmoPlugin *plugin = nullptr;
	bool selected = false;
	std::vector<LineSet> lines;
	std::vector<HandleSet> handles;
	std::vector<Billboard> billboards;

public:
	void set_node_3d(Node3D *p_node) { node = p_node; }
	Node3D *get_node_3d() const { return node; }
	void set_plugin(EditorNode3DGizmoPlugin *p_plugin) { plugin = p_plugin; }
	EditorNode3DGizmoPlugin *get_plugin() const { return plugin; }

	void set_selected(bool p_selected) { selected = p_selected; }
	bool is_selected() const { return selected; }

	// Drops every line, handle and billboard.
	void clear();
	// p_lines holds pairs of points (an odd count drops the last point with an error).
	void add_lines(const std::vector<Vector3> &p_lines, const Ref<EditorGizmoMaterial> &p_material, bool p_billboard = false, const Color &p_modulate = Color(1, 1, 1, 1));
	// p_ids: one id per handle, or empty for 0..n-1.
	void add_handles(const std::vector<Vector3> &p_handles, const Ref<EditorGizmoMaterial> &p_material, const std::vector<int> &p_ids = std::vector<int>(), bool p_billboard = false, bool p_secondary = false);
	// A camera-facing icon at the node's origin, of constant screen size.
	void add_unscaled_billboard(const Ref<EditorGizmoMaterial> &p_material, real_t p_scale = 1.0, const Color &p_modulate = Color(1, 1, 1, 1));

	const std::vector<LineSet> &get_lines() const { return lines; }
	const std::vector<HandleSet> &get_handles() const { return handles; }
	const std::vector<Billboard> &get_billboards() const { return billboards; }
	// Local position of handle p_id (false when there is none).
	bool get_handle_position(int p_id, bool p_secondary, Vector3 &r_position) const;

	// clear() and let the plugin draw again.
	void redraw();

	// Forwarded to the plugin.
	String get_handle_name(int p_id, bool p_secondary = false) const;
	Variant get_handle_value(int p_id, bool p_secondary = false) const;
	void set_handle(int p_id, bool p_secondary, Camera3D *p_camera, const Vector2 &p_point);
	void commit_handle(int p_id, bool p_secondary, const Variant &p_restore, bool p_cancel = false);
};

class EditorNode3DGizmoPlugin : public RefCounted {
	GDCLASS(EditorNode3DGizmoPlugin, RefCounted);

	// [0] = not selected, [1] = selected.
	std::map<String, std::vector<Ref<EditorGizmoMaterial>>> materials;
	UndoRedo *undo_redo = nullptr;
	UndoRedo own_undo_redo;
	bool snap_enabled = false;
	real_t translate_snap = 1.0; // Metres (Godot's default translate snap).
	real_t rotate_snap = 15.0; // Degrees (Godot's default rotate snap).

	void _add_material(const String &p_name, const Ref<EditorGizmoMaterial> &p_unselected, const Ref<EditorGizmoMaterial> &p_selected);

public:
	virtual String get_gizmo_name() const { return "Node3D"; }
	virtual bool has_gizmo(Node3D *p_node) { return false; }
	// A new gizmo for p_node, or null when has_gizmo() says no.
	Ref<EditorNode3DGizmo> create_gizmo(Node3D *p_node);
	virtual void redraw(EditorNode3DGizmo *p_gizmo) {}

	virtual String get_handle_name(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary) const { return String(); }
	virtual Variant get_handle_value(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary) const { return Variant(); }
	// Drags handle p_id to screen point p_point of p_camera's viewport (the camera's SceneTree size).
	virtual void set_handle(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary, Camera3D *p_camera, const Vector2 &p_point) {}
	// Ends a drag: p_cancel restores p_restore; otherwise records one undo/redo action.
	virtual void commit_handle(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary, const Variant &p_restore, bool p_cancel) {}

	// Materials, by name. Lines: unselected ones are drawn at 40 % alpha (as Godot dims them).
	void create_material(const String &p_name, const Color &p_color, bool p_billboard = false, bool p_on_top = false);
	void create_icon_material(const String &p_name, const String &p_icon_path, bool p_on_top = false, const Color &p_albedo = Color(1, 1, 1, 1));
	void create_handle_material(const String &p_name, bool p_billboard = false, const String &p_icon_path = String());
	// The variant for p_gizmo's selection state (selected when p_gizmo is null). Unknown names: error, null.
	Ref<EditorGizmoMaterial> get_material(const String &p_name, const EditorNode3DGizmo *p_gizmo = nullptr) const;
	bool has_material(const String &p_name) const { return materials.count(p_name) > 0; }

	// The history commit_handle records into: the one set here, else the plugin's own.
	void set_undo_redo(UndoRedo *p_undo_redo) { undo_redo = p_undo_redo; }
	UndoRedo *get_undo_redo() { return undo_redo ? undo_redo : &own_undo_redo; }

	// Snapping while dragging (Godot reads these from Node3DEditor).
	void set_snap_enabled(bool p_enabled) { snap_enabled = p_enabled; }
	bool is_snap_enabled() const { return snap_enabled; }
	void set_translate_snap(real_t p_step);
	real_t get_translate_snap() const { return translate_snap; }
	void set_rotate_snap(real_t p_degrees);
	real_t get_rotate_snap() const { return rotate_snap; }
	// p_value rounded to a multiple of p_step (p_step <= 0: unchanged).
	static real_t snapped(real_t p_value, real_t p_step);

	// Vulkan clip space from camera (view) space for a p_viewport_size viewport, exactly as the
	// renderer builds it: create_depth_correction(true) * create_perspective(camera's vertical fov
	// for this aspect, aspect, near, far). (The RenderingServer camera is always perspective.)
	static Projection get_clip_from_view(const Camera3D *p_camera, const Vector2 &p_viewport_size);
	// World-space ray through screen point p_point (pixels, top-left origin) of a p_viewport_size
	// viewport, with the perspective the RenderingServer uses for p_camera. False on bad input.
	static bool get_camera_ray(const Camera3D *p_camera, const Vector2 &p_point, const Vector2 &p_viewport_size, Vector3 &r_origin, Vector3 &r_direction);
	// Same, with the size of the camera's SceneTree (error when outside a tree or of size 0).
	static bool get_camera_ray(const Camera3D *p_camera, const Vector2 &p_point, Vector3 &r_origin, Vector3 &r_direction);
	// Screen point (pixels) of world point p_world, the inverse of get_camera_ray. False when the
	// point is not in front of the camera's near plane.
	static bool project_to_screen(const Camera3D *p_camera, const Vector3 &p_world, const Vector2 &p_viewport_size, Vector2 &r_point);

	EditorNode3DGizmoPlugin() {}
	~EditorNode3DGizmoPlugin() override {}
};
