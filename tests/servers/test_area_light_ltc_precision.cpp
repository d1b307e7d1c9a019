/**************************************************************************/
/*  test_area_light_ltc_precision.cpp                                     */
/**************************************************************************/
/* godot-area: the LTC edge-integral precision fix (thesis section 5.4.4) */
/* as a stress test. A long thin area light just above a glossy metal    */
/* plane projects, for the points under it, to nearly antipodal corners  */
/* (more so after the LTC's M^-1, which stretches the tangent plane by    */
/* about 1 / alpha). The scene is rendered by the Forward+ renderer (the */
/* production shader, with the fix) and by the CPU reference renderer    */
/* (modules/reference, adaptive integration of the exact GGX); the        */
/* shader's LTC integral is also evaluated on the CPU in double precision */
/* (well conditioned) and in float32 with Heitz et al.'s original acos   */
/* edge integral (no split: the shader before the fix). The GPU image     */
/* must agree with the double evaluation to the RGBA16F rounding, and its */
/* max (and mean) error against the reference must be at least 10x below */
/* the unfixed float32 integral's.                                        */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/reference/reference_renderer.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_scene_helpers.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace TestAreaLightLTCPrecision {

// The stress scene: a metal plane (f0 = 1, no diffuse) seen straight down, a long thin light above it.
// Defaults: a 20 m x 2 mm light 4 mm above the plane, roughness 0.2 (GGX alpha 0.04); for points
// under the light the M^-1-transformed corners of each long edge are within ~1e-4 rad of antipodal,
// below float32's resolution of acos near -1. The centre row (odd size) lies right under the light;
// the camera 10 cm above the plane sees 12 cm of it (2.4 mm per pixel).
struct StressScene {
	int size = 49; // Pixels per side.
	float camera_height = 0.1f;
	float fovy = 60.0f;
	float roughness = 0.2f;
	Vector2 light_size = Vector2(20.0f, 0.002f);
	float light_height = 0.004f;
	float energy = 0.02f;
};

// Adds the scene's plane, material and light to any set of storages (RD or dummy) and fills r_data.
template <class TLight, class TMesh, class TMaterial>
static void build_scene(const StressScene &p_s, TLight &r_lights, TMesh &r_meshes, TMaterial &r_materials, std::vector<RID> &r_owned, RenderSceneData &r_data) {
	const RS::SurfaceData ground = RenderTest::make_plane(40.0f); // Normal +Y.
	RID mesh = r_meshes.mesh_create();
	r_meshes.mesh_add_surface(mesh, ground);
	RS::MaterialParams params;
	params.albedo = Color(1, 1, 1, 1);
	params.metallic = 1.0f; // f0 = albedo = 1, no diffuse: the image is the LTC specular alone.
	params.roughness = p_s.roughness;
	params.cull_back = false;
	RID material = r_materials.material_create();
	r_materials.material_set_params(material, params);
	RID light = r_lights.light_create(RS::LIGHT_AREA);
	r_lights.light_area_set_size(light, p_s.light_size);
	r_lights.light_set_param(light, RS::LIGHT_PARAM_ENERGY, p_s.energy);
	r_lights.light_set_param(light, RS::LIGHT_PARAM_SPECULAR, 1.0f); // Not Godot's default 0.5.
	r_lights.light_set_param(light, RS::LIGHT_PARAM_RANGE, 1000.0f);
	r_lights.light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 2.0f);
	r_owned = { mesh, material, light };

	r_data = RenderSceneData();
	r_data.cam_transform = Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, p_s.camera_height, 0));
	r_data.z_near = 0.01f;
	r_data.z_far = 50.0f;
	r_data.fovy_degrees = p_s.fovy;
	r_data.cam_projection = Projection::create_perspective(p_s.fovy, 1.0f, r_data.z_near, r_data.z_far);
	r_data.viewport_width = p_s.size;
	r_data.viewport_height = p_s.size;
	r_data.environment.has_environment = true;
	r_data.environment.background = RS::ENV_BG_COLOR;
	r_data.environment.bg_color = Color(0, 0, 0, 1);
	r_data.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
	r_data.environment.ambient_color = Color(0, 0, 0, 1);
	r_data.environment.ambient_energy = 0.0f;
	RenderSceneData::GeometryInstance g;
	g.mesh = mesh;
	g.material_override = material;
	r_data.geometry.push_back(g);
	RenderSceneData::LightInstance li;
	li.light = light;
	li.type = RS::LIGHT_AREA;
	// Facing down (local -Z = world -Y), long axis (local X) along world X.
	li.transform = Transform3D(Basis::from_columns(Vector3(1, 0, 0), Vector3(0, 0, -1), Vector3(0, 1, 0)), Vector3(0, p_s.light_height, 0));
	r_data.lights.push_back(li);
}

