/**************************************************************************/
/*  light_3d_gizmo_plugin.h                                               */
/**************************************************************************/
/* godot-area: the gizmo of every Light3D (Godot's Light3DGizmoPlugin     */
/* plus the AreaLight3D gizmo of the thesis, §5.1.2 and Listing A.4).     */
/*                                                                        */
/* Lines are tinted by the light colour brought to full brightness (HSV   */
/* value 1, as Godot does for visibility). Per light type, in local space: */
/*  - omni:  when selected, the range circle (camera-facing) and the three */
/*           axis circles; handle 0 "Radius" at (range, 0) on the circle.  */
/*  - spot:  when selected, the cone (four edges and the rim circle at     */
/*           range·cos(angle)); handle 0 "Radius" at (0, 0, -range),       */
/*           handle 1 "Aperture" on the rim at (w, 0, -d); it slides on  */
/*           the arc of radius range in the light's XZ plane.            */
/*  - directional: when selected, an arrow along -Z.                       */
/*  - area:  ALWAYS the rectangle outline (±a/2, ±b/2, 0); when selected   */
/*           also the cluster range box (a + 2r) x (b + 2r) x r in front   */
/*           (z from -r to 0) and handles 0 "Width" at (a/2, 0, 0) and 1   */
/*           "Height" at (0, b/2, 0).                                      */
/* Every light also gets a billboard icon (editor/icons/Gizmo*.svg).       */
/*                                                                        */
/* Dragging an area handle intersects the camera ray with the light's     */
/* local XY plane (through the inverse global transform); the local x     */
/* (resp. y) of the hit is the new half-extent, so area_size.x = 2·x      */
/* (resp. y = 2·y); negative values clamp to 0, and with snapping the     */
/* size snaps to the translate step. commit_handle restores the given     */
/* value on cancel, otherwise records one named undo/redo action.         */

#pragma once

#include "editor/plugins/node_3d_editor_gizmos.h"

#include <vector>

class Light3D;

class Light3DGizmoPlugin : public EditorNode3DGizmoPlugin {
	GDCLASS(Light3DGizmoPlugin, EditorNode3DGizmoPlugin);

public:
	enum {
		HANDLE_RANGE = 0, // Omni and spot.
		HANDLE_SPOT_ANGLE = 1,
		HANDLE_AREA_WIDTH = 0, // Half-width on +X.
		HANDLE_AREA_HEIGHT = 1, // Half-height on +Y.
	};

	// Icon files (relative to the repository root), one per light type.
	static const char *ICON_DIRECTIONAL;
	static const char *ICON_OMNI;
	static const char *ICON_SPOT;
	static const char *ICON_AREA;

	String get_gizmo_name() const override { return "Light3D"; }
	bool has_gizmo(Node3D *p_node) override;
	void redraw(EditorNode3DGizmo *p_gizmo) override;

	String get_handle_name(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary) const override;
	Variant get_handle_value(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary) const override;
	void set_handle(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary, Camera3D *p_camera, const Vector2 &p_point) override;
	void commit_handle(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary, const Variant &p_restore, bool p_cancel) override;

	// The light colour with its HSV value raised to 1 (black stays white, so the gizmo stays visible).
	static Color get_gizmo_color(const Light3D *p_light);
	// Local-space geometry, as line pairs.
	static std::vector<Vector3> get_area_outline(const Vector2 &p_size); // 4 segments, 8 points.
	// The outline drawn as the shape (RS::LightAreaShape): rectangle get_area_outline(); disk the ellipse;
	// sphere its three great circles; tube its two end circles, four side lines and the cap arcs.
	static std::vector<Vector3> get_area_shape_outline(int p_shape, const Vector2 &p_size);
	static std::vector<Vector3> get_area_range_box(const Vector2 &p_size, real_t p_range); // 12 segments.
	// New area_size when handle p_id is dragged to local point p_local (x or y is the half-extent).
	Vector2 get_area_size_for_drag(const Vector2 &p_old_size, int p_id, const Vector3 &p_local) const;

	Light3DGizmoPlugin();
};
