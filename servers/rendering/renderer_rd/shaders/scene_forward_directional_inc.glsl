/**************************************************************************/
/*  scene_forward_directional_inc.glsl                                    */
/**************************************************************************/
/* Directional light (sun) evaluation for the Forward+ scene shader,      */
/* compiled only into versions with USE_DIRECTIONAL_LIGHTS (views that   */
/* have a DirectionalLight3D). Not clustered: every fragment evaluates    */
/* every directional light, as Godot's light_process_directional loop.   */
/*                                                                        */
/* Units (Godot 4, no physical light units): light.color is               */
/* srgb_to_linear(light_color) * light_energy * pi, so a white Lambert    */
/* surface whose normal makes the angle theta with the light reflects     */
/* light_energy * cos(theta) (the same pi as punctual lights, see         */
/* scene_forward_lights_inc.glsl). The sun is treated as a direction      */
/* here; its disk (light.size) matters for the Embree reference (which   */
/* samples it) and for soft shadows. The cosine over a disk fully above  */
/* the horizon integrates to exactly the centre's cosine (the projected  */
/* solid angle of a spherical cap is pi sin^2(a) cos(theta)), so Lambert */
/* results agree with the reference to rounding.                          */
/*                                                                        */
/* Needs brdf_inc.glsl, light_data_inc.glsl and                           */
/* scene_forward_lights_inc.glsl (light_compute) included before.         */
/* USE_DIRECTIONAL_SHADOWS adds the shadow lookup (bindings 16-19).       */

#ifndef SCENE_FORWARD_DIRECTIONAL_INC_GLSL
#define SCENE_FORWARD_DIRECTIONAL_INC_GLSL

void light_process_directional(DirectionalLightData p_light, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, float p_shadow, inout vec3 r_diffuse, inout vec3 r_specular) {
	vec3 L = -p_light.direction;
	light_compute(N, L, V, p_light.color * p_shadow, p_light.specular_amount, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
}

#ifdef USE_DIRECTIONAL_SHADOWS
/* Directional shadows (DirectionalShadowRD, directional_shadow_rd.h):    */
/* only in versions of views with a shadowed directional light. Mirror   */
/* of DirectionalShadowRD::ShadowData (std140, 432 bytes).               */
struct DirectionalShadowData {
	mat4 shadow_from_view[4]; // View space -> (atlas u, v, depth 0..1) per split.
	vec4 split_end; // View depth (m) where each split ends.
	vec4 bias; // Depth offset per split (depth units): Godot's shadow_bias in metres / the split's depth range.
	vec4 normal_bias; // Receiver offset along its normal per split (m).
	vec4 radius; // Box half side per split (m).
	vec4 depth_range; // Metres spanned by depth 0..1 per split.
	vec4 uv_rect[4]; // Atlas rect per split (u0, v0, u1, v1).
	vec4 params; // split count, blend_splits, fade start (m), fade end = max distance (m).
	vec4 params2; // tan(sun angular radius), shadow_opacity, shadow_blur, atlas texel (uv).
};

#define MAX_DIRECTIONAL_SHADOWS 4 // DirectionalShadowRD::MAX_SHADOWED_LIGHTS.
layout(set = 0, binding = 16, std140) uniform DirectionalShadows {
	DirectionalShadowData data[MAX_DIRECTIONAL_SHADOWS];
}
directional_shadows;
layout(set = 0, binding = 17) uniform texture2D directional_shadow_atlas;
layout(set = 0, binding = 18) uniform sampler directional_shadow_compare_sampler; // Linear, compare LESS_OR_EQUAL.
layout(set = 0, binding = 19) uniform sampler directional_shadow_nearest_sampler; // Blocker search.

#define DIRECTIONAL_SHADOW_TAPS 16
#define DIRECTIONAL_SHADOW_GOLDEN_ANGLE 2.39996323

// Vogel disk tap p_i of DIRECTIONAL_SHADOW_TAPS, rotated by p_rotation (radians), radius <= 1.
vec2 directional_shadow_disk(int p_i, float p_rotation) {
	float r = sqrt((float(p_i) + 0.5) / float(DIRECTIONAL_SHADOW_TAPS));
	float theta = float(p_i) * DIRECTIONAL_SHADOW_GOLDEN_ANGLE + p_rotation;
	return r * vec2(cos(theta), sin(theta));
}

// Visibility 0..1 of split p_split of shadow p_shadow at view-space p_vertex. Penumbra from the sun disk:
// a blocker search over the widest penumbra the receiver can have, then PCF of width
// 2 tan(a) (receiver - blocker) (PCSS, Fernando 2005); at least shadow_blur texels.
float directional_shadow_split(uint p_shadow, uint p_split, vec3 p_vertex, vec3 p_normal, vec3 p_L, float p_rotation) {
	// Normal offset (Godot 4's): along the normal, scaled by 1 - max(0, L.(-N)) (full on faces towards the light,
	// less on faces turned away), without its component along the light.
	vec3 offset = p_normal * ((1.0 - max(0.0, dot(p_L, -p_normal))) * directional_shadows.data[p_shadow].normal_bias[p_split]);
	offset -= p_L * dot(p_L, offset);
	vec4 c = directional_shadows.data[p_shadow].shadow_from_view[p_split] * vec4(p_vertex + offset, 1.0);
	vec4 rect = directional_shadows.data[p_shadow].uv_rect[p_split];
	if (c.x < rect.x || c.y < rect.y || c.x > rect.z || c.y > rect.w || c.z >= 1.0) {
		return 1.0; // Outside the split's box (beyond its far side: no caster there).
	}
	float z = c.z - directional_shadows.data[p_shadow].bias[p_split];
	float texel = directional_shadows.data[p_shadow].params2.w;
	vec2 uv_per_m = (rect.zw - rect.xy) / (2.0 * directional_shadows.data[p_shadow].radius[p_split]);
	float range = directional_shadows.data[p_shadow].depth_range[p_split];
	float tan_a = directional_shadows.data[p_shadow].params2.x;
	vec2 lo = rect.xy + vec2(0.5 * texel), hi = rect.zw - vec2(0.5 * texel);
	vec2 filter_uv = vec2(max(directional_shadows.data[p_shadow].params2.z, 0.0) * texel);
	if (tan_a > 0.0) {
		// Blocker search: a blocker at depth d shadows within tan(a) (z - d) range metres; d >= 0.
		vec2 search_uv = max(filter_uv, tan_a * z * range * uv_per_m);
		float blockers = 0.0, blocker_depth = 0.0;
		for (int i = 0; i < DIRECTIONAL_SHADOW_TAPS; i++) {
			vec2 uv = clamp(c.xy + directional_shadow_disk(i, p_rotation) * search_uv, lo, hi);
			float d = textureLod(sampler2D(directional_shadow_atlas, directional_shadow_nearest_sampler), uv, 0.0).r;
			if (d < z) {
				blockers += 1.0;
				blocker_depth += d;
			}
		}
		if (blockers == 0.0) {
			return 1.0;
		}
		blocker_depth /= blockers;
		filter_uv = max(filter_uv, tan_a * (z - blocker_depth) * range * uv_per_m);
	}
	float lit = 0.0;
	for (int i = 0; i < DIRECTIONAL_SHADOW_TAPS; i++) {
		vec2 uv = clamp(c.xy + directional_shadow_disk(i, p_rotation) * filter_uv, lo, hi);
		lit += texture(sampler2DShadow(directional_shadow_atlas, directional_shadow_compare_sampler), vec3(uv, z));
	}
	return lit / float(DIRECTIONAL_SHADOW_TAPS);
}

// Visibility of directional shadow p_shadow at view-space p_vertex: the split holding its depth (blended
// with the next one over the split with blend_splits, as Godot), faded out towards max distance.
float directional_shadow_visibility(uint p_shadow, vec3 p_vertex, vec3 p_normal, vec3 p_L) {
	float depth = -p_vertex.z;
	vec4 params = directional_shadows.data[p_shadow].params;
	if (depth >= params.w) {
		return 1.0;
	}
	uint count = uint(params.x);
	uint split = 0u;
	while (split + 1u < count && depth >= directional_shadows.data[p_shadow].split_end[split]) {
		split++;
	}
	// Interleaved gradient noise (Jimenez 2014) rotates the taps per pixel: noise instead of banding.
	float rotation = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
	float shadow = directional_shadow_split(p_shadow, split, p_vertex, p_normal, p_L, rotation);
	if (params.y > 0.0 && split + 1u < count) {
		float begin = split == 0u ? 0.0 : directional_shadows.data[p_shadow].split_end[split - 1u];
		float blend = smoothstep(begin, directional_shadows.data[p_shadow].split_end[split], depth);
		shadow = mix(shadow, directional_shadow_split(p_shadow, split + 1u, p_vertex, p_normal, p_L, rotation), blend);
	}
	shadow = mix(shadow, 1.0, smoothstep(params.z, params.w, depth));
	return mix(1.0, shadow, directional_shadows.data[p_shadow].params2.y); // shadow_opacity.
}
#endif // USE_DIRECTIONAL_SHADOWS

#endif // SCENE_FORWARD_DIRECTIONAL_INC_GLSL