// Forward+ on the RD device (the production shader, with the precision fix). Empty on failure.
static std::vector<float> render_gpu(const StressScene &p_s) {
	RendererRD::LightStorage light_storage;
	RendererRD::MeshStorage mesh_storage;
	RendererRD::MaterialStorage material_storage;
	RenderForwardClustered renderer{ &light_storage, &mesh_storage, &material_storage };
	std::vector<float> image;
	if (material_storage.initialize_gpu() && light_storage.initialize_gpu(8) && renderer.initialize(8)) {
		std::vector<RID> owned;
		RenderSceneData data;
		build_scene(p_s, light_storage, mesh_storage, material_storage, owned, data);
		RID rt = renderer.render_target_create(p_s.size, p_s.size);
		renderer.render_scene(data, rt);
		image = renderer.render_target_get_data(rt);
		renderer.render_target_free(rt);
		mesh_storage.mesh_free(owned[0]);
		material_storage.material_free(owned[1]);
		light_storage.light_free(owned[2]);
	}
	renderer.finalize();
	light_storage.finalize_gpu();
	material_storage.finalize_gpu();
	return image;
}

static std::vector<float> render_reference(const StressScene &p_s) {
	RendererDummy::LightStorage light_storage;
	RendererDummy::MeshStorage mesh_storage;
	RendererDummy::MaterialStorage material_storage;
	ReferenceRenderer renderer{ &light_storage, &mesh_storage, &material_storage };
	ReferenceRenderOptions options;
	options.threads = 2;
	options.target_relative_error = 0.002f;
	options.max_samples = 65536;
	renderer.set_options(options);
	std::vector<RID> owned;
	RenderSceneData data;
	build_scene(p_s, light_storage, mesh_storage, material_storage, owned, data);
	RID rt = renderer.render_target_create(p_s.size, p_s.size);
	renderer.render_scene(data, rt);
	std::vector<float> image = renderer.render_target_get_data(rt);
	renderer.render_target_free(rt);
	mesh_storage.mesh_free(owned[0]);
	material_storage.material_free(owned[1]);
	light_storage.light_free(owned[2]);
	return image;
}

// The ground point (y = 0) seen through the centre of pixel (p_x, p_y), top row first (double).
static void ground_point(const StressScene &p_s, int p_x, int p_y, double r_p[3]) {
	const double t = std::tan(Math::deg_to_rad((double)p_s.fovy) * 0.5);
	const double x_ndc = (p_x + 0.5) / p_s.size * 2.0 - 1.0;
	const double y_ndc = 1.0 - (p_y + 0.5) / p_s.size * 2.0;
	// Camera looking down -Y with up = -Z: camera x = world +X, camera y = world -Z.
	const double dir[3] = { x_ndc * t, -1.0, -y_ndc * t };
	const double k = p_s.camera_height / -dir[1];
	r_p[0] = dir[0] * k;
	r_p[1] = 0.0;
	r_p[2] = dir[2] * k;
}

// Edge integral theta * normalize(a x b).z of unit vectors, well conditioned (atan2).
template <class T>
static T edge_atan2(const T *p_a, const T *p_b) {
	const T c[3] = { p_a[1] * p_b[2] - p_a[2] * p_b[1], p_a[2] * p_b[0] - p_a[0] * p_b[2], p_a[0] * p_b[1] - p_a[1] * p_b[0] };
	const T s = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
	if (s == T(0)) {
		return T(0);
	}
	return std::atan2(s, p_a[0] * p_b[0] + p_a[1] * p_b[1] + p_a[2] * p_b[2]) * c[2] / s;
}

// Heitz et al. 2016's original edge integral (the thesis before section 5.4.4, the shader before the
// fix): theta from acos, the direction from the raw cross product, no split. Ill-conditioned for
// near-antipodal ends.
template <class T>
static T edge_acos(const T *p_a, const T *p_b) {
	const T cos_theta = std::min(std::max(p_a[0] * p_b[0] + p_a[1] * p_b[1] + p_a[2] * p_b[2], T(-1)), T(1));
	const T theta = std::acos(cos_theta);
	const T cz = p_a[0] * p_b[1] - p_a[1] * p_b[0];
	return cz * (theta > T(0.001) ? theta / std::sin(theta) : T(1));
}

