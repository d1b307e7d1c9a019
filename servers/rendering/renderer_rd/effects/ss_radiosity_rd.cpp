/**************************************************************************/
/*  ss_radiosity_rd.cpp                                                   */
/**************************************************************************/
/* godot-area: image-space radiosity passes (see ss_radiosity_rd.h).      */

#include "servers/rendering/renderer_rd/effects/ss_radiosity_rd.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cstring>

SSRadiosityRD::FrameSettings SSRadiosityRD::get_frame_settings(const ScreenSpaceLightingSettings &p_settings) {
	FrameSettings f;
	f.ssil = p_settings.ssil_enabled;
	f.ssao = p_settings.ssao_enabled;
	// One pass computes both (the seed's Listing 6): SSIL's quality rules when SSIL is on, else SSAO's.
	const int quality = f.ssil ? p_settings.ssil_quality : p_settings.ssao_quality;
	f.sample_count = uint32_t(RS::get_ss_radiosity_sample_count(quality));
	f.half_size = f.ssil ? p_settings.ssil_half_size : p_settings.ssao_half_size;
	f.blur_passes = f.ssil ? p_settings.ssil_blur_passes : p_settings.ssao_blur_passes;
	f.interleave = get_interleave(f.sample_count);
	return f;
}

uint32_t SSRadiosityRD::get_interleave(uint32_t p_sample_count) {
	uint32_t k = 1;
	while (k < MAX_INTERLEAVE && (k + 1) * (k + 1) <= p_sample_count) {
		k++;
	}
	return k;
}

bool SSRadiosityRD::_ensure_shaders() {
	if (shaders_ready) {
		return true;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL_V_MSG(rd, false, "SSRadiosityRD: no RenderingDevice.");
	static_assert(PASS_MAX == 8 && COMPOSITE_MAX == 3, "One define per PassVariant.");
	const char *terms[COMPOSITE_MAX] = { "#define USE_SSIL\n", "#define USE_SSAO\n", "#define USE_SSIL\n#define USE_SSAO\n" };
	std::vector<String> defines = { "#define MODE_DOWNSAMPLE\n#define DOWNSAMPLE_HALF\n", "#define MODE_DOWNSAMPLE\n" };
	for (const char *mode : { "#define MODE_ISR\n", "#define MODE_BLUR\n" }) {
		for (const char *t : terms) {
			defines.push_back(String(mode) + t);
		}
	}
	ERR_FAIL_COND_V_MSG(!pass_shader.initialize("effects/ss_radiosity.glsl", defines), false,
			"SSRadiosityRD: cannot load shaders/effects/ss_radiosity.glsl.");
	for (int v = 0; v < PASS_MAX; v++) {
		RID shader = pass_shader.version_get_shader(v);
		ERR_FAIL_COND_V_MSG(!shader.is_valid(), false, vformat("SSRadiosityRD: ss_radiosity.glsl variant %d failed to compile: %s", v, pass_shader.get_last_error().c_str()));
		pass_pipelines[v] = rd->compute_pipeline_create(shader);
		ERR_FAIL_COND_V_MSG(!pass_pipelines[v].is_valid(), false, "SSRadiosityRD: compute pipeline creation failed.");
	}
	ERR_FAIL_COND_V_MSG(!composite_shader.initialize("effects/ss_radiosity_composite.glsl", { terms[0], terms[1], terms[2] }), false,
			"SSRadiosityRD: cannot load shaders/effects/ss_radiosity_composite.glsl.");
	for (int v = 0; v < COMPOSITE_MAX; v++) {
		ERR_FAIL_COND_V_MSG(!composite_shader.version_get_shader(v).is_valid(), false, vformat("SSRadiosityRD: ss_radiosity_composite.glsl variant %d failed to compile: %s", v, composite_shader.get_last_error().c_str()));
	}
	RD::SamplerState ss; // Nearest, clamp: every read is a texelFetch.
	sampler = rd->sampler_create(ss);
	vertex_format = rd->vertex_format_create({});
	shaders_ready = true;
	return true;
}

void SSRadiosityRD::_free_buffers(Buffers &r_b) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (!rd || !rd->is_initialized()) {
		return;
	}
	// Freeing a texture frees the framebuffers and uniform sets made with it.
	for (RID *t : { &r_b.normal, &r_b.albedo, &r_b.ambient, &r_b.coarse_gbuffer, &r_b.isr[0], &r_b.isr[1] }) {
		if (t->is_valid()) {
			rd->free(*t);
			*t = RID();
		}
	}
	if (r_b.fb_composite.is_valid() && rd->framebuffer_is_valid(r_b.fb_composite)) {
		rd->free(r_b.fb_composite); // Made only from the render target's colour, which stays.
	}
	r_b.fb_composite = RID();
	r_b.fb_gbuffer = RID();
	for (RID &s : r_b.sets) {
		s = RID();
	}
}

