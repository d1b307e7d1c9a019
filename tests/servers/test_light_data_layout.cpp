/**************************************************************************/
/*  test_light_data_layout.cpp                                            */
/**************************************************************************/
/* godot-area: the GPU light structs and their C++ mirrors agree byte for */
/* byte. The REAL GLSL (shaders/light_data_inc.glsl, cluster_data_inc.    */
/* glsl) is compiled by glslang inside a tiny compute shader; member      */
/* offsets (OpMemberDecorate Offset) and array strides (OpDecorate        */
/* ArrayStride) are read from the SPIR-V by a small parser below and      */
/* compared with offsetof/sizeof of                                       */
/* RendererRD::LightStorage::LightData / AreaLightData and                */
/* ClusterBuilderRD::ElementData; the scene UBO, push constants and the   */
/* other passes' blocks are read from the production shaders' SPIR-V.     */

#include "servers/rendering/renderer_rd/cluster_builder_rd.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_adaptive.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_renderer.h"
#include "servers/rendering/renderer_rd/effects/sky_rd.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cstddef>
#include <map>

namespace TestLightDataLayout {

// Member offsets and array stride of one struct, read from SPIR-V.
struct SPIRVStructLayout {
	bool found = false;
	std::map<String, uint32_t> member_offsets; // Member name -> byte offset.
	uint32_t array_stride = 0; // Stride of the runtime array of this struct (0 if none).
};

static String spirv_string(const std::vector<uint32_t> &p_words, size_t p_first) {
	String s;
	for (size_t i = p_first; i < p_words.size(); i++) {
		for (int b = 0; b < 4; b++) {
			char c = char((p_words[i] >> (8 * b)) & 0xFF);
			if (c == 0) {
				return s;
			}
			s += c;
		}
	}
	return s;
}

// SPIR-V opcodes/decorations used (SPIR-V specification 1.6, sections 3.32 and 3.20).
static constexpr uint32_t OP_NAME = 5, OP_MEMBER_NAME = 6, OP_TYPE_RUNTIME_ARRAY = 29, OP_DECORATE = 71, OP_MEMBER_DECORATE = 72;
static constexpr uint32_t DECORATION_ARRAY_STRIDE = 6, DECORATION_OFFSET = 35;

static SPIRVStructLayout spirv_struct_layout(const std::vector<uint32_t> &p_spirv, const String &p_struct_name) {
	SPIRVStructLayout layout;
	std::map<uint32_t, String> names;
	std::map<std::pair<uint32_t, uint32_t>, String> member_names;
	std::map<std::pair<uint32_t, uint32_t>, uint32_t> member_offsets;
	std::map<uint32_t, uint32_t> runtime_array_element; // Array id -> element type id.
	std::map<uint32_t, uint32_t> array_strides;
	for (size_t i = 5; i < p_spirv.size();) {
		uint32_t word_count = p_spirv[i] >> 16;
		uint32_t opcode = p_spirv[i] & 0xFFFF;
		if (word_count == 0 || i + word_count > p_spirv.size()) {
			break;
		}
		const uint32_t *op = &p_spirv[i];
		std::vector<uint32_t> inst(op, op + word_count);
		if (opcode == OP_NAME) {
			names[op[1]] = spirv_string(inst, 2);
		} else if (opcode == OP_MEMBER_NAME) {
			member_names[{ op[1], op[2] }] = spirv_string(inst, 3);
		} else if (opcode == OP_MEMBER_DECORATE && word_count >= 5 && op[3] == DECORATION_OFFSET) {
			member_offsets[{ op[1], op[2] }] = op[4];
		} else if (opcode == OP_DECORATE && word_count >= 4 && op[2] == DECORATION_ARRAY_STRIDE) {
			array_strides[op[1]] = op[3];
		} else if (opcode == OP_TYPE_RUNTIME_ARRAY) {
			runtime_array_element[op[1]] = op[2];
		}
		i += word_count;
	}
	uint32_t struct_id = 0;
	for (const auto &kv : names) {
		if (kv.second == p_struct_name) {
			struct_id = kv.first;
		}
	}
	if (struct_id == 0) {
		return layout;
	}
	layout.found = true;
	for (const auto &kv : member_offsets) {
		if (kv.first.first == struct_id) {
			layout.member_offsets[member_names[kv.first]] = kv.second;
		}
	}
	for (const auto &kv : runtime_array_element) {
		if (kv.second == struct_id && array_strides.count(kv.first)) {
			layout.array_stride = array_strides[kv.first];
		}
	}
	return layout;
}

// Compiles a compute shader that declares one std430 runtime array per struct (the way the scene
// shader and the cluster builder declare them) and returns its SPIR-V.
static std::vector<uint32_t> compile_layout_probe(RenderingDevice *p_rd, String &r_error) {
	String source = "#version 450\n";
	source += String(ShaderRD::get_embedded_source("light_data_inc.glsl")) + "\n";
	source += String(ShaderRD::get_embedded_source("cluster_data_inc.glsl")) + "\n";
	source += R"(
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) buffer Lights { LightData data[]; } lights;
layout(set = 0, binding = 1, std430) buffer AreaLights { AreaLightData data[]; } area_lights;
layout(set = 0, binding = 2, std430) buffer Elements { ClusterElementData data[]; } elements;
void main() {
	lights.data[1].inv_radius += area_lights.data[1].inv_radius + elements.data[1].radius;
}
)";
	return p_rd->shader_compile_spirv_from_source(RenderingDevice::SHADER_STAGE_COMPUTE, source, "light_data_layout_probe", &r_error);
}

#define MEMBER(m_struct, m_name) \
	{ #m_name, uint32_t(offsetof(m_struct, m_name)) }

static void check_layout(const SPIRVStructLayout &p_layout, const char *p_name, const std::vector<std::pair<String, uint32_t>> &p_members, size_t p_sizeof) {
	INFO("struct ", p_name);
	REQUIRE(p_layout.found);
	CHECK(p_layout.member_offsets.size() == p_members.size());
	for (const auto &m : p_members) {
		INFO("member ", m.first.c_str());
		REQUIRE(p_layout.member_offsets.count(m.first) == 1);
		CHECK(p_layout.member_offsets.at(m.first) == m.second);
	}
	CHECK(p_layout.array_stride == p_sizeof);
}

TEST_CASE("[LightStorage] LightData, AreaLightData and ClusterElementData match their GLSL structs in the SPIR-V") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	String error;
	std::vector<uint32_t> spirv = compile_layout_probe(rd, error);
	INFO("glslang: ", error.c_str());
	REQUIRE(!spirv.empty());

	using LD = RendererRD::LightStorage::LightData;
	check_layout(spirv_struct_layout(spirv, "LightData"), "LightData",
			{ MEMBER(LD, position), MEMBER(LD, inv_radius), MEMBER(LD, direction), MEMBER(LD, size), MEMBER(LD, color), MEMBER(LD, attenuation),
					MEMBER(LD, cone_attenuation), MEMBER(LD, cone_angle), MEMBER(LD, specular_amount), MEMBER(LD, cull_mask) },
			sizeof(LD));

	using AD = RendererRD::LightStorage::AreaLightData;
	check_layout(spirv_struct_layout(spirv, "AreaLightData"), "AreaLightData",
			{ MEMBER(AD, position), MEMBER(AD, inv_radius), MEMBER(AD, half_axis_x), MEMBER(AD, attenuation), MEMBER(AD, half_axis_y),
					MEMBER(AD, specular_amount), MEMBER(AD, normal), MEMBER(AD, shading_method), MEMBER(AD, color), MEMBER(AD, cull_mask), MEMBER(AD, texture_rect) },
			sizeof(AD));

	using ED = ClusterBuilderRD::ElementData;
	check_layout(spirv_struct_layout(spirv, "ClusterElementData"), "ClusterElementData",
			{ MEMBER(ED, position), MEMBER(ED, radius), MEMBER(ED, direction), MEMBER(ED, cone_cos), MEMBER(ED, extents), MEMBER(ED, cone_sin),
					MEMBER(ED, axis_x), MEMBER(ED, sphere_offset) },
			sizeof(ED));
}

// "struct p_name { ... };" as written in the embedded shader p_file ("" when absent).
static String embedded_struct(const char *p_file, const String &p_name) {
	const char *text = ShaderRD::get_embedded_source(p_file);
	if (!text) {
		return String();
	}
	const String source = text;
	const size_t begin = source.find("struct " + p_name + " {");
	const size_t end = begin == String::npos ? String::npos : source.find("\n};", begin);
	return end == String::npos ? String() : source.substr(begin, end + 3 - begin) + "\n";
}

// The integer value of "#define p_name <n>u" in the embedded shader p_file (-1 when absent).
static long embedded_define(const char *p_file, const String &p_name) {
	const char *text = ShaderRD::get_embedded_source(p_file);
	const String source = text ? String(text) : String();
	const size_t at = source.find("#define " + p_name + " ");
	return at == String::npos ? -1 : strtol(source.c_str() + at + p_name.size() + 9, nullptr, 10);
}

TEST_CASE("[LightStorage] the GLSL area shape and method values equal RS's, and the shape fits bits 24-31") {
	CHECK(embedded_define("light_data_inc.glsl", "AREA_SHAPE_RECTANGLE") == long(RS::LIGHT_AREA_SHAPE_RECTANGLE));
	CHECK(embedded_define("light_data_inc.glsl", "AREA_SHAPE_DISK") == long(RS::LIGHT_AREA_SHAPE_DISK));
	CHECK(embedded_define("light_data_inc.glsl", "AREA_SHAPE_SPHERE") == long(RS::LIGHT_AREA_SHAPE_SPHERE));
	CHECK(embedded_define("light_data_inc.glsl", "AREA_SHAPE_TUBE") == long(RS::LIGHT_AREA_SHAPE_TUBE));
	CHECK(embedded_define("light_data_inc.glsl", "AREA_SHADING_STOCHASTIC") == long(RS::LIGHT_AREA_SHADING_STOCHASTIC));
	CHECK(RendererRD::LightStorage::AREA_METHOD_SHAPE_SHIFT == 24u);
	CHECK(int(RS::LIGHT_AREA_SHAPE_MAX) <= 256);
	// The shader reads the shape as shading_method >> 24u (area_light_get_shape).
	const char *dispatch = ShaderRD::get_embedded_source("area_light_common_inc.glsl");
	REQUIRE(dispatch != nullptr);
	CHECK(String(dispatch).find("p_light.shading_method >> 24u") != String::npos);
}

TEST_CASE("[AreaShadowRendererRD] AreaShadowData and the adaptive pass structs match their GLSL structs in the SPIR-V") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const long max_maps = embedded_define("area_light_shadow_inc.glsl", "AREA_SHADOW_MAX_MAPS");
	CHECK(max_maps == long(AreaShadowRendererRD::MAX_MAPS_GPU));
	const String shadow_struct = embedded_struct("area_light_shadow_inc.glsl", "AreaShadowData");
	const String grid_struct = embedded_struct("area_shadow_adaptive_inc.glsl", "GridData");
	const String light_struct = embedded_struct("area_shadow_adaptive_inc.glsl", "AdaptiveLightData");
	REQUIRE(!shadow_struct.empty());
	REQUIRE(!grid_struct.empty());
	REQUIRE(!light_struct.empty());
	String source = "#version 450\n#define AREA_SHADOW_MAX_MAPS " + std::to_string(max_maps) + "u\n" + shadow_struct + grid_struct + light_struct;
	source += R"(
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) buffer Shadows { AreaShadowData data[]; } shadows;
layout(set = 0, binding = 1, std430) buffer Lights { AdaptiveLightData data[]; } lights;
void main() {
	shadows.data[1].bias += float(lights.data[1].grid.step);
}
)";
	String error;
	std::vector<uint32_t> spirv = rd->shader_compile_spirv_from_source(RenderingDevice::SHADER_STAGE_COMPUTE, source, "area_shadow_layout_probe", &error);
	INFO("glslang: ", error.c_str());
	REQUIRE(!spirv.empty());

	using SD = AreaShadowRendererRD::AreaShadowData;
	check_layout(spirv_struct_layout(spirv, "AreaShadowData"), "AreaShadowData",
			{ MEMBER(SD, light_from_view), MEMBER(SD, half_size), MEMBER(SD, depth_scale), MEMBER(SD, bias), MEMBER(SD, normal_bias), MEMBER(SD, pcf_radius),
					MEMBER(SD, map_count), MEMBER(SD, mode), MEMBER(SD, atlas_subdivision), MEMBER(SD, atlas_texel), MEMBER(SD, quadrant_size),
					MEMBER(SD, tile_size), MEMBER(SD, maps) },
			sizeof(SD));
	CHECK(sizeof(SD) == 448);

	using LD = AreaShadowAdaptiveRD::AdaptiveLightData;
	check_layout(spirv_struct_layout(spirv, "AdaptiveLightData"), "AdaptiveLightData",
			{ MEMBER(LD, light_from_view), MEMBER(LD, half_size), MEMBER(LD, depth_scale), MEMBER(LD, bias), MEMBER(LD, atlas_subdivision),
					MEMBER(LD, quadrant_size), MEMBER(LD, tile_size), MEMBER(LD, point_offset), MEMBER(LD, point_count), MEMBER(LD, words),
					MEMBER(LD, query_offset), MEMBER(LD, query_count), MEMBER(LD, grid) },
			sizeof(LD));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[LightStorage] the SPIR-V layout reader notices a wrong offset") {
	// The parser itself must be able to fail: a struct with a vec3 after a float gets std430 padding.
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	String error;
	String source = "#version 450\nstruct Probe { float a; vec3 b; };\nlayout(local_size_x = 1) in;\n"
					"layout(set = 0, binding = 0, std430) buffer B { Probe data[]; } buf;\nvoid main() { buf.data[0].a = 1.0; }\n";
	std::vector<uint32_t> spirv = rd->shader_compile_spirv_from_source(RenderingDevice::SHADER_STAGE_COMPUTE, source, "probe", &error);
	REQUIRE(!spirv.empty());
	SPIRVStructLayout layout = spirv_struct_layout(spirv, "Probe");
	REQUIRE(layout.found);
	CHECK(layout.member_offsets["a"] == 0);
	CHECK(layout.member_offsets["b"] == 16); // Not 4: a packed C++ {float a; float b[3];} would be wrong.
	CHECK(layout.array_stride == 32);
}

// Offsets of the members of the block (or struct) p_name in p_spirv against the C++ mirror; every
// GLSL member must be listed. Blocks are not arrays, so no stride is compared.
static void check_block(const std::vector<uint32_t> &p_spirv, const char *p_name, const std::vector<std::pair<String, uint32_t>> &p_members) {
	INFO("block ", p_name);
	const SPIRVStructLayout layout = spirv_struct_layout(p_spirv, p_name);
	REQUIRE(layout.found);
	CHECK(layout.member_offsets.size() == p_members.size());
	for (const auto &m : p_members) {
		INFO("member ", m.first.c_str());
		REQUIRE(layout.member_offsets.count(m.first) == 1);
		CHECK(layout.member_offsets.at(m.first) == m.second);
	}
}

// Stage p_stage of the production shader p_file (variant defines p_defines) as the renderer composes
// it, compiled to SPIR-V.
static std::vector<uint32_t> compile_production_stage(RenderingDevice *p_rd, const char *p_file, const String &p_defines, RenderingDevice::ShaderStage p_stage) {
	ShaderRD shader;
	REQUIRE(shader.initialize(p_file, { p_defines }));
	const String source = shader.get_stage_source(p_stage, 0);
	REQUIRE(!source.empty());
	String error;
	std::vector<uint32_t> spirv = p_rd->shader_compile_spirv_from_source(p_stage, source, p_file, &error);
	INFO(p_file, " glslang: ", error.c_str());
	REQUIRE(!spirv.empty());
	return spirv;
}

#define PAD4(m_struct, m_array, m_prefix)                                                                                 \
	{ m_prefix "0", uint32_t(offsetof(m_struct, m_array)) }, { m_prefix "1", uint32_t(offsetof(m_struct, m_array) + 4) }, \
			{ m_prefix "2", uint32_t(offsetof(m_struct, m_array) + 8) }, {                                                \
		m_prefix "3", uint32_t(offsetof(m_struct, m_array) + 12)                                                          \
	}

TEST_CASE("[RenderForwardClustered] the scene UBO, push constants and the other pass blocks match the production shaders' SPIR-V") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");

	// The colour pass with every optional block compiled in.
	const String scene_defines = "#define USE_AREA_LIGHTS\n#define USE_DIRECTIONAL_LIGHTS\n#define USE_DIRECTIONAL_SHADOWS\n#define USE_SKY_AMBIENT\n#define USE_SKY_REFLECTION\n#define AREA_METHOD_LTC\n";
	const std::vector<uint32_t> scene_fragment = compile_production_stage(rd, "forward_clustered/scene_forward_clustered.glsl", scene_defines, RenderingDevice::SHADER_STAGE_FRAGMENT);
	using SU = RenderForwardClustered::SceneDataUBO;
	check_block(scene_fragment, "SceneDataBlock",
			{ MEMBER(SU, clip_from_view), MEMBER(SU, view_from_clip), MEMBER(SU, view_from_world), MEMBER(SU, world_from_view), MEMBER(SU, viewport_size),
					MEMBER(SU, z_near), MEMBER(SU, z_far), MEMBER(SU, ambient_light), MEMBER(SU, omni_light_count), MEMBER(SU, spot_light_count),
					MEMBER(SU, cluster_tiles_x), MEMBER(SU, cluster_tile_count), MEMBER(SU, cluster_words_per_type), MEMBER(SU, flags),
					MEMBER(SU, area_light_count), MEMBER(SU, debug_cluster_type), MEMBER(SU, cluster_tile_size),
					MEMBER(SU, pad_scene0), MEMBER(SU, pad_scene1), MEMBER(SU, pad_scene2) });
	using DL = RendererRD::LightStorage::DirectionalLightData;
	check_block(scene_fragment, "DirectionalLightData",
			{ MEMBER(DL, direction), MEMBER(DL, energy), MEMBER(DL, color), MEMBER(DL, size), MEMBER(DL, specular_amount), MEMBER(DL, cull_mask),
					MEMBER(DL, flags), MEMBER(DL, shadow_index) });
	using DS = DirectionalShadowRD::ShadowData;
	check_block(scene_fragment, "DirectionalShadowData",
			{ MEMBER(DS, shadow_from_view), MEMBER(DS, split_end), MEMBER(DS, bias), MEMBER(DS, normal_bias), MEMBER(DS, radius),
					MEMBER(DS, depth_range), MEMBER(DS, uv_rect), MEMBER(DS, params), MEMBER(DS, params2) });
	using MU = RendererRD::MaterialStorage::MaterialUBO;
	check_block(scene_fragment, "MaterialBlock",
			{ MEMBER(MU, albedo), MEMBER(MU, emission), MEMBER(MU, roughness), MEMBER(MU, metallic), MEMBER(MU, specular), MEMBER(MU, normal_scale),
					MEMBER(MU, flags), MEMBER(MU, diffuse_mode), MEMBER(MU, alpha_scissor_threshold), MEMBER(MU, pad1), MEMBER(MU, uv1), MEMBER(MU, roughness_channel),
					MEMBER(MU, metallic_channel) });
	using SA = SkyRD::SkyAmbientUBO;
	check_block(scene_fragment, "SkyAmbient", { MEMBER(SA, sh), MEMBER(SA, pad) });

	const std::vector<uint32_t> scene_vertex = compile_production_stage(rd, "forward_clustered/scene_forward_clustered.glsl", scene_defines, RenderingDevice::SHADER_STAGE_VERTEX);
	using DP = RenderForwardClustered::DrawPushConstant;
	check_block(scene_vertex, "DrawData",
			{ MEMBER(DP, world_from_model), MEMBER(DP, normal_matrix), MEMBER(DP, layer_mask), MEMBER(DP, flags), MEMBER(DP, pad0), MEMBER(DP, pad1) });

	using BP = ClusterBuilderRD::BuildPushConstant;
	check_block(compile_production_stage(rd, "cluster_build.glsl", "#define CLUSTER_TYPE 0\n", RenderingDevice::SHADER_STAGE_COMPUTE), "Params",
			{ MEMBER(BP, view_from_clip), MEMBER(BP, screen_size), MEMBER(BP, z_far), MEMBER(BP, words_per_type), MEMBER(BP, tiles_x), MEMBER(BP, tiles_y),
					MEMBER(BP, tile_size), MEMBER(BP, pad0), MEMBER(BP, element_count) });

	using DD = AreaShadowRendererRD::DepthPushConstant;
	check_block(compile_production_stage(rd, "area_shadow_depth.glsl", "", RenderingDevice::SHADER_STAGE_VERTEX), "DrawData",
			{ MEMBER(DD, octant_view_from_model), MEMBER(DD, params) });

	using RP = AreaShadowAdaptiveRD::ReprojectionPushConstant;
	check_block(compile_production_stage(rd, "area_shadow_reprojection.glsl", "", RenderingDevice::SHADER_STAGE_COMPUTE), "Params",
			{ MEMBER(RP, view_from_clip), MEMBER(RP, depth_size), MEMBER(RP, max_cells), MEMBER(RP, light_count), PAD4(RP, pad, "pad") });

	using BD = AreaShadowAdaptiveRD::BandingPushConstant;
	check_block(compile_production_stage(rd, "area_shadow_banding.glsl", "", RenderingDevice::SHADER_STAGE_COMPUTE), "Params",
			{ MEMBER(BD, max_cells), MEMBER(BD, light_count), { "pad0", uint32_t(offsetof(BD, pad)) }, { "pad1", uint32_t(offsetof(BD, pad) + 4) } });

	using SK = SkyRD::SkyDataUBO;
	check_block(compile_production_stage(rd, "sky.glsl", "", RenderingDevice::SHADER_STAGE_FRAGMENT), "SkyDataBlock",
			{ MEMBER(SK, view_from_clip), MEMBER(SK, world_from_view), MEMBER(SK, viewport_size), MEMBER(SK, sky_top), MEMBER(SK, sky_horizon),
					MEMBER(SK, ground_bottom), MEMBER(SK, ground_horizon), MEMBER(SK, curves), MEMBER(SK, sun_direction), MEMBER(SK, sun_radiance),
					MEMBER(SK, rayleigh_beta), MEMBER(SK, mie_beta), MEMBER(SK, physical_ground), MEMBER(SK, physical_sun), MEMBER(SK, physical_disk) });
	using SR = SkyRD::RadiancePushConstant;
	check_block(compile_production_stage(rd, "sky_radiance.glsl", "", RenderingDevice::SHADER_STAGE_COMPUTE), "Params",
			{ MEMBER(SR, face), MEMBER(SR, size), MEMBER(SR, alpha), MEMBER(SR, sample_count) });
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestLightDataLayout
