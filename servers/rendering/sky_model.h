/**************************************************************************/
/*  sky_model.h                                                           */
/**************************************************************************/
/* godot-area: the sky of an Environment on the CPU, shared by the        */
/* Forward+ renderer (irradiance spherical harmonics for sky ambient,     */
/* uploaded once per sky change) and the Embree reference (background,    */
/* importance-sampled environment light). The GPU background pass         */
/* (shaders/sky.glsl) evaluates the same formula per pixel.               */
/*                                                                        */
/* ProceduralSkyMaterial (Godot 4's formula, directions world space, y up,*/
/* colours linear): with v = acos(dir.y) and h = pi/2,                    */
/*   above the horizon: c = 1 - v/h,                                       */
/*     sky = mix(horizon, top, clamp(1 - (1 - c)^(1/sky_curve))) * e_sky; */
/*     the sun (first DirectionalLight3D whose sky_mode is not LIGHT_ONLY, */
/*     angle s to its direction, size = light_angular_distance in rad):   */
/*     s < size: sky = sun_colour * sun_energy; s < sun_angle_max:        */
/*     sky = mix(sun, sky, clamp(1 - (1 - (s - size)/(max - size))^(1/sun_curve)));*/
/*   below: c = (v - h)/h,                                                 */
/*     ground = mix(ground_horizon, ground_bottom, clamp(1 - (1 - c)^(1/ground_curve))) * e_ground;*/
/*   result * energy_multiplier * background_energy_multiplier.           */
/*                                                                        */
/* PhysicalSkyMaterial (Godot 4's shader, scene/resources/3d/           */
/* sky_material.cpp, documented as "the Preetham analytic daylight      */
/* model": Preetham, Shirley & Smits 1999, "A Practical Analytic Model   */
/* for Daylight", with the Rayleigh/Mie in-scattering form of Hoffman &  */
/* Preetham 2002), with s = the light direction, mu_s = s.y, d = view:   */
/*   sun_energy E = max(0, 0.757 mu_s) * light_energy,                    */
/*   sun_fade f = 1 - clamp(1 - exp(mu_s), 0, 1),                         */
/*   beta_R = (rayleigh_coefficient - (1 - f)) * rayleigh_color * 1e-4,   */
/*   beta_M = turbidity * mie_coefficient * mie_color * 4.34e-4,           */
/*   m = 1 / (mu + 0.15 (3.885 + 54.5 mu)^-1.253), mu = max(0, d.y),      */
/*   T = exp(-(beta_R 8.4e3 m + beta_M 1.25e3 m)),                         */
/*   c = d.s, phase_R = 3/(16 pi) (1 + ((c + 1)/2)^2),                    */
/*   phase_M = Henyey-Greenstein(c, mie_eccentricity),                     */
/*   S = E (beta_R phase_R + beta_M phase_M) / (beta_R + beta_M),          */
/*   L_in = (S (1 - T))^1.5 * mix(1, (S T)^0.5, clamp((1 - mu_s)^5)),     */
/*   L_in *= mix(ground_color, 1, smoothstep(-0.1, 0.1, d.y)),             */
/*   disk = smoothstep(cos(size k), cos(size k / 2), c), k = sun_disk_scale,*/
/*   L = (L_in + E T disk light_colour)^(1 / (1.2 + 1.2 f))               */
/*       * energy_multiplier * background_energy_multiplier;              */
/*   no sun: black (night_sky is stored, not drawn). Colours linear.       */
/*                                                                        */
/* Irradiance SH: Ramamoorthi & Hanrahan 2001, "An Efficient              */
/* Representation for Irradiance Environment Maps": 9 coefficients       */
/* L_lm projected by midpoint quadrature on a latitude-longitude grid,    */
/* E(n) = sum_lm A_l L_lm Y_lm(n) with A_0 = pi, A_1 = 2pi/3, A_2 = pi/4.  */

#pragma once

#include "core/math/vector3.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering_server.h"

#include <cstdint>
#include <vector>

struct SkyModel {
	enum Type {
		TYPE_PROCEDURAL,
		TYPE_PHYSICAL,
	};
	Type type = TYPE_PROCEDURAL;
	// Linear, energies folded in (sky: e_sky * energy * bg, ground: e_ground * energy * bg).
	Vector3 sky_top;
	Vector3 sky_horizon;
	Vector3 ground_bottom;
	Vector3 ground_horizon;
	float sky_curve = 0.15f;
	float ground_curve = 0.02f;
	float sun_angle_max = 0.5235988f; // Radians.
	float sun_curve = 0.15f;
	bool sun_enabled = false;
	Vector3 sun_direction = Vector3(0, 1, 0); // World space, towards the sun.
	Vector3 sun_radiance; // Linear colour * light_energy * energy * bg.
	float sun_size = 0.0f; // Radians.
	// PhysicalSkyMaterial terms that do not depend on the view direction (formula above).
	Vector3 rayleigh_beta;
	Vector3 mie_beta;
	float mie_eccentricity = 0.8f;
	Vector3 physical_ground; // Linear ground_color.
	float sun_fade = 1.0f;
	float sun_energy = 0.0f; // E above.
	float sun_zenith_cos = 1.0f; // mu_s.
	Vector3 physical_sun_color; // Linear light colour.
	float exposure = 1.0f; // energy_multiplier * background_energy_multiplier.
	float disk_cos_outer = 1.0f; // cos(size * sun_disk_scale).
	float disk_cos_inner = 1.0f; // cos(size * sun_disk_scale / 2).

	// p_sun_direction: towards the sun (world); p_sun_color sRGB; p_bg_energy background_energy_multiplier.
	static SkyModel from_procedural(const RS::ProceduralSkyParams &p_params, float p_bg_energy, bool p_sun, const Vector3 &p_sun_direction, const Color &p_sun_color, float p_sun_energy, float p_sun_angular_distance_deg);

	// p_sun_direction towards the sun; p_sun_color sRGB; p_sun_angular_distance_deg the light's angular diameter.
	static SkyModel from_physical(const RS::PhysicalSkyParams &p_params, float p_bg_energy, bool p_sun, const Vector3 &p_sun_direction, const Color &p_sun_color, float p_sun_energy, float p_sun_angular_distance_deg);

	// The sky model of a view: the environment's procedural sky, its disk following the first directional
	// light whose sky_mode is not LIGHT_ONLY (Godot's LIGHT0). GPU and reference both call it.
	static SkyModel from_scene_data(const RenderSceneData &p_data, const class RendererLightStorage *p_light_storage);

	// Radiance seen along unit world direction p_dir.
	Vector3 evaluate(const Vector3 &p_dir) const;
	Vector3 evaluate_procedural(const Vector3 &p_dir) const;
	Vector3 evaluate_physical(const Vector3 &p_dir) const;

	// Irradiance SH (9 coefficients per channel, already times A_l): E(n) = sum_i sh[i] * Y_i(n).
	void compute_irradiance_sh(float r_sh[9][3], int p_rows = 96) const;
	static Vector3 evaluate_sh(const float p_sh[9][3], const Vector3 &p_n);
	// Real SH basis Y_0..Y_8 (l <= 2) at unit p_n.
	static void sh_basis(const Vector3 &p_n, float r_y[9]);

	// Key for "recompute only when the sky changes": equal models give equal keys.
	uint64_t get_hash() const;
};
