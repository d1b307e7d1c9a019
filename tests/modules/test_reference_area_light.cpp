/**************************************************************************/
/*  test_reference_area_light.cpp                                         */
/**************************************************************************/
/* godot-area: area lights in the CPU reference renderer against closed   */
/* forms: a Lambertian plane under a CORNER of a parallel rectangle light */
/* (the configuration factor of a differential area to a parallel        */
/* rectangle), the one-sided emission (exactly 0 behind the light), the   */
/* range window W(d), zero-size lights (exactly 0, no NaN) and the energy */
/* normalisation (far-field radiance independent of the size); and the   */
/* glossy case (roughness 0.05 metal under a large close light): MIS of   */
/* solid-angle and GGX samples converges per pixel, agrees with a brute-  */
/* force estimate, beats light-only sampling at equal cost, and is        */
/* deterministic. Dummy storages + ReferenceRenderer; no GPU, no cull.    */

#include "modules/reference/area_light.h"
#include "modules/reference/area_light_integrator.h"
#include "modules/reference/reference_renderer.h"

#include "core/math/math_funcs.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"

#include "tests/servers/render_scene_helpers.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestReferenceAreaLight {

struct AreaFixture {
	RendererDummy::LightStorage light_storage;
	RendererDummy::MeshStorage mesh_storage;
	RendererDummy::MaterialStorage material_storage;
	ReferenceRenderer renderer{ &light_storage, &mesh_storage, &material_storage };
	std::vector<RID> meshes, materials, lights, targets;
	RenderSceneData scene;
	const Color albedo_srgb = Color(0.8f, 0.8f, 0.8f, 1.0f);

	// A 40 m Lambert ground plane (y = 0, normal +Y, no specular) seen from p_camera_height straight
	// down, 60 degrees, p_size x p_size pixels, black background, no ambient light.
	AreaFixture(float p_camera_height, int p_size) {
		ReferenceRenderOptions options;
		options.threads = 2;
		options.target_relative_error = 0.001f;
		options.max_samples = 16384;
		renderer.set_options(options);

		const RS::SurfaceData ground = RenderTest::make_plane(20.0f); // Normal +Y.
		RID mesh = mesh_storage.mesh_create();
		mesh_storage.mesh_add_surface(mesh, ground);
		meshes.push_back(mesh);
		RS::MaterialParams params;
		params.albedo = albedo_srgb;
		params.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		params.specular_mode = RS::MATERIAL_SPECULAR_DISABLED;
		params.roughness = 1.0f;
		RID material = material_storage.material_create();
		material_storage.material_set_params(material, params);
		materials.push_back(material);

		scene.cam_transform = Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, p_camera_height, 0));
		scene.z_near = 0.05f;
		scene.z_far = 100.0f;
		scene.fovy_degrees = 60.0f;
		scene.cam_projection = Projection::create_perspective(60.0f, 1.0f, scene.z_near, scene.z_far);
		scene.viewport_width = p_size;
		scene.viewport_height = p_size;
		scene.environment.has_environment = true;
		scene.environment.background = RS::ENV_BG_COLOR;
		scene.environment.bg_color = Color(0, 0, 0, 1);
		scene.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
		scene.environment.ambient_color = Color(0, 0, 0, 1);
		scene.environment.ambient_energy = 0.0f;
		RenderSceneData::GeometryInstance g;
		g.mesh = mesh;
		g.material_override = material;
		scene.geometry.push_back(g);
	}
	~AreaFixture() {
		for (RID r : targets) {
			renderer.render_target_free(r);
		}
		for (RID r : meshes) {
			mesh_storage.mesh_free(r);
		}
		for (RID r : materials) {
			material_storage.material_free(r);
		}
		for (RID r : lights) {
			light_storage.light_free(r);
		}
	}
	// Adds a white area light (energy, size, range, attenuation, normalisation) at p_xform.
	RID add_area(float p_energy, const Vector2 &p_size, float p_range, float p_attenuation, bool p_normalize, const Transform3D &p_xform) {
		RID l = light_storage.light_create(RS::LIGHT_AREA);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_ENERGY, p_energy);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, p_range);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_ATTENUATION, p_attenuation);
		light_storage.light_area_set_size(l, p_size);
		light_storage.light_area_set_normalize_energy(l, p_normalize);
		lights.push_back(l);
		RenderSceneData::LightInstance li;
		li.light = l;
		li.type = RS::LIGHT_AREA;
		li.transform = p_xform;
		scene.lights.push_back(li);
		return l;
	}
	std::vector<float> render() {
		RID rt = renderer.render_target_create(scene.viewport_width, scene.viewport_height);
		targets.push_back(rt);
		renderer.render_scene(scene, rt);
		return renderer.render_target_get_data(rt);
	}
	// Linear albedo of the plane (what the renderer multiplies the diffuse sum by).
	double albedo() const { return Color::srgb_to_linear_channel(albedo_srgb.r); }
	// The ground point (y = 0) seen through the centre of pixel (p_x, p_y), top row first.
	Vector3 ground_point(int p_x, int p_y) const {
		const double t = std::tan(Math::deg_to_rad(double(scene.fovy_degrees)) * 0.5);
		const double x_ndc = (p_x + 0.5) / scene.viewport_width * 2.0 - 1.0;
		const double y_ndc = 1.0 - (p_y + 0.5) / scene.viewport_height * 2.0;
		const Vector3 dir = scene.cam_transform.basis.xform(Vector3(float(x_ndc * t), float(y_ndc * t), -1.0f));
		const Vector3 o = scene.cam_transform.origin;
		return o + dir * (-o.y / dir.y);
	}
	static const float *pixel(const std::vector<float> &p_image, int p_width, int p_x, int p_y) {
		return &p_image[(size_t(p_y) * p_width + p_x) * 4];
	}
};

// A light facing straight down (local -Z = world -Y): local X = world +X, local Y = world -Z.
static Basis facing_down() {
	return Basis::from_columns(Vector3(1, 0, 0), Vector3(0, 0, -1), Vector3(0, 1, 0));
}

// Configuration factor from a differential area to a parallel rectangle a x b at height h whose
// corner lies on the area's normal (Howell's catalogue, C-11), X = a / h, Y = b / h:
//   F = 1/(2 pi) [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))].
static double corner_configuration_factor(double p_a, double p_b, double p_h) {
	const double X = p_a / p_h, Y = p_b / p_h;
	const double sx = std::sqrt(1.0 + X * X), sy = std::sqrt(1.0 + Y * Y);
	return (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2.0 * Math::PI);
}

TEST_CASE("[Reference][AreaLight3D] a Lambert plane under a corner of a parallel rectangle matches the configuration factor within 0.5 %") {
	AreaFixture f(6.0f, 16);
	const double a = 2.0, b = 1.5, h = 1.0, energy = 2.0;
	// Put one corner of the light straight above the ground point of pixel (11, 5).
	const int px = 11, py = 5;
	const Vector3 g = f.ground_point(px, py);
	// Corner = centre - a/2 X - b/2 Y with X = +x, Y = -z: centre = g + (a/2, h, -b/2).
	const Transform3D xform(facing_down(), g + Vector3(float(a / 2), float(h), float(-b / 2)));
	// Attenuation 0 (W = 1) and a huge range: the purely physical integral. Not normalised: L_e = E * pi.
	f.add_area(float(energy), Vector2(float(a), float(b)), 1000.0f, 2.0f, false, xform);
	const std::vector<float> image = f.render();

	// Lambert: L_o = albedo/pi * E_irr, E_irr = L_e * pi * F, L_e = colour(1) * energy * pi (/ A_n = 1), so
	// L_o = albedo * energy * pi * F.
	const double F = corner_configuration_factor(a, b, h);
	const double expected = f.albedo() * energy * Math::PI * F;
	const float *p = AreaFixture::pixel(image, 16, px, py);
	CHECK(std::isfinite(p[0]));
	CHECK_MESSAGE(p[0] == doctest::Approx(expected).epsilon(0.005), "got ", p[0], ", expected ", expected, " (F = ", F, ")");
	CHECK(p[1] == doctest::Approx(p[0]));
	CHECK(p[2] == doctest::Approx(p[0]));
	CHECK(f.renderer.get_last_stats().area_light_samples > 0);

	SUBCASE("the same seed renders the same image") {
		const std::vector<float> again = f.render();
		CHECK(again == image);
	}
}

TEST_CASE("[Reference][AreaLight3D] nothing behind the light is lit (one-sided), and the range window applies") {
	AreaFixture f(6.0f, 16);
	// A 1 x 1 light standing on edge 1 m above the ground at x = 0, emitting along world +X:
	// local -Z = +X, so local Z = -X; local X = +Z, local Y = +Y.
	const Transform3D xform(Basis::from_columns(Vector3(0, 0, 1), Vector3(0, 1, 0), Vector3(-1, 0, 0)), Vector3(0, 1, 0));
	RID light = f.add_area(5.0f, Vector2(1, 1), 1000.0f, 2.0f, true, xform);
	const std::vector<float> image = f.render();
	int behind = 0, lit = 0;
	for (int y = 0; y < 16; y++) {
		for (int x = 0; x < 16; x++) {
			const Vector3 g = f.ground_point(x, y);
			const float *p = AreaFixture::pixel(image, 16, x, y);
			if (g.x < -0.05f) {
				behind++;
				CHECK_MESSAGE(p[0] == 0.0f, "pixel ", x, ",", y, " is behind the light and must be exactly 0, got ", p[0]);
			} else if (g.x > 0.05f) {
				lit += p[0] > 0.0f ? 1 : 0;
			}
		}
	}
	CHECK(behind > 20);
	CHECK(lit > 20);

	// Upstream Godot 4.7's meaning: area_attenuation a is a distance exponent, W(d) = window * d^(2 - a).
	auto check_window = [&](float p_attenuation) {
		const float range = 3.0f;
		f.light_storage.light_set_param(light, RS::LIGHT_PARAM_RANGE, range);
		f.light_storage.light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, p_attenuation);
		const std::vector<float> windowed = f.render();
		ReferenceBRDF::AreaLightData rect;
		ReferenceBRDF::area_light_set_frame(rect, xform);
		rect.size_x = rect.size_y = 1.0f;
		int checked = 0, outside = 0;
		for (int y = 0; y < 16; y++) {
			for (int x = 0; x < 16; x++) {
				const Vector3 g = f.ground_point(x, y);
				if (g.x <= 0.05f) {
					continue;
				}
				const double d = ReferenceBRDF::area_light_closest_distance(rect, g);
				const float full = AreaFixture::pixel(image, 16, x, y)[0];
				const float w = AreaFixture::pixel(windowed, 16, x, y)[0];
				if (d >= range) {
					outside++;
					CHECK(w == 0.0f);
					continue;
				}
				const double q = std::pow(d / range, 4.0);
				// Same seed and the same samples: only W differs (the full image has range 1000, W = 1 - 1e-11).
				const double expected = full * (1.0 - q) * (1.0 - q) * std::pow(std::max(d, 1e-4), 2.0 - p_attenuation);
				CHECK(w == doctest::Approx(expected).epsilon(1e-4));
				checked++;
			}
		}
		CHECK(checked > 10);
		CHECK(outside > 10);
	};
	SUBCASE("attenuation 2 (physical): W(d) = (1 - (d/r)^4)^2 scales the physical integral; d >= r is exactly 0") {
		check_window(2.0f);
	}
	SUBCASE("attenuation 1 (the default): W(d) = (1 - (d/r)^4)^2 * d, as upstream's d^-a times the integral's d^2") {
		check_window(1.0f);
	}
	SUBCASE("attenuation 3.5: W(d) = (1 - (d/r)^4)^2 * d^-1.5") {
		check_window(3.5f);
	}
}

TEST_CASE("[Reference][AreaLight3D] with shadows on, each sample is shadow-tested") {
	AreaFixture f(6.0f, 16);
	// A 2 x 2 occluder at y = 0.5 facing down: primary rays from above hit its back face and are culled
	// (cull_back), shadow rays see both faces.
	RS::SurfaceData occluder;
	occluder.vertices = { Vector3(-1, 0.5f, -1), Vector3(1, 0.5f, -1), Vector3(1, 0.5f, 1), Vector3(-1, 0.5f, 1) };
	occluder.normals = { Vector3(0, -1, 0), Vector3(0, -1, 0), Vector3(0, -1, 0), Vector3(0, -1, 0) };
	occluder.indices = { 0, 2, 1, 0, 3, 2 }; // (c - a) x (b - a) = -Y.
	RID mesh = f.mesh_storage.mesh_create();
	f.mesh_storage.mesh_add_surface(mesh, occluder);
	f.meshes.push_back(mesh);
	RenderSceneData::GeometryInstance g;
	g.mesh = mesh;
	g.material_override = f.materials[0];
	f.scene.geometry.push_back(g);
	f.add_area(5.0f, Vector2(0.5f, 0.5f), 100.0f, 2.0f, true, Transform3D(facing_down(), Vector3(0, 1, 0)));

	const std::vector<float> open = f.render();
	CHECK(f.renderer.get_last_stats().shadow_rays == 0);
	ReferenceRenderOptions options = f.renderer.get_options();
	options.shadows = true;
	f.renderer.set_options(options);
	const std::vector<float> shadowed = f.render();
	CHECK(f.renderer.get_last_stats().shadow_rays > 0);

	// Under the middle of the occluder every segment to the light crosses it: exactly 0.
	CHECK(AreaFixture::pixel(open, 16, 8, 8)[0] > 0.0f);
	CHECK(AreaFixture::pixel(shadowed, 16, 8, 8)[0] == 0.0f);
	// Far outside the occluder's shadow nothing changes (same seed, same samples, all unoccluded).
	CHECK(AreaFixture::pixel(shadowed, 16, 0, 0)[0] == AreaFixture::pixel(open, 16, 0, 0)[0]);
	CHECK(AreaFixture::pixel(open, 16, 0, 0)[0] > 0.0f);
	// A pixel near the shadow's edge is partly lit (a penumbra, not a hard step).
	bool penumbra = false;
	for (int x = 8; x < 16; x++) {
		const float o = AreaFixture::pixel(open, 16, x, 8)[0];
		const float s = AreaFixture::pixel(shadowed, 16, x, 8)[0];
		penumbra |= s > 0.02f * o && s < 0.98f * o;
	}
	CHECK(penumbra);
}

TEST_CASE("[Reference][AreaLight3D] a zero-size light contributes exactly 0 and no NaN") {
	AreaFixture f(6.0f, 8);
	const Transform3D xform(facing_down(), Vector3(0, 1, 0));
	SUBCASE("normalised, zero area") {
		f.add_area(10.0f, Vector2(0, 0), 100.0f, 1.0f, true, xform);
	}
	SUBCASE("normalised, zero width") {
		f.add_area(10.0f, Vector2(0, 2), 100.0f, 1.0f, true, xform);
	}
	SUBCASE("not normalised, zero height") {
		f.add_area(10.0f, Vector2(2, 0), 100.0f, 2.0f, false, xform);
	}
	const std::vector<float> image = f.render();
	for (size_t i = 0; i < image.size(); i += 4) {
		CHECK(image[i] == 0.0f);
		CHECK(image[i + 1] == 0.0f);
		CHECK(image[i + 2] == 0.0f);
	}
	CHECK(f.renderer.get_last_stats().area_light_samples == 0);
	// The helper agrees: no radiance, no division by zero.
	const Vector3 le = ReferenceBRDF::area_light_emitted_radiance(Color(1, 1, 1), 10.0f, false, Vector2(0, 2), true);
	CHECK(le == Vector3());
}

TEST_CASE("[Reference][AreaLight3D] normalize_energy: doubling the size at fixed energy keeps the far-field radiance") {
	const double energy = 50.0, h = 10.0;
	const int size = 8;
	std::vector<float> images[2];
	std::vector<Vector3> points;
	double albedo = 0.0;
	for (int i = 0; i < 2; i++) {
		AreaFixture f(20.0f, size);
		const float side = i == 0 ? 0.2f : 0.4f;
		f.add_area(float(energy), Vector2(side, side), 1000.0f, 2.0f, true, Transform3D(facing_down(), Vector3(0, float(h), 0)));
		images[i] = f.render();
		if (i == 0) {
			albedo = f.albedo();
			for (int y = 0; y < size; y++) {
				for (int x = 0; x < size; x++) {
					points.push_back(f.ground_point(x, y));
				}
			}
		}
	}
	for (int y = 0; y < size; y++) {
		for (int x = 0; x < size; x++) {
			const float small = AreaFixture::pixel(images[0], size, x, y)[0];
			const float large = AreaFixture::pixel(images[1], size, x, y)[0];
			REQUIRE(small > 0.0f);
			CHECK(large == doctest::Approx(small).epsilon(0.01));
			// Far field: like a point source of intensity energy * pi / pi per cos: a Lambert surface at
			// lateral distance rho receives L_o = albedo * energy * cos_i cos_l / dist^2 = albedo * E h^2 / dist^4.
			const Vector3 g = points[size_t(y) * size + x];
			const double dist2 = h * h + double(g.x) * g.x + double(g.z) * g.z;
			const double far_field = albedo * energy * h * h / (dist2 * dist2);
			CHECK(small == doctest::Approx(far_field).epsilon(0.01));
		}
	}
}

// The accuracy suite's hardest row (plane_r0.05_m1_4x4_close): a metal plane (roughness 0.05, sRGB
// albedo (0.9, 0.75, 0.6)) under a 4 x 4 light 0.4 m above the origin, facing down, seen from
// (0, 2.5, 3.2) towards (0, 0.2, 0) with 55 degrees; p_size x p_size pixels.
struct GlossyFixture : AreaFixture {
	Transform3D light_xform;
	RID light;
	const float energy = 2.0f;
	const Vector2 light_size = Vector2(4, 4);

	explicit GlossyFixture(int p_size) :
			AreaFixture(6.0f, p_size) {
		RS::MaterialParams params;
		params.albedo = Color(0.9f, 0.75f, 0.6f, 1.0f);
		params.metallic = 1.0f;
		params.roughness = 0.05f;
		params.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		material_storage.material_set_params(materials[0], params);
		const Vector3 eye(0, 2.5f, 3.2f);
		scene.cam_transform = Transform3D(Basis::looking_at(Vector3(0, 0.2f, 0) - eye, Vector3(0, 1, 0)), eye);
		scene.fovy_degrees = 55.0f;
		scene.cam_projection = Projection::create_perspective(55.0f, 1.0f, scene.z_near, scene.z_far);
		light_xform = Transform3D(facing_down(), Vector3(0, 0.4f, 0));
		light = add_area(energy, light_size, 1000.0f, 2.0f, true, light_xform);
		ReferenceRenderOptions options = renderer.get_options();
		options.target_relative_error = 0.002f; // The reference's defaults.
		options.max_samples = 4096;
		renderer.set_options(options);
	}
	// The light as the renderer sees it.
	ReferenceBRDF::AreaLightData light_data() {
		ReferenceBRDF::AreaLightData d;
		ReferenceBRDF::area_light_set_frame(d, light_xform);
		d.size_x = light_size.x;
		d.size_y = light_size.y;
		d.radiance = ReferenceBRDF::area_light_emitted_radiance(Color(1, 1, 1), energy, false, light_size, true);
		d.range = 1000.0f;
		d.attenuation = 2.0f;
		d.specular_amount = light_storage.light_get_param(light, RS::LIGHT_PARAM_SPECULAR);
		return d;
	}
	// The shading point of pixel (x, y) as the renderer sets it up (metal: no diffuse term).
	ReferenceBRDF::AreaLightShadingPoint shading_point(int p_x, int p_y) const {
		ReferenceBRDF::AreaLightShadingPoint p;
		p.vertex = ground_point(p_x, p_y);
		p.N = Vector3(0, 1, 0);
		p.ng = p.N;
		p.V = (scene.cam_transform.origin - p.vertex).normalized();
		p.diffuse_mode = ReferenceBRDF::BRDF_DIFFUSE_LAMBERT;
		p.roughness = 0.05f;
		const Color albedo = Color(0.9f, 0.75f, 0.6f).srgb_to_linear();
		p.f0 = Vector3(albedo.r, albedo.g, albedo.b);
		p.f90 = ReferenceBRDF::brdf_specular_f90(p.f0, 1.0f);
		p.specular_enabled = true;
		p.diffuse_weight = Vector3();
		return p;
	}
	// Brute force at pixel (x, y): 2^18 stratified samples of p_sampling (64 rounds of 64 x 64 strata),
	// with its own random stream.
	Vector3 brute_force(int p_x, int p_y, ReferenceBRDF::AreaLightSampling p_sampling, double *r_relative_error, int p_samples = 1 << 18) {
		AdaptiveIntegrationSettings settings;
		settings.strata_per_axis = 64;
		settings.min_rounds = 8;
		settings.max_samples = p_samples * 3; // Directions: up to three per MIS evaluation.
		settings.target_relative_error = 0.0;
		settings.absolute_error_floor = 0.0;
		ReferenceRNG rng(12345, uint64_t(p_y) * 1000 + p_x);
		const ReferenceBRDF::AreaLightIntegral r = ReferenceBRDF::area_light_integrate(light_data(), shading_point(p_x, p_y), p_sampling, settings, rng);
		*r_relative_error = r.relative_error;
		return r.radiance;
	}
};

static const int GLOSSY_SIZE = 24;
// Pixels of the glossy image checked against the brute force: inside the highlight, near its rim and
// in the dark part of the plane.
static const int GLOSSY_PIXELS[][2] = { { 12, 20 }, { 4, 22 }, { 20, 16 }, { 12, 12 }, { 2, 10 }, { 12, 6 } };

TEST_CASE("[Reference][AreaLight3D] glossy metal under a large close light: MIS converges per pixel and matches a brute-force estimate within 1 %") {
	GlossyFixture f(GLOSSY_SIZE);
	const std::vector<float> image = f.render();
	const ReferenceRenderStats &stats = f.renderer.get_last_stats();
	REQUIRE(stats.pixel_relative_error.size() == size_t(GLOSSY_SIZE * GLOSSY_SIZE));
	int below = 0, lit = 0;
	float worst = 0.0f, brightest = 0.0f, worst_absolute = 0.0f;
	for (int i = 0; i < GLOSSY_SIZE * GLOSSY_SIZE; i++) {
		CHECK(std::isfinite(image[i * 4]));
		brightest = std::max(brightest, image[i * 4]);
	}
	for (int i = 0; i < GLOSSY_SIZE * GLOSSY_SIZE; i++) {
		lit += image[i * 4] > 0.0f ? 1 : 0;
		below += stats.pixel_relative_error[i] <= 0.002f ? 1 : 0;
		worst = std::max(worst, stats.pixel_relative_error[i]);
		// The red channel carries the largest relative error of this albedo's three.
		worst_absolute = std::max(worst_absolute, stats.pixel_relative_error[i] * image[i * 4]);
	}
	MESSAGE("pixels below the 0.2 % target: ", below, " of ", GLOSSY_SIZE * GLOSSY_SIZE, ", worst ", worst, ", worst standard error / brightest pixel ", worst_absolute / brightest, ", integrals converged ", stats.area_light_integrals_converged, " of ", stats.area_light_integrals, ", directions per pixel ", double(stats.area_light_samples) / (GLOSSY_SIZE * GLOSSY_SIZE));
	CHECK(lit > GLOSSY_SIZE * GLOSSY_SIZE / 2);
	// Nearly all pixels are certified to 0.2 %. The rest (measured: 33 of 576) stop at the cap: the rim
	// of the highlight, where the narrow lobe is cut by the light's edge (a hit / miss boundary for the
	// GGX samples), and the lobe's far tail beyond the edge (down to 1e-5 of the highlight); their
	// standard error stays below 0.5 % of the brightest pixel (measured 0.33 %).
	CHECK(below >= GLOSSY_SIZE * GLOSSY_SIZE * 92 / 100);
	CHECK(worst_absolute <= 0.005f * brightest);
	CHECK(stats.area_light_integrals_converged == uint64_t(below));

	int cross_checked = 0;
	for (const auto &px : GLOSSY_PIXELS) {
		double brute_error = 0.0;
		const Vector3 brute = f.brute_force(px[0], px[1], ReferenceBRDF::AREA_LIGHT_SAMPLING_MIS, &brute_error);
		const float *p = AreaFixture::pixel(image, GLOSSY_SIZE, px[0], px[1]);
		INFO("pixel ", px[0], ",", px[1], ": reference ", p[0], " ", p[1], " ", p[2], ", brute force ", brute.x, " ", brute.y, " ", brute.z, " (relative error ", brute_error, ")");
		CHECK(brute_error < 0.001);
		for (int c = 0; c < 3; c++) {
			CHECK(std::fabs(double(p[c]) - double(brute[c])) <= 0.01 * std::fabs(double(brute[c])) + 1e-7);
		}
		// The brute force itself, against strategies that share nothing with MIS but their own sampler:
		// GGX samples alone (good inside the highlight) and solid-angle samples alone (good in the tails),
		// each where its own error estimate is small.
		const ReferenceBRDF::AreaLightSampling single[2] = { ReferenceBRDF::AREA_LIGHT_SAMPLING_BRDF, ReferenceBRDF::AREA_LIGHT_SAMPLING_SOLID_ANGLE };
		for (ReferenceBRDF::AreaLightSampling sampling : single) {
			double error = 0.0;
			const Vector3 other = f.brute_force(px[0], px[1], sampling, &error);
			if (error < 0.001) {
				cross_checked++;
				INFO("strategy ", int(sampling), ": ", other.x, " (relative error ", error, ")");
				CHECK(double(other.x) == doctest::Approx(double(brute.x)).epsilon(4.0 * (error + brute_error)));
			}
		}
	}
	CHECK(cross_checked >= 4);
}

TEST_CASE("[Reference][AreaLight3D] at equal cost, MIS has a lower error than light-only sampling on a glossy lobe") {
	GlossyFixture f(GLOSSY_SIZE);
	// At most 512 directions per pixel for every strategy (MIS: 170 light + 170 GGX + 170 lobe-window
	// samples), no early stop.
	ReferenceRenderOptions options = f.renderer.get_options();
	options.target_relative_error = 0.0f;
	options.max_samples = 512;
	const ReferenceBRDF::AreaLightSampling strategies[3] = { ReferenceBRDF::AREA_LIGHT_SAMPLING_MIS, ReferenceBRDF::AREA_LIGHT_SAMPLING_SOLID_ANGLE, ReferenceBRDF::AREA_LIGHT_SAMPLING_AREA };
	std::vector<float> images[3];
	for (int s = 0; s < 3; s++) {
		options.area_sampling = strategies[s];
		f.renderer.set_options(options);
		images[s] = f.render();
		CHECK(f.renderer.get_last_stats().area_light_samples <= uint64_t(512) * f.renderer.get_last_stats().area_light_integrals);
	}
	// Relative RMS error over the lit glossy pixels of a 6 x 6 grid, against the brute force.
	double sq[3] = {};
	int count = 0;
	for (int y = 2; y < GLOSSY_SIZE; y += 4) {
		for (int x = 2; x < GLOSSY_SIZE; x += 4) {
			double brute_error = 0.0;
			const Vector3 brute = f.brute_force(x, y, ReferenceBRDF::AREA_LIGHT_SAMPLING_MIS, &brute_error, 1 << 16);
			CHECK(brute_error < 0.002);
			if (!(brute.x > 1e-3f)) {
				continue;
			}
			count++;
			for (int s = 0; s < 3; s++) {
				const double e = (double(AreaFixture::pixel(images[s], GLOSSY_SIZE, x, y)[0]) - brute.x) / brute.x;
				sq[s] += e * e;
			}
		}
	}
	REQUIRE(count >= 10);
	const double mis = std::sqrt(sq[0] / count), solid = std::sqrt(sq[1] / count), area = std::sqrt(sq[2] / count);
	MESSAGE("relative RMS error at 512 directions over ", count, " glossy pixels: MIS ", mis, ", solid angle ", solid, ", area ", area);
	CHECK(mis < 0.5 * solid);
	CHECK(mis < 0.5 * area);
	CHECK(mis < 0.01);
}

TEST_CASE("[Reference][AreaLight3D] the MIS estimator is deterministic: the same image twice and for any thread count") {
	GlossyFixture f(16);
	ReferenceRenderOptions options = f.renderer.get_options();
	options.max_samples = 1024;
	options.threads = 1;
	f.renderer.set_options(options);
	const std::vector<float> first = f.render();
	const std::vector<float> again = f.render();
	options.threads = 3;
	f.renderer.set_options(options);
	const std::vector<float> threaded = f.render();
	CHECK(first == again);
	CHECK(first == threaded);
	bool any = false;
	for (size_t i = 0; i < first.size(); i += 4) {
		any |= first[i] > 0.0f;
	}
	CHECK(any);
	options.seed = 7;
	f.renderer.set_options(options);
	CHECK(f.render() != first); // Another seed: other samples.
}

TEST_CASE("[Reference][AreaLight3D] with shadows on, MIS shadow-tests light and GGX samples alike") {
	GlossyFixture f(12);
	// A 1 x 1 occluder at y = 0.2 facing down (invisible to the camera above: back-face culled).
	RS::SurfaceData occluder;
	occluder.vertices = { Vector3(-0.5f, 0.2f, -0.5f), Vector3(0.5f, 0.2f, -0.5f), Vector3(0.5f, 0.2f, 0.5f), Vector3(-0.5f, 0.2f, 0.5f) };
	occluder.normals = { Vector3(0, -1, 0), Vector3(0, -1, 0), Vector3(0, -1, 0), Vector3(0, -1, 0) };
	occluder.indices = { 0, 2, 1, 0, 3, 2 }; // (c - a) x (b - a) = -Y.
	RID mesh = f.mesh_storage.mesh_create();
	f.mesh_storage.mesh_add_surface(mesh, occluder);
	f.meshes.push_back(mesh);
	RenderSceneData::GeometryInstance g;
	g.mesh = mesh;
	g.material_override = f.materials[0];
	f.scene.geometry.push_back(g);
	// A fixed budget, so that both renders draw the same samples and only visibility differs.
	ReferenceRenderOptions options = f.renderer.get_options();
	options.target_relative_error = 0.0f;
	options.max_samples = 384;
	f.renderer.set_options(options);
	const std::vector<float> open = f.render();
	CHECK(f.renderer.get_last_stats().shadow_rays == 0);
	options.shadows = true;
	f.renderer.set_options(options);
	const std::vector<float> shadowed = f.render();
	const ReferenceRenderStats &stats = f.renderer.get_last_stats();
	// Every evaluated direction that reaches the light is tested: more rays than light samples alone.
	CHECK(stats.shadow_rays > stats.area_light_samples / 3);
	int darker = 0;
	for (size_t i = 0; i < open.size(); i += 4) {
		CHECK(shadowed[i] <= open[i]); // Same samples, some of them blocked: never brighter.
		darker += shadowed[i] < 0.5f * open[i] ? 1 : 0;
	}
	CHECK(darker > 3); // The occluder's reflection darkens the highlight.
}

TEST_CASE("[Reference][AreaLight3D] the spherical-rectangle sampler covers the rectangle's solid angle uniformly") {
	// A 2 x 1 rectangle at z = -1.5, corner (-0.5, -0.25); the solid angle of the point at the origin by
	// a fine midpoint rule of cos / r^2 over the area.
	const Vector3 corner(-0.5f, -0.25f, -1.5f), ex(2, 0, 0), ey(0, 1, 0);
	ReferenceBRDF::SphericalRectangleSampler sampler;
	REQUIRE(sampler.setup(Vector3(), corner, ex, ey));
	double omega = 0.0;
	const int n = 1000;
	for (int j = 0; j < n; j++) {
		for (int i = 0; i < n; i++) {
			const double x = -0.5 + 2.0 * (i + 0.5) / n, y = -0.25 + (j + 0.5) / n, z = 1.5;
			const double r2 = x * x + y * y + z * z;
			omega += z / (r2 * std::sqrt(r2)) * (2.0 / n) * (1.0 / n);
		}
	}
	CHECK(sampler.get_solid_angle() == doctest::Approx(omega).epsilon(1e-5));
	// Every sample lies on the rectangle, and the pdf is uniform in solid angle (1 / omega): then the
	// mean of dA/dw = r^2 / cos over the samples estimates area / omega.
	double mean = 0.0;
	const int m = 64;
	for (int j = 0; j < m; j++) {
		for (int i = 0; i < m; i++) {
			double q[3];
			sampler.sample((i + 0.5) / m, (j + 0.5) / m, q);
			CHECK(q[2] == doctest::Approx(-1.5));
			CHECK(q[0] >= -0.5 - 1e-9);
			CHECK(q[0] <= 1.5 + 1e-9);
			CHECK(q[1] >= -0.25 - 1e-9);
			CHECK(q[1] <= 0.75 + 1e-9);
			const double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
			mean += (r2 * std::sqrt(r2) / 1.5) * sampler.get_solid_angle() / 2.0;
		}
	}
	CHECK(mean / (m * m) == doctest::Approx(1.0).epsilon(1e-3));
	// In the rectangle's plane the parameterisation degenerates: setup() refuses (area sampling instead).
	CHECK_FALSE(sampler.setup(Vector3(0, 0, -1.5f), corner, ex, ey));
}

} // namespace TestReferenceAreaLight
