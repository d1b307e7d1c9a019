/**************************************************************************/
/*  rasterizer_scene_dummy.cpp                                            */
/**************************************************************************/

#include "servers/rendering/dummy/rasterizer_scene_dummy.h"

#include "core/error/error_macros.h"

void RasterizerSceneDummy::render_scene(const RenderSceneData &p_data, RID p_render_target) {
	ERR_FAIL_COND_MSG(!render_target_owner.owns(p_render_target), "Invalid render target RID.");
	last_scene_data = p_data;
	render_count++;
}

RID RasterizerSceneDummy::render_target_create(int p_width, int p_height) {
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE, RID(),
			vformat("Render target size %dx%d is invalid (1..%d per side).", p_width, p_height, Image::MAX_SIZE));
	RenderTarget rt;
	rt.width = p_width;
	rt.height = p_height;
	return render_target_owner.make_rid(rt);
}

bool RasterizerSceneDummy::render_target_free(RID p_rid) {
	if (!render_target_owner.owns(p_rid)) {
		return false;
	}
	render_target_owner.free(p_rid);
	return true;
}

std::vector<float> RasterizerSceneDummy::render_target_get_data(RID p_render_target) {
	const RenderTarget *rt = render_target_owner.get_or_null(p_render_target);
	ERR_FAIL_NULL_V_MSG(rt, std::vector<float>(), "Invalid render target RID.");
	std::vector<float> data((size_t)rt->width * rt->height * 4, 0.0f);
	for (size_t i = 3; i < data.size(); i += 4) {
		data[i] = 1.0f; // Opaque black.
	}
	return data;
}

std::vector<std::pair<String, double>> RasterizerSceneDummy::get_last_frame_profile() const {
	return {}; // No GPU passes.
}
