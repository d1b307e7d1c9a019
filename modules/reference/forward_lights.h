/**************************************************************************/
/*  forward_lights.h                                                      */
/**************************************************************************/
/* godot-area: the C++ twin of servers/rendering/renderer_rd/shaders/scene_forward_lights_inc.glsl and  */
/* servers/rendering/renderer_rd/shaders/light_data_inc.glsl (punctual light evaluation of the Forward+ */
/* renderer): Godot 4's distance attenuation, the spot cone falloff and   */
/* the per-light BRDF sum  L_o += f(l, v) L_i (n.l). Same function names  */
/* and arithmetic as the GLSL; the reference renderer shades in world     */
/* space instead of view space (rotation invariant).                      */
/*                                                                        */
/* Light units (scene_forward_lights_inc.glsl): LightData::color is       */
/* srgb_to_linear(light_color) * energy * pi (negative for negative       */
/* lights), filled exactly as RendererRD::LightStorage::fill_light_data.  */

#pragma once

#include "modules/reference/brdf.h"

namespace ReferenceBRDF {

// Mirror of struct LightData (servers/rendering/renderer_rd/shaders/light_data_inc.glsl), world space instead of view space.
struct LightData {
	Vector3 position; // World space, metres.
	float inv_radius = 1.0f; // 1 / range (1/m).
	Vector3 direction = Vector3(0, 0, -1); // World space, unit; spot axis. Unused for omni.
	float size = 0.0f; // Light size (m); reserved for soft shadows.
	Vector3 color; // Linear colour * energy * pi.
	float attenuation = 1.0f; // Distance exponent.
	float cone_attenuation = 0.0f; // Spot rim falloff exponent. Omni: 0.
	float cone_angle = -1.0f; // Spot: cos(half angle). Omni: -1.
	float specular_amount = 1.0f; // "light_specular".
	uint32_t cull_mask = 0xFFFFFFFF;
};

// Godot 4's omni/spot distance attenuation: (max(1 - (d/r)^4, 0))^2 * max(d, 1e-4)^-decay. Unitless.
inline float get_omni_attenuation(float p_distance, float p_inv_range, float p_decay) {
	float nd = p_distance * p_inv_range;
	nd *= nd;
	nd *= nd; // (d / r)^4
	nd = std::max(1.0f - nd, 0.0f);
	nd *= nd; // (1 - (d / r)^4)^2
	return nd * std::pow(std::max(p_distance, 0.0001f), -p_decay);
}

// Godot 4's spot cone falloff; exactly 0 outside the cone. Unitless, in [0, 1).
inline float get_spot_cone_attenuation(const Vector3 &p_light_to_fragment_dir, const Vector3 &p_spot_axis, float p_cone_angle, float p_cone_attenuation) {
	float c = p_light_to_fragment_dir.dot(p_spot_axis);
	if (c <= p_cone_angle) {
		return 0.0f;
	}
	float rim = std::max(0.0001f, (1.0f - c) / std::max(1.0f - p_cone_angle, 1e-6f));
	return 1.0f - std::pow(rim, p_cone_attenuation);
}

// Adds one light's contribution. N, V, L unit vectors (same space). p_light_radiance = color *
// attenuation. r_diffuse accumulates diffuse without albedo, r_specular reflected specular radiance.
inline void light_compute(const Vector3 &N, const Vector3 &L, const Vector3 &V, const Vector3 &p_light_radiance, float p_specular_amount, uint32_t p_diffuse_mode, float p_roughness, const Vector3 &p_f0, float p_f90, bool p_specular_enabled, Vector3 &r_diffuse, Vector3 &r_specular) {
	float NoL = N.dot(L);
	if (NoL <= 0.0f) {
		return;
	}
	Vector3 H = (V + L).normalized();
	float NoV = std::max(N.dot(V), 1e-4f);
	float NoH = glsl_clamp(N.dot(H), 0.0f, 1.0f);
	float LoH = glsl_clamp(L.dot(H), 0.0f, 1.0f);

	r_diffuse += p_light_radiance * (brdf_diffuse(p_diffuse_mode, NoV, NoL, LoH, p_roughness) * NoL);
	if (p_specular_enabled) {
		Vector3 s = brdf_specular(NoV, NoL, NoH, LoH, p_roughness, p_f0, p_f90);
		r_specular += (p_light_radiance * p_specular_amount) * s * NoL;
	}
}

// Returns the radiance arriving from an omni light at p_vertex (color * attenuation) and the unit
// direction towards it in r_L, or false when the attenuation is 0 (light_process_omni's early out).
inline bool light_omni_radiance(const LightData &p_light, const Vector3 &p_vertex, Vector3 &r_L, float &r_distance, Vector3 &r_radiance) {
	Vector3 light_rel_vec = p_light.position - p_vertex;
	float light_length = light_rel_vec.length();
	float attenuation = get_omni_attenuation(light_length, p_light.inv_radius, p_light.attenuation);
	if (attenuation <= 0.0f) {
		return false;
	}
	r_L = light_rel_vec / std::max(light_length, 1e-6f);
	r_distance = light_length;
	r_radiance = p_light.color * attenuation;
	return true;
}

// Spot version (light_process_spot): distance attenuation times the cone falloff.
inline bool light_spot_radiance(const LightData &p_light, const Vector3 &p_vertex, Vector3 &r_L, float &r_distance, Vector3 &r_radiance) {
	Vector3 light_rel_vec = p_light.position - p_vertex;
	float light_length = light_rel_vec.length();
	float attenuation = get_omni_attenuation(light_length, p_light.inv_radius, p_light.attenuation);
	Vector3 L = light_rel_vec / std::max(light_length, 1e-6f);
	attenuation *= get_spot_cone_attenuation(-L, p_light.direction, p_light.cone_angle, p_light.cone_attenuation);
	if (attenuation <= 0.0f) {
		return false;
	}
	r_L = L;
	r_distance = light_length;
	r_radiance = p_light.color * attenuation;
	return true;
}

} // namespace ReferenceBRDF
