/**************************************************************************/
/*  test_area_shadow_adaptive.cpp                                         */
/**************************************************************************/
/* godot-area: GPU side of adaptive area shadows: the reprojection pass   */
/* and the banding detector on a synthetic camera depth and a synthetic  */
/* atlas (each tile fully blocked or fully open), lazy compilation (no    */
/* ADAPTIVE light: no shader), and the over-frames loop through the       */
/* readback ring (results of older frames only), validation clean.        */

#include "servers/rendering/renderer_rd/effects/area_shadow_adaptive.h"

#include "core/config/project_settings.h"
#include "scene/3d/light_3d.h"
#include "servers/rendering/rendering_server_globals.h"
#include "tests/scene/scene_test_fixture.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cstring>
#include <set>

namespace TestAreaShadowAdaptive {

static constexpr uint32_t W = 64;
static constexpr uint32_t H = 64;

struct TilePool : public AreaShadowQuadtree::TileSource {
	std::set<uint32_t> free_tiles;
	std::set<uint32_t> used;
	explicit TilePool(uint32_t p_count) {
		for (uint32_t i = 0; i < p_count; i++) {
			free_tiles.insert(i);
		}
	}
	bool acquire_tile(uint32_t &r_tile) override {
		if (free_tiles.empty()) {
			return false;
		}
		r_tile = *free_tiles.begin();
		free_tiles.erase(free_tiles.begin());
		used.insert(r_tile);
		return true;
	}
	void release_tile(uint32_t p_tile) override {
		used.erase(p_tile);
		free_tiles.insert(p_tile);
	}
};

// Camera looking down -Z at a floor 2 m away (view z = -2); light 1 m above the floor facing it.
struct Scene {
	RenderingDevice *rd = nullptr;
	Projection clip_from_view;
	RID depth;
	RID atlas;
	AreaShadowAdaptiveRD::AtlasInfo atlas_info;
	AreaShadowAdaptiveRD::LightInput light;

	// p_blocked: tiles whose maps see a blocker everywhere (stored distance 0); the others are open.
	Scene(RenderingDevice *p_rd, uint32_t p_subdivision, const std::set<uint32_t> &p_blocked) :
			rd(p_rd) {
		clip_from_view = Projection::create_depth_correction(true) * Projection::create_perspective(60.0f, 1.0f, 0.1f, 10.0f);
		float d = clip_from_view.xform(Vector3(0.0f, 0.0f, -2.0f)).z;
		std::vector<float> depth_data(W * H, d);
		RD::TextureFormat tf;
		tf.format = RD::DATA_FORMAT_R32_SFLOAT;
		tf.width = W;
		tf.height = H;
		tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
		std::vector<uint8_t> bytes(depth_data.size() * 4);
		memcpy(bytes.data(), depth_data.data(), bytes.size());
		depth = rd->texture_create(tf, { bytes });

		const uint32_t size = 128;
		uint32_t tile = size / p_subdivision;
		std::vector<float> atlas_data(size * size, 1e6f);
		for (uint32_t y = 0; y < size; y++) {
			for (uint32_t x = 0; x < size; x++) {
				uint32_t t = (y / tile) * p_subdivision + x / tile;
				if (p_blocked.count(t)) {
					atlas_data[y * size + x] = 0.0f;
				}
			}
		}
		tf.width = size;
		tf.height = size;
		bytes.resize(atlas_data.size() * 4);
		memcpy(bytes.data(), atlas_data.data(), bytes.size());
		atlas = rd->texture_create(tf, { bytes });
		atlas_info.texture = atlas;
		atlas_info.size = size;
		atlas_info.subdivision = p_subdivision;

		light.key = 7;
		light.light_from_view = Transform3D(Basis(), Vector3(0.0f, 0.0f, 1.0f)); // Floor at light z = -1.
		light.size = Vector2(1.0f, 1.0f);
		light.depth_scale = 0.2f;
		light.bias = 0.02f;
	}
	~Scene() {
		rd->free(depth);
		rd->free(atlas);
	}
};

static AreaShadowQuadtree::Query quad(uint32_t p_t0, uint32_t p_t1, uint32_t p_t2, uint32_t p_t3) {
	AreaShadowQuadtree::Query q;
	q.corner_uv[0] = Vector2(0, 0);
	q.corner_uv[1] = Vector2(1, 0);
	q.corner_uv[2] = Vector2(0, 1);
	q.corner_uv[3] = Vector2(1, 1);
	q.corner_tile[0] = p_t0;
	q.corner_tile[1] = p_t1;
	q.corner_tile[2] = p_t2;
	q.corner_tile[3] = p_t3;
	q.uv_min = Vector2(0, 0);
	q.uv_max = Vector2(1, 1);
	return q;
}

TEST_CASE("[AreaShadowAdaptive] reprojection and banding detector on a synthetic atlas") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	{
		Scene scene(rd, 2, { 0, 2 }); // Tiles 0 and 2 blocked, 1 and 3 open.
		AreaShadowAdaptiveRD adaptive;
		REQUIRE(adaptive.initialize());
		// No ADAPTIVE light: a frame with nothing to test compiles nothing.
		adaptive.begin_frame();
		CHECK(adaptive.dispatch(scene.depth, W, H, scene.clip_from_view, scene.atlas_info, {}) == 0);
		CHECK_FALSE(adaptive.is_reprojection_compiled());

		std::vector<AreaShadowQuadtree::Query> queries = {
			quad(0, 1, 2, 3), // Two blocked corners: 0.5 everywhere, a plateau: banding.
			quad(1, 3, 1, 3), // All open: 1, no penumbra.
			quad(0, 0, 2, 2), // All blocked: 0, umbra.
			quad(0, 1, 1, 3), // One blocked: 0.75 plateau: banding.
		};
		std::vector<float> values;
		std::vector<uint32_t> flags = adaptive.test_queries_blocking(scene.depth, W, H, scene.clip_from_view, scene.atlas_info, scene.light, queries, &values);
		CHECK(adaptive.is_reprojection_compiled());
		REQUIRE(flags.size() == 4);
		const uint32_t both = AreaShadowAdaptiveRD::FLAG_BANDING | AreaShadowAdaptiveRD::FLAG_PENUMBRA;
		CHECK(flags[0] == both);
		CHECK(flags[1] == 0); // Lit: neither banding nor penumbra.
		CHECK(flags[2] == 0); // Umbra.
		CHECK(flags[3] == both);
		const uint32_t g = W / AreaShadowAdaptiveRD::DEFAULT_REPROJECTION_DIVISOR; // 8 x 8 grid.
		REQUIRE(values.size() >= 4 * g * g);
		const float expected[4] = { 0.5f, 1.0f, 0.0f, 0.75f };
		for (uint32_t q = 0; q < 4; q++) {
			uint32_t wrong = 0;
			for (uint32_t i = 0; i < g * g; i++) {
				wrong += values[q * g * g + i] == expected[q] ? 0 : 1;
			}
			CHECK_MESSAGE(wrong == 0, "query ", q);
		}
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaShadowAdaptive] over-frames subdivision through the ring uses older frames only") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	{
		// 16 tiles; the root's (0,0) and (0,1) corner maps (tiles 0 and 2) see blockers, every later map is
		// open, so the quads touching those corners keep banding and the tree grows toward them.
		Scene scene(rd, 4, { 0, 2 });
		TilePool pool(16);
		AreaShadowAdaptiveRD adaptive;
		REQUIRE(adaptive.initialize(2));
		adaptive.set_max_depth(2);
		uint32_t results_seen = 0;
		for (uint32_t f = 1; f <= 8; f++) {
			adaptive.begin_frame();
			if (adaptive.get_last_result_frame() != 0) {
				CHECK(adaptive.get_last_result_frame() < adaptive.get_frame()); // Never the frame being built.
				results_seen++;
			}
			AreaShadowQuadtree *tree = adaptive.light_get_tree(scene.light.key, &pool);
			REQUIRE(tree != nullptr);
			tree->collect_draws(); // The synthetic atlas stands for the drawn maps.
			adaptive.dispatch(scene.depth, W, H, scene.clip_from_view, scene.atlas_info, { scene.light });
			rd->submit_and_sync();
		}
		AreaShadowQuadtree *tree = adaptive.light_get_tree(scene.light.key, &pool);
		CHECK(results_seen > 0);
		CHECK(tree->get_point_count() > 4); // Banding made it subdivide.
		CHECK(tree->get_depth() >= 1);
		CHECK(pool.used.size() == tree->get_point_count());
		CHECK(adaptive.get_ring().get_current_frame_poll_count() == 0);
		adaptive.light_release(scene.light.key);
		CHECK(pool.used.empty());
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaShadowAdaptive

namespace TestAreaShadowAdaptive {

TEST_CASE("[AreaShadowAdaptive] quadtree tiles come from the atlas and the grid lights' sharing counts them") {
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(256, 4)); // 16 tiles.
	AreaShadowAdaptiveRD::AtlasTiles tiles(&atlas);
	std::set<uint32_t> tree_tiles;
	{
		AreaShadowQuadtree tree;
		REQUIRE(tree.reset(&tiles));
		REQUIRE(tree.expand(AreaShadowQuadtree::root_key()));
		CHECK(atlas.get_external_tile_count() == 9);
		CHECK(atlas.get_free_tile_count() == 7);
		for (const AreaShadowQuadtree::Point &p : tree.get_points()) {
			tree_tiles.insert(p.tile);
		}
		CHECK(tree_tiles.size() == 9);
		// A grid light asking for 3 x 3 gets what is left (the corners), never a tile of the tree.
		for (int f = 0; f < 3; f++) {
			atlas.begin_frame();
			atlas.light_set(1, 3, 1.0f, 1);
			atlas.end_frame();
		}
		CHECK(atlas.light_get_grid(1) == 2);
		for (const AreaShadowAtlas::Map &m : atlas.light_get_maps(1)) {
			CHECK(tree_tiles.count(m.tile) == 0);
		}
		CHECK(atlas.get_free_tile_count() == 3);
		// Reconfiguring takes every tile back: the tree's later release must not free anything twice.
		uint64_t config = atlas.get_configuration();
		REQUIRE(atlas.configure(512, 4));
		CHECK(atlas.get_configuration() != config);
		CHECK(atlas.get_external_tile_count() == 0);
		CHECK(atlas.get_free_tile_count() == 16);
	}
	CHECK(atlas.get_free_tile_count() == 16); // The tree's destructor released nothing twice.
	{
		AreaShadowQuadtree tree;
		REQUIRE(tree.reset(&tiles));
		tree.clear();
		CHECK(atlas.get_external_tile_count() == 0);
		CHECK(atlas.get_free_tile_count() == 16);
	}
}

} // namespace TestAreaShadowAdaptive

