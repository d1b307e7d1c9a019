/**************************************************************************/
/*  directional_shadow_rd.cpp                                             */
/**************************************************************************/
/* See directional_shadow_rd.h: PSSM split fitting (Zhang et al. 2006,    */
/* "Parallel-Split Shadow Maps", with Godot's linear split offsets),      */
/* stable texel-snapped boxes (Valient 2008) and the depth passes.        */

#include "servers/rendering/renderer_rd/directional_shadow_rd.h"

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "core/math/vector4.h"
#include "servers/rendering/renderer_rd/effects/shadow_casters_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

namespace {

struct DepthPushConstant {
	float clip_from_model[16];
	uint32_t has_color[4]; // ALPHA_TEST variant only (the plain one's push constant ends before it).
};
static_assert(sizeof(DepthPushConstant) == 80, "Must match shaders/directional_shadow_depth.glsl.");
static constexpr uint32_t DEPTH_PUSH_CONSTANT_OPAQUE_SIZE = 64; // clip_from_model only.

uint32_t _split_count(RS::LightDirectionalShadowMode p_mode) {
	switch (p_mode) {
		case RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL:
			return 1;
		case RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_2_SPLITS:
			return 2;
		default:
			return 4;
	}
}

// Atlas rect (texels) of split p_split of the light in square p_region (x, y, side).
void _split_rect(uint32_t p_count, uint32_t p_split, const uint32_t p_region[3], uint32_t r_rect[4]) {
	const uint32_t s = p_region[2];
	if (p_count == 1) {
		r_rect[0] = p_region[0];
		r_rect[1] = p_region[1];
		r_rect[2] = s;
		r_rect[3] = s;
	} else if (p_count == 2) { // Godot: left and right halves, full height.
		r_rect[0] = p_region[0] + p_split * (s / 2);
		r_rect[1] = p_region[1];
		r_rect[2] = s / 2;
		r_rect[3] = s;
	} else {
		r_rect[0] = p_region[0] + (p_split & 1u) * (s / 2);
		r_rect[1] = p_region[1] + (p_split >> 1u) * (s / 2);
		r_rect[2] = s / 2;
		r_rect[3] = s / 2;
	}
}

RD::PipelineRasterizationState _raster_state() {
	RD::PipelineRasterizationState raster;
	raster.cull_mode = RD::POLYGON_CULL_DISABLED; // Both sides cast (single-sided planes too).
	// Pancaking: casters nearer the light than the box's near side flatten onto depth 0 per fragment.
	raster.enable_depth_clamp = true;
	return raster;
}

RD::PipelineDepthStencilState _depth_state() {
	RD::PipelineDepthStencilState depth;
	depth.enable_depth_test = true;
	depth.enable_depth_write = true;
	depth.depth_compare_operator = RD::COMPARE_OP_LESS;
	return depth;
}

} // namespace

/* Split math */

Transform3D DirectionalShadowRD::Split::get_clip_from_world() const {
	const Vector3 x = light_basis.get_column(0) / radius;
	const Vector3 y = light_basis.get_column(1) / radius;
	const float depth_scale = 1.0f / (z_max - z_min);
	const Vector3 z = light_basis.get_column(2) * -depth_scale; // Depth grows away from the light.
	Transform3D t;
	t.basis = Basis(x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z); // Rows.
	t.origin = -t.basis.xform(center) + Vector3(0, 0, z_max * depth_scale);
	return t;
}

