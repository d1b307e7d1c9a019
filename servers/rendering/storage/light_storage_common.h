/**************************************************************************/
/*  light_storage_common.h                                                */
/**************************************************************************/
/* godot-area: the CPU-side light record and its validated setters and    */
/* getters, shared by RendererDummy::LightStorage and                     */
/* RendererRD::LightStorage (GPU upload stays in the RD storage).         */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/storage/light_storage.h"

class LightStorageCommon : public RendererLightStorage {
protected:
	// One light as the storages keep it on the CPU.
	struct LightRecord {
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
		RS::LightOmniShadowMode omni_shadow_mode = RS::LIGHT_OMNI_SHADOW_CUBE;
		RS::LightDirectionalShadowMode directional_shadow_mode = RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL;
		bool directional_blend_splits = false;
		RS::LightDirectionalSkyMode directional_sky_mode = RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY;
		Vector2 area_size = RendererLightStorage::get_default_area_size(); // Metres, local X and Y.
		bool area_normalize_energy = true;
		RS::LightAreaShadingMethod area_shading_method = RS::LIGHT_AREA_SHADING_LTC;
		int area_stochastic_samples = RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT;
		RS::LightAreaShadowMode area_shadow_mode = RS::LIGHT_AREA_SHADOW_FIXED;
		int area_shadow_grid = RS::LIGHT_AREA_SHADOW_GRID_DEFAULT;
		RS::LightAreaShape area_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE;
		RID area_texture; // area_texture (a material storage texture), RID() for none.
		uint64_t version = 0;
	};

	mutable RID_Owner<LightRecord, true> light_owner;

	// Looks a light up; prints an error naming p_caller and returns null for an RID this storage does not own.
	LightRecord *_get_light(RID p_light, const char *p_caller) const;

	// p_owner_name names the RID owner in leak reports; p_default_omni_shadow_mode is the storage default of new lights.
	LightStorageCommon(const char *p_owner_name, RS::LightOmniShadowMode p_default_omni_shadow_mode);

private:
	RS::LightOmniShadowMode default_omni_shadow_mode = RS::LIGHT_OMNI_SHADOW_CUBE;

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
	void light_area_set_shape(RID p_light, RS::LightAreaShape p_shape) override;
	void light_area_set_texture(RID p_light, RID p_texture) override;

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
	RS::LightAreaShape light_area_get_shape(RID p_light) const override;
	RID light_area_get_texture(RID p_light) const override;
	AABB light_get_aabb(RID p_light) const override;
	uint64_t light_get_version(RID p_light) const override;
};
