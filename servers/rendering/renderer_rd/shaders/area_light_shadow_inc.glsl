/**************************************************************************/
/*  area_light_shadow_inc.glsl                                            */
/**************************************************************************/
/* Soft shadows of area lights (thesis section 6.1, Listing A.3): the     */
/* visibility of a shading point is the average over the light's sample   */
/* maps of a PCF lookup (Heckbert and Herf), or, in the PCSS baseline     */
/* mode, a PCSS lookup of one map from the light centre. The scene shader */
/* multiplies the area light's diffuse and specular by it.                */
/*                                                                        */
/* Bindings (set 0, area-light colour variant only): 12 AreaShadowLights  */
/* (one entry per GPU area light, same index as area_lights.data),        */
/* 13 the atlas (distance * depth_scale per texel), 14 a nearest sampler. */
/* C++ mirror of AreaShadowData: AreaShadowRendererRD::AreaShadowData      */
/* (servers/rendering/renderer_rd/area_shadow_renderer.h), 448 bytes.     */
/* A light with map_count 0 is unshadowed (visibility 1); maps listed are */
/* always drawn (never garbage).                                          */

#ifndef AREA_LIGHT_SHADOW_INC_GLSL
#define AREA_LIGHT_SHADOW_INC_GLSL

#include "area_shadow_octant_inc.glsl"

#define AREA_SHADOW_MAX_MAPS 84u
#define AREA_SHADOW_MODE_FIXED 0u
#define AREA_SHADOW_MODE_PCSS 1u

// Lookups compiled in: AREA_SHADOWS_PCF (grid modes) and/or AREA_SHADOWS_PCSS (PCSS baseline), set by the
// area version key of RenderForwardClustered from the lights that have maps; with neither, both.
#if !defined(AREA_SHADOWS_PCF) && !defined(AREA_SHADOWS_PCSS)
#define AREA_SHADOWS_PCF
#define AREA_SHADOWS_PCSS
#endif

struct AreaShadowData { // std430, 448 bytes.
	mat4 light_from_view; // 0: view space -> light space (orthonormal; emission along -Z).
	vec2 half_size; // 64: rectangle half extents (m).
	float depth_scale; // 72: stored depth = distance * depth_scale.
	float bias; // 76: depth bias in texels of the receiver (shadow_bias).
	float normal_bias; // 80: normal offset in texels of the receiver (shadow_normal_bias).
	float pcf_radius; // 84: PCF kernel radius in texels.
	uint map_count; // 88: valid maps (0 = unshadowed).
	uint mode; // 92: AREA_SHADOW_MODE_*.
	uint atlas_subdivision; // 96: tiles per side.
	float atlas_texel; // 100: 1 / atlas size (pixels).
	uint quadrant_size; // 104: pixels per octant view (tile size / 2).
	uint tile_size; // 108: pixels per tile (>= 2 * quadrant_size).
	uint maps[AREA_SHADOW_MAX_MAPS]; // 112: tile | u_num << 12 | v_num << 16 | den << 20 | weight << 24 (u = u_num / den).
};

layout(set = 0, binding = 12, std430) restrict readonly buffer AreaShadowLights {
	AreaShadowData data[];
}
area_shadows;

layout(set = 0, binding = 13) uniform texture2D area_shadow_atlas;
layout(set = 0, binding = 14) uniform sampler area_shadow_sampler; // Nearest (texelFetch: PCSS).
layout(set = 0, binding = 15) uniform sampler area_shadow_compare_sampler; // Linear, compare LESS_OR_EQUAL (PCF).

vec2 area_shadow_map_uv(uint p_packed) {
	float den = float((p_packed >> 20u) & 0xFu);
	if (den == 0.0) {
		return vec2(0.5);
	}
	return vec2(float((p_packed >> 12u) & 0xFu), float((p_packed >> 16u) & 0xFu)) / den;
}

// Quadrature weight of a map: bits 24..31 / 256 when set (ADAPTIVE: the point's share of the light from
// its quadtree, AreaShadowQuadtree::get_point_weights()), else the trapezoid rule of a regular grid.
float area_shadow_map_weight(uint p_packed, vec2 p_uv) {
	uint w = p_packed >> 24u;
	if (w != 0u) {
		return float(w) * (1.0 / 256.0);
	}
	vec2 edge = mix(vec2(1.0), vec2(0.5), vec2(greaterThan(abs(p_uv - 0.5), vec2(0.4999)))); // Trapezoid rule.
	return edge.x * edge.y;
}

// Pixel origin of quadrant p_quadrant of the map's tile.
ivec2 area_shadow_quadrant_origin(uint p_packed, uint p_quadrant, uint p_subdivision, uint p_quadrant_size, uint p_tile_size) {
	uint tile = p_packed & 0xFFFu;
	uvec2 t = uvec2(tile % p_subdivision, tile / p_subdivision) * p_tile_size;
	return ivec2(t + uvec2(p_quadrant & 1u, p_quadrant >> 1u) * p_quadrant_size);
}

float area_shadow_fetch(ivec2 p_origin, int p_size, ivec2 p_texel) {
	ivec2 t = clamp(p_texel, ivec2(0), ivec2(p_size - 1)); // Never leave the quadrant.
	return texelFetch(sampler2D(area_shadow_atlas, area_shadow_sampler), p_origin + t, 0).r;
}

// Offset from the sample point p_sample to the receiver, quadrant origin, texel position and the
// receiver distance (stored units) for one map.
// r_weight: the sample's share of the light's irradiance at the receiver (quadrature weight of the point,
// area_shadow_map_weight(), times the point-to-point form factor cos_light * cos_receiver / d^2), so the average
// approximates the ratio of the shadowed to the unshadowed light integral, not a plain vote.
// p_light: index into area_shadows.data; its fields are read from the buffer where used (a local copy of the
// 448-byte record would be made per pixel and light).
float area_shadow_pcf(uint p_light, uint p_packed, vec3 p_pos, vec3 p_normal, int p_radius, float p_spacing, out float r_weight) {
	vec2 uv = area_shadow_map_uv(p_packed);
	vec3 sample_pos = vec3((uv - 0.5) * 2.0 * area_shadows.data[p_light].half_size, 0.0);
	vec3 v = p_pos - sample_pos;
	float dist = length(v);
	float grid_weight = area_shadow_map_weight(p_packed, uv);
	r_weight = grid_weight * max(-v.z, 0.0) * max(dot(p_normal, -v), 0.0) / max(dist * dist * dist * dist, 1e-12);
	// World size of one texel at the receiver (the views span about 2.5 units at distance 1).
	float texel_world = dist * (2.0 * AREA_SHADOW_OCTANT_HALF_X) / float(area_shadows.data[p_light].quadrant_size);
	v += p_normal * (area_shadows.data[p_light].normal_bias * texel_world);
	if (v.z >= 0.0) {
		return 1.0; // Not in front of this sample (the light does not reach it anyway).
	}
	uint quadrant;
	vec2 quv;
	area_shadow_octant_project(v, quadrant, quv);
	int qsize = int(area_shadows.data[p_light].quadrant_size);
	ivec2 origin = area_shadow_quadrant_origin(p_packed, quadrant, area_shadows.data[p_light].atlas_subdivision, area_shadows.data[p_light].quadrant_size, area_shadows.data[p_light].tile_size);
	vec2 center = vec2(origin) + quv * float(qsize); // Atlas pixels (texel centres at + 0.5).
	// Slope-scaled bias: across one texel a plane tilted by theta to the ray changes distance by about
	// texel_world * tan(theta); the PCF taps reach p_radius texels away.
	float cos_theta = clamp(dot(p_normal, -v) / max(length(v), 1e-6), 0.05, 1.0);
	float slope = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, 8.0);
	float receiver = (length(v) - texel_world * (area_shadows.data[p_light].bias * 10.0 + slope * (float(p_radius) * p_spacing + 1.0))) * area_shadows.data[p_light].depth_scale;
	// Hardware depth compare: each tap is a bilinear 2 x 2 PCF in one fetch (receiver <= stored: lit). Tap
	// positions stay between the quadrant's outer texel centres, so no tap reads a neighbouring view.
	vec2 lo = vec2(origin) + 0.5;
	vec2 hi = vec2(origin) + float(qsize) - 0.5;
	float atlas_texel = area_shadows.data[p_light].atlas_texel;
	float lit = 0.0;
	for (int y = -p_radius; y <= p_radius; y++) {
		for (int x = -p_radius; x <= p_radius; x++) {
			vec2 p = clamp(center + vec2(x, y) * p_spacing, lo, hi) * atlas_texel;
			lit += textureLod(sampler2DShadow(area_shadow_atlas, area_shadow_compare_sampler), vec3(p, receiver), 0.0);
		}
	}
	float n = float(2 * p_radius + 1);
	return lit / (n * n);
}

