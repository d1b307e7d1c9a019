/**************************************************************************/
/*  environment.h                                                         */
/**************************************************************************/
/* godot-area: Environment resource (background and ambient light subset  */
/* of Godot 4.7's), owning one RS environment RID. Put it in a scene with */
/* a WorldEnvironment node or on a Camera3D.                              */

#pragma once

#include "core/io/resource.h"
#include "core/io/tonemap.h"
#include "scene/resources/sky.h"
#include "servers/rendering_server.h"

class Environment : public Resource {
	GDCLASS(Environment, Resource);

public:
	// Values equal Godot's (saved in scene files) and RS::EnvironmentBG.
	enum BGMode {
		BG_CLEAR_COLOR = RS::ENV_BG_CLEAR_COLOR,
		BG_COLOR = RS::ENV_BG_COLOR,
		BG_SKY = RS::ENV_BG_SKY,
		BG_CANVAS = RS::ENV_BG_CANVAS,
		BG_KEEP = RS::ENV_BG_KEEP,
		BG_CAMERA_FEED = RS::ENV_BG_CAMERA_FEED,
		BG_MAX
	};
	enum AmbientSource {
		AMBIENT_SOURCE_BG = RS::ENV_AMBIENT_SOURCE_BG,
		AMBIENT_SOURCE_DISABLED = RS::ENV_AMBIENT_SOURCE_DISABLED,
		AMBIENT_SOURCE_COLOR = RS::ENV_AMBIENT_SOURCE_COLOR,
		AMBIENT_SOURCE_SKY = RS::ENV_AMBIENT_SOURCE_SKY,
		AMBIENT_SOURCE_MAX
	};
	// Godot's Environment.ReflectionSource (reflected_light_source), same order and values.
	enum ReflectionSource {
		REFLECTION_SOURCE_BG = RS::ENV_REFLECTION_SOURCE_BG,
		REFLECTION_SOURCE_DISABLED = RS::ENV_REFLECTION_SOURCE_DISABLED,
		REFLECTION_SOURCE_SKY = RS::ENV_REFLECTION_SOURCE_SKY,
		REFLECTION_SOURCE_MAX
	};
	// Godot's Environment.ToneMapper (tonemap_mode), same order and values.
	enum ToneMapper {
		TONE_MAPPER_LINEAR,
		TONE_MAPPER_REINHARDT,
		TONE_MAPPER_FILMIC,
		TONE_MAPPER_ACES,
		TONE_MAPPER_AGX,
		TONE_MAPPER_MAX
	};

private:
	RID environment;
	BGMode bg_mode = BG_CLEAR_COLOR;
	Color bg_color = Color(0, 0, 0, 1);
	float bg_energy_multiplier = 1.0f;
	AmbientSource ambient_source = AMBIENT_SOURCE_BG;
	Color ambient_color = Color(0, 0, 0, 1);
	float ambient_energy = 1.0f;
	float ambient_sky_contribution = 1.0f;
	ReflectionSource reflection_source = REFLECTION_SOURCE_BG;
	Ref<Sky> sky;
	ToneMapper tonemap_mode = TONE_MAPPER_LINEAR;
	float tonemap_exposure = 1.0f;
	float tonemap_white = 1.0f;
	// SSAO / SSIL (Godot 4's names and defaults; both drive the image-space radiosity pass).
	bool ssao_enabled = false;
	float ssao_radius = 1.0f;
	float ssao_intensity = 2.0f;
	float ssao_power = 1.5f;
	float ssao_detail = 0.5f;
	float ssao_horizon = 0.06f;
	float ssao_sharpness = 0.98f;
	float ssao_direct_light_affect = 0.0f;
	float ssao_ao_channel_affect = 0.0f;
	bool ssil_enabled = false;
	float ssil_radius = 5.0f;
	float ssil_intensity = 1.0f;
	float ssil_sharpness = 0.98f;
	float ssil_normal_rejection = 1.0f;

	void _update_ambient_light();
	void _update_ssao();
	void _update_ssil();
	// False (with an error naming the property and value) when p_value is not finite or outside p_min..p_max.
	static bool _check_ss_value(const char *p_property, float p_value, float p_min, float p_max);

protected:
	static void _bind_methods();
	void _validate_property(PropertyInfo &p_property) const;

public:
	RID get_rid() const override { return environment; }

	void set_background(BGMode p_bg);
	BGMode get_background() const { return bg_mode; }
	void set_bg_color(const Color &p_color);
	Color get_bg_color() const { return bg_color; }
	// Finite and >= 0.
	void set_bg_energy_multiplier(float p_multiplier);
	float get_bg_energy_multiplier() const { return bg_energy_multiplier; }

	void set_ambient_source(AmbientSource p_source);
	AmbientSource get_ambient_source() const { return ambient_source; }
	void set_ambient_light_color(const Color &p_color);
	Color get_ambient_light_color() const { return ambient_color; }
	// Finite and >= 0.
	void set_ambient_light_energy(float p_energy);
	float get_ambient_light_energy() const { return ambient_energy; }

	// The sky of background_mode Sky and of sky ambient (Godot's "sky").
	void set_sky(const Ref<Sky> &p_sky);
	Ref<Sky> get_sky() const { return sky; }
	// 0..1 (Godot clamps it): the share of the ambient light that comes from the sky.
	void set_ambient_light_sky_contribution(float p_contribution);
	float get_ambient_light_sky_contribution() const { return ambient_sky_contribution; }
	// reflected_light_source: BG (default) reflects the sky under a sky background, SKY always, DISABLED never.
	void set_reflection_source(ReflectionSource p_source);
	ReflectionSource get_reflection_source() const { return reflection_source; }

	// Tonemapping of the 8-bit previews (PNG, editor viewport); the HDR image and EXR stay scene-linear.
	void set_tonemapper(ToneMapper p_mode);
	ToneMapper get_tonemapper() const { return tonemap_mode; }
	// Finite and > 0.
	void set_tonemap_exposure(float p_exposure);
	float get_tonemap_exposure() const { return tonemap_exposure; }
	// Finite and > 0 (Reinhard, Filmic and ACES; Linear and AgX ignore it, as Godot).
	void set_tonemap_white(float p_white);
	float get_tonemap_white() const { return tonemap_white; }
	// SSAO (Godot's ssao_* properties; ranges as Godot's sliders, "or_greater" ones bounded at 1e4).
	void set_ssao_enabled(bool p_enabled);
	bool is_ssao_enabled() const { return ssao_enabled; }
	void set_ssao_radius(float p_radius);
	float get_ssao_radius() const { return ssao_radius; }
	void set_ssao_intensity(float p_intensity);
	float get_ssao_intensity() const { return ssao_intensity; }
	void set_ssao_power(float p_power);
	float get_ssao_power() const { return ssao_power; }
	void set_ssao_detail(float p_detail);
	float get_ssao_detail() const { return ssao_detail; }
	void set_ssao_horizon(float p_horizon);
	float get_ssao_horizon() const { return ssao_horizon; }
	void set_ssao_sharpness(float p_sharpness);
	float get_ssao_sharpness() const { return ssao_sharpness; }
	// Saved as "ssao_light_affect" (Godot's property name for this setter pair).
	void set_ssao_direct_light_affect(float p_amount);
	float get_ssao_direct_light_affect() const { return ssao_direct_light_affect; }
	void set_ssao_ao_channel_affect(float p_amount);
	float get_ssao_ao_channel_affect() const { return ssao_ao_channel_affect; }
	// SSIL (Godot's ssil_* properties).
	void set_ssil_enabled(bool p_enabled);
	bool is_ssil_enabled() const { return ssil_enabled; }
	void set_ssil_radius(float p_radius);
	float get_ssil_radius() const { return ssil_radius; }
	void set_ssil_intensity(float p_intensity);
	float get_ssil_intensity() const { return ssil_intensity; }
	void set_ssil_sharpness(float p_sharpness);
	float get_ssil_sharpness() const { return ssil_sharpness; }
	void set_ssil_normal_rejection(float p_amount);
	float get_ssil_normal_rejection() const { return ssil_normal_rejection; }

	// The three values above as core/io/tonemap.h settings.
	Tonemap::Settings get_tonemap_settings() const;
	// The tonemap of an 8-bit preview of a view: the camera's environment, else the world's (as the renderer
	// resolves them), else Tonemap::MODE_ACES_FITTED (godot-area's preview for scenes without an Environment).
	static Tonemap::Settings get_preview_tonemap(const Ref<Environment> &p_camera_environment, const Ref<Environment> &p_world_environment);

	Environment();
	~Environment() override;
};

VARIANT_ENUM_CAST(Environment::BGMode);
VARIANT_ENUM_CAST(Environment::AmbientSource);
VARIANT_ENUM_CAST(Environment::ReflectionSource);
VARIANT_ENUM_CAST(Environment::ToneMapper);
