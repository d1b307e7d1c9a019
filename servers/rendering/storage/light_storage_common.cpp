/**************************************************************************/
/*  light_storage_common.cpp                                              */
/**************************************************************************/

#include "servers/rendering/storage/light_storage_common.h"

#include "core/error/error_macros.h"

#include <cmath>

LightStorageCommon::LightStorageCommon(const char *p_owner_name, RS::LightOmniShadowMode p_default_omni_shadow_mode) :
		light_owner(p_owner_name), default_omni_shadow_mode(p_default_omni_shadow_mode) {}

LightStorageCommon::LightRecord *LightStorageCommon::_get_light(RID p_light, const char *p_caller) const {
	LightRecord *light = light_owner.get_or_null(p_light);
	if (!light) {
		ERR_PRINT(vformat("%s: Invalid light RID (not created by this light storage, or already freed).", p_caller));
	}
	return light;
}

#define GET_LIGHT_OR_FAIL(m_var)                            \
	LightRecord *m_var = _get_light(p_light, __FUNCTION__); \
	if (!m_var) {                                           \
		return;                                             \
	}

#define GET_LIGHT_OR_FAIL_V(m_var, m_ret)                         \
	const LightRecord *m_var = _get_light(p_light, __FUNCTION__); \
	if (!m_var) {                                                 \
		return m_ret;                                             \
	}

RID LightStorageCommon::light_create(RS::LightType p_type) {
	ERR_FAIL_INDEX_V_MSG((int)p_type, (int)RS::LIGHT_AREA + 1, RID(), "light_create: type is not a LightType value.");
	LightRecord light;
	light.type = p_type;
	light.omni_shadow_mode = default_omni_shadow_mode;
	for (int i = 0; i < RS::LIGHT_PARAM_MAX; i++) {
		light.param[i] = get_default_param(p_type, RS::LightParam(i));
	}
	return light_owner.make_rid(light);
}

bool LightStorageCommon::light_free(RID p_rid) {
	if (!light_owner.owns(p_rid)) {
		return false;
	}
	light_owner.free(p_rid);
	return true;
}

void LightStorageCommon::light_set_param(RID p_light, RS::LightParam p_param, float p_value) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_param, (int)RS::LIGHT_PARAM_MAX, "light_set_param: parameter is not a LightParam value.");
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
			light->version++; // Culling bounds or cached shadows change.
			break;
		default:
			break;
	}
}

void LightStorageCommon::light_set_color(RID p_light, const Color &p_color) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(!p_color.is_finite(), "light_set_color: colour must be finite; the old value is kept.");
	light->color = p_color;
}

void LightStorageCommon::light_set_shadow(RID p_light, bool p_enabled) {
	GET_LIGHT_OR_FAIL(light);
	if (light->shadow == p_enabled) {
		return;
	}
	light->shadow = p_enabled;
	light->version++;
}

void LightStorageCommon::light_set_negative(RID p_light, bool p_enable) {
	GET_LIGHT_OR_FAIL(light);
	light->negative = p_enable;
}

void LightStorageCommon::light_set_cull_mask(RID p_light, uint32_t p_mask) {
	GET_LIGHT_OR_FAIL(light);
	if (light->cull_mask == p_mask) {
		return;
	}
	light->cull_mask = p_mask;
	light->version++;
}

void LightStorageCommon::light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) {
	GET_LIGHT_OR_FAIL(light);
	if (light->shadow_caster_mask == p_mask) {
		return;
	}
	light->shadow_caster_mask = p_mask;
	light->version++;
}

void LightStorageCommon::light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) {
	GET_LIGHT_OR_FAIL(light);
	if (light->reverse_cull == p_enabled) {
		return;
	}
	light->reverse_cull = p_enabled;
	light->version++;
}

void LightStorageCommon::light_set_bake_mode(RID p_light, RS::LightBakeMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_BAKE_DYNAMIC + 1, "light_set_bake_mode: mode is not a LightBakeMode value.");
	light->bake_mode = p_mode;
}

void LightStorageCommon::light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(!std::isfinite(p_begin) || !std::isfinite(p_shadow) || !std::isfinite(p_length), "light_set_distance_fade: distances must be finite; the old values are kept.");
	ERR_FAIL_COND_MSG(p_begin < 0.0f || p_shadow < 0.0f || p_length < 0.0f, "light_set_distance_fade: distances must not be negative; the old values are kept.");
	light->distance_fade = p_enabled;
	light->distance_fade_begin = p_begin;
	light->distance_fade_shadow = p_shadow;
	light->distance_fade_length = p_length;
}

void LightStorageCommon::light_omni_set_shadow_mode(RID p_light, RS::LightOmniShadowMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_OMNI_SHADOW_CUBE + 1, "light_omni_set_shadow_mode: mode is not a LightOmniShadowMode value.");
	if (light->omni_shadow_mode == p_mode) {
		return;
	}
	light->omni_shadow_mode = p_mode;
	light->version++;
}

void LightStorageCommon::light_directional_set_shadow_mode(RID p_light, RS::LightDirectionalShadowMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS + 1, "light_directional_set_shadow_mode: mode is not a LightDirectionalShadowMode value.");
	if (light->directional_shadow_mode == p_mode) {
		return;
	}
	light->directional_shadow_mode = p_mode;
	light->version++;
}

void LightStorageCommon::light_directional_set_blend_splits(RID p_light, bool p_enable) {
	GET_LIGHT_OR_FAIL(light);
	if (light->directional_blend_splits == p_enable) {
		return;
	}
	light->directional_blend_splits = p_enable;
	light->version++;
}

void LightStorageCommon::light_directional_set_sky_mode(RID p_light, RS::LightDirectionalSkyMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_DIRECTIONAL_SKY_MODE_SKY_ONLY + 1, "light_directional_set_sky_mode: mode is not a LightDirectionalSkyMode value.");
	light->directional_sky_mode = p_mode;
}

void LightStorageCommon::light_area_set_size(RID p_light, const Vector2 &p_size) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_size: the light is not an area light.");
	if (!validate_area_size(p_size)) {
		return;
	}
	if (light->area_size == p_size) {
		return;
	}
	light->area_size = p_size;
	light->version++; // Culling bounds change.
}

void LightStorageCommon::light_area_set_normalize_energy(RID p_light, bool p_enable) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_normalize_energy: the light is not an area light.");
	light->area_normalize_energy = p_enable;
}

void LightStorageCommon::light_area_set_shading_method(RID p_light, RS::LightAreaShadingMethod p_method) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_shading_method: the light is not an area light.");
	ERR_FAIL_INDEX_MSG((int)p_method, (int)RS::LIGHT_AREA_SHADING_MAX, vformat("light_area_set_shading_method: %d is not a LightAreaShadingMethod value (0..%d).", (int)p_method, (int)RS::LIGHT_AREA_SHADING_MAX - 1));
	light->area_shading_method = p_method;
}

void LightStorageCommon::light_area_set_stochastic_samples(RID p_light, int p_samples) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_stochastic_samples: the light is not an area light.");
	ERR_FAIL_COND_MSG(p_samples < RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN || p_samples > RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MAX,
			vformat("light_area_set_stochastic_samples: %d samples is out of range (%d..%d).", p_samples, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MAX));
	light->area_stochastic_samples = p_samples;
}

Vector2 LightStorageCommon::light_area_get_size(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, Vector2());
	return light->area_size;
}

bool LightStorageCommon::light_area_get_normalize_energy(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->area_normalize_energy;
}

RS::LightAreaShadingMethod LightStorageCommon::light_area_get_shading_method(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHADING_LTC);
	return light->area_shading_method;
}

int LightStorageCommon::light_area_get_stochastic_samples(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT);
	return light->area_stochastic_samples;
}

RS::LightType LightStorageCommon::light_get_type(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_DIRECTIONAL);
	return light->type;
}

float LightStorageCommon::light_get_param(RID p_light, RS::LightParam p_param) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	ERR_FAIL_INDEX_V_MSG((int)p_param, (int)RS::LIGHT_PARAM_MAX, 0.0f, "light_get_param: parameter is not a LightParam value.");
	return light->param[p_param];
}

Color LightStorageCommon::light_get_color(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, Color());
	return light->color;
}

bool LightStorageCommon::light_has_shadow(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->shadow;
}

bool LightStorageCommon::light_is_negative(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->negative;
}

uint32_t LightStorageCommon::light_get_cull_mask(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0);
	return light->cull_mask;
}

uint32_t LightStorageCommon::light_get_shadow_caster_mask(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0);
	return light->shadow_caster_mask;
}

bool LightStorageCommon::light_get_reverse_cull_face_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->reverse_cull;
}

RS::LightBakeMode LightStorageCommon::light_get_bake_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_BAKE_DISABLED);
	return light->bake_mode;
}

bool LightStorageCommon::light_is_distance_fade_enabled(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->distance_fade;
}

float LightStorageCommon::light_get_distance_fade_begin(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	return light->distance_fade_begin;
}

float LightStorageCommon::light_get_distance_fade_shadow(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	return light->distance_fade_shadow;
}

float LightStorageCommon::light_get_distance_fade_length(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0.0f);
	return light->distance_fade_length;
}

RS::LightOmniShadowMode LightStorageCommon::light_omni_get_shadow_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_OMNI_SHADOW_CUBE);
	return light->omni_shadow_mode;
}

RS::LightDirectionalShadowMode LightStorageCommon::light_directional_get_shadow_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL);
	return light->directional_shadow_mode;
}

bool LightStorageCommon::light_directional_get_blend_splits(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, false);
	return light->directional_blend_splits;
}

RS::LightDirectionalSkyMode LightStorageCommon::light_directional_get_sky_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY);
	return light->directional_sky_mode;
}

AABB LightStorageCommon::light_get_aabb(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, AABB());
	// Area lights: thesis Listing A.1 (see compute_area_light_aabb).
	return compute_light_aabb(light->type, light->param[RS::LIGHT_PARAM_RANGE], light->param[RS::LIGHT_PARAM_SPOT_ANGLE], light->area_size, light->area_shape);
}

uint64_t LightStorageCommon::light_get_version(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, 0);
	return light->version;
}

/* Area light shadows */

void LightStorageCommon::light_area_set_shadow_mode(RID p_light, RS::LightAreaShadowMode p_mode) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_shadow_mode: the light is not an area light.");
	ERR_FAIL_INDEX_MSG((int)p_mode, (int)RS::LIGHT_AREA_SHADOW_MAX, vformat("light_area_set_shadow_mode: %d is not a LightAreaShadowMode value (0..%d).", (int)p_mode, (int)RS::LIGHT_AREA_SHADOW_MAX - 1));
	if (light->area_shadow_mode == p_mode) {
		return;
	}
	light->area_shadow_mode = p_mode;
	light->version++; // Cached shadow maps change.
}

void LightStorageCommon::light_area_set_shadow_grid(RID p_light, int p_grid) {
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

RS::LightAreaShadowMode LightStorageCommon::light_area_get_shadow_mode(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHADOW_FIXED);
	return light->area_shadow_mode;
}

void LightStorageCommon::light_area_set_shape(RID p_light, RS::LightAreaShape p_shape) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_shape: the light is not an area light.");
	ERR_FAIL_INDEX_MSG((int)p_shape, (int)RS::LIGHT_AREA_SHAPE_MAX, vformat("light_area_set_shape: %d is not a LightAreaShape value (0..%d); the old shape is kept.", (int)p_shape, (int)RS::LIGHT_AREA_SHAPE_MAX - 1));
	if (light->area_shape == p_shape) {
		return;
	}
	light->area_shape = p_shape;
	light->version++; // Culling bounds and shadow sample points change.
}

RS::LightAreaShape LightStorageCommon::light_area_get_shape(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHAPE_RECTANGLE);
	return light->area_shape;
}

int LightStorageCommon::light_area_get_shadow_grid(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RS::LIGHT_AREA_SHADOW_GRID_DEFAULT);
	return light->area_shadow_grid;
}

void LightStorageCommon::light_area_set_texture(RID p_light, RID p_texture) {
	GET_LIGHT_OR_FAIL(light);
	ERR_FAIL_COND_MSG(light->type != RS::LIGHT_AREA, "light_area_set_texture: the light is not an area light.");
	// No version bump: the texture changes neither the culling bounds nor the shadows.
	light->area_texture = p_texture;
}

RID LightStorageCommon::light_area_get_texture(RID p_light) const {
	GET_LIGHT_OR_FAIL_V(light, RID());
	return light->area_texture;
}
