/**************************************************************************/
/*  area_shadow_renderer.cpp                                              */
/**************************************************************************/

#include "servers/rendering/renderer_rd/effects/area_shadow_renderer.h"

#include "core/config/project_settings.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_adaptive.h"
#include "servers/rendering/renderer_rd/effects/shadow_casters_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <algorithm>
#include <cmath>
#include <cstring>

// Near plane of the octant views (m); casters closer than this to a sample point are clipped.
static constexpr float OCTANT_Z_NEAR = 0.002f;

void AreaShadowRendererRD::get_octant_axes(uint32_t p_quadrant, Vector3 &r_right, Vector3 &r_up, Vector3 &r_forward) {
	float sx = (p_quadrant & 1u) ? 1.0f : -1.0f;
	float sy = (p_quadrant & 2u) ? 1.0f : -1.0f;
	r_forward = Vector3(sx, sy, -1.0f) * 0.57735027f;
	r_right = Vector3(sy, -sx, 0.0f) * 0.70710678f;
	r_up = Vector3(sx, sy, 2.0f) * 0.40824829f;
}

uint32_t AreaShadowRendererRD::pack_map(uint32_t p_tile, const Vector2 &p_uv, uint32_t p_grid) {
	// One map (PCSS, or the centre map of an exhausted atlas): den 0, the light's centre standing for all of it.
	uint32_t den = p_grid >= 2 ? p_grid - 1 : 0;
	uint32_t un = den ? uint32_t(std::lround(p_uv.x * den)) : 0;
	uint32_t vn = den ? uint32_t(std::lround(p_uv.y * den)) : 0;
	return (p_tile & 0xFFFu) | ((un & 0xFu) << 12) | ((vn & 0xFu) << 16) | ((den & 0xFu) << 20);
}

uint32_t AreaShadowRendererRD::pack_tree_map(uint32_t p_tile, const Vector2 &p_uv, uint32_t p_cell) {
	// Points of a depth <= 3 tree lie on the 9 x 9 lattice (multiples of 1/8): one index of 81.
	uint32_t un = uint32_t(std::min(std::max(std::lround(p_uv.x * 8.0f), 0l), 8l));
	uint32_t vn = uint32_t(std::min(std::max(std::lround(p_uv.y * 8.0f), 0l), 8l));
	return (p_tile & 0xFFFu) | ((vn * 9u + un) << 12) | ((p_cell & 0xFFFu) << 19) | TREE_MAP_BIT;
}

bool AreaShadowRendererRD::get_surface_sample(const Vector2 &p_uv, uint32_t p_den, float p_half_length, float p_radius, Vector3 &r_position, Basis &r_light_from_sample) {
	// Equal-area capsule map (Archimedes: 2 pi r of area per unit of axial length, on the cylinder and on
	// the end spheres); doc/shadows.md "Sphere and tube lights".
	const float eps = 1e-4f;
	const bool pole = p_uv.y < eps || p_uv.y > 1.0f - eps;
	if (p_uv.x > 1.0f - eps || (pole && p_uv.x > eps)) {
		return false;
	}
	const float phi = 2.0f * float(Math::PI) * p_uv.x + 0.25f * float(Math::PI);
	const float h = (2.0f * p_uv.y - 1.0f) * (p_half_length + p_radius);
	const float c = std::min(std::max(h, -p_half_length), p_half_length);
	const float dz = h - c;
	const float rho = std::sqrt(std::max(p_radius * p_radius - dz * dz, 0.0f));
	const Vector3 n = (Vector3(dz, 0.0f, 0.0f) + Vector3(0.0f, std::sin(phi), -std::cos(phi)) * rho) / std::max(p_radius, 1e-6f);
	const Vector3 x_axis(0.0f, std::cos(phi), std::sin(phi));
	const Vector3 chord = pole || p_den == 0 ? Vector3() : Vector3(0.0f, std::sin(phi), -std::cos(phi)) * (rho * (1.0f - std::cos(float(Math::PI) / float(p_den))));
	r_position = Vector3(c, 0.0f, 0.0f) + n * p_radius - chord;
	r_light_from_sample = Basis::from_columns(x_axis, (-n).cross(x_axis), -n);
	return true;
}

RS::AreaShadowFilter AreaShadowRendererRD::get_project_filter() {
	const int v = int(GLOBAL_DEF(SETTING_FILTER, int(RS::AREA_SHADOW_FILTER_PENUMBRA)).to_int());
	if (v < 0 || v >= int(RS::AREA_SHADOW_FILTER_MAX)) {
		ERR_PRINT(vformat("%s must be 0 (PCF) or 1 (PENUMBRA); got %d. Using 1.", SETTING_FILTER, v));
		return RS::AREA_SHADOW_FILTER_PENUMBRA;
	}
	return RS::AreaShadowFilter(v);
}

bool AreaShadowRendererRD::initialize(RendererRD::LightStorage *p_light_storage, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage, uint32_t p_max_lights) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !rd->is_initialized(), false, "AreaShadowRendererRD::initialize() needs an initialized RenderingDevice.");
	ERR_FAIL_COND_V_MSG(!p_light_storage || !p_mesh_storage || !p_material_storage, false, "AreaShadowRendererRD needs the light, mesh and material storages.");
	if (initialized) {
		return true;
	}
	light_storage = p_light_storage;
	mesh_storage = p_mesh_storage;
	material_storage = p_material_storage;
	max_lights = std::max(p_max_lights, 1u);
	sample_filter = get_project_filter() == RS::AREA_SHADOW_FILTER_PENUMBRA;
	// Project settings for the default atlas (per-viewport sizes come from RS::area_shadow_atlas_set_size).
	// Invalid values are reported by set_atlas_size() and the built-in defaults stay.
	{
		int size = int(GLOBAL_DEF("rendering/lights_and_shadows/area_shadow_atlas_size", int(AreaShadowAtlas::DEFAULT_SIZE)).to_int());
		int subdivision = int(GLOBAL_DEF("rendering/lights_and_shadows/area_shadow_atlas_subdivision", int(AreaShadowAtlas::DEFAULT_SUBDIVISION)).to_int());
		if (uint32_t(size) != default_size || uint32_t(subdivision) != default_subdivision) {
			if (size <= 0 || subdivision <= 0 || !set_atlas_size(uint32_t(size), uint32_t(subdivision))) {
				ERR_PRINT(vformat("Project settings rendering/lights_and_shadows/area_shadow_atlas_size = %d, _subdivision = %d are invalid; using %u and %u.", size, subdivision, default_size, default_subdivision));
			}
		}
	}
	data_buffer = rd->storage_buffer_create(max_lights * sizeof(AreaShadowData));
	rd->set_resource_name(data_buffer, "AreaShadowRendererRD shadow data");

	RD::TextureFormat tf;
	tf.format = ATLAS_FORMAT;
	tf.width = 16;
	tf.height = 16;
	tf.usage_bits = RD::TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT;
	dummy_texture = rd->texture_create(tf);

	RD::SamplerState ss; // Nearest, clamp: texelFetch (PCSS blocker search and filter).
	sampler = rd->sampler_create(ss);
	RD::SamplerState cs; // Bilinear depth compare (receiver <= stored: lit): the PCF taps.
	cs.mag_filter = RD::SAMPLER_FILTER_LINEAR;
	cs.min_filter = RD::SAMPLER_FILTER_LINEAR;
	cs.enable_compare = true;
	cs.compare_op = RD::COMPARE_OP_LESS_OR_EQUAL;
	compare_sampler = rd->sampler_create(cs);
	ERR_FAIL_COND_V_MSG(!data_buffer.is_valid() || !dummy_texture.is_valid() || !sampler.is_valid() || !compare_sampler.is_valid(), false, "AreaShadowRendererRD: GPU resources could not be created.");
	ERR_FAIL_COND_V_MSG(!depth_shader.initialize("area_shadow_depth.glsl", ShadowCastersRD::get_variant_defines()), false, "AreaShadowRendererRD: cannot load shaders/area_shadow_depth.glsl.");
	initialized = true;
	return true;
}

void AreaShadowRendererRD::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized()) {
		for (auto &e : atlases) {
			_free_atlas_texture(e.second);
		}
		if (pipeline.is_valid()) {
			rd->free(pipeline);
		}
		if (alpha_pipeline.is_valid()) {
			rd->free(alpha_pipeline);
		}
		if (dummy_texture.is_valid()) {
			rd->free(dummy_texture);
		}
		if (sampler.is_valid()) {
			rd->free(sampler);
		}
		if (compare_sampler.is_valid()) {
			rd->free(compare_sampler);
		}
		if (data_buffer.is_valid()) {
			rd->free(data_buffer);
		}
	}
	atlases.clear();
	current = nullptr;
	pipeline = RID();
	alpha_pipeline = RID();
	dummy_texture = RID();
	sampler = RID();
	compare_sampler = RID();
	data_buffer = RID();
	depth_shader.clear();
	initialized = false;
}

void AreaShadowRendererRD::_free_atlas_texture(AtlasInstance &p_atlas) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (p_atlas.texture.is_valid() && rd && rd->is_initialized()) {
		rd->free(p_atlas.texture); // Frees the framebuffer too.
	}
	p_atlas.texture = RID();
	p_atlas.framebuffer = RID();
}

AreaShadowRendererRD::AtlasInstance &AreaShadowRendererRD::_get_atlas_instance(uint64_t p_owner) {
	auto it = atlases.find(p_owner);
	if (it != atlases.end()) {
		return it->second;
	}
	AtlasInstance &a = atlases[p_owner];
	a.atlas.configure(default_size, default_subdivision);
	return a;
}

void AreaShadowRendererRD::_check_adaptive_configuration(AtlasInstance &p_atlas) {
	if (p_atlas.adaptive && p_atlas.adaptive_configuration != p_atlas.atlas.get_configuration()) {
		// configure() took every tile back (tile_release ignores them): the trees start again from their roots.
		p_atlas.adaptive->release_lights_except({});
		p_atlas.adaptive_configuration = p_atlas.atlas.get_configuration();
	}
}

bool AreaShadowRendererRD::_ensure_adaptive(AtlasInstance &p_atlas) {
	if (p_atlas.adaptive) {
		return true;
	}
	std::unique_ptr<AreaShadowAdaptiveRD> adaptive(new AreaShadowAdaptiveRD);
	ERR_FAIL_COND_V_MSG(!adaptive->initialize(), false, "Area shadows: the ADAPTIVE driver could not be initialized; ADAPTIVE lights stay unshadowed.");
	if (adaptive_divisor != 0) {
		adaptive->set_reprojection_divisor(adaptive_divisor);
	}
	adaptive->set_skip_settled(adaptive_skip_settled);
	adaptive->set_same_depth_rule(adaptive_same_depth);
	p_atlas.adaptive_tiles.reset(new AreaShadowAdaptiveRD::AtlasTiles(&p_atlas.atlas));
	p_atlas.adaptive = std::move(adaptive);
	p_atlas.adaptive_configuration = p_atlas.atlas.get_configuration();
	return true;
}

void AreaShadowRendererRD::begin_frame(RID p_owner) {
	ERR_FAIL_COND_MSG(!initialized, "AreaShadowRendererRD::begin_frame: not initialized.");
	auto it = atlases.find(p_owner.get_id());
	if (it == atlases.end() || !it->second.adaptive) {
		return; // No ADAPTIVE light was ever drawn in this atlas: nothing to read.
	}
	_check_adaptive_configuration(it->second);
	it->second.adaptive->begin_frame();
}

uint32_t AreaShadowRendererRD::dispatch_adaptive(RID p_depth, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, const String &p_timestamp_prefix) {
	if (!current || !current->adaptive || current->adaptive_lights.empty() || !current->texture.is_valid()) {
		return 0;
	}
	AreaShadowAdaptiveRD::AtlasInfo info;
	info.texture = current->texture;
	info.size = current->atlas.get_size();
	info.subdivision = current->atlas.get_subdivision();
	return current->adaptive->dispatch(p_depth, p_width, p_height, p_clip_from_view, info, current->adaptive_lights, p_timestamp_prefix);
}

uint32_t AreaShadowRendererRD::light_get_shadow_map_count(RID p_light) const {
	if (!current) {
		return 0;
	}
	auto it = current->map_counts.find(p_light.get_id());
	return it != current->map_counts.end() ? it->second : 0;
}

uint32_t AreaShadowRendererRD::get_shadow_map_count() const {
	uint32_t total = 0;
	if (current) {
		for (const auto &e : current->map_counts) {
			total += e.second;
		}
	}
	return total;
}

bool AreaShadowRendererRD::is_reprojection_compiled() const {
	for (const auto &e : atlases) {
		if (e.second.adaptive && e.second.adaptive->is_reprojection_compiled()) {
			return true;
		}
	}
	return false;
}

bool AreaShadowRendererRD::set_adaptive_reprojection_divisor(uint32_t p_divisor) {
	ERR_FAIL_COND_V_MSG(p_divisor > 64, false, vformat("Area shadow reprojection divisor %u is invalid (expected 1..64, or 0 for the project setting).", p_divisor));
	adaptive_divisor = p_divisor;
	uint32_t value = p_divisor != 0 ? p_divisor : AreaShadowAdaptiveRD::get_project_reprojection_divisor();
	for (auto &e : atlases) {
		if (e.second.adaptive) {
			e.second.adaptive->set_reprojection_divisor(value);
		}
	}
	return true;
}

void AreaShadowRendererRD::set_adaptive_same_depth_rule(bool p_enable) {
	adaptive_same_depth = p_enable;
	for (auto &e : atlases) {
		if (e.second.adaptive) {
			e.second.adaptive->set_same_depth_rule(p_enable);
		}
	}
}

void AreaShadowRendererRD::set_adaptive_skip_settled(bool p_enable) {
	adaptive_skip_settled = p_enable;
	for (auto &e : atlases) {
		if (e.second.adaptive) {
			e.second.adaptive->set_skip_settled(p_enable);
		}
	}
}

bool AreaShadowRendererRD::set_atlas_size(uint32_t p_size, uint32_t p_subdivision) {
	AreaShadowAtlas probe; // Validates (and prints the error) without touching any atlas.
	if (!probe.configure(p_size, p_subdivision)) {
		return false;
	}
	default_size = p_size;
	default_subdivision = p_subdivision;
	for (auto &e : atlases) {
		AtlasInstance &a = e.second;
		if (a.custom_size) {
			continue;
		}
		uint32_t old = a.atlas.get_size();
		a.atlas.configure(p_size, p_subdivision);
		if (old != a.atlas.get_size()) {
			_free_atlas_texture(a);
		}
	}
	return true;
}

AreaShadowAtlas &AreaShadowRendererRD::get_atlas() {
	return current ? current->atlas : _get_atlas_instance(0).atlas;
}

const AreaShadowAtlas *AreaShadowRendererRD::get_owner_atlas(RID p_owner) const {
	auto it = atlases.find(p_owner.get_id());
	return it != atlases.end() ? &it->second.atlas : nullptr;
}

void AreaShadowRendererRD::release_owner(RID p_owner) {
	auto it = atlases.find(p_owner.get_id());
	if (it == atlases.end()) {
		return;
	}
	if (current == &it->second) {
		current = nullptr;
	}
	_free_atlas_texture(it->second);
	atlases.erase(it);
}

bool AreaShadowRendererRD::_ensure_atlas(AtlasInstance &p_atlas) {
	if (p_atlas.texture.is_valid()) {
		return true;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	RD::TextureFormat tf;
	tf.format = ATLAS_FORMAT;
	tf.width = p_atlas.atlas.get_size();
	tf.height = p_atlas.atlas.get_size();
	tf.usage_bits = RD::TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT;
	p_atlas.texture = rd->texture_create(tf);
	ERR_FAIL_COND_V_MSG(!p_atlas.texture.is_valid(), false, vformat("Area shadow atlas: a %u x %u depth texture could not be created.", tf.width, tf.height));
	rd->set_resource_name(p_atlas.texture, "Area shadow atlas");
	p_atlas.framebuffer = rd->framebuffer_create({ p_atlas.texture });
	RD::FramebufferFormatID format = rd->framebuffer_get_format(p_atlas.framebuffer);
	if (!pipeline.is_valid() || pipeline_format != format) {
		if (pipeline.is_valid()) {
			rd->free(pipeline);
		}
		if (alpha_pipeline.is_valid()) {
			rd->free(alpha_pipeline); // Made again, for the new format, by the next alpha-scissor caster.
			alpha_pipeline = RID();
		}
		RD::PipelineRasterizationState raster;
		raster.cull_mode = RD::POLYGON_CULL_DISABLED; // Both sides cast (single-sided planes too).
		RD::PipelineDepthStencilState depth;
		depth.enable_depth_test = true;
		depth.enable_depth_write = true;
		depth.depth_compare_operator = RD::COMPARE_OP_LESS;
		RID shader = depth_shader.version_get_shader(0);
		ERR_FAIL_COND_V_MSG(!shader.is_valid(), false, "Area shadow depth shader failed to compile: " + depth_shader.get_last_error());
		pipeline = rd->render_pipeline_create(shader, format, mesh_storage->get_vertex_format(), RD::RENDER_PRIMITIVE_TRIANGLES, raster, depth, RD::PipelineColorBlendState::create_disabled(0));
		pipeline_format = format;
		ERR_FAIL_COND_V_MSG(!pipeline.is_valid(), false, "Area shadow depth pipeline creation failed.");
	}
	return true;
}

static void _hash_bytes(uint64_t &r_hash, const void *p_data, size_t p_size) {
	const uint8_t *b = static_cast<const uint8_t *>(p_data);
	for (size_t i = 0; i < p_size; i++) {
		r_hash ^= b[i];
		r_hash *= 1099511628211ull; // FNV-1a.
	}
}

static void _hash_transform(uint64_t &r_hash, const Transform3D &p_t) {
	float f[16];
	Projection::from_transform(p_t).to_floats(f);
	_hash_bytes(r_hash, f, sizeof(f));
}

bool AreaShadowRendererRD::caster_in_near_layer(const Transform3D &p_world_from_light, const Vector3 &p_half_extent, float p_reach, const AABB &p_caster) {
	// The caster's box in light space (a box around the rotated box: never nearer than the caster is).
	const AABB local = p_world_from_light.affine_inverse().xform(p_caster);
	const Vector3 lo = local.position;
	const Vector3 hi = local.position + local.size;
	Vector3 gap;
	for (int a = 0; a < 3; a++) {
		gap[a] = std::max(std::max(lo[a] - p_half_extent[a], -p_half_extent[a] - hi[a]), 0.0f);
	}
	return gap.length() < near_layer_reach(p_reach);
}

void AreaShadowRendererRD::prepare(const RenderSceneData &p_data, const std::vector<uint32_t> &p_area_sources, const Transform3D &p_view_from_world, const Projection &p_clip_from_world, RID p_owner) {
	ERR_FAIL_COND_MSG(!initialized, "AreaShadowRendererRD::prepare: not initialized.");
	AtlasInstance &inst = _get_atlas_instance(p_owner.get_id());
	current = &inst;
	{
		// Per-viewport size (RS::area_shadow_atlas_set_size, validated there) or the renderer default.
		bool custom = p_data.area_shadow_atlas_size > 0 && p_data.area_shadow_atlas_subdivision > 0;
		uint32_t want_size = custom ? p_data.area_shadow_atlas_size : default_size;
		uint32_t want_sub = custom ? p_data.area_shadow_atlas_subdivision : default_subdivision;
		if (want_size != inst.atlas.get_size() || want_sub != inst.atlas.get_subdivision()) {
			uint32_t old = inst.atlas.get_size();
			if (inst.atlas.configure(want_size, want_sub) && old != inst.atlas.get_size()) {
				_free_atlas_texture(inst);
			}
		}
		inst.custom_size = custom;
	}
	_check_adaptive_configuration(inst);
	AreaShadowAtlas &atlas = inst.atlas;
	std::map<uint64_t, LightFrame> &frame_lights = inst.frame_lights;
	uint32_t count = std::min(uint32_t(p_area_sources.size()), max_lights);
	data.assign(count, AreaShadowData());
	for (AreaShadowData &d : data) {
		memset(&d, 0, sizeof(d));
	}
	frame_lights.clear();
	inst.map_counts.clear();
	inst.adaptive_draws.clear();
	inst.adaptive_lights.clear();
	std::vector<uint64_t> gpu_keys(count, 0);
	// ADAPTIVE lights of this frame: GPU index, key, content hash; handled after the grid lights' sharing.
	struct AdaptiveLight {
		uint32_t index = 0;
		uint64_t key = 0;
		uint64_t hash = 0;
		float importance = 0.0f; // AreaShadowAtlas::compute_importance(), as the grid lights'.
		std::vector<AreaShadowAtlas::Map> maps;
		std::vector<uint32_t> cells; // AreaShadowQuadtree::get_point_cells() of each map.
	};
	std::vector<AdaptiveLight> adaptive_lights;
	surface_fallbacks = 0;

	atlas.begin_frame();
	for (uint32_t i = 0; i < count; i++) {
		ERR_CONTINUE(p_area_sources[i] >= p_data.lights.size());
		const RenderSceneData::LightInstance &li = p_data.lights[p_area_sources[i]];
		if (!light_storage->owns_light(li.light) || !light_storage->light_has_shadow(li.light)) {
			continue;
		}
		// The sample points lie on a rectangle in the light's XY plane (thesis 6.1); a disk uses the square
		// of its area, sqrt(pi) / 2 = 0.886 of its diameters. A sphere or a tube emits all around: its points
		// lie on its surface (get_surface_sample()), each map in front of its own point; `size` (the extent
		// for the importance, the heuristic and the hash) is then the sphere's 0.886 square or the tube's
		// segment by its diameter.
		const Vector2 area_size = light_storage->light_area_get_size(li.light);
		Vector2 size = area_size;
		const RS::LightAreaShape shape = light_storage->light_area_get_shape(li.light);
		if (shape == RS::LIGHT_AREA_SHAPE_DISK) {
			size = size * 0.8862269f;
		} else if (shape == RS::LIGHT_AREA_SHAPE_SPHERE) {
			size = Vector2(size.x, size.x) * 0.8862269f;
		}
		if (!(size.x * size.y > 0.0f)) {
			continue; // A zero-size light emits nothing.
		}
		LightFrame lf;
		lf.key = li.instance.is_valid() ? li.instance.get_id() : li.light.get_id();
		lf.world_from_light = Transform3D(li.transform.basis.orthonormalized(), li.transform.origin);
		lf.size = size;
		lf.range = std::max(light_storage->light_get_param(li.light, RS::LIGHT_PARAM_RANGE), 1e-3f);
		lf.reach = lf.range + size.length();
		if (shape == RS::LIGHT_AREA_SHAPE_SPHERE || shape == RS::LIGHT_AREA_SHAPE_TUBE) {
			lf.all_around = true;
			lf.radius = 0.5f * (shape == RS::LIGHT_AREA_SHAPE_SPHERE ? area_size.x : area_size.y);
			lf.half_length = shape == RS::LIGHT_AREA_SHAPE_TUBE ? 0.5f * area_size.x : 0.0f;
			lf.reach = lf.range + 2.0f * (lf.half_length + lf.radius);
		}
		AABB box = lf.world_from_light.xform(light_storage->light_get_aabb(li.light));
		uint64_t hash = 1469598103934665603ull;
		_hash_transform(hash, lf.world_from_light);
		uint64_t version = light_storage->light_get_version(li.light);
		_hash_bytes(hash, &version, sizeof(version));
		_hash_bytes(hash, &size, sizeof(size));
		_hash_bytes(hash, &lf.range, sizeof(lf.range));
		// Casters: the scene cull's list for this light (every instance in its influence box, on screen or
		// not).
		for (uint32_t c : li.shadow_casters) {
			ERR_CONTINUE(c >= p_data.shadow_geometry.size());
			const RenderSceneData::GeometryInstance *gi = &p_data.shadow_geometry[c];
			if (!mesh_storage->owns_mesh(gi->mesh) || mesh_storage->mesh_get_surface_count(gi->mesh) == 0) {
				continue;
			}
			lf.casters.push_back(gi);
			uint64_t ids[2] = { gi->instance.get_id(), gi->mesh.get_id() };
			_hash_bytes(hash, ids, sizeof(ids));
			_hash_transform(hash, gi->transform);
			ShadowCastersRD::hash_materials(hash, *gi, mesh_storage, material_storage); // Blended: none; scissor: its cut.
		}
		RS::LightAreaShadowMode mode = light_storage->light_area_get_shadow_mode(li.light);
		if (lf.all_around && mode == RS::LIGHT_AREA_SHADOW_ADAPTIVE) {
			// The ADAPTIVE passes reproject points of the light's plane: a sphere or tube takes HEURISTIC's grid.
			mode = RS::LIGHT_AREA_SHADOW_HEURISTIC;
			surface_fallbacks++;
		}
		if (mode == RS::LIGHT_AREA_SHADOW_ADAPTIVE) {
			// Its quadtree takes single free tiles after the grid lights' sharing (end_frame()).
			AdaptiveLight al;
			al.index = i;
			al.key = lf.key;
			al.hash = hash;
			al.importance = AreaShadowAtlas::compute_importance(box, p_clip_from_world, size);
			adaptive_lights.push_back(al);
		} else {
			uint32_t grid = mode == RS::LIGHT_AREA_SHADOW_PCSS_BASELINE ? 1 : uint32_t(light_storage->light_area_get_shadow_grid(li.light));
			if (mode == RS::LIGHT_AREA_SHADOW_HEURISTIC) {
				std::vector<AABB> casters;
				for (const RenderSceneData::GeometryInstance *gi : lf.casters) {
					casters.push_back(gi->aabb);
				}
				grid = AreaShadowAdaptiveRD::compute_heuristic_grid(box, size, lf.range, p_data, lf.world_from_light, casters, sample_filter); // Thesis 6.5 estimate.
				grid = lf.all_around ? std::max(grid, MIN_SURFACE_GRID) : grid;
			} else if (lf.all_around && mode == RS::LIGHT_AREA_SHADOW_FIXED && grid < MIN_SURFACE_GRID) {
				grid = MIN_SURFACE_GRID;
				surface_fallbacks++;
			}
			_hash_bytes(hash, &grid, sizeof(grid));
			if (lf.all_around) {
				// Surface points depend on the grid level the atlas gives (their chord shift): a level change
				// redraws every map (the frame of the change still shows the kept ones at the old level).
				const uint32_t level = atlas.light_get_grid(lf.key);
				_hash_bytes(hash, &level, sizeof(level));
			}
			float importance = AreaShadowAtlas::compute_importance(box, p_clip_from_world, size);
			atlas.light_set(lf.key, grid, importance, hash);
			gpu_keys[i] = lf.key;
		}

		AreaShadowData &d = data[i];
		Projection::from_transform(lf.world_from_light.affine_inverse() * p_data.cam_transform).to_floats(d.light_from_view);
		d.half_size[0] = lf.all_around ? lf.half_length : size.x * 0.5f;
		d.half_size[1] = lf.all_around ? lf.radius : size.y * 0.5f;
		d.depth_scale = 1.0f / lf.reach;
		d.bias = light_storage->light_get_param(li.light, RS::LIGHT_PARAM_SHADOW_BIAS);
		d.normal_bias = light_storage->light_get_param(li.light, RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS);
		d.pcf_radius = std::min(std::max(light_storage->light_get_param(li.light, RS::LIGHT_PARAM_SHADOW_BLUR) * 2.0f, 0.0f), 8.0f);
		d.mode = uint32_t(mode) | (sample_filter ? FLAG_SAMPLE_FILTER : 0u) | (lf.all_around ? FLAG_ALL_AROUND : 0u);
		if (sample_filter && mode != RS::LIGHT_AREA_SHADOW_PCSS_BASELINE) {
			// The near-layer step only where a caster can be in the near layer (a window's bars in front of
			// the light): elsewhere its code is left out of the shader version.
			const Vector3 half_extent = lf.all_around ? Vector3(lf.half_length + lf.radius, lf.radius, lf.radius) : Vector3(area_size.x, area_size.y, 0.0f) * 0.5f;
			for (const RenderSceneData::GeometryInstance *gi : lf.casters) {
				if (caster_in_near_layer(lf.world_from_light, half_extent, lf.reach, gi->aabb)) {
					d.mode |= FLAG_NEAR_LAYER;
					break;
				}
			}
		}
		frame_lights[lf.key] = lf;
	}
	if (surface_fallbacks != surface_warned) {
		if (surface_fallbacks > 0) {
			WARN_PRINT(vformat("%u shadowed sphere or tube area lights asked for an area_shadow_grid below %u or for ADAPTIVE: their sample points lie on the surface, where coarser grids leave some receivers facing none, and the ADAPTIVE passes reproject points of a plane; they use %u x %u (FIXED) or HEURISTIC's grid (at least %u x %u).", surface_fallbacks, MIN_SURFACE_GRID, MIN_SURFACE_GRID, MIN_SURFACE_GRID, MIN_SURFACE_GRID, MIN_SURFACE_GRID));
			surface_warnings++;
		}
		surface_warned = surface_fallbacks;
	}
	// Trees of lights that are gone or no longer ADAPTIVE give their tiles back before the grid lights share.
	if (inst.adaptive) {
		std::vector<uint64_t> seen;
		for (const AdaptiveLight &al : adaptive_lights) {
			seen.push_back(al.key);
		}
		inst.adaptive->release_lights_except(seen);
	}
	atlas.end_frame();
	// ADAPTIVE: the trees (free tiles only, never evicting grid lights), their dirty points as draws after
	// the atlas' own (same per-frame cap), the drawn points and their cells for the shader.
	if (!adaptive_lights.empty() && _ensure_adaptive(inst)) {
		// What every ADAPTIVE light's tests see besides the light itself: the camera, the receivers (all
		// geometry of the view) and the atlas.
		uint64_t view_hash = 1469598103934665603ull;
		_hash_transform(view_hash, p_data.cam_transform);
		{
			float f[16];
			p_data.cam_projection.to_floats(f);
			_hash_bytes(view_hash, f, sizeof(f));
			uint32_t view[2] = { p_data.viewport_width > 0 ? uint32_t(p_data.viewport_width) : 0u, p_data.viewport_height > 0 ? uint32_t(p_data.viewport_height) : 0u };
			_hash_bytes(view_hash, view, sizeof(view));
			uint64_t configuration = atlas.get_configuration();
			_hash_bytes(view_hash, &configuration, sizeof(configuration));
		}
		for (const RenderSceneData::GeometryInstance &gi : p_data.geometry) {
			uint64_t ids[2] = { gi.instance.get_id(), gi.mesh.get_id() };
			_hash_bytes(view_hash, ids, sizeof(ids));
			_hash_transform(view_hash, gi.transform);
		}
		// Fair sharing between the trees (thesis 6.5, as the grid lights share the atlas): lights without
		// a tree are served first, and each tree holds at most its importance share of the tiles the
		// trees may use (their own plus the free ones; at least the four of a root quad); while a light
		// still waits, the others keep four free tiles for it.
		uint32_t waiting = 0;
		float importance_sum = 0.0f;
		for (AdaptiveLight &al : adaptive_lights) {
			waiting += inst.adaptive->light_get_tree_or_null(al.key) ? 0 : 1;
			importance_sum += std::max(al.importance, 0.0f);
		}
		std::stable_sort(adaptive_lights.begin(), adaptive_lights.end(), [&](const AdaptiveLight &p_a, const AdaptiveLight &p_b) {
			const bool a_new = !inst.adaptive->light_get_tree_or_null(p_a.key), b_new = !inst.adaptive->light_get_tree_or_null(p_b.key);
			return a_new != b_new ? a_new : p_a.importance > p_b.importance;
		});
		const uint32_t pool = atlas.get_free_tile_count() + atlas.get_external_tile_count();
		uint32_t cap = atlas.get_max_draws_per_frame();
		for (AdaptiveLight &al : adaptive_lights) {
			waiting -= inst.adaptive->light_get_tree_or_null(al.key) ? 0 : 1;
			const float share = importance_sum > 0.0f ? std::max(al.importance, 0.0f) / importance_sum : 1.0f / float(adaptive_lights.size());
			const uint32_t tile_cap = uint32_t(float(pool) * share);
			inst.adaptive->light_set_tile_cap(al.key, tile_cap); // May evict: shrinks a tree far over it.
			uint32_t used = uint32_t(atlas.get_draws().size() + inst.adaptive_draws.size());
			uint32_t budget = used < cap ? cap - used : 0;
			if (!inst.adaptive->light_prepare(al.key, inst.adaptive_tiles.get(), al.hash, budget, inst.adaptive_draws, al.maps, &al.cells)) {
				if (!inst.adaptive_warned) {
					WARN_PRINT(vformat("Area shadow atlas (%u x %u tiles): no four free tiles for an ADAPTIVE light; it stays unshadowed until tiles free up.", atlas.get_subdivision(), atlas.get_subdivision()));
					inst.adaptive_warned = true;
				}
				continue;
			}
			gpu_keys[al.index] = al.key;
			const LightFrame &lf = frame_lights[al.key];
			const RenderSceneData::LightInstance &li = p_data.lights[p_area_sources[al.index]];
			AreaShadowAdaptiveRD::LightInput in;
			in.key = al.key;
			in.light_from_view = lf.world_from_light.affine_inverse() * p_data.cam_transform;
			in.size = lf.size;
			in.depth_scale = 1.0f / (lf.range + lf.size.length());
			in.bias = light_storage->light_get_param(li.light, RS::LIGHT_PARAM_SHADOW_BIAS);
			// A split needs up to five new points (within the light's cap, which light_prepare() applied).
			in.can_grow = atlas.get_free_tile_count() >= 5 + 4 * waiting;
			in.box = light_storage->light_get_aabb(li.light); // Its tests cover the box's screen rectangle.
			uint64_t state = view_hash;
			_hash_bytes(state, &al.hash, sizeof(al.hash));
			_hash_bytes(state, &in.bias, sizeof(in.bias));
			_hash_bytes(state, &in.can_grow, sizeof(in.can_grow));
			_hash_bytes(state, &tile_cap, sizeof(tile_cap)); // A new share: test again (grow into it, or re-find after an eviction).
			in.state_hash = state != 0 ? state : 1;
			inst.adaptive_lights.push_back(in);
		}
	}
	if (!frame_lights.empty()) {
		_ensure_atlas(inst);
	}
	for (const AdaptiveLight &al : adaptive_lights) {
		if (gpu_keys[al.index] == 0 || !inst.texture.is_valid()) {
			continue;
		}
		AreaShadowData &d = data[al.index];
		d.atlas_subdivision = atlas.get_subdivision();
		d.atlas_texel = 1.0f / float(atlas.get_size());
		d.quadrant_size = atlas.get_tile_size() / 2;
		d.tile_size = atlas.get_tile_size();
		uint32_t n = 0;
		for (size_t m = 0; m < al.maps.size() && n < MAX_MAPS_GPU; m++) {
			// Each point with its cell (weight and filter box) from the tree; without tree weights (a
			// measurement knob), as a point of the 9 x 9 grid (trapezoid weight, 1/8 cell).
			d.maps[n++] = adaptive_tree_weights ? pack_tree_map(al.maps[m].tile, al.maps[m].uv, al.cells[m]) : pack_map(al.maps[m].tile, al.maps[m].uv, AreaShadowAtlas::MAX_GRID);
		}
		d.map_count = n;
		inst.map_counts[al.key] = n;
		gpu_keys[al.index] = 0; // Packed.
	}
	for (uint32_t i = 0; i < count; i++) {
		if (gpu_keys[i] == 0 || !inst.texture.is_valid()) {
			continue;
		}
		AreaShadowData &d = data[i];
		uint32_t grid = atlas.light_get_grid(gpu_keys[i]);
		d.atlas_subdivision = atlas.get_subdivision();
		d.atlas_texel = 1.0f / float(atlas.get_size());
		d.quadrant_size = atlas.get_tile_size() / 2;
		d.tile_size = atlas.get_tile_size();
		uint32_t n = 0;
		for (const AreaShadowAtlas::Map &m : atlas.light_get_maps(gpu_keys[i])) {
			if (m.valid && n < MAX_MAPS_GPU) {
				d.maps[n++] = pack_map(m.tile, m.uv, grid);
			}
		}
		d.map_count = n;
		inst.map_counts[gpu_keys[i]] = n;
	}
	if (count > 0) {
		RenderingDevice::get_singleton()->buffer_update(data_buffer, 0, count * sizeof(AreaShadowData), data.data());
	}
}

void AreaShadowRendererRD::render_shadows(const RenderSceneData &p_data, RID p_material_shader) {
	(void)p_data; // The casters were resolved by prepare() (pointers into p_data).
	last_draw_count = 0;
	if (!current) {
		return;
	}
	const AreaShadowAtlas &atlas = current->atlas;
	std::vector<AreaShadowAtlas::DrawRequest> draws = atlas.get_draws();
	draws.insert(draws.end(), current->adaptive_draws.begin(), current->adaptive_draws.end()); // ADAPTIVE tree points.
	if (draws.empty() || !current->texture.is_valid() || !pipeline.is_valid()) {
		return;
	}
	const std::map<uint64_t, LightFrame> &frame_lights = current->frame_lights;
	RenderingDevice *rd = RenderingDevice::get_singleton();
	// What each drawn caster casts (ShadowCastersRD: blended surfaces nothing, alpha-scissor ones through the
	// ALPHA_TEST variant with their material set), resolved before any draw list: the sets record buffer updates.
	ShadowCastersRD::FrameSurfaces casters;
	for (const AreaShadowAtlas::DrawRequest &req : draws) {
		auto it = frame_lights.find(req.light);
		if (it == frame_lights.end()) {
			continue;
		}
		for (const RenderSceneData::GeometryInstance *caster : it->second.casters) {
			casters.add(caster, mesh_storage, material_storage, p_material_shader);
		}
	}
	if (casters.any_alpha_test && !alpha_pipeline.is_valid()) {
		RID shader = depth_shader.version_get_shader(ShadowCastersRD::DEPTH_VARIANT_ALPHA_TEST);
		ERR_FAIL_COND_MSG(!shader.is_valid(), "Area shadow depth shader (ALPHA_TEST) failed to compile: " + depth_shader.get_last_error());
		RD::PipelineRasterizationState raster;
		raster.cull_mode = RD::POLYGON_CULL_DISABLED; // As the opaque pipeline (_ensure_atlas()).
		RD::PipelineDepthStencilState depth;
		depth.enable_depth_test = true;
		depth.enable_depth_write = true;
		depth.depth_compare_operator = RD::COMPARE_OP_LESS;
		alpha_pipeline = rd->render_pipeline_create(shader, pipeline_format, mesh_storage->get_vertex_format(), RD::RENDER_PRIMITIVE_TRIANGLES, raster, depth, RD::PipelineColorBlendState::create_disabled(0));
		ERR_FAIL_COND_MSG(!alpha_pipeline.is_valid(), "Area shadow depth pipeline (ALPHA_TEST) creation failed.");
	}
	for (const AreaShadowAtlas::DrawRequest &req : draws) {
		auto it = frame_lights.find(req.light);
		ERR_CONTINUE(it == frame_lights.end());
		const LightFrame &lf = it->second;
		AreaShadowAtlas::TileRect r = AreaShadowAtlas::get_tile_rect(req.tile, atlas.get_size(), atlas.get_subdivision());
		uint32_t q = r.size / 2;
		Vector3 sample_local((req.uv.x - 0.5f) * lf.size.x, (req.uv.y - 0.5f) * lf.size.y, 0.0f);
		Basis light_from_sample; // The light's own frame: rectangles, disks, one centre map.
		const uint32_t grid = lf.all_around ? atlas.light_get_grid(req.light) : 0;
		if (grid >= 2 && !get_surface_sample(req.uv, grid - 1, lf.half_length, lf.radius, sample_local, light_from_sample)) {
			continue; // A repeated point of the surface grid (seam, pole): the shader skips its map.
		}
		Vector3 sample_world = lf.world_from_light.xform(sample_local);
		DepthPushConstant pc;
		pc.params[0] = 1.0f / lf.reach;
		pc.params[1] = OCTANT_Z_NEAR;
		pc.params[2] = lf.reach * 2.0f;
		pc.params[3] = 0.0f;
		RD::DrawListID list = rd->draw_list_begin(current->framebuffer, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, {}, 1.0f, RD::Rect(int32_t(r.x), int32_t(r.y), r.size, r.size));
		rd->draw_list_bind_render_pipeline(list, pipeline);
		bool alpha_bound = false;
		for (uint32_t quadrant = 0; quadrant < 4; quadrant++) {
			rd->draw_list_set_viewport(list, RD::Rect(int32_t(r.x + (quadrant & 1u) * q), int32_t(r.y + (quadrant >> 1u) * q), q, q));
			Vector3 right, up, forward;
			get_octant_axes(quadrant, right, up, forward);
			const Basis &lb = lf.world_from_light.basis;
			Transform3D octant_from_world;
			Vector3 rw = lb.xform(light_from_sample.xform(right)), uw = lb.xform(light_from_sample.xform(up)), fw = lb.xform(light_from_sample.xform(forward));
			octant_from_world.basis = Basis(rw.x, rw.y, rw.z, uw.x, uw.y, uw.z, fw.x, fw.y, fw.z); // Rows.
			octant_from_world.origin = -octant_from_world.basis.xform(sample_world);
			for (const RenderSceneData::GeometryInstance *caster : lf.casters) {
				const RenderSceneData::GeometryInstance &gi = *caster;
				Projection::from_transform(octant_from_world * gi.transform).to_floats(pc.octant_view_from_model);
				const std::pair<uint32_t, uint32_t> range = casters.get_range(caster);
				for (uint32_t i = range.first; i < range.second; i++) {
					const ShadowCastersRD::Surface &surface = casters.surfaces[i];
					ShadowCastersRD::bind_surface(list, surface, pipeline, alpha_pipeline, alpha_bound);
					pc.params[3] = surface.alpha_test && surface.gpu->has_colors ? 1.0f : 0.0f;
					ShadowCastersRD::draw_surface(list, surface, &pc, sizeof(pc));
				}
			}
		}
		rd->draw_list_end();
		last_draw_count++;
	}
	total_draw_count += last_draw_count;
}
