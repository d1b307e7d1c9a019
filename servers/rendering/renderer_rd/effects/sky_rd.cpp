/**************************************************************************/
/*  sky_rd.cpp                                                            */
/**************************************************************************/
/* godot-area: sky background and SH ambient (see sky_rd.h).              */

#include "servers/rendering/renderer_rd/effects/sky_rd.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"

#include <cstring>

bool SkyRD::_ensure_gpu() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL_V_MSG(rd, false, "SkyRD: no RenderingDevice.");
	if (!shader_ready) {
		ERR_FAIL_COND_V_MSG(!shader.initialize("sky.glsl", { "" }), false, "SkyRD: cannot load shaders/sky.glsl.");
		ERR_FAIL_COND_V_MSG(!shader.version_get_shader(0).is_valid(), false, "SkyRD: sky.glsl failed to compile: " + shader.get_last_error());
		shader_ready = true;
	}
	if (!data_ubo.is_valid()) {
		data_ubo = rd->uniform_buffer_create(sizeof(SkyDataUBO));
		ambient_ubo = rd->uniform_buffer_create(sizeof(SkyAmbientUBO));
		rd->set_resource_name(data_ubo, "SkyRD background data");
		rd->set_resource_name(ambient_ubo, "SkyRD ambient SH");
		vertex_format = rd->vertex_format_create({});
	}
	if (!data_set.is_valid() || !rd->uniform_set_is_valid(data_set)) {
		data_set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, data_ubo) }, shader.version_get_shader(0), 0);
	}
	return data_ubo.is_valid() && ambient_ubo.is_valid() && data_set.is_valid();
}

static void _v4(float *r_out, const Vector3 &p_v, float p_w) {
	r_out[0] = p_v.x;
	r_out[1] = p_v.y;
	r_out[2] = p_v.z;
	r_out[3] = p_w;
}

bool SkyRD::prepare(const RenderSceneData &p_data, const RendererLightStorage *p_light_storage, const Projection &p_clip_from_view, int p_width, int p_height) {
	const RenderSceneData::EnvironmentData &env = p_data.environment;
	frame_background = env.has_sky && env.background == RS::ENV_BG_SKY;
	frame_ambient = env.has_sky && env.sky_ambient && env.ambient_sky_contribution > 0.0f;
	if (!frame_background && !frame_ambient) {
		return true; // No sky in this view: nothing built, nothing drawn.
	}
	ERR_FAIL_COND_V(!_ensure_gpu(), false);
	RenderingDevice *rd = RenderingDevice::get_singleton();
	model = SkyModel::from_scene_data(p_data, p_light_storage);
	const uint64_t hash = model.get_hash() ^ (uint64_t(*reinterpret_cast<const uint32_t *>(&env.ambient_sky_contribution)) * 0x9E3779B97F4A7C15ULL);
	if (frame_ambient && (!model_valid || hash != model_hash)) {
		// The sky changed (or the first frame with sky ambient): project once, upload once.
		model.compute_irradiance_sh(sh);
		SkyAmbientUBO a;
		memset(&a, 0, sizeof(a));
		const float scale = env.ambient_sky_contribution / float(Math::PI); // Irradiance -> Lambert radiance factor.
		for (int k = 0; k < 9; k++) {
			for (int c = 0; c < 3; c++) {
				a.sh[k][c] = sh[k][c] * scale;
			}
		}
		rd->buffer_update(ambient_ubo, 0, sizeof(a), &a);
		model_hash = hash;
		model_valid = true;
		update_count++;
	}
	if (frame_background) {
		SkyDataUBO u;
		memset(&u, 0, sizeof(u));
		p_clip_from_view.inverse().to_floats(u.view_from_clip);
		Projection::from_transform(p_data.cam_transform).to_floats(u.world_from_view);
		u.viewport_size[0] = float(p_width);
		u.viewport_size[1] = float(p_height);
		_v4(u.sky_top, model.sky_top, 0.0f);
		_v4(u.sky_horizon, model.sky_horizon, 0.0f);
		_v4(u.ground_bottom, model.ground_bottom, 0.0f);
		_v4(u.ground_horizon, model.ground_horizon, 0.0f);
		u.curves[0] = model.sky_curve;
		u.curves[1] = model.ground_curve;
		u.curves[2] = model.sun_angle_max;
		u.curves[3] = model.sun_curve;
		_v4(u.sun_direction, model.sun_direction, model.sun_size);
		_v4(u.sun_radiance, model.sun_radiance, model.sun_enabled ? 1.0f : 0.0f);
		rd->buffer_update(data_ubo, 0, sizeof(u), &u);
	}
	return true;
}

void SkyRD::draw_background(RenderingDevice::DrawListID p_list, RenderingDevice::FramebufferFormatID p_format) {
	ERR_FAIL_COND_MSG(!frame_background || !data_set.is_valid(), "SkyRD::draw_background: no sky prepared for this frame.");
	RenderingDevice *rd = RenderingDevice::get_singleton();
	RID &pipeline = pipelines[p_format];
	if (!pipeline.is_valid()) {
		RD::PipelineRasterizationState raster;
		raster.cull_mode = RD::POLYGON_CULL_DISABLED;
		RD::PipelineDepthStencilState depth;
		depth.enable_depth_test = true;
		depth.enable_depth_write = false;
		depth.depth_compare_operator = RD::COMPARE_OP_LESS_OR_EQUAL; // Only where the depth is still the far plane.
		pipeline = rd->render_pipeline_create(shader.version_get_shader(0), p_format, vertex_format, RD::RENDER_PRIMITIVE_TRIANGLES, raster, depth, RD::PipelineColorBlendState::create_disabled(1));
		ERR_FAIL_COND_MSG(!pipeline.is_valid(), "SkyRD: the sky pipeline could not be created.");
	}
	rd->draw_list_bind_render_pipeline(p_list, pipeline);
	rd->draw_list_bind_uniform_set(p_list, data_set, 0);
	rd->draw_list_draw(p_list, false, 1, 3);
}

void SkyRD::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized()) {
		for (auto &kv : pipelines) {
			rd->free(kv.second);
		}
		if (data_ubo.is_valid()) {
			rd->free(data_ubo); // Frees data_set too.
		}
		if (ambient_ubo.is_valid()) {
			rd->free(ambient_ubo);
		}
	}
	pipelines.clear();
	data_ubo = RID();
	ambient_ubo = RID();
	data_set = RID();
	shader.clear();
	shader_ready = false;
	model_valid = false;
	frame_background = false;
	frame_ambient = false;
}
