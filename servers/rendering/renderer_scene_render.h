/**************************************************************************/
/*  renderer_scene_render.h                                               */
/**************************************************************************/
/* godot-area: the abstract 3D renderer (Godot's RendererSceneRender) and */
/* RenderSceneData, everything RendererSceneCull hands it for one camera  */
/* and one frame. The Vulkan renderer (renderer_rd) and the dummy         */
/* renderer implement it.                                                 */

#pragma once

#include "core/math/projection.h"
#include "servers/rendering/storage/environment_storage.h"
#include "servers/rendering_server.h"

// One frame of one viewport, after culling. Mesh and light RIDs refer to storage objects that are
// alive during render_scene(). material_override is already checked (RID() = none); surface
// materials read from mesh storage are not, so check owns_material() and use a default material.
struct RenderSceneData {
	// A visible mesh instance.
	struct GeometryInstance {
		RID instance; // Scene-cull instance RID (stable key for per-instance caches).
		RID mesh; // Mesh storage RID.
		RID material_override; // RID() when none.
		Transform3D transform; // world_from_object.
		AABB aabb; // World-space bound.
		uint32_t layer_mask = 1; // Matched against light cull masks.
		// GeometryInstance3D::cast_shadow: OFF casts nothing; SHADOWS_ONLY casts but the colour passes skip it.
		RS::ShadowCastingSetting cast_shadows = RS::SHADOW_CASTING_SETTING_ON;
	};

	// A visible light (directional lights are never culled).
	struct LightInstance {
		RID instance; // Scene-cull instance RID.
		RID light; // Light storage RID (read parameters from RSG::light_storage).
		RS::LightType type = RS::LIGHT_OMNI;
		Transform3D transform; // world_from_light; the light shines along its local -Z.
		AABB aabb; // World-space bound (empty for directional lights).
		// Shadowed area lights: indices into RenderSceneData::shadow_geometry of the instances whose bound
		// meets the light's influence box (a + 2r) x (b + 2r) x r, camera-visible or not
		// (RendererSceneCull fills it; nothing else casts).
		std::vector<uint32_t> shadow_casters;
	};

	// Background and ambient after resolving scenario/camera environments (camera wins).
	// Colours are sRGB (node values) and energies are multipliers; the renderer linearises once.
	struct EnvironmentData {
		bool has_environment = false; // False: default clear colour, no ambient.
		RS::EnvironmentBG background = RS::ENV_BG_CLEAR_COLOR;
		Color bg_color = Color(0.3f, 0.3f, 0.3f, 1); // Resolved: default clear colour for CLEAR_COLOR.
		float bg_energy = 1.0f;
		RS::EnvironmentAmbientSource ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
		Color ambient_color = Color(0, 0, 0, 1); // Resolved: for source BG, the background colour.
		float ambient_energy = 0.0f; // Resolved: 0 when ambient is disabled.
		// Sky (ENV_BG_SKY and sky ambient): the ProceduralSkyMaterial of the environment's Sky.
		bool has_sky = false; // A sky with a material is attached and used (background or ambient).
		RS::SkyMaterialType sky_type = RS::SKY_MATERIAL_PROCEDURAL;
		RS::ProceduralSkyParams sky;
		RS::PhysicalSkyParams physical_sky; // sky_type PHYSICAL.
		int sky_radiance_size = 256;
		// Sky reflections (radiance cubemap, SkyRD): resolved from reflected_light_source and the background.
		bool sky_reflections = false;
		// Ambient from the sky: ambient = mix(ambient_color * energy, sky irradiance / pi * energy, contribution).
		bool sky_ambient = false;
		float ambient_sky_contribution = 1.0f;
		// SSAO / SSIL (image-space radiosity after the opaque pass); inactive unless enabled.
		ScreenSpaceLightingSettings ss_lighting;
	};

	Transform3D cam_transform; // world_from_view (camera-to-world).
	Projection cam_projection; // OpenGL clip space; the RD renderer applies create_depth_correction().
	float z_near = 0.05f;
	float z_far = 4000.0f;
	float fovy_degrees = 75.0f;
	int viewport_width = 0;
	int viewport_height = 0;
	uint32_t camera_cull_mask = 0xFFFFF;
	RS::ViewportDebugDraw debug_draw = RS::VIEWPORT_DEBUG_DRAW_DISABLED;

	std::vector<GeometryInstance> geometry; // Visible geometry, scenario order.
	std::vector<LightInstance> directional_lights; // All visible directional lights.
	std::vector<LightInstance> lights; // Omni, spot and area lights that passed frustum culling.
	std::vector<GeometryInstance> shadow_geometry; // Shadow casters of the area lights (LightInstance::shadow_casters).
	// Area shadow atlas of this viewport (RS::area_shadow_atlas_set_size); 0 = the renderer's default.
	uint32_t area_shadow_atlas_size = 0;
	uint32_t area_shadow_atlas_subdivision = 0;
	EnvironmentData environment;
};

class RendererSceneRender {
public:
	// Renders p_data into p_render_target (the image readable with render_target_get_data()).
	virtual void render_scene(const RenderSceneData &p_data, RID p_render_target) = 0;
	// Creates an offscreen float RGBA render target of p_width x p_height (RID() on bad sizes).
	virtual RID render_target_create(int p_width, int p_height) = 0;
	// Frees a render target; returns false if p_rid is not one.
	virtual bool render_target_free(RID p_rid) = 0;
	// Returns true if p_rid is a render target of this renderer.
	virtual bool owns_render_target(RID p_rid) const = 0;
	// Reads back the last rendered image: width * height * 4 floats, linear RGBA, top row first.
	virtual std::vector<float> render_target_get_data(RID p_render_target) = 0;
	// The RenderingDevice texture holding the render target's HDR colour (null without one).
	virtual RID render_target_get_color_texture(RID p_render_target) const { return RID(); }
	// GPU time per pass of the last rendered frame, as (pass name, milliseconds).
	virtual std::vector<std::pair<String, double>> get_last_frame_profile() const = 0;
	// ADAPTIVE area-shadow quads the last render_scene() tested (0: every adaptive light has settled, or none).
	virtual uint32_t get_last_frame_area_shadow_tests() const { return 0; }
	// RS::get_rendering_info() counters of the last render_scene().
	virtual uint64_t get_last_frame_rendering_info(RS::RenderingInfo p_info) const { return 0; }
	// When true, shade every light for every pixel instead of using clusters (test reference).
	virtual void set_debug_force_all_lights(bool p_enable) = 0;
	// RS::area_shadow_filter_set_mode() (renderers without area shadows ignore it).
	virtual void area_shadow_filter_set_mode(RS::AreaShadowFilter p_filter) {}
	virtual RS::AreaShadowFilter area_shadow_filter_get_mode() const { return RS::AREA_SHADOW_FILTER_PENUMBRA; }
	// RS::set_debug_disable_area_lights().
	virtual void set_debug_disable_area_lights(bool p_disable) {}
	// RS::get_debug_scene_shader_sources().
	virtual std::vector<std::pair<String, String>> get_debug_scene_shader_sources() const { return {}; }

	virtual ~RendererSceneRender() {}
};
