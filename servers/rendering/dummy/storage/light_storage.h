/**************************************************************************/
/*  light_storage.h                                                       */
/**************************************************************************/
/* godot-area: CPU-only light storage (like Godot's dummy rasterizer),    */
/* used by the server when no GPU backend is plugged in, and by tests.    */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/storage/light_storage.h"

namespace RendererDummy {

class LightStorage : public RendererLightStorage {
	struct Light {
		RS::LightType type = RS::LIGHT_OMNI;
		float param[RS::LIGHT_PARAM_MAX] = {};
		Color color = Color(1, 1, 1, 1);
		bool shadow = false;
		bool negative = false;
		bool reverse_cull = false;
		uint32_t cull_mask = 0xFFFFFFFF;
		uint32_t shadow_caster_mask = 0xFFFFFFFF;
		RS::LightBakeMode bake_mode = RS::LIGHT_BAKE_DYNAMIC;
		bool distance_fade = false;
		float distance_fade_begin = 40.0f;
		float distance_fade_shadow = 50.0f;
		float distance_fade_length = 10.0f;
		RS::LightOmniShadowMode omni_shadow_mode = RS::LIGHT_OMNI_SHADOW_DUAL_PARABOLOID;
		RS::LightDirectionalShadowMode directional_shadow_mode = RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL;
		bool directional_blend_splits = false;
		RS::LightDirectionalSkyMode directional_sky_mode = RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY;
		Vector2 area_size = RendererLightStorage::get_default_area_size();
		bool area_normalize_energy = true;
		RS::LightAreaShadingMethod area_shading_method = RS::LIGHT_AREA_SHADING_LTC;
		int area_stochastic_samples = RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT;
		RS::LightAreaShadowMode area_shadow_mode = RS::LIGHT_AREA_SHADOW_FIXED;
		int area_shadow_grid = RS::LIGHT_AREA_SHADOW_GRID_DEFAULT;
		uint64_t version = 0;
	};

	mutable RID_Owner<Light, true> light_owner{ "Light" };

public:
	RID light_create(RS::LightType p_type) override;
	bool light_free(RID p_rid) override;
	bool owns_light(RID p_rid) const override { return light_owner.owns(p_rid); }

	void light_set_param(RID p_light, RS::LightParam p_param, float p_value) override;
	void light_set_color(RID p_light, const Color &p_color) override;
	void light_set_shadow(RID p_light, bool p_enabled) override;
	void light_set_negative(RID p_light, bool p_enable) override;
	void light_set_cull_mask(RID p_light, uint32_t p_mask) override;
	void light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) override;
	void light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) override;
	void light_set_bake_mode(RID p_light, RS::LightBakeMode p_mode) override;
	void light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) override;
	void light_omni_set_shadow_mode(RID p_light, RS::LightOmniShadowMode p_mode) override;
	void light_directional_set_shadow_mode(RID p_light, RS::LightDirectionalShadowMode p_mode) override;
	void light_directional_set_blend_splits(RID p_light, bool p_enable) override;
	void light_directional_set_sky_mode(RID p_light, RS::LightDirectionalSkyMode p_mode) override;
	void light_area_set_size(RID p_light, const Vector2 &p_size) override;
	void light_area_set_normalize_energy(RID p_light, bool p_enable) override;
	void light_area_set_shading_method(RID p_light, RS::LightAreaShadingMethod p_method) override;
	void light_area_set_stochastic_samples(RID p_light, int p_samples) override;
	void light_area_set_shadow_mode(RID p_light, RS::LightAreaShadowMode p_mode) override;
	void light_area_set_shadow_grid(RID p_light, int p_grid) override;

	RS::LightType light_get_type(RID p_light) const override;
	float light_get_param(RID p_light, RS::LightParam p_param) const override;
	Color light_get_color(RID p_light) const override;
	bool light_has_shadow(RID p_light) const override;
	bool light_is_negative(RID p_light) const override;
	uint32_t light_get_cull_mask(RID p_light) const override;
	uint32_t light_get_shadow_caster_mask(RID p_light) const override;
	bool light_get_reverse_cull_face_mode(RID p_light) const override;
	RS::LightBakeMode light_get_bake_mode(RID p_light) const override;
	bool light_is_distance_fade_enabled(RID p_light) const override;
	float light_get_distance_fade_begin(RID p_light) const override;
	float light_get_distance_fade_shadow(RID p_light) const override;
	float light_get_distance_fade_length(RID p_light) const override;
	RS::LightOmniShadowMode light_omni_get_shadow_mode(RID p_light) const override;
	RS::LightDirectionalShadowMode light_directional_get_shadow_mode(RID p_light) const override;
	bool light_directional_get_blend_splits(RID p_light) const override;
	RS::LightDirectionalSkyMode light_directional_get_sky_mode(RID p_light) const override;
	Vector2 light_area_get_size(RID p_light) const override;
	bool light_area_get_normalize_energy(RID p_light) const override;
	RS::LightAreaShadingMethod light_area_get_shading_method(RID p_light) const override;
	int light_area_get_stochastic_samples(RID p_light) const override;
	RS::LightAreaShadowMode light_area_get_shadow_mode(RID p_light) const override;
	int light_area_get_shadow_grid(RID p_light) const override;
	AABB light_get_aabb(RID p_light) const override;
	uint64_t light_get_version(RID p_light) const override;
};

} // namespace RendererDummy
