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
