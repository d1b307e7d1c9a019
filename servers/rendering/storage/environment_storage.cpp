/**************************************************************************/
/*  environment_storage.cpp                                               */
/**************************************************************************/

#include "servers/rendering/storage/environment_storage.h"

#include "core/error/error_macros.h"

#include <cmath>

RID RendererEnvironmentStorage::environment_allocate() {
	return environment_owner.make_rid();
}

bool RendererEnvironmentStorage::environment_free(RID p_rid) {
	if (!environment_owner.owns(p_rid)) {
		return false;
	}
	environment_owner.free(p_rid);
	return true;
}

void RendererEnvironmentStorage::environment_set_background(RID p_env, RS::EnvironmentBG p_bg) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "Invalid environment RID.");
	ERR_FAIL_INDEX_MSG((int)p_bg, (int)RS::ENV_BG_MAX, "Background mode is not an EnvironmentBG value.");
	env->background = p_bg;
}

void RendererEnvironmentStorage::environment_set_bg_color(RID p_env, const Color &p_color) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "Invalid environment RID.");
	ERR_FAIL_COND_MSG(!p_color.is_finite(), "Background colour must be finite.");
	env->bg_color = p_color;
}

void RendererEnvironmentStorage::environment_set_bg_energy(RID p_env, float p_multiplier) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "Invalid environment RID.");
	ERR_FAIL_COND_MSG(!std::isfinite(p_multiplier) || p_multiplier < 0.0f, vformat("Background energy must be finite and not negative, got %s.", rtos(p_multiplier).c_str()));
	env->bg_energy = p_multiplier;
}

void RendererEnvironmentStorage::environment_set_ambient_light(RID p_env, const Color &p_color, RS::EnvironmentAmbientSource p_ambient, float p_energy) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "Invalid environment RID.");
	ERR_FAIL_COND_MSG(!p_color.is_finite(), "Ambient colour must be finite.");
	ERR_FAIL_INDEX_MSG((int)p_ambient, (int)RS::ENV_AMBIENT_SOURCE_SKY + 1, "Ambient source is not an EnvironmentAmbientSource value.");
	ERR_FAIL_COND_MSG(!std::isfinite(p_energy) || p_energy < 0.0f, vformat("Ambient energy must be finite and not negative, got %s.", rtos(p_energy).c_str()));
	env->ambient_color = p_color;
	env->ambient_source = p_ambient;
	env->ambient_energy = p_energy;
}

/* SSAO / SSIL (image-space radiosity) */

static bool _ss_check(const char *p_name, float p_value, float p_min, float p_max) {
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_value) || p_value < p_min || p_value > p_max, false,
			vformat("Environment %s must be finite and in %s..%s, got %s; the SSAO/SSIL settings are unchanged.", p_name, rtos(p_min).c_str(), rtos(p_max).c_str(), rtos(p_value).c_str()));
	return true;
}

void RendererEnvironmentStorage::environment_set_ssao(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_power, float p_detail, float p_horizon, float p_sharpness, float p_light_affect, float p_ao_channel_affect) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "environment_set_ssao: invalid environment RID.");
	// Godot's ranges; radius, intensity and power take "or_greater" values, bounded here at 1e4.
	if (!_ss_check("ssao_radius", p_radius, 0.01f, 1e4f) || !_ss_check("ssao_intensity", p_intensity, 0.0f, 1e4f) || !_ss_check("ssao_power", p_power, 0.01f, 1e4f) ||
			!_ss_check("ssao_detail", p_detail, 0.0f, 5.0f) || !_ss_check("ssao_horizon", p_horizon, 0.0f, 1.0f) || !_ss_check("ssao_sharpness", p_sharpness, 0.0f, 1.0f) ||
			!_ss_check("ssao_light_affect", p_light_affect, 0.0f, 1.0f) || !_ss_check("ssao_ao_channel_affect", p_ao_channel_affect, 0.0f, 1.0f)) {
		return;
	}
	ScreenSpaceLightingSettings &s = env->ss_lighting;
	s.ssao_enabled = p_enable;
	s.ssao_radius = p_radius;
	s.ssao_intensity = p_intensity;
	s.ssao_power = p_power;
	s.ssao_detail = p_detail;
	s.ssao_horizon = p_horizon;
	s.ssao_sharpness = p_sharpness;
	s.ssao_light_affect = p_light_affect;
	s.ssao_ao_channel_affect = p_ao_channel_affect;
}

void RendererEnvironmentStorage::environment_set_ssil(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_sharpness, float p_normal_rejection) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "environment_set_ssil: invalid environment RID.");
	if (!_ss_check("ssil_radius", p_radius, 0.01f, 1e4f) || !_ss_check("ssil_intensity", p_intensity, 0.0f, 1e4f) || !_ss_check("ssil_sharpness", p_sharpness, 0.0f, 1.0f) ||
			!_ss_check("ssil_normal_rejection", p_normal_rejection, 0.0f, 1.0f)) {
		return;
	}
	ScreenSpaceLightingSettings &s = env->ss_lighting;
	s.ssil_enabled = p_enable;
	s.ssil_radius = p_radius;
	s.ssil_intensity = p_intensity;
	s.ssil_sharpness = p_sharpness;
	s.ssil_normal_rejection = p_normal_rejection;
}

void RendererEnvironmentStorage::set_ssao_quality(int p_quality, bool p_half_size, int p_blur_passes) {
	ERR_FAIL_INDEX_MSG(p_quality, int(RS::ENV_SSAO_QUALITY_ULTRA) + 1, vformat("environment_set_ssao_quality: quality must be 0..4 (Very Low..Ultra), got %d.", p_quality));
	ERR_FAIL_COND_MSG(p_blur_passes < 0 || p_blur_passes > 4, vformat("environment_set_ssao_quality: blur passes must be 0..4, got %d.", p_blur_passes));
	ss_quality.ssao_quality = p_quality;
	ss_quality.ssao_half_size = p_half_size;
	ss_quality.ssao_blur_passes = p_blur_passes;
}

void RendererEnvironmentStorage::set_ssil_quality(int p_quality, bool p_half_size, int p_blur_passes) {
	ERR_FAIL_INDEX_MSG(p_quality, int(RS::ENV_SSIL_QUALITY_ULTRA) + 1, vformat("environment_set_ssil_quality: quality must be 0..4 (Very Low..Ultra), got %d.", p_quality));
	ERR_FAIL_COND_MSG(p_blur_passes < 0 || p_blur_passes > 4, vformat("environment_set_ssil_quality: blur passes must be 0..4, got %d.", p_blur_passes));
	ss_quality.ssil_quality = p_quality;
	ss_quality.ssil_half_size = p_half_size;
	ss_quality.ssil_blur_passes = p_blur_passes;
}

ScreenSpaceLightingSettings RendererEnvironmentStorage::get_ss_lighting(RID p_env) const {
	const Environment *env = environment_owner.get_or_null(p_env);
	ScreenSpaceLightingSettings s = env ? env->ss_lighting : ScreenSpaceLightingSettings();
	s.ssao_quality = ss_quality.ssao_quality;
	s.ssao_half_size = ss_quality.ssao_half_size;
	s.ssao_blur_passes = ss_quality.ssao_blur_passes;
	s.ssil_quality = ss_quality.ssil_quality;
	s.ssil_half_size = ss_quality.ssil_half_size;
	s.ssil_blur_passes = ss_quality.ssil_blur_passes;
	return s;
}

/* Skies */

void RendererEnvironmentStorage::environment_set_sky(RID p_env, RID p_sky) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "environment_set_sky: invalid environment RID.");
	ERR_FAIL_COND_MSG(p_sky.is_valid() && !sky_owner.owns(p_sky), "environment_set_sky: invalid sky RID.");
	env->sky = p_sky;
}

void RendererEnvironmentStorage::environment_set_ambient_sky_contribution(RID p_env, float p_contribution) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "environment_set_ambient_sky_contribution: invalid environment RID.");
	ERR_FAIL_COND_MSG(!std::isfinite(p_contribution), "ambient_light_sky_contribution must be finite.");
	env->ambient_sky_contribution = std::fmin(std::fmax(p_contribution, 0.0f), 1.0f); // Godot clamps it to 0..1.
}

RID RendererEnvironmentStorage::sky_allocate() {
	return sky_owner.make_rid();
}

RID RendererEnvironmentStorage::sky_material_allocate() {
	return sky_material_owner.make_rid();
}

bool RendererEnvironmentStorage::sky_free(RID p_rid) {
	if (sky_owner.owns(p_rid)) {
		for (RID e : environment_owner.get_owned_list()) {
			Environment *env = environment_owner.get_or_null(e);
			if (env->sky == p_rid) {
				env->sky = RID();
			}
		}
		sky_owner.free(p_rid);
		return true;
	}
	if (sky_material_owner.owns(p_rid)) {
		for (RID k : sky_owner.get_owned_list()) {
			Sky *sky = sky_owner.get_or_null(k);
			if (sky->material == p_rid) {
				sky->material = RID();
			}
		}
		sky_material_owner.free(p_rid);
		return true;
	}
	return false;
}

void RendererEnvironmentStorage::sky_set_material(RID p_sky, RID p_material) {
	Sky *sky = sky_owner.get_or_null(p_sky);
	ERR_FAIL_NULL_MSG(sky, "sky_set_material: invalid sky RID.");
	ERR_FAIL_COND_MSG(p_material.is_valid() && !sky_material_owner.owns(p_material), "sky_set_material: invalid sky material RID.");
	sky->material = p_material;
}

void RendererEnvironmentStorage::sky_set_radiance_size(RID p_sky, int p_size) {
	Sky *sky = sky_owner.get_or_null(p_sky);
	ERR_FAIL_NULL_MSG(sky, "sky_set_radiance_size: invalid sky RID.");
	ERR_FAIL_COND_MSG(p_size < 32 || p_size > 2048, vformat("sky_set_radiance_size: %d is outside 32..2048.", p_size));
	sky->radiance_size = p_size;
}

void RendererEnvironmentStorage::sky_material_set_procedural(RID p_material, const RS::ProceduralSkyParams &p_params) {
	SkyMaterial *m = sky_material_owner.get_or_null(p_material);
	ERR_FAIL_NULL_MSG(m, "sky_material_set_procedural: invalid sky material RID.");
	m->type = RS::SKY_MATERIAL_PROCEDURAL;
	m->procedural = p_params;
}

void RendererEnvironmentStorage::sky_material_set_physical(RID p_material, const RS::PhysicalSkyParams &p_params) {
	SkyMaterial *m = sky_material_owner.get_or_null(p_material);
	ERR_FAIL_NULL_MSG(m, "sky_material_set_physical: invalid sky material RID.");
	m->type = RS::SKY_MATERIAL_PHYSICAL;
	m->physical = p_params;
}

void RendererEnvironmentStorage::environment_set_reflection_source(RID p_env, RS::EnvironmentReflectionSource p_source) {
	Environment *env = environment_owner.get_or_null(p_env);
	ERR_FAIL_NULL_MSG(env, "environment_set_reflection_source: invalid environment RID.");
	ERR_FAIL_COND_MSG(int(p_source) < 0 || int(p_source) > int(RS::ENV_REFLECTION_SOURCE_SKY), vformat("environment_set_reflection_source: %d is not a reflected_light_source (0 BG, 1 DISABLED, 2 SKY).", int(p_source)));
	env->reflection_source = p_source;
}
