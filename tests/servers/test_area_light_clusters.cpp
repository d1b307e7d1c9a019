/**************************************************************************/
/*  test_area_light_clusters.cpp                                          */
/**************************************************************************/
/* godot-area: area lights in the cluster builder (element type AREA,     */
/* oriented box (a + 2r) x (b + 2r) x r in front of the light, thesis     */
/* section 5.1.1) on lavapipe: no point of the true influence region is   */
/* ever missed, the box takes no more clusters than the eq. 5.1 sphere    */
/* (ratios printed), the debug view writes the per-pixel counts, and      */
/* clustered shading equals brute force with area, omni and spot lights.  */

#include "servers/rendering/renderer_rd/cluster_builder_rd.h"

#include "core/math/math_funcs.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

namespace TestAreaLightClusters {

struct Rng {
	uint32_t seed;
	float next() {
		seed = seed * 1664525u + 1013904223u;
		return float(seed >> 8) / float(1u << 24);
	}
	float range(float p_a, float p_b) { return p_a + (p_b - p_a) * next(); }
};

// A view-space area light for the cluster builder.
struct ViewAreaLight {
	Vector3 center, half_x, half_y, normal;
	float range;
};

static ViewAreaLight random_light(Rng &r_rng) {
	ViewAreaLight l;
	l.center = Vector3(r_rng.range(-6, 6), r_rng.range(-4, 4), r_rng.range(-20, -3));
	Basis b = Basis::from_euler(Vector3(r_rng.range(-3.1f, 3.1f), r_rng.range(-3.1f, 3.1f), r_rng.range(-3.1f, 3.1f)));
	float a = r_rng.range(0.0f, 4.0f), h = r_rng.range(0.0f, 2.0f);
	l.half_x = b.xform(Vector3(1, 0, 0)) * (a * 0.5f);
	l.half_y = b.xform(Vector3(0, 1, 0)) * (h * 0.5f);
	l.normal = b.xform(Vector3(0, 0, -1));
	l.range = r_rng.range(0.3f, 4.0f);
	return l;
}

struct ClusterSetup {
	ClusterBuilderRD builder;
	Projection clip_from_view;
	uint32_t width = 256, height = 192;
	float z_far = 40.0f;
	std::vector<uint32_t> words;

	bool init() {
		if (!builder.initialize(64) || !builder.setup(width, height)) {
			return false;
		}
		clip_from_view = Projection::create_depth_correction(true) * Projection::create_perspective(60.0f, float(width) / float(height), 0.05f, z_far);
		builder.begin(clip_from_view, z_far);
		return true;
	}
	void bake(RenderingDevice *p_rd) {
		builder.bake_cluster();
		std::vector<uint8_t> raw = p_rd->buffer_get_data(builder.get_cluster_buffer());
		words.resize(raw.size() / 4);
		memcpy(words.data(), raw.data(), words.size() * 4);
	}
	bool has(ClusterBuilderRD::ElementType p_type, uint32_t p_index, uint32_t p_tx, uint32_t p_ty, uint32_t p_slice) const {
		uint32_t offset = builder.get_cluster_offset(p_type, p_tx, p_ty, p_slice) + p_index / 32;
		return (words[offset] >> (p_index % 32)) & 1u;
	}
	// Cluster of a view-space point (false when it is outside the view).
	bool cluster_of(const Vector3 &p_view, uint32_t &r_tx, uint32_t &r_ty, uint32_t &r_slice) const {
		float depth = -p_view.z;
		if (depth <= 0.06f || depth >= z_far) {
			return false;
		}
		Vector3 ndc = clip_from_view.xform(p_view);
		if (std::fabs(ndc.x) >= 0.999f || std::fabs(ndc.y) >= 0.999f) {
			return false;
		}
		float px = (ndc.x * 0.5f + 0.5f) * width;
		float py = (ndc.y * 0.5f + 0.5f) * height;
		r_tx = std::min(uint32_t(px) / builder.get_tile_size(), builder.get_tiles_x() - 1);
		r_ty = std::min(uint32_t(py) / builder.get_tile_size(), builder.get_tiles_y() - 1);
		r_slice = std::min(uint32_t(depth / builder.get_slice_depth() * ClusterBuilderRD::Z_SLICES), ClusterBuilderRD::Z_SLICES - 1);
		return true;
	}
	uint32_t count(ClusterBuilderRD::ElementType p_type, uint32_t p_index) const {
		uint32_t n = 0;
		for (uint32_t ty = 0; ty < builder.get_tiles_y(); ty++) {
			for (uint32_t tx = 0; tx < builder.get_tiles_x(); tx++) {
				for (uint32_t s = 0; s < ClusterBuilderRD::Z_SLICES; s++) {
					n += has(p_type, p_index, tx, ty, s) ? 1 : 0;
				}
			}
		}
		return n;
	}
};

TEST_CASE("[AreaLight3D][Cluster] every point of an area light's influence region lies in a cluster that lists the light") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ClusterSetup cs;
		REQUIRE(cs.init());
		Rng rng{ 777u };
		std::vector<ViewAreaLight> lights;
		for (int i = 0; i < 40; i++) {
			lights.push_back(random_light(rng));
			const ViewAreaLight &l = lights.back();
			REQUIRE(cs.builder.add_area_light(l.center, l.half_x, l.half_y, l.normal, l.range));
		}
		cs.bake(rd);
		CHECK(cs.builder.get_element_count(ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT) == 40);

