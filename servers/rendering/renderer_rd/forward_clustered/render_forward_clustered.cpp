/**************************************************************************/
/*  render_forward_clustered.cpp                                          */
/**************************************************************************/

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/error/error_macros.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>

// IEEE 754 binary16 -> binary32 (readback of the RGBA16F target).
static float _half_to_float(uint16_t p_h) {
	uint32_t sign = uint32_t(p_h & 0x8000) << 16;
	uint32_t exponent = (p_h >> 10) & 0x1F;
	uint32_t mantissa = p_h & 0x3FF;
	uint32_t bits;
	if (exponent == 0) {
		if (mantissa == 0) {
			bits = sign;
		} else { // Subnormal: renormalise.
			exponent = 127 - 15 + 1;
			while ((mantissa & 0x400) == 0) {
				mantissa <<= 1;
				exponent--;
			}
			mantissa &= 0x3FF;
			bits = sign | (exponent << 23) | (mantissa << 13);
		}
	} else if (exponent == 31) {
		bits = sign | 0x7F800000 | (mantissa << 13); // Inf / NaN.
	} else {
		bits = sign | ((exponent + 127 - 15) << 23) | (mantissa << 13);
	}
	float f;
	memcpy(&f, &bits, sizeof(f));
	return f;
}

static void _transform_to_floats(const Transform3D &p_t, float *r_out) {
	Projection::from_transform(p_t).to_floats(r_out);
}

RenderForwardClustered::RenderForwardClustered(RendererRD::LightStorage *p_light_storage, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage) :
		light_storage(p_light_storage), mesh_storage(p_mesh_storage), material_storage(p_material_storage) {
}

RenderForwardClustered::~RenderForwardClustered() {
	finalize();
}

bool RenderForwardClustered::initialize(uint32_t p_max_lights_per_type) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !rd->is_initialized(), false, "RenderForwardClustered::initialize() needs an initialized RenderingDevice.");
	ERR_FAIL_COND_V_MSG(!light_storage || !mesh_storage || !material_storage, false, "RenderForwardClustered needs light, mesh and material storages.");
	if (initialized) {
		return true;
	}
	// Indexed by SceneShaderVariant. The brute-force and debug variants are compiled on first use only.
	std::vector<String> variants = { "", "#define MODE_DEPTH\n", "#define USE_AREA_LIGHTS\n", "#define MODE_FORCE_ALL_LIGHTS\n",
		"#define USE_AREA_LIGHTS\n#define MODE_FORCE_ALL_LIGHTS\n", "#define MODE_DEBUG_CLUSTER\n", "#define USE_AREA_LIGHTS\n#define MODE_DEBUG_CLUSTER\n" };
	static_assert(SCENE_SHADER_MAX == 7, "One variant define per SceneShaderVariant.");
	ERR_FAIL_COND_V_MSG(!scene_shader.initialize("forward_clustered/scene_forward_clustered.glsl", variants), false,
			"RenderForwardClustered: cannot load shaders/forward_clustered/scene_forward_clustered.glsl.");
	// The area-light variant is compiled on first use (render_scene), never for scenes without area lights.
	for (int v = 0; v < SCENE_SHADER_COLOR_AREA; v++) {
		ERR_FAIL_COND_V_MSG(!scene_shader.version_get_shader(v).is_valid(), false,
				vformat("RenderForwardClustered: scene shader variant %d failed to compile: %s", v, scene_shader.get_last_error().c_str()));
	}
	ERR_FAIL_COND_V_MSG(!cluster_builder.initialize(p_max_lights_per_type), false, "RenderForwardClustered: the cluster builder failed to initialize.");
	if (!light_storage->is_gpu_initialized()) {
		ERR_FAIL_COND_V_MSG(!light_storage->initialize_gpu(cluster_builder.get_max_elements()), false, "RenderForwardClustered: light buffers failed.");
	}
	ERR_FAIL_COND_V_MSG(light_storage->get_max_lights() > cluster_builder.get_max_elements(), false, "RenderForwardClustered: the light storage holds more lights per type than the cluster builder.");
	if (!material_storage->get_sampler().is_valid()) {
		ERR_FAIL_COND_V_MSG(!material_storage->initialize_gpu(), false, "RenderForwardClustered: material storage GPU setup failed.");
	}
	light_storage->set_area_texture_source(material_storage); // area_texture texels (the atlas copies them on change).
	ERR_FAIL_COND_V_MSG(!area_shadows.initialize(light_storage, mesh_storage, material_storage, light_storage->get_max_lights()), false, "RenderForwardClustered: area shadows failed to initialize.");
	directional_shadows.initialize(light_storage, mesh_storage, material_storage); // GPU resources on the first shadowed sun.
	scene_ubo = rd->uniform_buffer_create(sizeof(SceneDataUBO));
	rd->set_resource_name(scene_ubo, "RenderForwardClustered scene data");
	initialized = true;
	return true;
}

void RenderForwardClustered::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	bool live = rd && rd->is_initialized();
	for (RID rid : render_target_owner.get_owned_list()) {
		_free_render_target(render_target_owner.get_or_null(rid));
		render_target_owner.free(rid);
	}
	if (live) {
		for (auto &kv : pipelines) {
			rd->free(kv.second);
		}
		if (scene_ubo.is_valid()) {
			rd->free(scene_ubo); // Frees the scene sets too.
		}
	}
	pipelines.clear();
	scene_ubo = RID();
	scene_set_color = RID();
	scene_set_depth = RID();
	scene_set_cluster_buffer = RID();
	area_versions.clear(); // Their shaders are freed by scene_shader.clear(), their sets with scene_ubo.
	compiled_area_method_mask = 0;
	compiled_area_shapes = false;
	compiled_feature_mask = 0;
	ltc_lut.finalize();
	sky.finalize();
	ss_radiosity.finalize();
	area_shadows.finalize();
	directional_shadows.finalize();
	cluster_builder.finalize();
	scene_shader.clear();
	initialized = false;
}

/* Render targets */

