/**************************************************************************/
/*  light_storage.cpp                                                     */
/**************************************************************************/
/* godot-area: shared helpers of the abstract light storage.              */

#include "servers/rendering/storage/light_storage.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"

#include <cmath>

float RendererLightStorage::get_default_param(RS::LightType p_type, RS::LightParam p_param) {
	// Godot 4's storage defaults (LightStorage::_light_initialize), not the Light3D node defaults.
	switch (p_param) {
		case RS::LIGHT_PARAM_ENERGY:
		case RS::LIGHT_PARAM_INDIRECT_ENERGY:
		case RS::LIGHT_PARAM_VOLUMETRIC_FOG_ENERGY:
		case RS::LIGHT_PARAM_RANGE:
		case RS::LIGHT_PARAM_ATTENUATION:
		case RS::LIGHT_PARAM_SPOT_ATTENUATION:
		case RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS:
		case RS::LIGHT_PARAM_SHADOW_OPACITY:
			return 1.0f;
		case RS::LIGHT_PARAM_SPECULAR:
			return 0.5f;
		case RS::LIGHT_PARAM_SIZE:
		case RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE:
		case RS::LIGHT_PARAM_SHADOW_BLUR:
			return 0.0f;
		case RS::LIGHT_PARAM_SPOT_ANGLE:
			return 45.0f;
		case RS::LIGHT_PARAM_SHADOW_SPLIT_1_OFFSET:
			return 0.1f;
		case RS::LIGHT_PARAM_SHADOW_SPLIT_2_OFFSET:
			return 0.3f;
		case RS::LIGHT_PARAM_SHADOW_SPLIT_3_OFFSET:
			return 0.6f;
		case RS::LIGHT_PARAM_SHADOW_FADE_START:
			return 0.8f;
		case RS::LIGHT_PARAM_SHADOW_BIAS:
			return 0.02f;
		case RS::LIGHT_PARAM_SHADOW_PANCAKE_SIZE:
			return 20.0f;
		case RS::LIGHT_PARAM_TRANSMITTANCE_BIAS:
			return 0.05f;
		case RS::LIGHT_PARAM_INTENSITY:
			return p_type == RS::LIGHT_DIRECTIONAL ? 100000.0f : 1000.0f;
		case RS::LIGHT_PARAM_MAX:
			break;
	}
	ERR_FAIL_V_MSG(0.0f, vformat("Invalid light parameter %d.", (int)p_param));
}

const char *RendererLightStorage::get_param_name(RS::LightParam p_param) {
	static const char *names[RS::LIGHT_PARAM_MAX] = {
		"LIGHT_PARAM_ENERGY",
		"LIGHT_PARAM_INDIRECT_ENERGY",
		"LIGHT_PARAM_VOLUMETRIC_FOG_ENERGY",
		"LIGHT_PARAM_SPECULAR",
		"LIGHT_PARAM_RANGE",
		"LIGHT_PARAM_SIZE",
		"LIGHT_PARAM_ATTENUATION",
		"LIGHT_PARAM_SPOT_ANGLE",
		"LIGHT_PARAM_SPOT_ATTENUATION",
		"LIGHT_PARAM_SHADOW_MAX_DISTANCE",
		"LIGHT_PARAM_SHADOW_SPLIT_1_OFFSET",
		"LIGHT_PARAM_SHADOW_SPLIT_2_OFFSET",
		"LIGHT_PARAM_SHADOW_SPLIT_3_OFFSET",
		"LIGHT_PARAM_SHADOW_FADE_START",
		"LIGHT_PARAM_SHADOW_NORMAL_BIAS",
		"LIGHT_PARAM_SHADOW_BIAS",
		"LIGHT_PARAM_SHADOW_PANCAKE_SIZE",
		"LIGHT_PARAM_SHADOW_OPACITY",
		"LIGHT_PARAM_SHADOW_BLUR",
		"LIGHT_PARAM_TRANSMITTANCE_BIAS",
		"LIGHT_PARAM_INTENSITY",
	};
	if (p_param < 0 || p_param >= RS::LIGHT_PARAM_MAX) {
		return "LIGHT_PARAM_<invalid>";
	}
	return names[p_param];
}

bool RendererLightStorage::validate_param(RS::LightParam p_param, float p_value) {
	ERR_FAIL_INDEX_V_MSG((int)p_param, (int)RS::LIGHT_PARAM_MAX, false, "Light parameter index is out of range.");
	const char *name = get_param_name(p_param);
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_value), false, vformat("%s must be a finite number, got %s; the old value is kept.", name, rtos(p_value).c_str()));
	switch (p_param) {
		case RS::LIGHT_PARAM_RANGE:
		case RS::LIGHT_PARAM_SIZE:
		case RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE:
		case RS::LIGHT_PARAM_SHADOW_PANCAKE_SIZE:
		case RS::LIGHT_PARAM_SHADOW_BLUR:
		case RS::LIGHT_PARAM_INTENSITY:
		case RS::LIGHT_PARAM_SPECULAR:
			ERR_FAIL_COND_V_MSG(p_value < 0.0f, false, vformat("%s must not be negative, got %s; the old value is kept.", name, rtos(p_value).c_str()));
			break;
		case RS::LIGHT_PARAM_SPOT_ANGLE:
			ERR_FAIL_COND_V_MSG(p_value < 0.0f || p_value > 180.0f, false, vformat("%s must be between 0 and 180 degrees, got %s; the old value is kept.", name, rtos(p_value).c_str()));
			break;
		case RS::LIGHT_PARAM_SHADOW_OPACITY:
			ERR_FAIL_COND_V_MSG(p_value < 0.0f || p_value > 1.0f, false, vformat("%s must be between 0 and 1, got %s; the old value is kept.", name, rtos(p_value).c_str()));
			break;
		default:
			// Energy may be negative-signed by users, attenuation is an exponent (-10..10 in 4.x),
			// biases and split offsets are free: only finiteness is required.
			break;
	}
	return true;
}

bool RendererLightStorage::validate_param(RS::LightType p_type, RS::LightParam p_param, float p_value) {
	if (!validate_param(p_param, p_value)) {
		return false;
	}
	if (p_type == RS::LIGHT_AREA && p_param == RS::LIGHT_PARAM_ATTENUATION) {
		// The area light's distance exponent: W(d) = window * d^(2 - attenuation). Upstream warns that
		// negative values give unexpected results; we reject them.
		ERR_FAIL_COND_V_MSG(p_value < 0.0f, false, vformat("LIGHT_PARAM_ATTENUATION of an area light must not be negative, got %s; the old value is kept.", rtos(p_value).c_str()));
	}
	return true;
}

bool RendererLightStorage::validate_area_size(const Vector2 &p_size) {
	ERR_FAIL_COND_V_MSG(!p_size.is_finite(), false, vformat("Area light size must be finite, got (%s, %s); the old value is kept.", rtos(p_size.x).c_str(), rtos(p_size.y).c_str()));
	ERR_FAIL_COND_V_MSG(p_size.x < 0.0f || p_size.y < 0.0f, false, vformat("Area light size must not be negative, got (%s, %s); the old value is kept.", rtos(p_size.x).c_str(), rtos(p_size.y).c_str()));
	return true;
}

AABB RendererLightStorage::compute_area_light_aabb(float p_range, const Vector2 &p_size, RS::LightAreaShape p_shape) {
	if (p_shape == RS::LIGHT_AREA_SHAPE_SPHERE) {
		const real_t h = p_size.x * 0.5f + p_range;
		return AABB(Vector3(-h, -h, -h), Vector3(h, h, h) * 2.0f);
	}
	if (p_shape == RS::LIGHT_AREA_SHAPE_TUBE) {
		const real_t radius = p_size.y * 0.5f;
		const Vector3 h(p_size.x * 0.5f + radius + p_range, radius + p_range, radius + p_range);
		return AABB(-h, h * 2.0f);
	}
	const real_t half_a = p_size.x * 0.5f + p_range;
	const real_t half_b = p_size.y * 0.5f + p_range;
	return AABB(Vector3(-half_a, -half_b, -p_range), Vector3(half_a * 2.0f, half_b * 2.0f, p_range));
}

float RendererLightStorage::compute_area_light_cull_radius(float p_range, const Vector2 &p_size, RS::LightAreaShape p_shape) {
	switch (p_shape) {
		case RS::LIGHT_AREA_SHAPE_DISK:
			return p_range + 0.5f * std::fmax(p_size.x, p_size.y);
		case RS::LIGHT_AREA_SHAPE_SPHERE:
			return p_range + 0.5f * p_size.x;
		case RS::LIGHT_AREA_SHAPE_TUBE:
			return p_range + 0.5f * (p_size.x + p_size.y);
		default:
			return p_range + 0.5f * std::sqrt(p_size.x * p_size.x + p_size.y * p_size.y);
	}
}

float RendererLightStorage::compute_area_light_emitting_area(const Vector2 &p_size, RS::LightAreaShape p_shape) {
	const float pi = float(Math::PI);
	switch (p_shape) {
		case RS::LIGHT_AREA_SHAPE_DISK:
			return pi * p_size.x * p_size.y * 0.25f;
		case RS::LIGHT_AREA_SHAPE_SPHERE:
			return pi * p_size.x * p_size.x;
		case RS::LIGHT_AREA_SHAPE_TUBE:
			return pi * p_size.y * (p_size.x + p_size.y);
		default:
			return p_size.x * p_size.y;
	}
}

AABB RendererLightStorage::compute_light_aabb(RS::LightType p_type, float p_range, float p_spot_angle_degrees, const Vector2 &p_area_size, RS::LightAreaShape p_area_shape) {
	switch (p_type) {
		case RS::LIGHT_DIRECTIONAL:
			return AABB();
		case RS::LIGHT_OMNI:
			return AABB(Vector3(-p_range, -p_range, -p_range), Vector3(p_range, p_range, p_range) * 2.0f);
		case RS::LIGHT_SPOT: {
			if (p_spot_angle_degrees >= 90.0f) {
				// The lit region reaches behind the apex: bound the whole range sphere.
				return AABB(Vector3(-p_range, -p_range, -p_range), Vector3(p_range, p_range, p_range) * 2.0f);
			}
			// Spherical sector along -Z: the rim sits at radius range * sin(angle), the cap reaches z = -range.
			// Godot uses range * tan(angle); sin(angle) <= tan(angle), so this box is tighter and still encloses.
			float radial = p_range * std::sin(Math::deg_to_rad(p_spot_angle_degrees));
			return AABB(Vector3(-radial, -radial, -p_range), Vector3(radial * 2.0f, radial * 2.0f, p_range));
		}
		case RS::LIGHT_AREA:
			return compute_area_light_aabb(p_range, p_area_size, p_area_shape);
	}
	ERR_FAIL_V_MSG(AABB(), vformat("Invalid light type %d.", (int)p_type));
}
