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
/* ClusterBuilderRD::ElementData.                                         */

#include "servers/rendering/renderer_rd/cluster_builder_rd.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>

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

static String read_text(const String &p_path) {
	std::ifstream f(p_path);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
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

#define MEMBER(m_struct, m_name) { #m_name, uint32_t(offsetof(m_struct, m_name)) }

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
					MEMBER(AD, specular_amount), MEMBER(AD, normal), MEMBER(AD, shading_method), MEMBER(AD, color), MEMBER(AD, cull_mask) },
			sizeof(AD));

	using ED = ClusterBuilderRD::ElementData;
	check_layout(spirv_struct_layout(spirv, "ClusterElementData"), "ClusterElementData",
			{ MEMBER(ED, position), MEMBER(ED, radius), MEMBER(ED, direction), MEMBER(ED, cone_cos), MEMBER(ED, extents), MEMBER(ED, cone_sin),
					MEMBER(ED, axis_x), MEMBER(ED, pad0) },
			sizeof(ED));
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

} // namespace TestLightDataLayout