RID RenderForwardClustered::render_target_create(int p_width, int p_height) {
	ERR_FAIL_COND_V_MSG(!initialized, RID(), "render_target_create: the renderer is not initialized.");
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0 || p_width > 16384 || p_height > 16384, RID(),
			vformat("render_target_create: size %dx%d is invalid (expected 1..16384 per side).", p_width, p_height));
	RenderingDevice *rd = RenderingDevice::get_singleton();
	RenderTarget rt;
	rt.width = p_width;
	rt.height = p_height;

	RD::TextureFormat tf;
	tf.format = HDR_FORMAT;
	tf.width = p_width;
	tf.height = p_height;
	tf.usage_bits = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	rt.color = rd->texture_create(tf);
	tf.format = DEPTH_FORMAT;
	tf.usage_bits = RD::TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT;
	rt.depth = rd->texture_create(tf);
	ERR_FAIL_COND_V_MSG(!rt.color.is_valid() || !rt.depth.is_valid(), RID(), "render_target_create: texture creation failed.");
	rt.fb_depth = rd->framebuffer_create({ rt.depth });
	rt.fb_color = rd->framebuffer_create({ rt.color, rt.depth });
	rd->set_resource_name(rt.color, "RenderForwardClustered HDR colour");
	return render_target_owner.make_rid(rt);
}

void RenderForwardClustered::_free_render_target(RenderTarget *p_rt) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (!p_rt || !rd || !rd->is_initialized()) {
		return;
	}
	// Freeing the textures frees the framebuffers made from them.
	if (p_rt->color.is_valid()) {
		rd->free(p_rt->color);
	}
	if (p_rt->depth.is_valid()) {
		rd->free(p_rt->depth);
	}
}

bool RenderForwardClustered::render_target_free(RID p_rid) {
	RenderTarget *rt = render_target_owner.get_or_null(p_rid);
	if (!rt) {
		return false;
	}
	ss_radiosity.release_owner(p_rid); // Its SSIL/SSAO buffers (before the colour they use goes).
	_free_render_target(rt);
	render_target_owner.free(p_rid);
	area_shadows.release_owner(p_rid); // Its area shadow atlas (one per render target, i.e. viewport).
	return true;
}

RID RenderForwardClustered::render_target_get_color_texture(RID p_render_target) const {
	const RenderTarget *rt = render_target_owner.get_or_null(p_render_target);
	ERR_FAIL_NULL_V_MSG(rt, RID(), "render_target_get_color_texture: invalid render target RID.");
	return rt->color;
}

std::vector<float> RenderForwardClustered::render_target_get_data(RID p_render_target) {
	const RenderTarget *rt = render_target_owner.get_or_null(p_render_target);
	ERR_FAIL_NULL_V_MSG(rt, std::vector<float>(), "render_target_get_data: invalid render target RID.");
	RenderingDevice *rd = RenderingDevice::get_singleton();
	std::vector<uint8_t> bytes = rd->texture_get_data(rt->color);
	size_t texels = size_t(rt->width) * rt->height * 4;
	ERR_FAIL_COND_V_MSG(bytes.size() != texels * 2, std::vector<float>(), "render_target_get_data: unexpected readback size.");
	std::vector<float> out(texels);
	const uint16_t *h = reinterpret_cast<const uint16_t *>(bytes.data());
	for (size_t i = 0; i < texels; i++) {
		out[i] = _half_to_float(h[i]);
	}
	return out;
}

/* Pipelines and sets */

String RenderForwardClustered::get_area_method_defines(uint32_t p_area_methods) {
	static const char *names[RS::LIGHT_AREA_SHADING_MAX] = { "AREA_METHOD_LTC", "AREA_METHOD_LTC_POLYNOMIAL", "AREA_METHOD_MRP", "AREA_METHOD_STOCHASTIC", nullptr, "AREA_METHOD_LTC_2LOBE" };
	String defines;
	for (int m = 0; m < RS::LIGHT_AREA_SHADING_MAX; m++) {
		if (((p_area_methods >> m) & 1u) && names[m]) {
			defines += String("#define ") + names[m] + "\n";
		}
	}
	if (p_area_methods & AREA_VERSION_SHADOWS_PCF) {
		defines += "#define AREA_SHADOWS_PCF\n";
	}
	if (p_area_methods & AREA_VERSION_SHADOWS_PCSS) {
		defines += "#define AREA_SHADOWS_PCSS\n";
	}
	if (p_area_methods & AREA_VERSION_SHADOWS_NEAR) {
		defines += "#define AREA_SHADOWS_NEAR_LAYER\n";
	}
	if (p_area_methods & AREA_VERSION_SHADOWS_TREE) {
		defines += "#define AREA_SHADOWS_TREE\n";
	}
	if (p_area_methods & AREA_VERSION_SHAPES) {
		defines += "#define USE_AREA_SHAPES\n";
	}
	if (p_area_methods & AREA_VERSION_TEXTURE) {
		defines += "#define AREA_LIGHT_TEXTURE\n";
	}
	return defines;
}

std::vector<std::pair<String, String>> RenderForwardClustered::get_debug_scene_shader_sources() const {
	std::vector<std::pair<String, String>> sources;
	sources.push_back({ "base.frag", scene_shader.get_stage_source(RenderingDevice::SHADER_STAGE_FRAGMENT, SCENE_SHADER_COLOR) });
	static const char *names[] = { "LTC", "LTC_POLYNOMIAL", "MRP", "STOCHASTIC", "AUTO", "LTC_2LOBE" };
	for (int m = 0; m < RS::LIGHT_AREA_SHADING_MAX; m++) {
		if (m == RS::LIGHT_AREA_SHADING_AUTO) {
			continue; // A policy, not shader code: it picks one of the others.
		}
		const String name = m < int(std::size(names)) ? String(names[m]) : vformat("method_%d", m);
		sources.push_back({ "area_" + name + ".frag", scene_shader.get_stage_source(RenderingDevice::SHADER_STAGE_FRAGMENT, SCENE_SHADER_COLOR_AREA, get_area_method_defines(1u << m)) });
	}
	for (int m = 0; m < RS::LIGHT_AREA_SHADING_MAX; m++) {
		if (m == RS::LIGHT_AREA_SHADING_AUTO) {
			continue;
		}
		const String name = m < int(std::size(names)) ? String(names[m]) : vformat("method_%d", m);
		sources.push_back({ "area_" + name + "_shapes.frag", scene_shader.get_stage_source(RenderingDevice::SHADER_STAGE_FRAGMENT, SCENE_SHADER_COLOR_AREA, get_area_method_defines((1u << m) | AREA_VERSION_SHAPES)) });
	}
	return sources;
}

uint32_t RenderForwardClustered::_get_area_shadow_version_bits() const {
	uint32_t bits = 0;
	const std::vector<AreaShadowRendererRD::AreaShadowData> &data = area_shadows.get_data();
	const size_t count = std::min(data.size(), size_t(light_storage->get_area_light_count()));
	for (size_t i = 0; i < count; i++) {
		if (data[i].map_count == 0) {
			continue; // Unshadowed (the shader's visibility is 1 without a lookup).
		}
		bits |= (data[i].mode & 0xFFu) == uint32_t(RS::LIGHT_AREA_SHADOW_PCSS_BASELINE) ? AREA_VERSION_SHADOWS_PCSS : AREA_VERSION_SHADOWS_PCF;
		bits |= (data[i].mode & AreaShadowRendererRD::FLAG_NEAR_LAYER) ? AREA_VERSION_SHADOWS_NEAR : 0u;
		bits |= (data[i].mode & 0xFFu) == uint32_t(RS::LIGHT_AREA_SHADOW_ADAPTIVE) ? AREA_VERSION_SHADOWS_TREE : 0u; // Only ADAPTIVE packs tree points.
	}
	return bits;
}