static RID _make_texture(RenderingDevice *p_rd, RD::DataFormat p_format, int p_w, int p_h, uint32_t p_usage, const char *p_name) {
	RD::TextureFormat tf;
	tf.format = p_format;
	tf.width = uint32_t(p_w);
	tf.height = uint32_t(p_h);
	tf.usage_bits = p_usage;
	RID t = p_rd->texture_create(tf);
	if (t.is_valid()) {
		p_rd->set_resource_name(t, p_name);
	}
	return t;
}

bool SSRadiosityRD::_make_sets(Buffers &r_b) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	using U = RD::Uniform;
	// Both downsample variants declare the same bindings.
	r_b.sets[0] = rd->uniform_set_create({ U(RD::UNIFORM_TYPE_SAMPLER, 0, sampler), U(RD::UNIFORM_TYPE_TEXTURE, 1, r_b.color), U(RD::UNIFORM_TYPE_TEXTURE, 2, r_b.depth),
												 U(RD::UNIFORM_TYPE_TEXTURE, 3, r_b.normal), U(RD::UNIFORM_TYPE_IMAGE, 4, r_b.coarse_gbuffer) },
			pass_shader.version_get_shader(PASS_DOWNSAMPLE_HALF), 0);
	// The ISR variants declare the same bindings: one set per target serves them all.
	for (int i = 0; i < 2; i++) {
		r_b.sets[1 + i] = rd->uniform_set_create({ U(RD::UNIFORM_TYPE_SAMPLER, 0, sampler), U(RD::UNIFORM_TYPE_TEXTURE, 1, r_b.coarse_gbuffer), U(RD::UNIFORM_TYPE_IMAGE, 2, r_b.isr[i]) },
				pass_shader.version_get_shader(PASS_ISR_SSIL), 0);
	}
	for (int v = 0; v < COMPOSITE_MAX; v++) {
		for (int i = 0; i < 2; i++) {
			r_b.sets[3 + 2 * v + i] = rd->uniform_set_create({ U(RD::UNIFORM_TYPE_SAMPLER, 0, sampler), U(RD::UNIFORM_TYPE_TEXTURE, 1, r_b.isr[i]), U(RD::UNIFORM_TYPE_IMAGE, 2, r_b.isr[1 - i]) },
					pass_shader.version_get_shader(PASS_BLUR_SSIL + v), 0);
		}
	}
	for (int v = 0; v < COMPOSITE_MAX; v++) {
		std::vector<U> u = { U(RD::UNIFORM_TYPE_SAMPLER, 0, sampler), U(RD::UNIFORM_TYPE_TEXTURE, 1, r_b.depth), U(RD::UNIFORM_TYPE_TEXTURE, 4, r_b.isr[0]) };
		if (v != COMPOSITE_SSAO) {
			u.push_back(U(RD::UNIFORM_TYPE_TEXTURE, 2, r_b.albedo));
		}
		if (v != COMPOSITE_SSIL) {
			u.push_back(U(RD::UNIFORM_TYPE_TEXTURE, 3, r_b.ambient));
		}
		r_b.sets[3 + 2 * COMPOSITE_MAX + v] = rd->uniform_set_create(u, composite_shader.version_get_shader(v), 0);
	}
	for (RID s : r_b.sets) {
		ERR_FAIL_COND_V_MSG(!s.is_valid(), false, "SSRadiosityRD: uniform set creation failed.");
	}
	return true;
}

