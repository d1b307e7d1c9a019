/**************************************************************************/
/*  rendering_server_default.cpp                                          */
/**************************************************************************/

#include "servers/rendering/rendering_server_default.h"

#include "core/error/error_macros.h"
#include "servers/rendering/dummy/rasterizer_dummy.h"
#include "servers/rendering/rendering_server_globals.h"

#include <algorithm>

RenderingServerDefault *RenderingServerDefault::create_dummy() {
	return new RenderingServerDefault(new RasterizerDummy);
}

RenderingServerDefault::RenderingServerDefault(RendererCompositor *p_compositor) {
	compositor = p_compositor ? p_compositor : new RasterizerDummy;
	if (!p_compositor) {
		ERR_PRINT("RenderingServerDefault needs a compositor; falling back to the dummy backend.");
	}
	scene_cull = new RendererSceneCull;
	environment_storage = new RendererEnvironmentStorage;
	RSG::rasterizer = compositor;
	RSG::light_storage = compositor->get_light_storage();
	RSG::mesh_storage = compositor->get_mesh_storage();
	RSG::material_storage = compositor->get_material_storage();
	RSG::scene_render = compositor->get_scene_render();
	RSG::environment_storage = environment_storage;
	RSG::scene = scene_cull;
}

RenderingServerDefault::~RenderingServerDefault() {
	// Render targets belong to viewports; leaked viewports are reported by viewport_owner.
	for (const RID &rid : viewport_order) {
		Viewport *viewport = viewport_owner.get_or_null(rid);
		if (viewport && viewport->render_target.is_valid()) {
			RSG::scene_render->render_target_free(viewport->render_target);
			viewport->render_target = RID();
		}
	}
	delete scene_cull;
	delete environment_storage;
	if (RSG::rasterizer == compositor) {
		RSG::rasterizer = nullptr;
		RSG::light_storage = nullptr;
		RSG::mesh_storage = nullptr;
		RSG::material_storage = nullptr;
		RSG::scene_render = nullptr;
		RSG::environment_storage = nullptr;
		RSG::scene = nullptr;
	}
	delete compositor;
}

/* MESH API */

RID RenderingServerDefault::mesh_create() {
	return RSG::mesh_storage->mesh_create();
}

void RenderingServerDefault::mesh_add_surface(RID p_mesh, const SurfaceData &p_surface) {
	RSG::mesh_storage->mesh_add_surface(p_mesh, p_surface);
}

void RenderingServerDefault::mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) {
	ERR_FAIL_COND_MSG(p_material.is_valid() && !RSG::material_storage->owns_material(p_material), "Invalid material RID for the mesh surface.");
	RSG::mesh_storage->mesh_surface_set_material(p_mesh, p_surface, p_material);
}

RID RenderingServerDefault::mesh_surface_get_material(RID p_mesh, int p_surface) const {
	return RSG::mesh_storage->mesh_surface_get_material(p_mesh, p_surface);
}

int RenderingServerDefault::mesh_get_surface_count(RID p_mesh) const {
	return RSG::mesh_storage->mesh_get_surface_count(p_mesh);
}

AABB RenderingServerDefault::mesh_get_aabb(RID p_mesh) const {
	return RSG::mesh_storage->mesh_get_aabb(p_mesh);
}

void RenderingServerDefault::mesh_clear(RID p_mesh) {
	RSG::mesh_storage->mesh_clear(p_mesh);
}

/* TEXTURE API */

RID RenderingServerDefault::texture_2d_create(const Image &p_image) {
	return RSG::material_storage->texture_2d_create(p_image);
}

RID RenderingServerDefault::texture_2d_create_rgba8(int p_width, int p_height, const std::vector<uint8_t> &p_data) {
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE, RID(),
			vformat("Texture size %dx%d is invalid (1..%d per side).", p_width, p_height, Image::MAX_SIZE));
	const size_t expected = (size_t)p_width * p_height * 4;
	ERR_FAIL_COND_V_MSG(p_data.size() != expected, RID(), vformat("Texture data has %zu bytes, expected %zu (RGBA8).", p_data.size(), expected));
	std::vector<float> texels(expected);
	for (size_t i = 0; i < expected; i++) {
		texels[i] = p_data[i] * (1.0f / 255.0f);
	}
	Image image;
	image.set_data(p_width, p_height, texels);
	return RSG::material_storage->texture_2d_create(image);
}

Image RenderingServerDefault::texture_2d_get(RID p_texture) const {
	const Image *image = RSG::material_storage->texture_get_image(p_texture);
	return image ? *image : Image();
}

/* MATERIAL API */

RID RenderingServerDefault::material_create() {
	return RSG::material_storage->material_create();
}

void RenderingServerDefault::material_set_params(RID p_material, const MaterialParams &p_params) {
	ERR_FAIL_COND_MSG(p_params.albedo_texture.is_valid() && !RSG::material_storage->owns_texture(p_params.albedo_texture), "Invalid albedo texture RID; the material is unchanged.");
	ERR_FAIL_COND_MSG(p_params.normal_texture.is_valid() && !RSG::material_storage->owns_texture(p_params.normal_texture), "Invalid normal texture RID; the material is unchanged.");
	RSG::material_storage->material_set_params(p_material, p_params);
}

RS::MaterialParams RenderingServerDefault::material_get_params(RID p_material) const {
	return RSG::material_storage->material_get_params(p_material);
}

/* LIGHT API */

RID RenderingServerDefault::_light_create(LightType p_type) {
	return RSG::light_storage->light_create(p_type);
}

RID RenderingServerDefault::directional_light_create() {
	return _light_create(LIGHT_DIRECTIONAL);
}

RID RenderingServerDefault::omni_light_create() {
	return _light_create(LIGHT_OMNI);
}

RID RenderingServerDefault::spot_light_create() {
	return _light_create(LIGHT_SPOT);
}

RID RenderingServerDefault::area_light_create() {
	return _light_create(LIGHT_AREA);
}

void RenderingServerDefault::light_set_param(RID p_light, LightParam p_param, float p_value) {
	RSG::light_storage->light_set_param(p_light, p_param, p_value);
}

void RenderingServerDefault::light_set_color(RID p_light, const Color &p_color) {
	RSG::light_storage->light_set_color(p_light, p_color);
}

void RenderingServerDefault::light_set_shadow(RID p_light, bool p_enabled) {
	RSG::light_storage->light_set_shadow(p_light, p_enabled);
}

void RenderingServerDefault::light_set_negative(RID p_light, bool p_enable) {
	RSG::light_storage->light_set_negative(p_light, p_enable);
}

void RenderingServerDefault::light_set_cull_mask(RID p_light, uint32_t p_mask) {
	RSG::light_storage->light_set_cull_mask(p_light, p_mask);
}

void RenderingServerDefault::light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) {
	RSG::light_storage->light_set_shadow_caster_mask(p_light, p_mask);
}

void RenderingServerDefault::light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) {
	RSG::light_storage->light_set_reverse_cull_face_mode(p_light, p_enabled);
}

void RenderingServerDefault::light_set_bake_mode(RID p_light, LightBakeMode p_bake_mode) {
	RSG::light_storage->light_set_bake_mode(p_light, p_bake_mode);
}

void RenderingServerDefault::light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) {
	RSG::light_storage->light_set_distance_fade(p_light, p_enabled, p_begin, p_shadow, p_length);
}

void RenderingServerDefault::light_omni_set_shadow_mode(RID p_light, LightOmniShadowMode p_mode) {
	RSG::light_storage->light_omni_set_shadow_mode(p_light, p_mode);
}

void RenderingServerDefault::light_directional_set_shadow_mode(RID p_light, LightDirectionalShadowMode p_mode) {
	RSG::light_storage->light_directional_set_shadow_mode(p_light, p_mode);
}

void RenderingServerDefault::light_directional_set_blend_splits(RID p_light, bool p_enable) {
	RSG::light_storage->light_directional_set_blend_splits(p_light, p_enable);
}