		int tested = 0, missed = 0;
		uint64_t assigned = 0;
		for (uint32_t i = 0; i < lights.size(); i++) {
			const ViewAreaLight &l = lights[i];
			assigned += cs.count(ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT, i);
			for (int k = 0; k < 400; k++) {
				// Closest point on the rectangle plus an offset in the front half-ball of radius r.
				Vector3 q = l.center + l.half_x * rng.range(-1, 1) + l.half_y * rng.range(-1, 1);
				Vector3 w;
				do {
					w = Vector3(rng.range(-1, 1), rng.range(-1, 1), rng.range(-1, 1));
				} while (w.length_squared() > 1.0f);
				if (w.dot(l.normal) < 0.0f) {
					w = w - l.normal * (2.0f * w.dot(l.normal));
				}
				// Bias a third of the samples to the boundary of the region (the hardest case).
				if (k % 3 == 0 && w.length_squared() > 1e-6f) {
					w = w.normalized() * 0.999f;
				}
				Vector3 p = q + w * l.range;
				uint32_t tx, ty, slice;
				if (!cs.cluster_of(p, tx, ty, slice)) {
					continue;
				}
				tested++;
				if (!cs.has(ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT, i, tx, ty, slice)) {
					missed++;
				}
			}
		}
		uint64_t total = uint64_t(cs.builder.get_tiles_x()) * cs.builder.get_tiles_y() * ClusterBuilderRD::Z_SLICES * lights.size();
		MESSAGE("area light cluster test: ", tested, " points, ", missed, " missed; ", assigned, " of ", total, " (light, cluster) pairs assigned");
		CHECK(tested > 4000);
		CHECK_MESSAGE(missed == 0, "a cluster containing a lit point must list the area light");
		CHECK(assigned < total / 4); // The boxes actually cull.
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Cluster] the tile size keeps the tile grid within its budget") {
	// Small views get fine tiles (a 16 px tile is a twelfth of a 192 px view), 720p and 1080p Godot's 16 px,
	// 4K coarser ones so the cluster buffer does not grow with the pixel count.
	CHECK(ClusterBuilderRD::tile_size_for(192, 108) == 8);
	CHECK(ClusterBuilderRD::tile_size_for(640, 360) == 8);
	CHECK(ClusterBuilderRD::tile_size_for(1280, 720) == 16);
	CHECK(ClusterBuilderRD::tile_size_for(1920, 1080) == 16);
	CHECK(ClusterBuilderRD::tile_size_for(3840, 2160) == 32);
	for (uint32_t w : { 16u, 100u, 777u, 1920u, 2560u, 4096u }) {
		for (uint32_t h : { 16u, 99u, 1080u, 1440u, 4096u }) {
			const uint32_t t = ClusterBuilderRD::tile_size_for(w, h);
			const uint64_t tiles = uint64_t((w + t - 1) / t) * ((h + t - 1) / t);
			CHECK(tiles <= ClusterBuilderRD::MAX_TILES);
			if (t > ClusterBuilderRD::MIN_TILE_SIZE) {
				const uint32_t finer = t / 2; // The next finer size would break the budget.
				CHECK(uint64_t((w + finer - 1) / finer) * ((h + finer - 1) / finer) > ClusterBuilderRD::MAX_TILES);
			}
		}
	}
}