// PCSS baseline (one map from the light centre): blocker search, penumbra estimate, variable PCF.
float area_shadow_pcss(uint p_light, uint p_packed, vec3 p_pos, vec3 p_normal) {
	vec3 v = p_pos;
	float dist = length(v);
	float texel_world = dist * (2.0 * AREA_SHADOW_OCTANT_HALF_X) / float(area_shadows.data[p_light].quadrant_size);
	v += p_normal * (area_shadows.data[p_light].normal_bias * texel_world);
	if (v.z >= 0.0) {
		return 1.0;
	}
	uint quadrant;
	vec2 quv;
	area_shadow_octant_project(v, quadrant, quv);
	int qsize = int(area_shadows.data[p_light].quadrant_size);
	ivec2 origin = area_shadow_quadrant_origin(p_packed, quadrant, area_shadows.data[p_light].atlas_subdivision, area_shadows.data[p_light].quadrant_size, area_shadows.data[p_light].tile_size);
	vec2 center = quv * float(qsize);
	float cos_theta = clamp(dot(p_normal, -v) / max(length(v), 1e-6), 0.05, 1.0);
	float slope = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, 8.0);
	float receiver_m = length(v) - texel_world * (area_shadows.data[p_light].bias * 10.0 + slope * 2.0); // As area_shadow_pcf, radius 1.

	float receiver = receiver_m * area_shadows.data[p_light].depth_scale;
	float light_radius = length(area_shadows.data[p_light].half_size);
	// Search region: the light's angular radius seen from the receiver, in texels.
	float texels_per_unit = float(qsize) / (2.0 * AREA_SHADOW_OCTANT_HALF_X);
	float search = clamp(light_radius / max(receiver_m, 1e-3) * texels_per_unit, 1.0, 24.0);
	float blocker_sum = 0.0;
	float blockers = 0.0;
	for (int y = -3; y <= 3; y++) {
		for (int x = -3; x <= 3; x++) {
			float d = area_shadow_fetch(origin, qsize, ivec2(center + vec2(x, y) * (search / 3.0)));
			if (d < receiver) {
				blocker_sum += d;
				blockers += 1.0;
			}
		}
	}
	if (blockers == 0.0) {
		return 1.0;
	}
	float blocker_m = blocker_sum / blockers / area_shadows.data[p_light].depth_scale;
	// Penumbra width at the receiver (similar triangles), as an angle seen from the centre, in texels.
	float penumbra_m = 2.0 * light_radius * (receiver_m - blocker_m) / max(blocker_m, 1e-3);
	float radius = clamp(penumbra_m / max(receiver_m, 1e-3) * texels_per_unit * 0.5, 1.0, 32.0);
	float lit = 0.0;
	for (int y = -4; y <= 4; y++) {
		for (int x = -4; x <= 4; x++) {
			lit += area_shadow_fetch(origin, qsize, ivec2(center + vec2(x, y) * (radius / 4.0))) >= receiver ? 1.0 : 0.0;
		}
	}
	return lit / 81.0;
}

// Visibility (0..1) of area light p_light_index (index into area_lights.data) from view-space point
// p_vertex with unit view-space normal p_normal.
float light_process_area_shadow(uint p_light_index, vec3 p_vertex, vec3 p_normal) {
	uint count = min(area_shadows.data[p_light_index].map_count, AREA_SHADOW_MAX_MAPS);
	if (count == 0u) {
		return 1.0;
	}
	// Fields straight from the buffer, no local copy of the 448-byte record.
	mat4 light_from_view = area_shadows.data[p_light_index].light_from_view;
	vec3 pos = (light_from_view * vec4(p_vertex, 1.0)).xyz;
	vec3 normal = mat3(light_from_view) * p_normal;
#ifdef AREA_SHADOWS_PCSS
	if (area_shadows.data[p_light_index].mode == AREA_SHADOW_MODE_PCSS) {
		return area_shadow_pcss(p_light_index, area_shadows.data[p_light_index].maps[0], pos, normal);
	}
#endif
#ifdef AREA_SHADOWS_PCF
	// Filter radius from the sub-lights' penumbra: pcf_radius is the kernel of the whole light (one map).
	// The n x n sample points span the rectangle edge to edge, n - 1 steps, so neighbouring maps' shadow
	// edges lie about pcf_radius / (n - 1) texels apart: that is each sub-light's penumbra, and the average
	// over the maps is the filter beyond it (thesis 6.1). From 9 maps on: 3 x 3 bilinear compare taps
	// spread over it (one tap when it is under half a texel) instead of (2 r + 1)^2; fewer maps keep the
	// light's kernel at one-texel steps.
	float pcf_radius = area_shadows.data[p_light_index].pcf_radius;
	int radius = int(pcf_radius + 0.5);
	float spacing = 1.0;
	if (count >= 9u) {
		spacing = pcf_radius / (sqrt(float(count)) - 1.0);
		radius = spacing < 0.5 ? 0 : 1;
	}
	float visibility = 0.0;
	float total = 0.0;
	for (uint i = 0u; i < count; i++) {
		float w;
		// maps[i] straight from the buffer: a dynamically indexed array of the local copy s would be
		// copied whole into indexable memory per pixel and light (llvmpipe: about 40 % of a shadowed frame).
		float lit = area_shadow_pcf(p_light_index, area_shadows.data[p_light_index].maps[i], pos, normal, radius, spacing, w);
		visibility += lit * w;
		total += w;
	}
	return total > 0.0 ? visibility / total : 1.0;
#else
	return 1.0; // Not reached: this version's shadowed lights are all PCSS.
#endif
}

#endif // AREA_LIGHT_SHADOW_INC_GLSL