// Cosine form factor of the quad p_q (clipped to z >= 0) in precision T, as ltc_polygon_form_factor,
// with the edge integral p_edge.
template <class T>
static T form_factor(const T p_q[4][3], T (*p_edge)(const T *, const T *)) {
	T c[5][3];
	int n = 0;
	for (int i = 0; i < 4; i++) {
		const T *a = p_q[i];
		const T *b = p_q[(i + 1) & 3];
		if (a[2] > T(0)) {
			c[n][0] = a[0], c[n][1] = a[1], c[n][2] = a[2];
			n++;
		}
		if ((a[2] > T(0)) != (b[2] > T(0))) {
			const T t = a[2] / (a[2] - b[2]);
			c[n][0] = a[0] + (b[0] - a[0]) * t, c[n][1] = a[1] + (b[1] - a[1]) * t, c[n][2] = T(0);
			n++;
		}
	}
	if (n < 3) {
		return T(0);
	}
	for (int i = 0; i < n; i++) {
		const T l = std::sqrt(c[i][0] * c[i][0] + c[i][1] * c[i][1] + c[i][2] * c[i][2]);
		c[i][0] /= l, c[i][1] /= l, c[i][2] /= l;
	}
	T sum = T(0);
	for (int i = 0; i < n; i++) {
		sum += p_edge(c[i], c[(i + 1) % n]);
	}
	return std::fabs(sum) * T(0.5) / T(Math::PI);
}

// The shader's LTC specular (same LUT, bilinear as the sampler, same matrix and Fresnel) evaluated on
// the CPU in precision T with the edge integral p_edge; the stress scene's metal has f0 = f90 = 1, so
// F = fn + 0 * fg and the image is grey. Double with edge_atan2: what the GPU would output without float
// rounding. Float with edge_acos: the unfixed shader's arithmetic.
template <class T>
static std::vector<double> render_cpu_ltc(const StressScene &p_s, T (*p_edge)(const T *, const T *)) {
	const float *lut = LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX);
	const int n_lut = LTCTableIO::get_builtin_size();
	const T le = T(p_s.energy * Math::PI / ((double)p_s.light_size.x * p_s.light_size.y));
	const T hx = T(0.5) * T(p_s.light_size.x), hz = T(0.5) * T(p_s.light_size.y); // Local Y maps to world -Z.
	std::vector<double> image((size_t)p_s.size * p_s.size);
	for (int py = 0; py < p_s.size; py++) {
		for (int px = 0; px < p_s.size; px++) {
			double pd[3];
			ground_point(p_s, px, py, pd);
			const T p[3] = { T(pd[0]), T(pd[1]), T(pd[2]) };
			T v[3] = { -p[0], T(p_s.camera_height) - p[1], -p[2] };
			const T vl = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
			v[0] /= vl, v[1] /= vl, v[2] /= vl;
			const T nov = v[1]; // N = +Y.
			// Frame: z = N, x = normalize(V - N NoV), y = z x x.
			T tx[3] = { v[0], T(0), v[2] };
			T tl = std::sqrt(tx[0] * tx[0] + tx[2] * tx[2]);
			if (tl < T(1e-12)) {
				tx[0] = T(1), tx[2] = T(0), tl = T(1);
			}
			tx[0] /= tl, tx[2] /= tl;
			const T ty[3] = { tx[2], T(0), -tx[0] }; // (0, 1, 0) x tx.
			// LUT, bilinear between cell centres (the sampler's texel-centre mapping).
			const double fr = std::min(std::max((double)p_s.roughness, 0.0), 1.0) * (n_lut - 1);
			const double ft = std::sqrt(1.0 - std::min(std::max((double)nov, 0.0), 1.0)) * (n_lut - 1);
			const int r0 = std::min((int)fr, n_lut - 2), t0 = std::min((int)ft, n_lut - 2);
			const double wr = fr - r0, wt = ft - t0;
			T m[7];
			for (int k = 0; k < 7; k++) {
				auto cell = [&](int r, int t) { return (double)lut[((size_t)t * n_lut + r) * 8 + k]; };
				m[k] = T((cell(r0, t0) * (1.0 - wr) + cell(r0 + 1, t0) * wr) * (1.0 - wt) + (cell(r0, t0 + 1) * (1.0 - wr) + cell(r0 + 1, t0 + 1) * wr) * wt);
			}
			const T a = m[0], b = m[1], c = m[2], d = m[3], e = m[4];
			const T s = T(1) / (a * e - b * d);
			T q[4][3];
			const T sx[4] = { -1, 1, 1, -1 }, sy[4] = { -1, -1, 1, 1 };
			for (int i = 0; i < 4; i++) {
				// World corner relative to the shading point: centre (0, h, 0) + sx hx X + sy hz (-Z).
				const T w[3] = { sx[i] * hx - p[0], T(p_s.light_height) - p[1], -sy[i] * hz - p[2] };
				const T lx = w[0] * tx[0] + w[1] * tx[1] + w[2] * tx[2];
				const T ly = w[0] * ty[0] + w[1] * ty[1] + w[2] * ty[2];
				const T lz = w[1];
				// M^-1 = s [[e, 0, -b], [0, (ae - bd) / c, 0], [-d, 0, a]].
				q[i][0] = s * (e * lx - b * lz);
				q[i][1] = ly / c;
				q[i][2] = s * (-d * lx + a * lz);
			}
			image[(size_t)py * p_s.size + px] = double(le * form_factor<T>(q, p_edge) * m[5]);
		}
	}
	return image;
}

