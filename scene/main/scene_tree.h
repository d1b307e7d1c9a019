/**************************************************************************/
/*  scene_tree.h                                                          */
/**************************************************************************/
/* godot-area: a small SceneTree. It owns the root node ("root"), the     */
/* World3D (scenario + environment) that 3D nodes render into, and one RS */
/* viewport that draws the current Camera3D. Godot splits this between    */
/* SceneTree, Window/Viewport and World3D; we keep one object.            */
/*                                                                        */
/*   SceneTree tree;                       // needs a live RenderingServer */
/*   tree.get_root()->add_child(scene);    // nodes enter the tree         */
/*   tree.set_size(64, 64);                                               */
/*   Image img = tree.render();            // RS::draw() + read back      */

#pragma once

#include "core/io/image.h"
#include "core/object/ref_counted.h"
#include "scene/main/node.h"
#include "scene/resources/world_3d.h"

class Camera3D;

class SceneTree {
	Node *root = nullptr;
	Ref<World3D> world_3d;
	RID viewport;
	Camera3D *camera = nullptr;
	int width = 0;
	int height = 0;

public:
	Node *get_root() const { return root; }
	Ref<World3D> get_world_3d() const { return world_3d; }
	RID get_viewport_rid() const { return viewport; }

	// The camera the viewport renders from (Godot: Viewport::get_camera_3d()).
	Camera3D *get_camera_3d() const { return camera; }
	// Called by Camera3D only. A null camera detaches the viewport's camera.
	void _camera_set(Camera3D *p_camera);

	// Viewport size in pixels (0 = nothing is drawn).
	void set_size(int p_width, int p_height);
	int get_width() const { return width; }
	int get_height() const { return height; }
	// Draws every active viewport (RS::draw) and returns this tree's image (linear HDR float RGBA).
	Image render();
	// A still image: draws until every AREA_SHADOW_ADAPTIVE light has settled (its subdivision refines over
	// frames; RS::get_frame_area_shadow_tests() == 0) or p_max_frames draws, then reads back. Without
	// adaptive lights this is one draw, like render(). r_frames (optional): the draws made.
	Image render_settled(int p_max_frames = DEFAULT_SETTLE_FRAMES, int *r_frames = nullptr);
	static constexpr int DEFAULT_SETTLE_FRAMES = 32;

	SceneTree();
	~SceneTree();
	SceneTree(const SceneTree &) = delete;
	SceneTree &operator=(const SceneTree &) = delete;
};
