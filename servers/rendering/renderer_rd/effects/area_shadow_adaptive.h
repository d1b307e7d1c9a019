/**************************************************************************/
/*  area_shadow_adaptive.h                                                */
/**************************************************************************/
/* godot-area: GPU side of adaptive area-light shadows (thesis 6.3,       */
/* Algorithm 1, spread over frames without a CPU stall).                  */
/*                                                                        */
/* Per frame, for every ADAPTIVE light: begin_frame() reads the banding   */
/* flags of the newest COMPLETED frame from a ring of GPU buffers         */
/* (AreaShadowReadbackRing) and applies them to the light's quadtree      */
/* (AreaShadowQuadtree: expand on banding, prune idle quads); the caller  */
/* draws the tree's dirty points into the atlas and renders the scene;    */
/* then dispatch() records the reprojection pass (per light and cell of   */
/* the screen rectangle of its range box, at a per-light step that gives  */
/* it at most the pixel budget of the whole view at 1/divisor, never      */
/* finer than full resolution: one visibility bit per distinct corner     */
/* point of the light's tested quads; neighbouring quads share corners,   */
/* so each map is read once per cell; shaders/                            */
/* area_shadow_reprojection.glsl) and the banding detector (each quad's   */
/* value = mean of its corners' bits; shaders/area_shadow_banding.glsl)   */
/* writing one flag word per quad into this frame's ring buffer. Nothing  */
/* waits for the frame being built.                                       */
/*                                                                        */
/* The two compute shaders are compiled on the first dispatch with work,  */
/* so a scene without an ADAPTIVE light never compiles them.              */
/*                                                                        */
/* Settled lights: when a full round of a light's tests changed nothing   */
/* for one LightInput::state_hash (camera, scene, light, atlas), the      */
/* light is not tested again until that hash changes (set_skip_settled).  */
/*                                                                        */
/* Readback: each frame's flags are copied back with                     */
/* RenderingDevice::buffer_get_data_async() (no flush): they arrive when  */
/* the frame's fence has signalled, and a ring slot counts as complete    */
/* only then, so begin_frame() reads host memory and never submits or     */
/* waits. With this engine's one frame in flight, that is one frame late. */

#pragma once

#include "core/math/aabb.h"
#include "core/math/projection.h"
#include "servers/rendering/renderer_rd/area_lights/area_shadow_atlas.h"
#include "servers/rendering/renderer_rd/area_lights/area_shadow_quadtree.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/area_shadow_readback_ring.h"
#include "servers/rendering/renderer_scene_render.h"

#include <map>
#include <memory>
#include <vector>

class AreaShadowAdaptiveRD {
public:
	/* Definition */

	static constexpr uint32_t DEFAULT_REPROJECTION_DIVISOR = 8; // Thesis 6.4: 1/8 of the viewport.
	static constexpr uint32_t MAX_QUERIES_PER_FRAME = 256;
	static constexpr const char *SETTING_REPROJECTION_DIVISOR = "rendering/lights_and_shadows/area_shadow_reprojection_divisor";
	static constexpr const char *SETTING_MAX_DEPTH = "rendering/lights_and_shadows/area_shadow_adaptive_max_depth";
	// HEURISTIC's assumed occluder distance as a fraction of the light's range (thesis 6.5: the estimate is
	// for lighting artists to tune). Larger = occluders assumed nearer the receivers = narrower penumbrae.
	static constexpr const char *SETTING_HEURISTIC_OCCLUDER_FRACTION = "rendering/lights_and_shadows/area_shadow_heuristic_occluder_fraction";
	static constexpr float DEFAULT_HEURISTIC_OCCLUDER_FRACTION = 0.25f;
	static constexpr uint32_t MAX_GPU_DEPTH = 3; // 9 x 9 maps: the AreaShadowData packing's limit.
	static constexpr uint32_t MAX_VISIBILITY_WORDS = 3; // AREA_SHADOW_ADAPTIVE_MAX_WORDS: 95 points per light.
	// Bits of a query's flag word (shaders/area_shadow_banding.glsl).
	static constexpr uint32_t FLAG_BANDING = 1;
	static constexpr uint32_t FLAG_PENUMBRA = 2; // Some cell is in the quad's penumbra (0 < v < 1).

	// Mirrors of shaders/area_shadow_adaptive_inc.glsl (std430).
	// One light's reprojection grid. Cell (x, y) samples the depth pixel origin + (x, y) * step + step / 2
	// (clamped to origin + extent - 1); its visibility words start at offset + (y * size.x + x) * words.
	struct GridData { // 32 bytes.
		uint32_t origin[2]; // Depth pixels.
		uint32_t size[2]; // Cells.
		uint32_t step; // Depth pixels per cell (1 = full resolution).
		uint32_t offset; // First visibility word of the light.
		uint32_t extent[2]; // Depth pixels covered (the rectangle).
	};
	static_assert(sizeof(GridData) == 32, "GridData must match shaders/area_shadow_adaptive_inc.glsl.");

	struct AdaptiveLightData { // 144 bytes: one light under test.
		float light_from_view[16];
		float half_size[2];
		float depth_scale;
		float bias;
		uint32_t atlas_subdivision;
		uint32_t quadrant_size;
		uint32_t tile_size;
		uint32_t point_offset; // First PointData.
		uint32_t point_count; // The corners of its tested quads, each once.
		uint32_t words; // Visibility words per cell: bit 0 receiver, bit p + 1 point p (<= MAX_VISIBILITY_WORDS).
		uint32_t query_offset; // First QueryData.
		uint32_t query_count;
		GridData grid;
	};
	static_assert(sizeof(AdaptiveLightData) == 144, "AdaptiveLightData must match shaders/area_shadow_adaptive_inc.glsl.");

	struct PointData { // 16 bytes.
		float uv[2];
		uint32_t tile;
		uint32_t pad;
	};
	static_assert(sizeof(PointData) == 16, "PointData must match shaders/area_shadow_adaptive_inc.glsl.");

	struct QueryData { // 32 bytes: one tested quad.
		uint32_t corners[4]; // Indices into its light's points.
		uint32_t light; // Index into the frame's AdaptiveLightData.
		uint32_t pad[3];
	};
	static_assert(sizeof(QueryData) == 32, "QueryData must match shaders/area_shadow_adaptive_inc.glsl.");

	struct ReprojectionPushConstant {
		float view_from_clip[16];
		uint32_t depth_size[2];
		uint32_t max_cells; // Largest size.x * size.y of the lights (dispatch x).
		uint32_t light_count;
		uint32_t pad[4];
	};
	static_assert(sizeof(ReprojectionPushConstant) == 96, "Push constant must match shaders/area_shadow_reprojection.glsl.");

	struct BandingPushConstant {
		uint32_t max_cells;
		uint32_t light_count;
		uint32_t pad[2];
	};

	// What dispatch() needs of one ADAPTIVE light this frame.
	struct LightInput {
		uint64_t key = 0;
		Transform3D light_from_view; // Orthonormal.
		Vector2 size;
		float depth_scale = 1.0f; // 1 / (range + diagonal), as the atlas.
		float bias = 0.02f; // shadow_bias.
		bool can_grow = true; // false: the atlas has no tile for a split (no expansion tests, prune tests only).
		// The light's range box in light space (light_get_aabb()): its tests only cover the box's screen
		// rectangle, at up to the whole view's pixel budget. Zero size: the whole view at 1/divisor.
		AABB box;
		// Everything the light's tests depend on (camera, light, casters and receivers, atlas); 0 = unknown.
		// A light whose tests all came back without a change for this state is settled: it is not tested
		// again until the state changes (set_skip_settled()).
		uint64_t state_hash = 0;
	};

	// Tiles of an AreaShadowAtlas for a light's quadtree (AreaShadowAtlas::tile_acquire/tile_release).
	// When the atlas' get_configuration() changes, release the trees (light_release) and start again.
	class AtlasTiles : public AreaShadowQuadtree::TileSource {
		AreaShadowAtlas *atlas = nullptr;

	public:
		bool acquire_tile(uint32_t &r_tile) override { return atlas && atlas->tile_acquire(r_tile); }
		void release_tile(uint32_t p_tile) override {
			if (atlas) {
				atlas->tile_release(p_tile);
			}
		}
		explicit AtlasTiles(AreaShadowAtlas *p_atlas) :
				atlas(p_atlas) {}
	};

	// The atlas layout for the lookups.
	struct AtlasInfo {
		RID texture;
		uint32_t size = 0;
		uint32_t subdivision = 1;
	};

private:
	/* Private Members */

	struct IssuedQuery {
		uint64_t light = 0;
		uint64_t state_hash = 0;
		bool can_grow = true;
		AreaShadowQuadtree::Query query;
	};

	ShaderRD reprojection_shader;
	ShaderRD banding_shader;
	RID reprojection_pipeline;
	RID banding_pipeline;
	RID sampler;
	RID query_buffer; // QueryData[MAX_QUERIES_PER_FRAME].
	RID light_buffer; // AdaptiveLightData[MAX_QUERIES_PER_FRAME] (a light has at least one query).
	RID point_buffer; // PointData[4 * MAX_QUERIES_PER_FRAME].
	RID values_buffer; // Visibility words per (light, cell).
	uint32_t values_capacity = 0; // Words.
	std::vector<RID> flag_buffers; // One per ring slot: uint per query.
	std::vector<std::vector<IssuedQuery>> slot_queries;
	std::vector<uint64_t> slot_submissions; // RenderingDevice::get_frames_submitted() when recorded.
	std::vector<std::vector<uint32_t>> slot_flags; // Delivered by RenderingDevice::buffer_get_data_async().
	std::vector<bool> slot_arrived;
	std::vector<uint64_t> slot_tokens; // Bumped per write: a late delivery for a reused slot is ignored.
	std::shared_ptr<bool> alive; // false after finalize(): deliveries still in flight are dropped.
	AreaShadowReadbackRing ring;
	// Each tree's tiles go through a capped source (fair sharing between trees, light_set_tile_cap()).
	// Declared before the trees, so they outlive them (a tree gives its tiles back when destroyed).
	class CappedTiles : public AreaShadowQuadtree::TileSource {
		AreaShadowQuadtree::TileSource *source = nullptr;
		uint32_t held = 0;

	public:
		uint32_t cap = UINT32_MAX;
		bool acquire_tile(uint32_t &r_tile) override;
		void release_tile(uint32_t p_tile) override;
		uint32_t get_held() const { return held; }
		explicit CappedTiles(AreaShadowQuadtree::TileSource *p_source) :
				source(p_source) {}
	};
	std::map<uint64_t, std::unique_ptr<CappedTiles>> tree_tiles;
	std::map<uint64_t, uint32_t> tile_caps; // Light -> the most tiles its tree may hold.
	uint64_t evictions = 0;
	std::map<uint64_t, std::unique_ptr<AreaShadowQuadtree>> trees;
	std::map<uint64_t, uint64_t> content_hashes;
	std::map<uint64_t, uint64_t> settled; // Light -> state hash its last complete round of tests left unchanged.
	bool skip_settled = true;
	bool same_depth = true;
	uint32_t last_skipped_count = 0;
	uint32_t divisor = DEFAULT_REPROJECTION_DIVISOR;
	uint32_t max_depth = AreaShadowQuadtree::DEFAULT_MAX_DEPTH;
	uint64_t frame = 0;
	uint32_t last_query_count = 0;
	uint32_t last_cell_count = 0;
	uint32_t last_point_count = 0;
	uint32_t last_offscreen_count = 0;
	uint32_t last_banding_count = 0;
	uint64_t last_result_frame = 0;
	// No-stall instrumentation (begin_frame()).
	uint64_t readback_count = 0;
	uint64_t current_frame_read_count = 0; // Reads of data recorded in a submission not complete at begin_frame(): must stay 0.
	uint64_t last_read_submission = 0; // Submission that recorded the last data read.
	uint64_t last_begin_submission = 0; // RenderingDevice::get_frames_submitted() at the last begin_frame().
	bool dispatched_this_frame = false;
	uint64_t extra_dispatch_count = 0; // dispatch() twice without begin_frame() in between.
	bool initialized = false;

	struct PassData; // One frame's lights, points and quads (area_shadow_adaptive.cpp).
	struct PassResources; // The GPU objects the two passes bind.
	PassResources _pass_resources(RID p_depth, uint32_t p_width, uint32_t p_height, RID p_atlas, RID p_values, RID p_flags);
	static bool _record_passes(const PassResources &p_res, const PassData &p_pass, const Projection &p_clip_from_view, const String &p_timestamp_prefix);
	bool _ensure_pipelines();
	void _update_settled(uint64_t p_light, const AreaShadowQuadtree &p_tree, const std::vector<const IssuedQuery *> &p_answered, uint32_t p_changes);

public:
	/* Public Methods */

	bool initialize(uint32_t p_ring_slots = AreaShadowReadbackRing::DEFAULT_SLOTS);
	void finalize();
	bool is_initialized() const { return initialized; }

	// Reprojection budget: each light gets at most as many cells as the whole view at 1/p_divisor
	// (1..64, default 8), spread over its range box's screen rectangle, never finer than full resolution.
	bool set_reprojection_divisor(uint32_t p_divisor);
	uint32_t get_reprojection_divisor() const { return divisor; }
	// Deepest subdivision (1..3: the GPU map packing holds 9 x 9 points at most).
	bool set_max_depth(uint32_t p_depth);
	uint32_t get_max_depth() const { return max_depth; }

	// Start of a frame, before anything is recorded: applies the newest completed frame's flags.
	void begin_frame();
	uint64_t get_frame() const { return frame; }
	// The light's quadtree, created (root quad) on first use with tiles from p_tiles; nullptr when the
	// source has no four tiles.
	AreaShadowQuadtree *light_get_tree(uint64_t p_light, AreaShadowQuadtree::TileSource *p_tiles);
	bool has_light(uint64_t p_light) const { return trees.count(p_light) != 0; }
	// Everything the renderer needs of an ADAPTIVE light in one call (after begin_frame()): the tree
	// (created on first use), its maps redrawn when p_content_hash changed, up to p_max_draws draw
	// requests appended to r_draws (as the atlas' own, map_index = point index), and the drawn maps
	// (tile, uv) for the shader in r_maps. false when the light has no tree (no four free tiles).
	// r_cells (optional): each map's cell code (AreaShadowQuadtree::get_point_cells(): its share of the light
	// and filter box), same order as r_maps.
	bool light_prepare(uint64_t p_light, AreaShadowQuadtree::TileSource *p_tiles, uint64_t p_content_hash, uint32_t p_max_draws, std::vector<AreaShadowAtlas::DrawRequest> &r_draws, std::vector<AreaShadowAtlas::Map> &r_maps, std::vector<uint32_t> *r_cells = nullptr);
	const AreaShadowQuadtree *light_get_tree_or_null(uint64_t p_light) const;
	uint32_t get_light_count() const { return uint32_t(trees.size()); }
	// The most tiles p_light's tree may hold from now on (the renderer's share of the atlas for it; at
	// least the four of a root quad). Splits that would exceed it fail as if the atlas were full; a tree
	// larger than (1 + EVICTION_SLACK) x the cap + 4 is shrunk to it at once (AreaShadowQuadtree::shrink(),
	// finest quads first), one within that keeps its tiles until it prunes (hysteresis).
	void light_set_tile_cap(uint64_t p_light, uint32_t p_cap);
	static constexpr float EVICTION_SLACK = 0.25f;
	// Parents pruned by light_set_tile_cap() evictions since the start.
	uint64_t get_eviction_count() const { return evictions; }
	// Frees a light's tree (tiles back to its source).
	void light_release(uint64_t p_light);
	// Releases every light not in p_seen (culled, freed, no longer ADAPTIVE).
	void release_lights_except(const std::vector<uint64_t> &p_seen);

	// Records the reprojection and banding passes of this frame's tests for p_lights (after the
	// scene's depth is written and the tree's points are drawn). p_depth: the camera depth (sampled,
	// Vulkan [0,1] depth), p_clip_from_view: the depth-corrected projection that wrote it.
	// Returns the number of quads tested (0: nothing to do, or every ring slot still in flight).
	// p_timestamp_prefix (non-empty): GPU timestamps p_timestamp_prefix + "area_reprojection" after the
	// reprojection and + "area_banding" after the banding detector (the renderer's profiler passes).
	uint32_t dispatch(RID p_depth, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, const AtlasInfo &p_atlas, const std::vector<LightInput> &p_lights, const String &p_timestamp_prefix = String());

	// The reprojection grid of p_light in a p_width x p_height view (offset 0): the screen rectangle of
	// its range box (the 8 corners, clipped at the camera plane, clamped to the viewport; the whole view
	// when the box is empty) at the smallest step >= 1 whose cell count fits
	// ceil(w / p_divisor) * ceil(h / p_divisor). false when the box is off-screen.
	static bool compute_light_grid(const LightInput &p_light, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, uint32_t p_divisor, GridData &r_grid);

	// Lower level, for tests: tests p_queries against the given atlas now and returns the flags
	// (flushes: submit + sync).
	std::vector<uint32_t> test_queries_blocking(RID p_depth, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, const AtlasInfo &p_atlas, const LightInput &p_light, const std::vector<AreaShadowQuadtree::Query> &p_queries, std::vector<float> *r_values = nullptr);

	// Project settings (registered on first use): the reprojection divisor (1..64, default 8) and the
	// deepest subdivision of ADAPTIVE and HEURISTIC lights (1..3, default 3). Bad values print an error
	// naming the setting and fall back to the default.
	static uint32_t get_project_reprojection_divisor();
	static uint32_t get_project_max_depth();
	// SETTING_HEURISTIC_OCCLUDER_FRACTION (0.01..0.99, default 0.25; bad values print an error and use it).
	static float get_project_heuristic_occluder_fraction();
	// HEURISTIC (thesis 6.5): the grid (2, 3, 5 or 9) for an area light of p_size and p_range whose
	// world range box is p_world_box, seen by p_data's camera (distance to the box, fovy, viewport
	// height), up to get_project_max_depth(). p_casters (world AABBs of the light's casters, may be
	// empty) give the occluder and receiver distances along the light's normal (-Z of
	// p_world_from_light); without them the project's occluder fraction of the range is assumed.
	// p_sample_filter: the lookup uses the per-sample penumbra filter (the ramp target, 2 or 5 x 5 only,
	// AreaShadowQuadtree::HeuristicInput::sample_filter); false: the fixed PCF (hard steps, up to 9 x 9).
	static uint32_t compute_heuristic_grid(const AABB &p_world_box, const Vector2 &p_size, float p_range, const RenderSceneData &p_data, const Transform3D &p_world_from_light = Transform3D(), const std::vector<AABB> &p_casters = {}, bool p_sample_filter = false);

	// True once a dispatch with work compiled the reprojection shader.
	bool is_reprojection_compiled() const { return reprojection_shader.is_variant_created(0); }
	const AreaShadowReadbackRing &get_ring() const { return ring; }
	uint32_t get_last_query_count() const { return last_query_count; }
	// Reprojection cells of the last dispatch() (all queries), and lights it skipped as off-screen.
	uint32_t get_last_cell_count() const { return last_cell_count; }
	// Sample points the last dispatch() read per cell, over all lights: each corner shared by tested quads once.
	uint32_t get_last_point_count() const { return last_point_count; }
	uint32_t get_last_offscreen_count() const { return last_offscreen_count; }
	uint32_t get_last_banding_count() const { return last_banding_count; }
	uint64_t get_last_result_frame() const { return last_result_frame; }
	// No stall: flag buffers read so far, and how many of those reads touched data of a submission that had
	// not completed when begin_frame() started (i.e. waited for GPU work of the frame being built): 0.
	uint64_t get_readback_count() const { return readback_count; }
	uint64_t get_current_frame_read_count() const { return current_frame_read_count; }
	uint64_t get_last_read_submission() const { return last_read_submission; }
	uint64_t get_last_begin_submission() const { return last_begin_submission; }
	uint64_t get_extra_dispatch_count() const { return extra_dispatch_count; } // dispatch() calls after the first of a frame.
	// Settled lights (a full round of tests changed nothing for the same state_hash) are not tested until
	// their state changes; off: every light is tested every frame (Algorithm 1 as written).
	void set_skip_settled(bool p_enable);
	bool is_skip_settled() const { return skip_settled; }
	// The trees' same-depth rule (AreaShadowQuadtree::set_same_depth_rule()), now and for new trees.
	void set_same_depth_rule(bool p_enable);
	bool is_light_settled(uint64_t p_light, uint64_t p_state_hash) const;
	// Lights skipped by the last dispatch() because they were settled.
	uint32_t get_last_skipped_count() const { return last_skipped_count; }

	~AreaShadowAdaptiveRD() { finalize(); }
};