TEST_CASE("[AreaLight3D][Cluster] the oriented box takes no more clusters than the eq. 5.1 bounding sphere") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		const float sizes[][2] = { { 0.0f, 0.0f }, { 1.0f, 1.0f }, { 4.0f, 1.0f }, { 4.0f, 4.0f } };
		const float ranges[] = { 0.5f, 2.0f, 5.0f };
		// Orientations: facing the camera, facing sideways, facing up (a ceiling-like light seen obliquely).
		const Vector3 rotations[] = { Vector3(0, float(Math::PI), 0), Vector3(0, float(Math::PI) * 0.5f, 0), Vector3(float(Math::PI) * 0.5f, 0, 0) };
		uint64_t box_total = 0, sphere_total = 0;
		int configs = 0, worse = 0;
		for (const auto &size : sizes) {
			for (float r : ranges) {
				ClusterSetup cs;
				REQUIRE(cs.init());
				uint32_t n = 0;
				for (const Vector3 &rot : rotations) {
					Basis b = Basis::from_euler(rot);
					Vector3 c(0.5f, -0.3f, -12.0f);
					Vector3 hx = b.xform(Vector3(1, 0, 0)) * (size[0] * 0.5f);
					Vector3 hy = b.xform(Vector3(0, 1, 0)) * (size[1] * 0.5f);
					Vector3 normal = b.xform(Vector3(0, 0, -1));
					cs.builder.add_area_light(c, hx, hy, normal, r);
					float radius = r + std::sqrt(size[0] * size[0] + size[1] * size[1]) * 0.5f; // Thesis eq. 5.1.
					cs.builder.add_light(ClusterBuilderRD::ELEMENT_TYPE_OMNI_LIGHT, c, radius);
					n++;
				}
				cs.bake(rd);
				for (uint32_t i = 0; i < n; i++) {
					uint32_t box = cs.count(ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT, i);
					uint32_t sphere = cs.count(ClusterBuilderRD::ELEMENT_TYPE_OMNI_LIGHT, i);
					MESSAGE("size ", size[0], "x", size[1], " range ", r, " orientation ", i, ": box ", box, " clusters, sphere ", sphere, ", ratio ",
							sphere ? double(box) / sphere : 0.0);
					box_total += box;
					sphere_total += sphere;
					configs++;
					worse += box > sphere ? 1 : 0;
					CHECK(sphere > 0);
					CHECK(box > 0);
					CHECK_MESSAGE(box <= sphere, "the box must not take more clusters than the sphere");
				}
			}
		}
		MESSAGE("box / sphere cluster assignment over ", configs, " configurations: ", double(box_total) / double(sphere_total), " (", worse, " worse)");
		CHECK(box_total < sphere_total);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

/* Rendering: clustered == brute force, debug view. */

// Storages + renderer (tests/servers/render_test_fixture.h), 64 lights per type.
struct RenderFixture : RenderTest::RenderFixture {
	bool init() { return RenderTest::RenderFixture::init(64); }
};

using RenderTest::add_quad;
using RenderTest::make_box;

