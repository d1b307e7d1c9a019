/**************************************************************************/
/*  test_area_shadow_atlas.cpp                                            */
/**************************************************************************/
/* godot-area: the GPU-free area shadow atlas allocator: sample order,    */
/* scattered tiles, release and reuse, exhaustion, dirty tracking and the */
/* fair sharing between lights (thesis sections 6.1 and 6.5).             */

#include "servers/rendering/renderer_rd/area_lights/area_shadow_atlas.h"

#include "core/error/error_macros.h"

#include <doctest/doctest.h>

#include <set>

namespace TestAreaShadowAtlas {

struct CountWarnings {
	int warnings = 0;
	ErrorHandlerList handler;
	CountWarnings() {
		handler.callback = [this](ErrorHandlerType p_type, const String &) {
			if (p_type == ERR_HANDLER_WARNING) {
				warnings++;
			}
		};
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~CountWarnings() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
};

static std::set<uint32_t> tiles_of(const AreaShadowAtlas &p_atlas, uint64_t p_light) {
	std::set<uint32_t> out;
	for (const AreaShadowAtlas::Map &m : p_atlas.light_get_maps(p_light)) {
		out.insert(m.tile);
	}
	return out;
}

static void frame(AreaShadowAtlas &p_atlas, const std::vector<std::pair<uint64_t, float>> &p_lights, uint32_t p_grid = 9, uint64_t p_hash = 1) {
	p_atlas.begin_frame();
	for (const auto &l : p_lights) {
		p_atlas.light_set(l.first, p_grid, l.second, p_hash);
	}
	p_atlas.end_frame();
}

TEST_CASE("[AreaShadowAtlas] samples follow the Schwarzler subdivision order") {
	std::vector<Vector2> s2 = AreaShadowAtlas::get_grid_samples(2);
	REQUIRE(s2.size() == 4);
	std::vector<Vector2> s9 = AreaShadowAtlas::get_grid_samples(9);
	REQUIRE(s9.size() == 81);
	// The corners come first.
	for (int i = 0; i < 4; i++) {
		CHECK((s9[i].x == 0.0f || s9[i].x == 1.0f));
		CHECK((s9[i].y == 0.0f || s9[i].y == 1.0f));
	}
	// Then the edge midpoints and the centre (level 1): 5 points, then level 2 (16 more).
	std::vector<Vector2> s3 = AreaShadowAtlas::get_grid_samples(3);
	REQUIRE(s3.size() == 9);
	for (int i = 4; i < 9; i++) {
		CHECK(AreaShadowAtlas::get_coordinate_level(std::max(s3[i].x, s3[i].y) == 0.5f ? 0.5f : std::min(s3[i].x, s3[i].y)) <= 1);
		CHECK((s3[i].x == 0.5f || s3[i].y == 0.5f));
	}
	// Nested: 2 -> 3 -> 5 -> 9 are prefixes of each other.
	std::vector<Vector2> s5 = AreaShadowAtlas::get_grid_samples(5);
	for (size_t i = 0; i < s3.size(); i++) {
		CHECK(s5[i] == s3[i]);
		CHECK(s9[i] == s3[i]);
	}
	for (size_t i = 0; i < s5.size(); i++) {
		CHECK(s9[i] == s5[i]);
	}
	CHECK(AreaShadowAtlas::get_subdivision_samples(1).size() == 9);
	CHECK(AreaShadowAtlas::get_grid_samples(1).size() == 1);
	CHECK(AreaShadowAtlas::get_grid_samples(4).size() == 16);
}

TEST_CASE("[AreaShadowAtlas] allocate, free and reuse scattered tiles") {
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(512, 8)); // 64 tiles of 64 px.
	CHECK(atlas.get_tile_size() == 64);
	{
		CountWarnings silence;
		CHECK_FALSE(atlas.configure(512, 0));
		CHECK_FALSE(atlas.configure(8, 1));
	}
	CHECK(atlas.get_subdivision() == 8);

