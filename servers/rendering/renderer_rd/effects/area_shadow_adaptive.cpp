/**************************************************************************/
/*  area_shadow_adaptive.cpp                                              */
/**************************************************************************/

#include "servers/rendering/renderer_rd/effects/area_shadow_adaptive.h"

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <set>
#include <tuple>

/* Settings and heuristic */

uint32_t AreaShadowAdaptiveRD::get_project_reprojection_divisor() {
	int v = int(GLOBAL_DEF(SETTING_REPROJECTION_DIVISOR, int(DEFAULT_REPROJECTION_DIVISOR)).to_int());
	if (v < 1 || v > 64) {
		ERR_PRINT(vformat("%s must be 1..64; got %d. Using %u.", SETTING_REPROJECTION_DIVISOR, v, DEFAULT_REPROJECTION_DIVISOR));
		return DEFAULT_REPROJECTION_DIVISOR;
	}
	return uint32_t(v);
}

uint32_t AreaShadowAdaptiveRD::get_project_max_depth() {
	int v = int(GLOBAL_DEF(SETTING_MAX_DEPTH, int(MAX_GPU_DEPTH)).to_int());
	if (v < 1 || v > int(MAX_GPU_DEPTH)) {
		ERR_PRINT(vformat("%s must be 1..%u; got %d. Using %u.", SETTING_MAX_DEPTH, MAX_GPU_DEPTH, v, MAX_GPU_DEPTH));
		return MAX_GPU_DEPTH;
	}
	return uint32_t(v);
}

float AreaShadowAdaptiveRD::get_project_heuristic_occluder_fraction() {
	double v = GLOBAL_DEF(SETTING_HEURISTIC_OCCLUDER_FRACTION, double(DEFAULT_HEURISTIC_OCCLUDER_FRACTION)).to_float();
	if (!(v >= 0.01 && v <= 0.99)) {
		ERR_PRINT(vformat("%s must be 0.01..0.99; got %f. Using %.2f.", SETTING_HEURISTIC_OCCLUDER_FRACTION, v, double(DEFAULT_HEURISTIC_OCCLUDER_FRACTION)));
		return DEFAULT_HEURISTIC_OCCLUDER_FRACTION;
	}
	return float(v);
}

uint32_t AreaShadowAdaptiveRD::compute_heuristic_grid(const AABB &p_world_box, const Vector2 &p_size, float p_range, const RenderSceneData &p_data, const Transform3D &p_world_from_light, const std::vector<AABB> &p_casters, bool p_sample_filter) {
	AreaShadowQuadtree::HeuristicInput in;
	in.light_size = p_size;
	in.range = p_range;
	// Camera to the closest point of the range box (0 inside it).
	Vector3 cam = p_data.cam_transform.origin;
	Vector3 lo = p_world_box.position;
	Vector3 hi = p_world_box.position + p_world_box.size;
	Vector3 d;
	for (int i = 0; i < 3; i++) {
		d[i] = std::max(std::max(lo[i] - cam[i], cam[i] - hi[i]), real_t(0));
	}
	in.camera_distance = d.length();
	in.fov_y = p_data.fovy_degrees * 0.017453293f;
	in.viewport_height = p_data.viewport_height > 0 ? float(p_data.viewport_height) : 1080.0f;
	in.max_depth = get_project_max_depth();
	in.occluder_fraction = get_project_heuristic_occluder_fraction();
	in.sample_filter = p_sample_filter;
	// Each caster's extent along the light's normal: its nearest point can occlude, its farthest can
	// receive. Casters behind the light plane or beyond the range do neither.
	const Vector3 normal = -p_world_from_light.basis.get_column(2).normalized();
	const Vector3 origin = p_world_from_light.origin;
	float nearest = FLT_MAX, farthest = 0.0f;
	for (const AABB &b : p_casters) {
		float lo = FLT_MAX, hi = -FLT_MAX;
		for (int c = 0; c < 8; c++) {
			const float t = (b.get_endpoint(c) - origin).dot(normal);
			lo = std::min(lo, t);
			hi = std::max(hi, t);
		}
		if (hi <= 0.0f || lo >= p_range) {
			continue;
		}
		nearest = std::min(nearest, std::max(lo, 0.0f));
		farthest = std::max(farthest, std::min(hi, p_range));
	}
	if (nearest <= farthest && farthest > 0.0f) { // Equal: no occluder in front of any receiver.
		in.occluder_distance = std::max(nearest, 1e-3f);
		in.receiver_distance = farthest;
	}
	return AreaShadowQuadtree::estimate_heuristic(in).grid;
}

bool AreaShadowAdaptiveRD::initialize(uint32_t p_ring_slots) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !rd->is_initialized(), false, "AreaShadowAdaptiveRD::initialize() needs an initialized RenderingDevice.");
	if (initialized) {
		return true;
	}
	ERR_FAIL_COND_V(!ring.configure(p_ring_slots), false);
	divisor = get_project_reprojection_divisor();
	max_depth = get_project_max_depth();
	// Loading splits the files; nothing is compiled before the first dispatch with work.
	ERR_FAIL_COND_V_MSG(!reprojection_shader.initialize("area_shadow_reprojection.glsl", { "" }), false, "AreaShadowAdaptiveRD: cannot load shaders/area_shadow_reprojection.glsl.");
	ERR_FAIL_COND_V_MSG(!banding_shader.initialize("area_shadow_banding.glsl", { "" }), false, "AreaShadowAdaptiveRD: cannot load shaders/area_shadow_banding.glsl.");
	RD::SamplerState ss; // Nearest, clamp: texelFetch only.
	sampler = rd->sampler_create(ss);
	query_buffer = rd->storage_buffer_create(MAX_QUERIES_PER_FRAME * sizeof(QueryData));
	rd->set_resource_name(query_buffer, "AreaShadowAdaptiveRD queries");
	light_buffer = rd->storage_buffer_create(MAX_QUERIES_PER_FRAME * sizeof(AdaptiveLightData));
	rd->set_resource_name(light_buffer, "AreaShadowAdaptiveRD lights");
	point_buffer = rd->storage_buffer_create(4 * MAX_QUERIES_PER_FRAME * sizeof(PointData));
	rd->set_resource_name(point_buffer, "AreaShadowAdaptiveRD sample points");
	flag_buffers.clear();
	for (uint32_t i = 0; i < ring.get_slot_count(); i++) {
		RID b = rd->storage_buffer_create(MAX_QUERIES_PER_FRAME * sizeof(uint32_t));
		rd->set_resource_name(b, vformat("AreaShadowAdaptiveRD banding flags %u", i));
		flag_buffers.push_back(b);
	}
	slot_queries.assign(ring.get_slot_count(), std::vector<IssuedQuery>());
	slot_submissions.assign(ring.get_slot_count(), 0);
	slot_flags.assign(ring.get_slot_count(), std::vector<uint32_t>());
	slot_arrived.assign(ring.get_slot_count(), false);
	slot_tokens.assign(ring.get_slot_count(), 0);
	alive = std::make_shared<bool>(true);
	ring.set_frame_complete_predicate([this](uint64_t p_frame) {
		// A frame is complete when its flags arrived (RenderingDevice::buffer_get_data_async() delivers them
		// after the frame's fence wait); polling never waits.
		for (uint32_t i = 0; i < ring.get_slot_count(); i++) {
			if (ring.get_slot_state(i) == AreaShadowReadbackRing::SLOT_IN_FLIGHT && ring.get_slot_frame(i) == p_frame) {
				// A submit that failed drops the readback: once the device waited for a frame at least as new
				// as the slot's, it counts as complete (without flags: ignored). With frames in flight a later
				// frame being submitted proves nothing.
				return slot_arrived[i] || RenderingDevice::get_singleton()->get_frames_completed() > slot_submissions[i];
			}
		}
		return true;
	});
	ERR_FAIL_COND_V_MSG(!sampler.is_valid() || !query_buffer.is_valid() || !light_buffer.is_valid() || !point_buffer.is_valid(), false, "AreaShadowAdaptiveRD: GPU resources could not be created.");
	initialized = true;
	return true;
}

void AreaShadowAdaptiveRD::finalize() {
	if (alive) {
		*alive = false; // Readbacks still in flight are dropped on arrival.
		alive.reset();
	}
	trees.clear(); // Tiles back to their sources.
	tree_tiles.clear();
	tile_caps.clear();
	content_hashes.clear();
	settled.clear();
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized()) {
		RID all[] = { reprojection_pipeline, banding_pipeline, sampler, query_buffer, light_buffer, point_buffer, values_buffer };
		for (RID r : all) {
			if (r.is_valid()) {
				rd->free(r);
			}
		}
		for (RID r : flag_buffers) {
			if (r.is_valid()) {
				rd->free(r);
			}
		}
	}
	reprojection_pipeline = RID();
	banding_pipeline = RID();
	sampler = RID();
	query_buffer = RID();
	light_buffer = RID();
	point_buffer = RID();
	values_buffer = RID();
	values_capacity = 0;
	flag_buffers.clear();
	slot_queries.clear();
	slot_flags.clear();
	slot_arrived.clear();
	slot_tokens.clear();
	reprojection_shader.clear();
	banding_shader.clear();
	initialized = false;
}

bool AreaShadowAdaptiveRD::set_reprojection_divisor(uint32_t p_divisor) {
	ERR_FAIL_COND_V_MSG(p_divisor < 1 || p_divisor > 64, false, vformat("Area shadow reprojection divisor %u is invalid (expected 1..64).", p_divisor));
	divisor = p_divisor;
	settled.clear();
	return true;
}

bool AreaShadowAdaptiveRD::set_max_depth(uint32_t p_depth) {
	ERR_FAIL_COND_V_MSG(p_depth < 1 || p_depth > 3, false, vformat("Area shadow adaptive max depth %u is invalid (expected 1..3: 9 x 9 maps at most).", p_depth));
	max_depth = p_depth;
	settled.clear();
	for (auto &kv : trees) {
		kv.second->set_max_depth(max_depth);
	}
	return true;
}

bool AreaShadowAdaptiveRD::_ensure_pipelines() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (!reprojection_pipeline.is_valid()) {
		RID shader = reprojection_shader.version_get_shader(0);
		ERR_FAIL_COND_V_MSG(!shader.is_valid(), false, "Area shadow reprojection shader failed to compile: " + reprojection_shader.get_last_error());
		reprojection_pipeline = rd->compute_pipeline_create(shader);
	}
	if (!banding_pipeline.is_valid()) {
		RID shader = banding_shader.version_get_shader(0);
		ERR_FAIL_COND_V_MSG(!shader.is_valid(), false, "Area shadow banding shader failed to compile: " + banding_shader.get_last_error());
		banding_pipeline = rd->compute_pipeline_create(shader);
	}
	return reprojection_pipeline.is_valid() && banding_pipeline.is_valid();
}

/* Lights */

bool AreaShadowAdaptiveRD::CappedTiles::acquire_tile(uint32_t &r_tile) {
	if (held >= cap || !source || !source->acquire_tile(r_tile)) {
		return false;
	}
	held++;
	return true;
}

void AreaShadowAdaptiveRD::CappedTiles::release_tile(uint32_t p_tile) {
	if (source) {
		source->release_tile(p_tile);
	}
	held -= held > 0 ? 1 : 0;
}

void AreaShadowAdaptiveRD::light_set_tile_cap(uint64_t p_light, uint32_t p_cap) {
	p_cap = std::max(p_cap, 4u);
	tile_caps[p_light] = p_cap;
	auto it = tree_tiles.find(p_light);
	if (it == tree_tiles.end()) {
		return;
	}
	it->second->cap = p_cap;
	// Eviction with hysteresis: a tree over its share by more than EVICTION_SLACK of it gives back its finest
	// quads down to the share, so the tiles go to the lights that now matter more; within the slack it keeps
	// them (importance noise never churns maps).
	auto tree = trees.find(p_light);
	if (tree != trees.end() && float(it->second->get_held()) > float(p_cap) * (1.0f + EVICTION_SLACK) + 4.0f) {
		evictions += tree->second->shrink(p_cap);
	}
}

AreaShadowQuadtree *AreaShadowAdaptiveRD::light_get_tree(uint64_t p_light, AreaShadowQuadtree::TileSource *p_tiles) {
	auto it = trees.find(p_light);
	if (it != trees.end()) {
		return it->second.get();
	}
	std::unique_ptr<CappedTiles> tiles(new CappedTiles(p_tiles));
	auto cap = tile_caps.find(p_light);
	tiles->cap = cap != tile_caps.end() ? cap->second : UINT32_MAX;
	std::unique_ptr<AreaShadowQuadtree> tree(new AreaShadowQuadtree);
	tree->set_max_depth(max_depth);
	tree->set_same_depth_rule(same_depth);
	if (!tree->reset(tiles.get())) {
		return nullptr;
	}
	tree_tiles[p_light] = std::move(tiles);
	AreaShadowQuadtree *ptr = tree.get();
	trees[p_light] = std::move(tree);
	return ptr;
}

bool AreaShadowAdaptiveRD::light_prepare(uint64_t p_light, AreaShadowQuadtree::TileSource *p_tiles, uint64_t p_content_hash, uint32_t p_max_draws, std::vector<AreaShadowAtlas::DrawRequest> &r_draws, std::vector<AreaShadowAtlas::Map> &r_maps, std::vector<uint32_t> *r_cells) {
	AreaShadowQuadtree *tree = light_get_tree(p_light, p_tiles);
	if (!tree) {
		return false;
	}
	auto h = content_hashes.find(p_light);
	if (h != content_hashes.end() && h->second != p_content_hash) {
		tree->mark_all_dirty(); // The light or a caster moved: every map is redrawn.
	}
	content_hashes[p_light] = p_content_hash;
	std::vector<AreaShadowQuadtree::Point> points = tree->get_points();
	for (const AreaShadowQuadtree::Point &p : tree->collect_draws(p_max_draws)) {
		AreaShadowAtlas::DrawRequest d;
		d.light = p_light;
		d.tile = p.tile;
		d.uv = p.uv;
		for (uint32_t i = 0; i < points.size(); i++) {
			if (points[i].tile == p.tile) {
				d.map_index = i;
			}
		}
		r_draws.push_back(d);
	}
	points = tree->get_points(); // Drawn this frame: valid now.
	std::vector<uint32_t> cells = tree->get_point_cells();
	for (size_t i = 0; i < points.size(); i++) {
		const AreaShadowQuadtree::Point &p = points[i];
		if (p.valid) {
			AreaShadowAtlas::Map m;
			m.uv = p.uv;
			m.tile = p.tile;
			m.valid = true;
			m.dirty = p.dirty;
			r_maps.push_back(m);
			if (r_cells) {
				r_cells->push_back(i < cells.size() ? cells[i] : 0u);
			}
		}
	}
	return true;
}

const AreaShadowQuadtree *AreaShadowAdaptiveRD::light_get_tree_or_null(uint64_t p_light) const {
	auto it = trees.find(p_light);
	return it != trees.end() ? it->second.get() : nullptr;
}

void AreaShadowAdaptiveRD::light_release(uint64_t p_light) {
	trees.erase(p_light); // First: the tree gives its tiles back through its source.
	tree_tiles.erase(p_light);
	tile_caps.erase(p_light);
	content_hashes.erase(p_light);
	settled.erase(p_light);
}

void AreaShadowAdaptiveRD::release_lights_except(const std::vector<uint64_t> &p_seen) {
	for (auto it = trees.begin(); it != trees.end();) {
		if (std::find(p_seen.begin(), p_seen.end(), it->first) == p_seen.end()) {
			content_hashes.erase(it->first);
			settled.erase(it->first);
			const uint64_t key = it->first;
			it = trees.erase(it); // First: the tree gives its tiles back through its source.
			tree_tiles.erase(key);
			tile_caps.erase(key);
		} else {
			++it;
		}
	}
	for (auto it = tile_caps.begin(); it != tile_caps.end();) { // Caps of lights that never got a tree.
		it = std::find(p_seen.begin(), p_seen.end(), it->first) == p_seen.end() ? tile_caps.erase(it) : std::next(it);
	}
}

/* Frames */

void AreaShadowAdaptiveRD::begin_frame() {
	ERR_FAIL_COND_MSG(!initialized, "AreaShadowAdaptiveRD::begin_frame: not initialized.");
	frame++;
	ring.begin_frame(frame);
	dispatched_this_frame = false;
	last_begin_submission = RenderingDevice::get_singleton()->get_frames_submitted();
	std::map<uint64_t, std::vector<AreaShadowQuadtree::Result>> results;
	uint64_t data_frame = 0;
	int slot = ring.take_newest_completed(&data_frame);
	last_banding_count = 0;
	if (slot >= 0 && !slot_queries[slot].empty()) {
		const std::vector<IssuedQuery> &issued = slot_queries[slot];
		// The slot's flags arrived when its frame's fence signalled (buffer_get_data_async()): reading them
		// neither submits nor waits.
		readback_count++;
		last_read_submission = slot_submissions[slot];
		if (slot_submissions[slot] >= last_begin_submission || data_frame >= frame) {
			current_frame_read_count++; // Would wait for the frame being built (never expected).
		}
		const std::vector<uint32_t> &flags = slot_flags[slot];
		if (flags.size() == issued.size()) {
			for (size_t i = 0; i < issued.size(); i++) {
				const AreaShadowQuadtree::Query &q = issued[i].query;
				const bool banding = (flags[i] & FLAG_BANDING) != 0;
				results[issued[i].light].push_back({ q.node, q.version, q.parent_test, banding, (flags[i] & FLAG_PENUMBRA) != 0 });
				last_banding_count += banding ? 1 : 0;
			}
		}
		last_result_frame = data_frame;
	}
	std::map<uint64_t, std::vector<const IssuedQuery *>> answered;
	if (!results.empty()) {
		for (const IssuedQuery &iq : slot_queries[slot]) {
			answered[iq.light].push_back(&iq);
		}
	}
	for (auto &kv : trees) {
		kv.second->begin_frame();
		auto rit = results.find(kv.first);
		uint32_t changes = kv.second->apply_results(rit == results.end() ? std::vector<AreaShadowQuadtree::Result>() : rit->second);
		if (rit != results.end()) {
			_update_settled(kv.first, *kv.second, answered[kv.first], changes);
		}
	}
}

void AreaShadowAdaptiveRD::_update_settled(uint64_t p_light, const AreaShadowQuadtree &p_tree, const std::vector<const IssuedQuery *> &p_answered, uint32_t p_changes) {
	settled.erase(p_light);
	if (p_changes != 0 || p_answered.empty()) {
		return;
	}
	// Settled when these answers covered every test the tree would issue now, all for one known state.
	uint64_t state = p_answered[0]->state_hash;
	std::vector<std::pair<uint64_t, bool>> done;
	for (const IssuedQuery *iq : p_answered) {
		if (iq->state_hash != state) {
			return;
		}
		done.push_back(std::make_pair(iq->query.node, iq->query.parent_test));
	}
	if (state == 0) {
		return;
	}
	std::sort(done.begin(), done.end());
	for (const AreaShadowQuadtree::Query &q : p_tree.build_queries(p_answered[0]->can_grow)) {
		if (!std::binary_search(done.begin(), done.end(), std::make_pair(q.node, q.parent_test))) {
			return; // A test not answered yet (a new prune test, or one cut by MAX_QUERIES_PER_FRAME).
		}
	}
	settled[p_light] = state;
}

void AreaShadowAdaptiveRD::set_skip_settled(bool p_enable) {
	skip_settled = p_enable;
	settled.clear();
}

void AreaShadowAdaptiveRD::set_same_depth_rule(bool p_enable) {
	same_depth = p_enable;
	settled.clear();
	for (auto &kv : trees) {
		kv.second->set_same_depth_rule(p_enable);
	}
}

bool AreaShadowAdaptiveRD::is_light_settled(uint64_t p_light, uint64_t p_state_hash) const {
	auto it = settled.find(p_light);
	return it != settled.end() && p_state_hash != 0 && it->second == p_state_hash;
}

// One frame's input of the passes: the lights under test (grid, sample points), the corner points of their
// tested quads (each point once per light: neighbouring quads share corners), and the quads.
struct AreaShadowAdaptiveRD::PassData {
	std::vector<AreaShadowAdaptiveRD::AdaptiveLightData> lights;
	std::vector<AreaShadowAdaptiveRD::PointData> points;
	std::vector<AreaShadowAdaptiveRD::QueryData> queries;
	uint32_t words = 0; // Visibility words of all lights.
	uint32_t cells = 0;
	uint32_t max_cells = 0;

	// Distinct corners of p_queries (at most MAX_VISIBILITY_WORDS * 32 - 1 fit a cell's words).
	static uint32_t count_points(const std::vector<AreaShadowQuadtree::Query> &p_queries) {
		std::set<std::tuple<uint32_t, real_t, real_t>> seen;
		for (const AreaShadowQuadtree::Query &q : p_queries) {
			for (uint32_t c = 0; c < 4; c++) {
				seen.insert(std::make_tuple(q.corner_tile[c], q.corner_uv[c].x, q.corner_uv[c].y));
			}
		}
		return uint32_t(seen.size());
	}

	void add_light(const AreaShadowAdaptiveRD::LightInput &p_light, const AreaShadowAdaptiveRD::AtlasInfo &p_atlas, const AreaShadowAdaptiveRD::GridData &p_grid, const std::vector<AreaShadowQuadtree::Query> &p_queries) {
		AreaShadowAdaptiveRD::AdaptiveLightData l;
		memset(&l, 0, sizeof(l));
		Projection::from_transform(p_light.light_from_view).to_floats(l.light_from_view);
		l.half_size[0] = p_light.size.x * 0.5f;
		l.half_size[1] = p_light.size.y * 0.5f;
		l.depth_scale = p_light.depth_scale;
		l.bias = p_light.bias;
		const uint32_t sub = std::max(p_atlas.subdivision, 1u);
		l.atlas_subdivision = sub;
		l.tile_size = p_atlas.size / sub;
		l.quadrant_size = std::max(l.tile_size / 2, 1u);
		l.point_offset = uint32_t(points.size());
		l.query_offset = uint32_t(queries.size());
		l.query_count = uint32_t(p_queries.size());
		const uint32_t light_index = uint32_t(lights.size());
		std::map<std::tuple<uint32_t, real_t, real_t>, uint32_t> by_tile; // A point: its map and its place.
		for (const AreaShadowQuadtree::Query &q : p_queries) {
			AreaShadowAdaptiveRD::QueryData d;
			memset(&d, 0, sizeof(d));
			d.light = light_index;
			for (uint32_t c = 0; c < 4; c++) {
				const std::tuple<uint32_t, real_t, real_t> point_key(q.corner_tile[c], q.corner_uv[c].x, q.corner_uv[c].y);
				auto it = by_tile.find(point_key);
				if (it == by_tile.end()) {
					AreaShadowAdaptiveRD::PointData pt;
					pt.uv[0] = q.corner_uv[c].x;
					pt.uv[1] = q.corner_uv[c].y;
					pt.tile = q.corner_tile[c];
					pt.pad = 0;
					points.push_back(pt);
					it = by_tile.emplace(point_key, uint32_t(by_tile.size())).first;
				}
				d.corners[c] = it->second;
			}
			queries.push_back(d);
		}
		l.point_count = uint32_t(by_tile.size());
		l.words = (l.point_count + 1 + 31) / 32; // A tree has at most 81 points: 3 words (the caller checks).
		l.grid = p_grid;
		l.grid.offset = words;
		const uint32_t grid_cells = p_grid.size[0] * p_grid.size[1];
		words += grid_cells * l.words;
		cells += grid_cells;
		max_cells = std::max(max_cells, grid_cells);
		lights.push_back(l);
	}
};

bool AreaShadowAdaptiveRD::compute_light_grid(const LightInput &p_light, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, uint32_t p_divisor, GridData &r_grid) {
	memset(&r_grid, 0, sizeof(r_grid));
	ERR_FAIL_COND_V_MSG(p_width == 0 || p_height == 0 || p_divisor == 0, false, vformat("Area shadow reprojection grid: bad view %u x %u or divisor %u.", p_width, p_height, p_divisor));
	const uint32_t budget = std::max((p_width + p_divisor - 1) / p_divisor, 1u) * std::max((p_height + p_divisor - 1) / p_divisor, 1u);
	uint32_t x0 = 0, y0 = 0, x1 = p_width, y1 = p_height;
	uint32_t step = p_divisor;
	const AABB &box = p_light.box;
	if (box.size.x > 0.0f || box.size.y > 0.0f || box.size.z > 0.0f) {
		// The 8 corners in view space; the parts behind the camera plane are clipped off (edges cut at z = -eps).
		const Transform3D view_from_light = p_light.light_from_view.affine_inverse();
		Vector3 c[8];
		for (int i = 0; i < 8; i++) {
			c[i] = view_from_light.xform(box.position + Vector3(box.size.x * real_t(i & 1), box.size.y * real_t((i >> 1) & 1), box.size.z * real_t((i >> 2) & 1)));
		}
		const real_t z_clip = -1e-4f;
		std::vector<Vector3> pts;
		for (int i = 0; i < 8; i++) {
			if (c[i].z <= z_clip) {
				pts.push_back(c[i]);
			}
			for (int bit = 1; bit < 8; bit <<= 1) {
				int j = i | bit;
				if (j == i) {
					continue; // Each edge once: from the corner without the bit.
				}
				if ((c[i].z - z_clip) * (c[j].z - z_clip) < 0.0f) {
					real_t t = (z_clip - c[i].z) / (c[j].z - c[i].z);
					pts.push_back(c[i] + (c[j] - c[i]) * t);
				}
			}
		}
		if (pts.empty()) {
			return false; // Wholly behind the camera.
		}
		real_t lo_x = 1e30f, lo_y = 1e30f, hi_x = -1e30f, hi_y = -1e30f;
		for (const Vector3 &p : pts) {
			Vector3 n = p_clip_from_view.xform(p);
			if (!Math::is_finite(n.x) || !Math::is_finite(n.y)) {
				lo_x = lo_y = -1e30f; // Degenerate: take the whole view.
				hi_x = hi_y = 1e30f;
				break;
			}
			lo_x = std::min(lo_x, n.x);
			hi_x = std::max(hi_x, n.x);
			lo_y = std::min(lo_y, n.y);
			hi_y = std::max(hi_y, n.y);
		}
		auto to_pixel = [](real_t p_ndc, uint32_t p_size, bool p_up) {
			double v = (double(p_ndc) * 0.5 + 0.5) * double(p_size);
			v = p_up ? std::ceil(v) : std::floor(v);
			return uint32_t(std::min(std::max(v, 0.0), double(p_size)));
		};
		x0 = to_pixel(lo_x, p_width, false);
		x1 = to_pixel(hi_x, p_width, true);
		y0 = to_pixel(lo_y, p_height, false);
		y1 = to_pixel(hi_y, p_height, true);
		if (x1 <= x0 || y1 <= y0) {
			return false; // Off-screen.
		}
		// The finest step (>= 1: never finer than full resolution) that keeps the cells within the budget.
		const uint32_t w = x1 - x0, h = y1 - y0;
		step = std::max(uint32_t(std::floor(std::sqrt(double(w) * double(h) / double(budget)))), 1u);
		while (((w + step - 1) / step) * ((h + step - 1) / step) > budget) {
			step++;
		}
	}
	r_grid.origin[0] = x0;
	r_grid.origin[1] = y0;
	r_grid.extent[0] = x1 - x0;
	r_grid.extent[1] = y1 - y0;
	r_grid.step = step;
	r_grid.size[0] = std::max((r_grid.extent[0] + step - 1) / step, 1u);
	r_grid.size[1] = std::max((r_grid.extent[1] + step - 1) / step, 1u);
	return true;
}

struct AreaShadowAdaptiveRD::PassResources {
	RID reprojection_pipeline, banding_pipeline, reprojection_shader, banding_shader, sampler;
	RID depth, atlas, lights, points, queries, values, flags;
	uint32_t width = 0;
	uint32_t height = 0;
};

bool AreaShadowAdaptiveRD::_record_passes(const PassResources &p_res, const PassData &p_pass, const Projection &p_clip_from_view, const String &p_timestamp_prefix) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	rd->buffer_update(p_res.lights, 0, uint32_t(p_pass.lights.size() * sizeof(AreaShadowAdaptiveRD::AdaptiveLightData)), p_pass.lights.data());
	rd->buffer_update(p_res.points, 0, uint32_t(p_pass.points.size() * sizeof(AreaShadowAdaptiveRD::PointData)), p_pass.points.data());
	rd->buffer_update(p_res.queries, 0, uint32_t(p_pass.queries.size() * sizeof(AreaShadowAdaptiveRD::QueryData)), p_pass.queries.data());
	std::vector<RD::Uniform> u1 = {
		RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 0, p_res.depth),
		RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 1, p_res.sampler),
		RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 2, p_res.atlas),
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 3, p_res.lights),
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 4, p_res.values),
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 5, p_res.points),
	};
	RID set1 = rd->uniform_set_create(u1, p_res.reprojection_shader, 0);
	std::vector<RD::Uniform> u2 = {
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, p_res.values),
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, p_res.flags),
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 2, p_res.lights),
		RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 3, p_res.queries),
	};
	RID set2 = rd->uniform_set_create(u2, p_res.banding_shader, 0);
	ERR_FAIL_COND_V_MSG(!set1.is_valid() || !set2.is_valid(), false, "Area shadow reprojection: uniform sets could not be created.");
	AreaShadowAdaptiveRD::ReprojectionPushConstant rpc;
	memset(&rpc, 0, sizeof(rpc));
	p_clip_from_view.inverse().to_floats(rpc.view_from_clip);
	rpc.depth_size[0] = p_res.width;
	rpc.depth_size[1] = p_res.height;
	rpc.max_cells = p_pass.max_cells;
	rpc.light_count = uint32_t(p_pass.lights.size());
	AreaShadowAdaptiveRD::BandingPushConstant bpc;
	memset(&bpc, 0, sizeof(bpc));
	bpc.max_cells = p_pass.max_cells;
	bpc.light_count = uint32_t(p_pass.lights.size());
	rd->buffer_clear(p_res.flags, 0, uint32_t(p_pass.queries.size() * sizeof(uint32_t)));
	RD::ComputeListID list = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(list, p_res.reprojection_pipeline);
	rd->compute_list_bind_uniform_set(list, set1, 0);
	rd->compute_list_set_push_constant(list, &rpc, sizeof(rpc));
	rd->compute_list_dispatch_threads(list, p_pass.max_cells, 1, rpc.light_count);
	if (!p_timestamp_prefix.empty()) {
		rd->capture_timestamp(p_timestamp_prefix + "area_reprojection");
	}
	rd->compute_list_bind_compute_pipeline(list, p_res.banding_pipeline);
	rd->compute_list_bind_uniform_set(list, set2, 0);
	rd->compute_list_set_push_constant(list, &bpc, sizeof(bpc));
	rd->compute_list_dispatch_threads(list, p_pass.max_cells, 1, bpc.light_count);
	if (!p_timestamp_prefix.empty()) {
		rd->capture_timestamp(p_timestamp_prefix + "area_banding");
	}
	rd->compute_list_end();
	rd->free(set1); // Deferred until the frame completes.
	rd->free(set2);
	return true;
}

AreaShadowAdaptiveRD::PassResources AreaShadowAdaptiveRD::_pass_resources(RID p_depth, uint32_t p_width, uint32_t p_height, RID p_atlas, RID p_values, RID p_flags) {
	PassResources r;
	r.reprojection_pipeline = reprojection_pipeline;
	r.banding_pipeline = banding_pipeline;
	r.reprojection_shader = reprojection_shader.version_get_shader(0);
	r.banding_shader = banding_shader.version_get_shader(0);
	r.sampler = sampler;
	r.depth = p_depth;
	r.atlas = p_atlas;
	r.lights = light_buffer;
	r.points = point_buffer;
	r.queries = query_buffer;
	r.values = p_values;
	r.flags = p_flags;
	r.width = p_width;
	r.height = p_height;
	return r;
}

uint32_t AreaShadowAdaptiveRD::dispatch(RID p_depth, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, const AtlasInfo &p_atlas, const std::vector<LightInput> &p_lights, const String &p_timestamp_prefix) {
	ERR_FAIL_COND_V_MSG(!initialized, 0, "AreaShadowAdaptiveRD::dispatch: not initialized.");
	last_query_count = 0;
	if (dispatched_this_frame) {
		extra_dispatch_count++; // Two dispatches in one frame: the second one's slot is read as usual.
	}
	dispatched_this_frame = true;
	if (p_lights.empty() || p_width == 0 || p_height == 0 || !p_depth.is_valid() || !p_atlas.texture.is_valid()) {
		return 0;
	}
	std::vector<IssuedQuery> issued;
	PassData pass;
	last_skipped_count = 0;
	last_offscreen_count = 0;
	last_cell_count = 0;
	last_point_count = 0;
	for (const LightInput &l : p_lights) {
		auto it = trees.find(l.key);
		if (it == trees.end()) {
			continue;
		}
		if (skip_settled && is_light_settled(l.key, l.state_hash)) {
			last_skipped_count++; // Same view, same scene, and its last full round changed nothing.
			continue;
		}
		GridData grid;
		if (!compute_light_grid(l, p_width, p_height, p_clip_from_view, divisor, grid)) {
			last_offscreen_count++; // Its range box is not on screen: nothing to see, nothing to test.
			continue;
		}
		std::vector<AreaShadowQuadtree::Query> queries = it->second->build_queries(l.can_grow);
		if (queries.size() > MAX_QUERIES_PER_FRAME - issued.size()) {
			queries.resize(MAX_QUERIES_PER_FRAME - issued.size()); // The rest is tested on a later frame.
		}
		if (queries.empty()) {
			continue;
		}
		ERR_CONTINUE_MSG(PassData::count_points(queries) >= MAX_VISIBILITY_WORDS * 32, "AreaShadowAdaptiveRD: a light's tested quads have more distinct corners than a cell's visibility words hold.");
		for (const AreaShadowQuadtree::Query &q : queries) {
			IssuedQuery iq;
			iq.light = l.key;
			iq.state_hash = l.state_hash;
			iq.can_grow = l.can_grow;
			iq.query = q;
			issued.push_back(iq);
		}
		pass.add_light(l, p_atlas, grid, queries);
	}
	if (issued.empty()) {
		return 0; // Nothing to test: no shader is compiled for it.
	}
	int slot = ring.acquire_write_slot();
	if (slot < 0) {
		return 0; // Every result buffer is still in flight: test again next frame rather than wait.
	}
	slot_queries[slot].clear();
	slot_flags[slot].clear();
	slot_arrived[slot] = true; // Nothing to wait for unless the passes and the readback are recorded below.
	if (!_ensure_pipelines()) {
		return 0;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	uint32_t need = std::max(pass.words, 1u);
	if (need > values_capacity) {
		if (values_buffer.is_valid()) {
			rd->free(values_buffer);
		}
		values_capacity = std::max(need, values_capacity * 2);
		values_buffer = rd->storage_buffer_create(values_capacity * sizeof(uint32_t));
		rd->set_resource_name(values_buffer, "AreaShadowAdaptiveRD reprojection visibility");
	}
	if (!_record_passes(_pass_resources(p_depth, p_width, p_height, p_atlas.texture, values_buffer, flag_buffers[slot]), pass, p_clip_from_view, p_timestamp_prefix)) {
		return 0;
	}
	// The flags come back without a flush once this frame completes.
	const uint64_t token = ++slot_tokens[slot];
	std::shared_ptr<bool> alive_token = alive;
	slot_arrived[slot] = !rd->buffer_get_data_async(
			flag_buffers[slot], [this, alive_token, slot, token](const std::vector<uint8_t> &p_bytes) {
				if (!*alive_token || slot_tokens[slot] != token) {
					return; // Finalized, or the slot was reused.
				}
				slot_flags[slot].resize(p_bytes.size() / sizeof(uint32_t));
				memcpy(slot_flags[slot].data(), p_bytes.data(), slot_flags[slot].size() * sizeof(uint32_t));
				slot_arrived[slot] = true;
			},
			0, uint32_t(issued.size() * sizeof(uint32_t)));
	last_cell_count = pass.cells;
	last_point_count = uint32_t(pass.points.size());
	slot_queries[slot] = issued;
	slot_submissions[slot] = rd->get_frames_submitted();
	last_query_count = uint32_t(issued.size());
	return last_query_count;
}

std::vector<uint32_t> AreaShadowAdaptiveRD::test_queries_blocking(RID p_depth, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, const AtlasInfo &p_atlas, const LightInput &p_light, const std::vector<AreaShadowQuadtree::Query> &p_queries, std::vector<float> *r_values) {
	ERR_FAIL_COND_V_MSG(!initialized, std::vector<uint32_t>(), "AreaShadowAdaptiveRD::test_queries_blocking: not initialized.");
	ERR_FAIL_COND_V_MSG(p_queries.empty() || p_queries.size() > MAX_QUERIES_PER_FRAME, std::vector<uint32_t>(), vformat("AreaShadowAdaptiveRD::test_queries_blocking: %u queries (expected 1..%u).", uint32_t(p_queries.size()), MAX_QUERIES_PER_FRAME));
	ERR_FAIL_COND_V(!_ensure_pipelines(), std::vector<uint32_t>());
	RenderingDevice *rd = RenderingDevice::get_singleton();
	GridData grid;
	if (!compute_light_grid(p_light, p_width, p_height, p_clip_from_view, divisor, grid)) {
		return std::vector<uint32_t>(p_queries.size(), 0u); // Off-screen: nothing can band.
	}
	ERR_FAIL_COND_V_MSG(PassData::count_points(p_queries) >= MAX_VISIBILITY_WORDS * 32, std::vector<uint32_t>(), vformat("AreaShadowAdaptiveRD::test_queries_blocking: the quads have more than %u distinct corners.", MAX_VISIBILITY_WORDS * 32 - 1));
	PassData pass;
	pass.add_light(p_light, p_atlas, grid, p_queries);
	const uint32_t n = uint32_t(p_queries.size());
	RID values = rd->storage_buffer_create(pass.words * sizeof(uint32_t));
	RID flags = rd->storage_buffer_create(n * sizeof(uint32_t));
	std::vector<uint32_t> out;
	if (_record_passes(_pass_resources(p_depth, p_width, p_height, p_atlas.texture, values, flags), pass, p_clip_from_view, String())) {
		std::vector<uint8_t> fb = rd->buffer_get_data(flags);
		out.resize(n);
		memcpy(out.data(), fb.data(), std::min(fb.size(), out.size() * sizeof(uint32_t)));
		if (r_values) {
			// Each quad's value per cell, as the banding detector forms it: the mean of its corners' bits.
			std::vector<uint8_t> vb = rd->buffer_get_data(values);
			std::vector<uint32_t> words(vb.size() / sizeof(uint32_t));
			memcpy(words.data(), vb.data(), words.size() * sizeof(uint32_t));
			const AdaptiveLightData &l = pass.lights[0];
			const uint32_t cells = grid.size[0] * grid.size[1];
			r_values->assign(size_t(n) * cells, -1.0f);
			for (uint32_t q = 0; q < n && words.size() >= size_t(cells) * l.words; q++) {
				for (uint32_t c = 0; c < cells; c++) {
					const uint32_t *w = &words[size_t(c) * l.words];
					if ((w[0] & 1u) == 0) {
						continue;
					}
					uint32_t seen = 0;
					for (uint32_t k = 0; k < 4; k++) {
						const uint32_t bit = pass.queries[q].corners[k] + 1;
						seen += (w[bit >> 5] >> (bit & 31)) & 1u;
					}
					(*r_values)[size_t(q) * cells + c] = float(seen) * 0.25f;
				}
			}
		}
	}
	rd->free(values);
	rd->free(flags);
	return out;
}