// A ground plane, three boxes, 12 area lights + 8 omni + 8 spot lights at random.
static RenderSceneData build_mixed_scene(RenderFixture &f, int p_w, int p_h) {
	RS::SurfaceData plane;
	add_quad(plane, Vector3(), Vector3(0, 0, 10), Vector3(10, 0, 0));
	RID plane_mesh = f.mesh_storage.mesh_create();
	f.mesh_storage.mesh_add_surface(plane_mesh, plane);
	RID box_mesh = f.mesh_storage.mesh_create();
	f.mesh_storage.mesh_add_surface(box_mesh, make_box(Vector3(0.5f, 0.5f, 0.5f)));
	f.meshes = { plane_mesh, box_mesh };
	RID ground = f.material_storage.material_create();
	RID glossy = f.material_storage.material_create();
	f.materials = { ground, glossy };
	RS::MaterialParams gp;
	gp.albedo = Color(0.8f, 0.8f, 0.8f, 1);
	gp.roughness = 0.4f;
	gp.cull_back = false;
	f.material_storage.material_set_params(ground, gp);
	RS::MaterialParams bp;
	bp.albedo = Color(0.9f, 0.5f, 0.2f, 1);
	bp.roughness = 0.2f;
	bp.metallic = 0.7f;
	f.material_storage.material_set_params(glossy, bp);

	RenderSceneData d;
	d.cam_transform = Transform3D(Basis::looking_at(Vector3(0, -6, -8)), Vector3(0, 6, 8));
	d.z_near = 0.05f;
	d.z_far = 40.0f;
	d.fovy_degrees = 60.0f;
	d.cam_projection = Projection::create_perspective(60.0f, float(p_w) / float(p_h), d.z_near, d.z_far);
	d.viewport_width = p_w;
	d.viewport_height = p_h;
	d.environment.has_environment = true;
	d.environment.background = RS::ENV_BG_COLOR;
	d.environment.bg_color = Color(0, 0, 0, 1);
	auto geometry = [&d](RID p_mesh, RID p_mat, const Transform3D &p_xform) {
		RenderSceneData::GeometryInstance g;
		g.mesh = p_mesh;
		g.material_override = p_mat;
		g.transform = p_xform;
		d.geometry.push_back(g);
	};
	geometry(plane_mesh, ground, Transform3D());
	geometry(box_mesh, glossy, Transform3D(Basis(), Vector3(-2, 0.5f, 0)));
	geometry(box_mesh, glossy, Transform3D(Basis::from_axis_angle(Vector3(0, 1, 0), 0.6f), Vector3(1.5f, 0.5f, -1.5f)));
	geometry(box_mesh, glossy, Transform3D(Basis(), Vector3(0.5f, 0.5f, 2.5f)));

	Rng rng{ 4242u };
	for (int i = 0; i < 28; i++) {
		RS::LightType type = i < 12 ? RS::LIGHT_AREA : (i % 2 ? RS::LIGHT_SPOT : RS::LIGHT_OMNI);
		RID l = f.light_storage.light_create(type);
		f.lights.push_back(l);
		f.light_storage.light_set_param(l, RS::LIGHT_PARAM_ENERGY, rng.range(0.5f, 2.5f));
		f.light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, rng.range(0.8f, 3.0f));
		f.light_storage.light_set_param(l, RS::LIGHT_PARAM_ATTENUATION, rng.range(0.0f, 2.0f));
		f.light_storage.light_set_color(l, Color(rng.range(0.3f, 1), rng.range(0.3f, 1), rng.range(0.3f, 1), 1));
		Vector3 pos(rng.range(-6, 6), rng.range(0.2f, 2.5f), rng.range(-6, 6));
		Basis basis = Basis::from_euler(Vector3(rng.range(-3, 3), rng.range(-3, 3), rng.range(-3, 3)));
		if (type == RS::LIGHT_AREA) {
			f.light_storage.light_area_set_size(l, Vector2(rng.range(0.1f, 2.0f), rng.range(0.1f, 2.0f)));
		} else if (type == RS::LIGHT_SPOT) {
			f.light_storage.light_set_param(l, RS::LIGHT_PARAM_SPOT_ANGLE, rng.range(10, 70));
		}
		RenderSceneData::LightInstance li;
		li.light = l;
		li.type = type;
		li.transform = Transform3D(basis, pos);
		d.lights.push_back(li);
	}
	return d;
}

