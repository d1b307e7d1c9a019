/**************************************************************************/
/*  node_3d_editor_plugin.h                                               */
/**************************************************************************/
/* godot-area: the editor's 3D viewport (Godot: Node3DEditorViewport),    */
/* without any window code, so it also runs headless:                     */
/*  - an editor Camera3D (not part of the edited scene) that orbits a     */
/*    focus point (right or middle drag), pans (shift + drag) and zooms   */
/*    (wheel); it starts at the scene's own camera when there is one;     */
/*  - the frame rendered by the engine's Forward+ renderer (the SceneTree */
/*    viewport), tonemapped like `render --png` (ACES fitted), with the   */
/*    light gizmos drawn on top by GizmoOverlay (the selected light's     */
/*    gizmo as selected: range box and handles);                          */
/*  - picking: a left press on a handle of the selected gizmo starts a    */
/*    drag through the gizmo plugin (set_handle while moving,             */
/*    commit_handle on release: one undo action in the shared UndoRedo);  */
/*    a left click elsewhere selects the node whose origin is nearest     */
/*    the click (within PICK_RADIUS pixels).                              */
/* While a handle is dragged only the overlay follows the mouse; the      */
/* scene is rendered again on release (lavapipe renders on the CPU).      */
/* Points are viewport pixels, top-left origin.                           */

#pragma once

#include "core/io/image.h"
#include "core/io/tonemap.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"
#include "core/object/ref_counted.h"
#include "core/templates/rid.h"
#include "core/variant/variant.h"

#include <functional>
#include <utility>
#include <vector>

class Camera3D;
class EditorNode3DGizmo;
class Light3DGizmoPlugin;
class Node;
class Node3D;
class SceneTree;
class UndoRedo;

class Node3DEditorViewport {
public:
	enum MouseButton {
		MOUSE_BUTTON_LEFT,
		MOUSE_BUTTON_RIGHT,
		MOUSE_BUTTON_MIDDLE,
	};
	static constexpr real_t PICK_RADIUS = 24.0; // Pixels, for node origins.
	static constexpr real_t HANDLE_PICK_RADIUS = 10.0; // Pixels, for gizmo handles.

	struct HandleInfo {
		int id = 0;
		String name;
		Vector2 position; // Viewport pixels.
	};

private:
	SceneTree *tree = nullptr;
	Node *scene_root = nullptr;
	Camera3D *camera = nullptr; // Owned by the tree (child of its root).
	UndoRedo *undo_redo = nullptr;
	int width = 0;
	int height = 0;

	Vector3 focus;
	real_t yaw = 0; // Radians, around +Y; 0 looks along -Z.
	real_t pitch = 0; // Radians, positive looks down.
	real_t distance = 5;

	Ref<Light3DGizmoPlugin> gizmo_plugin;
	Node3D *selected = nullptr;
	Ref<EditorNode3DGizmo> selected_gizmo;

	int drag_handle = -1;
	Variant drag_restore;
	int orbit_button = -1;
	bool pan = false;
	Vector2 last_mouse;
	bool press_on_nothing = false;
	Vector2 press_position;

	Image rendered; // Scene-linear, without gizmos (CPU display only).
	std::vector<uint8_t> display; // RGBA8 with gizmos (CPU display only).
	bool gpu_display = false;
	Image overlay; // GPU display: the gizmos, premultiplied linear RGBA over transparent black.
	RID overlay_texture; // GPU display: overlay on the RenderingDevice (RGBA32F).
	bool render_dirty = true;
	bool display_dirty = true;
	std::vector<std::pair<String, double>> profile;
	uint64_t frames_rendered = 0;
	int settle_frames = 0; // Consecutive frames that still tested ADAPTIVE area-shadow quads.
	bool settling = false; // Draw again: ADAPTIVE area shadows are still refining.

	std::function<void(const String &)> event_callback;

	void _update_camera();
	void _event(const String &p_text);
	void _redraw_display();
	void _draw_gizmos(Image &r_image);
	void _free_overlay();

public:
	// p_tree must hold p_scene_root under its root. Adds the editor camera to the tree's root and
	// makes it current; frames p_scene_root (from its Camera3D when it has one).
	bool setup(SceneTree *p_tree, Node *p_scene_root, int p_width, int p_height, UndoRedo *p_undo_redo);
	void clear(); // Removes the editor camera.
	Camera3D *get_camera() const { return camera; }
	int get_width() const { return width; }
	int get_height() const { return height; }
	// New size in pixels (the window's viewport panel was resized): renders again at that size.
	void set_size(int p_width, int p_height);

	// GPU display (the editor window): update() renders without reading the frame back and keeps
	// the gizmos in an overlay texture; the window samples get_scene_texture() (scene-linear
	// RGBA16F, the RenderingServer viewport's own texture), composites get_overlay_texture() over
	// it in linear light and applies get_tonemap(), which is what the CPU display computes
	// (Tonemap::apply of the scene with the gizmos blended in). Both RIDs change with the size.
	// Off by default (headless: get_rgba8()).
	void set_gpu_display(bool p_enabled);
	bool is_gpu_display() const { return gpu_display; }
	RID get_scene_texture() const;
	RID get_overlay_texture() const { return overlay_texture; }
	Tonemap::Settings get_tonemap() const;

	// Aims the camera at the scene: from its Camera3D, else at the origin from +Z.
	void frame_scene();
	void orbit(real_t p_dx_pixels, real_t p_dy_pixels);
	void pan_view(real_t p_dx_pixels, real_t p_dy_pixels);
	void zoom(real_t p_steps); // Positive: closer.

	// Selection (the gizmo follows); nullptr or a non-3D node clears the gizmo.
	void set_selected(Node *p_node);
	Node3D *get_selected() const { return selected; }
	// Handles of the selected gizmo as seen now (empty when none).
	std::vector<HandleInfo> get_handles() const;
	// Handle nearest to p_point within HANDLE_PICK_RADIUS, or -1.
	int pick_handle(const Vector2 &p_point) const;
	// The Node3D of the edited scene whose origin is nearest p_point within PICK_RADIUS, lights first.
	Node3D *pick_node(const Vector2 &p_point) const;

	// Mouse input. Returns true when the selection changed (left click on a node or nothing).
	bool mouse_button(int p_button, bool p_pressed, const Vector2 &p_point, bool p_shift);
	void mouse_motion(const Vector2 &p_point);
	bool is_dragging_handle() const { return drag_handle >= 0; }
	// Cancels a handle drag (restores the value, records nothing).
	void cancel_drag();

	// Re-renders after changes of the scene (call with true after any edit: inspector, undo, ...).
	void mark_scene_changed() { render_dirty = true; }
	// Renders when needed; returns true when the displayed pixels changed.
	bool update();
	const std::vector<uint8_t> &get_rgba8() const { return display; }
	// GPU time per pass of the last rendered frame (the renderer's profiler).
	const std::vector<std::pair<String, double>> &get_profile() const { return profile; }
	uint64_t get_frames_rendered() const { return frames_rendered; }
	// The displayed viewport (scene + gizmos) as a PNG.
	bool save_screenshot(const String &p_path, String *r_error) const;

	// Events for logs and tests ("drag_start ...", "drag_end ..."), one line each.
	void set_event_callback(const std::function<void(const String &)> &p_callback) { event_callback = p_callback; }

	Node3DEditorViewport();
	~Node3DEditorViewport();
};