	frame(atlas, { { 1, 1.0f } }, 3);
	CHECK(atlas.light_get_grid(1) == 3);
	CHECK(atlas.light_get_tile_count(1) == 9);
	CHECK(atlas.get_free_tile_count() == 55);
	frame(atlas, { { 1, 1.0f }, { 2, 1.0f } }, 3);
	std::set<uint32_t> a = tiles_of(atlas, 1), b = tiles_of(atlas, 2);
	CHECK(a.size() == 9);
	CHECK(b.size() == 9);
	for (uint32_t t : a) {
		CHECK(b.count(t) == 0);
	}
	// Light 1 is culled: its tiles come back; a light with a larger grid takes them and more: scattered.
	frame(atlas, { { 2, 1.0f }, { 3, 1.0f } }, 5);
	CHECK_FALSE(atlas.has_light(1));
	std::set<uint32_t> c = tiles_of(atlas, 3);
	CHECK(c.size() == 25);
	int reused = 0;
	for (uint32_t t : a) {
		reused += int(c.count(t));
	}
	CHECK(reused == 9); // The freed tiles are reused...
	bool contiguous = (*c.rbegin() - *c.begin() + 1) == c.size();
	CHECK_FALSE(contiguous); // ...and the light's tiles are not one contiguous run.
	// GPU tile rectangles from indices.
	AreaShadowAtlas::TileRect r = AreaShadowAtlas::get_tile_rect(10, 512, 8);
	CHECK(r.x == 128);
	CHECK(r.y == 64);
	CHECK(r.size == 64);
	atlas.light_release(3);
	atlas.light_release(2);
	CHECK(atlas.get_free_tile_count() == 64);
}

TEST_CASE("[AreaShadowAtlas] exhaustion warns once and degrades gracefully") {
	CountWarnings w;
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(256, 3)); // 9 tiles.
	std::vector<std::pair<uint64_t, float>> ls = { { 1, 3.0f }, { 2, 2.0f }, { 3, 1.0f } };
	for (int f = 0; f < 4; f++) {
		frame(atlas, ls, 3);
	}
	CHECK(atlas.is_exhausted());
	CHECK(atlas.get_exhaustion_warning_count() == 1);
	CHECK(w.warnings == 1);
	CHECK(atlas.light_get_grid(1) == 2);
	CHECK(atlas.light_get_grid(2) == 2);
	CHECK(atlas.light_get_grid(3) == 1); // Fallback: one centre map.
	CHECK(atlas.get_free_tile_count() == 0);
	// Every map handed out was drawn (valid), never a garbage tile.
	for (uint64_t id = 1; id <= 3; id++) {
		for (const AreaShadowAtlas::Map &m : atlas.light_get_maps(id)) {
			CHECK(m.valid);
			CHECK(m.tile < 9);
		}
	}
}

TEST_CASE("[AreaShadowAtlas] independent atlases") {
	AreaShadowAtlas a, b;
	REQUIRE(a.configure(512, 4));
	REQUIRE(b.configure(1024, 8));
	frame(a, { { 7, 1.0f } }, 3);
	CHECK(a.light_get_tile_count(7) == 9);
	CHECK(b.light_get_tile_count(7) == 0);
	CHECK(b.get_free_tile_count() == 64);
	frame(b, { { 7, 1.0f } }, 5);
	CHECK(b.light_get_tile_count(7) == 25);
	CHECK(a.light_get_tile_count(7) == 9);
}

TEST_CASE("[AreaShadowAtlas] dirty tracking: a static scene redraws nothing after the first frame") {
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(1024, 16));
	frame(atlas, { { 1, 1.0f }, { 2, 0.5f } }, 3, 42);
	CHECK(atlas.get_draws().size() == 18);
	for (int f = 0; f < 5; f++) {
		frame(atlas, { { 1, 1.0f }, { 2, 0.5f } }, 3, 42);
		CHECK(atlas.get_draws().size() == 0);
	}
	CHECK(atlas.get_total_draws() == 18);
	// Light 2 (or something in its range) moves: only its maps redraw.
	atlas.begin_frame();
	atlas.light_set(1, 3, 1.0f, 42);
	atlas.light_set(2, 3, 0.5f, 43);
	atlas.end_frame();
	CHECK(atlas.get_draws().size() == 9);
	for (const AreaShadowAtlas::DrawRequest &d : atlas.get_draws()) {
		CHECK(d.light == 2);
	}
	// Per-frame cap: the rest waits, and maps never drawn are not valid meanwhile.
	atlas.set_max_draws_per_frame(5);
	frame(atlas, { { 1, 1.0f }, { 2, 0.5f }, { 3, 0.5f } }, 3, 44);
	CHECK(atlas.get_draws().size() == 5);
	int invalid = 0;
	for (const AreaShadowAtlas::Map &m : atlas.light_get_maps(3)) {
		invalid += m.valid ? 0 : 1;
	}
	CHECK(invalid == 4); // Light 3's maps (never drawn) come first: 5 of its 9 drawn.
	uint64_t before = atlas.get_total_draws();
	for (int f = 0; f < 10; f++) {
		frame(atlas, { { 1, 1.0f }, { 2, 0.5f }, { 3, 0.5f } }, 3, 44);
	}
	CHECK(atlas.get_total_draws() - before == 22); // 4 + 9 + 9 remaining, then nothing.
}