namespace TestAreaShadowAdaptive {

TEST_CASE("[AreaShadowAdaptive] heuristic grid from the camera, with the project's max depth") {
	RenderSceneData data;
	data.fovy_degrees = 60.0f;
	data.viewport_height = 720;
	// Light 1 x 1 m, range 3, at the origin facing -Z: its range box.
	AABB box(Vector3(-3.5f, -3.5f, -3.0f), Vector3(7.0f, 7.0f, 3.0f));
	data.cam_transform.origin = Vector3(0.0f, 0.0f, -2.0f); // Inside the box.
	CHECK(AreaShadowAdaptiveRD::compute_heuristic_grid(box, Vector2(1, 1), 3.0f, data) == 9);
	data.cam_transform.origin = Vector3(0.0f, 0.0f, -2000.0f);
	CHECK(AreaShadowAdaptiveRD::compute_heuristic_grid(box, Vector2(1, 1), 3.0f, data) == 2);
	uint32_t prev = 9;
	for (float z = 1.0f; z < 3000.0f; z *= 2.0f) {
		data.cam_transform.origin = Vector3(0.0f, 0.0f, -3.0f - z);
		uint32_t g = AreaShadowAdaptiveRD::compute_heuristic_grid(box, Vector2(1, 1), 3.0f, data);
		CHECK((g == 2 || g == 3 || g == 5 || g == 9)); // Nested grids (the atlas keeps drawn maps).
		CHECK(g <= prev); // Farther: never more.
		prev = g;
	}
	// The project caps the depth: 2 levels = 5 x 5 at most.
	ProjectSettings *ps = ProjectSettings::get_singleton();
	AreaShadowAdaptiveRD::get_project_max_depth(); // Registers the setting.
	REQUIRE(ps->set_setting(AreaShadowAdaptiveRD::SETTING_MAX_DEPTH, 2));
	data.cam_transform.origin = Vector3(0.0f, 0.0f, -2.0f);
	CHECK(AreaShadowAdaptiveRD::compute_heuristic_grid(box, Vector2(1, 1), 3.0f, data) == 5);
	{
		SceneTest::ErrorCatcher errors;
		ps->set_setting(AreaShadowAdaptiveRD::SETTING_MAX_DEPTH, 7);
		CHECK(AreaShadowAdaptiveRD::get_project_max_depth() == AreaShadowAdaptiveRD::MAX_GPU_DEPTH);
		CHECK(errors.contains(AreaShadowAdaptiveRD::SETTING_MAX_DEPTH));
		ps->set_setting(AreaShadowAdaptiveRD::SETTING_REPROJECTION_DIVISOR, 0);
		CHECK(AreaShadowAdaptiveRD::get_project_reprojection_divisor() == AreaShadowAdaptiveRD::DEFAULT_REPROJECTION_DIVISOR);
		CHECK(errors.contains(AreaShadowAdaptiveRD::SETTING_REPROJECTION_DIVISOR));
	}
	ps->clear_override(AreaShadowAdaptiveRD::SETTING_MAX_DEPTH);
	ps->clear_override(AreaShadowAdaptiveRD::SETTING_REPROJECTION_DIVISOR);
	CHECK(AreaShadowAdaptiveRD::get_project_max_depth() == 3);
	CHECK(AreaShadowAdaptiveRD::get_project_reprojection_divisor() == 8);

	// The artist's knob: occluders assumed nearer the receivers (a larger fraction of the range) mean
	// narrower penumbrae and never more maps; at some distance strictly fewer.
	CHECK(AreaShadowAdaptiveRD::get_project_heuristic_occluder_fraction() == doctest::Approx(0.25f));
	bool fewer_somewhere = false;
	for (float z = 1.0f; z < 3000.0f; z *= 2.0f) {
		data.cam_transform.origin = Vector3(0.0f, 0.0f, -3.0f - z);
		uint32_t conservative = AreaShadowAdaptiveRD::compute_heuristic_grid(box, Vector2(1, 1), 3.0f, data);
		REQUIRE(ps->set_setting(AreaShadowAdaptiveRD::SETTING_HEURISTIC_OCCLUDER_FRACTION, 0.75));
		uint32_t tuned = AreaShadowAdaptiveRD::compute_heuristic_grid(box, Vector2(1, 1), 3.0f, data);
		ps->clear_override(AreaShadowAdaptiveRD::SETTING_HEURISTIC_OCCLUDER_FRACTION);
		CHECK(tuned <= conservative);
		fewer_somewhere = fewer_somewhere || tuned < conservative;
	}
	CHECK(fewer_somewhere);
	{
		SceneTest::ErrorCatcher errors;
		ps->set_setting(AreaShadowAdaptiveRD::SETTING_HEURISTIC_OCCLUDER_FRACTION, 1.5);
		CHECK(AreaShadowAdaptiveRD::get_project_heuristic_occluder_fraction() == doctest::Approx(0.25f));
		CHECK(errors.contains(AreaShadowAdaptiveRD::SETTING_HEURISTIC_OCCLUDER_FRACTION));
	}
	ps->clear_override(AreaShadowAdaptiveRD::SETTING_HEURISTIC_OCCLUDER_FRACTION);
}

TEST_CASE("[AreaShadowAdaptive] AreaLight3D shadow modes ADAPTIVE and HEURISTIC reach the server") {
	SceneTest::DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	CHECK(int(AreaLight3D::AREA_SHADOW_FIXED) == 0);
	CHECK(int(AreaLight3D::AREA_SHADOW_PCSS_BASELINE) == 1);
	CHECK(int(AreaLight3D::AREA_SHADOW_ADAPTIVE) == int(RS::LIGHT_AREA_SHADOW_ADAPTIVE));
	CHECK(int(AreaLight3D::AREA_SHADOW_HEURISTIC) == int(RS::LIGHT_AREA_SHADOW_HEURISTIC));
	RID rid = light->get_light();
	bool valid = false;
	light->set("area_shadow_mode", 2, &valid);
	CHECK(valid);
	CHECK(RSG::light_storage->light_area_get_shadow_mode(rid) == RS::LIGHT_AREA_SHADOW_ADAPTIVE);
	light->set("area_shadow_mode", 3, &valid);
	CHECK(valid);
	CHECK(RSG::light_storage->light_area_get_shadow_mode(rid) == RS::LIGHT_AREA_SHADOW_HEURISTIC);
	{
		SceneTest::ErrorCatcher errors;
		light->set("area_shadow_mode", 4);
		CHECK(errors.contains("area_shadow_mode"));
	}
	CHECK(light->get_area_shadow_mode() == AreaLight3D::AREA_SHADOW_HEURISTIC);
	delete light;
}

} // namespace TestAreaShadowAdaptive

