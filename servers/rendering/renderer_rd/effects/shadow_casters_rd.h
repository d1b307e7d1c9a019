/**************************************************************************/
/*  shadow_casters_rd.h                                                   */
/**************************************************************************/
/* godot-area: what a mesh surface casts into a shadow map, shared by the */
/* area (AreaShadowRendererRD) and directional (DirectionalShadowRD)      */
/* depth passes. Godot's BaseMaterial3D rules (doc/compatibility.md):     */
/* - transparency DISABLED: the whole surface casts (the depth shader's   */
/*   plain variant: no material read, the pipeline of an all-opaque scene */
/*   is the one it always was);                                           */
/* - ALPHA_SCISSOR (and ALPHA_HASH, which draws as it): a cut-out shadow, */
/*   the depth shader's ALPHA_TEST variant with the material's set 1      */
/*   (shaders/shadow_alpha_test_inc.glsl), compiled on first use;         */
/* - ALPHA (blended): no shadow, as Godot ("materials with alpha          */
/*   transparency never cast shadows").                                   */
/* Material sets are made against the scene's colour shader: set 1 is     */
/* declared once for every pass (shaders/material_block_inc.glsl), so the */
/* colour pass and the shadow passes share one set per material.          */

#pragma once

#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "servers/rendering/renderer_scene_render.h"

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

class ShadowCastersRD {
public:
	// ShaderRD variants of area_shadow_depth.glsl and directional_shadow_depth.glsl.
	enum DepthVariant {
		DEPTH_VARIANT_OPAQUE,
		DEPTH_VARIANT_ALPHA_TEST,
		DEPTH_VARIANT_MAX
	};
	// The variant defines, indexed by DepthVariant.
	static std::vector<String> get_variant_defines() { return { "", "#define ALPHA_TEST\n" }; }

	struct Surface {
		const RendererRD::MeshStorage::SurfaceGPU *gpu = nullptr;
		RID material_set; // ALPHA_TEST only: the material's set 1.
		bool alpha_test = false;
	};

	// How a surface with material p_material (RID() or invalid: the default material) casts: false for a
	// blended one (no shadow); r_alpha_test for ALPHA_SCISSOR.
	static bool material_casts(const RendererRD::MaterialStorage *p_material_storage, RID p_material, bool &r_alpha_test);
	// The surfaces of p_instance that cast, appended to r_surfaces; material sets are created against
	// p_material_shader (records buffer updates: call outside draw lists). Returns the number appended.
	static uint32_t collect(const RenderSceneData::GeometryInstance &p_instance, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage, RID p_material_shader, std::vector<Surface> &r_surfaces);
	// The surfaces of every caster of a frame's passes, each caster resolved once.
	struct FrameSurfaces {
		std::map<const RenderSceneData::GeometryInstance *, std::pair<uint32_t, uint32_t>> ranges; // [begin, end) in surfaces.
		std::vector<Surface> surfaces;
		bool any_alpha_test = false;
		// Adds p_instance's surfaces unless already added (collect(); call outside draw lists).
		void add(const RenderSceneData::GeometryInstance *p_instance, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage, RID p_material_shader);
		std::pair<uint32_t, uint32_t> get_range(const RenderSceneData::GeometryInstance *p_instance) const;
	};
	// Binds p_alpha_pipeline or p_pipeline as p_surface needs (r_alpha_bound: which one the list has bound) and,
	// for an alpha-tested surface, its material set (set 1).
	static void bind_surface(RD::DrawListID p_list, const Surface &p_surface, RID p_pipeline, RID p_alpha_pipeline, bool &r_alpha_bound);
	// Draws p_surface's arrays with the push constant p_push (p_push_size bytes).
	static void draw_surface(RD::DrawListID p_list, const Surface &p_surface, const void *p_push, uint32_t p_push_size);
	// FNV-1a of what decides p_instance's shadow shape beyond its mesh and transform: its cast_shadows and, per
	// surface, its transparency and, when alpha-tested, the threshold, albedo alpha, albedo texture, uv1 and
	// vertex colour use (the area maps are redrawn when it changes).
	static void hash_materials(uint64_t &r_hash, const RenderSceneData::GeometryInstance &p_instance, const RendererRD::MeshStorage *p_mesh_storage, const RendererRD::MaterialStorage *p_material_storage);
};
