/**************************************************************************/
/*  area_shadow_atlas.cpp                                                 */
/**************************************************************************/

#include "servers/rendering/renderer_rd/area_lights/area_shadow_atlas.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>

AreaShadowAtlas::AreaShadowAtlas() {
	_reset_tiles();
}

/* Sample pattern */

uint32_t AreaShadowAtlas::get_coordinate_level(real_t p_t) {
	if (p_t == 0.0f || p_t == 1.0f) {
		return 0;
	}
	for (uint32_t level = 1; level <= 8; level++) {
		real_t scaled = p_t * real_t(1u << level);
		if (scaled == std::floor(scaled)) {
			return level;
		}
	}
	return 255;
}

std::vector<Vector2> AreaShadowAtlas::get_grid_samples(uint32_t p_grid) {
	std::vector<Vector2> out;
	if (p_grid == 0) {
		return out;
	}
	if (p_grid == 1) {
		out.push_back(Vector2(0.5f, 0.5f));
		return out;
	}
	struct Entry {
		Vector2 uv;
		uint32_t level;
		uint32_t order;
	};
	std::vector<Entry> entries;
	for (uint32_t j = 0; j < p_grid; j++) {
		for (uint32_t i = 0; i < p_grid; i++) {
			Entry e;
			e.uv = Vector2(real_t(i) / real_t(p_grid - 1), real_t(j) / real_t(p_grid - 1));
			// A point appears at the level of its finer coordinate (corners: 0; edge midpoints and the
			// centre of the first quad: 1; ...).
			e.level = std::max(get_coordinate_level(e.uv.x), get_coordinate_level(e.uv.y));
			e.order = j * p_grid + i;
			entries.push_back(e);
		}
	}
	std::stable_sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) { return a.level < b.level; });
	for (const Entry &e : entries) {
		out.push_back(e.uv);
	}
	return out;
}

std::vector<Vector2> AreaShadowAtlas::get_subdivision_samples(uint32_t p_levels) {
	ERR_FAIL_COND_V_MSG(p_levels > 3, std::vector<Vector2>(), vformat("get_subdivision_samples: %u levels exceed the 9 x 9 maximum (3 levels).", p_levels));
	return get_grid_samples((1u << p_levels) + 1);
}

float AreaShadowAtlas::compute_importance(const AABB &p_world_box, const Projection &p_clip_from_world, const Vector2 &p_light_size) {
	float area = std::max(float(p_light_size.x * p_light_size.y), 1e-4f);
	if (!std::isfinite(area)) {
		area = 1e-4f;
	}
	real_t min_x = 1e30f, min_y = 1e30f, max_x = -1e30f, max_y = -1e30f;
	int behind = 0;
	for (int i = 0; i < 8; i++) {
		Vector3 p = p_world_box.get_endpoint(i);
		Vector4 c = p_clip_from_world.xform(Vector4(p.x, p.y, p.z, 1.0f));
		if (c.w <= 1e-6f) {
			behind++;
			continue;
		}
		real_t x = c.x / c.w;
		real_t y = c.y / c.w;
		min_x = std::min(min_x, x);
		max_x = std::max(max_x, x);
		min_y = std::min(min_y, y);
		max_y = std::max(max_y, y);
	}
	if (behind == 8) {
		return 0.0f;
	} else if (behind > 0) {
		return area; // Reaches behind the camera (the camera may be inside): treat as covering the screen.
	}
	min_x = std::max(min_x, real_t(-1));
	min_y = std::max(min_y, real_t(-1));
	max_x = std::min(max_x, real_t(1));
	max_y = std::min(max_y, real_t(1));
	if (max_x <= min_x || max_y <= min_y) {
		return 0.0f;
	}
	float coverage = float((max_x - min_x) * (max_y - min_y) / 4.0f);
	return coverage * area;
}

AreaShadowAtlas::TileRect AreaShadowAtlas::get_tile_rect(uint32_t p_tile, uint32_t p_atlas_size, uint32_t p_subdivision) {
	TileRect r;
	if (p_subdivision == 0) {
		return r;
	}
	r.size = p_atlas_size / p_subdivision;
	r.x = (p_tile % p_subdivision) * r.size;
	r.y = (p_tile / p_subdivision) * r.size;
	return r;
}

/* Configuration */

void AreaShadowAtlas::_reset_tiles() {
	free_tiles.clear();
	external_tiles.clear();
	configuration++;
	for (uint32_t t = 0; t < subdivision * subdivision; t++) {
		free_tiles.insert(t);
	}
	for (auto &kv : lights) {
		kv.second.maps.clear();
		kv.second.grid = 0;
	}
}

bool AreaShadowAtlas::configure(uint32_t p_size, uint32_t p_subdivision) {
	ERR_FAIL_COND_V_MSG(p_size < 16 || p_size > 16384, false, vformat("Area shadow atlas size %u is invalid (expected 16..16384 pixels).", p_size));
	ERR_FAIL_COND_V_MSG(p_subdivision < 1 || p_subdivision > 64, false, vformat("Area shadow atlas subdivision %u is invalid (expected 1..64 tiles per side).", p_subdivision));
	ERR_FAIL_COND_V_MSG(p_size / p_subdivision < 8, false, vformat("Area shadow atlas tiles would be %u pixels (size %u / subdivision %u); at least 8 are needed.", p_size / p_subdivision, p_size, p_subdivision));
	if (p_size == size && p_subdivision == subdivision) {
		return true;
	}
	size = p_size;
	subdivision = p_subdivision;
	_reset_tiles();
	exhaustion_warned = false;
	return true;
}

bool AreaShadowAtlas::tile_acquire(uint32_t &r_tile) {
	if (free_tiles.empty()) {
		return false;
	}
	r_tile = *free_tiles.begin();
	free_tiles.erase(free_tiles.begin());
	external_tiles.insert(r_tile);
	return true;
}

void AreaShadowAtlas::tile_release(uint32_t p_tile) {
	if (external_tiles.erase(p_tile) != 0) {
		free_tiles.insert(p_tile);
	}
}

/* Per light */

void AreaShadowAtlas::_release_maps(LightState &p_light) {
	for (const Map &m : p_light.maps) {
		free_tiles.insert(m.tile);
	}
	p_light.maps.clear();
	p_light.grid = 0;
}

void AreaShadowAtlas::_set_grid(LightState &p_light, uint32_t p_grid) {
	if (p_grid == p_light.grid) {
		return;
	}
	std::vector<Vector2> uvs = get_grid_samples(p_grid);
	std::vector<Map> kept;
	kept.reserve(uvs.size());
	std::vector<bool> used(p_light.maps.size(), false);
	// Keep the maps whose sample point is in the new set (nested grids keep everything).
	for (const Vector2 &uv : uvs) {
		bool found = false;
		for (size_t i = 0; i < p_light.maps.size(); i++) {
			if (!used[i] && p_light.maps[i].uv == uv) {
				used[i] = true;
				kept.push_back(p_light.maps[i]);
				found = true;
				break;
			}
		}
		if (!found) {
			Map m;
			m.uv = uv;
			m.tile = UINT32_MAX; // Assigned below, once the dropped tiles are free.
			kept.push_back(m);
		}
	}
	for (size_t i = 0; i < p_light.maps.size(); i++) {
		if (!used[i]) {
			free_tiles.insert(p_light.maps[i].tile);
		}
	}
	for (Map &m : kept) {
		if (m.tile != UINT32_MAX) {
			continue;
		}
		ERR_FAIL_COND_MSG(free_tiles.empty(), "AreaShadowAtlas: internal error, no free tile for a planned map.");
		m.tile = *free_tiles.begin();
		free_tiles.erase(free_tiles.begin());
		m.valid = false;
		m.dirty = true;
	}
	p_light.maps = kept;
	p_light.grid = p_grid;
}

std::vector<uint32_t> AreaShadowAtlas::_allowed_grids(uint32_t p_requested) {
	std::vector<uint32_t> out;
	if (p_requested <= 1) {
		out.push_back(1);
		return out;
	}
	const uint32_t nested[4] = { 2, 3, 5, 9 };
	for (uint32_t g : nested) {
		if (g < p_requested) {
			out.push_back(g);
		}
	}
	out.push_back(p_requested);
	return out;
}

void AreaShadowAtlas::begin_frame() {
	frame++;
	in_frame = true;
	draws.clear();
	frame_evictions = 0;
}

void AreaShadowAtlas::light_set(uint64_t p_light, uint32_t p_grid, float p_importance, uint64_t p_content_hash) {
	LightState &s = lights[p_light];
	s.requested_grid = std::min(std::max(p_grid, 1u), MAX_GRID); // 1: one centre map (PCSS baseline).
	s.importance = (std::isfinite(p_importance) && p_importance > 0.0f) ? p_importance : 0.0f;
	if (!s.hash_known || s.content_hash != p_content_hash) {
		for (Map &m : s.maps) {
			m.dirty = true;
		}
	}
	s.content_hash = p_content_hash;
	s.hash_known = true;
	s.last_seen_frame = frame;
}

void AreaShadowAtlas::light_release(uint64_t p_light) {
	auto it = lights.find(p_light);
	if (it == lights.end()) {
		return;
	}
	_release_maps(it->second);
	lights.erase(it);
}

std::vector<AreaShadowAtlas::Map> AreaShadowAtlas::light_get_maps(uint64_t p_light) const {
	auto it = lights.find(p_light);
	return it == lights.end() ? std::vector<Map>() : it->second.maps;
}

uint32_t AreaShadowAtlas::light_get_grid(uint64_t p_light) const {
	auto it = lights.find(p_light);
	return it == lights.end() ? 0 : it->second.grid;
}

uint32_t AreaShadowAtlas::light_get_tile_count(uint64_t p_light) const {
	auto it = lights.find(p_light);
	return it == lights.end() ? 0 : uint32_t(it->second.maps.size());
}

/* Frame */

void AreaShadowAtlas::end_frame() {
	if (!in_frame) {
		begin_frame();
	}
	// Lights not set this frame (culled, hidden, shadows off) give their tiles back.
	std::vector<uint64_t> gone;
	std::vector<uint64_t> visible;
	for (auto &kv : lights) {
		if (kv.second.last_seen_frame != frame) {
			gone.push_back(kv.first);
		} else {
			visible.push_back(kv.first);
		}
	}
	for (uint64_t id : gone) {
		light_release(id);
	}
	std::stable_sort(visible.begin(), visible.end(), [this](uint64_t a, uint64_t b) {
		return lights[a].importance > lights[b].importance;
	});
	_share_tiles(visible);
	_build_draws(visible);
	in_frame = false;
}

void AreaShadowAtlas::_share_tiles(const std::vector<uint64_t> &p_visible) {
	const uint32_t total = get_tile_count() - std::min(get_tile_count(), uint32_t(external_tiles.size())); // Single tiles (ADAPTIVE) are taken.
	struct Plan {
		LightState *s = nullptr;
		std::vector<uint32_t> allowed;
		int index = -1; // Into allowed; -1: fallback grid (0 or 1).
		uint32_t fallback_grid = 0;
		uint32_t target = 0; // Target grid.
		uint32_t final_grid = 0;
	};
	std::vector<Plan> plans(p_visible.size());
	uint32_t budget = total;
	exhausted_this_frame = false;
	uint32_t starved = 0;
	// 1. Minimums, most important first: the four corners each; the rest degrade (centre map, then none).
	for (size_t i = 0; i < p_visible.size(); i++) {
		Plan &p = plans[i];
		p.s = &lights[p_visible[i]];
		p.allowed = _allowed_grids(p.s->requested_grid);
		uint32_t min_tiles = p.allowed[0] * p.allowed[0];
		if (budget >= min_tiles) {
			p.index = 0;
			budget -= min_tiles;
		}
	}
	for (Plan &p : plans) {
		if (p.index < 0) {
			starved++;
			if (budget >= 1) {
				p.fallback_grid = 1;
				budget -= 1;
			}
		}
	}
	if (starved > 0) {
		exhausted_this_frame = true;
		if (!exhaustion_warned) {
			exhaustion_warned = true;
			exhaustion_warnings++;
			WARN_PRINT(vformat("Area shadow atlas exhausted: %u shadowed area lights are visible but the atlas has %u tiles (%u x %u); %u of the least important lights fall back to one centre map (hard shadow) or no shadow. Raise the subdivision with area_shadow_atlas_set_size().",
					uint32_t(p_visible.size()), total, subdivision, subdivision, starved));
		}
	}
	// 2. Proportional share: repeatedly give the next grid level to the light with the fewest tiles per
	// unit of importance whose next level still fits.
	while (true) {
		int best = -1;
		double best_key = 0.0;
		for (size_t i = 0; i < plans.size(); i++) {
			const Plan &p = plans[i];
			if (p.index < 0 || p.index + 1 >= int(p.allowed.size())) {
				continue;
			}
			uint32_t cur = p.allowed[p.index] * p.allowed[p.index];
			uint32_t next = p.allowed[p.index + 1] * p.allowed[p.index + 1];
			if (next - cur > budget) {
				continue;
			}
			double key = double(cur) / std::max(double(p.s->importance), 1e-9);
			if (best < 0 || key < best_key) {
				best = int(i);
				best_key = key;
			}
		}
		if (best < 0) {
			break;
		}
		Plan &p = plans[best];
		budget -= p.allowed[p.index + 1] * p.allowed[p.index + 1] - p.allowed[p.index] * p.allowed[p.index];
		p.index++;
	}
	// 3. Hysteresis: keep the current grid while it is close to the target (no ping-pong). A light whose
	// target is the grid it asked for is not held below it (area_shadow_grid 6 after 5 gives 36 maps).
	uint32_t final_sum = 0;
	for (Plan &p : plans) {
		p.target = p.index >= 0 ? p.allowed[p.index] : p.fallback_grid;
		p.final_grid = p.target;
		uint32_t cur = p.s->grid;
		bool cur_allowed = std::find(p.allowed.begin(), p.allowed.end(), cur) != p.allowed.end();
		bool full_request = p.target == p.s->requested_grid && cur < p.target;
		if (p.index >= 0 && cur_allowed && !full_request) {
			float t = float(p.target * p.target);
			float c = float(cur * cur);
			if (c <= t * (1.0f + hysteresis) && c * (1.0f + hysteresis) >= t) {
				p.final_grid = cur;
			}
		}
		final_sum += p.final_grid * p.final_grid;
	}
	for (size_t i = plans.size(); i-- > 0 && final_sum > total;) { // Least important first.
		Plan &p = plans[i];
		if (p.final_grid > p.target) {
			final_sum -= p.final_grid * p.final_grid - p.target * p.target;
			p.final_grid = p.target;
		}
	}
	// 4. Shrinks. Evicting tiles from a light that stays visible is capped per frame, except what lights
	// below their minimum need.
	uint32_t min_need = 0;
	for (const Plan &p : plans) {
		uint32_t want = std::min(p.final_grid * p.final_grid, MIN_GRID * MIN_GRID);
		uint32_t have = p.s->grid * p.s->grid;
		if (have < want) {
			min_need += want - have;
		}
	}
	for (size_t i = plans.size(); i-- > 0;) { // Least important lights give first.
		Plan &p = plans[i];
		uint32_t cur = p.s->grid;
		if (p.final_grid >= cur) {
			continue;
		}
		bool forced = cur > p.s->requested_grid || get_free_tile_count() < min_need;
		if (!forced) {
			// Step down as far toward the target as the eviction budget allows; at least one level per
			// frame so a light far above its share always converges.
			std::vector<uint32_t> options = p.allowed;
			options.insert(options.begin(), 1);
			uint32_t chosen = cur;
			for (size_t k = options.size(); k-- > 0;) {
				uint32_t g = options[k];
				if (g >= cur || g < p.final_grid) {
					continue;
				}
				bool fits = frame_evictions + (cur * cur - g * g) <= max_evictions_per_frame;
				if (fits || (chosen == cur && frame_evictions == 0)) {
					chosen = g;
				}
				if (!fits) {
					break;
				}
			}
			p.final_grid = chosen;
			if (chosen == cur) {
				continue; // Postponed to a later frame.
			}
		}
		uint32_t amount = cur * cur - p.final_grid * p.final_grid;
		_set_grid(*p.s, p.final_grid);
		frame_evictions += amount;
	}
	// 5. Growth from the free tiles: lights below their minimum first, then by importance.
	for (int pass = 0; pass < 2; pass++) {
		for (Plan &p : plans) {
			uint32_t cur = p.s->grid;
			bool below_min = cur * cur < std::min(p.final_grid * p.final_grid, MIN_GRID * MIN_GRID);
			if ((pass == 0) != below_min || p.final_grid <= cur) {
				continue;
			}
			// Largest allowed grid <= final that fits in the free tiles.
			std::vector<uint32_t> options = p.allowed;
			options.insert(options.begin(), 1);
			uint32_t chosen = cur;
			for (uint32_t g : options) {
				if (g > p.final_grid || g <= cur) {
					continue;
				}
				if (g * g - cur * cur <= get_free_tile_count()) {
					chosen = g;
				}
			}
			if (chosen != cur) {
				_set_grid(*p.s, chosen);
			}
		}
	}
}

void AreaShadowAtlas::_build_draws(const std::vector<uint64_t> &p_visible) {
	std::vector<uint64_t> order = p_visible;
	auto has_invalid = [this](uint64_t id) {
		for (const Map &m : lights[id].maps) {
			if (!m.valid) {
				return true;
			}
		}
		return false;
	};
	// Maps never drawn first (they are not shown yet), then the least recently drawn light, then importance.
	std::stable_sort(order.begin(), order.end(), [&](uint64_t a, uint64_t b) {
		bool ia = has_invalid(a), ib = has_invalid(b);
		if (ia != ib) {
			return ia;
		}
		return lights[a].last_draw_frame < lights[b].last_draw_frame;
	});
	for (uint64_t id : order) {
		LightState &s = lights[id];
		bool drew = false;
		for (uint32_t i = 0; i < s.maps.size() && draws.size() < max_draws_per_frame; i++) {
			Map &m = s.maps[i];
			if (!m.dirty) {
				continue;
			}
			DrawRequest d;
			d.light = id;
			d.map_index = i;
			d.tile = m.tile;
			d.uv = m.uv;
			draws.push_back(d);
			m.dirty = false;
			m.valid = true;
			drew = true;
		}
		if (drew) {
			s.last_draw_frame = frame;
		}
	}
	total_draws += draws.size();
}