namespace TestAreaShadowAdaptive {

TEST_CASE("[AreaShadowAdaptive] light_prepare lists each map once and redraws on a content change") {
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(256, 4));
	AreaShadowAdaptiveRD::AtlasTiles tiles(&atlas);
	AreaShadowAdaptiveRD adaptive; // The light-side calls need no GPU.
	std::vector<AreaShadowAtlas::DrawRequest> draws;
	std::vector<AreaShadowAtlas::Map> maps;
	REQUIRE(adaptive.light_prepare(5, &tiles, 100, 2, draws, maps));
	CHECK(draws.size() == 2); // Capped per frame.
	CHECK(maps.size() == 2); // Only drawn maps reach the shader.
	draws.clear();
	maps.clear();
	REQUIRE(adaptive.light_prepare(5, &tiles, 100, 512, draws, maps));
	CHECK(draws.size() == 2); // The other two corners.
	CHECK(maps.size() == 4);
	draws.clear();
	maps.clear();
	REQUIRE(adaptive.light_prepare(5, &tiles, 100, 512, draws, maps));
	CHECK(draws.empty()); // Static: nothing to redraw.
	CHECK(maps.size() == 4);
	draws.clear();
	maps.clear();
	REQUIRE(adaptive.light_prepare(5, &tiles, 101, 512, draws, maps));
	CHECK(draws.size() == 4); // Moved: all redrawn.
	std::set<uint32_t> draw_tiles;
	for (const AreaShadowAtlas::DrawRequest &d : draws) {
		CHECK(d.light == 5);
		draw_tiles.insert(d.tile);
	}
	CHECK(draw_tiles.size() == 4);
	CHECK(atlas.get_external_tile_count() == 4);
	adaptive.release_lights_except({});
	CHECK(atlas.get_external_tile_count() == 0);
	CHECK_FALSE(adaptive.has_light(5));
}

} // namespace TestAreaShadowAdaptive

TEST_CASE("[AreaShadowAdaptive] per-light reprojection grid: the light's screen rectangle within the view's budget") {
	const uint32_t W = 288, H = 162, DIVISOR = 8;
	const uint32_t budget = ((W + DIVISOR - 1) / DIVISOR) * ((H + DIVISOR - 1) / DIVISOR);
	const Projection clip_from_view = Projection::create_depth_correction(true) * Projection::create_perspective(60.0f, float(W) / float(H), 0.05f, 100.0f);
	AreaShadowAdaptiveRD::LightInput light;
	light.size = Vector2(1.0f, 1.0f);
	AreaShadowAdaptiveRD::GridData grid;

	// No box: the whole view at 1/divisor, as before.
	REQUIRE(AreaShadowAdaptiveRD::compute_light_grid(light, W, H, clip_from_view, DIVISOR, grid));
	CHECK(grid.step == DIVISOR);
	CHECK(grid.origin[0] == 0);
	CHECK(grid.origin[1] == 0);
	CHECK(grid.size[0] * grid.size[1] <= budget);

	// A small box far in front of the camera (light space = view space shifted 20 m ahead): a small
	// rectangle around the view centre, tested finer than 1/divisor but never finer than full resolution.
	light.box = AABB(Vector3(-0.5f, -0.5f, -0.5f), Vector3(1.0f, 1.0f, 0.5f));
	light.light_from_view = Transform3D(Basis(), Vector3(0.0f, 0.0f, 20.0f));
	REQUIRE(AreaShadowAdaptiveRD::compute_light_grid(light, W, H, clip_from_view, DIVISOR, grid));
	CHECK(grid.step >= 1);
	CHECK(grid.step < DIVISOR);
	CHECK(grid.size[0] * grid.size[1] <= budget);
	CHECK(grid.origin[0] > 0);
	CHECK(grid.origin[0] + grid.extent[0] < W);
	CHECK(grid.origin[1] > 0);
	CHECK(grid.origin[1] + grid.extent[1] < H);
	CHECK(grid.origin[0] < W / 2);
	CHECK(grid.origin[0] + grid.extent[0] > W / 2);

	// A box filling the view: the budget at the divisor's step (or coarser), never more cells.
	light.box = AABB(Vector3(-50.0f, -50.0f, -1.0f), Vector3(100.0f, 100.0f, 0.9f));
	light.light_from_view = Transform3D(Basis(), Vector3(0.0f, 0.0f, 2.0f));
	REQUIRE(AreaShadowAdaptiveRD::compute_light_grid(light, W, H, clip_from_view, DIVISOR, grid));
	CHECK(grid.step >= DIVISOR);
	CHECK(grid.size[0] * grid.size[1] <= budget);

	// Behind the camera or off to the side: not tested.
	light.box = AABB(Vector3(-0.5f, -0.5f, -0.5f), Vector3(1.0f, 1.0f, 0.5f));
	light.light_from_view = Transform3D(Basis(), Vector3(0.0f, 0.0f, -5.0f));
	CHECK_FALSE(AreaShadowAdaptiveRD::compute_light_grid(light, W, H, clip_from_view, DIVISOR, grid));
	light.light_from_view = Transform3D(Basis(), Vector3(-200.0f, 0.0f, 5.0f));
	CHECK_FALSE(AreaShadowAdaptiveRD::compute_light_grid(light, W, H, clip_from_view, DIVISOR, grid));
}