uint32_t DirectionalShadowRD::compute_splits(const SplitSettings &p_settings, const Transform3D &p_world_from_light, const Transform3D &p_cam_transform, const Projection &p_cam_projection, Split r_splits[MAX_SPLITS], float p_z_near, float p_z_far) {
	const uint32_t count = _split_count(p_settings.mode);
	// Corners of the view frustum (view space) on the near and far planes; the edges are straight lines, so a
	// corner at any depth is a linear blend (perspective and orthogonal cameras alike).
	const Projection inv = p_cam_projection.inverse();
	Vector3 near_c[4], far_c[4];
	for (int i = 0; i < 4; i++) {
		const float x = (i & 1) ? 1.0f : -1.0f, y = (i & 2) ? 1.0f : -1.0f;
		const Vector4 a = inv.xform(Vector4(x, y, -1.0f, 1.0f));
		const Vector4 b = inv.xform(Vector4(x, y, 1.0f, 1.0f));
		near_c[i] = Vector3(a.x, a.y, a.z) / a.w;
		far_c[i] = Vector3(b.x, b.y, b.z) / b.w;
	}
	float z_near = -near_c[0].z, z_far = -far_c[0].z;
	if (p_cam_projection.columns[2].w != 0.0f && p_z_near > 0.0f && p_z_far > p_z_near) {
		// Perspective: the camera's own planes (a float projection and its inverse round them by ~1e-4
		// relative); the corners lie on rays from the eye.
		const float exact_near = p_z_near, exact_far = p_z_far;
		for (int i = 0; i < 4; i++) {
			near_c[i] *= exact_near / z_near;
			far_c[i] *= exact_far / z_far;
		}
		z_near = exact_near;
		z_far = exact_far;
	}
	float max_distance = p_settings.max_distance > 0.0f ? std::fmin(p_settings.max_distance, z_far) : z_far;
	max_distance = std::fmax(max_distance, z_near + 0.001f);
	const float range = max_distance - z_near;
	float d[MAX_SPLITS + 1];
	d[0] = z_near;
	for (uint32_t k = 1; k < count; k++) {
		const float offset = std::fmin(std::fmax(p_settings.split_offsets[k - 1], 0.0f), 1.0f);
		d[k] = std::fmax(d[k - 1], z_near + offset * range); // Monotonic even if the offsets are not.
	}
	d[count] = max_distance;

	const Basis light_basis = p_world_from_light.basis.orthonormalized();
	for (uint32_t k = 0; k < count; k++) {
		Split &s = r_splits[k];
		s = Split();
		s.range_begin = d[k];
		s.range_end = d[k + 1];
		s.light_basis = light_basis;
		Vector3 center;
		for (int c = 0; c < 8; c++) {
			const float depth = c < 4 ? d[k] : d[k + 1];
			const float t = (depth - z_near) / (z_far - z_near);
			const Vector3 v = near_c[c & 3] + (far_c[c & 3] - near_c[c & 3]) * t;
			s.corners[c] = p_cam_transform.xform(v);
			center += s.corners[c];
		}
		center /= 8.0f;
		float radius = 0.0f;
		for (int c = 0; c < 8; c++) {
			radius = std::fmax(radius, (s.corners[c] - center).length());
		}
		radius = std::fmax(radius, 1e-4f);
		const uint32_t w = std::max(p_settings.tile_width[k], 4u), h = std::max(p_settings.tile_height[k], 4u);
		// One texel of margin on each side for the snapping below (it moves the centre by under a texel).
		radius *= float(std::min(w, h)) / float(std::min(w, h) - 2);
		const float unit_x = 2.0f * radius / float(w), unit_y = 2.0f * radius / float(h);
		Vector3 cl = light_basis.xform_inv(center);
		cl.x = std::floor(cl.x / unit_x) * unit_x;
		cl.y = std::floor(cl.y / unit_y) * unit_y;
		s.center = light_basis.xform(cl);
		s.radius = radius;
		s.z_min = -radius;
		s.z_max = radius;
	}
	return count;
}

/* Resources */

bool DirectionalShadowRD::set_atlas_size(uint32_t p_size) {
	ERR_FAIL_COND_V_MSG(p_size < 256 || p_size > 16384 || (p_size & (p_size - 1)) != 0, false,
			vformat("DirectionalShadowRD: atlas size %u must be a power of two in 256..16384.", p_size));
	requested_size = p_size;
	return true;
}

uint32_t DirectionalShadowRD::get_requested_atlas_size() const {
	return requested_size ? requested_size : get_project_atlas_size();
}

