/**************************************************************************/
/*  area_shadow_quadtree.h                                                */
/**************************************************************************/
/* godot-area: the adaptive subdivision of one area light for soft        */
/* shadows (thesis section 6.3, Algorithm 1, after Schwarzler et al.),    */
/* GPU-free so it is unit-testable.                                       */
/*                                                                        */
/* A quadtree over the light's canonical square [0,1]^2 ((0,0) = local    */
/* (-a/2, -b/2)). Every node is a quad; its four corners are sample       */
/* points, each with one shadow map (one atlas tile). Points live on a    */
/* 2^8 lattice and are shared between neighbouring quads: a point is      */
/* created (and its tile acquired) by the first quad that uses it and     */
/* freed (tile released) with the last one (reference counts).            */
/*                                                                        */
/* Over frames (no CPU stall): build_queries() lists the banding tests of */
/* this frame (every expandable leaf; every parent whose children are     */
/* idle leaves); their answers come back some frames later and go to      */
/* apply_results(): a leaf with banding is expanded, a leaf without is    */
/* idle; a tested parent without banding is pruned. "Idle" (thesis 6.3):  */
/* a leaf that has stayed a leaf since its last test, i.e. not recently   */
/* created or pruned. Stale answers (the node changed since the test was  */
/* issued) are recognised by a per-node version and ignored.              */
/*                                                                        */
/* Also the analytic heuristic of section 6.5 (estimate_heuristic()).     */

#pragma once

#include "core/math/vector2.h"

#include <cstdint>
#include <map>
#include <vector>

class AreaShadowQuadtree {
public:
	/* Definition */

	static constexpr uint32_t LATTICE_LEVELS = 8;
	static constexpr uint32_t LATTICE = 1u << LATTICE_LEVELS; // Points at (x, y) / LATTICE, x, y in 0..LATTICE.
	static constexpr uint32_t DEFAULT_MAX_DEPTH = 3; // 9 x 9 points at most (the GPU packing's limit).
	static constexpr uint32_t INVALID_TILE = UINT32_MAX;

	// Where the points' shadow maps live. The atlas (or a test pool) implements it; it must outlive the
	// tree's points (call clear() before destroying the source).
	class TileSource {
	public:
		virtual bool acquire_tile(uint32_t &r_tile) = 0;
		virtual void release_tile(uint32_t p_tile) = 0;
		virtual ~TileSource() {}
	};

	// One sample point: lattice position, its tile, how many quads use it, and its draw state
	// (valid: drawn at least once; dirty: must be (re)drawn).
	struct Point {
		uint32_t x = 0;
		uint32_t y = 0;
		Vector2 uv;
		uint32_t tile = INVALID_TILE;
		uint32_t refs = 0;
		bool valid = false;
		bool dirty = true;
	};

	// One banding test of a quad. Corners in the order (u0,v0), (u1,v0), (u0,v1), (u1,v1).
	struct Query {
		uint64_t node = 0;
		uint32_t version = 0;
		bool parent_test = false; // true: prune test of a parent; false: expansion test of a leaf.
		uint32_t depth = 0;
		Vector2 uv_min;
		Vector2 uv_max;
		Vector2 corner_uv[4];
		uint32_t corner_tile[4] = { 0, 0, 0, 0 };
	};

	struct Result {
		uint64_t node = 0;
		uint32_t version = 0;
		bool parent_test = false;
		bool banding = false;
		// The test saw the quad's penumbra (a receiver cell with 0 < v < 1). Same-depth rule of
		// apply_results(): a leaf that sees its penumbra expands when a quad of its depth bands.
		bool penumbra = false;
	};

	// Inputs of the analytic heuristic (thesis 6.5). Distances in metres, angles in radians.
	struct HeuristicInput {
		Vector2 light_size = Vector2(1, 1); // a, b.
		float range = 5.0f; // area_range: receivers are at most this far from the light.
		float camera_distance = 10.0f; // Camera to the closest point of the light's range box (0 inside).
		float fov_y = 1.3089969f; // Vertical field of view (75 degrees).
		float viewport_height = 1080.0f; // Pixels.
		float target_step_px = 1.5f; // Largest acceptable banding step on screen.
		float occluder_fraction = 0.25f; // Conservative occluder distance, as a fraction of the range.
		// Measured from the light's casters along its normal (metres; 0 = unknown: occluder_fraction *
		// range and the range): the nearest caster point and the farthest receiver point in range.
		float occluder_distance = 0.0f;
		float receiver_distance = 0.0f;
		float min_camera_distance = 0.1f; // Clamp (camera inside the box).
		uint32_t max_depth = DEFAULT_MAX_DEPTH;
		// The per-sample penumbra filter is on (RS::AREA_SHADOW_FILTER_PENUMBRA): each map's edge is spread
		// over the penumbra of its own cell, so the n - 1 steps are ramps, not bands, and the target is a
		// ramp width (filter_ramp_px) instead of a hard step (target_step_px). With the filter the error
		// stops falling at 5 x 5 (FILTER_MAX_DEPTH) and the 3 x 3 grid is worse than the 2 x 2 one (its
		// centre map cannot see the floor beside an occluder's base), so depth 1 becomes depth 2.
		bool sample_filter = false;
		float filter_ramp_px = 4.0f;
	};

	static constexpr uint32_t FILTER_MAX_DEPTH = 2;

	struct HeuristicResult {
		uint32_t depth = 0; // Subdivision levels: grid 2^depth + 1.
		uint32_t grid = 2;
		float penumbra_m = 0.0f; // Conservative penumbra width on the receiver.
		float penumbra_px = 0.0f; // Its projected width on screen.
		float step_px = 0.0f; // Width of one banding step on screen with this grid.
	};

private:
	/* Private Members */

	struct Node {
		uint32_t depth = 0;
		uint32_t i = 0;
		uint32_t j = 0;
		bool has_children = false;
		bool idle = false;
		uint32_t version = 0;
		uint64_t created_frame = 0; // Frame the node last changed shape (created, expanded or pruned).
	};

	TileSource *tiles = nullptr;
	uint32_t max_depth = DEFAULT_MAX_DEPTH;
	bool same_depth = true;
	uint64_t frame = 0;
	uint64_t change_count = 0;
	std::map<uint64_t, Node> nodes;
	std::map<uint32_t, Point> points;

	static uint32_t _point_key(uint32_t p_x, uint32_t p_y) { return p_y * (LATTICE + 1) + p_x; }
	void _corners(const Node &p_node, uint32_t r_x[4], uint32_t r_y[4]) const;
	void _ref_corners(const Node &p_node);
	void _unref_corners(const Node &p_node);
	bool _children_idle_leaves(const Node &p_node) const;
	Query _make_query(uint64_t p_key, const Node &p_node, bool p_parent) const;

public:
	/* Public Methods */

	static uint64_t make_node_key(uint32_t p_depth, uint32_t p_i, uint32_t p_j) { return (uint64_t(p_depth) << 48) | (uint64_t(p_i) << 24) | uint64_t(p_j); }
	static uint64_t root_key() { return make_node_key(0, 0, 0); }

	// (Re)starts the tree with the root quad (its four corners). Returns false (and leaves the tree empty)
	// when the source has no four tiles. Frees the old tree first.
	bool reset(TileSource *p_tiles);
	// Frees every point (tiles go back to the source) and node.
	void clear();
	bool is_empty() const { return nodes.empty(); }

	// Deepest level (1..LATTICE_LEVELS); nodes deeper than a new limit are pruned (their points freed).
	void set_max_depth(uint32_t p_depth);
	uint32_t get_max_depth() const { return max_depth; }
	// The same-depth rule of apply_results() (default on); off: Algorithm 1 as written (each quad on its
	// own answer), for measuring what the rule is worth.
	void set_same_depth_rule(bool p_enable) { same_depth = p_enable; }
	bool is_same_depth_rule() const { return same_depth; }

	// Subdivides leaf p_node into four. Needs tiles for the new points (up to 5); fails without changing
	// anything if the node is not an expandable leaf or the tiles are not there.
	bool expand(uint64_t p_node);
	// Removes the children of p_node (they must be leaves); points no other quad uses are freed.
	bool prune(uint64_t p_node);
	// Eviction (fair sharing, when the light's share of the atlas fell): prunes the deepest parents whose
	// children are all leaves, finest first (ties: lattice order), until at most p_max_points points are
	// left or only the root quad is. Returns how many parents were pruned.
	uint32_t shrink(uint32_t p_max_points);

	// Per frame: begin_frame(); apply_results(newest completed answers); draw collect_draws();
	// render; issue build_queries().
	void begin_frame() { frame++; }
	uint64_t get_frame() const { return frame; }
	// Applies banding answers (Algorithm 1): leaves with banding expand, leaves without become idle,
	// parents without banding are pruned. Stale answers are ignored. Returns how many nodes changed.
	// Same-depth rule (ours, beyond the thesis): quads of one depth have one size, so under one occluder
	// and receiver they throw penumbrae of one width and steps of one size; when any quad of depth d
	// bands in p_results, every depth-d leaf whose test saw its penumbra expands too, and no depth-d
	// parent is pruned. A detector that misses a step on one quad (its penumbra off-screen, between
	// reprojection cells) then no longer leaves a coarse quad beside fine ones, whose steps dominate the
	// error; trees stay uniform where the whole light throws the penumbra.
	uint32_t apply_results(const std::vector<Result> &p_results);
	// Tests to run this frame: expansion tests of leaves above the maximum depth whose corners are drawn
	// (p_expansion_tests false, e.g. when the atlas has no free tile: only leaves not idle yet, so that
	// they can become idle and their parents be tested for pruning), then prune tests of parents whose
	// four children are idle leaves.
	std::vector<Query> build_queries(bool p_expansion_tests = true) const;

	// Marks every point for redraw (scene changed).
	void mark_all_dirty();
	// Points to draw now (dirty ones, at most p_max), marked valid and clean from here on.
	std::vector<Point> collect_draws(uint32_t p_max = UINT32_MAX);

	bool has_node(uint64_t p_node) const { return nodes.count(p_node) != 0; }
	bool node_is_leaf(uint64_t p_node) const;
	bool node_is_idle(uint64_t p_node) const;
	uint32_t get_node_count() const { return uint32_t(nodes.size()); }
	uint32_t get_leaf_count() const;
	uint32_t get_depth() const; // Deepest leaf.
	uint32_t get_point_count() const { return uint32_t(points.size()); }
	// Points in lattice order (row by row).
	std::vector<Point> get_points() const;
	bool has_point(const Vector2 &p_uv) const;
	uint32_t get_point_refs(const Vector2 &p_uv) const; // 0 if absent.
	// Each point's share of the light (sum over the leaves it is a corner of, of a quarter of the leaf's
	// area); same order as get_points(), sums to 1.
	std::vector<float> get_point_weights() const;
	// Each point's cell (the part of the light it stands for, thesis 6.3 with the weights above): the quarter,
	// next to the point, of every leaf it is a corner of. Per point (same order as get_points()) 12 bits, 3
	// per quadrant q around it (bit 0 of q: towards +u, bit 1: towards +v) at bits 3q..3q+2: 0 = no such
	// leaf (a T-junction's coarse side, or outside the light), else that leaf's depth + 1. Depths up to 6.
	std::vector<uint32_t> get_point_cells() const;
	static constexpr uint32_t CELL_BITS = 3;
	// The share of the light of a cell code of get_point_cells(): sum of (leaf side / 2)^2 (equals
	// get_point_weights()), and its extent from the point towards -u, +u, -v, +v (half the largest leaf side
	// on that side; the bounding box of the quarters).
	static float get_cell_weight(uint32_t p_cell);
	static void get_cell_extent(uint32_t p_cell, float r_extent[4]);
	// Total number of expand/prune operations so far (convergence checks).
	uint64_t get_change_count() const { return change_count; }

	// Analytic estimate of the needed subdivision (thesis 6.5): the widest penumbra this light can
	// throw, light size x (receiver - occluder) / occluder with the receiver at the range and the occluder at
	// occluder_fraction x range (clamped to the range box), projected on the screen at the camera distance;
	// a grid of n points per side splits it in n - 1 steps, so n - 1 >= penumbra_px / target_step_px.
	static HeuristicResult estimate_heuristic(const HeuristicInput &p_input);

	AreaShadowQuadtree() {}
	~AreaShadowQuadtree() { clear(); }
	AreaShadowQuadtree(const AreaShadowQuadtree &) = delete;
	AreaShadowQuadtree &operator=(const AreaShadowQuadtree &) = delete;
};
