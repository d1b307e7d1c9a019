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
/* GPU-free AreaShadowAtlas (storage_rd/area_shadow_atlas.h).             */
/* Mapping of one map: four perspective octant views in the four          */
/* quadrants of a tile (shaders/area_shadow_octant_inc.glsl; the choice   */
/* is measured in doc/shadows.md).                                        */
/* Casters: LightInstance::shadow_casters from RendererSceneCull (every   */
/* instance in the light's influence box, on screen or not); hand-built   */
/* scenes fall back to the visible geometry in the box.                   */

#pragma once

#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_rd/storage_rd/area_shadow_atlas.h"
#include "servers/rendering/renderer_scene_render.h"

#include <map>
#include <vector>

namespace RendererRD {
class LightStorage;
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
	};

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
		uint32_t maps[MAX_MAPS_GPU]; // tile | u_num << 16 | v_num << 20 | den << 24.
	};
	static_assert(sizeof(AreaShadowData) == 448, "AreaShadowData must match shaders/area_light_shadow_inc.glsl (448 bytes).");

	// Mirror of the DrawData push constant of shaders/area_shadow_depth.glsl.
	struct DepthPushConstant {
		float octant_view_from_model[16];
		float params[4]; // depth_scale, z_near, z_far, 0.
	};

	static constexpr RD::DataFormat ATLAS_FORMAT = RD::DATA_FORMAT_D32_SFLOAT;

	// Octant view of quadrant p_quadrant (0..3; bit 0: x > 0, bit 1: y > 0) in light space: rows right,
	// up, forward (shaders/area_shadow_octant_inc.glsl).
	static void get_octant_axes(uint32_t p_quadrant, Vector3 &r_right, Vector3 &r_up, Vector3 &r_forward);
	// Packs one map for the shader (tile and sample uv as a fraction of the grid).
	static uint32_t pack_map(uint32_t p_tile, const Vector2 &p_uv, uint32_t p_grid);

private:
	/* Private Members */

	RendererRD::LightStorage *light_storage = nullptr;
	RendererRD::MeshStorage *mesh_storage = nullptr;
	ShaderRD depth_shader;
	RID pipeline;
	RD::FramebufferFormatID pipeline_format = 0;
	RID dummy_texture; // Bound when no atlas exists yet.
	RID sampler;
	RID data_buffer; // AreaShadowData[max_lights].
	uint32_t max_lights = 0;
	std::vector<AreaShadowData> data;
	uint32_t last_draw_count = 0;
	uint64_t total_draw_count = 0;
	bool initialized = false;

	struct LightFrame {
		uint64_t key = 0;
		Transform3D world_from_light; // Orthonormal.
		Vector2 size;
		float range = 1.0f;
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
	};
	std::map<uint64_t, AtlasInstance> atlases;
	AtlasInstance *current = nullptr; // Atlas of the last prepare().
	uint32_t default_size = AreaShadowAtlas::DEFAULT_SIZE;
	uint32_t default_subdivision = AreaShadowAtlas::DEFAULT_SUBDIVISION;

	bool _ensure_atlas(AtlasInstance &p_atlas);
	void _free_atlas_texture(AtlasInstance &p_atlas);
	AtlasInstance &_get_atlas_instance(uint64_t p_owner);

public:
	/* Public Methods */

	bool initialize(RendererRD::LightStorage *p_light_storage, RendererRD::MeshStorage *p_mesh_storage, uint32_t p_max_lights);
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

	// Shares the tiles among the shadowed area lights of this frame and fills the AreaShadowData array
	// (index = GPU area light index). p_area_sources[i]: index into p_data.lights of GPU area light i
	// (LightStorage::get_area_light_source_indices()). p_owner: the render target (selects its atlas; sized
	// by p_data.area_shadow_atlas_size/_subdivision when non-zero). Records a buffer update: call outside lists.
	void prepare(const RenderSceneData &p_data, const std::vector<uint32_t> &p_area_sources, const Transform3D &p_view_from_world, const Projection &p_clip_from_world, RID p_owner = RID());
	// Records the depth passes of the maps listed by prepare() (before the scene passes). p_data must be
	// the RenderSceneData given to prepare() (the casters point into it).
	void render_shadows(const RenderSceneData &p_data);

	RID get_data_buffer() const { return data_buffer; }
	RID get_atlas_texture() const { return current && current->texture.is_valid() ? current->texture : dummy_texture; }
	RID get_sampler() const { return sampler; }
	const std::vector<AreaShadowData> &get_data() const { return data; }
	// Shadow maps drawn by the last render_shadows() and since initialize().
	uint32_t get_last_draw_count() const { return last_draw_count; }
	// True when the last prepare() had at least one shadowed area light (the profiler lists "area_shadows").
	bool has_frame_shadows() const { return current && !current->frame_lights.empty(); }
	uint64_t get_total_draw_count() const { return total_draw_count; }

	~AreaShadowRendererRD() { finalize(); }
};
