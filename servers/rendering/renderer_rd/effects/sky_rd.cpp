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

void SkyRD::_fill_model(SkyDataUBO &r_u) const {
	_v4(r_u.sky_top, model.sky_top, model.type == SkyModel::TYPE_PHYSICAL ? 1.0f : 0.0f);
	_v4(r_u.sky_horizon, model.sky_horizon, 0.0f);
	_v4(r_u.ground_bottom, model.ground_bottom, 0.0f);
	_v4(r_u.ground_horizon, model.ground_horizon, 0.0f);
	r_u.curves[0] = model.sky_curve;
	r_u.curves[1] = model.ground_curve;
	r_u.curves[2] = model.sun_angle_max;
	r_u.curves[3] = model.sun_curve;
	_v4(r_u.sun_direction, model.sun_direction, model.sun_size);
	_v4(r_u.sun_radiance, model.sun_radiance, model.sun_enabled ? 1.0f : 0.0f);
	_v4(r_u.rayleigh_beta, model.rayleigh_beta, model.sun_energy);
	_v4(r_u.mie_beta, model.mie_beta, model.mie_eccentricity);
	_v4(r_u.physical_ground, model.physical_ground, model.sun_fade);
	_v4(r_u.physical_sun, model.physical_sun_color, model.exposure);
	r_u.physical_disk[0] = model.disk_cos_outer;
	r_u.physical_disk[1] = model.disk_cos_inner;
	r_u.physical_disk[2] = model.sun_zenith_cos;
	r_u.physical_disk[3] = 0.0f;
}

bool SkyRD::_ensure_radiance(int p_size) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (!radiance_shader_ready) {
		ERR_FAIL_COND_V_MSG(!radiance_shader.initialize("sky_radiance.glsl", { "" }), false, "SkyRD: cannot load shaders/sky_radiance.glsl.");
		RID s = radiance_shader.version_get_shader(0);
		ERR_FAIL_COND_V_MSG(!s.is_valid(), false, "SkyRD: sky_radiance.glsl failed to compile: " + radiance_shader.get_last_error());
		radiance_pipeline = rd->compute_pipeline_create(s);
		ERR_FAIL_COND_V_MSG(!radiance_pipeline.is_valid(), false, "SkyRD: the radiance filter pipeline could not be created.");
		RD::SamplerState ss;
		ss.mag_filter = RD::SAMPLER_FILTER_LINEAR;
		ss.min_filter = RD::SAMPLER_FILTER_LINEAR;
		ss.mip_filter = RD::SAMPLER_FILTER_LINEAR;
		radiance_sampler = rd->sampler_create(ss);
		radiance_shader_ready = true;
	}
	if (radiance_cube.is_valid() && radiance_size == p_size && rd->texture_is_valid(radiance_cube)) {
		return true;
	}
	if (radiance_cube.is_valid()) {
		rd->free(radiance_cube); // Frees its slices and their sets.
		radiance_cube = RID();
	}
	radiance_sets.clear();
	int mips = 1;
	while ((p_size >> mips) > 0 && mips < MAX_RADIANCE_MIPS) {
		mips++;
	}
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R16G16B16A16_SFLOAT;
	tf.width = uint32_t(p_size);
	tf.height = uint32_t(p_size);
	tf.array_layers = 6;
	tf.mipmaps = uint32_t(mips);
	tf.texture_type = RD::TEXTURE_TYPE_CUBE;
	tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_STORAGE_BIT;
	radiance_cube = rd->texture_create(tf);
	ERR_FAIL_COND_V_MSG(!radiance_cube.is_valid(), false, vformat("SkyRD: the %dx%d radiance cubemap could not be created.", p_size, p_size));
	rd->set_resource_name(radiance_cube, "SkyRD radiance cubemap");
	RID shader = radiance_shader.version_get_shader(0);
	for (int m = 0; m < mips; m++) {
		for (int f = 0; f < 6; f++) {
			RID slice = rd->texture_create_shared_from_slice(radiance_cube, uint32_t(f), uint32_t(m));
			ERR_FAIL_COND_V_MSG(!slice.is_valid(), false, "SkyRD: a radiance cubemap slice could not be created.");
			RID set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, data_ubo), RD::Uniform(RD::UNIFORM_TYPE_IMAGE, 1, slice) }, shader, 0);
			ERR_FAIL_COND_V_MSG(!set.is_valid(), false, "SkyRD: a radiance filter uniform set could not be created.");
			radiance_sets.push_back(set);
		}
	}
	radiance_size = p_size;
	radiance_mips = mips;
	radiance_valid = false;
	return true;
}