uint32_t DirectionalShadowRD::get_project_atlas_size() {
	const int64_t v = GLOBAL_DEF(SETTING_ATLAS_SIZE, int64_t(DEFAULT_ATLAS_SIZE)).to_int();
	if (v < 256 || v > 16384 || (v & (v - 1)) != 0) {
		ERR_PRINT(vformat("%s must be a power of two in 256..16384; got %lld. Using %u.", SETTING_ATLAS_SIZE, (long long)v, DEFAULT_ATLAS_SIZE));
		return DEFAULT_ATLAS_SIZE;
	}
	return uint32_t(v);
}

bool DirectionalShadowRD::_ensure_resources() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !mesh_storage, false, "DirectionalShadowRD: no RenderingDevice or mesh storage.");
	const uint32_t size = get_requested_atlas_size();
	if (atlas.is_valid() && atlas_size != size) {
		rd->free(atlas); // Frees the framebuffer too; the scene sets notice the new texture.
		atlas = RID();
		framebuffer = RID();
	}
	if (!data_buffer.is_valid()) {
		data_buffer = rd->uniform_buffer_create(sizeof(ShadowBlock));
		ERR_FAIL_COND_V_MSG(!data_buffer.is_valid(), false, "DirectionalShadowRD: the shadow data buffer could not be created.");
		rd->set_resource_name(data_buffer, "Directional shadow data");
		RD::SamplerState cs; // Bilinear depth compare (receiver <= stored: lit).
		cs.mag_filter = RD::SAMPLER_FILTER_LINEAR;
		cs.min_filter = RD::SAMPLER_FILTER_LINEAR;
		cs.enable_compare = true;
		cs.compare_op = RD::COMPARE_OP_LESS_OR_EQUAL;
		compare_sampler = rd->sampler_create(cs);
		nearest_sampler = rd->sampler_create(RD::SamplerState());
		ERR_FAIL_COND_V_MSG(!compare_sampler.is_valid() || !nearest_sampler.is_valid(), false, "DirectionalShadowRD: samplers could not be created.");
		ERR_FAIL_COND_V_MSG(!depth_shader.initialize("directional_shadow_depth.glsl", ShadowCastersRD::get_variant_defines()), false, "DirectionalShadowRD: cannot load shaders/directional_shadow_depth.glsl.");
	}
	if (!atlas.is_valid()) {
		RD::TextureFormat tf;
		tf.format = ATLAS_FORMAT;
		tf.width = size;
		tf.height = size;
		tf.usage_bits = RD::TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT;
		atlas = rd->texture_create(tf);
		ERR_FAIL_COND_V_MSG(!atlas.is_valid(), false, vformat("DirectionalShadowRD: a %u x %u depth atlas could not be created.", size, size));
		rd->set_resource_name(atlas, "Directional shadow atlas");
		atlas_size = size;
		framebuffer = rd->framebuffer_create({ atlas });
		ERR_FAIL_COND_V_MSG(!framebuffer.is_valid(), false, "DirectionalShadowRD: the atlas framebuffer could not be created.");
	}
	if (!pipeline.is_valid()) {
		RID shader = depth_shader.version_get_shader(ShadowCastersRD::DEPTH_VARIANT_OPAQUE);
		ERR_FAIL_COND_V_MSG(!shader.is_valid(), false, "DirectionalShadowRD: the depth shader failed to compile: " + depth_shader.get_last_error());
		pipeline = rd->render_pipeline_create(shader, rd->framebuffer_get_format(framebuffer), mesh_storage->get_vertex_format(), RD::RENDER_PRIMITIVE_TRIANGLES, _raster_state(), _depth_state(), RD::PipelineColorBlendState::create_disabled(0));
		ERR_FAIL_COND_V_MSG(!pipeline.is_valid(), false, "DirectionalShadowRD: the depth pipeline could not be created.");
	}
	return true;
}

void DirectionalShadowRD::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized()) {
		for (RID *r : { &pipeline, &alpha_pipeline, &atlas, &data_buffer, &compare_sampler, &nearest_sampler }) {
			if (r->is_valid()) {
				rd->free(*r);
			}
		}
	}
	pipeline = RID();
	alpha_pipeline = RID();
	atlas = RID();
	framebuffer = RID();
	data_buffer = RID();
	compare_sampler = RID();
	nearest_sampler = RID();
	atlas_size = 0;
	depth_shader.clear();
	passes.clear();
	shadowed_count = 0;
}

/* Frame */

bool DirectionalShadowRD::prepare(const RenderSceneData &p_data, const Transform3D &p_view_from_world) {
	passes.clear();
	shadowed_count = 0;
	dropped_count = 0;
	ERR_FAIL_NULL_V(light_storage, false);
	const std::vector<uint32_t> &sources = light_storage->get_directional_light_source_indices();
	std::vector<uint32_t> shadowed; // GPU directional light indices with shadow_enabled.
	for (uint32_t i = 0; i < sources.size(); i++) {
		const RID light = p_data.directional_lights[sources[i]].light;
		if (!light_storage->light_has_shadow(light)) {
			continue;
		}
		if (shadowed.size() == MAX_SHADOWED_LIGHTS) {
			dropped_count++;
			continue;
		}
		shadowed.push_back(i);
	}
	if (dropped_count) {
		WARN_PRINT(vformat("DirectionalShadowRD: %d shadowed directional lights beyond the first %d of the view draw no shadow.", int(dropped_count), int(MAX_SHADOWED_LIGHTS)));
	}
	if (shadowed.empty()) {
		return true; // Nothing created, nothing recorded (fill_directional_light_data() set every index to -1).
	}
	ERR_FAIL_COND_V(!_ensure_resources(), false);

	// Every mesh that may cast: the visible geometry plus the area lights' off-screen casters (deduplicated).
	std::vector<const RenderSceneData::GeometryInstance *> candidates;
	std::set<uint64_t> seen;
	for (const std::vector<RenderSceneData::GeometryInstance> *list : { &p_data.geometry, &p_data.shadow_geometry }) {
		for (const RenderSceneData::GeometryInstance &g : *list) {
			// Without an instance RID (scenes built by hand) only the visible list counts.
			if (g.instance.is_valid() ? !seen.insert(g.instance.get_id()).second : list != &p_data.geometry) {
				continue;
			}
			if (g.cast_shadows == RS::SHADOW_CASTING_SETTING_OFF) {
				continue; // GeometryInstance3D::cast_shadow Off.
			}
			candidates.push_back(&g);
		}
	}

	const Transform3D world_from_view = p_view_from_world.affine_inverse();
	const float texel_uv = 1.0f / float(atlas_size);
	memset(&block, 0, sizeof(block));
	const uint32_t region_side = shadowed.size() == 1 ? atlas_size : atlas_size / 2;
	for (uint32_t si = 0; si < shadowed.size(); si++) {
		const uint32_t gpu_index = shadowed[si];
		const RenderSceneData::LightInstance &li = p_data.directional_lights[sources[gpu_index]];
		const RID light = li.light;
		const uint32_t region[3] = { (si & 1u) * region_side, (si >> 1u) * region_side, region_side };
		SplitSettings settings;
		settings.mode = light_storage->light_directional_get_shadow_mode(light);
		for (int k = 0; k < 3; k++) {
			settings.split_offsets[k] = light_storage->light_get_param(light, RS::LightParam(RS::LIGHT_PARAM_SHADOW_SPLIT_1_OFFSET + k));
		}
		settings.max_distance = light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE);
		const uint32_t count = _split_count(settings.mode);
		uint32_t rects[MAX_SPLITS][4];
		for (uint32_t k = 0; k < count; k++) {
			_split_rect(count, k, region, rects[k]);
			settings.tile_width[k] = rects[k][2];
			settings.tile_height[k] = rects[k][3];
		}
		Split splits[MAX_SPLITS];
		compute_splits(settings, li.transform, world_from_view, p_data.cam_projection, splits, p_data.z_near, p_data.z_far);
		const uint32_t caster_mask = light_storage->light_get_shadow_caster_mask(light);
		const float pancake = light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_PANCAKE_SIZE);

		ShadowData &sd = block.data[si];
		const float bias = light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_BIAS);
		const float normal_bias = light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS);
		const float shadow_blur = std::fmax(light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_BLUR), 0.0f);
		for (uint32_t k = 0; k < count; k++) {
			Split &s = splits[k];
			Pass pass;
			// Casters: boxes overlapping the split's box in light x, y and not wholly beyond its far side;
			// the box's near side moves up to the farthest caster towards the light.
			for (const RenderSceneData::GeometryInstance *g : candidates) {
				if ((g->layer_mask & caster_mask) == 0) {
					continue;
				}
				// The mesh's own bound (hand-built scenes leave GeometryInstance::aabb empty).
				const AABB aabb = mesh_storage->owns_mesh(g->mesh) ? g->transform.xform(mesh_storage->mesh_get_aabb(g->mesh)) : g->aabb;
				Vector3 lo(1e30f, 1e30f, 1e30f), hi(-1e30f, -1e30f, -1e30f);
				for (int c = 0; c < 8; c++) {
					const Vector3 p = s.to_light(aabb.get_endpoint(c));
					lo = lo.min(p);
					hi = hi.max(p);
				}
				if (hi.x < -s.radius || lo.x > s.radius || hi.y < -s.radius || lo.y > s.radius || hi.z < s.z_min) {
					continue;
				}
				s.z_max = std::fmax(s.z_max, hi.z);
				pass.casters.push_back(g);
			}
			// directional_shadow_pancake_size (Godot's): the box starts at most that far in front of the slice's
			// sphere; casters before it are flattened onto its near side (depth clamp), which keeps the depth
			// range, and so the bias in metres, independent of huge casters such as a ground plane. 0: off.
			if (pancake > 0.0f) {
				s.z_max = std::fmin(s.z_max, s.radius + pancake);
			}
			pass.clip_from_world = s.get_clip_from_world();
			memcpy(pass.rect, rects[k], sizeof(pass.rect));
			// Atlas uv of the split's rect; (x / r, y / r) in -1..1 maps onto it (Vulkan: clip y -1 is row 0).
			const float u0 = rects[k][0] * texel_uv, v0 = rects[k][1] * texel_uv;
			const float u1 = (rects[k][0] + rects[k][2]) * texel_uv, v1 = (rects[k][1] + rects[k][3]) * texel_uv;
			Transform3D uv_from_clip;
			uv_from_clip.basis = Basis(0.5f * (u1 - u0), 0, 0, 0, 0.5f * (v1 - v0), 0, 0, 0, 1);
			uv_from_clip.origin = Vector3(0.5f * (u0 + u1), 0.5f * (v0 + v1), 0.0f);
			Projection::from_transform(uv_from_clip * pass.clip_from_world * world_from_view).to_floats(sd.shadow_from_view[k]);
			sd.split_end[k] = s.range_end;
			// Godot 4's shadow_bias, in metres: the receiver moves towards the light by shadow_bias / 100 times the
			// split's nominal depth range (2 radius + directional_shadow_pancake_size, Godot's bias_scale) times
			// shadow_blur (RendererSceneCull::_light_instance_setup_directional_shadow, LightStorage). Stored in
			// this split's depth units (an orthographic depth is linear in metres).
			sd.bias[k] = get_bias_metres(bias, s.radius, pancake, shadow_blur) / std::fmax(s.z_max - s.z_min, 1e-6f);
			sd.normal_bias[k] = get_normal_bias_metres(normal_bias, s.radius, std::min(rects[k][2], rects[k][3]));
			sd.radius[k] = s.radius;
			sd.depth_range[k] = s.z_max - s.z_min;
			sd.uv_rect[k][0] = u0;
			sd.uv_rect[k][1] = v0;
			sd.uv_rect[k][2] = u1;
			sd.uv_rect[k][3] = v1;
			passes.push_back(std::move(pass));
		}
		const float max_distance = splits[count - 1].range_end;
		const float fade_start = std::fmin(std::fmax(light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_FADE_START), 0.0f), 0.999f);
		sd.params[0] = float(count);
		sd.params[1] = light_storage->light_directional_get_blend_splits(light) && count > 1 ? 1.0f : 0.0f;
		sd.params[2] = max_distance * fade_start;
		sd.params[3] = max_distance;
		const float angular_radius = Math::deg_to_rad(std::fmin(std::fmax(light_storage->light_get_param(light, RS::LIGHT_PARAM_SIZE), 0.0f), 90.0f)) * 0.5f;
		sd.params2[0] = std::tan(std::fmin(angular_radius, 1.5f));
		sd.params2[1] = std::fmin(std::fmax(light_storage->light_get_param(light, RS::LIGHT_PARAM_SHADOW_OPACITY), 0.0f), 1.0f);
		sd.params2[2] = shadow_blur;
		sd.params2[3] = texel_uv;
		light_storage->directional_light_set_shadow_index(gpu_index, int32_t(si));
	}
	shadowed_count = uint32_t(shadowed.size());
	light_storage->upload_directional_light_buffer();
	RenderingDevice::get_singleton()->buffer_update(data_buffer, 0, sizeof(ShadowBlock), &block);
	return true;
}

