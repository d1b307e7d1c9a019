/**************************************************************************/
/*  sky_inc.glsl                                                          */
/**************************************************************************/
/* The sky of an Environment on the GPU: the data block (mirror:          */
/* SkyRD::SkyDataUBO, set 0 binding 0) and sky_evaluate(dir), the         */
/* radiance seen along a world-space direction. Used by the background    */
/* pass (sky.glsl) and the radiance cubemap filter (sky_radiance.glsl).   */
/* The C++ twin, and the formulas with their sources, are in              */
/* servers/rendering/sky_model.h (ProceduralSkyMaterial: Godot 4's        */
/* gradient and sun halo; PhysicalSkyMaterial: Preetham et al. 1999 as    */
/* Godot 4 documents it). Colours are linear and energies folded in on    */
/* the CPU; the block holds only what a direction needs.                  */

#ifndef SKY_INC_GLSL
#define SKY_INC_GLSL

#define SKY_MODEL_PROCEDURAL 0.0
#define SKY_MODEL_PHYSICAL 1.0

layout(set = 0, binding = 0, std140) uniform SkyDataBlock { // Mirror: SkyRD::SkyDataUBO.
	mat4 view_from_clip; // Inverse of the depth-corrected projection (background pass only).
	mat4 world_from_view;
	vec4 viewport_size; // xy pixels.
	vec4 sky_top; // rgb linear * energies; w = model (SKY_MODEL_*).
	vec4 sky_horizon;
	vec4 ground_bottom;
	vec4 ground_horizon;
	vec4 curves; // sky_curve, ground_curve, sun_angle_max (rad), sun_curve.
	vec4 sun_direction; // xyz world, towards the sun; w = size (rad).
	vec4 sun_radiance; // rgb; w = 1 when a sun drives the sky.
	// PhysicalSkyMaterial (sky_model.h, SkyModel::physical_*).
	vec4 rayleigh_beta; // rgb; w = sun energy 0.757 max(cos zenith, 0) * light_energy.
	vec4 mie_beta; // rgb; w = mie_eccentricity.
	vec4 physical_ground; // rgb linear ground_color; w = sun_fade.
	vec4 physical_sun; // rgb linear light colour; w = exposure (energy_multiplier * background energy).
	vec4 physical_disk; // x = cos(size * scale), y = cos(size * scale / 2), z = cos(sun zenith angle).
}
sky;

float sky_curve_blend(float p_c, float p_curve) {
	float base = clamp(1.0 - p_c, 0.0, 1.0);
	float t = p_curve > 0.0 ? 1.0 - pow(base, 1.0 / p_curve) : (base < 1.0 ? 1.0 : 0.0);
	return clamp(t, 0.0, 1.0);
}

vec3 sky_evaluate_procedural(vec3 p_dir) {
	const float half_pi = 1.57079632679;
	float v = acos(clamp(p_dir.y, -1.0, 1.0));
	if (p_dir.y >= 0.0) {
		vec3 c = mix(sky.sky_horizon.rgb, sky.sky_top.rgb, sky_curve_blend(1.0 - v / half_pi, sky.curves.x));
		if (sky.sun_radiance.w > 0.0) {
			float s = acos(clamp(dot(sky.sun_direction.xyz, p_dir), -1.0, 1.0));
			float size = sky.sun_direction.w;
			if (s < size) {
				c = sky.sun_radiance.rgb;
			} else if (s < sky.curves.z) {
				float c2 = (s - size) / max(sky.curves.z - size, 1e-6);
				c = mix(sky.sun_radiance.rgb, c, sky_curve_blend(c2, sky.curves.w));
			}
		}
		return c;
	}
	return mix(sky.ground_horizon.rgb, sky.ground_bottom.rgb, sky_curve_blend((v - half_pi) / half_pi, sky.curves.y));
}

vec3 sky_evaluate_physical(vec3 p_dir) {
	if (sky.sun_radiance.w <= 0.0) {
		return vec3(0.0); // No sun: Godot shows only night_sky (not drawn here).
	}
	const float pi = 3.14159265359;
	vec3 beta_r = sky.rayleigh_beta.rgb;
	vec3 beta_m = sky.mie_beta.rgb;
	float sun_energy = sky.rayleigh_beta.w;
	// Optical mass along the view ray (Kasten and Young's air mass form, Godot's constants).
	float mu = max(0.0, p_dir.y);
	float optical_mass = 1.0 / (mu + 0.15 * pow(3.885 + 54.5 * mu, -1.253));
	vec3 extinction = exp(-(beta_r * (8.4e3 * optical_mass) + beta_m * (1.25e3 * optical_mass)));
	float cos_theta = dot(p_dir, sky.sun_direction.xyz);
	float rayleigh_phase = (3.0 / (16.0 * pi)) * (1.0 + (cos_theta * 0.5 + 0.5) * (cos_theta * 0.5 + 0.5));
	float g = sky.mie_beta.w;
	float mie_phase = (1.0 / (4.0 * pi)) * (1.0 - g * g) / pow(max(1.0 + g * g - 2.0 * g * cos_theta, 1e-6), 1.5);
	vec3 scatter = sun_energy * (beta_r * rayleigh_phase + beta_m * mie_phase) / max(beta_r + beta_m, vec3(1e-12));
	vec3 lin = pow(scatter * (1.0 - extinction), vec3(1.5));
	lin *= mix(vec3(1.0), pow(scatter * extinction, vec3(0.5)), clamp(pow(1.0 - sky.physical_disk.z, 5.0), 0.0, 1.0));
	lin *= mix(sky.physical_ground.rgb, vec3(1.0), smoothstep(-0.1, 0.1, p_dir.y));
	float disk = 0.0;
	if (sky.physical_disk.y > sky.physical_disk.x) {
		disk = smoothstep(sky.physical_disk.x, sky.physical_disk.y, cos_theta);
	}
	vec3 c = lin + (sun_energy * extinction) * disk * sky.physical_sun.rgb;
	return pow(max(c, vec3(0.0)), vec3(1.0 / (1.2 + 1.2 * sky.physical_ground.w))) * sky.physical_sun.w;
}

vec3 sky_evaluate(vec3 p_dir) {
	if (sky.sky_top.w == SKY_MODEL_PHYSICAL) {
		return sky_evaluate_physical(p_dir);
	}
	return sky_evaluate_procedural(p_dir);
}

#endif // SKY_INC_GLSL