TEST_CASE("[AreaLight3D][Cluster] clustered shading equals brute force with area, omni and spot lights") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RenderSceneData d = build_mixed_scene(f, W, H);
		RID rt = f.renderer.render_target_create(W, H);
		f.renderer.render_scene(d, rt);
		std::vector<float> clustered = f.renderer.render_target_get_data(rt);
		CHECK(f.renderer.get_cluster_builder()->get_element_count(ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT) == 12);
		CHECK(f.light_storage.get_area_light_count() == 12);

		f.renderer.set_debug_force_all_lights(true);
		f.renderer.render_scene(d, rt);
		std::vector<float> brute = f.renderer.render_target_get_data(rt);
		f.renderer.set_debug_force_all_lights(false);

		REQUIRE(clustered.size() == brute.size());
		float max_diff = 0.0f;
		int lit = 0, nan = 0;
		for (size_t i = 0; i < clustered.size(); i++) {
			max_diff = std::max(max_diff, std::fabs(clustered[i] - brute[i]));
			nan += std::isnan(clustered[i]) ? 1 : 0;
			if ((i % 4) != 3 && brute[i] > 0.01f) {
				lit++;
			}
		}
		CHECK(nan == 0);
		CHECK(lit > 200);
		CHECK_MESSAGE(max_diff < 1e-4f, "clustered and brute-force images differ by ", max_diff);

		// Without the area lights the picture must change (they really contribute).
		RenderSceneData no_area = d;
		no_area.lights.erase(no_area.lights.begin(), no_area.lights.begin() + 12);
		f.renderer.render_scene(no_area, rt);
		std::vector<float> without = f.renderer.render_target_get_data(rt);
		float area_diff = 0.0f;
		for (size_t i = 0; i < without.size(); i++) {
			area_diff = std::max(area_diff, std::fabs(without[i] - clustered[i]));
		}
		CHECK(area_diff > 0.01f);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Cluster] the cluster debug view writes per-pixel area-light counts") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int W = 64, H = 64;
		RenderSceneData d = build_mixed_scene(f, W, H);
		RID rt = f.renderer.render_target_create(W, H);
		d.debug_draw = RS::VIEWPORT_DEBUG_DRAW_CLUSTER_AREA_LIGHTS;
		f.renderer.render_scene(d, rt);
		std::vector<float> img = f.renderer.render_target_get_data(rt);
		ClusterBuilderRD *cb = f.renderer.get_cluster_builder();
		std::vector<uint8_t> raw = rd->buffer_get_data(cb->get_cluster_buffer());
		std::vector<uint32_t> words(raw.size() / 4);
		memcpy(words.data(), raw.data(), words.size() * 4);

		// Each pixel's count must be the popcount of one of the 32 slices of its tile, and at least
		// one pixel must show area lights. The exact slice depends on the fragment depth, so check
		// membership in the tile's set of slice counts.
		int nonzero = 0, mismatched = 0, max_count = 0;
		for (int y = 0; y < H; y++) {
			for (int x = 0; x < W; x++) {
				float v = img[(size_t(y) * W + x) * 4];
				int count = int(v + 0.5f);
				max_count = std::max(max_count, count);
				nonzero += count > 0 ? 1 : 0;
				bool ok = false;
				for (uint32_t s = 0; s < ClusterBuilderRD::Z_SLICES && !ok; s++) {
					uint32_t offset = cb->get_cluster_offset(ClusterBuilderRD::ELEMENT_TYPE_AREA_LIGHT, x / cb->get_tile_size(), y / cb->get_tile_size(), s);
					int n = 0;
					for (uint32_t w = 0; w < cb->get_words_per_type(); w++) {
						n += __builtin_popcount(words[offset + w]);
					}
					ok = n == count;
				}
				mismatched += ok || v == 0.0f ? 0 : 1;
			}
		}
		MESSAGE("debug view: ", nonzero, " pixels list area lights, max ", max_count, " per cluster");
		CHECK(nonzero > 0);
		CHECK(max_count <= 12);
		CHECK(mismatched == 0);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightClusters
