/**************************************************************************/
/*  test_directional_shadow.cpp                                           */
/**************************************************************************/
/* godot-area: DirectionalLight3D shadows (issue 16 item 2,               */
/* servers/rendering/renderer_rd/directional_shadow_rd.h).                */
/* - Split math: the splits tile [z_near, max_distance] without gaps and  */
/*   grow monotonically; each split's orthographic box contains every     */
/*   corner of its frustum slice; box centres sit on the texel grid and   */
/*   radii do not change when the camera only turns (stable shadows).     */
/* - A box on a plane under a shadowed sun, seen from 3 distances (so the */
/*   box falls into different PSSM splits): the GPU's visibility          */
/*   (shadowed / unshadowed radiance) against the Embree reference with   */
/*   shadow rays over the sun disk.                                       */
/* - A view without a shadowed sun builds nothing and times no pass.      */

#include "modules/reference/reference_renderer.h"
#include "servers/rendering/renderer_rd/directional_shadow_rd.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestDirectionalShadow {

using RenderTest::add_geometry;
using RenderTest::make_scene;

// A directional light shining along p_dir (world).
static Transform3D sun_along(const Vector3 &p_dir) {
	const Vector3 up = std::fabs(p_dir.normalized().y) > 0.99f ? Vector3(0, 0, 1) : Vector3(0, 1, 0);
	return Transform3D(Basis::looking_at(p_dir.normalized(), up), Vector3(0, 10, 0));
}

static Transform3D camera_at(const Vector3 &p_eye, const Vector3 &p_target) {
	return Transform3D(Basis::looking_at((p_target - p_eye).normalized(), Vector3(0, 1, 0)), p_eye);
}

static bool has_pass(const std::vector<std::pair<String, double>> &p_profile, const char *p_name) {
	for (const std::pair<String, double> &p : p_profile) {
		if (p.first == p_name) {
			return true;
		}
	}
	return false;
}

TEST_CASE("[DirectionalShadowRD] splits cover the view range without gaps, grow monotonically and their boxes contain the frustum slices") {
	const RS::LightDirectionalShadowMode modes[3] = { RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL, RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_2_SPLITS, RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS };
	const uint32_t expected_count[3] = { 1, 2, 4 };
	const Vector3 sun_dirs[3] = { Vector3(0.3f, -1.0f, 0.2f), Vector3(1.0f, -0.2f, 0.0f), Vector3(0.0f, -1.0f, 0.0f) };
	const Transform3D cams[3] = { camera_at(Vector3(0, 2, 5), Vector3(0, 0, 0)), camera_at(Vector3(13.7f, 1.3f, -4.1f), Vector3(20, 0.5f, 3)), camera_at(Vector3(-3, 40, 2), Vector3(0, 0, 0)) };
	const float max_distances[3] = { 100.0f, 25.0f, 0.0f }; // 0: the camera's far plane.
	int checked_corners = 0;
	for (int m = 0; m < 3; m++) {
		for (int l = 0; l < 3; l++) {
			for (int c = 0; c < 3; c++) {
				DirectionalShadowRD::SplitSettings st;
				st.mode = modes[m];
				st.max_distance = max_distances[c];
				const float z_near = 0.05f, z_far = 60.0f;
				const Projection proj = Projection::create_perspective(70.0f, 16.0f / 9.0f, z_near, z_far);
				DirectionalShadowRD::Split s[DirectionalShadowRD::MAX_SPLITS];
				const uint32_t n = DirectionalShadowRD::compute_splits(st, sun_along(sun_dirs[l]), cams[c], proj, s, z_near, z_far);
				REQUIRE(n == expected_count[m]);
				const float max_d = st.max_distance > 0.0f ? std::fmin(st.max_distance, z_far) : z_far;
				CHECK(s[0].range_begin == doctest::Approx(z_near));
				CHECK(s[n - 1].range_end == doctest::Approx(max_d));
				for (uint32_t k = 0; k < n; k++) {
					INFO("mode ", m, " light ", l, " camera ", c, " split ", k);
					CHECK(s[k].range_end > s[k].range_begin);
					if (k + 1 < n) {
						CHECK(s[k].range_end == s[k + 1].range_begin); // No gap, no overlap.
						CHECK(s[k + 1].radius >= s[k].radius * 0.999f); // Farther slices are larger.
					}
					// Godot's split offsets: z_near + split_k * range.
					if (n > 1 && k + 1 < n) {
						CHECK(s[k].range_end == doctest::Approx(z_near + st.split_offsets[k] * (max_d - z_near)));
					}
					for (int v = 0; v < 8; v++) {
						const Vector3 p = s[k].to_light(s[k].corners[v]);
						CHECK(std::fabs(p.x) <= s[k].radius * 1.0001f);
						CHECK(std::fabs(p.y) <= s[k].radius * 1.0001f);
						CHECK(p.z >= s[k].z_min - 1e-3f);
						CHECK(p.z <= s[k].z_max + 1e-3f);
						// The clip transform maps the slice into the unit box and depth 0..1.
						const Vector3 q = s[k].get_clip_from_world().xform(s[k].corners[v]);
						CHECK(std::fabs(q.x) <= 1.0001f);
						CHECK(std::fabs(q.y) <= 1.0001f);
						CHECK(q.z >= -1e-4f);
						CHECK(q.z <= 1.0001f);
						checked_corners++;
					}
					// The corners of the slices are the view frustum's at the split depths (the view ray through
					// the corner at depth d lies at d along the camera's -Z).
					const Vector3 back = cams[c].affine_inverse().xform(s[k].corners[0]);
					CHECK(-back.z == doctest::Approx(s[k].range_begin).epsilon(1e-4));
					// Texel snapping: the centre's light-space x and y are whole texels of the split.
					const float unit = 2.0f * s[k].radius / float(st.tile_width[k]);
					const Vector3 cl = s[k].light_basis.xform_inv(s[k].center);
					CHECK(std::fabs(cl.x / unit - std::round(cl.x / unit)) < 1e-2f);
					CHECK(std::fabs(cl.y / unit - std::round(cl.y / unit)) < 1e-2f);
				}
			}
		}
	}
	CHECK(checked_corners == 8 * 3 * 3 * (1 + 2 + 4));

	// Stability: turning the camera keeps every radius (the bounding sphere of a slice depends on its shape
	// only), and moving it by a fraction of a texel keeps the box on the same texel grid.
	DirectionalShadowRD::SplitSettings st;
	const Projection proj = Projection::create_perspective(60.0f, 1.0f, 0.05f, 200.0f);
	DirectionalShadowRD::Split a[4], b[4], moved[4];
	const Transform3D sun = sun_along(Vector3(0.4f, -1.0f, 0.3f));
	DirectionalShadowRD::compute_splits(st, sun, camera_at(Vector3(0, 2, 0), Vector3(5, 1, 3)), proj, a);
	DirectionalShadowRD::compute_splits(st, sun, camera_at(Vector3(0, 2, 0), Vector3(-4, 0, 1)), proj, b);
	Transform3D shifted = camera_at(Vector3(0, 2, 0), Vector3(5, 1, 3));
	shifted.origin += Vector3(0.013f, 0.0f, -0.007f);
	DirectionalShadowRD::compute_splits(st, sun, shifted, proj, moved);
	for (int k = 0; k < 4; k++) {
		CHECK(a[k].radius == doctest::Approx(b[k].radius).epsilon(1e-4));
		const float unit = 2.0f * a[k].radius / float(st.tile_width[k]);
		const Vector3 d = a[k].light_basis.xform_inv(moved[k].center - a[k].center);
		CHECK(std::fabs(d.x / unit - std::round(d.x / unit)) < 2e-2f);
		CHECK(std::fabs(d.y / unit - std::round(d.y / unit)) < 2e-2f);
	}
}

// Visibility of each pixel (shadowed / unshadowed radiance, red channel) where the unshadowed image is lit.
// r_shadow_rmse: over the pixels either image shadows (visibility < 0.99), where the error lives.
static double visibility_rmse(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int &r_pixels, double &r_mean_gpu, double &r_mean_ref, double &r_shadow_rmse, int &r_shadow_pixels) {
	double sum = 0.0, sum_gpu = 0.0, sum_ref = 0.0, sum_shadow = 0.0;
	r_pixels = 0;
	r_shadow_pixels = 0;
	for (size_t i = 0; i < p_open.size() / 4; i++) {
		const double o = p_open[i * 4], ro = p_ref_open[i * 4];
		if (o < 0.05 || ro < 0.05) {
			continue; // Faces turned from the sun and the background: no visibility to compare.
		}
		const double vg = std::fmin(p_shadowed[i * 4] / o, 1.0), vr = std::fmin(p_ref_shadowed[i * 4] / ro, 1.0);
		sum += (vg - vr) * (vg - vr);
		if (vg < 0.99 || vr < 0.99) {
			sum_shadow += (vg - vr) * (vg - vr);
			r_shadow_pixels++;
		}
		sum_gpu += vg;
		sum_ref += vr;
		r_pixels++;
	}
	r_mean_gpu = r_pixels ? sum_gpu / r_pixels : 0.0;
	r_mean_ref = r_pixels ? sum_ref / r_pixels : 0.0;
	r_shadow_rmse = r_shadow_pixels ? std::sqrt(sum_shadow / r_shadow_pixels) : 1.0;
	return r_pixels ? std::sqrt(sum / r_pixels) : 1.0;
}

TEST_CASE("[Render][DirectionalShadowRD] the shadow of a box on a plane matches the Embree reference: PSSM at 3 camera distances, ORTHOGONAL, PSSM 2, blend_splits") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		ReferenceRenderOptions open_options;
		open_options.threads = 2;
		open_options.sun_samples = 64;
		ReferenceRenderOptions shadow_options = open_options;
		shadow_options.shadows = true;
		ReferenceRenderer ref_open(&f.light_storage, &f.mesh_storage, &f.material_storage, open_options);
		ReferenceRenderer ref_shadow(&f.light_storage, &f.mesh_storage, &f.material_storage, shadow_options);

		const int W = 64, H = 48;
		RID plane = f.plane(80.0f);
		RID box = f.mesh(RenderTest::make_box(Vector3(0.5f, 0.5f, 0.5f)));
		RS::MaterialParams mp;
		mp.albedo = Color(1, 1, 1, 1);
		mp.roughness = 1.0f;
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		RID mat = f.material(mp);
		RID sun = f.light_storage.light_create(RS::LIGHT_DIRECTIONAL);
		f.lights.push_back(sun);
		// DirectionalLight3D's defaults (scene/3d/light_3d.cpp).
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE, 100.0f);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_FADE_START, 0.8f);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS, 2.0f);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_BIAS, 0.1f);
		RID rt = f.renderer.render_target_create(W, H);
		RID rt_open = ref_open.render_target_create(W, H);
		RID rt_shadow = ref_shadow.render_target_create(W, H);
		REQUIRE(rt.is_valid());

		// PSSM 4 at camera distances whose view of the box falls in splits 0, 1 and 2 (defaults 0.1, 0.2, 0.5 of
		// 100 m), with a soft (2 degree disk: blocker search + PCF) and a hard (0 degrees: 1 texel PCF) sun; then
		// ORTHOGONAL, PSSM 2 and blend_splits. Bounds: about twice the RMSE measured on lavapipe (doc/sun_sky.md);
		// since the biases follow Godot's metres (more offset in coarse splits: ORTHOGONAL over 100 m, PSSM 2, and
		// the 1-texel hard PCF at 4 m), those three cases about 1.25 times their measured RMSE.
		struct Case {
			RS::LightDirectionalShadowMode mode;
			float angular_distance;
			bool blend_splits;
			float distance;
			uint32_t passes;
			double bound; // Visibility RMSE over the lit pixels.
			double shadow_bound; // ... over the pixels either image shadows.
		};
		const RS::LightDirectionalShadowMode PSSM4 = RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS;
		const Case cases[] = {
			{ PSSM4, 2.0f, false, 4.0f, 4, 0.04, 0.2 },
			{ PSSM4, 2.0f, false, 15.0f, 4, 0.04, 0.2 },
			{ PSSM4, 2.0f, false, 35.0f, 4, 0.04, 0.2 },
			{ PSSM4, 0.0f, false, 4.0f, 4, 0.09, 0.55 },
			{ PSSM4, 0.0f, false, 15.0f, 4, 0.08, 0.4 },
			{ PSSM4, 0.0f, false, 35.0f, 4, 0.08, 0.4 },
			{ RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL, 2.0f, false, 4.0f, 1, 0.065, 0.4 },
			{ RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL, 2.0f, false, 15.0f, 1, 0.04, 0.2 },
			{ RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_2_SPLITS, 2.0f, false, 15.0f, 2, 0.06, 0.45 },
			{ PSSM4, 2.0f, true, 15.0f, 4, 0.04, 0.2 },
		};
		for (const Case &c : cases) {
			f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SIZE, c.angular_distance);
			f.light_storage.light_directional_set_shadow_mode(sun, c.mode);
			f.light_storage.light_directional_set_blend_splits(sun, c.blend_splits);
			const float dist = c.distance;
			const Vector3 eye = Vector3(0.0f, 0.55f, 1.0f).normalized() * dist;
			// The field of view narrows with distance so the box and its shadow keep their size on screen.
			RenderSceneData d = make_scene(camera_at(eye, Vector3(0, 0.3f, 0)), Math::rad_to_deg(2.0f * std::atan(2.5f / dist)), W, H, 200.0f);
			add_geometry(d, plane, mat, Transform3D());
			add_geometry(d, box, mat, Transform3D(Basis(), Vector3(0, 0.5f, 0)));
			RenderSceneData::LightInstance l;
			l.light = sun;
			l.type = RS::LIGHT_DIRECTIONAL;
			l.transform = sun_along(Vector3(0.6f, -1.0f, 0.35f));
			d.directional_lights.push_back(l);

			f.light_storage.light_set_shadow(sun, false);
			f.renderer.render_scene(d, rt);
			const std::vector<float> open = f.renderer.render_target_get_data(rt);
			CHECK_FALSE(has_pass(f.renderer.get_last_frame_profile(), "directional_shadows"));
			ref_open.render_scene(d, rt_open);
			f.light_storage.light_set_shadow(sun, true);
			f.renderer.render_scene(d, rt);
			const std::vector<float> shadowed = f.renderer.render_target_get_data(rt);
			CHECK(has_pass(f.renderer.get_last_frame_profile(), "directional_shadows"));
			CHECK(f.renderer.get_directional_shadows().get_frame_pass_count() == c.passes);
			ref_shadow.render_scene(d, rt_shadow);
			int pixels = 0, shadow_pixels = 0;
			double mean_gpu = 0.0, mean_ref = 0.0, shadow_rmse = 1.0;
			const double rmse = visibility_rmse(open, shadowed, ref_open.render_target_get_data(rt_open), ref_shadow.render_target_get_data(rt_shadow), pixels, mean_gpu, mean_ref, shadow_rmse, shadow_pixels);
			MESSAGE("mode ", int(c.mode), " blend_splits ", c.blend_splits, " light_angular_distance ", c.angular_distance, ", camera distance ", dist, " m: visibility RMSE ", rmse, " over ", pixels,
					" lit pixels (", shadow_rmse, " over the ", shadow_pixels, " shadowed ones); mean visibility GPU ", mean_gpu, " reference ", mean_ref);
			CHECK(pixels > W * H / 2);
			CHECK(shadow_pixels > 30); // The shadow is in view (else the comparison says nothing).
			CHECK(rmse < c.bound);
			CHECK(shadow_rmse < c.shadow_bound);
			CHECK(std::fabs(mean_gpu - mean_ref) < 0.007);
		}
		CHECK((f.renderer.get_compiled_feature_mask() & RenderForwardClustered::SCENE_VERSION_DIRECTIONAL_SHADOWS) != 0u);
		ref_open.render_target_free(rt_open);
		ref_shadow.render_target_free(rt_shadow);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

// Measured 2026-12-02 03:40 UTC on lavapipe (doc/sun_sky.md, "Depth bias"): with Godot's defaults no acne pixel
// on the bare plane (0 of about 7000; 98 % acne with both biases 0, so the check can fail); the box's shadow
// starts 0.05 m from its base (pixels of 0.037 m). Bounds: under 7 pixels of acne, 0.1 m.
static const double ACNE_FRACTION_BOUND = 0.001;
static const double PETER_PAN_BOUND_M = 0.1;

TEST_CASE("[Render][DirectionalShadowRD] Godot's shadow_bias in metres: a grazing sun leaves a bare plane acne-free and a box's shadow attached") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	// The metres formula itself (Godot 4: shadow_bias / 100 * (2 radius + pancake) * shadow_blur).
	CHECK(DirectionalShadowRD::get_bias_metres(0.1f, 5.0f, 20.0f, 1.0f) == doctest::Approx(0.03f));
	CHECK(DirectionalShadowRD::get_bias_metres(0.1f, 5.0f, 20.0f, 2.0f) == doctest::Approx(0.06f));
	CHECK(DirectionalShadowRD::get_normal_bias_metres(2.0f, 5.0f, 2048) == doctest::Approx(2.0f * 10.0f / 2048.0f));
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		const int W = 128, H = 96;
		RID plane = f.plane(150.0f);
		RID box = f.mesh(RenderTest::make_box(Vector3(0.5f, 0.5f, 0.5f)));
		RS::MaterialParams mp;
		mp.albedo = Color(1, 1, 1, 1);
		mp.roughness = 1.0f;
		mp.specular = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		RID mat = f.material(mp);
		RID sun = f.light_storage.light_create(RS::LIGHT_DIRECTIONAL);
		f.lights.push_back(sun);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE, 100.0f);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_FADE_START, 0.8f);
		f.light_storage.light_directional_set_shadow_mode(sun, RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS);
		RID rt = f.renderer.render_target_create(W, H);
		RenderSceneData::LightInstance l;
		l.light = sun;
		l.type = RS::LIGHT_DIRECTIONAL;
		// A grazing sun, 15 degrees above the horizon: the worst case for acne on a plane.
		const Vector3 sun_dir = Vector3(0.5f, -std::tan(Math::deg_to_rad(15.0f)), -0.866f).normalized();
		l.transform = sun_along(sun_dir);

		// 1. The bare plane seen from 1.7 m out to 100 m: every split, no caster but the plane itself.
		auto acne_fraction = [&](float p_bias, float p_normal_bias) {
			f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_BIAS, p_bias);
			f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS, p_normal_bias);
			RenderSceneData d = make_scene(camera_at(Vector3(0, 1.7f, 0), Vector3(0, 0.2f, -10.0f)), 70.0f, W, H, 200.0f);
			add_geometry(d, plane, mat, Transform3D());
			d.directional_lights.push_back(l);
			f.light_storage.light_set_shadow(sun, false);
			f.renderer.render_scene(d, rt);
			const std::vector<float> open = f.renderer.render_target_get_data(rt);
			f.light_storage.light_set_shadow(sun, true);
			f.renderer.render_scene(d, rt);
			const std::vector<float> shadowed = f.renderer.render_target_get_data(rt);
			int plane_pixels = 0, acne = 0;
			for (int i = 0; i < W * H; i++) {
				if (open[i * 4 + 1] <= 1e-4f) {
					continue; // Background.
				}
				plane_pixels++;
				acne += shadowed[i * 4 + 1] / open[i * 4 + 1] < 0.98f ? 1 : 0;
			}
			REQUIRE(plane_pixels > W * H / 3);
			return double(acne) / double(plane_pixels);
		};
		const double acne_default = acne_fraction(0.1f, 2.0f); // DirectionalLight3D's defaults.
		const double acne_none = acne_fraction(0.0f, 0.0f);
		MESSAGE("bare plane under a 15 degree sun: acne fraction ", acne_default, " with Godot's default biases, ", acne_none, " with none");
		CHECK(acne_default <= ACNE_FRACTION_BOUND);
		CHECK(acne_none > 0.05); // Without bias the same view has acne: the check above can fail.

		// 2. A 1 m box on the plane, the camera 4 m away (split 0), a 35 degree sun: how far from the box's base
		// the GPU's shadow leaves lit plane that the exact shadow (the box's silhouette cast analytically) covers.
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_BIAS, 0.1f);
		f.light_storage.light_set_param(sun, RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS, 2.0f);
		const Vector3 sun2 = Vector3(0.6f, -std::tan(Math::deg_to_rad(35.0f)), 0.35f).normalized();
		l.transform = sun_along(sun2);
		const Transform3D cam = camera_at(Vector3(0.0f, 2.2f, 3.4f), Vector3(-0.6f, 0.0f, -0.4f));
		RenderSceneData d = make_scene(cam, 60.0f, W, H, 200.0f);
		add_geometry(d, plane, mat, Transform3D());
		add_geometry(d, box, mat, Transform3D(Basis(), Vector3(0, 0.5f, 0)));
		d.directional_lights.push_back(l);
		f.light_storage.light_set_shadow(sun, false);
		f.renderer.render_scene(d, rt);
		const std::vector<float> open = f.renderer.render_target_get_data(rt);
		f.light_storage.light_set_shadow(sun, true);
		f.renderer.render_scene(d, rt);
		const std::vector<float> shadowed = f.renderer.render_target_get_data(rt);
		// Walk from the box's footprint along the shadow's axis (away from the sun, on the plane), where the exact
		// shadow is unambiguous, until the GPU's visibility first drops below 1/2: that distance is the gap.
		const Projection clip_from_world = Projection::create_depth_correction(true) * d.cam_projection * Projection::from_transform(cam.affine_inverse());
		const Vector3 axis = Vector3(sun2.x, 0.0f, sun2.z).normalized();
		const float exit = 0.5f / std::fmax(std::fabs(axis.x), std::fabs(axis.z)); // Leaves the 1 m footprint.
		const float shadow_length = 1.0f / std::tan(Math::deg_to_rad(35.0f)); // The box top's shadow, beyond the base.
		double gap = -1.0;
		int samples = 0;
		for (float t = 0.0f; t < shadow_length * 0.8f; t += 0.01f) {
			const Vector3 p = axis * (exit + t);
			const Vector3 c = clip_from_world.xform(p); // Divides by w.
			const int px = int((c.x * 0.5f + 0.5f) * W), py = int((c.y * 0.5f + 0.5f) * H);
			if (px < 0 || py < 0 || px >= W || py >= H) {
				continue;
			}
			samples++;
			const size_t i = (size_t(py) * W + px) * 4;
			if (open[i + 1] > 1e-4f && shadowed[i + 1] / open[i + 1] < 0.5f) {
				gap = t;
				break;
			}
		}
		MESSAGE("box on the plane under a 35 degree sun: the GPU's shadow starts ", gap, " m from the box's base along its axis (", samples, " samples; pixel about ", 2.0 * 4.1 * std::tan(Math::deg_to_rad(30.0f)) / W, " m)");
		CHECK(samples > 0); // The base of the shadow is in view.
		CHECK(gap >= 0.0); // The shadow is found at all.
		CHECK(gap <= PETER_PAN_BOUND_M);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[Render][DirectionalShadowRD] a view without a shadowed sun builds no atlas, records no pass and compiles no shadow code") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderTest::RenderFixture f;
		REQUIRE(f.init());
		RID plane = f.plane(5.0f);
		RS::MaterialParams mp;
		RID mat = f.material(mp);
		RID sun = f.light_storage.light_create(RS::LIGHT_DIRECTIONAL); // shadow_enabled off (Godot's default).
		f.lights.push_back(sun);
		RID rt = f.renderer.render_target_create(16, 16);
		RenderSceneData d = make_scene(RenderTest::camera_looking_down(3.0f), 60.0f, 16, 16, 20.0f);
		add_geometry(d, plane, mat, Transform3D());
		f.renderer.render_scene(d, rt); // No sun at all.
		CHECK_FALSE(has_pass(f.renderer.get_last_frame_profile(), "directional_shadows"));
		RenderSceneData::LightInstance l;
		l.light = sun;
		l.type = RS::LIGHT_DIRECTIONAL;
		l.transform = sun_along(Vector3(0.2f, -1.0f, 0.1f));
		d.directional_lights.push_back(l);
		f.renderer.render_scene(d, rt); // An unshadowed sun.
		CHECK(has_pass(f.renderer.get_last_frame_profile(), "opaque"));
		CHECK_FALSE(has_pass(f.renderer.get_last_frame_profile(), "directional_shadows"));
		CHECK_FALSE(f.renderer.get_directional_shadows().is_created());
		CHECK_FALSE(f.renderer.get_directional_shadows().get_data_buffer().is_valid());
		CHECK(f.renderer.get_directional_shadows().get_frame_pass_count() == 0u);
		CHECK((f.renderer.get_compiled_feature_mask() & RenderForwardClustered::SCENE_VERSION_DIRECTIONAL_SHADOWS) == 0u);
		CHECK(f.light_storage.get_directional_light_block().data[0].shadow_index == -1);
		CHECK(RenderForwardClustered::get_scene_version_defines(RenderForwardClustered::SCENE_VERSION_DIRECTIONAL).find("USE_DIRECTIONAL_SHADOWS") == String::npos);

		// Turning shadows on creates the atlas at the project setting's size and one pass per split.
		f.light_storage.light_set_shadow(sun, true);
		f.light_storage.light_directional_set_shadow_mode(sun, RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_2_SPLITS);
		f.renderer.render_scene(d, rt);
		CHECK(has_pass(f.renderer.get_last_frame_profile(), "directional_shadows"));
		CHECK(f.renderer.get_directional_shadows().is_created());
		CHECK(f.renderer.get_directional_shadows().get_atlas_size() == f.renderer.get_directional_shadows().get_requested_atlas_size());
		CHECK(f.renderer.get_directional_shadows().get_frame_pass_count() == 2u);
		CHECK(f.light_storage.get_directional_light_block().data[0].shadow_index == 0);
		f.light_storage.light_directional_set_shadow_mode(sun, RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL);
		f.renderer.render_scene(d, rt);
		CHECK(f.renderer.get_directional_shadows().get_frame_pass_count() == 1u);
		CHECK(f.renderer.get_directional_shadows().get_last_draw_count() == 1u); // The plane.
		// Bad atlas sizes are refused with an error and change nothing.
		set_error_print_silenced(true);
		CHECK_FALSE(f.renderer.get_directional_shadows().set_atlas_size(1000));
		set_error_print_silenced(false);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestDirectionalShadow
