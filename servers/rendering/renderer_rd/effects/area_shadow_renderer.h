/**************************************************************************/
/*  area_shadow_renderer.h                                                */
/**************************************************************************/
/* godot-area: GPU side of area-light soft shadows (thesis chapter 6):    */
/* the area shadow atlases (one per render target, i.e. per viewport, as  */
/* Godot's shadow atlas), the depth-only passes that draw one shadow map  */
/* per sample point of each shadowed area light, and the AreaShadowData   */
/* array (binding 12 of the area-light scene shader variant) that tells   */
/* shaders/area_light_shadow_inc.glsl where each light's maps are.        */
/*                                                                        */
/* Tile sharing, dirty tracking and the per-frame draw cap live in the    */
/* GPU-free AreaShadowAtlas (area_lights/area_shadow_atlas.h).             */
/* Mapping of one map: four perspective octant views in the four          */
/* quadrants of a tile (shaders/area_shadow_octant_inc.glsl; the choice   */
/* is measured in doc/shadows.md).                                        */
/* ADAPTIVE lights (thesis 6.3): one AreaShadowAdaptiveRD per atlas,     */
/* created with the first ADAPTIVE light; each such light's quadtree of   */
/* sample points takes single free tiles of the atlas (never evicts grid  */
/* lights) and its maps carry the points' cells (weight, filter box).     */
/* Per frame:                                                             */
/* begin_frame() (newest completed banding flags, before anything is      */
/* recorded), prepare(), render_shadows(), the scene's depth pre-pass,    */
/* dispatch_adaptive() (reprojection + banding of this frame's tests).    */
/* Casters: LightInstance::shadow_casters from RendererSceneCull (every   */
/* instance in the light's influence box, on screen or not); hand-built   */
/* scenes fall back to the visible geometry in the box. What each caster  */
/* surface casts (nothing when blended, a cut-out when alpha scissor) is  */
/* ShadowCastersRD's rule (effects/shadow_casters_rd.h).                  */

#pragma once

#include "servers/rendering/renderer_rd/area_lights/area_shadow_atlas.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_adaptive.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_scene_render.h"

#include <map>
#include <memory>
#include <vector>

namespace RendererRD {
class LightStorage;
class MaterialStorage;
class MeshStorage;
} // namespace RendererRD

class AreaShadowRendererRD {
public:
	/* Definition */

	static constexpr uint32_t MAX_MAPS_GPU = 84; // >= AreaShadowAtlas::MAX_MAPS, multiple of 4.

	// Must match AREA_SHADOW_MODE_* in shaders/area_light_shadow_inc.glsl (== RS::LightAreaShadowMode).
	enum Mode {
		MODE_FIXED = 0,
		MODE_PCSS_BASELINE = 1,
		MODE_ADAPTIVE = 2, // Drawn as FIXED with each tree point's cell (weight and filter box).
		MODE_HEURISTIC = 3, // Drawn as FIXED.
	};

	// AreaShadowData::mode bits above the mode (AREA_SHADOW_FLAG_* in the shader).
	static constexpr uint32_t FLAG_SAMPLE_FILTER = 0x100; // Per-sample penumbra filter (else the fixed PCF).
	// Sphere or tube: sample points on the surface, each map in front of its point (get_surface_sample());
	// AreaShadowData::half_size holds the capsule's half length and radius.
	static constexpr uint32_t FLAG_ALL_AROUND = 0x200;
	// Some caster is within near_layer_reach() of the light's sample points: the filter's near-layer step
	// can find a blocker there (RenderForwardClustered::AREA_VERSION_SHADOWS_NEAR compiles it in).
	static constexpr uint32_t FLAG_NEAR_LAYER = 0x400;
	// Distance from the light within which a blocker can be in the near layer: the shader's near cut,
	// d_blocker < d_receiver / (1 + AREA_SHADOW_MAX_K), at the farthest receiver (p_reach), with 25 % spare
	// for the normal offset.
	static float near_layer_reach(float p_reach) { return 1.25f * p_reach / (1.0f + NEAR_LAYER_MAX_K); }
	static constexpr float NEAR_LAYER_MAX_K = 8.0f; // AREA_SHADOW_MAX_K in area_light_shadow_inc.glsl.
	// True when a caster's world box p_caster lies within near_layer_reach() of the light's emitting extent
	// (the box of its sample points, light space: p_half_extent about the origin).
	static bool caster_in_near_layer(const Transform3D &p_world_from_light, const Vector3 &p_half_extent, float p_reach, const AABB &p_caster);
	// Smallest grid of a sphere or tube light: a 2 x 2 grid's points are the two poles, a 3 x 3's lie on one
	// great circle, so some receivers would face none of them.
	static constexpr uint32_t MIN_SURFACE_GRID = 5;

	// AreaShadowData::maps bit 31: an ADAPTIVE tree's point (pack_tree_map()), else a grid point (pack_map()).
	static constexpr uint32_t TREE_MAP_BIT = 0x80000000u;

	// Mirror of struct AreaShadowData in shaders/area_light_shadow_inc.glsl (std430), same names and order.
	struct AreaShadowData {
		float light_from_view[16];
		float half_size[2];
		float depth_scale;
		float bias;
		float normal_bias;
		float pcf_radius;
		uint32_t map_count;
		uint32_t mode;
		uint32_t atlas_subdivision;
		float atlas_texel;
		uint32_t quadrant_size;
		uint32_t tile_size;
		uint32_t maps[MAX_MAPS_GPU]; // pack_map() or pack_tree_map().
	};
	static_assert(sizeof(AreaShadowData) == 448, "AreaShadowData must match shaders/area_light_shadow_inc.glsl (448 bytes).");

	// Mirror of the DrawData push constant of shaders/area_shadow_depth.glsl.
	struct DepthPushConstant {
		float octant_view_from_model[16];
		float params[4]; // depth_scale, z_near, z_far, 1 if the surface has ARRAY_COLOR (ALPHA_TEST variant).
	};

	static constexpr RD::DataFormat ATLAS_FORMAT = RD::DATA_FORMAT_D32_SFLOAT;

	// Octant view of quadrant p_quadrant (0..3; bit 0: x > 0, bit 1: y > 0) in light space: rows right,
	// up, forward (shaders/area_shadow_octant_inc.glsl).
	static void get_octant_axes(uint32_t p_quadrant, Vector3 &r_right, Vector3 &r_up, Vector3 &r_forward);
	// Packs one grid map for the shader: tile (12 bits: atlases have at most 64 x 64 tiles), sample uv as
	// u_num / den, v_num / den (4 bits each, den = grid - 1 <= 8, bits 20..23); the shader weights it by the
	// trapezoid rule and filters it over its grid cell.
	static uint32_t pack_map(uint32_t p_tile, const Vector2 &p_uv, uint32_t p_grid);
	// Packs one point of an ADAPTIVE tree (depth <= 3): tile (12 bits), its index on the 9 x 9 lattice
	// (7 bits at 12), its cell code (AreaShadowQuadtree::get_point_cells(), 12 bits at 19) and TREE_MAP_BIT.
	// The shader takes the point's weight (its share of the light) and filter box from the cell.
	static uint32_t pack_tree_map(uint32_t p_tile, const Vector2 &p_uv, uint32_t p_cell);
	// Sample point of grid uv p_uv (grid p_den + 1) on the capsule of half length p_half_length (along light
	// X) and radius p_radius (a sphere: half length 0), and its frame (columns X, Y, Z in light space; Z the
	// inward normal, so the point emits along -Z as the rectangle does): the equal-area map of
	// area_shadow_surface_map() in shaders/area_light_shadow_inc.glsl, the point moved in to the chord of its
	// cell's arc. False for a repeated point (column u = 1, or a pole row beyond u = 0), whose map the shader
	// skips.
	static bool get_surface_sample(const Vector2 &p_uv, uint32_t p_den, float p_half_length, float p_radius, Vector3 &r_position, Basis &r_light_from_sample);
	// Sphere and tube lights whose grid was raised to MIN_SURFACE_GRID or whose ADAPTIVE mode ran as
	// HEURISTIC, and the warnings printed about them (one per change of that count).
	uint32_t get_surface_fallback_count() const { return surface_fallbacks; }
	uint32_t get_surface_warning_count() const { return surface_warnings; }

private:
	/* Private Members */

	RendererRD::LightStorage *light_storage = nullptr;
	RendererRD::MeshStorage *mesh_storage = nullptr;
	RendererRD::MaterialStorage *material_storage = nullptr;
	ShaderRD depth_shader; // Variants: ShadowCastersRD::DepthVariant.
	RID pipeline;
	RID alpha_pipeline; // ALPHA_TEST variant: made with the first alpha-scissor caster.
	RD::FramebufferFormatID pipeline_format = 0;
	RID dummy_texture; // Bound when no atlas exists yet.
	RID sampler;
	RID compare_sampler; // Linear + depth compare: the scene shader's bilinear PCF taps.
	RID data_buffer; // AreaShadowData[max_lights].
	uint32_t max_lights = 0;
	std::vector<AreaShadowData> data;
	uint32_t last_draw_count = 0;
	uint64_t total_draw_count = 0;
	uint32_t surface_fallbacks = 0;
	uint32_t surface_warned = 0;
	uint32_t surface_warnings = 0;
	bool initialized = false;

	struct LightFrame {
		uint64_t key = 0;
		Transform3D world_from_light; // Orthonormal.
		Vector2 size;
		float range = 1.0f;
		float reach = 1.0f; // Farthest receiver from a sample point: range + size.length() (sphere, tube: range + 2 (half length + radius)).
		bool all_around = false; // Sphere or tube: samples on the surface (get_surface_sample()).
		float half_length = 0.0f;
		float radius = 0.0f;
		uint32_t grid = 0; // Grid the maps were packed for.
		std::vector<const RenderSceneData::GeometryInstance *> casters; // Into the frame's RenderSceneData.
	};

	// One atlas per owner (render target id; 0 = scenes rendered without one).
	struct AtlasInstance {
		AreaShadowAtlas atlas;
		bool custom_size = false; // Sized per viewport (RenderSceneData), not by set_atlas_size().
		RID texture; // ATLAS_FORMAT, atlas.get_size() squared; created on the first shadowed light.
		RID framebuffer;
		std::map<uint64_t, LightFrame> frame_lights;
		std::map<uint64_t, uint32_t> map_counts; // Maps handed to the shader per light by the last prepare().
		// ADAPTIVE lights (created with the first one; declared after the atlas: the trees give their tiles
		// back to it when destroyed).
		std::unique_ptr<AreaShadowAdaptiveRD::AtlasTiles> adaptive_tiles;
		std::unique_ptr<AreaShadowAdaptiveRD> adaptive;
		uint64_t adaptive_configuration = 0; // atlas.get_configuration() the trees' tiles belong to.
		std::vector<AreaShadowAtlas::DrawRequest> adaptive_draws; // Tree points to draw this frame.
		std::vector<AreaShadowAdaptiveRD::LightInput> adaptive_lights; // This frame's ADAPTIVE lights.
		bool adaptive_warned = false;
	};
	std::map<uint64_t, AtlasInstance> atlases;
	AtlasInstance *current = nullptr; // Atlas of the last prepare().
	uint32_t default_size = AreaShadowAtlas::DEFAULT_SIZE;
	uint32_t default_subdivision = AreaShadowAtlas::DEFAULT_SUBDIVISION;
	uint32_t adaptive_divisor = 0; // 0: the project setting.
	bool adaptive_skip_settled = true;
	bool adaptive_same_depth = true;
	bool adaptive_tree_weights = true;
	bool sample_filter = true;

	bool _ensure_atlas(AtlasInstance &p_atlas);
	// Frees the ADAPTIVE trees when the atlas took every tile back (configure()).
	void _check_adaptive_configuration(AtlasInstance &p_atlas);
	bool _ensure_adaptive(AtlasInstance &p_atlas);
	void _free_atlas_texture(AtlasInstance &p_atlas);
	AtlasInstance &_get_atlas_instance(uint64_t p_owner);

public:
	/* Public Methods */

	bool initialize(RendererRD::LightStorage *p_light_storage, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage, uint32_t p_max_lights);
	void finalize();
	bool is_initialized() const { return initialized; }

	// Default atlas size in pixels and tiles per side, for every atlas not sized per viewport
	// (RenderSceneData::area_shadow_atlas_size). Frees their maps. False (old values kept) on bad input.
	bool set_atlas_size(uint32_t p_size, uint32_t p_subdivision);
	uint32_t get_default_atlas_size() const { return default_size; }
	uint32_t get_default_atlas_subdivision() const { return default_subdivision; }
	// The atlas of the last prepare() (the owner-0 atlas before any).
	AreaShadowAtlas &get_atlas();
	// The atlas of render target p_owner (nullptr if it has none yet).
	const AreaShadowAtlas *get_owner_atlas(RID p_owner) const;
	uint32_t get_atlas_count() const { return uint32_t(atlases.size()); }
	// Frees the atlas of a render target (call when the render target is freed).
	void release_owner(RID p_owner);

	// Start of a frame of render target p_owner, before anything else is recorded in the frame: the
	// ADAPTIVE lights' quadtrees take the newest completed frame's banding flags (never this frame's).
	void begin_frame(RID p_owner = RID());
	// Shares the tiles among the shadowed area lights of this frame and fills the AreaShadowData array
	// (index = GPU area light index). p_area_sources[i]: index into p_data.lights of GPU area light i
	// (LightStorage::get_area_light_source_indices()). p_owner: the render target (selects its atlas; sized
	// by p_data.area_shadow_atlas_size/_subdivision when non-zero). Records a buffer update: call outside lists.
	void prepare(const RenderSceneData &p_data, const std::vector<uint32_t> &p_area_sources, const Transform3D &p_view_from_world, const Projection &p_clip_from_world, RID p_owner = RID());
	// Records the depth passes of the maps listed by prepare() (before the scene passes). p_data must be
	// the RenderSceneData given to prepare() (the casters point into it). p_material_shader: the scene's
	// colour shader, whose set 1 layout (shaders/material_block_inc.glsl) the alpha-scissor casters' material
	// sets are made for.
	void render_shadows(const RenderSceneData &p_data, RID p_material_shader);
	// True once an alpha-scissor caster compiled the ALPHA_TEST depth variant.
	bool is_alpha_test_compiled() const { return depth_shader.is_variant_created(1); }
	// After the camera depth p_depth (p_width x p_height, written with the depth-corrected p_clip_from_view)
	// is complete: records the reprojection and banding passes of this frame's ADAPTIVE tests, with GPU
	// timestamps p_timestamp_prefix + "area_reprojection" / "area_banding" when there is work. Returns the
	// number of quads tested (0 without ADAPTIVE lights: nothing recorded, no shader compiled).
	uint32_t dispatch_adaptive(RID p_depth, uint32_t p_width, uint32_t p_height, const Projection &p_clip_from_view, const String &p_timestamp_prefix = String());

	// Shadow maps (sample points) the shader averaged for a light in the last prepare() (any mode; ADAPTIVE:
	// the drawn points of its tree). p_light: the light RID for scenes built by hand (RenderSceneData
	// without instances), the instance RID for RenderingServer scenes. 0 if unknown or unshadowed.
	uint32_t light_get_shadow_map_count(RID p_light) const;
	// The same summed over every light of the last prepare().
	uint32_t get_shadow_map_count() const;
	// The ADAPTIVE driver of the current atlas (nullptr before its first ADAPTIVE light).
	const AreaShadowAdaptiveRD *get_adaptive() const { return current ? current->adaptive.get() : nullptr; }
	// True once any atlas compiled the reprojection shader (an ADAPTIVE light had a quad to test).
	bool is_reprojection_compiled() const;
	// Reprojection budget = the cells of the whole view at camera / p_divisor (1..64), spent per light on its
	// range box's screen rectangle (never finer than full resolution), for every atlas, now and later; 0 = the
	// project setting (rendering/lights_and_shadows/area_shadow_reprojection_divisor).
	bool set_adaptive_reprojection_divisor(uint32_t p_divisor);
	// On (default): an ADAPTIVE light whose last full round of tests changed nothing is not tested again
	// while its camera, light, casters, receivers and atlas stay the same (a static view costs no
	// reprojection). Off: every frame tests (Algorithm 1 as written; tests of the convergence).
	void set_adaptive_skip_settled(bool p_enable);
	// The quadtrees' same-depth rule (doc/shadows_adaptive.md; default on). Off: each quad refines on its own
	// banding answer only (Algorithm 1 as written), which lets trees become non-uniform.
	void set_adaptive_same_depth_rule(bool p_enable);
	// On (default): each tree point is weighted by its share of the light and filtered over its own cell
	// (pack_tree_map()). Off: as a point of the uniform 9 x 9 grid (trapezoid weight, 1/8 cell), biased on
	// non-uniform trees; for the measurement that shows the weights matter.
	void set_adaptive_tree_weights(bool p_enable) { adaptive_tree_weights = p_enable; }
	// Per-sample penumbra filter (default on): each map's lookup is filtered over the penumbra of the light
	// cell its sample point stands for (shaders/area_light_shadow_inc.glsl, area_shadow_sample_filtered()).
	// Off: the fixed-size PCF of shadow_blur (thesis 6.1 as written), for comparisons.
	// RS::area_shadow_filter_set_mode(); initialize() starts from the project setting SETTING_FILTER.
	void set_sample_penumbra_filter(bool p_enable) { sample_filter = p_enable; }
	static constexpr const char *SETTING_FILTER = "rendering/lights_and_shadows/area_shadow_filter";
	// SETTING_FILTER as an RS::AreaShadowFilter (default PENUMBRA; bad values print an error and use it).
	static RS::AreaShadowFilter get_project_filter();
	bool is_sample_penumbra_filter_enabled() const { return sample_filter; }

	RID get_data_buffer() const { return data_buffer; }
	RID get_atlas_texture() const { return current && current->texture.is_valid() ? current->texture : dummy_texture; }
	RID get_sampler() const { return sampler; }
	RID get_compare_sampler() const { return compare_sampler; }
	const std::vector<AreaShadowData> &get_data() const { return data; }
	// Shadow maps drawn by the last render_shadows() and since initialize().
	uint32_t get_last_draw_count() const { return last_draw_count; }
	// True when the last prepare() had at least one shadowed area light (the profiler lists "area_shadows").
	bool has_frame_shadows() const { return current && !current->frame_lights.empty(); }
	uint64_t get_total_draw_count() const { return total_draw_count; }

	~AreaShadowRendererRD() { finalize(); }
};