void RenderingServerDefault::light_directional_set_sky_mode(RID p_light, LightDirectionalSkyMode p_mode) {
	RSG::light_storage->light_directional_set_sky_mode(p_light, p_mode);
}

void RenderingServerDefault::light_area_set_size(RID p_light, const Vector2 &p_size) {
	RSG::light_storage->light_area_set_size(p_light, p_size);
}

void RenderingServerDefault::light_area_set_normalize_energy(RID p_light, bool p_enable) {
	RSG::light_storage->light_area_set_normalize_energy(p_light, p_enable);
}

void RenderingServerDefault::light_area_set_shading_method(RID p_light, LightAreaShadingMethod p_method) {
	RSG::light_storage->light_area_set_shading_method(p_light, p_method);
}

void RenderingServerDefault::light_area_set_stochastic_samples(RID p_light, int p_samples) {
	RSG::light_storage->light_area_set_stochastic_samples(p_light, p_samples);
}

RS::LightType RenderingServerDefault::light_get_type(RID p_light) const {
	return RSG::light_storage->light_get_type(p_light);
}

float RenderingServerDefault::light_get_param(RID p_light, LightParam p_param) const {
	return RSG::light_storage->light_get_param(p_light, p_param);
}

AABB RenderingServerDefault::light_get_aabb(RID p_light) const {
	return RSG::light_storage->light_get_aabb(p_light);
}

Vector2 RenderingServerDefault::light_area_get_size(RID p_light) const {
	return RSG::light_storage->light_area_get_size(p_light);
}

bool RenderingServerDefault::light_area_get_normalize_energy(RID p_light) const {
	return RSG::light_storage->light_area_get_normalize_energy(p_light);
}

RS::LightAreaShadingMethod RenderingServerDefault::light_area_get_shading_method(RID p_light) const {
	return RSG::light_storage->light_area_get_shading_method(p_light);
}

int RenderingServerDefault::light_area_get_stochastic_samples(RID p_light) const {
	return RSG::light_storage->light_area_get_stochastic_samples(p_light);
}

/* CAMERA API */

RID RenderingServerDefault::camera_create() {
	return scene_cull->camera_allocate();
}

void RenderingServerDefault::camera_set_perspective(RID p_camera, float p_fovy_degrees, float p_z_near, float p_z_far) {
	scene_cull->camera_set_perspective(p_camera, p_fovy_degrees, p_z_near, p_z_far);
}

void RenderingServerDefault::camera_set_transform(RID p_camera, const Transform3D &p_transform) {
	scene_cull->camera_set_transform(p_camera, p_transform);
}

void RenderingServerDefault::camera_set_cull_mask(RID p_camera, uint32_t p_layers) {
	scene_cull->camera_set_cull_mask(p_camera, p_layers);
}

void RenderingServerDefault::camera_set_environment(RID p_camera, RID p_env) {
	scene_cull->camera_set_environment(p_camera, p_env);
}

/* ENVIRONMENT API */

RID RenderingServerDefault::environment_create() {
	return environment_storage->environment_allocate();
}

void RenderingServerDefault::environment_set_background(RID p_env, EnvironmentBG p_bg) {
	environment_storage->environment_set_background(p_env, p_bg);
}

void RenderingServerDefault::environment_set_bg_color(RID p_env, const Color &p_color) {
	environment_storage->environment_set_bg_color(p_env, p_color);
}

void RenderingServerDefault::environment_set_bg_energy(RID p_env, float p_multiplier) {
	environment_storage->environment_set_bg_energy(p_env, p_multiplier);
}

void RenderingServerDefault::environment_set_ambient_light(RID p_env, const Color &p_color, EnvironmentAmbientSource p_ambient, float p_energy) {
	environment_storage->environment_set_ambient_light(p_env, p_color, p_ambient, p_energy);
}

void RenderingServerDefault::environment_set_ssao(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_power, float p_detail, float p_horizon, float p_sharpness, float p_light_affect, float p_ao_channel_affect) {
	environment_storage->environment_set_ssao(p_env, p_enable, p_radius, p_intensity, p_power, p_detail, p_horizon, p_sharpness, p_light_affect, p_ao_channel_affect);
}

void RenderingServerDefault::environment_set_ssil(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_sharpness, float p_normal_rejection) {
	environment_storage->environment_set_ssil(p_env, p_enable, p_radius, p_intensity, p_sharpness, p_normal_rejection);
}

void RenderingServerDefault::environment_set_ssao_quality(EnvironmentSSAOQuality p_quality, bool p_half_size, int p_blur_passes) {
	environment_storage->set_ssao_quality(int(p_quality), p_half_size, p_blur_passes);
}

void RenderingServerDefault::environment_set_ssil_quality(EnvironmentSSILQuality p_quality, bool p_half_size, int p_blur_passes) {
	environment_storage->set_ssil_quality(int(p_quality), p_half_size, p_blur_passes);
}

/* SCENARIO API */

RID RenderingServerDefault::scenario_create() {
	return scene_cull->scenario_allocate();
}

RID RenderingServerDefault::sky_material_create() {
	return environment_storage->sky_material_allocate();
}

void RenderingServerDefault::sky_material_set_procedural(RID p_material, const ProceduralSkyParams &p_params) {
	environment_storage->sky_material_set_procedural(p_material, p_params);
}

void RenderingServerDefault::sky_material_set_physical(RID p_material, const PhysicalSkyParams &p_params) {
	environment_storage->sky_material_set_physical(p_material, p_params);
}

void RenderingServerDefault::environment_set_reflection_source(RID p_env, EnvironmentReflectionSource p_source) {
	environment_storage->environment_set_reflection_source(p_env, p_source);
}

RID RenderingServerDefault::sky_create() {
	return environment_storage->sky_allocate();
}

void RenderingServerDefault::sky_set_material(RID p_sky, RID p_material) {
	environment_storage->sky_set_material(p_sky, p_material);
}

void RenderingServerDefault::sky_set_radiance_size(RID p_sky, int p_size) {
	environment_storage->sky_set_radiance_size(p_sky, p_size);
}

void RenderingServerDefault::environment_set_sky(RID p_env, RID p_sky) {
	environment_storage->environment_set_sky(p_env, p_sky);
}

void RenderingServerDefault::environment_set_ambient_sky_contribution(RID p_env, float p_contribution) {
	environment_storage->environment_set_ambient_sky_contribution(p_env, p_contribution);
}

void RenderingServerDefault::scenario_set_environment(RID p_scenario, RID p_environment) {
	scene_cull->scenario_set_environment(p_scenario, p_environment);
}

/* INSTANCE API */

RID RenderingServerDefault::instance_create() {
	return scene_cull->instance_allocate();
}

void RenderingServerDefault::instance_set_base(RID p_instance, RID p_base) {
	scene_cull->instance_set_base(p_instance, p_base);
}

void RenderingServerDefault::instance_set_scenario(RID p_instance, RID p_scenario) {
	scene_cull->instance_set_scenario(p_instance, p_scenario);
}

void RenderingServerDefault::instance_set_transform(RID p_instance, const Transform3D &p_transform) {
	scene_cull->instance_set_transform(p_instance, p_transform);
}

void RenderingServerDefault::instance_set_visible(RID p_instance, bool p_visible) {
	scene_cull->instance_set_visible(p_instance, p_visible);
}

void RenderingServerDefault::instance_set_layer_mask(RID p_instance, uint32_t p_mask) {
	scene_cull->instance_set_layer_mask(p_instance, p_mask);
}

void RenderingServerDefault::instance_geometry_set_material_override(RID p_instance, RID p_material) {
	scene_cull->instance_geometry_set_material_override(p_instance, p_material);
}

void RenderingServerDefault::instance_geometry_set_cast_shadows_setting(RID p_instance, ShadowCastingSetting p_setting) {
	scene_cull->instance_geometry_set_cast_shadows_setting(p_instance, p_setting);
}

AABB RenderingServerDefault::instance_get_aabb(RID p_instance) const {
	return scene_cull->instance_get_aabb(p_instance);
}

/* VIEWPORT API */

RID RenderingServerDefault::viewport_create() {
	RID rid = viewport_owner.make_rid();
	viewport_order.push_back(rid);
	return rid;
}

void RenderingServerDefault::viewport_set_size(RID p_viewport, int p_width, int p_height) {
	Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_MSG(viewport, "Invalid viewport RID.");
	ERR_FAIL_COND_MSG(p_width < 0 || p_height < 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE,
			vformat("Viewport size %dx%d is invalid (0..%d per side).", p_width, p_height, Image::MAX_SIZE));
	if (viewport->width == p_width && viewport->height == p_height && (viewport->render_target.is_valid() || p_width == 0 || p_height == 0)) {
		return;
	}
	if (viewport->render_target.is_valid()) {
		RSG::scene_render->render_target_free(viewport->render_target);
		viewport->render_target = RID();
	}
	viewport->width = p_width;
	viewport->height = p_height;
	if (p_width > 0 && p_height > 0) {
		viewport->render_target = RSG::scene_render->render_target_create(p_width, p_height);
	}
}

void RenderingServerDefault::viewport_set_active(RID p_viewport, bool p_active) {
	Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_MSG(viewport, "Invalid viewport RID.");
	viewport->active = p_active;
}

void RenderingServerDefault::viewport_attach_camera(RID p_viewport, RID p_camera) {
	Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_MSG(viewport, "Invalid viewport RID.");
	ERR_FAIL_COND_MSG(p_camera.is_valid() && !scene_cull->is_camera(p_camera), "Invalid camera RID.");
	viewport->camera = p_camera;
}

void RenderingServerDefault::viewport_set_scenario(RID p_viewport, RID p_scenario) {
	Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_MSG(viewport, "Invalid viewport RID.");
	ERR_FAIL_COND_MSG(p_scenario.is_valid() && !scene_cull->is_scenario(p_scenario), "Invalid scenario RID.");
	viewport->scenario = p_scenario;
}

void RenderingServerDefault::viewport_set_debug_draw(RID p_viewport, ViewportDebugDraw p_draw) {
	Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_MSG(viewport, "Invalid viewport RID.");
	ERR_FAIL_INDEX_MSG((int)p_draw, (int)VIEWPORT_DEBUG_DRAW_CLUSTER_AREA_LIGHTS + 1, "Debug draw mode is not a ViewportDebugDraw value."); // The last value (godot-area's addition).
	viewport->debug_draw = p_draw;
}

Image RenderingServerDefault::viewport_get_texture_data(RID p_viewport) const {
	const Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_V_MSG(viewport, Image(), "Invalid viewport RID.");
	if (viewport->render_target.is_null()) {
		return Image();
	}
	Image image;
	const std::vector<float> data = RSG::scene_render->render_target_get_data(viewport->render_target);
	ERR_FAIL_COND_V_MSG(!image.set_data(viewport->width, viewport->height, data), Image(), "The renderer returned render target data of the wrong size.");
	return image;
}

RID RenderingServerDefault::viewport_get_texture(RID p_viewport) const {
	const Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_V_MSG(viewport, RID(), "Invalid viewport RID.");
	return viewport->render_target.is_null() ? RID() : RSG::scene_render->render_target_get_color_texture(viewport->render_target);
}

void RenderingServerDefault::area_shadow_atlas_set_size(RID p_viewport, int p_size, int p_subdivision) {
	Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_MSG(viewport, "area_shadow_atlas_set_size: invalid viewport RID.");
	if (p_size == 0) {
		viewport->area_shadow_atlas_size = 0; // Back to the renderer's default.
		viewport->area_shadow_atlas_subdivision = 0;
		return;
	}
	ERR_FAIL_COND_MSG(p_size < AREA_SHADOW_ATLAS_SIZE_MIN || p_size > AREA_SHADOW_ATLAS_SIZE_MAX || (p_size & (p_size - 1)) != 0,
			vformat("area_shadow_atlas_set_size: the size must be a power of two from %d to %d (or 0 for the default); got %d. The old size is kept.", AREA_SHADOW_ATLAS_SIZE_MIN, AREA_SHADOW_ATLAS_SIZE_MAX, p_size));
	ERR_FAIL_COND_MSG(p_subdivision < AREA_SHADOW_ATLAS_SUBDIVISION_MIN || p_subdivision > AREA_SHADOW_ATLAS_SUBDIVISION_MAX,
			vformat("area_shadow_atlas_set_size: the subdivision (tiles per side) must be %d..%d; got %d. The old size is kept.", AREA_SHADOW_ATLAS_SUBDIVISION_MIN, AREA_SHADOW_ATLAS_SUBDIVISION_MAX, p_subdivision));
	ERR_FAIL_COND_MSG(p_size / p_subdivision < 16,
			vformat("area_shadow_atlas_set_size: %d px split into %d x %d tiles leaves %d px per tile; tiles need at least 16 px. The old size is kept.", p_size, p_subdivision, p_subdivision, p_size / p_subdivision));
	viewport->area_shadow_atlas_size = p_size;
	viewport->area_shadow_atlas_subdivision = p_subdivision;
}

int RenderingServerDefault::area_shadow_atlas_get_size(RID p_viewport) const {
	const Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_V_MSG(viewport, 0, "area_shadow_atlas_get_size: invalid viewport RID.");
	return viewport->area_shadow_atlas_size;
}

int RenderingServerDefault::area_shadow_atlas_get_subdivision(RID p_viewport) const {
	const Viewport *viewport = viewport_owner.get_or_null(p_viewport);
	ERR_FAIL_NULL_V_MSG(viewport, 0, "area_shadow_atlas_get_subdivision: invalid viewport RID.");
	return viewport->area_shadow_atlas_subdivision;
}

/* MISC */

void RenderingServerDefault::set_default_clear_color(const Color &p_color) {
	ERR_FAIL_COND_MSG(!p_color.is_finite(), "Default clear colour must be finite.");
	default_clear_color = p_color;
}

Color RenderingServerDefault::get_default_clear_color() const {
	return default_clear_color;
}

void RenderingServerDefault::draw() {
	compositor->begin_frame();
	frame_area_shadow_tests = 0;
	for (uint64_t &info : frame_rendering_info) {
		info = 0;
	}
	for (const RID &rid : viewport_order) {
		const Viewport *viewport = viewport_owner.get_or_null(rid);
		if (!viewport || !viewport->active || viewport->render_target.is_null()) {
			continue;
		}
		if (!scene_cull->is_camera(viewport->camera) || !scene_cull->is_scenario(viewport->scenario)) {
			continue;
		}
		scene_cull->render_camera(viewport->camera, viewport->scenario, viewport->width, viewport->height, default_clear_color, viewport->debug_draw, viewport->render_target, viewport->area_shadow_atlas_size, viewport->area_shadow_atlas_subdivision);
		frame_area_shadow_tests += RSG::scene_render->get_last_frame_area_shadow_tests();
		for (int i = 0; i < RS::RENDERING_INFO_MAX; i++) {
			frame_rendering_info[i] += RSG::scene_render->get_last_frame_rendering_info(RS::RenderingInfo(i));
		}
	}
	compositor->end_frame();
}

void RenderingServerDefault::free(RID p_rid) {
	ERR_FAIL_COND_MSG(p_rid.is_null(), "Cannot free a null RID.");
	if (Viewport *viewport = viewport_owner.get_or_null(p_rid)) {
		if (viewport->render_target.is_valid()) {
			RSG::scene_render->render_target_free(viewport->render_target);
		}
		viewport_owner.free(p_rid);
		viewport_order.erase(std::remove(viewport_order.begin(), viewport_order.end(), p_rid), viewport_order.end());
		return;
	}
	if (scene_cull->free(p_rid)) {
		// Forget a freed camera or scenario in every viewport.
		for (const RID &rid : viewport_order) {
			Viewport *viewport = viewport_owner.get_or_null(rid);
			if (viewport && viewport->camera == p_rid) {
				viewport->camera = RID();
			}
			if (viewport && viewport->scenario == p_rid) {
				viewport->scenario = RID();
			}
		}
		return;
	}
	if (RSG::light_storage->light_free(p_rid) || RSG::mesh_storage->mesh_free(p_rid) || RSG::material_storage->material_free(p_rid)) {
		scene_cull->notify_base_freed(p_rid);
		return;
	}
	if (RSG::material_storage->texture_free(p_rid)) {
		return;
	}
	if (environment_storage->environment_free(p_rid)) {
		scene_cull->notify_environment_freed(p_rid);
		return;
	}
	if (environment_storage->sky_free(p_rid)) {
		return;
	}
	ERR_PRINT(vformat("Attempted to free an invalid or already freed RID (id %llu).", (unsigned long long)p_rid.get_id()));
}

std::vector<std::pair<String, double>> RenderingServerDefault::get_frame_profile() const {
	return RSG::scene_render->get_last_frame_profile();
}

void RenderingServerDefault::area_shadow_filter_set_mode(AreaShadowFilter p_filter) {
	ERR_FAIL_COND_MSG(p_filter < 0 || p_filter >= AREA_SHADOW_FILTER_MAX, vformat("area_shadow_filter_set_mode: the filter must be 0 (PCF) or 1 (PENUMBRA); got %d. The old one is kept.", int(p_filter)));
	RSG::scene_render->area_shadow_filter_set_mode(p_filter);
}

RS::AreaShadowFilter RenderingServerDefault::area_shadow_filter_get_mode() const {
	return RSG::scene_render->area_shadow_filter_get_mode();
}

void RenderingServerDefault::set_debug_disable_area_lights(bool p_disable) {
	RSG::scene_render->set_debug_disable_area_lights(p_disable);
}

std::vector<std::pair<String, String>> RenderingServerDefault::get_debug_scene_shader_sources() const {
	return RSG::scene_render->get_debug_scene_shader_sources();
}

void RenderingServerDefault::set_debug_force_all_lights(bool p_enable) {
	RSG::scene_render->set_debug_force_all_lights(p_enable);
}

/* Area light shadows */

void RenderingServerDefault::light_area_set_shadow_mode(RID p_light, LightAreaShadowMode p_mode) {
	RSG::light_storage->light_area_set_shadow_mode(p_light, p_mode);
}

void RenderingServerDefault::light_area_set_shadow_grid(RID p_light, int p_grid) {
	RSG::light_storage->light_area_set_shadow_grid(p_light, p_grid);
}

void RenderingServerDefault::light_area_set_shape(RID p_light, LightAreaShape p_shape) {
	RSG::light_storage->light_area_set_shape(p_light, p_shape);
}

RS::LightAreaShadowMode RenderingServerDefault::light_area_get_shadow_mode(RID p_light) const {
	return RSG::light_storage->light_area_get_shadow_mode(p_light);
}

int RenderingServerDefault::light_area_get_shadow_grid(RID p_light) const {
	return RSG::light_storage->light_area_get_shadow_grid(p_light);
}

RS::LightAreaShape RenderingServerDefault::light_area_get_shape(RID p_light) const {
	return RSG::light_storage->light_area_get_shape(p_light);
}

void RenderingServerDefault::light_area_set_texture(RID p_light, RID p_texture) {
	ERR_FAIL_COND_MSG(p_texture.is_valid() && !RSG::material_storage->owns_texture(p_texture), "light_area_set_texture: the texture RID is not a texture of this renderer (freed, or another kind of RID); the old texture is kept.");
	RSG::light_storage->light_area_set_texture(p_light, p_texture);
}

RID RenderingServerDefault::light_area_get_texture(RID p_light) const {
	return RSG::light_storage->light_area_get_texture(p_light);
}
