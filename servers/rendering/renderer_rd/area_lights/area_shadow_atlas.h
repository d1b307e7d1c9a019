/**************************************************************************/
/*  area_shadow_atlas.h                                                   */
/**************************************************************************/
/* godot-area: the tile allocator of the area-light shadow atlas (thesis  */
/* sections 6.1 and 6.5), GPU-free so it is unit-testable. The GPU side   */
/* (texture, depth passes) is AreaShadowRendererRD.                       */
/*                                                                        */
/* The atlas is s x s square tiles; each tile holds the shadow map of ONE */
/* sample point on one area light. Tiles are handed out SCATTERED (any    */
/* free tile, lowest index first) and every light keeps its own list of   */
/* (sample uv, tile) maps, so no fragmentation can occur.                 */
/*                                                                        */
/* Per frame: begin_frame(); light_set() for every visible shadowed area */
/* light; end_frame() releases lights not seen this frame, shares the     */
/* tiles fairly (importance-proportional, hysteresis, bounded evictions,  */
/* a minimum per light) and lists the maps to (re)draw, capped per frame. */
/* Maps are redrawn only when new or when the light's content hash (light */
/* transform and parameters, casters in its range) changed. A map that    */
/* was never drawn is never handed to the shader (no garbage reads).      */

#pragma once

#include "core/math/aabb.h"
#include "core/math/projection.h"
#include "core/math/vector2.h"

#include <cstdint>
#include <map>
#include <set>
#include <vector>

class AreaShadowAtlas {
public:
	/* Definition */

	static constexpr uint32_t MIN_GRID = 2; // 2 x 2 = the four corners.
	static constexpr uint32_t MAX_GRID = 9; // 9 x 9 = 81 maps.
	static constexpr uint32_t MAX_MAPS = MAX_GRID * MAX_GRID;
	static constexpr uint32_t DEFAULT_SIZE = 4096;
	static constexpr uint32_t DEFAULT_SUBDIVISION = 16; // 256 tiles of 256 px.
	static constexpr uint32_t DEFAULT_MAX_DRAWS_PER_FRAME = 512; // As Godot's shadow update cap.

	// One shadow map of a light: the sample point (canonical [0,1]^2 on the rectangle, (0,0) = local
	// (-a/2, -b/2)) and the tile it lives in. valid: drawn at least once (the shader may read it);
	// dirty: must be (re)drawn.
	struct Map {
		Vector2 uv;
		uint32_t tile = 0;
		bool valid = false;
		bool dirty = true;
	};

	// One map to render this frame.
	struct DrawRequest {
		uint64_t light = 0;
		uint32_t map_index = 0; // Index into light_get_maps(light).
		uint32_t tile = 0;
		Vector2 uv;
	};

	// Tile rectangle in pixels.
	struct TileRect {
		uint32_t x = 0;
		uint32_t y = 0;
		uint32_t size = 0;
	};

private:
	/* Private Members */

	struct LightState {
		uint32_t requested_grid = 3; // User's grid (area_shadow_grid).
		uint32_t grid = 0; // Grid the maps form now; 1 = centre only (exhaustion fallback), 0 = none.
		float importance = 0.0f;
		uint64_t content_hash = 0;
		bool hash_known = false;
		uint64_t last_seen_frame = 0;
		uint64_t last_draw_frame = 0;
		std::vector<Map> maps;
	};

	uint32_t size = DEFAULT_SIZE;
	uint32_t subdivision = DEFAULT_SUBDIVISION;
	uint32_t max_draws_per_frame = DEFAULT_MAX_DRAWS_PER_FRAME;
	uint32_t max_evictions_per_frame = 32; // Tiles taken from still-visible lights per frame (minimums excepted).
	float hysteresis = 0.5f; // Keep the current share while it is within [target / (1 + h), target * (1 + h)].

	std::set<uint32_t> free_tiles;
	std::set<uint32_t> external_tiles; // Handed out one by one (ADAPTIVE quadtrees), outside the sharing.
	uint64_t configuration = 1; // Bumped whenever every tile is taken back (configure()).
	std::map<uint64_t, LightState> lights;
	std::vector<DrawRequest> draws;
	uint64_t frame = 0;
	bool in_frame = false;
	uint32_t frame_evictions = 0;
	uint64_t total_draws = 0;
	uint32_t exhaustion_warnings = 0;
	bool exhaustion_warned = false;
	bool exhausted_this_frame = false;

	void _reset_tiles();
	void _release_maps(LightState &p_light);
	void _set_grid(LightState &p_light, uint32_t p_grid);
	static std::vector<uint32_t> _allowed_grids(uint32_t p_requested);
	void _share_tiles(const std::vector<uint64_t> &p_visible);
	void _build_draws(const std::vector<uint64_t> &p_visible);

public:
	/* Public Methods */

	// Sample points of a regular p_grid x p_grid grid on [0,1]^2 in the subdivision order of
	// Schwarzler et al. (thesis section 6.1, Fig. 6.2): the four corners, then the edge midpoints and
	// the quad centres of each dyadic level, level by level; points that are on no dyadic level (grids
	// other than 2^k + 1) come last, row by row. p_grid == 1 gives the centre. Grids 2, 3, 5, 9 are
	// nested: each is a prefix-free subset of the next, so growing keeps every map already drawn.
	static std::vector<Vector2> get_grid_samples(uint32_t p_grid);
	// The 2^p_levels + 1 grid of p_levels subdivision steps (0: the corners, 1: 9 points, ...).
	static std::vector<Vector2> get_subdivision_samples(uint32_t p_levels);
	// Dyadic subdivision level of a coordinate on [0,1] (0 for 0 and 1, 1 for 1/2, 2 for 1/4 and 3/4, ...,
	// 255 when not dyadic up to 1/256).
	static uint32_t get_coordinate_level(real_t p_t);

	// Importance heuristic for fair sharing (thesis section 6.5): the fraction of the screen covered by the
	// projected light influence box p_world_box (clip_from_world: OpenGL-style clip space, w > 0 in front),
	// times the light's area in m^2 (at least 1e-4). A box reaching behind the camera covers the screen.
	static float compute_importance(const AABB &p_world_box, const Projection &p_clip_from_world, const Vector2 &p_light_size);

	// Pixel rectangle of a tile (row-major tile index).
	static TileRect get_tile_rect(uint32_t p_tile, uint32_t p_atlas_size, uint32_t p_subdivision);

	// Atlas size in pixels (>= 16) and tiles per side (1..64, at most size / 8 pixels per tile). Frees
	// every map (all lights redraw). Returns false and keeps the old values on bad input.
	bool configure(uint32_t p_size, uint32_t p_subdivision);
	uint32_t get_size() const { return size; }
	uint32_t get_subdivision() const { return subdivision; }
	uint32_t get_tile_count() const { return subdivision * subdivision; }
	uint32_t get_tile_size() const { return size / subdivision; }
	uint32_t get_free_tile_count() const { return uint32_t(free_tiles.size()); }

	// Single tiles for ADAPTIVE lights (AreaShadowQuadtree points, via AreaShadowAdaptiveRD::AtlasTiles); the
	// fair sharing of the grid lights counts them as taken. configure() takes them back too: holders must
	// drop theirs when get_configuration() changes (tile_release ignores tiles it did not hand out).
	bool tile_acquire(uint32_t &r_tile);
	void tile_release(uint32_t p_tile);
	uint32_t get_external_tile_count() const { return uint32_t(external_tiles.size()); }
	uint64_t get_configuration() const { return configuration; }

	void set_max_draws_per_frame(uint32_t p_max) { max_draws_per_frame = p_max; }
	uint32_t get_max_draws_per_frame() const { return max_draws_per_frame; }
	void set_max_evictions_per_frame(uint32_t p_max) { max_evictions_per_frame = p_max; }
	void set_hysteresis(float p_hysteresis) { hysteresis = p_hysteresis < 0.0f ? 0.0f : p_hysteresis; }

	void begin_frame();
	// A visible, shadowed area light this frame. p_grid: requested grid (clamped to 1..9; 1 = one centre
	// map, the PCSS baseline); p_importance
	// >= 0; p_content_hash changes whenever its maps must be redrawn.
	void light_set(uint64_t p_light, uint32_t p_grid, float p_importance, uint64_t p_content_hash);
	// Releases lights not set this frame, shares the tiles and lists the draws (get_draws()). The
	// listed maps count as drawn from here on: the caller must render every one of them this frame.
	void end_frame();
	const std::vector<DrawRequest> &get_draws() const { return draws; }

	// Frees a light's tiles now (light freed or shadows disabled).
	void light_release(uint64_t p_light);
	bool has_light(uint64_t p_light) const { return lights.count(p_light) != 0; }
	// The light's maps (empty if unknown). Use only maps with valid == true.
	std::vector<Map> light_get_maps(uint64_t p_light) const;
	// Grid the light's maps form (0: none, 1: centre only).
	uint32_t light_get_grid(uint64_t p_light) const;
	uint32_t light_get_tile_count(uint64_t p_light) const;

	uint32_t get_frame_evictions() const { return frame_evictions; }
	uint64_t get_total_draws() const { return total_draws; }
	uint32_t get_exhaustion_warning_count() const { return exhaustion_warnings; }
	bool is_exhausted() const { return exhausted_this_frame; }

	AreaShadowAtlas();
};