bool RenderForwardClustered::is_scene_shader_variant_compiled(SceneShaderVariant p_variant) const {
	if (p_variant == SCENE_SHADER_COLOR_AREA) {
		return compiled_area_method_mask != 0;
	}
	return scene_shader.is_variant_created(p_variant);
}

int RenderForwardClustered::get_area_shader_version_count() const {
	int count = 0;
	for (const auto &kv : area_versions) {
		count += (kv.second.scene_set.is_valid() && (kv.first & AREA_VERSION_METHOD_BITS) != 0) ? 1 : 0;
	}
	return count;
}

String RenderForwardClustered::get_scene_version_defines(uint32_t p_key) {
	String defines = get_area_method_defines(p_key);
	if (p_key & SCENE_VERSION_DIRECTIONAL) {
		defines += "#define USE_DIRECTIONAL_LIGHTS\n";
	}
	if (p_key & SCENE_VERSION_SKY_AMBIENT) {
		defines += "#define USE_SKY_AMBIENT\n";
	}
	if (p_key & SCENE_VERSION_SS_RADIOSITY) {
		defines += "#define USE_SS_RADIOSITY\n";
	}
	if (p_key & SCENE_VERSION_DIRECTIONAL_SHADOWS) {
		defines += "#define USE_DIRECTIONAL_SHADOWS\n";
	}
	if (p_key & SCENE_VERSION_SKY_REFLECTION) {
		defines += "#define USE_SKY_REFLECTION\n";
	}
	return defines;
}

RID RenderForwardClustered::_get_version_shader(uint32_t p_key, SceneShaderVariant p_variant) {
	const uint32_t area_bits = AREA_VERSION_ALL_BITS;
	const uint32_t valid_bits = area_bits | SCENE_VERSION_FEATURE_BITS;
	const bool has_area = (p_key & AREA_VERSION_METHOD_BITS) != 0;
	ERR_FAIL_COND_V_MSG((p_key & ~valid_bits) != 0 || (!has_area && (p_key & area_bits) != 0), RID(),
			vformat("RenderForwardClustered: invalid scene shader version key 0x%x (area method mask | area shadow bits | feature bits).", p_key));
	ERR_FAIL_COND_V_MSG(has_area != _is_area_variant(p_variant), RID(), vformat("RenderForwardClustered: variant %d does not fit version key 0x%x.", int(p_variant), p_key));
	if (p_key == 0) {
		return scene_shader.version_get_shader(p_variant);
	}
	AreaVersion &av = area_versions[p_key];
	if (!av.version.is_valid()) {
		av.version = scene_shader.version_create(get_scene_version_defines(p_key));
	}
	RID shader = scene_shader.version_get_shader(av.version, p_variant);
	if (shader.is_valid()) {
		if (p_variant == SCENE_SHADER_COLOR_AREA) {
			compiled_area_method_mask |= p_key & AREA_VERSION_METHOD_BITS;
			compiled_area_shapes = compiled_area_shapes || (p_key & AREA_VERSION_SHAPES) != 0;
		}
		compiled_feature_mask |= p_key & SCENE_VERSION_FEATURE_BITS;
		area_texture_compiled = area_texture_compiled || (p_key & AREA_VERSION_TEXTURE) != 0;
	}
	return shader;
}

