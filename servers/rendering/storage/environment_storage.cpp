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
	m->procedural = p_params;
}
