/**************************************************************************/
/*  isr_sweep_scenes.h                                                    */
/**************************************************************************/
/* godot-area: the scenes of the image-space radiosity evaluation (seed   */
/* 003, §5.2): a closed Cornell-like room lit by one ceiling area light   */
/* (coloured side walls, or all white), and an open scene (a ground with  */
/* coloured blocks under an area light, no walls), each with a short      */
/* camera path. Built into any storages (the Forward+ renderer's and the  */
/* Embree reference's), so direct-only, ISR and one-bounce truth are      */
/* three images of the same frame. Tools build it through a               */
/* RenderingServer (IsrServerScene, the path users take); the renderer's  */
/* own unit tests (tests/servers/test_ss_radiosity.cpp) also build it     */
/* straight into the Forward+ storages.                                   */

#pragma once

#include "core/io/image.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/storage/light_storage.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"

#include <vector>

struct IsrScene {
	struct Object {
		RS::SurfaceData surface;
		RS::MaterialParams material;
		Transform3D transform;
	};
	struct AreaLightDesc {
		Transform3D transform; // Emits along local -Z.
		Vector2 size;
		Color color = Color(1, 1, 1, 1);
		float energy = 1.0f;
		float range = 10.0f;
	};
	std::vector<Object> objects;
	std::vector<AreaLightDesc> lights;
	std::vector<Transform3D> camera_path; // world_from_view per frame.
	float fovy_degrees = 60.0f;

	enum RoomColors {
		ROOM_CORNELL, // Red left wall, green right wall, the rest white.
		ROOM_WHITE, // Every wall white.
	};
	// A closed 2 x 2 x 2 m room (floor y = 0) with one 0.6 x 0.6 m area light under the ceiling, a white
	// block on the floor, cameras inside near the front wall.
	static IsrScene make_room(RoomColors p_colors);
	// An open scene: a 12 m ground, three coloured blocks and a white wall segment, one area light above;
	// cameras outside looking in.
	static IsrScene make_open();

	// Creates the resources in the storages and fills r_data (geometry + lights; camera from
	// camera_path[p_frame]); created RIDs go to the r_* lists (the caller frees them).
	void build(RendererMeshStorage &p_mesh, RendererMaterialStorage &p_material, RendererLightStorage &p_light, RenderSceneData &r_data, std::vector<RID> &r_meshes, std::vector<RID> &r_materials, std::vector<RID> &r_lights) const;
	// A view of p_width x p_height from camera_path[p_frame], black background, no ambient.
	RenderSceneData make_view(int p_frame, int p_width, int p_height) const;
};

// An IsrScene created through a RenderingServer: its meshes, materials and area lights in one scenario
// whose environment is black and unlit, and one viewport of the given size whose camera stands at a
// frame of the camera path. Freed by free() or the destructor.
class IsrServerScene {
	RenderingServer *rs = nullptr;
	const IsrScene *scene = nullptr;
	std::vector<RID> rids; // Freed last to first.
	RID environment;
	RID camera;
	RID viewport;

public:
	bool create(RenderingServer *p_rs, const IsrScene &p_scene, int p_width, int p_height);
	void set_frame(int p_frame);
	// Godot's Environment SSIL parameters and the global SSIL quality; p_settings.ssil_enabled false
	// turns the pass off (direct light only).
	void set_screen_space_lighting(const ScreenSpaceLightingSettings &p_settings);
	void set_active(bool p_active);
	RID get_viewport() const { return viewport; }
	// Draws every active viewport and returns this one's linear HDR image.
	Image draw();
	void free();

	IsrServerScene() {}
	~IsrServerScene() { free(); }
	IsrServerScene(const IsrServerScene &) = delete;
	IsrServerScene &operator=(const IsrServerScene &) = delete;
};
