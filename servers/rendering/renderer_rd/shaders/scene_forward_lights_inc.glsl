/**************************************************************************/
/*  scene_forward_lights_inc.glsl                                         */
/**************************************************************************/
/* Punctual light evaluation for the Forward+ scene shader: distance and  */
/* cone attenuation (Godot 4's curves) and the per-light BRDF sum of the  */
/* discretized rendering equation (thesis eq. 2.2):                       */
/*                                                                        */
/*   L_o += f(l, v) * L_i * (n.l),   L_i = light.color * attenuation      */
/*                                                                        */
/* Light units (Godot 4, non-physical light units): light.color is        */
/* srgb_to_linear(light_color) * light_energy * pi, filled by             */
/* LightStorage::update_light_buffers(). The pi cancels the 1/pi of the   */
/* Lambert BRDF, so a white Lambertian surface facing an energy-1 light   */
/* at attenuation 1 reflects exactly 1 (Godot: "energy *= Math_PI" when   */
/* physical light units are off). So, for Lambert, the reflected radiance */
/* is  albedo / pi * (pi * energy * color) * attenuation(d) * cos(theta). */
/*                                                                        */
/* Needs brdf_inc.glsl and light_data_inc.glsl included before.           */

#ifndef SCENE_FORWARD_LIGHTS_INC_GLSL
#define SCENE_FORWARD_LIGHTS_INC_GLSL

// Godot 4's omni/spot distance attenuation (get_omni_attenuation):
//   window(d) = (max(1 - (d / r)^4, 0))^2   (smooth falloff to exactly 0 at the range r)
//   falloff(d) = d^-attenuation            (attenuation = 2 is the inverse square law; 1 is Godot's default)
// d is clamped to 1e-4 m so a fragment at the light position does not divide by zero.
// Unitless; exactly 0 for d >= r.
float get_omni_attenuation(float p_distance, float p_inv_range, float p_decay) {
	float nd = p_distance * p_inv_range;
	nd *= nd;
	nd *= nd; // (d / r)^4
	nd = max(1.0 - nd, 0.0);
	nd *= nd; // (1 - (d / r)^4)^2
	return nd * pow(max(p_distance, 0.0001), -p_decay);
}

// Godot 4's spot cone falloff (light_process_spot). With c = cos(angle between the spot axis and the
// light-to-fragment direction) and c0 = cone_angle = cos(spot half angle):
//   s = max(c, c0)                                    (clamped to the cone edge)
//   rim = max(1e-4, (1 - s) / (1 - c0))               (0 on the axis, 1 on and outside the edge)
//   cone = 1 - rim^cone_attenuation
// Outside the cone s = c0, rim = 1 and cone = 1 - 1 = 0 EXACTLY (any exponent), which is what makes
// clustering lossless and the "outside the cone is black" test exact. Unitless, in [0, 1).
float get_spot_cone_attenuation(vec3 p_light_to_fragment_dir, vec3 p_spot_axis, float p_cone_angle, float p_cone_attenuation) {
	// highp throughout (Godot notes mediump here leaks light at the edge).
	float c = dot(p_light_to_fragment_dir, p_spot_axis);
	if (c <= p_cone_angle) {
		return 0.0; // What the formula gives (1 - 1^e); returned explicitly so no pow() rounding can leak.
	}
	float rim = max(0.0001, (1.0 - c) / max(1.0 - p_cone_angle, 1e-6));
	return 1.0 - pow(rim, p_cone_attenuation);
}

// Adds one light's contribution. All vectors in view space and unit length: N the shading normal,
// V towards the eye, L towards the light. p_light_radiance = light.color * attenuation (see top).
// r_diffuse accumulates irradiance-weighted diffuse BRDF without albedo (times albedo later),
// r_specular accumulates reflected specular radiance.
void light_compute(vec3 N, vec3 L, vec3 V, vec3 p_light_radiance, float p_specular_amount, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	float NoL = dot(N, L);
	if (NoL <= 0.0) {
		return;
	}
	vec3 H = normalize(V + L);
	// NoV clamped away from 0: grazing views would make V_SmithGGXCorrelatedFast blow up at alpha = 0.
	float NoV = max(dot(N, V), 1e-4);
	float NoH = clamp(dot(N, H), 0.0, 1.0);
	float LoH = clamp(dot(L, H), 0.0, 1.0);

	r_diffuse += p_light_radiance * (brdf_diffuse(p_diffuse_mode, NoV, NoL, LoH, p_roughness) * NoL);
	if (p_specular_enabled) {
		r_specular += p_light_radiance * p_specular_amount * brdf_specular(NoV, NoL, NoH, LoH, p_roughness, p_f0, p_f90) * NoL;
	}
}

// Omni light: distance attenuation only. p_vertex is the view-space fragment position.
void light_process_omni(LightData p_light, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	vec3 light_rel_vec = p_light.position - p_vertex;
	float light_length = length(light_rel_vec);
	float attenuation = get_omni_attenuation(light_length, p_light.inv_radius, p_light.attenuation);
	if (attenuation <= 0.0) {
		return;
	}
	vec3 L = light_rel_vec / max(light_length, 1e-6);
	light_compute(N, L, V, p_light.color * attenuation, p_light.specular_amount, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
}

// Spot light: distance attenuation times the cone falloff.
void light_process_spot(LightData p_light, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	vec3 light_rel_vec = p_light.position - p_vertex;
	float light_length = length(light_rel_vec);
	float attenuation = get_omni_attenuation(light_length, p_light.inv_radius, p_light.attenuation);
	vec3 L = light_rel_vec / max(light_length, 1e-6);
	attenuation *= get_spot_cone_attenuation(-L, p_light.direction, p_light.cone_angle, p_light.cone_attenuation);
	if (attenuation <= 0.0) {
		return;
	}
	light_compute(N, L, V, p_light.color * attenuation, p_light.specular_amount, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
}

#endif // SCENE_FORWARD_LIGHTS_INC_GLSL
