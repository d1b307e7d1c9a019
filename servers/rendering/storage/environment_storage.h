/**************************************************************************/
/*  environment_storage.h                                                 */
/**************************************************************************/
/* godot-area: environment resources (Godot's RendererEnvironmentStorage, */
/* a concrete CPU-only class shared by every backend).                    */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering_server.h"

// Godot's Environment SSAO/SSIL parameters plus the global quality, as the image-space radiosity pass
// (renderer_rd/effects/ss_radiosity_rd.h) reads them. Defaults are Godot 4's.
struct ScreenSpaceLightingSettings {
	bool ssao_enabled = false;
	float ssao_radius = 1.0f; // m.
	float ssao_intensity = 2.0f;
	float ssao_power = 1.5f;
	float ssao_detail = 0.5f;
	float ssao_horizon = 0.06f;
	float ssao_sharpness = 0.98f;
	float ssao_light_affect = 0.0f;
	float ssao_ao_channel_affect = 0.0f;
	bool ssil_enabled = false;
	float ssil_radius = 5.0f; // m.
	float ssil_intensity = 1.0f;
	float ssil_sharpness = 0.98f;
	float ssil_normal_rejection = 1.0f;
	// Global quality (RS::environment_set_ssao_quality / _ssil_quality).
	int ssao_quality = RS::ENV_SSAO_QUALITY_MEDIUM;
	bool ssao_half_size = true;
	int ssao_blur_passes = 2;
	int ssil_quality = RS::ENV_SSIL_QUALITY_MEDIUM;
	bool ssil_half_size = true;
	int ssil_blur_passes = 2;
	bool is_active() const { return ssao_enabled || ssil_enabled; }
};

class RendererEnvironmentStorage {
public:
	// CPU record of one environment. Colours are sRGB (node values); the renderer linearises.
	struct Environment {
		RS::EnvironmentBG background = RS::ENV_BG_CLEAR_COLOR;
		Color bg_color = Color(0, 0, 0, 1);
		float bg_energy = 1.0f;
		RS::EnvironmentAmbientSource ambient_source = RS::ENV_AMBIENT_SOURCE_BG;
		Color ambient_color = Color(0, 0, 0, 1);
		float ambient_energy = 1.0f;
		float ambient_sky_contribution = 1.0f;
		RID sky; // RendererEnvironmentStorage sky, RID() = none.
		RS::EnvironmentReflectionSource reflection_source = RS::ENV_REFLECTION_SOURCE_BG; // Godot's default.
		ScreenSpaceLightingSettings ss_lighting; // SSAO/SSIL (quality fields unused: they are global).
	};
	struct SkyMaterial {
		RS::SkyMaterialType type = RS::SKY_MATERIAL_PROCEDURAL;
		RS::ProceduralSkyParams procedural;
		RS::PhysicalSkyParams physical;
	};
	struct Sky {
		RID material; // A SkyMaterial, RID() = none (Godot then draws black).
		int radiance_size = 256;
	};

private:
	RID_Owner<Environment, true> environment_owner{ "Environment" };
	RID_Owner<Sky, true> sky_owner{ "Sky" };
	RID_Owner<SkyMaterial, true> sky_material_owner{ "SkyMaterial" };
	ScreenSpaceLightingSettings ss_quality; // Only the global quality fields are used.

public:
	// Creates an environment with Godot's defaults.
	RID environment_allocate();
	// Frees an environment; returns false if p_rid is not one.
	bool environment_free(RID p_rid);
	// Returns true if p_rid is an environment.
	bool is_environment(RID p_rid) const { return environment_owner.owns(p_rid); }
	// Returns the record or nullptr (valid only during the current call).
	const Environment *environment_get(RID p_rid) const { return environment_owner.get_or_null(p_rid); }

	// Sets the background mode.
	void environment_set_background(RID p_env, RS::EnvironmentBG p_bg);
	// Sets the background colour (sRGB).
	void environment_set_bg_color(RID p_env, const Color &p_color);
	// Sets the background energy (finite, >= 0).
	void environment_set_bg_energy(RID p_env, float p_multiplier);
	void environment_set_sky(RID p_env, RID p_sky);
	void environment_set_ambient_sky_contribution(RID p_env, float p_contribution);

	RID sky_allocate();
	RID sky_material_allocate();
	// Frees a sky or sky material (environments and skies using it lose it); false if p_rid is neither.
	bool sky_free(RID p_rid);
	void sky_set_material(RID p_sky, RID p_material);
	void sky_set_radiance_size(RID p_sky, int p_size);
	void sky_material_set_procedural(RID p_material, const RS::ProceduralSkyParams &p_params);
	void sky_material_set_physical(RID p_material, const RS::PhysicalSkyParams &p_params);
	void environment_set_reflection_source(RID p_env, RS::EnvironmentReflectionSource p_source);
	const Sky *sky_get(RID p_sky) const { return sky_owner.get_or_null(p_sky); }
	const SkyMaterial *sky_material_get(RID p_material) const { return sky_material_owner.get_or_null(p_material); }

	// Godot's SSAO / SSIL parameters (each finite and inside Godot's range, else an error and no change).
	void environment_set_ssao(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_power, float p_detail, float p_horizon, float p_sharpness, float p_light_affect, float p_ao_channel_affect);
	void environment_set_ssil(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_sharpness, float p_normal_rejection);
	// Global quality: RS::EnvironmentSSAOQuality / SSILQuality, half resolution, blur passes 0..4.
	void set_ssao_quality(int p_quality, bool p_half_size, int p_blur_passes);
	void set_ssil_quality(int p_quality, bool p_half_size, int p_blur_passes);
	// The settings of p_env with the global quality filled in (defaults when p_env is invalid).
	ScreenSpaceLightingSettings get_ss_lighting(RID p_env) const;

	// Sets ambient colour, source and energy (finite, >= 0).
	void environment_set_ambient_light(RID p_env, const Color &p_color, RS::EnvironmentAmbientSource p_ambient, float p_energy);
};