void SkyRD::filter_radiance() {
	ERR_FAIL_COND_MSG(!radiance_pending || !radiance_pipeline.is_valid(), "SkyRD::filter_radiance: nothing to filter this frame.");
	RenderingDevice *rd = RenderingDevice::get_singleton();
	RD::ComputeListID list = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(list, radiance_pipeline);
	for (int m = 0; m < radiance_mips; m++) {
		const uint32_t size = std::max(1u, uint32_t(radiance_size) >> m);
		const float r = get_mip_roughness(m, radiance_mips);
		for (int f = 0; f < 6; f++) {
			RadiancePushConstant pc;
			pc.face = uint32_t(f);
			pc.size = size;
			pc.alpha = r * r;
			pc.sample_count = get_radiance_sample_count(m);
			rd->compute_list_bind_uniform_set(list, radiance_sets[size_t(m) * 6 + f], 0);
			rd->compute_list_set_push_constant(list, &pc, sizeof(pc));
			rd->compute_list_dispatch_threads(list, size, size, 1);
		}
	}
	rd->compute_list_end();
	radiance_pending = false;
	radiance_valid = true;
	radiance_update_count++;
}

bool SkyRD::prepare(const RenderSceneData &p_data, const RendererLightStorage *p_light_storage, const Projection &p_clip_from_view, int p_width, int p_height) {
	const RenderSceneData::EnvironmentData &env = p_data.environment;
	frame_background = env.has_sky && env.background == RS::ENV_BG_SKY;
	frame_ambient = env.has_sky && env.sky_ambient && env.ambient_sky_contribution > 0.0f;
	frame_reflections = env.has_sky && env.sky_reflections;
	radiance_pending = false;
	if (!frame_background && !frame_ambient && !frame_reflections) {
		return true; // No sky in this view: nothing built, nothing drawn.
	}
	ERR_FAIL_COND_V(!_ensure_gpu(), false);
	RenderingDevice *rd = RenderingDevice::get_singleton();
	model = SkyModel::from_scene_data(p_data, p_light_storage);
	const uint64_t model_key = model.get_hash();
	uint32_t contribution_bits = 0;
	memcpy(&contribution_bits, &env.ambient_sky_contribution, sizeof(contribution_bits));
	const uint64_t hash = model_key ^ (uint64_t(contribution_bits) * 0x9E3779B97F4A7C15ULL);
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
	// The block is rewritten every frame (the view matrices change); the model part feeds the background
	// and the radiance filter.
	SkyDataUBO u;
	memset(&u, 0, sizeof(u));
	p_clip_from_view.inverse().to_floats(u.view_from_clip);
	Projection::from_transform(p_data.cam_transform).to_floats(u.world_from_view);
	u.viewport_size[0] = float(p_width);
	u.viewport_size[1] = float(p_height);
	_fill_model(u);
	rd->buffer_update(data_ubo, 0, sizeof(u), &u);
	if (frame_reflections) {
		ERR_FAIL_COND_V(!_ensure_radiance(std::min(std::max(env.sky_radiance_size, 32), 2048)), false);
		if (!radiance_valid || radiance_hash != model_key) {
			radiance_pending = true; // Filtered by filter_radiance() this frame; a static sky never again.
			radiance_hash = model_key;
		}
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
		if (radiance_cube.is_valid()) {
			rd->free(radiance_cube);
		}
		if (radiance_pipeline.is_valid()) {
			rd->free(radiance_pipeline);
		}
		if (radiance_sampler.is_valid()) {
			rd->free(radiance_sampler);
		}
	}
	radiance_cube = RID();
	radiance_pipeline = RID();
	radiance_sampler = RID();
	radiance_sets.clear();
	radiance_shader.clear();
	radiance_shader_ready = false;
	radiance_valid = false;
	radiance_pending = false;
	frame_reflections = false;
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
