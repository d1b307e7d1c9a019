/**************************************************************************/
/*  rasterizer_scene_dummy.h                                              */
/**************************************************************************/
/* godot-area: a scene renderer that draws nothing (Godot's dummy         */
/* rasterizer): render targets read back as opaque black. It keeps a copy */
/* of the last RenderSceneData so tests can inspect what the server sent. */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/renderer_scene_render.h"

class RasterizerSceneDummy : public RendererSceneRender {
	struct RenderTarget {
		int width = 0;
		int height = 0;
	};

	mutable RID_Owner<RenderTarget, true> render_target_owner{ "RenderTarget" };
	RenderSceneData last_scene_data;
	int render_count = 0;
	bool force_all_lights = false;

public:
	void render_scene(const RenderSceneData &p_data, RID p_render_target) override;
	RID render_target_create(int p_width, int p_height) override;
	bool render_target_free(RID p_rid) override;
	bool owns_render_target(RID p_rid) const override { return render_target_owner.owns(p_rid); }
	std::vector<float> render_target_get_data(RID p_render_target) override;
	std::vector<std::pair<String, double>> get_last_frame_profile() const override;
	void set_debug_force_all_lights(bool p_enable) override { force_all_lights = p_enable; }

	// The data of the last render_scene() call (tests).
	const RenderSceneData &get_last_scene_data() const { return last_scene_data; }
	// Number of render_scene() calls so far (tests).
	int get_render_count() const { return render_count; }
	// Last value given to set_debug_force_all_lights() (tests).
	bool is_debug_force_all_lights() const { return force_all_lights; }
};
