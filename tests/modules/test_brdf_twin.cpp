/**************************************************************************/
/*  test_brdf_twin.cpp                                                    */
/**************************************************************************/
/* godot-area: proves that the reference renderer's C++ BRDF and light    */
/* functions (modules/reference/brdf.h, forward_lights.h) are the GPU's:  */
/* a compute shader that includes the real servers/rendering/renderer_rd/shaders/brdf_inc.glsl,         */
/* light_data_inc.glsl and scene_forward_lights_inc.glsl (read from disk, */
/* not copied) evaluates them at 12 288 random tuples on lavapipe, and    */
/* the C++ twins must agree within 1e-4 relative (values above 1e-6).     */

#include "modules/reference/forward_lights.h"
#include "modules/reference/sampling.h"

#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#ifndef GODOT_AREA_ROOT
#define GODOT_AREA_ROOT "."
#endif

namespace TestBRDFTwin {

static String read_shader(const String &p_name) {
	std::ifstream f(String(GODOT_AREA_ROOT) + "/servers/rendering/renderer_rd/shaders/" + p_name);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

// One tuple (std430, 8 x vec4 = 128 bytes). Must match struct Tuple in the shader below.
struct Tuple {
	float n[4]; // xyz unit normal.
	float v[4]; // xyz unit view vector.
	float l[4]; // xyz unit light vector.
	float dots[4]; // NoV, NoL, NoH, LoH (computed on the CPU; the BRDF functions take these).
	float f0[4]; // rgb f0, w = metallic.
	float p0[4]; // roughness, specular_amount, distance, inv_range.
	float p1[4]; // decay, cone_angle, cone_attenuation, unused.
	float axis[4]; // xyz spot axis.
};
static_assert(sizeof(Tuple) == 128, "Tuple must match the shader's std430 layout.");

static const int OUT_VEC4_PER_TUPLE = 4;

static const char *twin_main = R"(
struct Tuple {
	vec4 n;
	vec4 v;
	vec4 l;
	vec4 dots;
	vec4 f0;
	vec4 p0;
	vec4 p1;
	vec4 axis;
};
layout(set = 0, binding = 0, std430) restrict readonly buffer Inputs { Tuple data[]; } inputs;
layout(set = 0, binding = 1, std430) restrict writeonly buffer Outputs { vec4 data[]; } outputs;
layout(push_constant, std430) uniform Params { uint count; uint pad0; uint pad1; uint pad2; } params;

void main() {
	uint i = gl_GlobalInvocationID.x;
	if (i >= params.count) {
		return;
	}
	Tuple t = inputs.data[i];
	float NoV = t.dots.x, NoL = t.dots.y, NoH = t.dots.z, LoH = t.dots.w;
	float roughness = t.p0.x;
	float metallic = t.f0.w;
	float alpha = roughness * roughness;
	float f90 = brdf_specular_f90(t.f0.rgb, metallic);
	vec3 spec = brdf_specular(NoV, NoL, NoH, LoH, roughness, t.f0.rgb, f90);
	outputs.data[i * 4u + 0u] = vec4(spec, f90);
	outputs.data[i * 4u + 1u] = vec4(brdf_diffuse(BRDF_DIFFUSE_BURLEY, NoV, NoL, LoH, roughness), brdf_diffuse(BRDF_DIFFUSE_LAMBERT, NoV, NoL, LoH, roughness), D_GGX(NoH, alpha), V_SmithGGXCorrelatedFast(NoV, NoL, alpha));
	vec3 diffuse_light = vec3(0.0);
	vec3 specular_light = vec3(0.0);
	light_compute(t.n.xyz, t.l.xyz, t.v.xyz, vec3(1.0, 0.5, 0.25), t.p0.y, BRDF_DIFFUSE_BURLEY, roughness, t.f0.rgb, f90, true, diffuse_light, specular_light);
	outputs.data[i * 4u + 2u] = vec4(diffuse_light.x, specular_light);
	float att = get_omni_attenuation(t.p0.z, t.p0.w, t.p1.x);
	float cone = get_spot_cone_attenuation(-t.l.xyz, t.axis.xyz, t.p1.y, t.p1.z);
	outputs.data[i * 4u + 3u] = vec4(att, cone, F_Schlick(t.f0.r, f90, LoH), Fd_Burley(NoV, NoL, LoH, roughness));
}
)";

static Vector3 random_unit(ReferenceRNG &r_rng) {
	float z = 1.0f - 2.0f * r_rng.next_float();
	float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
	float phi = 2.0f * float(Math::PI) * r_rng.next_float();
	return Vector3(r * std::cos(phi), r * std::sin(phi), z);
}

// Relative difference check: |a - b| <= 1e-4 |b| where |b| > 1e-6 (else |a - b| <= 1e-10).
static bool agrees(float p_gpu, float p_cpu) {
	float d = std::fabs(p_gpu - p_cpu);
	if (std::fabs(p_cpu) > 1e-6f) {
		return d <= 1e-4f * std::fabs(p_cpu);
	}
	return d <= 1e-10f + 1e-4f * std::fabs(p_cpu) || std::fabs(p_gpu) <= 1e-6f;
}

TEST_CASE("[BRDF] GLSL brdf_inc.glsl and scene_forward_lights_inc.glsl equal their C++ twins at 12288 random tuples") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");

