/**************************************************************************/
/*  gizmo_overlay.h                                                       */
/**************************************************************************/
/* godot-area: draws editor gizmos (lines, handles, billboard icons) on   */
/* top of a rendered HDR Image, for `godot-area render --gizmos`. We have */
/* no editor viewport, so this stands in for Godot's gizmo meshes:        */
/*                                                                        */
/*   Image img = tree.render();                                           */
/*   GizmoOverlay::draw(img, tree);       // every Light3D's gizmo        */
/*                                                                        */
/* Geometry comes from the gizmo plugins (Light3DGizmoPlugin for every    */
/* Light3D), so what is drawn is exactly what the plugin's redraw()       */
/* records. Projection matches the renderer: the camera transform, the    */
/* perspective RendererSceneCull builds for this image's aspect, Vulkan's */
/* depth correction (y down) and pixel centres at (x + 0.5, y + 0.5).     */
/*                                                                        */
/* Lines: clipped in camera space against the near plane (nothing behind  */
/* the camera is drawn), then against the image, then drawn anti-aliased  */
/* (Xiaolin Wu's algorithm). Handles: filled 7x7 squares with a dark      */
/* border. Icons: the SVG's shapes (rectangles, circles, triangles),      */
/* mirrored as a small shape table in gizmo_overlay.cpp and rasterized    */
/* with 4x4 supersampling, tinted by the gizmo modulate; the icon is      */
/* centred on the node's origin and drawn only when that is in front of   */
/* the near plane. Colours are sRGB with straight alpha, converted to     */
/* linear and alpha-blended onto the scene-linear image. No depth test:   */
/* gizmos are drawn on top, like Godot's "on top" gizmo materials.        */

#pragma once

#include "core/io/image.h"
#include "core/math/projection.h"
#include "core/math/transform_3d.h"
#include "core/math/vector2.h"

class Camera3D;
class EditorNode3DGizmo;
class Node;
class SceneTree;

class GizmoOverlay {
	int width = 0;
	int height = 0;
	Transform3D world_from_view; // The camera transform.
	Transform3D view_from_world;
	Projection clip_from_view; // Vulkan clip space.
	real_t z_near = 0.05;
	real_t tan_half_fovy = 1;
	bool valid = false;

	void _plot(Image &r_image, int p_x, int p_y, const Color &p_linear, float p_coverage) const;
	void _draw_line_2d(Image &r_image, Vector2 p_a, Vector2 p_b, const Color &p_linear) const;
	Vector2 _view_to_pixel(const Vector3 &p_view) const;

public:
	// Handle squares: side in pixels.
	static constexpr int HANDLE_SIZE = 7;
	// Icon side limits in pixels.
	static constexpr int ICON_MIN_SIZE = 12;
	static constexpr int ICON_MAX_SIZE = 48;

	// Prepares the camera for an image of p_width x p_height. False (with an error) on bad input.
	bool setup(const Camera3D *p_camera, int p_width, int p_height);
	bool is_valid() const { return valid; }

	// Pixel position of a world point (top-left origin); false when it is not in front of the near plane.
	bool project(const Vector3 &p_world, Vector2 &r_pixel) const;
	// A world-space segment, near-clipped; p_color is sRGB with straight alpha.
	void draw_line(Image &r_image, const Vector3 &p_world_a, const Vector3 &p_world_b, const Color &p_color) const;
	// A handle square centred on the projection of p_world.
	void draw_handle(Image &r_image, const Vector3 &p_world, const Color &p_color) const;
	// The icon of p_icon_path (a stand-in disc for unknown icons), centred on p_world. Size in
	// pixels: height * p_scale / tan(fovy / 2) (constant on screen), clamped to ICON_MIN/MAX_SIZE.
	void draw_icon(Image &r_image, const Vector3 &p_world, const String &p_icon_path, real_t p_scale, const Color &p_color) const;
	// Whether the icon of p_icon_path covers point (p_u, p_v) of its 32x32 SVG viewBox (y down);
	// the shape test draw_icon() samples (also used to check the tables against the SVG files).
	static bool icon_covers(const String &p_icon_path, float p_u, float p_v);
	// Everything p_gizmo recorded (call its redraw() first), placed by its node's global transform.
	void draw_gizmo(Image &r_image, const EditorNode3DGizmo &p_gizmo) const;

	// Redraws and draws the gizmo of every visible Light3D under p_root (included), seen from
	// p_camera. p_selected draws them as selected (range volumes and handles too); otherwise only
	// what Godot shows for unselected lights (icons, and the area lights' outlines).
	// Returns the number of gizmos drawn, or -1 on bad input (error printed, image untouched).
	static int draw(Image &r_image, Node *p_root, const Camera3D *p_camera, bool p_selected = false);
	// Same, for the tree's root and its current camera (-1 with an error when it has none).
	static int draw(Image &r_image, SceneTree &p_tree, bool p_selected = false);
};