RID SSRadiosityRD::prepare(RID p_owner, RID p_color, RID p_depth, int p_width, int p_height, const FrameSettings &p_frame) {
	ERR_FAIL_COND_V_MSG(!p_frame.is_active(), RID(), "SSRadiosityRD::prepare: neither SSIL nor SSAO is enabled.");
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0, RID(), vformat("SSRadiosityRD::prepare: invalid size %dx%d.", p_width, p_height));
	ERR_FAIL_COND_V(!_ensure_shaders(), RID());
	RenderingDevice *rd = RenderingDevice::get_singleton();
	const int scale = p_frame.half_size ? 2 : 1;
	const int cw = (p_width + scale - 1) / scale;
	const int ch = (p_height + scale - 1) / scale;
	Buffers &b = buffers[p_owner];
	const bool valid = b.fb_gbuffer.is_valid() && rd->framebuffer_is_valid(b.fb_gbuffer) && b.color == p_color && b.depth == p_depth && b.width == p_width && b.height == p_height && b.coarse_width == cw && b.coarse_height == ch;
	if (valid) {
		return b.fb_gbuffer;
	}
	_free_buffers(b);
	b.width = p_width;
	b.height = p_height;
	b.coarse_width = cw;
	b.coarse_height = ch;
	b.color = p_color;
	b.depth = p_depth;
	const uint32_t attachment = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT;
	const uint32_t storage = RD::TEXTURE_USAGE_STORAGE_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	b.normal = _make_texture(rd, GBUFFER_FORMAT, p_width, p_height, attachment, "SSRadiosityRD normal");
	b.albedo = _make_texture(rd, GBUFFER_FORMAT, p_width, p_height, attachment, "SSRadiosityRD albedo");
	b.ambient = _make_texture(rd, GBUFFER_FORMAT, p_width, p_height, attachment, "SSRadiosityRD ambient");
	b.coarse_gbuffer = _make_texture(rd, COARSE_FORMAT, cw, ch, storage, "SSRadiosityRD coarse G-buffer");
	b.isr[0] = _make_texture(rd, COARSE_FORMAT, cw, ch, storage, "SSRadiosityRD ISR 0");
	b.isr[1] = _make_texture(rd, COARSE_FORMAT, cw, ch, storage, "SSRadiosityRD ISR 1");
	ERR_FAIL_COND_V_MSG(!b.normal.is_valid() || !b.albedo.is_valid() || !b.ambient.is_valid() || !b.coarse_gbuffer.is_valid() || !b.isr[0].is_valid() || !b.isr[1].is_valid(),
			RID(), "SSRadiosityRD: texture creation failed.");
	b.fb_gbuffer = rd->framebuffer_create({ p_color, b.normal, b.albedo, b.ambient, p_depth });
	b.fb_composite = rd->framebuffer_create({ p_color });
	ERR_FAIL_COND_V_MSG(!b.fb_gbuffer.is_valid() || !b.fb_composite.is_valid(), RID(), "SSRadiosityRD: framebuffer creation failed.");
	ERR_FAIL_COND_V(!_make_sets(b), RID());
	return b.fb_gbuffer;
}

bool SSRadiosityRD::render(RID p_owner, const Projection &p_clip_from_view, const ScreenSpaceLightingSettings &p_settings, const FrameSettings &p_frame, const String &p_timestamp) {
	auto it = buffers.find(p_owner);
	ERR_FAIL_COND_V_MSG(it == buffers.end() || !it->second.fb_gbuffer.is_valid(), false, "SSRadiosityRD::render: prepare() did not run for this render target.");
	Buffers &b = it->second;
	RenderingDevice *rd = RenderingDevice::get_singleton();
	const Projection &p = p_clip_from_view; // Column-major: p.columns[c][r].

	PassPushConstant pc;
	memset(&pc, 0, sizeof(pc));
	pc.proj_xy[0] = p.columns[0][0];
	pc.proj_xy[1] = p.columns[1][1];
	pc.proj_xy[2] = p.columns[2][0];
	pc.proj_xy[3] = p.columns[2][1];
	pc.proj_zw[0] = p.columns[3][0];
	pc.proj_zw[1] = p.columns[3][1];
	pc.proj_zw[2] = p.columns[2][3];
	pc.proj_zw[3] = p.columns[3][3];
	pc.proj_depth[0] = p.columns[2][2];
	pc.proj_depth[1] = p.columns[3][2];
	pc.proj_depth[2] = float(b.coarse_width);
	pc.proj_depth[3] = float(b.coarse_height);
	pc.ssil[0] = p_settings.ssil_radius;
	pc.ssil[1] = p_settings.ssil_normal_rejection;
	pc.ssil[2] = p_frame.ssil ? 1.0f : 0.0f;
	pc.ssil[3] = std::max(2.0f, MAX_DISK_FRACTION * float(std::max(b.coarse_width, b.coarse_height)));
	pc.ssao[0] = p_settings.ssao_radius;
	pc.ssao[1] = p_settings.ssao_horizon;
	pc.ssao[2] = p_settings.ssao_detail;
	pc.ssao[3] = p_frame.ssao ? 1.0f : 0.0f;
	pc.blur[2] = p_settings.ssil_sharpness;
	pc.blur[3] = p_settings.ssao_sharpness;
	pc.misc[0] = p_frame.sample_count;
	pc.misc[1] = uint32_t(b.width);
	pc.misc[2] = uint32_t(b.height);
	pc.misc[3] = p_frame.half_size ? 2u : 1u;
	pc.pattern[0] = std::max(p_frame.interleave, 1u);
	if (p_frame.ssao && p_settings.ssao_ao_channel_affect > 0.0f) {
		WARN_PRINT_ONCE("Environment ssao_ao_channel_affect has no effect: godot-area materials have no ambient occlusion texture channel.");
	}

	const uint32_t cw = uint32_t(b.coarse_width), ch = uint32_t(b.coarse_height);
	// Blur and composite variants: only the terms that are on.
	const int variant = p_frame.ssil ? (p_frame.ssao ? COMPOSITE_SSIL_SSAO : COMPOSITE_SSIL) : COMPOSITE_SSAO;
	RD::ComputeListID list = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(list, pass_pipelines[p_frame.half_size ? PASS_DOWNSAMPLE_HALF : PASS_DOWNSAMPLE_FULL]);
	rd->compute_list_bind_uniform_set(list, b.sets[0], 0);
	rd->compute_list_set_push_constant(list, &pc, sizeof(pc));
	rd->compute_list_dispatch_threads(list, cw, ch, 1);
	rd->compute_list_add_barrier(list);
	// Each blur pass is one dispatch, ping-pong between isr[0] and isr[1]; the ISR step writes where the
	// last pass then lands in isr[0], which the composite reads.
	const int passes = std::max(p_frame.blur_passes, 0);
	int current = passes & 1;
	rd->compute_list_bind_compute_pipeline(list, pass_pipelines[PASS_ISR_SSIL + variant]);
	rd->compute_list_bind_uniform_set(list, b.sets[1 + current], 0);
	rd->compute_list_set_push_constant(list, &pc, sizeof(pc));
	rd->compute_list_dispatch_threads(list, cw, ch, 1);
	last_pass_count = 2;
	for (int pass = 0; pass < passes; pass++) {
		rd->compute_list_add_barrier(list);
		pc.blur[0] = float(1 << std::min(pass, 8)); // A trous: 1, 2, 4, ... coarse pixels.
		rd->compute_list_bind_compute_pipeline(list, pass_pipelines[PASS_BLUR_SSIL + variant]);
		rd->compute_list_bind_uniform_set(list, b.sets[3 + 2 * variant + current], 0); // isr[current] -> the other.
		rd->compute_list_set_push_constant(list, &pc, sizeof(pc));
		rd->compute_list_dispatch_threads(list, cw, ch, 1);
		current = 1 - current;
		last_pass_count++;
	}
	rd->compute_list_end();

	CompositePushConstant cc;
	memset(&cc, 0, sizeof(cc));
	cc.proj_depth[0] = p.columns[2][2];
	cc.proj_depth[1] = p.columns[3][2];
	cc.proj_depth[2] = p.columns[2][3];
	cc.proj_depth[3] = p.columns[3][3];
	cc.sizes[0] = float(b.width);
	cc.sizes[1] = float(b.height);
	cc.sizes[2] = float(b.coarse_width);
	cc.sizes[3] = float(b.coarse_height);
	cc.terms[0] = p_frame.ssil ? p_settings.ssil_intensity : 0.0f;
	cc.terms[1] = p_settings.ssao_intensity;
	cc.terms[2] = p_settings.ssao_power;
	cc.terms[3] = p_settings.ssao_light_affect;
	cc.flags[0] = p_frame.ssao ? 1.0f : 0.0f;
	cc.flags[1] = BILATERAL_EPS_RELATIVE;
	cc.flags[2] = BILATERAL_MATCH_RELATIVE;

	RD::FramebufferFormatID format = rd->framebuffer_get_format(b.fb_composite);
	RID &pipeline = composite_pipelines[std::make_pair(format, variant)];
	if (!pipeline.is_valid()) {
		RD::PipelineRasterizationState raster;
		raster.cull_mode = RD::POLYGON_CULL_DISABLED;
		RD::PipelineDepthStencilState depth; // No depth attachment.
		RD::PipelineColorBlendState blend = RD::PipelineColorBlendState::create_disabled(1);
		// C' = src + C * src.a (ss_radiosity_composite.glsl); alpha keeps the target's.
		RD::PipelineColorBlendState::Attachment &a = blend.attachments[0];
		a.enable_blend = true;
		a.src_color_blend_factor = RD::BLEND_FACTOR_ONE;
		a.dst_color_blend_factor = RD::BLEND_FACTOR_SRC_ALPHA;
		a.src_alpha_blend_factor = RD::BLEND_FACTOR_ZERO;
		a.dst_alpha_blend_factor = RD::BLEND_FACTOR_ONE;
		pipeline = rd->render_pipeline_create(composite_shader.version_get_shader(variant), format, vertex_format, RD::RENDER_PRIMITIVE_TRIANGLES, raster, depth, blend);
		ERR_FAIL_COND_V_MSG(!pipeline.is_valid(), false, "SSRadiosityRD: the composite pipeline could not be created.");
	}
	RD::DrawListID dl = rd->draw_list_begin(b.fb_composite, RD::INITIAL_ACTION_LOAD, RD::INITIAL_ACTION_LOAD);
	rd->draw_list_bind_render_pipeline(dl, pipeline);
	rd->draw_list_bind_uniform_set(dl, b.sets[3 + 2 * COMPOSITE_MAX + variant], 0);
	rd->draw_list_set_push_constant(dl, &cc, sizeof(cc));
	rd->draw_list_draw(dl, false, 1, 3);
	rd->draw_list_end();
	last_pass_count++;
	rd->capture_timestamp(p_timestamp);
	return true;
}

RID SSRadiosityRD::get_isr_texture(RID p_owner) const {
	auto it = buffers.find(p_owner);
	return it == buffers.end() ? RID() : it->second.isr[0];
}

void SSRadiosityRD::release_owner(RID p_owner) {
	auto it = buffers.find(p_owner);
	if (it != buffers.end()) {
		_free_buffers(it->second);
		buffers.erase(it);
	}
}

void SSRadiosityRD::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	const bool live = rd && rd->is_initialized();
	for (auto &kv : buffers) {
		_free_buffers(kv.second);
	}
	buffers.clear();
	if (live) {
		for (RID &p : pass_pipelines) {
			if (p.is_valid()) {
				rd->free(p);
			}
		}
		for (auto &kv : composite_pipelines) {
			rd->free(kv.second);
		}
		if (sampler.is_valid()) {
			rd->free(sampler);
		}
	}
	for (RID &p : pass_pipelines) {
		p = RID();
	}
	composite_pipelines.clear();
	sampler = RID();
	pass_shader.clear();
	composite_shader.clear();
	shaders_ready = false;
	last_pass_count = 0;
}
