/**************************************************************************/
/*  area_shadow_quadtree.cpp                                              */
/**************************************************************************/

#include "servers/rendering/renderer_rd/area_lights/area_shadow_quadtree.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>

/* Points */

void AreaShadowQuadtree::_corners(const Node &p_node, uint32_t r_x[4], uint32_t r_y[4]) const {
	uint32_t size = LATTICE >> p_node.depth;
	uint32_t x0 = p_node.i * size;
	uint32_t y0 = p_node.j * size;
	for (uint32_t c = 0; c < 4; c++) {
		r_x[c] = x0 + ((c & 1u) ? size : 0);
		r_y[c] = y0 + ((c & 2u) ? size : 0);
	}
}

void AreaShadowQuadtree::_ref_corners(const Node &p_node) {
	uint32_t xs[4], ys[4];
	_corners(p_node, xs, ys);
	for (uint32_t c = 0; c < 4; c++) {
		auto it = points.find(_point_key(xs[c], ys[c]));
		ERR_CONTINUE_MSG(it == points.end(), "AreaShadowQuadtree: internal error, a quad corner has no point.");
		it->second.refs++;
	}
}

void AreaShadowQuadtree::_unref_corners(const Node &p_node) {
	uint32_t xs[4], ys[4];
	_corners(p_node, xs, ys);
	for (uint32_t c = 0; c < 4; c++) {
		auto it = points.find(_point_key(xs[c], ys[c]));
		ERR_CONTINUE_MSG(it == points.end(), "AreaShadowQuadtree: internal error, a quad corner has no point.");
		if (--it->second.refs == 0) {
			if (tiles && it->second.tile != INVALID_TILE) {
				tiles->release_tile(it->second.tile);
			}
			points.erase(it);
		}
	}
}

/* Tree */

bool AreaShadowQuadtree::reset(TileSource *p_tiles) {
	clear();
	ERR_FAIL_NULL_V_MSG(p_tiles, false, "AreaShadowQuadtree::reset: no tile source.");
	tiles = p_tiles;
	Node root;
	uint32_t xs[4], ys[4];
	_corners(root, xs, ys);
	uint32_t acquired[4];
	for (uint32_t c = 0; c < 4; c++) {
		if (!tiles->acquire_tile(acquired[c])) {
			for (uint32_t k = 0; k < c; k++) {
				tiles->release_tile(acquired[k]);
			}
			return false;
		}
	}
	for (uint32_t c = 0; c < 4; c++) {
		Point p;
		p.x = xs[c];
		p.y = ys[c];
		p.uv = Vector2(real_t(p.x) / real_t(LATTICE), real_t(p.y) / real_t(LATTICE));
		p.tile = acquired[c];
		points[_point_key(p.x, p.y)] = p;
	}
	root.version = uint32_t(++change_count);
	root.created_frame = frame;
	nodes[root_key()] = root;
	_ref_corners(root);
	return true;
}

void AreaShadowQuadtree::clear() {
	if (tiles) {
		for (const auto &kv : points) {
			if (kv.second.tile != INVALID_TILE) {
				tiles->release_tile(kv.second.tile);
			}
		}
	}
	points.clear();
	nodes.clear();
}

void AreaShadowQuadtree::set_max_depth(uint32_t p_depth) {
	ERR_FAIL_COND_MSG(p_depth < 1 || p_depth > LATTICE_LEVELS, vformat("AreaShadowQuadtree: max depth %u is invalid (expected 1..%u).", p_depth, LATTICE_LEVELS));
	max_depth = p_depth;
	// Prune everything below the new limit, deepest parents first.
	for (uint32_t d = LATTICE_LEVELS; d-- > max_depth;) {
		std::vector<uint64_t> parents;
		for (const auto &kv : nodes) {
			if (kv.second.depth == d && kv.second.has_children) {
				parents.push_back(kv.first);
			}
		}
		for (uint64_t k : parents) {
			prune(k);
		}
	}
}

bool AreaShadowQuadtree::expand(uint64_t p_node) {
	auto it = nodes.find(p_node);
	ERR_FAIL_COND_V_MSG(it == nodes.end(), false, "AreaShadowQuadtree::expand: unknown node.");
	Node &n = it->second;
	if (n.has_children || n.depth >= max_depth || !tiles) {
		return false;
	}
	// The 3 x 3 lattice points of the four children; the corners exist, up to five are new.
	uint32_t half = (LATTICE >> n.depth) / 2;
	uint32_t x0 = n.i * 2 * half;
	uint32_t y0 = n.j * 2 * half;
	std::vector<uint32_t> new_x, new_y, new_tiles;
	for (uint32_t b = 0; b < 3; b++) {
		for (uint32_t a = 0; a < 3; a++) {
			uint32_t x = x0 + a * half, y = y0 + b * half;
			if (points.count(_point_key(x, y)) == 0) {
				new_x.push_back(x);
				new_y.push_back(y);
			}
		}
	}
	for (size_t k = 0; k < new_x.size(); k++) {
		uint32_t t;
		if (!tiles->acquire_tile(t)) {
			for (uint32_t r : new_tiles) {
				tiles->release_tile(r);
			}
			return false; // All or nothing.
		}
		new_tiles.push_back(t);
	}
	for (size_t k = 0; k < new_x.size(); k++) {
		Point p;
		p.x = new_x[k];
		p.y = new_y[k];
		p.uv = Vector2(real_t(p.x) / real_t(LATTICE), real_t(p.y) / real_t(LATTICE));
		p.tile = new_tiles[k];
		points[_point_key(p.x, p.y)] = p; // refs 0 until the children reference it.
	}
	Node parent = n;
	parent.has_children = true;
	parent.idle = false;
	parent.version = uint32_t(++change_count);
	parent.created_frame = frame;
	nodes[p_node] = parent;
	for (uint32_t c = 0; c < 4; c++) {
		Node child;
		child.depth = parent.depth + 1;
		child.i = parent.i * 2 + (c & 1u);
		child.j = parent.j * 2 + ((c >> 1u) & 1u);
		child.version = uint32_t(++change_count);
		child.created_frame = frame;
		nodes[make_node_key(child.depth, child.i, child.j)] = child;
		_ref_corners(child);
	}
	return true;
}

bool AreaShadowQuadtree::prune(uint64_t p_node) {
	auto it = nodes.find(p_node);
	ERR_FAIL_COND_V_MSG(it == nodes.end(), false, "AreaShadowQuadtree::prune: unknown node.");
	if (!it->second.has_children) {
		return false;
	}
	Node parent = it->second;
	// Children with children of their own go first (set_max_depth and clear paths).
	for (uint32_t c = 0; c < 4; c++) {
		uint64_t ck = make_node_key(parent.depth + 1, parent.i * 2 + (c & 1u), parent.j * 2 + ((c >> 1u) & 1u));
		auto cit = nodes.find(ck);
		if (cit == nodes.end()) {
			continue;
		}
		if (cit->second.has_children) {
			prune(ck);
			cit = nodes.find(ck);
		}
		Node child = cit->second;
		nodes.erase(cit);
		_unref_corners(child);
	}
	parent.has_children = false;
	parent.idle = false; // Recently pruned: not idle until tested as a leaf.
	parent.version = uint32_t(++change_count);
	parent.created_frame = frame;
	nodes[p_node] = parent;
	return true;
}

uint32_t AreaShadowQuadtree::shrink(uint32_t p_max_points) {
	uint32_t pruned = 0;
	while (points.size() > p_max_points) {
		uint64_t best = 0;
		uint32_t best_depth = 0;
		bool found = false;
		for (const auto &kv : nodes) {
			const Node &n = kv.second;
			if (!n.has_children || (found && n.depth <= best_depth)) {
				continue;
			}
			bool leaves = true;
			for (uint32_t c = 0; c < 4 && leaves; c++) {
				auto cit = nodes.find(make_node_key(n.depth + 1, n.i * 2 + (c & 1u), n.j * 2 + ((c >> 1u) & 1u)));
				leaves = cit == nodes.end() || !cit->second.has_children;
			}
			if (leaves) {
				best = kv.first;
				best_depth = n.depth;
				found = true;
			}
		}
		if (!found || !prune(best)) {
			break;
		}
		pruned++;
	}
	return pruned;
}

bool AreaShadowQuadtree::_children_idle_leaves(const Node &p_node) const {
	if (!p_node.has_children) {
		return false;
	}
	for (uint32_t c = 0; c < 4; c++) {
		auto it = nodes.find(make_node_key(p_node.depth + 1, p_node.i * 2 + (c & 1u), p_node.j * 2 + ((c >> 1u) & 1u)));
		if (it == nodes.end() || it->second.has_children || !it->second.idle) {
			return false;
		}
	}
	return true;
}

/* Frames */

uint32_t AreaShadowQuadtree::apply_results(const std::vector<Result> &p_results) {
	uint32_t changed = 0;
	// Leaves at the maximum depth are never tested (they cannot expand): idle once they survived a frame.
	for (auto &kv : nodes) {
		Node &n = kv.second;
		if (!n.has_children && n.depth >= max_depth && n.created_frame < frame) {
			n.idle = true;
		}
	}
	// Depths where some current (not stale) answer bands: the same-depth rule.
	uint32_t banding_depths = 0;
	for (const Result &r : p_results) {
		auto it = nodes.find(r.node);
		if (same_depth && r.banding && it != nodes.end() && it->second.version == r.version && it->second.depth < 32) {
			banding_depths |= 1u << it->second.depth;
		}
	}
	// Leaves first: expand on banding (or a penumbra at a banding depth), otherwise idle.
	for (const Result &r : p_results) {
		if (r.parent_test) {
			continue;
		}
		auto it = nodes.find(r.node);
		if (it == nodes.end() || it->second.version != r.version || it->second.has_children) {
			continue; // Stale: the node changed since the test was issued.
		}
		const bool depth_bands = (banding_depths >> it->second.depth) & 1u;
		if (r.banding || (r.penumbra && depth_bands)) {
			it->second.idle = false;
			if (expand(r.node)) {
				changed++;
			}
		} else {
			it->second.idle = true;
		}
	}
	// Then the checked parents: no banding with their children merged back (and none at their depth) -> prune.
	for (const Result &r : p_results) {
		if (!r.parent_test || r.banding) {
			continue;
		}
		auto it = nodes.find(r.node);
		if (it == nodes.end() || it->second.version != r.version || !_children_idle_leaves(it->second)) {
			continue;
		}
		if ((banding_depths >> it->second.depth) & 1u) {
			continue; // A quad of this depth bands: its steps are as wide here.
		}
		if (prune(r.node)) {
			changed++;
		}
	}
	return changed;
}

AreaShadowQuadtree::Query AreaShadowQuadtree::_make_query(uint64_t p_key, const Node &p_node, bool p_parent) const {
	Query q;
	q.node = p_key;
	q.version = p_node.version;
	q.parent_test = p_parent;
	q.depth = p_node.depth;
	uint32_t xs[4], ys[4];
	_corners(p_node, xs, ys);
	for (uint32_t c = 0; c < 4; c++) {
		const Point &p = points.at(_point_key(xs[c], ys[c]));
		q.corner_uv[c] = p.uv;
		q.corner_tile[c] = p.tile;
	}
	q.uv_min = q.corner_uv[0];
	q.uv_max = q.corner_uv[3];
	return q;
}

std::vector<AreaShadowQuadtree::Query> AreaShadowQuadtree::build_queries(bool p_expansion_tests) const {
	std::vector<Query> out;
	auto corners_drawn = [this](const Node &p_node) {
		uint32_t xs[4], ys[4];
		_corners(p_node, xs, ys);
		for (uint32_t c = 0; c < 4; c++) {
			auto it = points.find(_point_key(xs[c], ys[c]));
			if (it == points.end() || !it->second.valid) {
				return false;
			}
		}
		return true;
	};
	for (const auto &kv : nodes) {
		const Node &n = kv.second;
		// Without tiles to grow, an idle leaf's retest could not change anything; a leaf that is not idle yet
		// is still tested, or its parent could never be tested for pruning (which is what frees tiles).
		if (!n.has_children && n.depth < max_depth && corners_drawn(n) && (p_expansion_tests || !n.idle)) {
			out.push_back(_make_query(kv.first, n, false));
		}
	}
	for (const auto &kv : nodes) {
		const Node &n = kv.second;
		if (_children_idle_leaves(n) && corners_drawn(n)) {
			out.push_back(_make_query(kv.first, n, true));
		}
	}
	return out;
}

void AreaShadowQuadtree::mark_all_dirty() {
	for (auto &kv : points) {
		kv.second.dirty = true;
	}
}

std::vector<AreaShadowQuadtree::Point> AreaShadowQuadtree::collect_draws(uint32_t p_max) {
	std::vector<Point> out;
	// Points never drawn first (they hold back every quad using them), then the rest.
	for (int pass = 0; pass < 2; pass++) {
		for (auto &kv : points) {
			Point &p = kv.second;
			if (out.size() >= p_max) {
				return out;
			}
			if (!p.dirty || (pass == 0) == p.valid) {
				continue;
			}
			p.dirty = false;
			p.valid = true;
			out.push_back(p);
		}
	}
	return out;
}

/* Queries */

bool AreaShadowQuadtree::node_is_leaf(uint64_t p_node) const {
	auto it = nodes.find(p_node);
	return it != nodes.end() && !it->second.has_children;
}

bool AreaShadowQuadtree::node_is_idle(uint64_t p_node) const {
	auto it = nodes.find(p_node);
	return it != nodes.end() && !it->second.has_children && it->second.idle;
}

uint32_t AreaShadowQuadtree::get_leaf_count() const {
	uint32_t n = 0;
	for (const auto &kv : nodes) {
		n += kv.second.has_children ? 0 : 1;
	}
	return n;
}

uint32_t AreaShadowQuadtree::get_depth() const {
	uint32_t d = 0;
	for (const auto &kv : nodes) {
		d = std::max(d, kv.second.depth);
	}
	return d;
}

std::vector<AreaShadowQuadtree::Point> AreaShadowQuadtree::get_points() const {
	std::vector<Point> out;
	out.reserve(points.size());
	for (const auto &kv : points) {
		out.push_back(kv.second);
	}
	return out;
}

bool AreaShadowQuadtree::has_point(const Vector2 &p_uv) const {
	return get_point_refs(p_uv) > 0;
}

uint32_t AreaShadowQuadtree::get_point_refs(const Vector2 &p_uv) const {
	real_t fx = p_uv.x * real_t(LATTICE), fy = p_uv.y * real_t(LATTICE);
	if (!(fx >= 0.0f && fy >= 0.0f && fx <= real_t(LATTICE) && fy <= real_t(LATTICE)) || fx != std::floor(fx) || fy != std::floor(fy)) {
		return 0;
	}
	auto it = points.find(_point_key(uint32_t(fx), uint32_t(fy)));
	return it == points.end() ? 0 : it->second.refs;
}

std::vector<float> AreaShadowQuadtree::get_point_weights() const {
	std::vector<float> out;
	for (uint32_t cell : get_point_cells()) {
		out.push_back(get_cell_weight(cell)); // A quarter of every leaf the point is a corner of.
	}
	return out;
}

std::vector<uint32_t> AreaShadowQuadtree::get_point_cells() const {
	std::map<uint32_t, uint32_t> cells;
	for (const auto &kv : nodes) {
		const Node &n = kv.second;
		if (n.has_children) {
			continue;
		}
		uint32_t xs[4], ys[4];
		_corners(n, xs, ys);
		for (uint32_t c = 0; c < 4; c++) {
			// Corner c = (c & 1 ? u1 : u0, c & 2 ? v1 : v0): the leaf lies on the other side of it, quadrant 3 - c.
			cells[_point_key(xs[c], ys[c])] |= (std::min(n.depth + 1, 7u)) << (CELL_BITS * (3u - c));
		}
	}
	std::vector<uint32_t> out;
	out.reserve(points.size());
	for (const auto &kv : points) {
		auto it = cells.find(kv.first);
		out.push_back(it == cells.end() ? 0u : it->second);
	}
	return out;
}

// Half the side of the leaf in quadrant p_quadrant of a cell code (0: none).
static float _cell_half_side(uint32_t p_cell, uint32_t p_quadrant) {
	uint32_t code = (p_cell >> (AreaShadowQuadtree::CELL_BITS * p_quadrant)) & 7u;
	return code > 0 ? 0.5f / float(1u << (code - 1)) : 0.0f;
}

float AreaShadowQuadtree::get_cell_weight(uint32_t p_cell) {
	float w = 0.0f;
	for (uint32_t q = 0; q < 4; q++) {
		float half = _cell_half_side(p_cell, q);
		w += half * half;
	}
	return w;
}

void AreaShadowQuadtree::get_cell_extent(uint32_t p_cell, float r_extent[4]) {
	for (uint32_t i = 0; i < 4; i++) {
		r_extent[i] = 0.0f;
	}
	for (uint32_t q = 0; q < 4; q++) {
		float half = _cell_half_side(p_cell, q);
		float &eu = r_extent[(q & 1u) ? 1 : 0];
		float &ev = r_extent[(q & 2u) ? 3 : 2];
		eu = std::max(eu, half);
		ev = std::max(ev, half);
	}
}

/* Heuristic */

AreaShadowQuadtree::HeuristicResult AreaShadowQuadtree::estimate_heuristic(const HeuristicInput &p_input) {
	HeuristicResult res;
	const HeuristicInput &in = p_input;
	ERR_FAIL_COND_V_MSG(!std::isfinite(in.light_size.x) || !std::isfinite(in.light_size.y) || !std::isfinite(in.range) || !std::isfinite(in.camera_distance) || !std::isfinite(in.fov_y) || !std::isfinite(in.viewport_height) || !std::isfinite(in.target_step_px) || !std::isfinite(in.occluder_fraction),
			res, "AreaShadowQuadtree::estimate_heuristic: non-finite input; using the four corners.");
	uint32_t depth_limit = std::min(std::max(in.max_depth, 1u), LATTICE_LEVELS);
	float light = std::max(std::max(float(in.light_size.x), float(in.light_size.y)), 0.0f);
	float range = std::max(in.range, 1e-3f);
	if (light <= 0.0f) {
		return res;
	}
	// Penumbra width on the receiver (similar triangles), occluder between the light and the receiver:
	// the casters' distances when known, else the conservative fraction of the range.
	float occluder = std::min(std::max(in.occluder_fraction, 1e-3f), 1.0f) * range;
	float receiver = range;
	if (in.occluder_distance > 0.0f && in.receiver_distance > 0.0f && std::isfinite(in.occluder_distance) && std::isfinite(in.receiver_distance)) {
		receiver = std::min(in.receiver_distance, range);
		occluder = std::min(std::max(in.occluder_distance, 1e-3f * range), receiver);
	}
	float penumbra = light * (receiver - occluder) / occluder;
	penumbra = std::min(penumbra, light + 2.0f * range); // Never wider than the lit range box.
	// Pixel footprint at the camera distance.
	float cam = std::max(in.camera_distance, std::max(in.min_camera_distance, 1e-3f));
	float fov = std::min(std::max(in.fov_y, 1e-3f), 3.1f);
	float pixel_m = 2.0f * cam * std::tan(fov * 0.5f) / std::max(in.viewport_height, 1.0f);
	float target = std::max(in.sample_filter ? in.filter_ramp_px : in.target_step_px, 0.1f);
	if (in.sample_filter) {
		depth_limit = std::min(depth_limit, FILTER_MAX_DEPTH);
	}
	res.penumbra_m = penumbra;
	res.penumbra_px = penumbra / pixel_m;
	float steps = res.penumbra_px / target; // n - 1 must reach this.
	uint32_t depth = 0;
	while (depth < depth_limit && float(1u << depth) < steps) {
		depth++;
	}
	if (in.sample_filter && depth == 1 && depth_limit >= 2) {
		depth = 2; // Filtered 3 x 3 is less accurate than 2 x 2 (doc/shadows.md): straight to 5 x 5.
	}
	res.depth = depth;
	res.grid = (1u << depth) + 1;
	res.step_px = res.penumbra_px / float(1u << depth);
	return res;
}
