/**************************************************************************/
/*  rd_test_shaders.h                                                     */
/**************************************************************************/
/* Shared test helpers for RenderingDevice tests that build their own     */
/* shaders: GLSL -> shader RID (each stage must compile) and a vertex     */
/* shader covering the viewport with one procedural triangle.             */

#pragma once

#include "servers/rendering/rendering_device.h"

#include <doctest/doctest.h>

#include <utility>
#include <vector>

// Compiles GLSL stages with glslang and creates the shader; each stage must compile (glslang's log is shown).
inline RID rd_test_compile_shader(RenderingDevice *p_rd, const std::vector<std::pair<RenderingDevice::ShaderStage, String>> &p_sources, const String &p_name) {
	std::vector<RenderingDevice::ShaderStageSPIRVData> stages;
	for (const auto &src : p_sources) {
		String err;
		RenderingDevice::ShaderStageSPIRVData sd;
		sd.shader_stage = src.first;
		sd.spirv = p_rd->shader_compile_spirv_from_source(src.first, src.second, p_name, &err);
		INFO(err);
		REQUIRE(!sd.spirv.empty());
		stages.push_back(sd);
	}
	return p_rd->shader_create_from_spirv(stages, p_name);
}

// A vertex shader whose three procedural vertices (draw_list_draw(list, false, 1, 3)) cover the viewport.
constexpr const char *RD_TEST_FULLSCREEN_VS = R"(#version 450
void main() {
	vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
	gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
