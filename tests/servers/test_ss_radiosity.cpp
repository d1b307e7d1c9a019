/**************************************************************************/
/*  test_ss_radiosity.cpp                                                 */
/**************************************************************************/
/* godot-area: image-space radiosity (SSIL/SSAO, issue 22, seed 003).     */
/* The GLSL terms (shaders/effects/ss_radiosity_inc.glsl) run on the GPU  */
/* against hand-computed values; the pass is checked for cost (nothing    */
/* without SSIL/SSAO), determinism and, in a Cornell-like room, against   */
/* the Embree one-bounce truth.                                           */

#include "modules/benchmark/isr_sweep.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

namespace TestSSRadiosity {

// Each case: inputs a, b, c, d (vec4) and a mode; out = vec4.
static const char *TERMS_COMPUTE = R"(#[compute]
#version 450
#include "effects/ss_radiosity_inc.glsl"
layout(local_size_x = 1) in;
struct Case { vec4 a; vec4 b; vec4 c; vec4 d; };
layout(set = 0, binding = 0, std430) restrict readonly buffer In { Case cases[]; } in_buf;
layout(set = 0, binding = 1, std430) restrict writeonly buffer Out { vec4 values[]; } out_buf;
void main() {
	uint i = gl_GlobalInvocationID.x;
	Case k = in_buf.cases[i];
	uint mode = uint(k.d.w);
	vec4 r = vec4(0.0);
	if (mode == 0u) { // isr_form_factor(p = a.xyz, n_p = b.xyz, x = c.xyz, n_x = d.xyz, area = a.w, rejection = b.w)
		r.x = isr_form_factor(k.a.xyz, k.b.xyz, k.c.xyz, k.d.xyz, k.a.w, k.b.w);
	} else if (mode == 1u) { // isr_patch_radiance(rho = a.xyz, F = a.w, L = b.xyz)
		r.xyz = isr_patch_radiance(k.a.xyz, k.a.w, k.b.xyz);
	} else if (mode == 2u) { // isr_occlusion(p = a.xyz, n = b.xyz, x = c.xyz, r = a.w, N = b.w, horizon = c.w)
		r.x = isr_occlusion(k.a.xyz, k.b.xyz, k.c.xyz, k.a.w, k.b.w, k.c.w);
	} else if (mode == 3u) { // isr_bilateral_weights(f = a.xy, z = b, z_p = a.z, eps = c.x, match = c.y)
		r = isr_bilateral_weights(k.a.xy, k.b, k.a.z, k.c.x, k.c.y);
	} else if (mode == 4u) { // isr_view_position(ndc = a.xy, d = a.z, proj_xy = b, proj_zw = c)
		r.xyz = isr_view_position(k.a.xy, k.a.z, k.b, k.c);
	} else if (mode == 5u) { // isr_linear_depth(depth = a.x, P22 = b.x, P32 = b.y, P23 = b.z, P33 = b.w)
		r.x = isr_linear_depth(k.a.x, k.b.x, k.b.y, k.b.z, k.b.w);
	} else if (mode == 6u) { // isr_pack(rgb = a.xyz, a = a.w, normal = b.xyz, depth = b.w): out = unpacked normal, depth
		uvec4 t = isr_pack(k.a.xyz, k.a.w, k.b.xyz, k.b.w);
		r = vec4(isr_unpack_normal(t), isr_unpack_depth(t));
	} else if (mode == 7u) { // the same: out = unpacked value
		r = isr_unpack_value(isr_pack(k.a.xyz, k.a.w, k.b.xyz, k.b.w));
	}
	out_buf.values[i] = r;
}
)";

struct TermCase {
	float a[4] = { 0, 0, 0, 0 };
	float b[4] = { 0, 0, 0, 0 };
	float c[4] = { 0, 0, 0, 0 };
	float d[4] = { 0, 0, 0, 0 };
};
static_assert(sizeof(TermCase) == 64, "TermCase must match Case in TERMS_COMPUTE.");

static void _set(float *r_v, float p_x, float p_y, float p_z, float p_w) {
	r_v[0] = p_x;
	r_v[1] = p_y;
	r_v[2] = p_z;
	r_v[3] = p_w;
}

// Runs every case through the GLSL terms; returns one vec4 per case (empty on failure).
static std::vector<float> _run_terms(RenderingDevice *p_rd, const std::vector<TermCase> &p_cases) {
	std::vector<float> out;
	ShaderRD shader_rd;
	REQUIRE(shader_rd.initialize_from_source(TERMS_COMPUTE, "ss_radiosity_terms", { "" }));
	RID shader = shader_rd.version_get_shader(0);
	REQUIRE_MESSAGE(shader.is_valid(), shader_rd.get_last_error());
	const uint32_t count = uint32_t(p_cases.size());
	RID in = p_rd->storage_buffer_create(count * sizeof(TermCase), p_cases.data());
	RID buf = p_rd->storage_buffer_create(count * 16);
	RID set = p_rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, in), RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, buf) }, shader, 0);
	RID pipeline = p_rd->compute_pipeline_create(shader);
	REQUIRE(pipeline.is_valid());
	RD::ComputeListID list = p_rd->compute_list_begin();
	p_rd->compute_list_bind_compute_pipeline(list, pipeline);
	p_rd->compute_list_bind_uniform_set(list, set, 0);
	p_rd->compute_list_dispatch(list, count, 1, 1);
	p_rd->compute_list_end();
	p_rd->submit();
	p_rd->sync();
	std::vector<uint8_t> data = p_rd->buffer_get_data(buf);
	if (data.size() == count * 16) {
		out.resize(count * 4);
		memcpy(out.data(), data.data(), data.size());
	}
	p_rd->free(pipeline);
	p_rd->free(in);
	p_rd->free(buf);
	return out;
}

TEST_CASE("[SSRadiosity] the form factor (eq. 6), patch radiance (eq. 25) and occlusion (eq. 26) terms match hand-computed values") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	std::vector<TermCase> cases;
	std::vector<double> expected;
	TermCase k;
	// Two patches facing each other 2 m apart, dA = 0.01 m^2: F = dA / (pi r^2 + dA) = 0.01 / (4 pi + 0.01).
	_set(k.a, 0, 0, 0, 0.01f);
	_set(k.b, 0, 0, 1, 1.0f);
	_set(k.c, 0, 0, 2, 0);
	_set(k.d, 0, 0, -1, 0);
	cases.push_back(k);
	expected.push_back(0.01 / (4.0 * Math::PI + 0.01));
	// 45 degrees off both normals at r^2 = 2, dA = 0.02: cos cos = 1/2, F = 0.01 / (2 pi + 0.02).
	_set(k.a, 0, 0, 0, 0.02f);
	_set(k.c, 1, 0, 1, 0);
	_set(k.d, -1, 0, 0, 0);
	cases.push_back(k);
	expected.push_back(0.01 / (2.0 * Math::PI + 0.02));
	// Behind the receiver: 0.
	_set(k.a, 0, 0, 0, 0.01f);
	_set(k.c, 0, 0, -2, 0);
	_set(k.d, 0, 0, 1, 0);
	cases.push_back(k);
	expected.push_back(0.0);
	// The emitter faces away: 0 with normal rejection 1 ...
	_set(k.c, 0, 0, 2, 0);
	_set(k.d, 0, 0, 1, 0);
	cases.push_back(k);
	expected.push_back(0.0);
	// ... and |cos| (the facing value) with normal rejection 0.
	_set(k.b, 0, 0, 1, 0.0f);
	cases.push_back(k);
	expected.push_back(0.01 / (4.0 * Math::PI + 0.01));
	// A large patch almost touching: the disk form factor stays below 1 (eq. 6 alone would be ~3e5).
	_set(k.a, 0, 0, 0, 1.0f);
	_set(k.b, 0, 0, 1, 1.0f);
	_set(k.c, 0, 0, 0.001f, 0);
	_set(k.d, 0, 0, -1, 0);
	cases.push_back(k);
	expected.push_back(1.0 / (Math::PI * 1e-6 + 1.0));
	for (TermCase &c : cases) {
		c.d[3] = 0; // Mode 0.
	}
	const size_t form_factor_cases = cases.size();
	// Eq. 25: rho F L per channel: (0.5, 0.25, 1) * 0.1 * (2, 4, 1) = (0.1, 0.1, 0.1).
	TermCase r;
	_set(r.a, 0.5f, 0.25f, 1.0f, 0.1f);
	_set(r.b, 2, 4, 1, 0);
	r.d[3] = 1;
	cases.push_back(r);
	// Eq. 26, N = 24: a sphere of radius 0.5 at 1 m straight above: 2 pi / 24 (1 - sqrt(3/4)).
	TermCase o;
	_set(o.a, 0, 0, 0, 0.5f);
	_set(o.b, 0, 0, 1, 24.0f);
	_set(o.c, 0, 0, 1, 0.0f);
	o.d[3] = 2;
	cases.push_back(o);
	// Radius 1 at 2 m, 60 degrees off the normal: times cos 60 = 1/2.
	_set(o.a, 0, 0, 0, 1.0f);
	_set(o.c, std::sqrt(3.0f), 0, 1, 0.0f);
	cases.push_back(o);
	// The same with ssao_horizon 0.2: (cos - 0.2) / 0.8 = 0.375.
	o.c[3] = 0.2f;
	cases.push_back(o);
	// p inside the sphere: the full 2 pi / N times cos.
	_set(o.a, 0, 0, 0, 3.0f);
	_set(o.c, 0, 0, 1, 0.0f);
	cases.push_back(o);
	const std::vector<float> v = _run_terms(rd, cases);
	REQUIRE(v.size() == cases.size() * 4);
	for (size_t i = 0; i < form_factor_cases; i++) {
		CHECK_MESSAGE(std::fabs(double(v[i * 4]) - expected[i]) <= 1e-5 * std::max(expected[i], 1e-3), vformat("form factor case %d: GPU %.8g, hand %.8g", int(i), v[i * 4], expected[i]));
	}
	const float *l = &v[form_factor_cases * 4];
	CHECK(std::fabs(l[0] - 0.1f) < 1e-6f);
	CHECK(std::fabs(l[1] - 0.1f) < 1e-6f);
	CHECK(std::fabs(l[2] - 0.1f) < 1e-6f);
	const double base = 2.0 * Math::PI / 24.0 * (1.0 - std::sqrt(0.75));
	const double occl[4] = { base, base * 0.5, base * 0.375, 2.0 * Math::PI / 24.0 };
	for (int i = 0; i < 4; i++) {
		const double g = v[(form_factor_cases + 1 + i) * 4];
		CHECK_MESSAGE(std::fabs(g - occl[i]) <= 1e-5 * occl[i], vformat("occlusion case %d: GPU %.8g, hand %.8g", i, g, occl[i]));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity] linear depth and view position are rebuilt from the depth-corrected projection to float precision (§4.3)") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const Projection projections[2] = {
		Projection::create_depth_correction(true) * Projection::create_perspective(60.0f, 4.0f / 3.0f, 0.05f, 50.0f),
		Projection::create_depth_correction(true) * Projection::create_orthogonal(-2.0f, 3.0f, -1.5f, 1.0f, 0.1f, 20.0f),
	};
	std::vector<TermCase> cases;
	std::vector<Vector3> points;
	for (int pi = 0; pi < 2; pi++) {
		const Projection &p = projections[pi];
		for (int i = 0; i < 16; i++) {
			// View points in front of the camera, spread over the frustum.
			const float d = 0.3f + 1.1f * float(i);
			const Vector3 view(0.37f * float((i % 5) - 2) * (pi == 0 ? d * 0.2f : 0.5f), 0.29f * float((i % 3) - 1) * (pi == 0 ? d * 0.2f : 0.5f), -d);
			const Vector4 clip = p.xform(Vector4(view.x, view.y, view.z, 1.0f));
			const double w = double(clip.w);
			TermCase k;
			_set(k.a, float(double(clip.x) / w), float(double(clip.y) / w), d, 0);
			_set(k.b, p.columns[0][0], p.columns[1][1], p.columns[2][0], p.columns[2][1]);
			_set(k.c, p.columns[3][0], p.columns[3][1], p.columns[2][3], p.columns[3][3]);
			k.d[3] = 4;
			cases.push_back(k);
			TermCase z;
			_set(z.a, float(double(clip.z) / w), 0, 0, 0);
			_set(z.b, p.columns[2][2], p.columns[3][2], p.columns[2][3], p.columns[3][3]);
			z.d[3] = 5;
			cases.push_back(z);
			points.push_back(view);
		}
	}
	const std::vector<float> v = _run_terms(rd, cases);
	REQUIRE(v.size() == cases.size() * 4);
	double worst_position = 0.0, worst_depth = 0.0;
	for (size_t i = 0; i < points.size(); i++) {
		const Vector3 &e = points[i];
		const float *pos = &v[i * 8];
		const double scale = std::max(1.0, double(e.length()));
		worst_position = std::max(worst_position, std::sqrt(double((pos[0] - e.x) * (pos[0] - e.x) + (pos[1] - e.y) * (pos[1] - e.y) + (pos[2] - e.z) * (pos[2] - e.z))) / scale);
		worst_depth = std::max(worst_depth, std::fabs(double(v[i * 8 + 4]) + double(e.z)) / double(-e.z));
	}
	MESSAGE(vformat("worst relative position error %.3g, worst relative linear depth error %.3g", worst_position, worst_depth));
	// Position from exact ndc and depth: a few float ulps. Depth from a float depth-buffer value: the
	// perspective depth's own precision (d^2 / near ulps) at d = 17 m, near 0.05 m is ~1e-4.
	CHECK(worst_position < 4e-6);
	CHECK(worst_depth < 2e-4);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity] bilateral upsampling weights (eqs. 27-28) sum to one and keep a silhouette that bilinear blurs") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	std::vector<TermCase> cases;
	auto add = [&cases](float p_fx, float p_fy, float p_zp, float z0, float z1, float z2, float z3) {
		TermCase k;
		_set(k.a, p_fx, p_fy, p_zp, 0);
		_set(k.b, z0, z1, z2, z3);
		_set(k.c, SSRadiosityRD::BILATERAL_EPS_RELATIVE, SSRadiosityRD::BILATERAL_MATCH_RELATIVE, 0, 0);
		k.d[3] = 3;
		cases.push_back(k);
	};
	add(0.75f, 0.5f, 1.0f, 1.0f, 5.0f, 1.0f, 5.0f); // Foreground pixel at z 1; samples 1 and 3 are background at 5.
	add(0.3f, 0.6f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f); // A surface facing the camera: exactly bilinear.
	add(0.5f, 0.5f, 1.0f, 3.0f, 4.0f, 5.0f, 6.0f); // No sample matches: the nearest depth alone.
	add(0.9f, 0.9f, 2.0f, 2.0f, 0.0f, 0.0f, 0.0f); // Three coarse samples without a surface.
	const std::vector<float> w = _run_terms(rd, cases);
	REQUIRE(w.size() == cases.size() * 4);
	for (size_t i = 0; i < cases.size(); i++) {
		const double sum = double(w[i * 4]) + w[i * 4 + 1] + w[i * 4 + 2] + w[i * 4 + 3];
		CHECK_MESSAGE(std::fabs(sum - 1.0) < 1e-5, vformat("case %d: weights sum to %.7f", int(i), sum));
	}
	// Silhouette: values 1 on the foreground samples, 0 on the background ones.
	const double values[4] = { 1.0, 0.0, 1.0, 0.0 };
	double bilateral = 0.0, bilinear = 0.0;
	const double fx = 0.75, fy = 0.5;
	const double wb[4] = { (1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy };
	for (int i = 0; i < 4; i++) {
		bilateral += w[i] * values[i];
		bilinear += wb[i] * values[i];
	}
	MESSAGE(vformat("silhouette pixel (foreground value 1): bilateral %.4f, plain bilinear %.4f", bilateral, bilinear));
	CHECK(bilateral > 0.99);
	CHECK_FALSE(bilinear > 0.99); // The test fails with plain bilinear weights (0.25 here).
	// Equal depths: the bilinear weights.
	const double fx2 = 0.3, fy2 = 0.6;
	const double wb2[4] = { (1 - fx2) * (1 - fy2), fx2 * (1 - fy2), (1 - fx2) * fy2, fx2 * fy2 };
	for (int i = 0; i < 4; i++) {
		CHECK(std::fabs(w[4 + i] - wb2[i]) < 1e-6);
	}
	CHECK(w[8] == doctest::Approx(1.0)); // Nearest depth (3) alone.
	CHECK(w[12] == doctest::Approx(1.0));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

/* Rendering */

struct GpuScene {
	RenderTest::RenderFixture f;
	std::vector<RID> meshes, materials, lights;
	RenderSceneData d;
	RID rt;
	int w = 0, h = 0;
	bool init(const IsrScene &p_scene, int p_frame, int p_w, int p_h) {
		if (!f.init()) {
			return false;
		}
		w = p_w;
		h = p_h;
		d = p_scene.make_view(p_frame, p_w, p_h);
		p_scene.build(f.mesh_storage, f.material_storage, f.light_storage, d, f.meshes, f.materials, f.lights);
		rt = f.renderer.render_target_create(p_w, p_h);
		return rt.is_valid();
	}
	std::vector<float> render() {
		f.renderer.render_scene(d, rt);
		return f.renderer.render_target_get_data(rt);
	}
	bool profile_has(const char *p_name) const {
		for (const auto &kv : f.renderer.get_last_frame_profile()) {
			if (kv.first == p_name) {
				return true;
			}
		}
		return false;
	}
	~GpuScene() {
		if (rt.is_valid()) {
			f.renderer.render_target_free(rt);
		}
	}
};

TEST_CASE("[SSRadiosity] a packed coarse texel keeps the value to half precision, the normal to 1e-4 and the depth exactly") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	// Normals over all octants (the octahedral fold for z < 0 included), the poles and an axis.
	const float normals[][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 }, { 0.48f, 0.6f, 0.64f }, { -0.48f, 0.6f, -0.64f }, { 0.6f, -0.48f, -0.64f }, { -0.36f, -0.48f, 0.8f }, { 0.0f, 0.6f, -0.8f } };
	std::vector<TermCase> cases;
	for (const float *n : normals) {
		TermCase k;
		_set(k.a, 0.1234f, 3.5f, 1000.0f, 0.0625f);
		_set(k.b, n[0], n[1], n[2], 17.318f);
		k.d[3] = 6;
		cases.push_back(k);
		k.d[3] = 7;
		cases.push_back(k);
	}
	const std::vector<float> v = _run_terms(rd, cases);
	REQUIRE(v.size() == cases.size() * 4);
	double worst_normal = 0.0;
	for (size_t i = 0; i < cases.size(); i += 2) {
		const float *n = cases[i].b;
		const float *g = &v[i * 4];
		worst_normal = std::max(worst_normal, double(std::sqrt((g[0] - n[0]) * (g[0] - n[0]) + (g[1] - n[1]) * (g[1] - n[1]) + (g[2] - n[2]) * (g[2] - n[2]))));
		CHECK(g[3] == 17.318f); // The depth is stored as a float: exact.
		const float *val = &v[(i + 1) * 4];
		const float in[4] = { 0.1234f, 3.5f, 1000.0f, 0.0625f };
		for (int c = 0; c < 4; c++) {
			CHECK(std::fabs(val[c] - in[c]) <= in[c] / 1024.0f); // Half floats: 11 significant bits.
		}
	}
	MESSAGE(vformat("packed normal: worst error %.2e", worst_normal));
	CHECK(worst_normal < 1e-4);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity] interleaved sampling: k x k pixels share the pattern, every pixel keeps at least one sample") {
	// k = min(4, floor(sqrt(N))) for Godot's 12 / 24 / 48 / 80 / 128 samples and small counts.
	CHECK(SSRadiosityRD::get_interleave(1) == 1u);
	CHECK(SSRadiosityRD::get_interleave(3) == 1u);
	CHECK(SSRadiosityRD::get_interleave(4) == 2u);
	CHECK(SSRadiosityRD::get_interleave(12) == 3u);
	CHECK(SSRadiosityRD::get_interleave(24) == 4u);
	CHECK(SSRadiosityRD::get_interleave(48) == 4u);
	CHECK(SSRadiosityRD::get_interleave(128) == 4u);
	for (int q = RS::ENV_SSIL_QUALITY_VERY_LOW; q <= RS::ENV_SSIL_QUALITY_ULTRA; q++) {
		ScreenSpaceLightingSettings s;
		s.ssil_enabled = true;
		s.ssil_quality = q;
		const SSRadiosityRD::FrameSettings f = SSRadiosityRD::get_frame_settings(s);
		CHECK(f.interleave * f.interleave <= f.sample_count);
	}
}

TEST_CASE("[SSRadiosity][Render] full-size SSIL (half_size off) adds the light of the half-size pass") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const int W = 64, H = 48;
	const IsrScene room = IsrScene::make_room(IsrScene::ROOM_WHITE);
	IsrImages half, full;
	String error;
	ScreenSpaceLightingSettings s = IsrSweep::default_settings();
	REQUIRE_MESSAGE(IsrSweep::render_gpu(room, 0, W, H, s, half, &error), error);
	s.ssil_half_size = false;
	REQUIRE_MESSAGE(IsrSweep::render_gpu(room, 0, W, H, s, full, &error), error);
	double add_half = 0.0, add_full = 0.0;
	int non_finite = 0;
	for (size_t i = 0; i < full.isr.size(); i += 4) {
		add_half += double(half.isr[i]) - double(half.direct[i]);
		add_full += double(full.isr[i]) - double(full.direct[i]);
		non_finite += std::isfinite(full.isr[i]) ? 0 : 1;
	}
	MESSAGE(vformat("white room %dx%d, red channel added: half size %.5f, full size %.5f per pixel", W, H, add_half / (W * H), add_full / (W * H)));
	CHECK(non_finite == 0);
	CHECK(add_half > 0.0);
	// The same estimate at twice the resolution: within 15 % (the pattern and the blur footprint differ).
	CHECK(std::fabs(add_full - add_half) < 0.15 * add_half);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity][Render] a view without SSIL or SSAO builds no pass, texture, shader or pipeline") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		GpuScene g;
		REQUIRE(g.init(IsrScene::make_room(IsrScene::ROOM_CORNELL), 0, 64, 48));
		g.render();
		g.render();
		CHECK_FALSE(g.f.renderer.get_ss_radiosity().has_resources());
		CHECK((g.f.renderer.get_compiled_feature_mask() & RenderForwardClustered::SCENE_VERSION_SS_RADIOSITY) == 0u);
		CHECK(g.f.renderer.get_ss_radiosity().get_last_pass_count() == 0u);
		CHECK_FALSE(g.profile_has("ss_radiosity"));
		// Enabling SSIL builds it; the profile then has the pass.
		g.d.environment.ss_lighting.ssil_enabled = true;
		g.render();
		CHECK(g.f.renderer.get_ss_radiosity().has_resources());
		CHECK((g.f.renderer.get_compiled_feature_mask() & RenderForwardClustered::SCENE_VERSION_SS_RADIOSITY) != 0u);
		// Downsample, ISR, 2 blur passes (one 3 x 3 dispatch each), composite.
		CHECK(g.f.renderer.get_ss_radiosity().get_last_pass_count() == 5u);
		CHECK(g.profile_has("ss_radiosity"));
		// Switching it off again records nothing.
		g.d.environment.ss_lighting.ssil_enabled = false;
		g.render();
		CHECK(g.f.renderer.get_ss_radiosity().get_last_pass_count() == 0u);
		CHECK_FALSE(g.profile_has("ss_radiosity"));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity][Render] a static camera gives bit-identical frames with SSIL and SSAO on") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		GpuScene g;
		REQUIRE(g.init(IsrScene::make_room(IsrScene::ROOM_CORNELL), 1, 80, 60));
		g.d.environment.ss_lighting.ssil_enabled = true;
		g.d.environment.ss_lighting.ssao_enabled = true;
		g.d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_COLOR;
		g.d.environment.ambient_color = Color(0.3f, 0.3f, 0.3f, 1);
		g.d.environment.ambient_energy = 1.0f;
		const std::vector<float> a = g.render();
		const std::vector<float> b = g.render();
		const std::vector<float> c = g.render();
		REQUIRE(a.size() == size_t(80 * 60 * 4));
		CHECK(memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
		CHECK(memcmp(a.data(), c.data(), a.size() * sizeof(float)) == 0);
		int non_finite = 0;
		for (float x : a) {
			non_finite += std::isfinite(x) ? 0 : 1;
		}
		CHECK(non_finite == 0);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity][Render] SSAO alone darkens the ambient light and adds none") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		GpuScene g;
		REQUIRE(g.init(IsrScene::make_room(IsrScene::ROOM_CORNELL), 0, 64, 48));
		g.d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_COLOR;
		g.d.environment.ambient_color = Color(0.3f, 0.3f, 0.3f, 1);
		g.d.environment.ambient_energy = 1.0f;
		const std::vector<float> plain = g.render();
		g.d.environment.ss_lighting.ssao_enabled = true;
		const std::vector<float> ao = g.render();
		REQUIRE(plain.size() == ao.size());
		REQUIRE(g.f.renderer.get_ss_radiosity().get_last_pass_count() == 5u);
		double darker = 0.0;
		int brighter = 0, non_finite = 0;
		for (size_t i = 0; i < ao.size(); i += 4) {
			for (int c = 0; c < 3; c++) {
				non_finite += std::isfinite(ao[i + c]) ? 0 : 1;
				brighter += ao[i + c] > plain[i + c] * 1.0001f + 1e-6f ? 1 : 0;
				darker += double(plain[i + c]) - double(ao[i + c]);
			}
		}
		MESSAGE(vformat("SSAO alone: mean darkening %.5f per channel, %d channels brighter", darker / (ao.size() / 4 * 3), brighter));
		CHECK(non_finite == 0);
		CHECK(brighter == 0);
		CHECK(darker > 0.0);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

// Mean of (a - b) over the rectangle [x0, x1) x [y0, y1), per channel.
static Color _mean_difference(const std::vector<float> &p_a, const std::vector<float> &p_b, int p_w, int p_x0, int p_y0, int p_x1, int p_y1) {
	double s[3] = { 0, 0, 0 };
	int n = 0;
	for (int y = p_y0; y < p_y1; y++) {
		for (int x = p_x0; x < p_x1; x++) {
			for (int c = 0; c < 3; c++) {
				s[c] += double(p_a[(size_t(y) * p_w + x) * 4 + c]) - double(p_b[(size_t(y) * p_w + x) * 4 + c]);
			}
			n++;
		}
	}
	return Color(float(s[0] / n), float(s[1] / n), float(s[2] / n), 1);
}

TEST_CASE("[SSRadiosity][Render][Reference] Cornell room: ISR is closer to the one-bounce truth than direct light alone") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const int W = 64, H = 48;
	const IsrScene room = IsrScene::make_room(IsrScene::ROOM_CORNELL);
	IsrImages images;
	String error;
	REQUIRE_MESSAGE(IsrSweep::render_gpu(room, 0, W, H, IsrSweep::default_settings(), images, &error), error);
	// 48 bounce rays and 4 light samples per bounce keep the truth at a few seconds on two cores; its
	// noise (~15 % of the indirect part per pixel) is well below ISR's gain over direct light here.
	ReferenceRenderOptions ro = IsrSweep::truth_options(48);
	ro.bounce_light_samples = 4;
	ro.threads = 2;
	REQUIRE_MESSAGE(IsrSweep::render_truth(room, 0, W, H, ro, images, &error), error);
	IsrQuality q;
	REQUIRE_MESSAGE(IsrSweep::evaluate(images, q, &error), error);
	MESSAGE(vformat("Cornell room %dx%d: pixels with indirect light %d, ISR closer on %.2f %%; mean error DL %.5f ISR %.5f (gain %.1f %%); Pearson DL %.4f ISR %.4f",
			W, H, q.indirect_pixels, 100.0 * q.improved_share, q.mean_error_dl, q.mean_error_isr, 100.0 * q.mean_error_gain, q.pearson_dl, q.pearson_isr));
	CHECK(q.indirect_pixels > W * H / 2);
	CHECK(q.improved_share >= 0.95);
	CHECK(q.mean_error_gain > 0.0);
	CHECK(q.quality == 1);
	// Colour bleeding: the floor next to the red (left) wall gets red light, in ISR as in the truth.
	// Floor strip: the bottom eighth of the image, left quarter.
	const Color isr_add = _mean_difference(images.isr, images.direct, W, 0, H * 7 / 8, W / 4, H);
	const Color truth_add = _mean_difference(images.truth, images.direct, W, 0, H * 7 / 8, W / 4, H);
	MESSAGE(vformat("floor by the red wall: ISR adds (%.4f %.4f %.4f), the truth adds (%.4f %.4f %.4f)", isr_add.r, isr_add.g, isr_add.b, truth_add.r, truth_add.g, truth_add.b));
	CHECK(truth_add.r > 1.3f * truth_add.g);
	CHECK(isr_add.r > 1.3f * isr_add.g);
	CHECK(isr_add.r > 1.3f * isr_add.b);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[SSRadiosity][Render] a white room gets no colour shift from ISR") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const int W = 96, H = 72;
	IsrImages images;
	String error;
	REQUIRE_MESSAGE(IsrSweep::render_gpu(IsrScene::make_room(IsrScene::ROOM_WHITE), 0, W, H, IsrSweep::default_settings(), images, &error), error);
	const Color add = _mean_difference(images.isr, images.direct, W, 0, 0, W, H);
	MESSAGE(vformat("white room: ISR adds (%.5f %.5f %.5f) on average", add.r, add.g, add.b));
	CHECK(add.r > 0.002f); // It adds light at all ...
	CHECK(std::fabs(add.g - add.r) < 0.01f * add.r); // ... and grey light: no channel 1 % off.
	CHECK(std::fabs(add.b - add.r) < 0.01f * add.r);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestSSRadiosity
