/**************************************************************************/
/*  directional_shadow_rd.h                                               */
/**************************************************************************/
/* godot-area: DirectionalLight3D shadows of the Forward+ renderer        */
/* (issue 16 item 2; Godot's directional shadow atlas and PSSM).          */
/*                                                                        */
/* Split math (compute_splits, CPU only, unit-tested): the view range     */
/* [z_near, max_distance] (max_distance = min(directional_shadow_max_     */
/* distance, z_far), Godot's meaning) is cut at z_near + split_k * range  */
/* for k = 1..3 (ORTHOGONAL: one split, PARALLEL_2_SPLITS: two, cut at     */
/* split_1, PARALLEL_4_SPLITS: four). Each slice of the view frustum gets */
/* an orthographic box along the light: the slice's bounding sphere       */
/* (centre = mean of its 8 corners, radius = farthest corner: invariant   */
/* under camera rotation), grown by w / (w - 2) for a texel of margin and */
/* with its light-space centre snapped to whole texels, so the shadow     */
/* does not swim when the camera moves (Valient 2008, "Stable Cascaded    */
/* Shadow Maps", ShaderX6). Depth 0..1 spans from the farthest caster     */
/* towards the light to the far side of the sphere.                       */
/*                                                                        */
/* Atlas (its own, independent of the area shadow atlas): one D32 texture */
/* of rendering/lights_and_shadows/directional_shadow/size texels per     */
/* side (Godot's setting and default, 4096), made on the first frame with */
/* a shadowed directional light in view. Up to MAX_SHADOWED_LIGHTS lights */
/* share it (1: whole atlas; 2..4: quadrants, Godot's layout); inside a   */
/* light's square, ORTHOGONAL uses all of it, 2 splits the left and right */
/* halves, 4 splits its quadrants.                                        */
/*                                                                        */
/* Bias, Godot's units: shadow_bias / 100 is a depth offset in the 0..1   */
/* depth of split 0, scaled per split by its radius over split 0's;       */
/* shadow_normal_bias moves it along its normal (less the part along the  */
/* light) by that many texels of the split, times (1 - N.L).              */
/* directional_shadow_pancake_size: the box starts at most that far      */
/* before the slice's sphere; nearer casters are flattened onto it (depth */
/* clamp). Soft shadows: the sun disk of                                  */
/* angular diameter light_angular_distance gives a penumbra of width       */
/* 2 tan(a) * (receiver - blocker distance) (a blocker search, then PCF   */
/* of that width: Fernando 2005, PCSS); 0 degrees: a 3 x 3 texel PCF     */
/* times shadow_blur.                                                     */
/*                                                                        */
/* A view without a shadowed directional light creates nothing (no       */
/* atlas, no pipeline, no buffer) and records no pass. What each caster   */
/* surface casts (nothing when blended, a cut-out when alpha scissor) is  */
/* ShadowCastersRD's rule (effects/shadow_casters_rd.h).                  */

#pragma once

#include "core/math/projection.h"
#include "core/math/transform_3d.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/rendering_device.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace RendererRD {
class LightStorage;
class MaterialStorage;
class MeshStorage;
} // namespace RendererRD

class DirectionalShadowRD {
public:
	static constexpr uint32_t MAX_SPLITS = 4; // Godot's MAX_DIRECTIONAL_LIGHT_CASCADES.
	static constexpr uint32_t MAX_SHADOWED_LIGHTS = 4; // Lights sharing the atlas (quadrants).
	static constexpr uint32_t DEFAULT_ATLAS_SIZE = 4096; // Godot's default.
	static constexpr const char *SETTING_ATLAS_SIZE = "rendering/lights_and_shadows/directional_shadow/size";
	static constexpr RD::DataFormat ATLAS_FORMAT = RD::DATA_FORMAT_D32_SFLOAT;

	// What the split math needs of a light and a view (world space, metres).
	struct SplitSettings {
		RS::LightDirectionalShadowMode mode = RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS;
		float split_offsets[3] = { 0.1f, 0.2f, 0.5f }; // directional_shadow_split_1..3 (fractions of the range).
		float max_distance = 100.0f; // directional_shadow_max_distance (0: the camera's z_far).
		uint32_t tile_width[MAX_SPLITS] = { 1024, 1024, 1024, 1024 }; // Texels of each split's atlas rect.
		uint32_t tile_height[MAX_SPLITS] = { 1024, 1024, 1024, 1024 };
	};

	struct Split {
		float range_begin = 0.0f; // View depth (m, positive) where the split starts.
		float range_end = 0.0f; // ... and ends (== next split's range_begin).
		Vector3 center; // World-space centre of the box (snapped).
		float radius = 0.0f; // Half side of the box in x and y (m), margin included.
		float z_min = 0.0f; // Light-space z of the far side of the box (relative to centre; z points towards the light).
		float z_max = 0.0f; // Light-space z of the near side (>= radius; raised to the casters by fit_casters).
		Basis light_basis; // Columns: light x, y, z (towards the light); orthonormal.
		Vector3 corners[8]; // World-space corners of the frustum slice (4 at range_begin, 4 at range_end).
		// World -> (x / r, y / r, depth 0..1) of the box; depth 0 at z_max (nearest the light).
		Transform3D get_clip_from_world() const;
		// Light-space coordinates (relative to the centre) of a world point.
		Vector3 to_light(const Vector3 &p_world) const { return light_basis.xform_inv(p_world - center); }
	};

	// Splits of one light for one view. p_world_from_light: the light's transform (shines along -Z);
	// p_cam_transform: world_from_view; p_cam_projection: the camera's OpenGL-style projection.
	// p_z_near / p_z_far: the camera's planes when known (perspective; 0: read from the projection).
	// Returns the split count (1, 2 or 4); r_splits[0..count-1] are filled.
	static uint32_t compute_splits(const SplitSettings &p_settings, const Transform3D &p_world_from_light, const Transform3D &p_cam_transform, const Projection &p_cam_projection, Split r_splits[MAX_SPLITS], float p_z_near = 0.0f, float p_z_far = 0.0f);

	// Godot 4's shadow_bias of a split in metres (the receiver moves that far towards the light):
	// shadow_bias / 100 * (2 * radius + pancake_size) * shadow_blur, radius of the split's sphere (m).
	static float get_bias_metres(float p_shadow_bias, float p_radius, float p_pancake_size, float p_shadow_blur) {
		return p_shadow_bias / 100.0f * (2.0f * p_radius + std::fmax(p_pancake_size, 0.0f)) * p_shadow_blur;
	}
	// Godot 4's shadow_normal_bias in metres: shadow_normal_bias texels of the split, 2 * radius / side.
	static float get_normal_bias_metres(float p_shadow_normal_bias, float p_radius, uint32_t p_side) {
		return p_shadow_normal_bias * 2.0f * p_radius / float(p_side > 0 ? p_side : 1);
	}

	// Mirror of DirectionalShadowData in shaders/scene_forward_directional_inc.glsl (std140).
	struct ShadowData {
		float shadow_from_view[MAX_SPLITS][16]; // View space -> (atlas u, atlas v, depth 0..1).
		float split_end[4]; // View depth (m) where each split ends.
		float bias[4]; // Depth offset per split (0..1 depth units).
		float normal_bias[4]; // Receiver offset along the normal per split (m).
		float radius[4]; // Box half side per split (m).
		float depth_range[4]; // Metres spanned by depth 0..1 per split.
		float uv_rect[MAX_SPLITS][4]; // Atlas rect per split: u0, v0, u1, v1.
		float params[4]; // split count, blend_splits (0/1), fade start (view depth m), fade end (max distance m).
		float params2[4]; // tan(angular radius), shadow_opacity, shadow_blur, atlas texel size (uv).
	};
	static_assert(sizeof(ShadowData) == 432, "ShadowData must match scene_forward_directional_inc.glsl.");
	struct ShadowBlock {
		ShadowData data[MAX_SHADOWED_LIGHTS];
	};

private:
	RendererRD::LightStorage *light_storage = nullptr;
	RendererRD::MeshStorage *mesh_storage = nullptr;
	RendererRD::MaterialStorage *material_storage = nullptr;
	ShaderRD depth_shader; // Loaded on the first shadowed frame; variants: ShadowCastersRD::DepthVariant.
	RID atlas; // ATLAS_FORMAT, atlas_size^2.
	RID framebuffer;
	RID pipeline;
	RID alpha_pipeline; // ALPHA_TEST variant: made with the first alpha-scissor caster.
	RID data_buffer; // ShadowBlock, uniform buffer.
	RID compare_sampler; // Linear, compare LESS_OR_EQUAL.
	RID nearest_sampler; // Nearest, clamp (blocker search).
	uint32_t atlas_size = 0; // Of the created atlas (0: none).
	uint32_t requested_size = 0; // set_atlas_size(); 0: the project setting.

	struct Pass {
		Transform3D clip_from_world;
		uint32_t rect[4]; // x, y, w, h in texels.
		std::vector<const RenderSceneData::GeometryInstance *> casters;
	};
	std::vector<Pass> passes; // This frame's.
	uint32_t shadowed_count = 0; // Lights with a shadow this frame.
	uint32_t dropped_count = 0; // Shadowed lights beyond MAX_SHADOWED_LIGHTS this frame (warned, unshadowed).
	uint64_t last_draw_count = 0;
	ShadowBlock block = {};

	bool _ensure_resources();

public:
	bool is_created() const { return atlas.is_valid(); }
	// Atlas size in texels (power of two, 256..16384) instead of the project setting; takes effect when the
	// atlas is (re)created. False on a bad value.
	bool set_atlas_size(uint32_t p_size);
	uint32_t get_atlas_size() const { return atlas_size; }
	// The size the next atlas gets (set_atlas_size() or the project setting, validated).
	uint32_t get_requested_atlas_size() const;
	// SETTING_ATLAS_SIZE (registered with its default on first call); bad values: an error and the default.
	static uint32_t get_project_atlas_size();

	// Fits the splits of every shadowed directional light of the view (LightStorage's directional order),
	// writes their shadow index into the directional light block (re-uploaded), fills the shadow data and
	// collects the casters per split. Creates the atlas on first need. False on GPU failure.
	bool prepare(const RenderSceneData &p_data, const Transform3D &p_view_from_world);
	bool has_frame_shadows() const { return shadowed_count > 0; }
	uint32_t get_frame_shadowed_light_count() const { return shadowed_count; }
	uint32_t get_frame_pass_count() const { return uint32_t(passes.size()); }
	uint64_t get_last_draw_count() const { return last_draw_count; }
	const ShadowBlock &get_block() const { return block; }
	// One depth pass per split of this frame (outside any draw list). p_material_shader: the scene's colour
	// shader, whose set 1 layout (shaders/material_block_inc.glsl) the alpha-scissor casters' material sets
	// are made for.
	void render_shadows(RID p_material_shader);
	// True once an alpha-scissor caster compiled the ALPHA_TEST depth variant.
	bool is_alpha_test_compiled() const { return depth_shader.is_variant_created(1); }

	RID get_atlas_texture() const { return atlas; }
	RID get_data_buffer() const { return data_buffer; }
	RID get_compare_sampler() const { return compare_sampler; }
	RID get_nearest_sampler() const { return nearest_sampler; }

	void initialize(RendererRD::LightStorage *p_light_storage, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage) {
		light_storage = p_light_storage;
		mesh_storage = p_mesh_storage;
		material_storage = p_material_storage;
	}
	void finalize();
	~DirectionalShadowRD() { finalize(); }
};