RID RenderForwardClustered::_get_pipeline(SceneShaderVariant p_variant, RD::PolygonCullMode p_cull, RD::FramebufferFormatID p_format, uint32_t p_area_methods, PipelineMode p_mode) {
	// The whole 32-bit version key: every area and feature bit selects a different shader.
	ERR_FAIL_COND_V_MSG(p_format < 0 || p_format > 0xFFFF, RID(), vformat("RenderForwardClustered: framebuffer format id %d does not fit the pipeline key.", int(p_format)));
	const uint64_t key = uint64_t(p_variant) | (uint64_t(p_cull) << 8) | (uint64_t(p_mode) << 12) | (uint64_t(p_format) << 16) | (uint64_t(p_area_methods) << 32);
	auto it = pipelines.find(key);
	if (it != pipelines.end()) {
		return it->second;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	RD::PipelineRasterizationState raster;
	raster.cull_mode = p_cull;
	// Godot's winding: front faces are clockwise on screen (the projection flips y for Vulkan and the
	// image is stored top row first, so on-screen orientation is framebuffer orientation).
	raster.front_face = RD::POLYGON_FRONT_FACE_CLOCKWISE;
	RD::PipelineDepthStencilState depth;
	depth.enable_depth_test = true;
	if (p_variant == SCENE_SHADER_DEPTH) {
		depth.enable_depth_write = true;
		depth.depth_compare_operator = RD::COMPARE_OP_LESS;
	} else {
		// Depth comes from the pre-pass (invariant gl_Position makes it bit-identical).
		// Alpha scissor surfaces are not in the pre-pass (their holes would hide what is behind): they write
		// their own depth.
		depth.enable_depth_write = p_mode == PIPELINE_MODE_DEPTH_WRITE;
		depth.depth_compare_operator = RD::COMPARE_OP_LESS_OR_EQUAL;
	}
	// The SSIL/SSAO version writes colour plus the three image-space radiosity inputs.
	const int color_attachments = p_variant == SCENE_SHADER_DEPTH ? 0 : ((p_area_methods & SCENE_VERSION_SS_RADIOSITY) ? 4 : 1);
	RD::PipelineColorBlendState blend = RD::PipelineColorBlendState::create_disabled(color_attachments);
	if (p_mode == PIPELINE_MODE_BLEND && color_attachments > 0) {
		// Godot's BLEND_MODE_MIX: colour = src * src.a + dst * (1 - src.a); alpha = src.a + dst.a * (1 - src.a).
		// The image-space radiosity inputs keep the opaque surfaces' values.
		RD::PipelineColorBlendState::Attachment &a = blend.attachments[0];
		a.enable_blend = true;
		a.src_color_blend_factor = RD::BLEND_FACTOR_SRC_ALPHA;
		a.dst_color_blend_factor = RD::BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
		a.src_alpha_blend_factor = RD::BLEND_FACTOR_ONE;
		a.dst_alpha_blend_factor = RD::BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
		for (int i = 1; i < color_attachments; i++) {
			blend.attachments[i].write_r = blend.attachments[i].write_g = blend.attachments[i].write_b = blend.attachments[i].write_a = false;
		}
	}
	RID shader = p_variant == SCENE_SHADER_DEPTH ? scene_shader.version_get_shader(p_variant) : _get_version_shader(p_area_methods, p_variant);
	ERR_FAIL_COND_V_MSG(!shader.is_valid(), RID(), "RenderForwardClustered: the scene shader for this pipeline failed to compile: " + scene_shader.get_last_error());
	RID pipeline = rd->render_pipeline_create(shader, p_format, mesh_storage->get_vertex_format(), RD::RENDER_PRIMITIVE_TRIANGLES, raster, depth, blend);
	ERR_FAIL_COND_V_MSG(!pipeline.is_valid(), RID(), "RenderForwardClustered: render pipeline creation failed.");
	pipelines[key] = pipeline;
	return pipeline;
}

bool RenderForwardClustered::_ensure_scene_sets(uint32_t p_area_methods) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	RID cluster_buffer = cluster_builder.get_cluster_buffer();
	const bool has_area = (p_area_methods & AREA_VERSION_METHOD_BITS) != 0;
	if (p_area_methods != 0) {
		if (has_area && !ltc_lut.is_initialized()) {
			ERR_FAIL_COND_V_MSG(!ltc_lut.initialize(), false, "RenderForwardClustered: the LTC lookup table could not be created.");
		}
		RID shader = _get_version_shader(p_area_methods, has_area ? SCENE_SHADER_COLOR_AREA : SCENE_SHADER_COLOR);
		AreaVersion &av = area_versions[p_area_methods];
		const RID shadow_atlas = has_area ? area_shadows.get_atlas_texture() : RID();
		const RID directional_buffer = (p_area_methods & SCENE_VERSION_DIRECTIONAL) ? light_storage->get_directional_light_buffer() : RID();
		const RID sky_buffer = (p_area_methods & SCENE_VERSION_SKY_AMBIENT) ? sky.get_ambient_buffer() : RID();
		const RID sun_atlas = (p_area_methods & SCENE_VERSION_DIRECTIONAL_SHADOWS) ? directional_shadows.get_atlas_texture() : RID();
		const RID sky_radiance = (p_area_methods & SCENE_VERSION_SKY_REFLECTION) ? sky.get_radiance_texture() : RID();
		const RID texture_atlas = (p_area_methods & AREA_VERSION_TEXTURE) ? light_storage->get_area_light_atlas().get_texture() : RID();
		// One statement per input, so each feature's comparison is its own line (patches/README.md).
		bool area_ok = av.scene_set.is_valid() && rd->uniform_set_is_valid(av.scene_set) && av.scene_set_cluster_buffer == cluster_buffer;
		area_ok = area_ok && av.scene_set_shadow_atlas == shadow_atlas;
		area_ok = area_ok && av.scene_set_directional_buffer == directional_buffer;
		area_ok = area_ok && av.scene_set_sky_buffer == sky_buffer;
		area_ok = area_ok && av.scene_set_directional_shadow_atlas == sun_atlas;
		area_ok = area_ok && av.scene_set_sky_radiance == sky_radiance;
		area_ok = area_ok && av.scene_set_area_light_atlas == texture_atlas;
		if (!area_ok) {
			if (av.scene_set.is_valid() && rd->uniform_set_is_valid(av.scene_set)) {
				rd->free(av.scene_set);
			}
			ERR_FAIL_COND_V_MSG(!shader.is_valid(), false, "RenderForwardClustered: the scene shader version failed to compile: " + scene_shader.get_last_error());
			std::vector<RD::Uniform> u;
			u.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, scene_ubo));
			u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, light_storage->get_omni_light_buffer()));
			u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 2, light_storage->get_spot_light_buffer()));
			u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 3, cluster_buffer));
			if (has_area) {
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 5, light_storage->get_area_light_buffer()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 6, ltc_lut.get_texture()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 7, ltc_lut.get_sampler()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 12, area_shadows.get_data_buffer()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 13, area_shadows.get_atlas_texture()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 14, area_shadows.get_sampler()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 15, area_shadows.get_compare_sampler()));
			}
			if (p_area_methods & AREA_VERSION_TEXTURE) {
				ERR_FAIL_COND_V_MSG(!texture_atlas.is_valid(), false, "RenderForwardClustered: a textured area light version without the area light atlas.");
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 4, texture_atlas));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 10, light_storage->get_area_light_atlas().get_sampler()));
			}
			if (p_area_methods & SCENE_VERSION_DIRECTIONAL) {
				ERR_FAIL_COND_V_MSG(!directional_buffer.is_valid(), false, "RenderForwardClustered: a directional version without the directional light buffer.");
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 8, directional_buffer));
			}
			if (p_area_methods & SCENE_VERSION_SKY_AMBIENT) {
				ERR_FAIL_COND_V_MSG(!sky_buffer.is_valid(), false, "RenderForwardClustered: a sky ambient version without the sky buffer.");
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 9, sky_buffer));
			}
			if (p_area_methods & SCENE_VERSION_DIRECTIONAL_SHADOWS) {
				ERR_FAIL_COND_V_MSG(!sun_atlas.is_valid(), false, "RenderForwardClustered: a directional shadow version without the directional shadow atlas.");
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 16, directional_shadows.get_data_buffer()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 17, sun_atlas));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 18, directional_shadows.get_compare_sampler()));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 19, directional_shadows.get_nearest_sampler()));
			}
			if (p_area_methods & SCENE_VERSION_SKY_REFLECTION) {
				ERR_FAIL_COND_V_MSG(!sky_radiance.is_valid(), false, "RenderForwardClustered: a sky reflection version without the radiance cubemap.");
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 20, sky_radiance));
				u.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 21, sky.get_radiance_sampler()));
			}
			av.scene_set = rd->uniform_set_create(u, shader, 0);
			av.scene_set_cluster_buffer = cluster_buffer;
			av.scene_set_shadow_atlas = shadow_atlas;
			av.scene_set_directional_buffer = directional_buffer;
			av.scene_set_sky_buffer = sky_buffer;
			av.scene_set_directional_shadow_atlas = sun_atlas;
			av.scene_set_sky_radiance = sky_radiance;
			av.scene_set_area_light_atlas = texture_atlas;
		}
		if (!av.scene_set.is_valid()) {
			return false;
		}
	}
	bool color_ok = scene_set_color.is_valid() && rd->uniform_set_is_valid(scene_set_color) && scene_set_cluster_buffer == cluster_buffer;
	if (!color_ok) {
		if (scene_set_color.is_valid() && rd->uniform_set_is_valid(scene_set_color)) {
			rd->free(scene_set_color);
		}
		std::vector<RD::Uniform> u;
		u.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, scene_ubo));
		u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, light_storage->get_omni_light_buffer()));
		u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 2, light_storage->get_spot_light_buffer()));
		u.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 3, cluster_buffer));
		scene_set_color = rd->uniform_set_create(u, scene_shader.version_get_shader(SCENE_SHADER_COLOR), 0);
		scene_set_cluster_buffer = cluster_buffer;
	}
	if (!scene_set_depth.is_valid() || !rd->uniform_set_is_valid(scene_set_depth)) {
		std::vector<RD::Uniform> u;
		u.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, scene_ubo));
		scene_set_depth = rd->uniform_set_create(u, scene_shader.version_get_shader(SCENE_SHADER_DEPTH), 0);
	}
	return scene_set_color.is_valid() && scene_set_depth.is_valid();
}

