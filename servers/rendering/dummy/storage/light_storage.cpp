/**************************************************************************/
/*  light_storage.cpp                                                     */
/**************************************************************************/

#include "servers/rendering/dummy/storage/light_storage.h"

#include "core/error/error_macros.h"

#include <cmath>

using namespace RendererDummy;

#define GET_LIGHT_OR_FAIL(m_var) \
	Light *m_var = light_owner.get_or_null(p_light); \
	ERR_FAIL_NULL_MSG(m_var, "Invalid light RID.")

#define GET_LIGHT_OR_FAIL_V(m_var, m_ret) \
	const Light *m_var = light_owner.get_or_null(p_light); \
	ERR_FAIL_NULL_V_MSG(m_var, m_ret, "Invalid light RID.")

RID LightStorage::light_create(RS::LightType p_type) {
	ERR_FAIL_INDEX_V_MSG((int)p_type, (int)RS::LIGHT_AREA + 1, RID(), "Light type is not a LightType value.");
	Light light;
	light.type = p_type;
	for (int i = 0; i < RS::LIGHT_PARAM_MAX; i++) {
		light.param[i] = get_default_param(p_type, RS::LightParam(i));
	}
	return light_owner.make_rid(light);
}

bool LightStorage::light_free(RID p_rid) {
	if (!light_owner.owns(p_rid)) {
		return false;
	}
	light_owner.free(p_rid);
	return true;
}

void LightStorage::light_set_param(RID p_light, RS::LightParam p_param, float p_value) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_param, (int)RS::LIGHT_PARAM_MAX, "Light parameter is not a LightParam value.");
	if (!validate_param(light->type, p_param, p_value)) {
		return;
	}
	if (light->param[p_param] == p_value) {
		return;
	}
	light->param[p_param] = p_value;
	switch (p_param) {
		case RS::LIGHT_PARAM_RANGE:
		case RS::LIGHT_PARAM_SPOT_ANGLE:
		case RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE:
		case RS::LIGHT_PARAM_SHADOW_SPLIT_1_OFFSET:
		case RS::LIGHT_PARAM_SHADOW_SPLIT_2_OFFSET:
		case RS::LIGHT_PARAM_SHADOW_SPLIT_3_OFFSET:
		case RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS:
		case RS::LIGHT_PARAM_SHADOW_BIAS:
		case RS::LIGHT_PARAM_SHADOW_PANCAKE_SIZE:
			light->version++; // Culling bound or cached shadows change.
			break;
		default:
			break;
	}
}

void LightStorage::light_set_color(RID p_light, const Color &p_color) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(!p_color.is_finite(), "Light colour must be finite; the old value is kept.");
	light->color = p_color;
}

void LightStorage::light_set_shadow(RID p_light, bool p_enabled) {
	GET_LIGHT_OR_FAIL(light);
	if (light->shadow == p_enabled) {
		return;
	}
	light->shadow = p_enabled;
	light->version++;
}

void LightStorage::light_set_negative(RID p_light, bool p_enable) {
	GET_LIGHT_OR_FAIL(light);
	light->negative = p_enable;
}

void LightStorage::light_set_cull_mask(RID p_light, uint32_t p_mask) {
	GET_LIGHT_OR_FAIL(light);
	if (light->cull_mask == p_mask) {
		return;
	}
	light->cull_mask = p_mask;
	light->version++;
}

void LightStorage::light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) {
	GET_LIGHT_OR_FAIL(light);
	if (light->shadow_caster_mask == p_mask) {
		return;
	}
	light->shadow_caster_mask = p_mask;
	light->version++;
}

void LightStorage::light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) {
	GET_LIGHT_OR_FAIL(light);
	if (light->reverse_cull == p_enabled) {
		return;
	}
	light->reverse_cull = p_enabled;
	light->version++;
}

void LightStorage::light_set_bake_mode(RID p_light, RS::LightBakeMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_BAKE_DYNAMIC + 1, "Bake mode is not a LightBakeMode value.");
	light->bake_mode = p_mode;
}

void LightStorage::light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(!std::isfinite(p_begin) || !std::isfinite(p_shadow) || !std::isfinite(p_length), "Distance fade begin, shadow and length must be finite; the old values are kept.");
	ERR_FAIL_COND_MSG(p_begin < 0.0f || p_shadow < 0.0f || p_length < 0.0f, "Distance fade begin, shadow and length must not be negative; the old values are kept.");
	light->distance_fade = p_enabled;
	light->distance_fade_begin = p_begin;
	light->distance_fade_shadow = p_shadow;
	light->distance_fade_length = p_length;
}

void LightStorage::light_omni_set_shadow_mode(RID p_light, RS::LightOmniShadowMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_OMNI_SHADOW_CUBE + 1, "Omni shadow mode is not a LightOmniShadowMode value.");
	if (light->omni_shadow_mode == p_mode) {
		return;
	}
	light->omni_shadow_mode = p_mode;
	light->version++;
}

void LightStorage::light_directional_set_shadow_mode(RID p_light, RS::LightDirectionalShadowMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS + 1, "Directional shadow mode is not a LightDirectionalShadowMode value.");
	if (light->directional_shadow_mode == p_mode) {
		return;
	}
	light->directional_shadow_mode = p_mode;
	light->version++;
}

void LightStorage::light_directional_set_blend_splits(RID p_light, bool p_enable) {
	GET_LIGHT_OR_FAIL(light);
	light->directional_blend_splits = p_enable;
}

void LightStorage::light_directional_set_sky_mode(RID p_light, RS::LightDirectionalSkyMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_DIRECTIONAL_SKY_MODE_SKY_ONLY + 1, "Sky mode is not a LightDirectionalSkyMode value.");
	light->directional_sky_mode = p_mode;
}

void LightStorage::light_area_set_size(RID p_light, const Vector2 &p_size) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_size: the light is not an area light.");
	if (!validate_area_size(p_size)) {
		return;
	}
	if (light->area_size == p_size) {
		return;
	}
	light->area_size = p_size;
	light->version++; // The culling sphere and bound change.
}

void LightStorage::light_area_set_normalize_energy(RID p_light, bool p_enable) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_normalize_energy: the light is not an area light.");
	light->area_normalize_energy = p_enable;
}

void LightStorage::light_area_set_shading_method(RID p_light, RS::LightAreaShadingMethod p_method) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_shading_method: the light is not an area light.");
	ERR_FAIL_INDEX_MSG((int)p_method, (int)RS::LIGHT_AREA_SHADING_MAX, vformat("light_area_set_shading_method: %d is not a LightAreaShadingMethod value (0..%d).", (int)p_method, (int)RS::LIGHT_AREA_SHADING_MAX - 1));
	light->area_shading_method = p_method;
}

void LightStorage::light_area_set_stochastic_samples(RID p_light, int p_samples) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_stochastic_samples: the light is not an area light.");
	ERR_FAIL_COND_MSG(p_samples < RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN || p_samples > RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MAX,
			vformat("light_area_set_stochastic_samples: %d samples is out of range (%d..%d).", p_samples, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MAX));
	light->area_stochastic_samples = p_samples;
}

RS::LightType LightStorage::light_get_type(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_DIRECTIONAL);
	return light->type;
}

float LightStorage::light_get_param(RID p_light, RS::LightParam p_param) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	ERR_FAIL_INDEX_V_MSG((int)p_param, (int)RS::LIGHT_PARAM_MAX, 0.0f, "Light parameter is not a LightParam value.");
	return light->param[p_param];
}

Color LightStorage::light_get_color(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, Color());
	return light->color;
}

bool LightStorage::light_has_shadow(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->shadow;
}

bool LightStorage::light_is_negative(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->negative;
}

uint32_t LightStorage::light_get_cull_mask(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0);
	return light->cull_mask;
}

uint32_t LightStorage::light_get_shadow_caster_mask(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0);
	return light->shadow_caster_mask;
}

bool LightStorage::light_get_reverse_cull_face_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->reverse_cull;
}

RS::LightBakeMode LightStorage::light_get_bake_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_BAKE_DISABLED);
	return light->bake_mode;
}

bool LightStorage::light_is_distance_fade_enabled(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->distance_fade;
}

float LightStorage::light_get_distance_fade_begin(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	return light->distance_fade_begin;
}

float LightStorage::light_get_distance_fade_shadow(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	return light->distance_fade_shadow;
}

float LightStorage::light_get_distance_fade_length(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	return light->distance_fade_length;
}

RS::LightOmniShadowMode LightStorage::light_omni_get_shadow_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_OMNI_SHADOW_CUBE);
	return light->omni_shadow_mode;
}

RS::LightDirectionalShadowMode LightStorage::light_directional_get_shadow_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL);
	return light->directional_shadow_mode;
}

bool LightStorage::light_directional_get_blend_splits(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->directional_blend_splits;
}

RS::LightDirectionalSkyMode LightStorage::light_directional_get_sky_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY);
	return light->directional_sky_mode;
}

Vector2 LightStorage::light_area_get_size(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, Vector2());
	return light->area_size;
}

bool LightStorage::light_area_get_normalize_energy(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->area_normalize_energy;
}

RS::LightAreaShadingMethod LightStorage::light_area_get_shading_method(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHADING_LTC);
	return light->area_shading_method;
}

int LightStorage::light_area_get_stochastic_samples(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT);
	return light->area_stochastic_samples;
}

AABB LightStorage::light_get_aabb(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, AABB());
	return compute_light_aabb(light->type, light->param[RS::LIGHT_PARAM_RANGE], light->param[RS::LIGHT_PARAM_SPOT_ANGLE], light->area_size);
}

uint64_t LightStorage::light_get_version(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0);
	return light->version;
}

/* Area light shadows */

void LightStorage::light_area_set_shadow_mode(RID p_light, RS::LightAreaShadowMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_shadow_mode: the light is not an area light.");
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_AREA_SHADOW_MAX, vformat("light_area_set_shadow_mode: %d is not a LightAreaShadowMode value (0..%d).", (int)p_mode, (int)RS::LIGHT_AREA_SHADOW_MAX - 1));
	if (light->area_shadow_mode == p_mode) {
		return;
	}
	light->area_shadow_mode = p_mode;
	light->version++; // Cached shadow maps change.
}

void LightStorage::light_area_set_shadow_grid(RID p_light, int p_grid) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_shadow_grid: the light is not an area light.");
	ERR_FAIL_COND_MSG(p_grid < RS::LIGHT_AREA_SHADOW_GRID_MIN || p_grid > RS::LIGHT_AREA_SHADOW_GRID_MAX,
			vformat("light_area_set_shadow_grid: area_shadow_grid %d is out of range (%d..%d); the old value is kept.", p_grid, RS::LIGHT_AREA_SHADOW_GRID_MIN, RS::LIGHT_AREA_SHADOW_GRID_MAX));
	if (light->area_shadow_grid == p_grid) {
		return;
	}
	light->area_shadow_grid = p_grid;
	light->version++;
}

RS::LightAreaShadowMode LightStorage::light_area_get_shadow_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHADOW_FIXED);
	return light->area_shadow_mode;
}

int LightStorage::light_area_get_shadow_grid(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHADOW_GRID_DEFAULT);
	return light->area_shadow_grid;
}
