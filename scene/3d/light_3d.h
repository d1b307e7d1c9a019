/**************************************************************************/
/*  light_3d.h                                                            */
/**************************************************************************/
/* godot-area: Light3D (abstract) and its leaves DirectionalLight3D,      */
/* OmniLight3D, SpotLight3D and AreaLight3D (a one-sided rectangle in    */
/* its local XY plane, emitting along -Z). Property names, groups, hints, */
/* enum order and defaults follow Godot 4.7 (checked against Godot's      */
/* light_3d.cpp; AreaLight3D against the area-light contract),            */
/* so scene files load unchanged. Lights shine along their node's -Z.     */
/*                                                                        */
/* The node keeps a copy of every value (getters never ask the server),   */
/* owns one RS light RID created by the type's constructor and attached   */
/* as the base of the VisualInstance3D instance, and frees it in the      */
/* destructor. Param values equal RS::LightParam, so forwarding is a cast.*/
/* Setters reject NaN/infinity and out-of-domain values with a message    */
/* that names the saved property, keeping the old value.                  */
/*                                                                        */
/* We have no project settings: physical light units are off, as in a    */
/* default Godot project, so light_intensity_lumens/lux and               */
/* light_temperature are bound but hidden (usage NONE) and only stored.   */
/* The projector texture is stored only (the RS has no projector call).   */

#pragma once

#include "scene/3d/visual_instance_3d.h"
#include "scene/resources/texture.h"
#include "servers/rendering_server.h"

class Light3D : public VisualInstance3D {
	GDCLASS(Light3D, VisualInstance3D);

public:
	enum Param {
		PARAM_ENERGY = RS::LIGHT_PARAM_ENERGY,
		PARAM_INDIRECT_ENERGY = RS::LIGHT_PARAM_INDIRECT_ENERGY,
		PARAM_VOLUMETRIC_FOG_ENERGY = RS::LIGHT_PARAM_VOLUMETRIC_FOG_ENERGY,
		PARAM_SPECULAR = RS::LIGHT_PARAM_SPECULAR,
		PARAM_RANGE = RS::LIGHT_PARAM_RANGE,
		PARAM_SIZE = RS::LIGHT_PARAM_SIZE,
		PARAM_ATTENUATION = RS::LIGHT_PARAM_ATTENUATION,
		PARAM_SPOT_ANGLE = RS::LIGHT_PARAM_SPOT_ANGLE,
		PARAM_SPOT_ATTENUATION = RS::LIGHT_PARAM_SPOT_ATTENUATION,
		PARAM_SHADOW_MAX_DISTANCE = RS::LIGHT_PARAM_SHADOW_MAX_DISTANCE,
		PARAM_SHADOW_SPLIT_1_OFFSET = RS::LIGHT_PARAM_SHADOW_SPLIT_1_OFFSET,
		PARAM_SHADOW_SPLIT_2_OFFSET = RS::LIGHT_PARAM_SHADOW_SPLIT_2_OFFSET,
		PARAM_SHADOW_SPLIT_3_OFFSET = RS::LIGHT_PARAM_SHADOW_SPLIT_3_OFFSET,
		PARAM_SHADOW_FADE_START = RS::LIGHT_PARAM_SHADOW_FADE_START,
		PARAM_SHADOW_NORMAL_BIAS = RS::LIGHT_PARAM_SHADOW_NORMAL_BIAS,
		PARAM_SHADOW_BIAS = RS::LIGHT_PARAM_SHADOW_BIAS,
		PARAM_SHADOW_PANCAKE_SIZE = RS::LIGHT_PARAM_SHADOW_PANCAKE_SIZE,
		PARAM_SHADOW_OPACITY = RS::LIGHT_PARAM_SHADOW_OPACITY,
		PARAM_SHADOW_BLUR = RS::LIGHT_PARAM_SHADOW_BLUR,
		PARAM_TRANSMITTANCE_BIAS = RS::LIGHT_PARAM_TRANSMITTANCE_BIAS,
		PARAM_INTENSITY = RS::LIGHT_PARAM_INTENSITY,
		PARAM_MAX = RS::LIGHT_PARAM_MAX
	};

	enum BakeMode {
		BAKE_DISABLED = RS::LIGHT_BAKE_DISABLED,
		BAKE_STATIC = RS::LIGHT_BAKE_STATIC,
		BAKE_DYNAMIC = RS::LIGHT_BAKE_DYNAMIC,
	};

private:
	RS::LightType type = RS::LIGHT_DIRECTIONAL;
	RID light;
	float param[PARAM_MAX] = {};
	Color color = Color(1, 1, 1, 1);
	bool shadow = false;
	bool negative = false;
	bool reverse_cull = false;
	uint32_t cull_mask = 0xFFFFFFFF;
	uint32_t shadow_caster_mask = 0xFFFFFFFF;
	BakeMode bake_mode = BAKE_DYNAMIC;
	Ref<Texture2D> projector;
	float temperature = 6500.0f;
	bool distance_fade_enabled = false;
	float distance_fade_begin = 40.0f;
	float distance_fade_shadow = 50.0f;
	float distance_fade_length = 10.0f;
	bool editor_only = false;

	void _push_distance_fade();

protected:
	static void _bind_methods();
	void _validate_property(PropertyInfo &p_property) const;
	void _update_instance_visibility() override;

	// Subclasses pass their type; creates the RS light and applies Godot's base defaults.
	Light3D(RS::LightType p_type);

public:
	// The saved property name of p_param for this light type ("omni_range", "spot_angle",
	// "light_angular_distance", ...), used in messages.
	String get_param_property_name(Param p_param) const;
	// Checks p_value for p_param: finite, and inside the parameter's domain. Returns an empty
	// string when valid, else the reason.
	String validate_param(Param p_param, float p_value) const;

	void set_param(Param p_param, float p_value);
	float get_param(Param p_param) const;

	void set_color(const Color &p_color);
	Color get_color() const { return color; }
	void set_shadow(bool p_enable);
	bool has_shadow() const { return shadow; }
	void set_negative(bool p_enable);
	bool is_negative() const { return negative; }
	void set_shadow_reverse_cull_face(bool p_enable);
	bool get_shadow_reverse_cull_face() const { return reverse_cull; }
	void set_cull_mask(uint32_t p_mask);
	uint32_t get_cull_mask() const { return cull_mask; }
	void set_shadow_caster_mask(uint32_t p_mask);
	uint32_t get_shadow_caster_mask() const { return shadow_caster_mask; }
	void set_bake_mode(BakeMode p_mode);
	BakeMode get_bake_mode() const { return bake_mode; }
	void set_projector(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_projector() const { return projector; }
	// Kelvin, 1000..15000 (stored; used only with physical light units).
	void set_temperature(float p_kelvin);
	float get_temperature() const { return temperature; }

	void set_enable_distance_fade(bool p_enable);
	bool is_distance_fade_enabled() const { return distance_fade_enabled; }
	void set_distance_fade_begin(float p_distance);
	float get_distance_fade_begin() const { return distance_fade_begin; }
	void set_distance_fade_shadow(float p_distance);
	float get_distance_fade_shadow() const { return distance_fade_shadow; }
	void set_distance_fade_length(float p_length);
	float get_distance_fade_length() const { return distance_fade_length; }

	// There is no editor here, so an editor-only light is never drawn.
	void set_editor_only(bool p_editor_only);
	bool is_editor_only() const { return editor_only; }

	RS::LightType get_light_type() const { return type; }
	RID get_light() const { return light; }

	// Local-space bounds: omni a cube of side 2·range; spot the cone's box (the omni cube
	// above 90 degrees); directional the unit cube (-1..1). AreaLight3D overrides it.
	AABB get_aabb() const override;

	// Configuration warnings (empty when fine), as Godot's.
	std::vector<String> get_configuration_warnings() const;

	// Exists only for ClassDB; prints an error (use a concrete subtype).
	Light3D();
	~Light3D() override;
};

class DirectionalLight3D : public Light3D {
	GDCLASS(DirectionalLight3D, Light3D);

public:
	enum ShadowMode {
		SHADOW_ORTHOGONAL = RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL,
		SHADOW_PARALLEL_2_SPLITS = RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_2_SPLITS,
		SHADOW_PARALLEL_4_SPLITS = RS::LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS,
	};
	enum SkyMode {
		SKY_MODE_LIGHT_AND_SKY = RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY,
		SKY_MODE_LIGHT_ONLY = RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_ONLY,
		SKY_MODE_SKY_ONLY = RS::LIGHT_DIRECTIONAL_SKY_MODE_SKY_ONLY,
	};

private:
	ShadowMode shadow_mode = SHADOW_PARALLEL_4_SPLITS;
	bool blend_splits = false;
	SkyMode sky_mode = SKY_MODE_LIGHT_AND_SKY;

protected:
	static void _bind_methods();
	void _validate_property(PropertyInfo &p_property) const;

public:
	void set_shadow_mode(ShadowMode p_mode);
	ShadowMode get_shadow_mode() const { return shadow_mode; }
	void set_blend_splits(bool p_enable);
	bool is_blend_splits_enabled() const { return blend_splits; }
	void set_sky_mode(SkyMode p_mode);
	SkyMode get_sky_mode() const { return sky_mode; }

	DirectionalLight3D();
};

class OmniLight3D : public Light3D {
	GDCLASS(OmniLight3D, Light3D);

public:
	enum ShadowMode {
		SHADOW_DUAL_PARABOLOID = RS::LIGHT_OMNI_SHADOW_DUAL_PARABOLOID,
		SHADOW_CUBE = RS::LIGHT_OMNI_SHADOW_CUBE,
	};

private:
	ShadowMode shadow_mode = SHADOW_CUBE;

protected:
	static void _bind_methods();

public:
	void set_shadow_mode(ShadowMode p_mode);
	ShadowMode get_shadow_mode() const { return shadow_mode; }

	OmniLight3D();
};

class SpotLight3D : public Light3D {
	GDCLASS(SpotLight3D, Light3D);

protected:
	static void _bind_methods();

public:
	SpotLight3D();
};

// An area light; by default (area_shape RECTANGLE) a rectangle area_size.x along local +X by area_size.y
// along +Y, centred at the origin; it emits uniform radiance along local -Z only (nothing behind it, z > 0,
// is lit). DISK is one-sided the same way; SPHERE and TUBE emit outwards everywhere (see AreaShape):
//   L_e = srgb_to_linear(light_color) * light_energy * pi / A_n,  A_n = the shape's emitting area
//   (RendererLightStorage::compute_area_light_emitting_area) if area_normalize_energy else 1,
// attenuated by W(d) = max(1 - (d / area_range)^4, 0)^2 * max(d, 1e-4)^(2 - area_attenuation), d = distance
// to the closest point of the shape (upstream Godot 4.7's meaning: area_attenuation is a distance
// exponent, 2 = physically correct inverse square, default 1). A zero area emits nothing.
class AreaLight3D : public Light3D {
	GDCLASS(AreaLight3D, Light3D);

public:
	enum AreaShadingMethod {
		AREA_SHADING_LTC = RS::LIGHT_AREA_SHADING_LTC,
		AREA_SHADING_LTC_POLYNOMIAL = RS::LIGHT_AREA_SHADING_LTC_POLYNOMIAL,
		AREA_SHADING_MRP = RS::LIGHT_AREA_SHADING_MRP,
		AREA_SHADING_STOCHASTIC = RS::LIGHT_AREA_SHADING_STOCHASTIC,
		AREA_SHADING_AUTO = RS::LIGHT_AREA_SHADING_AUTO,
		AREA_SHADING_LTC_2LOBE = RS::LIGHT_AREA_SHADING_LTC_2LOBE,
	};
	// The emitting shape (values equal RS::LightAreaShape); area_size means per shape: RECTANGLE x by y,
	// DISK an ellipse of diameters x and y (both one-sided, along -Z), SPHERE diameter x, TUBE a capsule
	// of segment length x along local X and diameter y (both emit outwards everywhere).
	enum AreaShape {
		AREA_SHAPE_RECTANGLE = RS::LIGHT_AREA_SHAPE_RECTANGLE,
		AREA_SHAPE_DISK = RS::LIGHT_AREA_SHAPE_DISK,
		AREA_SHAPE_SPHERE = RS::LIGHT_AREA_SHAPE_SPHERE,
		AREA_SHAPE_TUBE = RS::LIGHT_AREA_SHAPE_TUBE,
	};
	// How shadows are drawn when shadow_enabled is on (values equal RS::LightAreaShadowMode).
	enum AreaShadowMode {
		AREA_SHADOW_FIXED = RS::LIGHT_AREA_SHADOW_FIXED,
		AREA_SHADOW_PCSS_BASELINE = RS::LIGHT_AREA_SHADOW_PCSS_BASELINE,
		AREA_SHADOW_ADAPTIVE = RS::LIGHT_AREA_SHADOW_ADAPTIVE,
		AREA_SHADOW_HEURISTIC = RS::LIGHT_AREA_SHADOW_HEURISTIC,
	};

private:
	AreaShape area_shape = AREA_SHAPE_RECTANGLE;
	Vector2 area_size = Vector2(1, 1);
	bool area_normalize_energy = true;
	AreaShadingMethod area_shading_method = AREA_SHADING_LTC;
	int area_stochastic_samples = RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT;
	AreaShadowMode area_shadow_mode = AREA_SHADOW_FIXED;
	int area_shadow_grid = RS::LIGHT_AREA_SHADOW_GRID_DEFAULT;
	Ref<Texture2D> area_texture;

protected:
	static void _bind_methods();
	// area_shadow_* hidden (still saved) while shadow_enabled is off; area_shadow_grid also in every mode but FIXED.
	void _validate_property(PropertyInfo &p_property) const;

public:
	// RECTANGLE (default, upstream's), DISK, SPHERE or TUBE (else rejected with a message, the old value kept).
	void set_area_shape(AreaShape p_shape);
	AreaShape get_area_shape() const { return area_shape; }
	// Metres; both components finite and >= 0 (else rejected with a message, the old value kept).
	void set_area_size(const Vector2 &p_size);
	Vector2 get_area_size() const { return area_size; }
	void set_area_normalize_energy(bool p_enable);
	bool is_area_normalizing_energy() const { return area_normalize_energy; }
	void set_area_shading_method(AreaShadingMethod p_method);
	AreaShadingMethod get_area_shading_method() const { return area_shading_method; }
	// Samples per strategy and shading point of AREA_SHADING_STOCHASTIC (1..256, else rejected).
	void set_area_stochastic_samples(int p_samples);
	int get_area_stochastic_samples() const { return area_stochastic_samples; }
	void set_area_shadow_mode(AreaShadowMode p_mode);
	AreaShadowMode get_area_shadow_mode() const { return area_shadow_mode; }
	// AREA_SHADOW_FIXED: area_shadow_grid x area_shadow_grid shadow maps over the light (2..9, else rejected).
	void set_area_shadow_grid(int p_grid);
	int get_area_shadow_grid() const { return area_shadow_grid; }
	// Upstream Godot 4.7's area_texture (default null): the light's emitted colour over the rectangle, the
	// image upright as seen from the lit side (u along local -X, v along local -Y). The radiance at a point
	// is L_e times the texture's linear colour there; a white texture equals no texture.
	void set_area_texture(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_area_texture() const { return area_texture; }

	// Thesis Listing A.1: the shape grown by the range r (RendererLightStorage::compute_area_light_aabb):
	// rectangle and disk sideways and in front, AABB(-(a/2 + r, b/2 + r, r), (a + 2r, b + 2r, r)); sphere
	// and tube all around.
	AABB get_aabb() const override;

	AreaLight3D();
};

VARIANT_ENUM_CAST(Light3D::Param);
VARIANT_ENUM_CAST(Light3D::BakeMode);
VARIANT_ENUM_CAST(DirectionalLight3D::ShadowMode);
VARIANT_ENUM_CAST(DirectionalLight3D::SkyMode);
VARIANT_ENUM_CAST(OmniLight3D::ShadowMode);
VARIANT_ENUM_CAST(AreaLight3D::AreaShape);
VARIANT_ENUM_CAST(AreaLight3D::AreaShadingMethod);
VARIANT_ENUM_CAST(AreaLight3D::AreaShadowMode);