/* Rendering */

void RenderForwardClustered::render_scene(const RenderSceneData &p_data, RID p_render_target) {
	ERR_FAIL_COND_MSG(!initialized, "render_scene: the renderer is not initialized.");
	RenderTarget *rt = render_target_owner.get_or_null(p_render_target);
	ERR_FAIL_NULL_MSG(rt, "render_scene: invalid render target RID.");
	RenderingDevice *rd = RenderingDevice::get_singleton();
	// ADAPTIVE area shadows: apply the newest completed frame's banding flags before this frame records
	// anything (the readback then waits for no work of this frame).
	last_area_shadow_tests = 0;
	const bool area_code = !area_code_disabled;
	if (area_code) {
		area_shadows.begin_frame(p_render_target);
	}

	ERR_FAIL_COND_MSG(!cluster_builder.setup(rt->width, rt->height), "render_scene: cluster setup failed.");

	// Camera. Unit conversions of the frame happen here and in LightStorage::update_light_buffers().
	Projection clip_from_view = Projection::create_depth_correction(true) * p_data.cam_projection;
	Transform3D view_from_world = p_data.cam_transform.affine_inverse();
	float z_far = p_data.z_far > 0.0f ? p_data.z_far : p_data.cam_projection.get_z_far();

	cluster_builder.begin(clip_from_view, z_far);
	// AUTO area lights pick their method from the receivers inside their influence box (AreaMethodSelector).
	if (area_code) {
		light_storage->set_area_auto_receivers(&p_data.geometry, mesh_storage, material_storage);
	}
	light_storage->update_light_buffers(p_data.lights, view_from_world, &cluster_builder);
	light_storage->update_directional_light_buffer(p_data.directional_lights, view_from_world);
	// Sun shadows: splits fitted to this view; nothing at all without a shadowed directional light.
	ERR_FAIL_COND_MSG(!directional_shadows.prepare(p_data, view_from_world), "render_scene: directional shadows could not be prepared.");
	// Sky: SH recomputed only when the sky changes; nothing at all without a sky.
	ERR_FAIL_COND_MSG(!sky.prepare(p_data, light_storage, clip_from_view, rt->width, rt->height), "render_scene: the sky could not be prepared.");
	// Area shadows: share the atlas and fill the shadow data of the GPU area lights (before the sets).
	if (area_code) {
		area_shadows.prepare(p_data, light_storage->get_area_light_source_indices(), view_from_world, p_data.cam_projection * Projection::from_transform(view_from_world), p_render_target);
	}

	SceneDataUBO ubo;
	memset(&ubo, 0, sizeof(ubo));
	clip_from_view.to_floats(ubo.clip_from_view);
	clip_from_view.inverse().to_floats(ubo.view_from_clip);
	_transform_to_floats(view_from_world, ubo.view_from_world);
	_transform_to_floats(p_data.cam_transform, ubo.world_from_view);
	ubo.viewport_size[0] = float(rt->width);
	ubo.viewport_size[1] = float(rt->height);
	ubo.z_near = p_data.z_near;
	ubo.z_far = cluster_builder.get_slice_depth(); // The depth the cluster slices cover (<= z_far).
	const RenderSceneData::EnvironmentData &env = p_data.environment;
	Color ambient = env.ambient_color.srgb_to_linear();
	// Sky ambient: the colour part keeps (1 - ambient_light_sky_contribution), the sky part is the SH (SkyRD).
	const float ambient_colour_share = (env.has_sky && env.sky_ambient) ? 1.0f - env.ambient_sky_contribution : 1.0f;
	ubo.ambient_light[0] = ambient.r * env.ambient_energy * ambient_colour_share;
	ubo.ambient_light[1] = ambient.g * env.ambient_energy * ambient_colour_share;
	ubo.ambient_light[2] = ambient.b * env.ambient_energy * ambient_colour_share;
	ubo.ambient_light[3] = 1.0f;
	ubo.omni_light_count = light_storage->get_omni_light_count();
	ubo.spot_light_count = light_storage->get_spot_light_count();
	ubo.cluster_tiles_x = cluster_builder.get_tiles_x();
	ubo.cluster_tile_count = cluster_builder.get_tiles_x() * cluster_builder.get_tiles_y();
	ubo.cluster_words_per_type = cluster_builder.get_words_per_type();
	ubo.cluster_tile_size = cluster_builder.get_tile_size();
	ubo.area_light_count = area_code ? light_storage->get_area_light_count() : 0u;
	ubo.flags = force_all_lights ? SCENE_FLAG_FORCE_ALL_LIGHTS : 0;
	int cluster_debug = -1;
	if (p_data.debug_draw == RS::VIEWPORT_DEBUG_DRAW_CLUSTER_OMNI_LIGHTS) {
		cluster_debug = ClusterBuilderRD::ELEMENT_TYPE_OMNI_LIGHT;
	} else if (p_data.debug_draw == RS::VIEWPORT_DEBUG_DRAW_CLUSTER_SPOT_LIGHTS) {
		cluster_debug = ClusterBuilderRD::ELEMENT_TYPE_SPOT_LIGHT;
	} else if (p_data.debug_draw == RS::VIEWPORT_DEBUG_DRAW_CLUSTER_AREA_LIGHTS) {
		cluster_debug = ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT;
	}
	if (cluster_debug >= 0 && cluster_debug < ClusterBuilderRD::ELEMENT_TYPE_MAX) {
		ubo.flags |= SCENE_FLAG_DEBUG_CLUSTER;
		ubo.debug_cluster_type = uint32_t(cluster_debug);
	}
	rd->buffer_update(scene_ubo, 0, sizeof(ubo), &ubo);

	// Area-light variant only when this view has area lights (a scene without them pays nothing).
	// The shader version holds the code of exactly the shading methods this view's area lights use, and the
	// area shadow lookups only when some of them have shadow maps this frame.
	const bool use_area = ubo.area_light_count > 0;
	// Directional lights and sky add their own feature bits (no code, no bindings without them).
	uint32_t area_methods = use_area ? (light_storage->get_area_shading_method_mask() | _get_area_shadow_version_bits()) : 0u;
	if (use_area && (light_storage->get_area_shape_mask() & ~(1u << RS::LIGHT_AREA_SHAPE_RECTANGLE)) != 0) {
		area_methods |= AREA_VERSION_SHAPES;
	}
	if (use_area && light_storage->has_textured_area_lights()) {
		area_methods |= AREA_VERSION_TEXTURE; // area_texture: the atlas and its fetch code, only now.
	}
	if (light_storage->get_directional_light_count() > 0) {
		area_methods |= SCENE_VERSION_DIRECTIONAL;
	}
	if (directional_shadows.has_frame_shadows()) {
		area_methods |= SCENE_VERSION_DIRECTIONAL_SHADOWS;
	}
	if (sky.has_frame_ambient()) {
		area_methods |= SCENE_VERSION_SKY_AMBIENT;
	}
	if (sky.has_frame_reflections()) {
		area_methods |= SCENE_VERSION_SKY_REFLECTION;
	}
	// SSIL / SSAO: only when the environment enables one (otherwise no pass, target or shader code).
	const SSRadiosityRD::FrameSettings ss_frame = SSRadiosityRD::get_frame_settings(env.ss_lighting);
	ss_radiosity.begin_frame();
	RID fb_opaque = rt->fb_color;
	if (ss_frame.is_active()) {
		fb_opaque = ss_radiosity.prepare(p_render_target, rt->color, rt->depth, rt->width, rt->height, ss_frame);
		ERR_FAIL_COND_MSG(!fb_opaque.is_valid(), "render_scene: the SSIL/SSAO buffers could not be created.");
		area_methods |= SCENE_VERSION_SS_RADIOSITY;
	}
	// Brute force and the cluster debug view are variants of their own: the production ones carry no code
	// for them. All colour variants declare the same bindings, so the sets are shared.
	SceneShaderVariant color_variant = use_area ? SCENE_SHADER_COLOR_AREA : SCENE_SHADER_COLOR;
	if ((ubo.flags & SCENE_FLAG_DEBUG_CLUSTER) != 0u) {
		color_variant = use_area ? SCENE_SHADER_COLOR_AREA_DEBUG : SCENE_SHADER_COLOR_DEBUG;
	} else if ((ubo.flags & SCENE_FLAG_FORCE_ALL_LIGHTS) != 0u) {
		color_variant = use_area ? SCENE_SHADER_COLOR_AREA_FORCE_ALL : SCENE_SHADER_COLOR_FORCE_ALL;
	}
	// Shader version per draw, as upstream Godot chooses it: an object that no visible area light's
	// influence box (light_get_aabb(), the support of the range window W) reaches gets exactly 0 from
	// every area light, so it is drawn with the same key less the area bits, whose shader has no area
	// code. Debug and brute-force views keep one version for the whole view.
	const bool area_per_draw = use_area && color_variant == SCENE_SHADER_COLOR_AREA;
	const uint32_t plain_methods = area_methods & ~AREA_VERSION_ALL_BITS;
	ERR_FAIL_COND_MSG(!_ensure_scene_sets(area_methods), "render_scene: scene uniform sets could not be created.");
	ERR_FAIL_COND_MSG(area_per_draw && !_ensure_scene_sets(plain_methods), "render_scene: scene uniform sets could not be created.");
	RID color_set = area_methods != 0 ? area_versions[area_methods].scene_set : scene_set_color;
	RID plain_set = plain_methods != 0 ? area_versions[plain_methods].scene_set : scene_set_color;
	std::vector<AABB> area_boxes; // World bounds of the area lights' influence boxes.
	if (area_per_draw) {
		for (const RenderSceneData::LightInstance &li : p_data.lights) {
			if (li.type == RS::LIGHT_AREA) {
				area_boxes.push_back(li.transform.xform(light_storage->light_get_aabb(li.light)));
			}
		}
	}

	// Draw items (material sets are created/updated here, outside any list).
	struct DrawItem {
		const RendererRD::MeshStorage::SurfaceGPU *gpu;
		RID material_set;
		RD::PolygonCullMode cull;
		bool area; // Drawn with the area-light version (color_variant, area_methods).
		RS::MaterialTransparency transparency;
		float view_depth; // Of the surface's AABB centre (sorts the blended surfaces back to front).
		DrawPushConstant pc;
	};
	std::vector<DrawItem> items;
	const Vector3 view_forward = -p_data.cam_transform.basis.get_column(2);
	// Material sets (set 1) are made against the plain colour variant: set 1 is declared identically in
	// both colour variants, so the sets are compatible with either pipeline and are not rebuilt per variant.
	RID color_shader = scene_shader.version_get_shader(SCENE_SHADER_COLOR);
	for (const RenderSceneData::GeometryInstance &g : p_data.geometry) {
		int surface_count = mesh_storage->owns_mesh(g.mesh) ? mesh_storage->mesh_get_surface_count(g.mesh) : 0;
		if (surface_count == 0 || g.cast_shadows == RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY) { // Shadows Only: cast, not drawn.
			continue;
		}
		DrawPushConstant pc;
		memset(&pc, 0, sizeof(pc));
		_transform_to_floats(g.transform, pc.world_from_model);
		Basis normal_basis = g.transform.basis.inverse().transposed();
		for (int c = 0; c < 3; c++) {
			Vector3 col = normal_basis.get_column(c);
			pc.normal_matrix[c * 4 + 0] = col.x;
			pc.normal_matrix[c * 4 + 1] = col.y;
			pc.normal_matrix[c * 4 + 2] = col.z;
		}
		pc.layer_mask = g.layer_mask;
		bool area = use_area && !area_per_draw;
		if (area_per_draw) {
			const AABB bound = g.transform.xform(mesh_storage->mesh_get_aabb(g.mesh));
			for (const AABB &box : area_boxes) {
				if (box.intersects(bound)) {
					area = true;
					break;
				}
			}
		}
		for (int s = 0; s < surface_count; s++) {
			const RendererRD::MeshStorage::SurfaceGPU *gpu = mesh_storage->mesh_surface_get_gpu(g.mesh, s);
			ERR_CONTINUE_MSG(!gpu, "render_scene: a mesh surface has no GPU data (created before the RenderingDevice?); skipped.");
			RID material = g.material_override.is_valid() ? g.material_override : mesh_storage->mesh_surface_get_material(g.mesh, s);
			DrawItem item;
			item.gpu = gpu;
			item.material_set = material_storage->material_get_uniform_set(material, color_shader);
			ERR_CONTINUE_MSG(!item.material_set.is_valid(), "render_scene: material uniform set creation failed; surface skipped.");
			item.cull = material_storage->material_is_cull_back(material) ? RD::POLYGON_CULL_BACK : RD::POLYGON_CULL_DISABLED;
			item.area = area;
			item.transparency = material_storage->material_get_transparency(material);
			item.view_depth = 0.0f;
			if (item.transparency == RS::MATERIAL_TRANSPARENCY_ALPHA) {
				const RS::SurfaceData *data = mesh_storage->mesh_get_surface(g.mesh, s);
				const Vector3 centre = g.transform.xform(data ? data->aabb.get_center() : Vector3());
				item.view_depth = (centre - p_data.cam_transform.origin).dot(view_forward);
			}
			item.pc = pc;
			item.pc.flags = gpu->has_colors ? DRAW_FLAG_HAS_COLOR : 0u;
			items.push_back(item);
		}
	}

	Color bg = env.bg_color.srgb_to_linear();
	Color clear_color(bg.r * env.bg_energy, bg.g * env.bg_energy, bg.b * env.bg_energy, 1.0f);

	String prefix = vformat("fc%llu_", (unsigned long long)frame_counter++);
	rd->capture_timestamp(prefix + "begin");

	// 0. Area shadow maps (only the dirty ones; none in a static scene after the first frame).
	// Debug labels name the area-light passes only in views with area lights.
	const bool area_labels = area_code && light_storage->get_area_light_count() > 0;
	if (area_labels) {
		rd->draw_command_begin_label("Render Area Shadow Maps");
	}
	if (area_code) {
		area_shadows.render_shadows(p_data, color_shader); // Alpha-scissor casters share the colour pass's material sets.
	}
	if (area_labels) {
		rd->draw_command_end_label();
	}
	if (area_code && area_shadows.has_frame_shadows()) {
		rd->capture_timestamp(prefix + "area_shadows"); // Profiled only in frames with shadowed area lights.
	}

	// 0b. Directional shadow splits (only with a shadowed directional light in view).
	if (directional_shadows.has_frame_shadows()) {
		rd->draw_command_begin_label("Render Directional Shadows");
		directional_shadows.render_shadows(color_shader);
		rd->draw_command_end_label();
		rd->capture_timestamp(prefix + "directional_shadows");
	}

	// 0c. Sky reflections: the radiance cubemap, only in a frame whose sky changed (none for a static sky).
	if (sky.has_pending_radiance()) {
		rd->draw_command_begin_label("Filter Sky Radiance");
		sky.filter_radiance();
		rd->draw_command_end_label();
		rd->capture_timestamp(prefix + "sky_radiance");
	}

	// 1. Depth pre-pass.
	rd->draw_command_begin_label("Render Depth Pre-Pass");
	RD::FramebufferFormatID depth_format = rd->framebuffer_get_format(rt->fb_depth);
	RD::DrawListID list = rd->draw_list_begin(rt->fb_depth, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, {}, 1.0f);
	rd->draw_list_bind_uniform_set(list, scene_set_depth, 0);
	for (const DrawItem &item : items) {
		if (item.transparency != RS::MATERIAL_TRANSPARENCY_DISABLED) {
			continue; // Scissored surfaces write depth in the opaque pass; blended ones never.
		}
		rd->draw_list_bind_render_pipeline(list, _get_pipeline(SCENE_SHADER_DEPTH, item.cull, depth_format));
		rd->draw_list_bind_uniform_set(list, scene_set_depth, 0);
		rd->draw_list_bind_vertex_array(list, item.gpu->vertex_array);
		rd->draw_list_set_push_constant(list, &item.pc, sizeof(item.pc));
		if (item.gpu->index_array.is_valid()) {
			rd->draw_list_bind_index_array(list, item.gpu->index_array);
			rd->draw_list_draw(list, true);
		} else {
			rd->draw_list_draw(list, false);
		}
	}
	rd->draw_list_end();
	rd->draw_command_end_label();
	rd->capture_timestamp(prefix + "depth_prepass");
	// 1b. ADAPTIVE area shadows: reprojection + banding of this frame's quad tests against the pre-pass depth
	// (timestamps "area_reprojection", "area_banding"; nothing without ADAPTIVE lights).
	if (area_labels) {
		rd->draw_command_begin_label("Area Shadow Adaptive Refinement");
	}
	last_area_shadow_tests = !area_code ? 0u : area_shadows.dispatch_adaptive(rt->depth, uint32_t(rt->width), uint32_t(rt->height), clip_from_view, prefix);
	if (area_labels) {
		rd->draw_command_end_label();
	}

	// 2. Cluster build.
	rd->draw_command_begin_label("Build Clusters");
	cluster_builder.bake_cluster(area_code ? ClusterBuilderRD::ELEMENT_TYPE_MAX : ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT);
	rd->draw_command_end_label();
	rd->capture_timestamp(prefix + "cluster_build");

	// 3. Opaque pass.
	rd->draw_command_begin_label("Render Opaque Pass");
	RD::FramebufferFormatID color_format = rd->framebuffer_get_format(fb_opaque);
	std::vector<Color> clear_colors = { clear_color };
	if (ss_frame.is_active()) {
		clear_colors.resize(4, Color(0, 0, 0, 0)); // Normal, albedo, ambient: zero where no geometry.
	}
	list = rd->draw_list_begin(fb_opaque, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_LOAD, clear_colors, 1.0f);
	last_draw_calls = 0;
	last_area_draw_calls = 0;
	auto draw_color_item = [&](const DrawItem &p_item, PipelineMode p_mode) {
		const bool plain = use_area && !p_item.area;
		rd->draw_list_bind_render_pipeline(list, plain ? _get_pipeline(SCENE_SHADER_COLOR, p_item.cull, color_format, plain_methods, p_mode) : _get_pipeline(color_variant, p_item.cull, color_format, area_methods, p_mode));
		rd->draw_list_bind_uniform_set(list, plain ? plain_set : color_set, 0);
		last_draw_calls++;
		last_area_draw_calls += p_item.area ? 1 : 0;
		rd->draw_list_bind_uniform_set(list, p_item.material_set, 1);
		rd->draw_list_bind_vertex_array(list, p_item.gpu->vertex_array);
		rd->draw_list_set_push_constant(list, &p_item.pc, sizeof(p_item.pc));
		if (p_item.gpu->index_array.is_valid()) {
			rd->draw_list_bind_index_array(list, p_item.gpu->index_array);
			rd->draw_list_draw(list, true);
		} else {
			rd->draw_list_draw(list, false);
		}
	};
	std::vector<const DrawItem *> blended;
	for (const DrawItem &item : items) {
		if (item.transparency == RS::MATERIAL_TRANSPARENCY_ALPHA) {
			blended.push_back(&item);
		} else {
			draw_color_item(item, item.transparency == RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR ? PIPELINE_MODE_DEPTH_WRITE : PIPELINE_MODE_OPAQUE);
		}
	}
	rd->draw_list_end();
	rd->draw_command_end_label();
	rd->capture_timestamp(prefix + "opaque");

	// 3b. SSIL / SSAO: image-space radiosity from the opaque pass's targets, composed into the colour.
	if (ss_frame.is_active()) {
		rd->draw_command_begin_label("SSIL/SSAO (Image-Space Radiosity)");
		ss_radiosity.render(p_render_target, clip_from_view, env.ss_lighting, ss_frame, prefix + "ss_radiosity");
		rd->draw_command_end_label();
	}

	// 4. Sky background (only with background_mode SKY): the far-plane pixels no geometry covered.
	if (sky.has_frame_background()) {
		rd->draw_command_begin_label("Draw Sky");
		list = rd->draw_list_begin(rt->fb_color, RD::INITIAL_ACTION_LOAD, RD::INITIAL_ACTION_LOAD);
		sky.draw_background(list, rd->framebuffer_get_format(rt->fb_color));
		rd->draw_list_end();
		rd->draw_command_end_label();
		rd->capture_timestamp(prefix + "sky");
	}

	// 5. Alpha-blended surfaces (transparency ALPHA), back to front by their AABB centre's view depth as
	// Godot sorts its transparent list, over the opaque pass and the sky; depth tested, not written.
	if (!blended.empty()) {
		rd->draw_command_begin_label("Render Transparent Pass");
		std::stable_sort(blended.begin(), blended.end(), [](const DrawItem *p_a, const DrawItem *p_b) { return p_a->view_depth > p_b->view_depth; });
		list = rd->draw_list_begin(fb_opaque, RD::INITIAL_ACTION_LOAD, RD::INITIAL_ACTION_LOAD);
		for (const DrawItem *item : blended) {
			draw_color_item(*item, PIPELINE_MODE_BLEND);
		}
		rd->draw_list_end();
		rd->draw_command_end_label();
		rd->capture_timestamp(prefix + "transparent");
	}

	// Frames in flight: submits this frame and opens the next, waiting only for the frame
	// rendering/rendering_device/vsync/frame_queue_size frames old. The pass times arrive with it.
	const uint64_t submitted_before = rd->get_frames_submitted();
	rd->swap_buffers();
	if (rd->get_frames_submitted() > submitted_before) {
		pending_profiles.emplace_back(rd->get_frames_submitted(), prefix);
		if (pending_profiles.size() > 8) {
			pending_profiles.erase(pending_profiles.begin()); // Never waited for by anyone: dropped.
		}
	}
}

void RenderForwardClustered::_update_profile() const {
	// The captured timestamps are those of the newest frame the device waited for: if this renderer
	// drew it, they become the profile (attributed to that frame, not to the frame just recorded).
	const uint64_t frame = RenderingDevice::get_singleton()->get_captured_timestamps_frame();
	if (frame <= last_profile_frame) {
		return;
	}
	for (size_t i = 0; i < pending_profiles.size(); i++) {
		if (pending_profiles[i].first == frame) {
			_read_profile(pending_profiles[i].second);
			last_profile_frame = frame;
			pending_profiles.erase(pending_profiles.begin(), pending_profiles.begin() + i + 1);
			return;
		}
	}
}

std::vector<std::pair<String, double>> RenderForwardClustered::get_last_frame_profile() const {
	// A synchronous read: the last drawn frame may still be in flight; wait for it (only it and older
	// frames), so the profile is that frame's, as callers (tests, the CLI) expect.
	if (!pending_profiles.empty()) {
		RenderingDevice::get_singleton()->wait_for_frame(pending_profiles.back().first);
	}
	_update_profile();
	return last_profile;
}

void RenderForwardClustered::_read_profile(const String &p_prefix) const {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	last_profile.clear();
	const int pass_count = 12;
	const char *names[pass_count] = { "begin", "area_shadows", "directional_shadows", "sky_radiance", "depth_prepass", "area_reprojection", "area_banding", "cluster_build", "opaque", "ss_radiosity", "sky", "transparent" };
	int64_t found[pass_count] = { -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 };
	uint32_t count = rd->get_captured_timestamps_count();
	for (uint32_t i = 0; i < count; i++) {
		String name = rd->get_captured_timestamp_name(i);
		for (int n = 0; n < pass_count; n++) {
			if (name == p_prefix + names[n]) {
				found[n] = i;
			}
		}
	}
	int prev = found[0] >= 0 ? 0 : -1; // Each pass is timed from the previous captured timestamp.
	for (int n = 1; n < pass_count; n++) {
		if (found[n] < 0) {
			continue; // Not recorded this frame (area_shadows) or timestamps unsupported on this device.
		}
		if (prev >= 0) {
			uint64_t t0 = rd->get_captured_timestamp_gpu_time(uint32_t(found[prev]));
			uint64_t t1 = rd->get_captured_timestamp_gpu_time(uint32_t(found[n]));
			double ms = t1 >= t0 ? double(t1 - t0) / 1.0e6 : 0.0;
			last_profile.push_back(std::make_pair(String(names[n]), ms));
		}
		prev = n;
	}
}

uint64_t RenderForwardClustered::get_last_frame_rendering_info(RS::RenderingInfo p_info) const {
	switch (p_info) {
		case RS::RENDERING_INFO_AREA_SHADOW_MAPS_IN_FRAME:
			return area_shadows.get_shadow_map_count();
		case RS::RENDERING_INFO_AREA_SHADOW_DRAW_CALLS_IN_FRAME:
			return area_shadows.get_last_draw_count();
		case RS::RENDERING_INFO_TOTAL_DRAW_CALLS_IN_FRAME:
			return last_draw_calls;
		case RS::RENDERING_INFO_AREA_LIGHT_DRAW_CALLS_IN_FRAME:
			return last_area_draw_calls;
		default:
			return 0;
	}
}