void DirectionalShadowRD::render_shadows(RID p_material_shader) {
	last_draw_count = 0;
	if (passes.empty() || !pipeline.is_valid()) {
		return;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	// What each caster casts (ShadowCastersRD: blended surfaces nothing, alpha-scissor ones through the
	// ALPHA_TEST variant with their material set), resolved before any draw list: the sets record buffer updates.
	ShadowCastersRD::FrameSurfaces casters;
	for (const Pass &pass : passes) {
		for (const RenderSceneData::GeometryInstance *g : pass.casters) {
			casters.add(g, mesh_storage, material_storage, p_material_shader);
		}
	}
	if (casters.any_alpha_test && !alpha_pipeline.is_valid()) {
		RID shader = depth_shader.version_get_shader(ShadowCastersRD::DEPTH_VARIANT_ALPHA_TEST);
		ERR_FAIL_COND_MSG(!shader.is_valid(), "DirectionalShadowRD: the depth shader (ALPHA_TEST) failed to compile: " + depth_shader.get_last_error());
		alpha_pipeline = rd->render_pipeline_create(shader, rd->framebuffer_get_format(framebuffer), mesh_storage->get_vertex_format(), RD::RENDER_PRIMITIVE_TRIANGLES, _raster_state(), _depth_state(), RD::PipelineColorBlendState::create_disabled(0));
		ERR_FAIL_COND_MSG(!alpha_pipeline.is_valid(), "DirectionalShadowRD: the depth pipeline (ALPHA_TEST) could not be created.");
	}
	for (const Pass &pass : passes) {
		const RD::Rect rect(int32_t(pass.rect[0]), int32_t(pass.rect[1]), pass.rect[2], pass.rect[3]);
		RD::DrawListID list = rd->draw_list_begin(framebuffer, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, {}, 1.0f, rect);
		rd->draw_list_bind_render_pipeline(list, pipeline);
		rd->draw_list_set_viewport(list, rect);
		bool alpha_bound = false;
		DepthPushConstant pc;
		memset(&pc, 0, sizeof(pc));
		for (const RenderSceneData::GeometryInstance *g : pass.casters) {
			Projection::from_transform(pass.clip_from_world * g->transform).to_floats(pc.clip_from_model);
			const std::pair<uint32_t, uint32_t> range = casters.get_range(g);
			for (uint32_t i = range.first; i < range.second; i++) {
				const ShadowCastersRD::Surface &surface = casters.surfaces[i];
				ShadowCastersRD::bind_surface(list, surface, pipeline, alpha_pipeline, alpha_bound);
				pc.has_color[0] = surface.gpu->has_colors ? 1u : 0u;
				ShadowCastersRD::draw_surface(list, surface, &pc, surface.alpha_test ? uint32_t(sizeof(pc)) : DEPTH_PUSH_CONSTANT_OPAQUE_SIZE);
				last_draw_count++;
			}
		}
		rd->draw_list_end();
	}
}