TEST_CASE("[AreaShadowAtlas] fair sharing follows importance with hysteresis and bounded evictions") {
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(1024, 8)); // 64 tiles.
	atlas.set_max_evictions_per_frame(16);
	frame(atlas, { { 1, 8.0f }, { 2, 2.0f }, { 3, 1.0f }, { 4, 0.01f } }, 9);
	uint32_t t1 = atlas.light_get_tile_count(1), t2 = atlas.light_get_tile_count(2), t3 = atlas.light_get_tile_count(3), t4 = atlas.light_get_tile_count(4);
	MESSAGE("tiles: ", t1, " ", t2, " ", t3, " ", t4);
	CHECK(t1 >= t2);
	CHECK(t2 >= t3);
	CHECK(t3 >= t4);
	CHECK(t1 > t4);
	CHECK(t4 >= 4); // Nobody below the four corners.
	CHECK(t1 + t2 + t3 + t4 <= 64);

	// Small importance fluctuations do not move tiles (no ping-pong).
	uint64_t draws_before = atlas.get_total_draws();
	for (int f = 0; f < 10; f++) {
		float wobble = (f % 2) ? 1.1f : 0.9f;
		frame(atlas, { { 1, 8.0f * wobble }, { 2, 2.0f / wobble }, { 3, 1.0f * wobble }, { 4, 0.01f } }, 9);
		CHECK(atlas.get_frame_evictions() == 0);
	}
	CHECK(atlas.get_total_draws() == draws_before);
	CHECK(atlas.light_get_tile_count(1) == t1);

	// The importance order flips: tiles move, a bounded number per frame, until the shares follow.
	uint32_t max_evictions = 0;
	for (int f = 0; f < 20; f++) {
		frame(atlas, { { 1, 0.01f }, { 2, 2.0f }, { 3, 1.0f }, { 4, 8.0f } }, 9);
		max_evictions = std::max(max_evictions, atlas.get_frame_evictions());
		for (uint64_t id = 1; id <= 4; id++) {
			CHECK(atlas.light_get_tile_count(id) >= 4);
		}
	}
	CHECK(max_evictions <= 16);
	CHECK(max_evictions > 0);
	CHECK(atlas.light_get_tile_count(4) > atlas.light_get_tile_count(1));

	// A newcomer always gets its corners even if the atlas is full.
	frame(atlas, { { 1, 0.01f }, { 2, 2.0f }, { 3, 1.0f }, { 4, 8.0f }, { 5, 0.001f } }, 9);
	CHECK(atlas.light_get_tile_count(5) >= 4);
}

TEST_CASE("[AreaShadowAtlas] a light gets the grid it asks for when the tiles are free") {
	AreaShadowAtlas atlas;
	REQUIRE(atlas.configure(1024, 16)); // 256 tiles.
	for (uint32_t grid : { 5u, 6u, 7u, 9u, 6u, 3u }) {
		for (int f = 0; f < 4; f++) {
			frame(atlas, { { 1, 1.0f } }, grid);
		}
		CHECK_MESSAGE(atlas.light_get_maps(1).size() == grid * grid, "area_shadow_grid ", grid);
	}
}

TEST_CASE("[AreaShadowAtlas] importance grows with screen coverage and light size") {
	Projection proj = Projection::create_perspective(60.0f, 1.0f, 0.1f, 100.0f);
	Transform3D cam; // At the origin looking down -Z.
	Projection clip_from_world = proj * Projection::from_transform(cam.affine_inverse());
	AABB near_box(Vector3(-1, -1, -6), Vector3(2, 2, 2));
	AABB far_box(Vector3(-1, -1, -40), Vector3(2, 2, 2));
	AABB behind(Vector3(-1, -1, 5), Vector3(2, 2, 2));
	float i_near = AreaShadowAtlas::compute_importance(near_box, clip_from_world, Vector2(1, 1));
	float i_far = AreaShadowAtlas::compute_importance(far_box, clip_from_world, Vector2(1, 1));
	float i_big = AreaShadowAtlas::compute_importance(near_box, clip_from_world, Vector2(2, 2));
	CHECK(i_near > i_far);
	CHECK(i_far > 0.0f);
	CHECK(i_big == doctest::Approx(i_near * 4.0f));
	CHECK(AreaShadowAtlas::compute_importance(behind, clip_from_world, Vector2(1, 1)) == 0.0f);
}

} // namespace TestAreaShadowAtlas
