/**************************************************************************/
/*  light_storage.h                                                       */
/**************************************************************************/
/* godot-area: abstract light resource storage (Godot's                   */
/* RendererLightStorage). Implemented on the CPU by                       */
/* RendererDummy::LightStorage and on Vulkan by RendererRD::LightStorage. */
/* Every setter of an implementation follows the storage pattern: look up */
/* and null-check, validate (validate_param), return early if unchanged,  */
/* bump the version only when culling or shadows are affected.            */

#pragma once

#include "servers/rendering_server.h"

class RendererLightStorage {
public:
	// Storage defaults of each parameter for a light type (Godot's storage defaults, NOT node defaults).
	static float get_default_param(RS::LightType p_type, RS::LightParam p_param);
	// Checks a parameter value: finite, and non-negative where negative makes no sense
	// (range, size, attenuation, spot angle 0..180, ...). Prints an error naming the parameter and
	// returns false when the value must be rejected (the caller keeps the old value).
	static bool validate_param(RS::LightParam p_param, float p_value);
	// Type-aware check: validate_param(p_param, p_value), plus the rules of the light type (an area
	// light's attenuation is an exponent >= 0 of its range window). Prints an error naming the parameter
	// and returns false when the value must be rejected.
	static bool validate_param(RS::LightType p_type, RS::LightParam p_param, float p_value);
	// Checks an area light size: both components finite and >= 0. Prints an error and returns false otherwise.
	static bool validate_area_size(const Vector2 &p_size);
	// Storage default of an area light's size (1 x 1 m).
	static Vector2 get_default_area_size() { return Vector2(1, 1); }
	// Returns the local-space bound of a light: omni cube of side 2 * range, spot cone AABB
	// (along -Z; a sphere cube when the angle is 90 degrees or more), directional empty, area
	// compute_area_light_aabb(p_range, p_area_size).
	static AABB compute_light_aabb(RS::LightType p_type, float p_range, float p_spot_angle_degrees, const Vector2 &p_area_size = Vector2(), RS::LightAreaShape p_area_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE);
	// Local-space bound of an area light (thesis Listing A.1): the shape grown by the range r. One-sided
	// shapes (rectangle, disk: a x b in the XY plane) only in front (-Z): AABB(-(a/2 + r, b/2 + r, r),
	// (a + 2r, b + 2r, r)). Shapes emitting all around: sphere (radius a/2) the cube of half side a/2 + r,
	// tube (segment a along X, radius b/2) the box of half extents (a/2 + b/2 + r, b/2 + r, b/2 + r).
	static AABB compute_area_light_aabb(float p_range, const Vector2 &p_size, RS::LightAreaShape p_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE);
	// Radius of the culling sphere of an area light around its centre (thesis eq. 5.1): the range plus
	// the largest distance of a point of the shape from the centre: rectangle sqrt(a^2 + b^2) / 2, disk
	// max(a, b) / 2, sphere a / 2, tube (a + b) / 2.
	static float compute_area_light_cull_radius(float p_range, const Vector2 &p_size, RS::LightAreaShape p_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE);
	// Emitting area (m^2) of an area light's shape, the A of area_normalize_energy: rectangle a b, disk
	// (ellipse of diameters a, b) pi a b / 4, sphere (diameter a) pi a^2, tube (capsule: segment a,
	// diameter b) pi b a + pi b^2.
	static float compute_area_light_emitting_area(const Vector2 &p_size, RS::LightAreaShape p_shape);
	// True for shapes that emit from both sides / all around (sphere, tube): no one-sided half space.
	static bool is_area_shape_two_sided(RS::LightAreaShape p_shape) { return p_shape == RS::LIGHT_AREA_SHAPE_SPHERE || p_shape == RS::LIGHT_AREA_SHAPE_TUBE; }
	// Returns the parameter's enum name ("LIGHT_PARAM_RANGE"), for messages.
	static const char *get_param_name(RS::LightParam p_param);

	// Creates a light of the given type with storage defaults.
	virtual RID light_create(RS::LightType p_type) = 0;
	// Frees a light; returns false if this storage does not own p_rid.
	virtual bool light_free(RID p_rid) = 0;
	// Returns true if p_rid is a light of this storage.
	virtual bool owns_light(RID p_rid) const = 0;

	// Sets one scalar parameter (validated).
	virtual void light_set_param(RID p_light, RS::LightParam p_param, float p_value) = 0;
	// Sets the colour (sRGB).
	virtual void light_set_color(RID p_light, const Color &p_color) = 0;
	// Enables shadows.
	virtual void light_set_shadow(RID p_light, bool p_enabled) = 0;
	// Makes the light negative.
	virtual void light_set_negative(RID p_light, bool p_enable) = 0;
	// Sets the layers the light affects.
	virtual void light_set_cull_mask(RID p_light, uint32_t p_mask) = 0;
	// Sets the layers that cast shadows.
	virtual void light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) = 0;
	// Sets reverse-face shadow rendering.
	virtual void light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) = 0;
	// Sets the bake mode.
	virtual void light_set_bake_mode(RID p_light, RS::LightBakeMode p_mode) = 0;
	// Sets distance fade parameters.
	virtual void light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) = 0;
	// Sets the omni shadow mode.
	virtual void light_omni_set_shadow_mode(RID p_light, RS::LightOmniShadowMode p_mode) = 0;
	// Sets the directional shadow mode.
	virtual void light_directional_set_shadow_mode(RID p_light, RS::LightDirectionalShadowMode p_mode) = 0;
	// Sets PSSM split blending.
	virtual void light_directional_set_blend_splits(RID p_light, bool p_enable) = 0;
	// Sets the directional sky mode.
	virtual void light_directional_set_sky_mode(RID p_light, RS::LightDirectionalSkyMode p_mode) = 0;
	// Sets an area light's rectangle (validate_area_size; bump the version: the bound changes).
	virtual void light_area_set_size(RID p_light, const Vector2 &p_size) = 0;
	// Sets whether an area light divides its radiance by its area.
	virtual void light_area_set_normalize_energy(RID p_light, bool p_enable) = 0;
	// Sets an area light's shading method.
	virtual void light_area_set_shading_method(RID p_light, RS::LightAreaShadingMethod p_method) = 0;
	// Sets an area light's stochastic sample count (RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN..MAX).
	virtual void light_area_set_stochastic_samples(RID p_light, int p_samples) = 0;
	// Area-light shadows: mode and FIXED sample grid (RS::LIGHT_AREA_SHADOW_GRID_MIN..MAX).
	virtual void light_area_set_shadow_mode(RID p_light, RS::LightAreaShadowMode p_mode) = 0;
	virtual void light_area_set_shadow_grid(RID p_light, int p_grid) = 0;
	// Sets an area light's shape (bump the version: the bound changes).
	virtual void light_area_set_shape(RID p_light, RS::LightAreaShape p_shape) = 0;
	// area_texture: a texture of the material storage, or RID() for none.
	virtual void light_area_set_texture(RID p_light, RID p_texture) = 0;

	// Returns the type (LIGHT_DIRECTIONAL with an error for an invalid RID).
	virtual RS::LightType light_get_type(RID p_light) const = 0;
	// Returns one parameter (0 for an invalid RID or index).
	virtual float light_get_param(RID p_light, RS::LightParam p_param) const = 0;
	// Returns the colour (sRGB).
	virtual Color light_get_color(RID p_light) const = 0;
	// Returns whether shadows are enabled.
	virtual bool light_has_shadow(RID p_light) const = 0;
	// Returns whether the light is negative.
	virtual bool light_is_negative(RID p_light) const = 0;
	// Returns the cull mask.
	virtual uint32_t light_get_cull_mask(RID p_light) const = 0;
	// Returns the shadow caster mask.
	virtual uint32_t light_get_shadow_caster_mask(RID p_light) const = 0;
	// Returns the reverse-face shadow flag.
	virtual bool light_get_reverse_cull_face_mode(RID p_light) const = 0;
	// Returns the bake mode.
	virtual RS::LightBakeMode light_get_bake_mode(RID p_light) const = 0;
	// Returns whether distance fade is on.
	virtual bool light_is_distance_fade_enabled(RID p_light) const = 0;
	// Returns distance fade begin (m).
	virtual float light_get_distance_fade_begin(RID p_light) const = 0;
	// Returns distance fade shadow distance (m).
	virtual float light_get_distance_fade_shadow(RID p_light) const = 0;
	// Returns distance fade length (m).
	virtual float light_get_distance_fade_length(RID p_light) const = 0;
	// Returns the omni shadow mode.
	virtual RS::LightOmniShadowMode light_omni_get_shadow_mode(RID p_light) const = 0;
	// Returns the directional shadow mode.
	virtual RS::LightDirectionalShadowMode light_directional_get_shadow_mode(RID p_light) const = 0;
	// Returns PSSM split blending.
	virtual bool light_directional_get_blend_splits(RID p_light) const = 0;
	// Returns the directional sky mode.
	virtual RS::LightDirectionalSkyMode light_directional_get_sky_mode(RID p_light) const = 0;
	// Returns an area light's rectangle in metres (zero with an error for an invalid RID).
	virtual Vector2 light_area_get_size(RID p_light) const = 0;
	// Returns whether an area light normalises its energy.
	virtual bool light_area_get_normalize_energy(RID p_light) const = 0;
	// Returns an area light's shading method.
	virtual RS::LightAreaShadingMethod light_area_get_shading_method(RID p_light) const = 0;
	// Returns an area light's stochastic sample count.
	virtual int light_area_get_stochastic_samples(RID p_light) const = 0;
	virtual RS::LightAreaShadowMode light_area_get_shadow_mode(RID p_light) const = 0;
	virtual int light_area_get_shadow_grid(RID p_light) const = 0;
	virtual RS::LightAreaShape light_area_get_shape(RID p_light) const = 0;
	virtual RID light_area_get_texture(RID p_light) const = 0;
	// Returns the local-space bound (see compute_light_aabb).
	virtual AABB light_get_aabb(RID p_light) const = 0;
	// Returns a counter bumped whenever culling or shadows are affected (cached shadows compare it).
	virtual uint64_t light_get_version(RID p_light) const = 0;

	virtual ~RendererLightStorage() {}
};