	String brdf = read_shader("brdf_inc.glsl");
	String light_data = read_shader("light_data_inc.glsl");
	String lights = read_shader("scene_forward_lights_inc.glsl");
	REQUIRE_MESSAGE(brdf.find("D_GGX") != String::npos, "servers/rendering/renderer_rd/shaders/brdf_inc.glsl is readable");
	REQUIRE_MESSAGE(lights.find("light_compute") != String::npos, "servers/rendering/renderer_rd/shaders/scene_forward_lights_inc.glsl is readable");
	String source = String("#version 450\nlayout(local_size_x = 64) in;\n") + brdf + "\n" + light_data + "\n" + lights + "\n" + twin_main;

	String err;
	RenderingDevice::ShaderStageSPIRVData stage;
	stage.shader_stage = RenderingDevice::SHADER_STAGE_COMPUTE;
	stage.spirv = rd->shader_compile_spirv_from_source(RenderingDevice::SHADER_STAGE_COMPUTE, source, "brdf_twin", &err);
	INFO(err);
	REQUIRE(!stage.spirv.empty());
	RID shader = rd->shader_create_from_spirv({ stage }, "brdf_twin");
	REQUIRE(shader.is_valid());

	// Random tuples: n, v, l on the sphere with v, l flipped into n's hemisphere (light_compute also
	// sees a few back-facing l through the unflipped copy), roughness 0.02..1, metallic 0..1, f0 from
	// Godot's formula or random, attenuation parameters over their useful ranges.
	const uint32_t count = 12288;
	std::vector<Tuple> tuples(count);
	ReferenceRNG rng(2024, 11);
	for (uint32_t i = 0; i < count; i++) {
		Tuple &t = tuples[i];
		memset(&t, 0, sizeof(t));
		Vector3 n = random_unit(rng);
		Vector3 v = random_unit(rng);
		Vector3 l = random_unit(rng);
		if (v.dot(n) < 0.0f) {
			v = -v;
		}
		if (l.dot(n) < 0.0f && (i % 8) != 0) {
			l = -l;
		}
		Vector3 h = (v + l).normalized();
		float NoV = std::max(n.dot(v), 1e-4f);
		float NoL = std::max(n.dot(l), 1e-4f);
		float NoH = ReferenceBRDF::glsl_clamp(n.dot(h), 0.0f, 1.0f);
		float LoH = ReferenceBRDF::glsl_clamp(l.dot(h), 0.0f, 1.0f);
		float roughness = 0.02f + 0.98f * rng.next_float();
		float metallic = rng.next_float();
		Vector3 f0;
		if (i % 2) {
			f0 = Vector3(rng.next_float(), rng.next_float(), rng.next_float());
		} else {
			float s = rng.next_float();
			float d = 0.16f * s * s;
			Vector3 albedo(rng.next_float(), rng.next_float(), rng.next_float());
			f0 = Vector3(d, d, d) * (1.0f - metallic) + albedo * metallic;
		}
		float range = 0.5f + 20.0f * rng.next_float();
		float distance = range * 1.1f * rng.next_float();
		float decay = 3.0f * rng.next_float();
		float cone_angle = std::cos(float(Math::PI) * 0.5f * rng.next_float());
		float cone_att = 0.1f + 4.0f * rng.next_float();
		Vector3 axis = -l + random_unit(rng) * (0.5f * rng.next_float()); // Near the light direction.
		axis = axis.normalized();
		const float vals[8][4] = {
			{ n.x, n.y, n.z, 0 },
			{ v.x, v.y, v.z, 0 },
			{ l.x, l.y, l.z, 0 },
			{ NoV, NoL, NoH, LoH },
			{ f0.x, f0.y, f0.z, metallic },
			{ roughness, 0.25f + rng.next_float(), distance, 1.0f / range },
			{ decay, cone_angle, cone_att, 0 },
			{ axis.x, axis.y, axis.z, 0 },
		};
		memcpy(&t, vals, sizeof(vals));
	}

