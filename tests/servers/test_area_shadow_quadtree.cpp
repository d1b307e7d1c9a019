/**************************************************************************/
/*  test_area_shadow_quadtree.cpp                                         */
/**************************************************************************/
/* godot-area: the adaptive subdivision quadtree of area-light shadows    */
/* (thesis 6.3, Algorithm 1): expand/prune/idle, shared reference-counted */
/* points, tile accounting, over-frames convergence with a fake banding   */
/* oracle behind the no-stall readback ring, and the 6.5 heuristic.       */

#include "servers/rendering/renderer_rd/area_lights/area_shadow_quadtree.h"
#include "servers/rendering/renderer_rd/storage_rd/area_shadow_readback_ring.h"

#include "core/error/error_macros.h"

#include <doctest/doctest.h>

#include <cmath>
#include <deque>
#include <random>
#include <set>

namespace TestAreaShadowQuadtree {

struct TilePool : public AreaShadowQuadtree::TileSource {
	std::set<uint32_t> free_tiles;
	std::set<uint32_t> used;
	uint32_t acquires = 0;
	uint32_t releases = 0;
	uint32_t bad_releases = 0;
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
		acquires++;
		return true;
	}
	void release_tile(uint32_t p_tile) override {
		if (used.erase(p_tile) == 0) {
			bad_releases++;
			return;
		}
		free_tiles.insert(p_tile);
		releases++;
	}
};

static uint64_t key(uint32_t p_d, uint32_t p_i, uint32_t p_j) {
	return AreaShadowQuadtree::make_node_key(p_d, p_i, p_j);
}

// Every point owns exactly one tile, tiles are unique and the pool agrees.
static void check_accounting(const AreaShadowQuadtree &p_tree, const TilePool &p_pool) {
	std::set<uint32_t> tiles;
	for (const AreaShadowQuadtree::Point &p : p_tree.get_points()) {
		CHECK(p.refs > 0);
		CHECK(p_pool.used.count(p.tile) == 1);
		tiles.insert(p.tile);
	}
	CHECK(tiles.size() == p_tree.get_point_count());
	CHECK(p_pool.used.size() == p_tree.get_point_count());
	CHECK(p_pool.bad_releases == 0);
}

static AreaShadowQuadtree::Result answer(const AreaShadowQuadtree::Query &p_q, bool p_banding, bool p_penumbra) {
	AreaShadowQuadtree::Result r{ p_q.node, p_q.version, p_q.parent_test, p_banding };
	r.penumbra = p_penumbra;
	return r;
}

// The same answer to every query.
static std::vector<AreaShadowQuadtree::Result> answer_all(const std::vector<AreaShadowQuadtree::Query> &p_queries, bool p_banding, bool p_penumbra) {
	std::vector<AreaShadowQuadtree::Result> out;
	for (const AreaShadowQuadtree::Query &q : p_queries) {
		out.push_back(answer(q, p_banding, p_penumbra));
	}
	return out;
}

static void draw_all(AreaShadowQuadtree &p_tree) {
	p_tree.collect_draws();
}

TEST_CASE("[AreaShadowQuadtree] expand and prune share points and keep tiles") {
	TilePool pool(64);
	AreaShadowQuadtree tree;
	REQUIRE(tree.reset(&pool));
	CHECK(tree.get_point_count() == 4);
	CHECK(tree.get_node_count() == 1);
	CHECK(tree.node_is_leaf(AreaShadowQuadtree::root_key()));
	CHECK(tree.get_point_refs(Vector2(0, 0)) == 1);

	REQUIRE(tree.expand(AreaShadowQuadtree::root_key()));
	CHECK(tree.get_point_count() == 9);
	CHECK(tree.get_node_count() == 5);
	CHECK(tree.get_leaf_count() == 4);
	CHECK(tree.get_point_refs(Vector2(0.5f, 0.5f)) == 4); // The centre: four children.
	CHECK(tree.get_point_refs(Vector2(0.5f, 0.0f)) == 2); // An edge midpoint: two children.
	CHECK(tree.get_point_refs(Vector2(1.0f, 1.0f)) == 2); // A corner: the root and one child.
	CHECK_FALSE(tree.expand(AreaShadowQuadtree::root_key())); // Not a leaf any more.
	check_accounting(tree, pool);

	// Two neighbouring children share the midpoint of their common edge: created once.
	uint32_t before = pool.acquires;
	REQUIRE(tree.expand(key(1, 0, 0)));
	CHECK(pool.acquires - before == 5);
	CHECK(tree.get_point_refs(Vector2(0.5f, 0.25f)) == 2);
	before = pool.acquires;
	REQUIRE(tree.expand(key(1, 1, 0)));
	CHECK(pool.acquires - before == 4); // (0.5, 0.25) already exists.
	CHECK(tree.get_point_refs(Vector2(0.5f, 0.25f)) == 4);
	CHECK(tree.get_point_count() == 9 + 5 + 4);
	check_accounting(tree, pool);

	// Pruning the first keeps the shared point (the neighbour still uses it); the last user frees it.
	REQUIRE(tree.prune(key(1, 0, 0)));
	CHECK(tree.has_point(Vector2(0.5f, 0.25f)));
	CHECK(tree.get_point_refs(Vector2(0.5f, 0.25f)) == 2);
	CHECK_FALSE(tree.has_point(Vector2(0.25f, 0.25f)));
	REQUIRE(tree.prune(key(1, 1, 0)));
	CHECK_FALSE(tree.has_point(Vector2(0.5f, 0.25f)));
	CHECK(tree.get_point_count() == 9);
	check_accounting(tree, pool);

	REQUIRE(tree.prune(AreaShadowQuadtree::root_key()));
	CHECK(tree.get_point_count() == 4);
	CHECK(pool.used.size() == 4);
	CHECK(pool.acquires - pool.releases == 4);
	tree.clear();
	CHECK(pool.used.empty());
	CHECK(pool.free_tiles.size() == 64);
}

TEST_CASE("[AreaShadowQuadtree] tile accounting never leaks under random expand and prune") {
	TilePool pool(40);
	{
		AreaShadowQuadtree tree;
		tree.set_max_depth(4);
		REQUIRE(tree.reset(&pool));
		std::mt19937 rng(1234);
		uint32_t failed_expansions = 0;
		for (int step = 0; step < 3000; step++) {
			std::vector<uint64_t> leaves, parents;
			for (uint32_t d = 0; d <= 4; d++) {
				for (uint32_t j = 0; j < (1u << d); j++) {
					for (uint32_t i = 0; i < (1u << d); i++) {
						uint64_t k = key(d, i, j);
						if (!tree.has_node(k)) {
							continue;
						}
						(tree.node_is_leaf(k) ? leaves : parents).push_back(k);
					}
				}
			}
			if (!parents.empty() && rng() % 3 == 0) {
				tree.prune(parents[rng() % parents.size()]);
			} else {
				uint32_t points = tree.get_point_count();
				uint32_t nodes = tree.get_node_count();
				if (!tree.expand(leaves[rng() % leaves.size()])) {
					failed_expansions++;
					CHECK(tree.get_point_count() == points); // All or nothing.
					CHECK(tree.get_node_count() == nodes);
				}
			}
			if (step % 100 == 0) {
				check_accounting(tree, pool);
			}
		}
		check_accounting(tree, pool);
		CHECK(failed_expansions > 0); // The pool (40) ran dry at some point: the failure path ran.
		CHECK(tree.get_depth() <= 4);
		tree.set_max_depth(1);
		CHECK(tree.get_depth() <= 1);
		check_accounting(tree, pool);
	} // The destructor gives everything back.
	CHECK(pool.used.empty());
	CHECK(pool.free_tiles.size() == 40);
	CHECK(pool.bad_releases == 0);
}

TEST_CASE("[AreaShadowQuadtree] a light without four free tiles gets no tree") {
	TilePool pool(3);
	AreaShadowQuadtree tree;
	CHECK_FALSE(tree.reset(&pool));
	CHECK(tree.is_empty());
	CHECK(pool.used.empty());
	CHECK(tree.build_queries().empty());
}

TEST_CASE("[AreaShadowQuadtree] idle leaves, queries and stale answers") {
	TilePool pool(81);
	AreaShadowQuadtree tree;
	REQUIRE(tree.reset(&pool));
	tree.begin_frame();
	// Undrawn corners: nothing to test yet.
	CHECK(tree.build_queries().empty());
	draw_all(tree);
	std::vector<AreaShadowQuadtree::Query> q = tree.build_queries();
	REQUIRE(q.size() == 1);
	CHECK_FALSE(q[0].parent_test);
	CHECK(q[0].uv_min == Vector2(0, 0));
	CHECK(q[0].uv_max == Vector2(1, 1));

	AreaShadowQuadtree::Result banding{ q[0].node, q[0].version, false, true };
	tree.begin_frame();
	CHECK(tree.apply_results({ banding }) == 1);
	CHECK(tree.get_leaf_count() == 4);
	CHECK_FALSE(tree.node_is_idle(key(1, 0, 0))); // Just created: not idle.
	// The same (now stale) answer again changes nothing.
	CHECK(tree.apply_results({ banding }) == 0);
	CHECK(tree.get_leaf_count() == 4);

	draw_all(tree);
	q = tree.build_queries();
	CHECK(q.size() == 4); // Four leaves; the root is no prune candidate while its children are not idle.
	tree.begin_frame();
	CHECK(tree.apply_results(answer_all(q, false, false)) == 0);
	CHECK(tree.node_is_idle(key(1, 0, 0)));
	q = tree.build_queries();
	REQUIRE(q.size() == 5); // Four leaves and the root's prune test.
	const AreaShadowQuadtree::Query *parent = nullptr;
	for (const AreaShadowQuadtree::Query &x : q) {
		if (x.parent_test) {
			parent = &x;
		}
	}
	REQUIRE(parent);
	CHECK(parent->node == AreaShadowQuadtree::root_key());
	// Parent still banding: kept.
	tree.begin_frame();
	CHECK(tree.apply_results({ { parent->node, parent->version, true, true } }) == 0);
	CHECK(tree.get_leaf_count() == 4);
	// Parent without banding: pruned; it is a leaf again but not idle (recently pruned).
	CHECK(tree.apply_results({ { parent->node, parent->version, true, false } }) == 1);
	CHECK(tree.get_leaf_count() == 1);
	CHECK(tree.get_point_count() == 4);
	CHECK_FALSE(tree.node_is_idle(AreaShadowQuadtree::root_key()));
	check_accounting(tree, pool);
	// A non-idle child blocks the prune test.
	tree.expand(AreaShadowQuadtree::root_key());
	draw_all(tree);
	for (const AreaShadowQuadtree::Query &x : tree.build_queries()) {
		CHECK_FALSE(x.parent_test);
	}
}

TEST_CASE("[AreaShadowQuadtree] same-depth rule: a banding quad refines the quads of its depth that see a penumbra") {
	TilePool pool(81);
	AreaShadowQuadtree tree;
	REQUIRE(tree.reset(&pool));
	REQUIRE(tree.expand(AreaShadowQuadtree::root_key()));
	draw_all(tree);
	std::vector<AreaShadowQuadtree::Query> q = tree.build_queries();
	REQUIRE(q.size() == 4);
	auto find = [](const std::vector<AreaShadowQuadtree::Query> &p_list, uint64_t p_node, bool p_parent) -> const AreaShadowQuadtree::Query * {
		for (const AreaShadowQuadtree::Query &x : p_list) {
			if (x.node == p_node && x.parent_test == p_parent) {
				return &x;
			}
		}
		return nullptr;
	};
	// (0,0) bands; (1,0) and (0,1) see a penumbra without a visible step; (1,1) sees none (lit or umbra).
	std::vector<AreaShadowQuadtree::Result> r = {
		answer(*find(q, key(1, 0, 0), false), true, true),
		answer(*find(q, key(1, 1, 0), false), false, true),
		answer(*find(q, key(1, 0, 1), false), false, true),
		answer(*find(q, key(1, 1, 1), false), false, false),
	};
	tree.begin_frame();
	CHECK(tree.apply_results(r) == 3);
	CHECK_FALSE(tree.node_is_leaf(key(1, 0, 0)));
	CHECK_FALSE(tree.node_is_leaf(key(1, 1, 0)));
	CHECK_FALSE(tree.node_is_leaf(key(1, 0, 1)));
	CHECK(tree.node_is_leaf(key(1, 1, 1)));
	CHECK(tree.node_is_idle(key(1, 1, 1)));
	check_accounting(tree, pool);
	// Without any banding quad, a penumbra alone expands nothing.
	{
		TilePool pool2(81);
		AreaShadowQuadtree t2;
		REQUIRE(t2.reset(&pool2));
		REQUIRE(t2.expand(AreaShadowQuadtree::root_key()));
		draw_all(t2);
		std::vector<AreaShadowQuadtree::Result> quiet = answer_all(t2.build_queries(), false, true);
		t2.begin_frame();
		CHECK(t2.apply_results(quiet) == 0);
		CHECK(t2.get_leaf_count() == 4);
	}
	// The depth-2 leaves come back clean: the three depth-1 parents are tested for pruning. One still bands:
	// none of them is pruned (their steps are as wide). Then none bands: all three are pruned.
	draw_all(tree);
	q = tree.build_queries();
	std::vector<AreaShadowQuadtree::Result> clean = answer_all(q, false, true);
	tree.begin_frame();
	CHECK(tree.apply_results(clean) == 0);
	q = tree.build_queries();
	const AreaShadowQuadtree::Query *p00 = find(q, key(1, 0, 0), true);
	const AreaShadowQuadtree::Query *p10 = find(q, key(1, 1, 0), true);
	const AreaShadowQuadtree::Query *p01 = find(q, key(1, 0, 1), true);
	REQUIRE(p00);
	REQUIRE(p10);
	REQUIRE(p01);
	std::vector<AreaShadowQuadtree::Result> one_bands = { answer(*p00, true, true), answer(*p10, false, true), answer(*p01, false, true) };
	tree.begin_frame();
	CHECK(tree.apply_results(one_bands) == 0);
	CHECK(tree.get_point_count() == 9 + 5 + 5 + 5 - 2); // (1,0,0)'s children share edges with the other two.
	std::vector<AreaShadowQuadtree::Result> none_bands = { answer(*p00, false, true), answer(*p10, false, true), answer(*p01, false, true) };
	tree.begin_frame();
	CHECK(tree.apply_results(none_bands) == 3);
	CHECK(tree.get_point_count() == 9);
	check_accounting(tree, pool);
}

TEST_CASE("[AreaShadowQuadtree] without tiles to grow, leaves are tested until idle so their parents can be pruned") {
	TilePool pool(81);
	AreaShadowQuadtree tree;
	REQUIRE(tree.reset(&pool));
	REQUIRE(tree.expand(AreaShadowQuadtree::root_key()));
	draw_all(tree);
	// Fresh leaves are not idle: tested even without expansion tests; no parent test yet.
	std::vector<AreaShadowQuadtree::Query> q = tree.build_queries(false);
	CHECK(q.size() == 4);
	for (const AreaShadowQuadtree::Query &x : q) {
		CHECK_FALSE(x.parent_test);
	}
	tree.begin_frame();
	CHECK(tree.apply_results(answer_all(q, false, false)) == 0);
	// Idle now: only the root's prune test remains, and a clean answer prunes it.
	q = tree.build_queries(false);
	REQUIRE(q.size() == 1);
	CHECK(q[0].parent_test);
	CHECK(q[0].node == AreaShadowQuadtree::root_key());
	tree.begin_frame();
	CHECK(tree.apply_results({ { q[0].node, q[0].version, true, false } }) == 1);
	CHECK(tree.get_point_count() == 4);
	check_accounting(tree, pool);
}

TEST_CASE("[AreaShadowQuadtree] point weights sum to one") {
	TilePool pool(81);
	AreaShadowQuadtree tree;
	REQUIRE(tree.reset(&pool));
	tree.expand(AreaShadowQuadtree::root_key());
	tree.expand(key(1, 1, 1));
	tree.expand(key(2, 2, 2));
	std::vector<float> w = tree.get_point_weights();
	REQUIRE(w.size() == tree.get_point_count());
	double sum = 0.0;
	for (float x : w) {
		CHECK(x >= 0.0f);
		sum += x;
	}
	CHECK(sum == doctest::Approx(1.0).epsilon(1e-5));
}

// The root quad, split once (nine points).
static void start_split(AreaShadowQuadtree &r_tree, TilePool &r_pool) {
	REQUIRE(r_tree.reset(&r_pool));
	REQUIRE(r_tree.expand(AreaShadowQuadtree::root_key()));
}

TEST_CASE("[AreaShadowQuadtree] point cells: the quarters of the point's leaves, their areas the weights, none across a T-junction") {
	TilePool pool(81);
	AreaShadowQuadtree tree;
	start_split(tree, pool);
	tree.expand(key(1, 1, 1)); // The (+u, +v) quarter at depth 2: T-junctions on its edges at u = 0.75, v = 0.75.
	tree.expand(key(2, 2, 2));
	std::vector<AreaShadowQuadtree::Point> points = tree.get_points();
	std::vector<uint32_t> cells = tree.get_point_cells();
	REQUIRE(cells.size() == points.size());
	double sum = 0.0;
	for (size_t i = 0; i < cells.size(); i++) {
		CAPTURE(points[i].uv);
		CHECK(cells[i] != 0u); // Every point is a corner of some leaf.
		sum += AreaShadowQuadtree::get_cell_weight(cells[i]);
		float e[4];
		AreaShadowQuadtree::get_cell_extent(cells[i], e);
		// The box stays on the light.
		CHECK(points[i].uv.x - e[0] >= -1e-6f);
		CHECK(points[i].uv.x + e[1] <= 1.0f + 1e-6f);
		CHECK(points[i].uv.y - e[2] >= -1e-6f);
		CHECK(points[i].uv.y + e[3] <= 1.0f + 1e-6f);
		if (points[i].uv == Vector2(0, 0)) {
			// A corner of the depth-1 leaf (0, 0): its quarter, a square of 1/4 towards +u, +v.
			CHECK(cells[i] == (2u << (3 * 3)));
			CHECK(AreaShadowQuadtree::get_cell_weight(cells[i]) == doctest::Approx(1.0 / 16.0));
			CHECK(e[0] == 0.0f);
			CHECK(e[1] == doctest::Approx(0.25f));
		}
		if (points[i].uv == Vector2(1.0f, 0.75f)) {
			// On the light's edge between the depth-2 leaves (3, 2) and (3, 3): towards -u only.
			CHECK(e[1] == 0.0f);
			CHECK(e[0] == doctest::Approx(0.125f));
			CHECK(e[2] == doctest::Approx(0.125f));
			CHECK(e[3] == doctest::Approx(0.125f));
			CHECK(AreaShadowQuadtree::get_cell_weight(cells[i]) == doctest::Approx(2.0 / 64.0));
		}
		if (points[i].uv == Vector2(0.5f, 0.75f)) {
			// A T-junction: the midpoint of the coarse leaf (1, 0, 1)'s edge, a corner of the finer leaves on
			// the +u side only, so nothing of the coarse leaf (the box does not reach towards -u).
			CHECK(e[0] == 0.0f);
			CHECK(e[1] == doctest::Approx(0.125f));
			CHECK(AreaShadowQuadtree::get_cell_weight(cells[i]) == doctest::Approx(1.0 / 64.0 + 1.0 / 256.0));
		}
	}
	CHECK(sum == doctest::Approx(1.0).epsilon(1e-5));
}

TEST_CASE("[AreaShadowQuadtree] shrink evicts the finest quads first, down to a point budget") {
	TilePool pool(81);
	AreaShadowQuadtree tree;
	start_split(tree, pool);
	for (uint32_t c = 0; c < 4; c++) {
		tree.expand(key(1, c & 1u, c >> 1u));
	}
	tree.expand(key(2, 0, 0));
	REQUIRE(tree.get_depth() == 3);
	const uint32_t before = tree.get_point_count();
	CHECK(tree.shrink(before) == 0); // Within budget: nothing.
	CHECK(tree.shrink(before - 1) == 1); // The one depth-3 quad goes first.
	CHECK(tree.get_depth() == 2);
	CHECK(tree.get_point_count() < before);
	check_accounting(tree, pool);
	CHECK(tree.shrink(12) > 0);
	CHECK(tree.get_point_count() <= 12);
	CHECK(tree.get_depth() <= 2);
	check_accounting(tree, pool);
	double sum = 0.0;
	for (float w : tree.get_point_weights()) {
		sum += w;
	}
	CHECK(sum == doctest::Approx(1.0).epsilon(1e-5));
	tree.shrink(0); // Never below the root quad.
	CHECK(tree.get_point_count() == 4);
	CHECK(tree.get_node_count() == 1);
	check_accounting(tree, pool);
}

// A fake GPU: answers each query with a banding oracle; a frame's answers complete p_latency frames later.
struct Simulation {
	TilePool pool;
	AreaShadowQuadtree tree;
	AreaShadowReadbackRing ring;
	std::vector<std::vector<AreaShadowQuadtree::Result>> slot_results;
	uint64_t frame = 0;
	uint32_t latency = 2;
	uint32_t level = 2; // The oracle asks for this depth in the penumbra strip (camera distance).
	uint32_t changes_last = 0;

	explicit Simulation(uint32_t p_tiles) :
			pool(p_tiles) {
		ring.configure(3);
		slot_results.resize(3);
		ring.set_frame_complete_predicate([this](uint64_t p_frame) { return p_frame + latency <= frame; });
		tree.reset(&pool);
	}
	// Banding where a quad overlaps the strip 0.3 <= u <= 0.4 (a penumbra) until it is `level` deep.
	bool oracle(const AreaShadowQuadtree::Query &p_q) const {
		bool strip = p_q.uv_max.x >= 0.3f && p_q.uv_min.x <= 0.4f;
		return strip ? p_q.depth < level : false;
	}
	void step() {
		frame++;
		ring.begin_frame(frame);
		tree.begin_frame();
		int done = ring.take_newest_completed();
		changes_last = done >= 0 ? tree.apply_results(slot_results[done]) : 0;
		tree.collect_draws();
		int slot = ring.acquire_write_slot();
		if (slot >= 0) {
			slot_results[slot].clear();
			for (const AreaShadowQuadtree::Query &q : tree.build_queries()) {
				slot_results[slot].push_back({ q.node, q.version, q.parent_test, oracle(q) });
			}
		}
	}
	// Frames until the tree stops changing (then checked to stay unchanged for p_hold frames).
	int converge(int p_max_frames, int p_hold) {
		uint64_t last_change = tree.get_change_count();
		int stable = 0;
		for (int f = 0; f < p_max_frames; f++) {
			step();
			if (tree.get_change_count() != last_change) {
				last_change = tree.get_change_count();
				stable = 0;
			} else if (++stable >= p_hold) {
				return f + 1 - p_hold;
			}
		}
		return -1;
	}
};

TEST_CASE("[AreaShadowQuadtree] over-frames subdivision converges and does not oscillate") {
	Simulation sim(256);
	sim.tree.set_max_depth(4);
	int frames = sim.converge(60, 10);
	REQUIRE(frames >= 0);
	CHECK(frames <= 40);
	uint32_t far_points = sim.tree.get_point_count();
	uint64_t changes = sim.tree.get_change_count();
	CHECK(sim.tree.get_depth() == 2);
	CHECK(far_points > 4);
	for (int f = 0; f < 300; f++) {
		sim.step();
	}
	CHECK(sim.tree.get_change_count() == changes); // Unchanged for 300 frames.
	CHECK(sim.tree.get_point_count() == far_points);
	check_accounting(sim.tree, sim.pool);
	CHECK(sim.ring.get_current_frame_poll_count() == 0);

	// The camera moves closer: banding persists one level deeper: more samples.
	sim.level = 4;
	frames = sim.converge(100, 10);
	REQUIRE(frames >= 0);
	uint32_t near_points = sim.tree.get_point_count();
	CHECK(near_points > far_points);
	CHECK(sim.tree.get_depth() == 4);
	changes = sim.tree.get_change_count();
	for (int f = 0; f < 300; f++) {
		sim.step();
	}
	CHECK(sim.tree.get_change_count() == changes);

	// And back: idle children with a banding-free parent are pruned.
	sim.level = 1;
	frames = sim.converge(200, 10);
	REQUIRE(frames >= 0);
	CHECK(sim.tree.get_point_count() < far_points);
	CHECK(sim.tree.get_depth() == 1);
	check_accounting(sim.tree, sim.pool);
}

TEST_CASE("[AreaShadowQuadtree] a full atlas stops growth without oscillation or leaks") {
	Simulation sim(12); // Room for the root, one expansion and a little more.
	sim.tree.set_max_depth(4);
	sim.level = 4;
	int frames = sim.converge(100, 10);
	REQUIRE(frames >= 0);
	// The pool bounds the point count by construction; what must hold is that the full pool, not the
	// requested depth, stopped the growth.
	CHECK(sim.tree.get_depth() < 4);
	CHECK(sim.pool.free_tiles.size() < 4); // Full: fewer tiles left than one expansion (4 children) needs.
	uint64_t changes = sim.tree.get_change_count();
	for (int f = 0; f < 300; f++) {
		sim.step();
	}
	CHECK(sim.tree.get_change_count() == changes);
	check_accounting(sim.tree, sim.pool);
}

TEST_CASE("[AreaShadowQuadtree] with the per-sample filter the heuristic saves maps: a ramp target, 2 x 2 or 5 x 5") {
	AreaShadowQuadtree::HeuristicInput in;
	in.light_size = Vector2(1.0f, 1.0f);
	in.range = 4.0f;
	in.viewport_height = 720.0f;
	in.max_depth = 3;
	bool fewer = false, four = false, twenty_five = false;
	uint32_t prev = 100;
	for (float d = 0.05f; d < 5000.0f; d *= 1.3f) {
		in.camera_distance = d;
		in.sample_filter = false;
		AreaShadowQuadtree::HeuristicResult hard = AreaShadowQuadtree::estimate_heuristic(in);
		in.sample_filter = true;
		AreaShadowQuadtree::HeuristicResult f = AreaShadowQuadtree::estimate_heuristic(in);
		CHECK((f.grid == 2 || f.grid == 5)); // No 3 x 3 (less accurate than 2 x 2 filtered), no 9 x 9.
		CHECK(f.depth <= hard.depth); // Never more maps than the hard-step target.
		CHECK(f.depth <= prev); // Farther: never more.
		CHECK(f.penumbra_px == doctest::Approx(hard.penumbra_px));
		if (f.depth == 0) {
			CHECK(f.penumbra_px <= in.filter_ramp_px + 1e-4f); // One ramp is enough only for a narrow penumbra.
		}
		prev = f.depth;
		fewer = fewer || f.depth < hard.depth;
		four = four || f.grid == 2;
		twenty_five = twenty_five || f.grid == 5;
	}
	CHECK(fewer);
	CHECK(four);
	CHECK(twenty_five);
	// A penumbra of 10 ramps' width: 9 x 9 with hard steps (1.5 px), 5 x 5 with the filter.
	in.camera_distance = 0.0f;
	in.sample_filter = false;
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).grid == 9);
	in.sample_filter = true;
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).grid == 5);
	in.max_depth = 1; // The project's limit still holds.
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).grid == 3);
}

TEST_CASE("[AreaShadowQuadtree] heuristic sample count is monotonic and bounded") {
	AreaShadowQuadtree::HeuristicInput in;
	in.light_size = Vector2(1.0f, 1.0f);
	in.range = 4.0f;
	in.viewport_height = 720.0f;
	in.max_depth = 3;

	// Closer camera -> never fewer samples; far away -> the four corners; very close -> the maximum.
	uint32_t prev = 100;
	for (float d = 0.05f; d < 2000.0f; d *= 1.5f) {
		in.camera_distance = d;
		AreaShadowQuadtree::HeuristicResult r = AreaShadowQuadtree::estimate_heuristic(in);
		CHECK(r.depth <= 3);
		CHECK(r.grid == (1u << r.depth) + 1);
		CHECK(r.depth <= prev);
		prev = r.depth;
		if (r.depth < 3) {
			CHECK(r.step_px <= in.target_step_px + 1e-4f); // The goal is met unless the limit is reached.
		}
	}
	in.camera_distance = 0.0f;
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).depth == 3);
	in.camera_distance = 5000.0f;
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).depth == 0);

	// Bigger light -> never fewer samples, and a wider penumbra.
	in.camera_distance = 30.0f;
	in.max_depth = 8;
	uint32_t prev_depth = 0;
	float prev_px = 0.0f;
	for (float s = 0.01f; s < 20.0f; s *= 1.7f) {
		in.light_size = Vector2(s, s * 0.5f);
		AreaShadowQuadtree::HeuristicResult r = AreaShadowQuadtree::estimate_heuristic(in);
		CHECK(r.depth >= prev_depth);
		CHECK(r.penumbra_px > prev_px);
		prev_depth = r.depth;
		prev_px = r.penumbra_px;
	}
	CHECK(prev_depth > 0);
	// A finer screen (more pixels) -> never fewer samples.
	in.light_size = Vector2(1, 1);
	in.viewport_height = 200.0f;
	uint32_t low = AreaShadowQuadtree::estimate_heuristic(in).depth;
	in.viewport_height = 4000.0f;
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).depth >= low);
	// Degenerate input.
	in.light_size = Vector2(0, 0);
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).depth == 0);
	set_error_print_silenced(true);
	in.light_size = Vector2(NAN, 1.0f);
	CHECK(AreaShadowQuadtree::estimate_heuristic(in).depth == 0);
	set_error_print_silenced(false);
}

} // namespace TestAreaShadowQuadtree
