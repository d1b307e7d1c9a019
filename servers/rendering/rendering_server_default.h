/**************************************************************************/
/*  rendering_server_default.h                                            */
/**************************************************************************/
/* godot-area: RenderingServer implementation. Forwards calls to          */
/* RSG::scene (RendererSceneCull) and the backend storages, and owns the  */
/* viewports. Usage:                                                      */
/*   RenderingServerDefault *rs = new RenderingServerDefault(             */
/*           new RasterizerDummy);  // or RendererCompositorRD        */
/*   ... RS::get_singleton()->mesh_create() ...                           */
/*   delete rs; // also deletes the compositor                            */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/renderer_compositor.h"
#include "servers/rendering/renderer_scene_cull.h"
#include "servers/rendering/storage/environment_storage.h"
#include "servers/rendering_server.h"

class RenderingServerDefault : public RenderingServer {
	struct Viewport {
		int width = 0;
		int height = 0;
		bool active = true;
		RID camera;
		RID scenario;
		RID render_target; // Created by viewport_set_size().
		RS::ViewportDebugDraw debug_draw = RS::VIEWPORT_DEBUG_DRAW_DISABLED;
		int area_shadow_atlas_size = 0; // 0: the renderer's default.
		int area_shadow_atlas_subdivision = 0;
	};

	RendererCompositor *compositor = nullptr;
	RendererSceneCull *scene_cull = nullptr;
	RendererEnvironmentStorage *environment_storage = nullptr;
	RID_Owner<Viewport, true> viewport_owner{ "Viewport" };
	std::vector<RID> viewport_order; // Creation order: draw() renders in this order.
	Color default_clear_color = Color(0.3f, 0.3f, 0.3f, 1.0f); // Godot's default_clear_color.
	uint32_t frame_area_shadow_tests = 0; // ADAPTIVE quads tested by the last draw().
	uint64_t frame_rendering_info[RS::RENDERING_INFO_MAX] = {}; // Counters of the last draw().

	RID _light_create(LightType p_type);

public:
	// Creates a server for the dummy (CPU-only) backend: no GPU needed.
	static RenderingServerDefault *create_dummy();

	RID mesh_create() override;
	void mesh_add_surface(RID p_mesh, const SurfaceData &p_surface) override;
	void mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) override;
	RID mesh_surface_get_material(RID p_mesh, int p_surface) const override;
	int mesh_get_surface_count(RID p_mesh) const override;
	AABB mesh_get_aabb(RID p_mesh) const override;
	void mesh_clear(RID p_mesh) override;

	RID texture_2d_create(const Image &p_image) override;
	RID texture_2d_create_rgba8(int p_width, int p_height, const std::vector<uint8_t> &p_data) override;
	Image texture_2d_get(RID p_texture) const override;

	RID material_create() override;
	void material_set_params(RID p_material, const MaterialParams &p_params) override;
	MaterialParams material_get_params(RID p_material) const override;

	RID directional_light_create() override;
	RID omni_light_create() override;
	RID spot_light_create() override;
	RID area_light_create() override;
	void light_set_param(RID p_light, LightParam p_param, float p_value) override;
	void light_set_color(RID p_light, const Color &p_color) override;
	void light_set_shadow(RID p_light, bool p_enabled) override;
	void light_set_negative(RID p_light, bool p_enable) override;
	void light_set_cull_mask(RID p_light, uint32_t p_mask) override;
	void light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) override;
	void light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) override;
	void light_set_bake_mode(RID p_light, LightBakeMode p_bake_mode) override;
	void light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) override;
	void light_omni_set_shadow_mode(RID p_light, LightOmniShadowMode p_mode) override;
	void light_directional_set_shadow_mode(RID p_light, LightDirectionalShadowMode p_mode) override;
	void light_directional_set_blend_splits(RID p_light, bool p_enable) override;
	void light_directional_set_sky_mode(RID p_light, LightDirectionalSkyMode p_mode) override;
	void light_area_set_size(RID p_light, const Vector2 &p_size) override;
	void light_area_set_normalize_energy(RID p_light, bool p_enable) override;
	void light_area_set_shading_method(RID p_light, LightAreaShadingMethod p_method) override;
	void light_area_set_stochastic_samples(RID p_light, int p_samples) override;
	void light_area_set_shadow_mode(RID p_light, LightAreaShadowMode p_mode) override;
	void light_area_set_shadow_grid(RID p_light, int p_grid) override;
	void light_area_set_shape(RID p_light, LightAreaShape p_shape) override;
	void light_area_set_texture(RID p_light, RID p_texture) override;
	LightType light_get_type(RID p_light) const override;
	float light_get_param(RID p_light, LightParam p_param) const override;
	AABB light_get_aabb(RID p_light) const override;
	Vector2 light_area_get_size(RID p_light) const override;
	bool light_area_get_normalize_energy(RID p_light) const override;
	LightAreaShadingMethod light_area_get_shading_method(RID p_light) const override;
	int light_area_get_stochastic_samples(RID p_light) const override;
	LightAreaShadowMode light_area_get_shadow_mode(RID p_light) const override;
	int light_area_get_shadow_grid(RID p_light) const override;
	LightAreaShape light_area_get_shape(RID p_light) const override;
	RID light_area_get_texture(RID p_light) const override;

	RID camera_create() override;
	void camera_set_perspective(RID p_camera, float p_fovy_degrees, float p_z_near, float p_z_far) override;
	void camera_set_transform(RID p_camera, const Transform3D &p_transform) override;
	void camera_set_cull_mask(RID p_camera, uint32_t p_layers) override;
	void camera_set_environment(RID p_camera, RID p_env) override;

	RID environment_create() override;
	void environment_set_background(RID p_env, EnvironmentBG p_bg) override;
	void environment_set_bg_color(RID p_env, const Color &p_color) override;
	void environment_set_bg_energy(RID p_env, float p_multiplier) override;
	void environment_set_ambient_light(RID p_env, const Color &p_color, EnvironmentAmbientSource p_ambient = ENV_AMBIENT_SOURCE_BG, float p_energy = 1.0f) override;
	void environment_set_ssao(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_power, float p_detail, float p_horizon, float p_sharpness, float p_light_affect, float p_ao_channel_affect) override;
	void environment_set_ssil(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_sharpness, float p_normal_rejection) override;
	void environment_set_ssao_quality(EnvironmentSSAOQuality p_quality, bool p_half_size, int p_blur_passes = 2) override;
	void environment_set_ssil_quality(EnvironmentSSILQuality p_quality, bool p_half_size, int p_blur_passes = 2) override;
	RID sky_material_create() override;
	void sky_material_set_procedural(RID p_material, const ProceduralSkyParams &p_params) override;
	void sky_material_set_physical(RID p_material, const PhysicalSkyParams &p_params) override;
	void environment_set_reflection_source(RID p_env, EnvironmentReflectionSource p_source) override;
	RID sky_create() override;
	void sky_set_material(RID p_sky, RID p_material) override;
	void sky_set_radiance_size(RID p_sky, int p_size) override;
	void environment_set_sky(RID p_env, RID p_sky) override;
	void environment_set_ambient_sky_contribution(RID p_env, float p_contribution) override;

	RID scenario_create() override;
	void scenario_set_environment(RID p_scenario, RID p_environment) override;

	RID instance_create() override;
	void instance_set_base(RID p_instance, RID p_base) override;
	void instance_set_scenario(RID p_instance, RID p_scenario) override;
	void instance_set_transform(RID p_instance, const Transform3D &p_transform) override;
	void instance_set_visible(RID p_instance, bool p_visible) override;
	void instance_set_layer_mask(RID p_instance, uint32_t p_mask) override;
	void instance_geometry_set_material_override(RID p_instance, RID p_material) override;
	void instance_geometry_set_cast_shadows_setting(RID p_instance, ShadowCastingSetting p_setting) override;
	AABB instance_get_aabb(RID p_instance) const override;

	RID viewport_create() override;
	void viewport_set_size(RID p_viewport, int p_width, int p_height) override;
	void viewport_set_active(RID p_viewport, bool p_active) override;
	void viewport_attach_camera(RID p_viewport, RID p_camera) override;
	void viewport_set_scenario(RID p_viewport, RID p_scenario) override;
	void viewport_set_debug_draw(RID p_viewport, ViewportDebugDraw p_draw) override;
	Image viewport_get_texture_data(RID p_viewport) const override;
	RID viewport_get_texture(RID p_viewport) const override;
	void area_shadow_atlas_set_size(RID p_viewport, int p_size, int p_subdivision) override;
	int area_shadow_atlas_get_size(RID p_viewport) const override;
	int area_shadow_atlas_get_subdivision(RID p_viewport) const override;

	void set_default_clear_color(const Color &p_color) override;
	Color get_default_clear_color() const override;
	void draw() override;
	void free(RID p_rid) override;
	std::vector<std::pair<String, double>> get_frame_profile() const override;
	uint32_t get_frame_area_shadow_tests() const override { return frame_area_shadow_tests; }
	uint64_t get_rendering_info(RenderingInfo p_info) const override {
		return p_info >= 0 && p_info < RENDERING_INFO_MAX ? frame_rendering_info[p_info] : 0;
	}
	void set_debug_force_all_lights(bool p_enable) override;
	void set_debug_disable_area_lights(bool p_disable) override;
	void area_shadow_filter_set_mode(AreaShadowFilter p_filter) override;
	AreaShadowFilter area_shadow_filter_get_mode() const override;
	std::vector<std::pair<String, String>> get_debug_scene_shader_sources() const override;

	// The scene cull of this server (tests read its counters).
	RendererSceneCull *get_scene_cull() const { return scene_cull; }

	// Takes ownership of p_compositor (must not be null) and publishes it through RSG::.
	explicit RenderingServerDefault(RendererCompositor *p_compositor);
	~RenderingServerDefault() override;
};