	RID in_buf = rd->storage_buffer_create(count * sizeof(Tuple), tuples.data());
	RID out_buf = rd->storage_buffer_create(count * OUT_VEC4_PER_TUPLE * 16);
	REQUIRE(in_buf.is_valid());
	REQUIRE(out_buf.is_valid());
	RID set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, in_buf), RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, out_buf) }, shader, 0);
	REQUIRE(set.is_valid());
	RID pipeline = rd->compute_pipeline_create(shader);
	REQUIRE(pipeline.is_valid());
	uint32_t params[4] = { count, 0, 0, 0 };
	RD::ComputeListID list = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(list, pipeline);
	rd->compute_list_bind_uniform_set(list, set, 0);
	rd->compute_list_set_push_constant(list, params, sizeof(params));
	rd->compute_list_dispatch_threads(list, count, 1, 1);
	rd->compute_list_end();
	std::vector<uint8_t> bytes = rd->buffer_get_data(out_buf);
	REQUIRE(bytes.size() == size_t(count) * OUT_VEC4_PER_TUPLE * 16);
	const float *gpu = reinterpret_cast<const float *>(bytes.data());

	using namespace ReferenceBRDF;
	int mismatches = 0;
	int compared = 0;
	float worst = 0.0f;
	int ill_conditioned = 0;
	for (uint32_t i = 0; i < count; i++) {
		const Tuple &t = tuples[i];
		Vector3 n(t.n[0], t.n[1], t.n[2]), v(t.v[0], t.v[1], t.v[2]), l(t.l[0], t.l[1], t.l[2]);
		float NoV = t.dots[0], NoL = t.dots[1], NoH = t.dots[2], LoH = t.dots[3];
		Vector3 f0(t.f0[0], t.f0[1], t.f0[2]);
		float metallic = t.f0[3], roughness = t.p0[0], alpha = roughness * roughness;
		float f90 = brdf_specular_f90(f0, metallic);
		Vector3 spec = brdf_specular(NoV, NoL, NoH, LoH, roughness, f0, f90);
		Vector3 diffuse_light, specular_light;
		light_compute(n, l, v, Vector3(1.0f, 0.5f, 0.25f), t.p0[1], BRDF_DIFFUSE_BURLEY, roughness, f0, f90, true, diffuse_light, specular_light);
		const float cpu[16] = {
			spec.x, spec.y, spec.z, f90,
			brdf_diffuse(BRDF_DIFFUSE_BURLEY, NoV, NoL, LoH, roughness), brdf_diffuse(BRDF_DIFFUSE_LAMBERT, NoV, NoL, LoH, roughness), D_GGX(NoH, alpha), V_SmithGGXCorrelatedFast(NoV, NoL, alpha),
			diffuse_light.x, specular_light.x, specular_light.y, specular_light.z,
			get_omni_attenuation(t.p0[2], t.p0[3], t.p1[0]), get_spot_cone_attenuation(-l, Vector3(t.axis[0], t.axis[1], t.axis[2]), t.p1[1], t.p1[2]), F_Schlick(f0.x, f90, LoH), Fd_Burley(NoV, NoL, LoH, roughness)
		};
		double a2 = double(alpha) * alpha;
		double fd = double(NoH) * NoH * (a2 - 1.0) + 1.0;
		float d_condition = float(4.0 * 1.1920929e-7 * double(NoH) * NoH * std::fabs(a2 - 1.0) / fd);
		if (d_condition > 1e-5f) {
			ill_conditioned++;
		}
		for (int k = 0; k < 16; k++) {
			float g = gpu[size_t(i) * 16 + k];
			compared++;
			// Value 13, the spot cone 1 - rim^e, cancels near the cone edge: one float ulp of pow() at
			// magnitude 1 (2^-23) is allowed on top, which is the conditioning of 1 - x, not a formula difference.
			// Values that contain D_GGX (0-2, 6, 9-11): near the peak of a sharp lobe its denominator
			// f = NoH^2 (alpha^2 - 1) + 1 cancels, and one rounding (or a fused multiply-add on the GPU)
			// changes D by about 2 * 2^-23 * NoH^2 |alpha^2 - 1| / f relative. That conditioning term is
			// allowed on top of 1e-4; it exceeds 1e-5 for only a handful of tuples (counted below).
			bool has_d = k <= 2 || k == 6 || (k >= 9 && k <= 11);
			float rel_tol = 1e-4f + (has_d ? d_condition : 0.0f);
			bool ok;
			if (k == 13) {
				ok = std::fabs(g - cpu[k]) <= 1e-4f * std::fabs(cpu[k]) + 1.2e-7f;
			} else if (std::fabs(cpu[k]) > 1e-6f) {
				ok = std::fabs(g - cpu[k]) <= rel_tol * std::fabs(cpu[k]);
			} else {
				ok = agrees(g, cpu[k]);
			}
			if (k != 13 && !has_d && std::fabs(cpu[k]) > 1e-6f) {
				worst = std::max(worst, std::fabs(g - cpu[k]) / std::fabs(cpu[k]));
			}
			if (!ok) {
				if (mismatches < 10) {
					MESSAGE(vformat("tuple %u value %d: GPU %.9g, C++ %.9g (roughness %.4f NoH %.7f)", i, k, g, cpu[k], roughness, NoH));
				}
				mismatches++;
			}
		}
	}
	MESSAGE(vformat("BRDF twin: %d values compared, worst relative difference without D_GGX and cone %.3g; %d tuples near a sharp GGX peak", compared, worst, ill_conditioned));
	CHECK(compared == int(count) * 16);
	CHECK(mismatches == 0);

	rd->free(pipeline);
	rd->free(set);
	rd->free(out_buf);
	rd->free(in_buf);
	rd->free(shader);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestBRDFTwin
