/**************************************************************************/
/*  test_area_light_ltc_horizon.cpp                                       */
/**************************************************************************/
/* godot-area: LTC surface-horizon clipping (issue #18). At grazing views */
/* the LTC lobe has mass below the receiver's plane; a light crossing the */
/* plane must light the receiver only through its part above the plane.  */
/* light_process_area_ltc (area_light_ltc_inc.glsl, on the GPU) shades a  */
/* glossy metal floor seen 10 degrees above it under three vertical       */
/* lights: A crosses the plane (y in [-0.5, 0.5]), B is A cropped to the  */
/* part above (y in [0, 0.5]), C is wholly below (y in [-1.1, -0.1]).     */
/* With the clipping A equals B to float rounding and C gives exactly 0;  */
/* without it A is brighter than B and C is not 0.                        */

#include "servers/rendering/renderer_rd/effects/ltc_lut_rd.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace TestAreaLightLTCHorizon {

static const char *HORIZON_COMPUTE = R"(#[compute]
#version 450
#include "brdf_inc.glsl"
#include "light_data_inc.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) buffer Out { vec4 values[]; } out_buf;
layout(set = 0, binding = 1) uniform texture2DArray ltc_lut_texture;
layout(set = 0, binding = 2) uniform sampler ltc_lut_sampler;
layout(push_constant, std430) uniform Params { float roughness; uint count; uint side; uint pad; } params;
#include "area_light_ltc_inc.glsl"
AreaLightData make_light(float p_centre_y, float p_half_height) {
	AreaLightData l;
	l.position = vec3(0.0, p_centre_y, -1.0);
	l.inv_radius = 0.001;
	l.half_axis_x = vec3(0.5, 0.0, 0.0);
	l.attenuation = 2.0;
	l.half_axis_y = vec3(0.0, p_half_height, 0.0);
	l.specular_amount = 1.0;
	l.normal = vec3(0.0, 0.0, 1.0);
	l.shading_method = 0u;
	l.color = vec3(1.0);
	l.cull_mask = 0xFFFFFFFFu;
	return l;
}
void main() {
	uint i = gl_GlobalInvocationID.x;
	if (i >= params.count) {
		return;
	}
	vec2 uv = (vec2(i % params.side, i / params.side) + 0.5) / float(params.side);
	vec3 p = vec3(uv.x * 4.0 - 2.0, 0.0, uv.y * 3.0 - 0.8);
	vec3 camera = vec3(0.0, 3.5 * sin(radians(10.0)), 3.5 * cos(radians(10.0)));
	vec3 V = normalize(camera - p);
	vec3 N = vec3(0.0, 1.0, 0.0);
	vec3 da = vec3(0.0), sa = vec3(0.0), db = vec3(0.0), sb = vec3(0.0), dc = vec3(0.0), sc = vec3(0.0);
	light_process_area_ltc(make_light(0.0, 0.5), p, N, V, params.roughness, vec3(1.0), 1.0, true, false, da, sa);
	light_process_area_ltc(make_light(0.25, 0.25), p, N, V, params.roughness, vec3(1.0), 1.0, true, false, db, sb);
	light_process_area_ltc(make_light(-0.6, 0.5), p, N, V, params.roughness, vec3(1.0), 1.0, true, false, dc, sc);
	out_buf.values[i] = vec4(sa.x, sb.x, sc.x + dc.x, da.x - db.x);
}
)";

struct Params {
	float roughness;
	uint32_t count;
	uint32_t side;
	uint32_t pad;
};

TEST_CASE("[AreaLight3D][LTC] a light crossing the receiver's plane lights it only through its part above (GPU)") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShaderRD shader_rd;
		REQUIRE(shader_rd.initialize_from_source(HORIZON_COMPUTE, "ltc_horizon", { "#define AREA_METHOD_LTC\n" }));
		RID shader = shader_rd.version_get_shader(0);
		REQUIRE_MESSAGE(shader.is_valid(), shader_rd.get_last_error());
		LTCLutRD lut;
		REQUIRE(lut.initialize());
		const uint32_t side = 48, count = side * side;
		RID buffer = rd->storage_buffer_create(count * 16);
		REQUIRE(buffer.is_valid());
		RID set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, buffer), RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 1, lut.get_texture()),
												 RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 2, lut.get_sampler()) },
				shader, 0);
		REQUIRE(set.is_valid());
		RID pipeline = rd->compute_pipeline_create(shader);
		REQUIRE(pipeline.is_valid());
		for (float roughness : { 0.25f, 0.5f, 0.8f }) {
			Params params = { roughness, count, side, 0 };
			RD::ComputeListID list = rd->compute_list_begin();
			rd->compute_list_bind_compute_pipeline(list, pipeline);
			rd->compute_list_bind_uniform_set(list, set, 0);
			rd->compute_list_set_push_constant(list, &params, sizeof(params));
			rd->compute_list_dispatch_threads(list, count, 1, 1);
			rd->compute_list_end();
			rd->submit();
			rd->sync();
			std::vector<uint8_t> data = rd->buffer_get_data(buffer);
			REQUIRE(data.size() == count * 16);
			const float *v = reinterpret_cast<const float *>(data.data());
			double peak = 0.0, max_diff = 0.0, below_max = 0.0, diffuse_diff = 0.0, sum_a = 0.0, sum_b = 0.0;
			int non_finite = 0;
			for (uint32_t i = 0; i < count; i++) {
				for (int c = 0; c < 4; c++) {
					non_finite += std::isfinite(v[i * 4 + c]) ? 0 : 1;
				}
				peak = std::max(peak, double(v[i * 4 + 1]));
				max_diff = std::max(max_diff, std::fabs(double(v[i * 4]) - double(v[i * 4 + 1])));
				sum_a += v[i * 4];
				sum_b += v[i * 4 + 1];
				below_max = std::max(below_max, std::fabs(double(v[i * 4 + 2])));
				diffuse_diff = std::max(diffuse_diff, std::fabs(double(v[i * 4 + 3])));
			}
			MESSAGE("roughness ", roughness, ": peak specular of the cropped light ", peak, ", max |crossing - cropped| ", max_diff, ", brightness ratio crossing / cropped ", sum_a / sum_b,
					", light wholly below: ", below_max);
			CHECK(non_finite == 0);
			REQUIRE(peak > 0.0);
			CHECK(max_diff <= 2e-4 * peak); // Float rounding of two different polygons with the same spherical image.
			CHECK(sum_a / sum_b == doctest::Approx(1.0).epsilon(1e-4));
			CHECK(below_max == 0.0); // Below the surface: neither diffuse nor specular.
			CHECK(diffuse_diff <= 2e-4 * peak); // The Lambert term clipped at the horizon already.
		}
		rd->free(pipeline);
		rd->free(set);
		rd->free(buffer);
		lut.finalize();
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightLTCHorizon
