/**************************************************************************/
/*  test_reference.cpp                                                    */
/**************************************************************************/
/* godot-area: self-checks of the CPU reference renderer: the adaptive    */
/* integrator against Lambert's polygon irradiance formula, GGX energy    */
/* (directional albedo <= 1), Monte Carlo convergence rate, exact hard    */
/* shadows, an omni-lit Lambertian plane against the analytic radiance    */
/* (the same formula as the GPU test), determinism over thread counts and */
/* rendering through RenderingServerDefault.                              */

#include "modules/reference/brdf.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "modules/reference/sampling.h"

#include "core/io/image.h"
#include "core/math/math_funcs.h"
#include "scene/main/godot_instance.h"
#include "servers/rendering/rendering_server_default.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_scene_helpers.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

namespace TestReference {

/* Scene helpers (dummy storages + RenderSceneData, no scene cull) */

struct ReferenceFixture {
	RendererDummy::LightStorage light_storage;
	RendererDummy::MeshStorage mesh_storage;
	RendererDummy::MaterialStorage material_storage;
	ReferenceRenderer renderer{ &light_storage, &mesh_storage, &material_storage };
	std::vector<RID> meshes, materials, lights, targets;

	~ReferenceFixture() {
		for (RID r : targets) {
			renderer.render_target_free(r);
		}
		for (RID m : meshes) {
			mesh_storage.mesh_free(m);
		}
		for (RID m : materials) {
			material_storage.material_free(m);
		}
		for (RID l : lights) {
			light_storage.light_free(l);
		}
	}
	RID mesh(const RS::SurfaceData &p_surface) {
		RID m = mesh_storage.mesh_create();
		mesh_storage.mesh_add_surface(m, p_surface);
		meshes.push_back(m);
		return m;
	}
	RID material(const RS::MaterialParams &p_params) {
		RID m = material_storage.material_create();
		material_storage.material_set_params(m, p_params);
		materials.push_back(m);
		return m;
	}
	RID omni(float p_energy, float p_range, float p_decay, const Color &p_color) {
		RID l = light_storage.light_create(RS::LIGHT_OMNI);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_ENERGY, p_energy);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, p_range);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_ATTENUATION, p_decay);
		light_storage.light_set_color(l, p_color);
		lights.push_back(l);
		return l;
	}
	std::vector<float> render(const RenderSceneData &p_data) {
		RID rt = renderer.render_target_create(p_data.viewport_width, p_data.viewport_height);
		targets.push_back(rt);
		renderer.render_scene(p_data, rt);
		return renderer.render_target_get_data(rt);
	}
};

using RenderTest::add_geometry;
using RenderTest::add_light;
using RenderTest::add_quad;
using RenderTest::camera_looking_down;
using RenderTest::make_box;
using RenderTest::make_scene;
using RenderTest::make_sphere;

// Square y = 0 of half side p_half_size, normal +Y.
static RS::SurfaceData make_ground(float p_half_size) {
	return RenderTest::make_plane(p_half_size);
}

// World point seen through the centre of pixel (p_px, p_py) on the plane y = 0 (top row first),
// from the field of view (independent of the renderer's inverse projection).
static Vector3 pixel_on_ground(const RenderSceneData &p_d, int p_px, int p_py) {
	double t = std::tan(Math::deg_to_rad(double(p_d.fovy_degrees)) * 0.5);
	double aspect = double(p_d.viewport_width) / double(p_d.viewport_height);
	double x_ndc = (p_px + 0.5) / p_d.viewport_width * 2.0 - 1.0;
	double y_ndc = 1.0 - (p_py + 0.5) / p_d.viewport_height * 2.0;
	Vector3 dir = p_d.cam_transform.basis.xform(Vector3(float(x_ndc * t * aspect), float(y_ndc * t), -1.0f));
	Vector3 o = p_d.cam_transform.origin;
	float s = -o.y / dir.y;
	return o + dir * s;
}

// Pixel whose area contains the world point (projected with the OpenGL projection; y flipped).
static void world_to_pixel(const RenderSceneData &p_d, const Vector3 &p_world, int &r_x, int &r_y) {
	Vector3 view = p_d.cam_transform.affine_inverse().xform(p_world);
	Vector3 ndc = p_d.cam_projection.xform(view);
	r_x = int(std::floor((ndc.x + 1.0f) * 0.5f * p_d.viewport_width));
	r_y = int(std::floor((1.0f - ndc.y) * 0.5f * p_d.viewport_height));
}

static Color pixel(const std::vector<float> &p_img, int p_w, int p_x, int p_y) {
	const float *p = &p_img[(size_t(p_y) * p_w + p_x) * 4];
	return Color(p[0], p[1], p[2], p[3]);
}

// Godot 4's omni attenuation, written independently of the shader and of brdf.h.
static double omni_attenuation(double p_d, double p_range, double p_decay) {
	double window = std::max(1.0 - std::pow(p_d / p_range, 4.0), 0.0);
	return window * window * std::pow(std::max(p_d, 1e-4), -p_decay);
}

/* Integration */

// Lambert's formula (1760) for the irradiance from a uniformly emitting polygon of radiance 1 at the
// origin with normal p_n: E = 1/2 sum_i angle(v_i, v_i+1) n . normalize(v_i x v_i+1) (polygon fully
// above the horizon; the sign depends on the winding, so the absolute value is taken).
static double lambert_polygon_irradiance(const std::vector<Vector3> &p_vertices, const Vector3 &p_n) {
	double sum = 0.0;
	for (size_t i = 0; i < p_vertices.size(); i++) {
		const Vector3 &a = p_vertices[i];
		const Vector3 &b = p_vertices[(i + 1) % p_vertices.size()];
		double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
		double la = std::sqrt(ax * ax + ay * ay + az * az), lb = std::sqrt(bx * bx + by * by + bz * bz);
		ax /= la, ay /= la, az /= la, bx /= lb, by /= lb, bz /= lb;
		double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
		double lc = std::sqrt(cx * cx + cy * cy + cz * cz);
		double angle = std::atan2(lc, ax * bx + ay * by + az * bz);
		sum += angle * (p_n.x * cx + p_n.y * cy + p_n.z * cz) / lc;
	}
	return std::fabs(0.5 * sum);
}

TEST_CASE("[Reference] adaptive integrator matches Lambert's polygon irradiance of a rectangle within 0.1 %") {
	// Receiver at the origin, normal tilted; a rectangle light above it, tilted too.
	const Vector3 n = Vector3(0.2f, 1.0f, -0.1f).normalized();
	const Vector3 corner(-0.7f, 1.2f, -0.4f);
	const Vector3 e1(1.1f, 0.15f, 0.0f);
	const Vector3 e2(0.1f, 0.2f, 0.9f);
	const Vector3 light_n = e1.cross(e2).normalized();
	const double area = e1.cross(e2).length();
	const double radiance[3] = { 1.0, 0.5, 2.0 }; // Three channels, one integrand.

	std::vector<Vector3> poly = { corner, corner + e1, corner + e1 + e2, corner + e2 };
	for (const Vector3 &p : poly) {
		REQUIRE_MESSAGE(p.dot(n) > 0.0f, "the rectangle lies fully above the receiver's horizon");
	}
	const double exact = lambert_polygon_irradiance(poly, n);
	REQUIRE(exact > 0.1);

	// E = integral over the rectangle of L cos(theta_r) cos(theta_l) / r^2 dA, as the mean over [0,1]^2.
	ReferenceIntegrand integrand = [&](double u, double v, double *r_value) {
		Vector3 p = corner + e1 * float(u) + e2 * float(v);
		double r2 = double(p.length_squared());
		double r = std::sqrt(r2);
		double cos_r = std::max(0.0, double(p.dot(n)) / r);
		double cos_l = std::fabs(double(p.dot(light_n))) / r;
		double g = cos_r * cos_l / r2 * area;
		for (int c = 0; c < 3; c++) {
			r_value[c] = radiance[c] * g;
		}
	};
	AdaptiveIntegrationSettings settings;
	settings.target_relative_error = 2e-4;
	settings.max_samples = 1 << 22;
	ReferenceRNG rng(7, 1);
	AdaptiveIntegrationResult res = integrate_adaptive(integrand, 3, settings, rng);
	CHECK(res.converged);
	CHECK(res.relative_error <= settings.target_relative_error);
	REQUIRE(res.value.size() == 3);
	for (int c = 0; c < 3; c++) {
		double expected = exact * radiance[c];
		INFO("channel ", c, " expected ", expected, " got ", res.value[c], " (", res.samples, " samples)");
		CHECK(std::fabs(res.value[c] - expected) <= 1e-3 * expected);
		CHECK_MESSAGE(std::fabs(res.value[c] - expected) <= 6.0 * res.standard_error[c] + 1e-6 * expected, "the reported standard error is honest");
	}

	SUBCASE("a loose target stops early, a zero integrand stops at the minimum") {
		AdaptiveIntegrationSettings loose = settings;
		loose.target_relative_error = 0.05;
		ReferenceRNG rng2(7, 2);
		AdaptiveIntegrationResult quick = integrate_adaptive(integrand, 3, loose, rng2);
		CHECK(quick.converged);
		CHECK(quick.samples < res.samples);
		ReferenceIntegrand zero = [](double, double, double *r_value) { r_value[0] = 0.0; };
		ReferenceRNG rng3(7, 3);
		AdaptiveIntegrationResult z = integrate_adaptive(zero, 1, settings, rng3);
		CHECK(z.converged);
		CHECK(z.samples == settings.min_rounds * settings.strata_per_axis * settings.strata_per_axis);
		CHECK(z.value[0] == 0.0);
	}
	SUBCASE("the sample cap stops a target that cannot be met") {
		AdaptiveIntegrationSettings capped = settings;
		capped.target_relative_error = 0.0;
		capped.max_samples = 512;
		ReferenceRNG rng4(7, 4);
		AdaptiveIntegrationResult c = integrate_adaptive(integrand, 3, capped, rng4);
		CHECK_FALSE(c.converged);
		CHECK(c.samples == 512);
	}
}

TEST_CASE("[Reference] GGX directional albedo with f0 = 1 does not exceed 1") {
	using namespace ReferenceBRDF;
	const Vector3 f0(1, 1, 1);
	const float f90 = brdf_specular_f90(f0, 0.0f);
	REQUIRE(f90 == 1.0f);
	const float roughnesses[] = { 0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f };
	const float view_cosines[] = { 1.0f, 0.8f, 0.5f, 0.2f, 0.05f };
	const int grid = 192; // Stratified importance samples per axis.
	double max_albedo = 0.0;
	for (float r : roughnesses) {
		const double alpha = double(r) * double(r);
		for (float nov : view_cosines) {
			// Normal +Z, view in the xz plane.
			const Vector3 V(std::sqrt(std::max(0.0f, 1.0f - nov * nov)), 0.0f, nov);
			double sum = 0.0;
			for (int j = 0; j < grid; j++) {
				for (int i = 0; i < grid; i++) {
					// Sample the half vector from D(h) (h.n): cos^2 = (1 - x) / (1 + (alpha^2 - 1) x).
					double x = (i + 0.5) / grid, y = (j + 0.5) / grid;
					double cos2 = (1.0 - x) / (1.0 + (alpha * alpha - 1.0) * x);
					double ct = std::sqrt(cos2), st = std::sqrt(std::max(0.0, 1.0 - cos2));
					double phi = 2.0 * Math::PI * y;
					Vector3 H(float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct));
					float VoH = V.dot(H);
					if (VoH <= 0.0f) {
						continue;
					}
					Vector3 L = H * (2.0f * VoH) - V;
					float NoL = L.z;
					if (NoL <= 0.0f) {
						continue;
					}
					float NoV = std::max(V.z, 1e-4f); // As light_compute clamps.
					float NoH = H.z;
					Vector3 f = brdf_specular(NoV, NoL, NoH, VoH, r, f0, f90);
					// pdf(l) = D(h) (n.h) / (4 (v.h)), so f cos / pdf = f NoL 4 VoH / (D NoH).
					double D = D_GGX(NoH, float(alpha));
					sum += double(f.x) * NoL * 4.0 * VoH / (D * NoH);
				}
			}
			double albedo = sum / double(grid * grid);
			INFO("roughness ", r, " NoV ", nov, " albedo ", albedo);
			CHECK(albedo <= 1.0 + 1e-3);
			CHECK(albedo > 0.2); // The integrand is not accidentally empty.
			max_albedo = std::max(max_albedo, albedo);
		}
	}
	MESSAGE(vformat("max GGX directional albedo (f0 = 1): %.6f", max_albedo));
}

TEST_CASE("[Reference] Monte Carlo error falls as N^-1/2 (stratified faster)") {
	// Integrand with known mean: f(u, v) = u^2 + v + sin(2 pi u v); mean = 1/3 + 1/2 + I, where
	// I = integral of sin(2 pi u v) over the square = (1/(2 pi)) * integral_0^1 (1 - cos(2 pi u)) / u du
	// = Cin(2 pi) / (2 pi), computed here by dense midpoint quadrature instead.
	double I = 0.0;
	const int q = 200000;
	for (int k = 0; k < q; k++) {
		double u = (k + 0.5) / q;
		I += (1.0 - std::cos(2.0 * Math::PI * u)) / u;
	}
	I = I / q / (2.0 * Math::PI);
	const double exact = 1.0 / 3.0 + 0.5 + I;
	ReferenceIntegrand f = [](double u, double v, double *r_value) { r_value[0] = u * u + v + std::sin(2.0 * Math::PI * u * v); };

	const int counts[] = { 16, 64, 256, 1024, 4096 };
	const int seeds = 300;
	for (int stratified = 0; stratified < 2; stratified++) {
		double sx = 0, sy = 0, sxx = 0, sxy = 0;
		for (int n : counts) {
			double se = 0.0;
			for (int s = 0; s < seeds; s++) {
				ReferenceRNG rng(1234 + s, uint64_t(n) * 2 + stratified);
				double e = integrate_fixed(f, 1, n, stratified != 0, rng)[0] - exact;
				se += e * e;
			}
			double rmse = std::sqrt(se / seeds);
			double lx = std::log(double(n)), ly = std::log(rmse);
			sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
		}
		const double m = 5.0;
		double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
		INFO("stratified ", stratified, " fitted log-log slope ", slope);
		if (stratified) {
			CHECK_MESSAGE(slope < -0.8, "jittered strata converge faster than N^-1/2 for a smooth integrand");
		} else {
			CHECK(std::fabs(slope + 0.5) <= 0.05);
		}
	}
}

/* Rendering */

TEST_CASE("[Reference] omni-lit Lambertian plane matches the analytic radiance") {
	ReferenceFixture f;
	const int W = 65, H = 65;
	RID plane = f.mesh(make_ground(20.0f));
	RS::MaterialParams mp;
	mp.albedo = Color(0.6f, 0.5f, 0.4f, 1.0f); // sRGB.
	mp.roughness = 1.0f;
	mp.metallic = 0.0f;
	mp.specular = 0.0f;
	mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
	mp.cull_back = false;
	RID mat = f.material(mp);
	const float energy = 2.0f, range = 6.0f, decay = 1.0f, height = 2.0f;
	const Color light_color(1.0f, 0.9f, 0.8f, 1.0f); // sRGB.
	RID light = f.omni(energy, range, decay, light_color);

	RenderSceneData d = make_scene(camera_looking_down(5.0f), 60.0f, W, H, 20.0f);
	add_geometry(d, plane, mat, Transform3D());
	const Vector3 light_pos(0, height, 0);
	add_light(d, light, RS::LIGHT_OMNI, Transform3D(Basis(), light_pos));
	std::vector<float> img = f.render(d);
	REQUIRE(img.size() == size_t(W * H * 4));

	// albedo / pi * (pi * energy * colour) * attenuation(d) * cos(theta), all linear.
	Color albedo = mp.albedo.srgb_to_linear();
	Color lc = light_color.srgb_to_linear();
	const int probes[4][2] = { { W / 2, H / 2 }, { 48, 20 }, { 10, 40 }, { 60, 3 } };
	for (const auto &p : probes) {
		Vector3 point = pixel_on_ground(d, p[0], p[1]);
		Vector3 to_light = light_pos - point;
		double dist = to_light.length();
		double cos_theta = to_light.y / dist;
		double e = (1.0 / Math::PI) * (Math::PI * energy) * omni_attenuation(dist, range, decay) * cos_theta;
		Color got = pixel(img, W, p[0], p[1]);
		double expected[3] = { albedo.r * lc.r * e, albedo.g * lc.g * e, albedo.b * lc.b * e };
		double actual[3] = { got.r, got.g, got.b };
		for (int c = 0; c < 3; c++) {
			INFO("pixel (", p[0], ", ", p[1], ") channel ", c, " expected ", expected[c], " got ", actual[c]);
			CHECK(expected[c] > 0.001);
			CHECK(std::fabs(actual[c] - expected[c]) <= 2e-4 * expected[c]);
		}
		CHECK(got.a == 1.0f);
	}
	// Beyond the range the light contributes exactly 0: shrink the range below the corner's distance.
	f.light_storage.light_set_param(light, RS::LIGHT_PARAM_RANGE, 3.0f);
	std::vector<float> short_range = f.render(d);
	REQUIRE((light_pos - pixel_on_ground(d, 0, 0)).length() > 3.0f);
	Color corner = pixel(short_range, W, 0, 0);
	CHECK(corner.r == 0.0f);
	CHECK(corner.g == 0.0f);
	CHECK(corner.b == 0.0f);
	CHECK(pixel(short_range, W, W / 2, H / 2).r > 0.01f);
}

TEST_CASE("[Reference] a lit plane has no black pixel on the edge shared by its two triangles") {
	// Issue 20 reported 17 black pixels on the shared diagonal of a lit plane (257 x 257, with and without
	// shadows); the renderer now sets RTC_SCENE_FLAG_ROBUST. Note: these views give 0 black pixels with and
	// without the flag on this machine's Embree, so this guards the property rather than reproducing the miss.
	for (int view = 0; view < 6; view++) { // Views 6+ of this loop see past the plane's far edge.
		const bool shadows = view % 2 == 1;
		ReferenceFixture f;
		ReferenceRenderOptions options = f.renderer.get_options();
		options.shadows = shadows;
		f.renderer.set_options(options);
		const int W = 257, H = 257;
		RID plane = f.mesh(make_ground(20.0f));
		RS::MaterialParams mp;
		mp.roughness = 1.0f;
		mp.metallic = 0.0f;
		mp.cull_back = false;
		RID mat = f.material(mp);
		RID light = f.omni(2.0f, 100.0f, 1.0f, Color(1, 1, 1, 1));
		// Straight down at the centre (the image diagonal is the shared edge), then oblique views of the same edge.
		Transform3D cam = camera_looking_down(5.0f);
		if (view >= 2) {
			const Vector3 eye(0.37f * view, 1.5f + 0.9f * view, 2.5f + 0.3f * view);
			const Vector3 target(-0.2f * view, 0.0f, -0.2f * view); // On the diagonal x = z.
			cam = Transform3D(Basis::looking_at(target - eye, Vector3(0, 1, 0)), eye);
		}
		RenderSceneData d = make_scene(cam, 60.0f, W, H, 40.0f);
		add_geometry(d, plane, mat, Transform3D());
		add_light(d, light, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(0, 2, 0)));
		std::vector<float> img = f.render(d);
		REQUIRE(img.size() == size_t(W * H * 4));
		int black = 0;
		for (int y = 0; y < H; y++) {
			for (int x = 0; x < W; x++) {
				black += pixel(img, W, x, y).r <= 0.0f;
			}
		}
		CHECK_MESSAGE(black == 0, black, " black pixels on a plane that fills view ", view, shadows ? " (shadows on)" : " (shadows off)");
	}
}

TEST_CASE("[Reference] shadow rays: occluded pixels are exactly 0, exposed ones equal the unshadowed value") {
	ReferenceFixture f;
	const int W = 64, H = 64;
	RID ground = f.mesh(make_ground(20.0f));
	RS::SurfaceData wall_s;
	add_quad(wall_s, Vector3(3, 1.5f, 0), Vector3(0, 1.45f, 0), Vector3(0, 0, 1)); // x = 3, y 0.05..2.95, z -1..1.
	RID wall = f.mesh(wall_s);
	RS::MaterialParams mp;
	mp.albedo = Color(0.8f, 0.8f, 0.8f, 1.0f);
	mp.roughness = 0.6f;
	mp.cull_back = false;
	RID mat = f.material(mp);
	RID light = f.omni(5.0f, 50.0f, 2.0f, Color(1, 1, 1, 1));

	RenderSceneData d = make_scene(camera_looking_down(6.0f), 90.0f, W, H, 50.0f);
	add_geometry(d, ground, mat, Transform3D());
	add_geometry(d, wall, mat, Transform3D());
	add_light(d, light, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(5, 2, 0)));

	ReferenceRenderOptions opt;
	opt.shadows = false;
	f.renderer.set_options(opt);
	std::vector<float> lit = f.render(d);
	CHECK(f.renderer.get_last_stats().shadow_rays == 0);
	opt.shadows = true;
	f.renderer.set_options(opt);
	std::vector<float> shadowed = f.render(d);
	CHECK(f.renderer.get_last_stats().shadow_rays > 0);
	REQUIRE(lit.size() == shadowed.size());

	// (0,0,0) and (-3,0,0): the segment to the light crosses the wall; (0,0,4) passes beside it.
	const Vector3 hidden[2] = { Vector3(0, 0, 0), Vector3(-3, 0, 0) };
	for (const Vector3 &w : hidden) {
		int x, y;
		world_to_pixel(d, w, x, y);
		REQUIRE(x >= 0);
		REQUIRE(x < W);
		REQUIRE(y >= 0);
		REQUIRE(y < H);
		INFO("hidden point ", w.x, " ", w.z, " pixel ", x, " ", y);
		CHECK(pixel(lit, W, x, y).r > 0.01f);
		Color c = pixel(shadowed, W, x, y);
		CHECK(c.r == 0.0f);
		CHECK(c.g == 0.0f);
		CHECK(c.b == 0.0f);
	}
	int ex, ey;
	world_to_pixel(d, Vector3(0, 0, 4), ex, ey);
	REQUIRE(ex >= 0);
	REQUIRE(ey >= 0);
	Color exposed = pixel(shadowed, W, ex, ey);
	CHECK(exposed.r > 0.01f);
	CHECK(exposed.r == pixel(lit, W, ex, ey).r);
	CHECK(exposed.g == pixel(lit, W, ex, ey).g);
	CHECK(exposed.b == pixel(lit, W, ex, ey).b);

	// With point sampling and one light every pixel is either fully lit or fully dark.
	int dark = 0, same = 0, other = 0;
	for (size_t i = 0; i < lit.size(); i += 4) {
		if (shadowed[i] == lit[i] && shadowed[i + 1] == lit[i + 1] && shadowed[i + 2] == lit[i + 2]) {
			same++;
		} else if (shadowed[i] == 0.0f && shadowed[i + 1] == 0.0f && shadowed[i + 2] == 0.0f) {
			dark++;
		} else {
			other++;
		}
	}
	CHECK(dark > 50);
	CHECK(same > 50);
	CHECK(other == 0);

	SUBCASE("ambient light stays in the shadow") {
		d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_COLOR;
		d.environment.ambient_color = Color(0.5f, 0.5f, 0.5f, 1.0f);
		d.environment.ambient_energy = 0.5f;
		std::vector<float> amb = f.render(d);
		int x, y;
		world_to_pixel(d, Vector3(0, 0, 0), x, y);
		float expected = Color::srgb_to_linear_channel(0.5f) * 0.5f * Color::srgb_to_linear_channel(0.8f);
		CHECK(pixel(amb, W, x, y).r == doctest::Approx(expected).epsilon(1e-6));
	}
}

TEST_CASE("[Reference] background, back-face culling, unshaded and spot cone match the GPU rules") {
	ReferenceFixture f;
	const int W = 33, H = 33;
	RenderSceneData d = make_scene(camera_looking_down(5.0f), 60.0f, W, H, 20.0f);
	d.environment.bg_color = Color(0.2f, 0.4f, 0.6f, 1.0f);
	d.environment.bg_energy = 2.0f;

	SUBCASE("empty scene shows the linearised background colour times energy") {
		std::vector<float> img = f.render(d);
		Color c = pixel(img, W, 5, 7);
		CHECK(c.r == doctest::Approx(Color::srgb_to_linear_channel(0.2f) * 2.0f));
		CHECK(c.b == doctest::Approx(Color::srgb_to_linear_channel(0.6f) * 2.0f));
		CHECK(c.a == 1.0f);
	}
	SUBCASE("a cull_back ground seen from below is invisible; unshaded outputs albedo") {
		RS::MaterialParams mp;
		mp.albedo = Color(0.3f, 0.6f, 0.9f, 1.0f);
		mp.unshaded = true;
		mp.cull_back = true;
		RID mat = f.material(mp);
		RID ground = f.mesh(make_ground(20.0f));
		add_geometry(d, ground, mat, Transform3D());
		std::vector<float> top = f.render(d);
		Color c = pixel(top, W, W / 2, H / 2);
		CHECK(c.r == doctest::Approx(Color::srgb_to_linear_channel(0.3f)));
		CHECK(c.g == doctest::Approx(Color::srgb_to_linear_channel(0.6f)));
		// Flip the ground upside down: its back faces the camera and is culled.
		d.geometry[0].transform = Transform3D(Basis(1, 0, 0, 0, -1, 0, 0, 0, -1), Vector3());
		std::vector<float> bottom = f.render(d);
		Color b = pixel(bottom, W, W / 2, H / 2);
		CHECK(b.r == doctest::Approx(Color::srgb_to_linear_channel(0.2f) * 2.0f));
	}
	SUBCASE("outside a spot cone the ground is exactly black") {
		RS::MaterialParams mp;
		mp.albedo = Color(1, 1, 1, 1);
		RID mat = f.material(mp);
		RID ground = f.mesh(make_ground(20.0f));
		add_geometry(d, ground, mat, Transform3D());
		RID spot = f.light_storage.light_create(RS::LIGHT_SPOT);
		f.lights.push_back(spot);
		f.light_storage.light_set_param(spot, RS::LIGHT_PARAM_RANGE, 10.0f);
		f.light_storage.light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 20.0f);
		// At (0, 2, 0) pointing straight down (-Z of the light = world -Y).
		add_light(d, spot, RS::LIGHT_SPOT, Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 2, 0)));
		std::vector<float> img = f.render(d);
		CHECK(pixel(img, W, W / 2, H / 2).r > 0.05f);
		Color outside = pixel(img, W, 2, 2);
		CHECK(outside.r == 0.0f);
		CHECK(outside.g == 0.0f);
		CHECK(outside.b == 0.0f);
	}
}

/* Cross-check with the GPU renderer */

// A scene description built through a RenderingServer, so the GPU and the reference get the same
// data through the door users take (RS API, scene cull, viewport).
struct CrossScene {
	struct Object {
		RS::SurfaceData surface;
		RS::MaterialParams material;
		Transform3D transform;
	};
	struct LightDesc {
		RS::LightType type;
		Transform3D transform;
		Color color;
		float energy, range, decay, spot_angle, spot_attenuation, specular;
	};
	std::vector<Object> objects;
	std::vector<LightDesc> lights;
	Transform3D camera;
	float fovy = 60.0f, z_far = 30.0f;
	Color bg_color = Color(0, 0, 0, 1);
	Color ambient_color = Color(0, 0, 0, 1);
	float ambient_energy = 0.0f;

	// Creates the scene in p_rs, draws one frame of p_w x p_h and frees everything again.
	Image render(RenderingServer *p_rs, int p_w, int p_h) const {
		std::vector<RID> owned; // Freed in reverse order of creation.
		RID scenario = p_rs->scenario_create();
		RID env = p_rs->environment_create();
		p_rs->environment_set_background(env, RS::ENV_BG_COLOR);
		p_rs->environment_set_bg_color(env, bg_color);
		p_rs->environment_set_ambient_light(env, ambient_color, ambient_energy > 0.0f ? RS::ENV_AMBIENT_SOURCE_COLOR : RS::ENV_AMBIENT_SOURCE_DISABLED, ambient_energy);
		p_rs->scenario_set_environment(scenario, env);
		owned.push_back(env);
		owned.push_back(scenario);
		for (const Object &o : objects) {
			RID mesh = p_rs->mesh_create();
			p_rs->mesh_add_surface(mesh, o.surface);
			RID mat = p_rs->material_create();
			p_rs->material_set_params(mat, o.material);
			p_rs->mesh_surface_set_material(mesh, 0, mat);
			RID inst = p_rs->instance_create();
			p_rs->instance_set_base(inst, mesh);
			p_rs->instance_set_scenario(inst, scenario);
			p_rs->instance_set_transform(inst, o.transform);
			owned.insert(owned.end(), { mat, mesh, inst });
		}
		for (const LightDesc &l : lights) {
			RID light = l.type == RS::LIGHT_SPOT ? p_rs->spot_light_create() : p_rs->omni_light_create();
			p_rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, l.energy);
			p_rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, l.range);
			p_rs->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, l.decay);
			p_rs->light_set_param(light, RS::LIGHT_PARAM_SPECULAR, l.specular);
			if (l.type == RS::LIGHT_SPOT) {
				p_rs->light_set_param(light, RS::LIGHT_PARAM_SPOT_ANGLE, l.spot_angle);
				p_rs->light_set_param(light, RS::LIGHT_PARAM_SPOT_ATTENUATION, l.spot_attenuation);
			}
			p_rs->light_set_color(light, l.color);
			RID inst = p_rs->instance_create();
			p_rs->instance_set_base(inst, light);
			p_rs->instance_set_scenario(inst, scenario);
			p_rs->instance_set_transform(inst, l.transform);
			owned.insert(owned.end(), { light, inst });
		}
		RID cam = p_rs->camera_create();
		p_rs->camera_set_perspective(cam, fovy, 0.05f, z_far);
		p_rs->camera_set_transform(cam, camera);
		RID viewport = p_rs->viewport_create();
		p_rs->viewport_set_size(viewport, p_w, p_h);
		p_rs->viewport_attach_camera(viewport, cam);
		p_rs->viewport_set_scenario(viewport, scenario);
		owned.insert(owned.end(), { cam, viewport });
		p_rs->draw();
		Image image = p_rs->viewport_get_texture_data(viewport);
		for (auto it = owned.rbegin(); it != owned.rend(); ++it) {
			p_rs->free(*it);
		}
		return image;
	}
};

// Draws p_scene with the Forward+ renderer and with the reference, each through its own GodotInstance.
static void render_gpu_and_reference(const CrossScene &p_scene, int p_w, int p_h, Image &r_gpu, Image &r_ref) {
	String error;
	{
		GodotInstance engine;
		REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_RD, &error, 64), error.c_str());
		r_gpu = p_scene.render(engine.get_rendering_server(), p_w, p_h);
	}
	{
		GodotInstance reference;
		REQUIRE_MESSAGE(reference.start_with_compositor(new RendererCompositorReference(ReferenceRenderOptions()), &error), error.c_str());
		r_ref = p_scene.render(reference.get_rendering_server(), p_w, p_h);
	}
}

TEST_CASE("[Reference][Render] the reference and the Forward+ renderer agree pixel by pixel on the same scene") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");

	CrossScene scene;
	{
		CrossScene::Object ground;
		ground.surface = make_ground(8.0f);
		ground.material.albedo = Color(0.7f, 0.65f, 0.6f, 1);
		ground.material.roughness = 0.55f;
		scene.objects.push_back(ground);
		CrossScene::Object box;
		box.surface = make_box(Vector3(0.5f, 0.5f, 0.5f));
		box.material.albedo = Color(0.9f, 0.5f, 0.2f, 1);
		box.material.roughness = 0.3f;
		box.material.metallic = 0.7f;
		box.transform = Transform3D(Basis::looking_at(Vector3(1, 0, -0.6f).normalized(), Vector3(0, 1, 0)), Vector3(-0.8f, 0.5f, 0.3f));
		scene.objects.push_back(box);
		CrossScene::Object ball;
		ball.surface = make_sphere(0.6f, 16, 32);
		ball.material.albedo = Color(0.3f, 0.5f, 0.8f, 1);
		ball.material.roughness = 0.4f;
		ball.material.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		ball.material.emission = Color(0.05f, 0.02f, 0.0f, 1);
		ball.transform = Transform3D(Basis(), Vector3(0.9f, 0.6f, -0.2f));
		scene.objects.push_back(ball);
		CrossScene::Object card; // Two-sided, seen partly from the back.
		add_quad(card.surface, Vector3(0, 0, 0), Vector3(0.5f, 0, 0), Vector3(0, 0.4f, 0));
		card.material.albedo = Color(0.4f, 0.8f, 0.4f, 1);
		card.material.cull_back = false;
		card.material.roughness = 0.8f;
		card.transform = Transform3D(Basis::looking_at(Vector3(0.5f, 0, 1).normalized(), Vector3(0, 1, 0)), Vector3(0.2f, 0.8f, -1.6f));
		scene.objects.push_back(card);
		scene.lights.push_back({ RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(1.5f, 2.0f, 1.0f)), Color(1, 0.9f, 0.8f, 1), 1.5f, 8.0f, 1.0f, 45.0f, 1.0f, 1.0f });
		scene.lights.push_back({ RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(-2.0f, 1.2f, -0.5f)), Color(0.5f, 0.7f, 1, 1), 2.0f, 5.0f, 2.0f, 45.0f, 1.0f, 0.5f });
		scene.lights.push_back({ RS::LIGHT_SPOT, Transform3D(Basis::looking_at(Vector3(0.2f, -1, -0.3f).normalized(), Vector3(0, 0, -1)), Vector3(0, 3, 0.5f)), Color(1, 1, 1, 1), 3.0f, 6.0f, 1.0f, 30.0f, 0.8f, 1.0f });
	}
	const int W = 96, H = 64;
	scene.camera = Transform3D(Basis::looking_at(Vector3(0, -0.45f, -1).normalized(), Vector3(0, 1, 0)), Vector3(0, 1.8f, 3.2f));
	scene.bg_color = Color(0.1f, 0.15f, 0.3f, 1);
	scene.ambient_color = Color(0.2f, 0.2f, 0.25f, 1);
	scene.ambient_energy = 0.5f;

	Image gpu, ref;
	render_gpu_and_reference(scene, W, H, gpu, ref);
	REQUIRE(gpu.get_width() == W);
	REQUIRE(gpu.get_height() == H);
	REQUIRE(ref.get_width() == W);
	REQUIRE(ref.get_height() == H);

	// The GPU target is half float (relative precision 2^-11): 2e-3 relative + 2e-4 absolute per
	// channel. Pixels whose centre falls within rounding distance of a silhouette or triangle edge may
	// pick the other triangle; allow 0.5 % of the pixels for that.
	int bad = 0, lit = 0;
	double worst = 0.0;
	for (int y = 0; y < H; y++) {
		for (int x = 0; x < W; x++) {
			Color g = gpu.get_pixel(x, y), r = ref.get_pixel(x, y);
			bool ok = true;
			for (int c = 0; c < 3; c++) {
				double diff = std::fabs(double(g[c]) - double(r[c]));
				ok = ok && diff <= 2e-3 * std::fabs(double(r[c])) + 2e-4;
				worst = std::max(worst, diff / (std::fabs(double(r[c])) + 1e-3));
			}
			lit += r.r > 0.05f ? 1 : 0;
			if (!ok) {
				if (bad < 5) {
					MESSAGE(vformat("pixel (%d, %d): GPU (%.5f %.5f %.5f) reference (%.5f %.5f %.5f)", x, y, g.r, g.g, g.b, r.r, r.g, r.b));
				}
				bad++;
			}
		}
	}
	MESSAGE(vformat("GPU vs reference: %d of %d pixels differ beyond tolerance", bad, W * H));
	CHECK(lit > W * H / 4);
	CHECK(bad <= W * H / 200);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Reference][Render] vertex_color_use_as_albedo: vertex colours multiply the albedo on the GPU and in the reference") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	// Two quads facing the camera with corner colours red, green, blue, white: left unshaded (colour as
	// given, alpha 1), right lit by an omni light with vertex_color_is_srgb.
	CrossScene scene;
	const Color corners[4] = { Color(1, 0, 0, 1), Color(0, 1, 0, 1), Color(0, 0, 1, 1), Color(1, 1, 1, 1) };
	for (int side = 0; side < 2; side++) {
		CrossScene::Object quad;
		add_quad(quad.surface, Vector3(side == 0 ? -0.55f : 0.55f, 0, 0), Vector3(0.5f, 0, 0), Vector3(0, 0.5f, 0));
		quad.surface.colors.assign(corners, corners + 4);
		quad.material.vertex_color_use_as_albedo = true;
		quad.material.unshaded = side == 0;
		quad.material.vertex_color_is_srgb = side == 1;
		quad.material.albedo = Color(0.8f, 0.8f, 0.8f, 1);
		scene.objects.push_back(quad);
	}
	scene.lights.push_back({ RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(0.6f, 0.3f, 1.0f)), Color(1, 1, 1, 1), 2.0f, 8.0f, 1.0f, 45.0f, 1.0f, 1.0f });
	const int W = 96, H = 48;
	scene.camera = Transform3D(Basis(), Vector3(0, 0, 1.3f));
	Image gpu, ref;
	render_gpu_and_reference(scene, W, H, gpu, ref);
	REQUIRE(gpu.get_width() == W);
	REQUIRE(ref.get_width() == W);
	int bad = 0, covered = 0;
	for (int y = 0; y < H; y++) {
		for (int x = 0; x < W; x++) {
			const Color g = gpu.get_pixel(x, y), r = ref.get_pixel(x, y);
			bool ok = true;
			for (int c = 0; c < 3; c++) {
				ok = ok && std::fabs(g[c] - r[c]) <= 2e-3f * std::fabs(r[c]) + 5e-4f;
			}
			covered += (r.r + r.g + r.b) > 0.0f ? 1 : 0;
			bad += ok ? 0 : 1;
		}
	}
	MESSAGE(vformat("vertex colours, GPU vs reference: %d of %d pixels differ beyond tolerance", bad, W * H));
	CHECK(covered > W * H / 3);
	CHECK(bad <= W * H / 200);
	// The unshaded quad spans x -1.05..-0.05, y -0.5..0.5 of a 3 m x 1.5 m view at 1.3 m: pixel (16, 38)
	// lies near its bottom-left vertex (red), (44, 9) near its top-right one (blue); times the albedo
	// 0.8 (linear 0.604).
	for (const Image *image : { &gpu, &ref }) {
		const Color red = image->get_pixel(16, 38), blue = image->get_pixel(44, 9);
		CHECK(red.r > 3.0f * red.b);
		CHECK(red.r < 0.61f);
		CHECK(blue.b > 3.0f * blue.r);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Reference] images are bit-identical across reruns and thread counts") {
	ReferenceFixture f;
	const int W = 48, H = 40;
	RS::SurfaceData s = make_ground(20.0f);
	add_quad(s, Vector3(0.5f, 0.6f, 0.2f), Vector3(0.4f, 0, 0.3f), Vector3(0, 0.5f, 0)); // A slanted card.
	RID mesh = f.mesh(s);
	RS::MaterialParams mp;
	mp.albedo = Color(0.7f, 0.3f, 0.2f, 1.0f);
	mp.roughness = 0.3f;
	mp.metallic = 0.4f;
	RID mat = f.material(mp);
	RID l1 = f.omni(3.0f, 10.0f, 1.0f, Color(1, 0.8f, 0.6f, 1));
	RID l2 = f.omni(1.0f, 8.0f, 2.0f, Color(0.5f, 0.7f, 1, 1));
	RenderSceneData d = make_scene(Transform3D(Basis::looking_at(Vector3(0, -0.6f, -1), Vector3(0, 1, 0)), Vector3(0, 2, 3)), 70.0f, W, H, 50.0f);
	add_geometry(d, mesh, mat, Transform3D());
	add_light(d, l1, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(1, 1.5f, 1)));
	add_light(d, l2, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(-1, 1, -0.5f)));

	ReferenceRenderOptions opt;
	opt.shadows = true;
	opt.threads = 1;
	f.renderer.set_options(opt);
	std::vector<float> a = f.render(d);
	opt.threads = 3;
	f.renderer.set_options(opt);
	std::vector<float> b = f.render(d);
	CHECK(f.renderer.get_last_stats().threads == 3);
	std::vector<float> c = f.render(d);
	REQUIRE(a.size() == b.size());
	CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
	CHECK(std::memcmp(b.data(), c.data(), b.size() * sizeof(float)) == 0);
	double sum = 0.0;
	for (float v : a) {
		CHECK_MESSAGE(std::isfinite(v), "every pixel value is finite");
		sum += v;
	}
	CHECK(sum > 1.0);
}

TEST_CASE("[Reference] renders through RenderingServerDefault with the reference compositor") {
	ReferenceRenderOptions opt;
	opt.threads = 2;
	RenderingServerDefault *rs = new RenderingServerDefault(new RendererCompositorReference(opt));
	{
		const int W = 31, H = 31;
		RID mesh = rs->mesh_create();
		rs->mesh_add_surface(mesh, make_ground(20.0f));
		RID material = rs->material_create();
		RS::MaterialParams mp;
		mp.albedo = Color(0.6f, 0.5f, 0.4f, 1.0f);
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		rs->material_set_params(material, mp);
		rs->mesh_surface_set_material(mesh, 0, material);
		RID light = rs->omni_light_create();
		rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, 2.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, 6.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 1.0f);
		RID camera = rs->camera_create();
		rs->camera_set_perspective(camera, 60.0f, 0.05f, 20.0f);
		rs->camera_set_transform(camera, camera_looking_down(5.0f));
		RID env = rs->environment_create();
		rs->environment_set_background(env, RS::ENV_BG_COLOR);
		rs->environment_set_bg_color(env, Color(0, 0, 0, 1));
		RID scenario = rs->scenario_create();
		rs->scenario_set_environment(scenario, env);
		RID instance = rs->instance_create();
		rs->instance_set_base(instance, mesh);
		rs->instance_set_scenario(instance, scenario);
		RID light_instance = rs->instance_create();
		rs->instance_set_base(light_instance, light);
		rs->instance_set_scenario(light_instance, scenario);
		rs->instance_set_transform(light_instance, Transform3D(Basis(), Vector3(0, 2, 0)));
		RID viewport = rs->viewport_create();
		rs->viewport_set_size(viewport, W, H);
		rs->viewport_attach_camera(viewport, camera);
		rs->viewport_set_scenario(viewport, scenario);
		rs->draw();
		Image img = rs->viewport_get_texture_data(viewport);
		REQUIRE(img.get_width() == W);
		REQUIRE(img.get_height() == H);
		// Centre pixel: straight below the light at 2 m, cos = 1: albedo * energy * 2^-1 * window.
		double window = std::pow(1.0 - std::pow(2.0 / 6.0, 4.0), 2.0);
		double expected = Color::srgb_to_linear_channel(0.6f) * 2.0 * 0.5 * window;
		CHECK(img.get_pixel(W / 2, H / 2).r == doctest::Approx(expected).epsilon(1e-4));
		for (RID rid : { viewport, light_instance, instance, scenario, env, camera, light, material, mesh }) {
			rs->free(rid);
		}
	}
	delete rs;
}

} // namespace TestReference