struct ErrorStats {
	double max_abs = 0.0; // max over pixels and RGB of |image - reference|.
	double mean_abs = 0.0;
	int non_finite = 0;
	int max_at = 0; // Pixel index of max_abs.
};

static ErrorStats compare(const std::vector<float> &p_image, const std::vector<float> &p_reference) {
	ErrorStats s;
	int n = 0;
	for (size_t i = 0; i < p_image.size(); i++) {
		if (i % 4 == 3) {
			continue;
		}
		if (!std::isfinite(p_image[i])) {
			s.non_finite++;
			s.max_abs = INFINITY;
			continue;
		}
		const double e = std::fabs((double)p_image[i] - (double)p_reference[i]);
		if (e > s.max_abs) {
			s.max_abs = e;
			s.max_at = (int)(i / 4);
		}
		s.mean_abs += e;
		n++;
	}
	s.mean_abs /= std::max(n, 1);
	return s;
}

TEST_CASE("[AreaLight3D][LTC] a long thin light close to a glossy plane: the 5.4.4 edge split cuts the max error against the reference at least 10x") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const StressScene scene;
	const std::vector<float> fixed = render_gpu(scene);
	const std::vector<float> reference = render_reference(scene);
	const std::vector<double> exact = render_cpu_ltc<double>(scene, edge_atan2<double>);
	const std::vector<double> unfixed = render_cpu_ltc<float>(scene, edge_acos<float>);
	const size_t n = size_t(scene.size) * scene.size * 4;
	REQUIRE(fixed.size() == n);
	REQUIRE(reference.size() == n);
	// The unfixed integral as an RGBA image (grey, as the GPU image).
	std::vector<float> broken(n, 0.0f);
	for (size_t i = 0; i < unfixed.size(); i++) {
		broken[i * 4] = broken[i * 4 + 1] = broken[i * 4 + 2] = (float)unfixed[i];
	}

	// 1. Against the reference renderer (the task's criterion). The reference integrates this light by
	// sampling the 20 m rectangle uniformly, so it is itself noisy here (about +-30 % along the centre
	// row, some pixels miss the highlight); the fixed shader's max error is dominated by that noise.
	const ErrorStats e_fixed = compare(fixed, reference);
	const ErrorStats e_broken = compare(broken, reference);
	// 2. Against the same LTC integral in double precision (same LUT cells, bilinear, same matrix and
	// Fresnel): isolates the float32 edge-integral error from the LTC approximation and reference noise.
	double peak = 0.0, fixed_exact = 0.0, broken_exact = 0.0;
	int noisy_broken = 0, noisy_fixed = 0;
	for (size_t i = 0; i < exact.size(); i++) {
		peak = std::max(peak, exact[i]);
	}
	REQUIRE(peak > 0.0);
	for (size_t i = 0; i < exact.size(); i++) {
		const double ef = std::fabs(fixed[i * 4] - exact[i]), eb = std::fabs(broken[i * 4] - exact[i]);
		fixed_exact = std::max(fixed_exact, ef);
		broken_exact = std::isfinite(eb) ? std::max(broken_exact, eb) : INFINITY;
		noisy_fixed += ef > 0.01 * peak ? 1 : 0;
		noisy_broken += !(eb <= 0.01 * peak) ? 1 : 0;
	}
	MESSAGE("vs reference: with the fix max |error| ", e_fixed.max_abs, " (mean ", e_fixed.mean_abs, "), without ", e_broken.max_abs, " (mean ", e_broken.mean_abs, "), ratio ",
			e_broken.max_abs / e_fixed.max_abs, "; vs the double-precision LTC (peak ", peak, "): with the fix ", fixed_exact, ", without ", broken_exact, "; pixels off by > 1 % of the peak: ",
			noisy_fixed, " with, ", noisy_broken, " without");
	CHECK(e_fixed.non_finite == 0);
	CHECK(e_broken.max_abs >= 10.0 * e_fixed.max_abs);
	CHECK(e_broken.mean_abs >= 10.0 * e_fixed.mean_abs);
	// The fix reproduces the exact LTC integral up to the RGBA16F target's rounding (2^-11 relative).
	CHECK(fixed_exact < 2e-3 * peak);
	CHECK(noisy_fixed == 0);
	// Without it the specular explodes along the light (the thesis' noisy artefacts).
	CHECK(broken_exact > peak);
	CHECK(noisy_broken > 0);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightLTCPrecision
