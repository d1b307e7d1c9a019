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
/* C++ mirror of AreaShadowData: AreaShadowRendererRD::AreaShadowData     */
/* (renderer_rd/effects/area_shadow_renderer.h), 448 bytes.               */
/* A light with map_count 0 is unshadowed (visibility 1); maps listed are */
/* always drawn (never garbage).                                          */
/* Sphere and tube lights (AREA_SHADOW_FLAG_ALL_AROUND, compiled with     */
/* USE_AREA_SHAPES): each sample point lies on the shape's surface and    */
/* its map covers the half space in front of that surface point           */
/* (area_shadow_surface_map(); doc/shadows.md "Sphere and tube lights").  */

#ifndef AREA_LIGHT_SHADOW_INC_GLSL
#define AREA_LIGHT_SHADOW_INC_GLSL

#include "area_shadow_octant_inc.glsl"

#define AREA_SHADOW_MAX_MAPS 84u
#define AREA_SHADOW_MODE_FIXED 0u
#define AREA_SHADOW_MODE_PCSS 1u
#define AREA_SHADOW_MODE_MASK 0xFFu
#define AREA_SHADOW_FLAG_SAMPLE_FILTER 0x100u // mode bit: per-sample penumbra filter (else the fixed PCF).
#define AREA_SHADOW_FLAG_ALL_AROUND 0x200u // mode bit: sphere or tube, sample points on its surface (half_size: half length, radius).
#define AREA_SHADOW_FLAG_NEAR_LAYER 0x400u // mode bit: a caster is close enough for the near layer (read by the C++ version key).
// Blocker search reach: blockers nearer the sample than d_receiver / (1 + this) are searched only partly.
#define AREA_SHADOW_SEARCH_K 2.0
#define AREA_SHADOW_MAX_K 8.0
#define AREA_SHADOW_MARCH_STEPS 2
// Near layer: blockers nearer the sample than d_receiver / (1 + AREA_SHADOW_MAX_K) (a window's mullion a few
// cm in front of the light) get their own step at their own ratio, k up to AREA_SHADOW_NEAR_MAX_K, and are
// left out of the march (whose k stops at AREA_SHADOW_MAX_K, where a sample behind the bar sees nothing).
#define AREA_SHADOW_NEAR_MAX_K 200.0
#define AREA_SHADOW_NEAR_DEPTH 1.5

// Lookups compiled in: AREA_SHADOWS_PCF (grid modes) and/or AREA_SHADOWS_PCSS (PCSS baseline), set by the
// area version key of RenderForwardClustered from the lights that have maps; with neither, all of them.
// AREA_SHADOWS_NEAR_LAYER: the per-sample filter's near-layer step (area_shadow_filtered()), when some light
// has AREA_SHADOW_FLAG_NEAR_LAYER; AREA_SHADOWS_TREE: the ADAPTIVE trees' points (AREA_SHADOW_TREE_MAP), when
// some light is ADAPTIVE. A SIMD rasterizer (llvmpipe) runs untaken branches too: each cost every shadowed
// frame of the FIXED default 4-8 % (doc/shadows.md "The default").
#if !defined(AREA_SHADOWS_PCF) && !defined(AREA_SHADOWS_PCSS)
#define AREA_SHADOWS_PCF
#define AREA_SHADOWS_PCSS
#define AREA_SHADOWS_NEAR_LAYER
#define AREA_SHADOWS_TREE
#endif

struct AreaShadowData { // std430, 448 bytes.
	mat4 light_from_view; // 0: view space -> light space (orthonormal; emission along -Z).
	vec2 half_size; // 64: rectangle half extents (m); AREA_SHADOW_FLAG_ALL_AROUND: capsule half length, radius.
	float depth_scale; // 72: stored depth = distance * depth_scale.
	float bias; // 76: depth bias in texels of the receiver (shadow_bias).
	float normal_bias; // 80: normal offset in texels of the receiver (shadow_normal_bias).
	float pcf_radius; // 84: PCF kernel radius in texels.
	uint map_count; // 88: valid maps (0 = unshadowed).
	uint mode; // 92: AREA_SHADOW_MODE_* | AREA_SHADOW_FLAG_*.
	uint atlas_subdivision; // 96: tiles per side.
	float atlas_texel; // 100: 1 / atlas size (pixels).
	uint quadrant_size; // 104: pixels per octant view (tile size / 2).
	uint tile_size; // 108: pixels per tile (>= 2 * quadrant_size).
	// 112: grid point: tile | u_num << 12 | v_num << 16 | den << 20 (u = u_num / den); tree point (bit 31,
	// AREA_SHADOW_TREE_MAP): tile | (v_num * 9 + u_num) << 12 (u = u_num / 8) | cell << 19 (area_shadow_tree_cell()).
	uint maps[AREA_SHADOW_MAX_MAPS];
};

layout(set = 0, binding = 12, std430) restrict readonly buffer AreaShadowLights {
	AreaShadowData data[];
}
area_shadows;

layout(set = 0, binding = 13) uniform texture2D area_shadow_atlas;
layout(set = 0, binding = 14) uniform sampler area_shadow_sampler; // Nearest (texelFetch: PCSS).
layout(set = 0, binding = 15) uniform sampler area_shadow_compare_sampler; // Linear, compare LESS_OR_EQUAL (PCF).

#define AREA_SHADOW_TREE_MAP 0x80000000u

vec2 area_shadow_map_uv(uint p_packed) {
#ifdef AREA_SHADOWS_TREE
	if ((p_packed & AREA_SHADOW_TREE_MAP) != 0u) {
		uint index = (p_packed >> 12u) & 0x7Fu;
		return vec2(float(index % 9u), float(index / 9u)) * 0.125;
	}
#endif
	float den = float((p_packed >> 20u) & 0xFu);
	if (den == 0.0) {
		return vec2(0.5);
	}
	return vec2(float((p_packed >> 12u) & 0xFu), float((p_packed >> 16u) & 0xFu)) / den;
}

// Cell of an ADAPTIVE tree point (thesis 6.3; AreaShadowQuadtree::get_point_cells()): the quarter next to the
// point of every leaf it is a corner of. Quadrant q (bit 0: towards +u, bit 1: towards +v) holds 3 bits, 0 =
// none, else the leaf's depth + 1: the quarter is a square of side 2^-depth / 2 (canonical units).
// r_weight: the cell's area, the point's share of the light (the sum of a quarter of each leaf, so a
// non-uniform tree's points sum to the whole light: unbiased); r_lo, r_hi: the cell's bounding box, offsets
// from the point in canonical units.
void area_shadow_tree_cell(uint p_packed, out float r_weight, out vec2 r_lo, out vec2 r_hi) {
	r_weight = 0.0;
	r_lo = vec2(0.0);
	r_hi = vec2(0.0);
	for (uint q = 0u; q < 4u; q++) {
		uint code = (p_packed >> (19u + 3u * q)) & 7u;
		if (code != 0u) {
			float half_side = 0.5 * exp2(1.0 - float(code));
			r_weight += half_side * half_side;
			vec2 toward = vec2(float(q & 1u), float(q >> 1u)) * 2.0 - 1.0;
			r_lo = min(r_lo, toward * half_side);
			r_hi = max(r_hi, toward * half_side);
		}
	}
}

// Quadrature weight of a map: a tree point's share of the light (area_shadow_tree_cell()), else the
// trapezoid rule of a regular grid.
float area_shadow_map_weight(uint p_packed, vec2 p_uv) {
#ifdef AREA_SHADOWS_TREE
	if ((p_packed & AREA_SHADOW_TREE_MAP) != 0u) {
		float w;
		vec2 lo, hi;
		area_shadow_tree_cell(p_packed, w, lo, hi);
		return w;
	}
#endif
	vec2 edge = mix(vec2(1.0), vec2(0.5), vec2(greaterThan(abs(p_uv - 0.5), vec2(0.4999)))); // Trapezoid rule.
	return edge.x * edge.y;
}

#ifdef USE_AREA_SHAPES
// Sample point of map p_packed of a sphere or tube light (AREA_SHADOW_FLAG_ALL_AROUND): on the capsule of half
// length p_shape.x along light X and radius p_shape.y (a sphere: half length 0), at the equal-area position
// of its uv: azimuth phi = 2 pi u + pi / 4 about X (phi = 0 would be -Z; the quarter turn gives a receiver on
// the light's axis two points of each 4-point ring instead of one), axial coordinate h = (2 v - 1)(half length
// + radius).
// Archimedes' hat-box theorem: a sphere zone of height dh has the area 2 pi r dh of the cylinder beside it, so
// the whole capsule has 2 pi r of area per unit of h and this map of [0,1]^2 is equal-area: the grid's
// trapezoid rule over uv stays a quadrature of the surface. Each map covers the half space in front of its
// own surface point (frame: X the azimuth tangent, Z the inward normal; emission along -Z, as the
// rectangle's), where that point emits: the octant views and every lookup work in that frame unchanged.
// The point itself sits on the chord of its cell's arc, rho (1 - cos(pi / den)) in from the surface, so that
// its cell (below) projects as the arc does (a 90-degree arc bulges 0.29 rho out of its tangent square).
// Column u = 1 repeats u = 0 and the rows v = 0, 1 are the two poles: those maps are skipped (false; the C++
// side never draws them) and their weight goes to the one kept (u = 0), so r_weight is the point's share of
// the surface (interior 1, a pole den / 2, of den^2). r_lo, r_hi: its cell (u +- 1/(2 den), v +- 1/(2 den)) laid
// into the plane of that chord: its length 2 rho sin(pi / den) across the azimuth (X), the meridian arc r dh / rho of
// its axial step dh (Y; dh on the cylinder); a pole's cell is its cap, a square of the cap's projected area.
// One map (den 0): the light's centre facing -Z stands for the whole light (front half space only).
// In: p_pos, p_normal in light space. Out: r_v = receiver - sample point, r_normal, in the map's frame.
bool area_shadow_surface_map(uint p_packed, vec2 p_shape, vec3 p_pos, vec3 p_normal, out vec3 r_v, out vec3 r_normal, out float r_weight, out vec2 r_lo, out vec2 r_hi) {
	uint den = (p_packed >> 20u) & 0xFu;
	uint un = (p_packed >> 12u) & 0xFu;
	uint vn = (p_packed >> 16u) & 0xFu;
	float half_len = p_shape.x;
	float radius = p_shape.y;
	if (den == 0u) {
		r_v = p_pos;
		r_normal = p_normal;
		r_weight = 1.0;
		r_hi = vec2(half_len + 0.8862269 * radius, 0.8862269 * radius);
		r_lo = -r_hi;
		return true;
	}
	bool pole = vn == 0u || vn == den;
	if (un == den || (pole && un != 0u)) {
		return false;
	}
	float fden = float(den);
	float span = half_len + radius;
	float phi = 6.2831853 * float(un) / fden + 0.78539816;
	float h = (2.0 * float(vn) / fden - 1.0) * span;
	float c = clamp(h, -half_len, half_len); // Axis point under the sample (an end sphere's centre on the caps).
	float dz = h - c;
	float rho = sqrt(max(radius * radius - dz * dz, 0.0));
	vec3 n = (vec3(dz, 0.0, 0.0) + vec3(0.0, sin(phi), -cos(phi)) * rho) / max(radius, 1e-6);
	vec3 x_axis = vec3(0.0, cos(phi), sin(phi));
	mat3 frame = mat3(x_axis, cross(-n, x_axis), -n); // Columns: the map's X, Y, Z in light space.
	vec3 chord = pole ? vec3(0.0) : vec3(0.0, sin(phi), -cos(phi)) * (rho * (1.0 - cos(3.14159265 / fden)));
	r_v = (p_pos - (vec3(c, 0.0, 0.0) + n * radius - chord)) * frame;
	r_normal = p_normal * frame;
	r_weight = pole ? 0.5 * fden : 1.0;
	float dh = 2.0 * span / fden; // Axial step of the grid.
	if (pole) {
		float depth = min(0.5 * dh, radius); // The cap's height.
		r_hi = vec2(0.8862269 * sqrt(max(depth * (2.0 * radius - depth), 0.0)));
	} else {
		r_hi = vec2(rho * sin(3.14159265 / fden), 0.5 * dh * radius / max(rho, 1e-6));
	}
	r_lo = -r_hi;
	return true;
}
#endif

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
	float grid_weight = area_shadow_map_weight(p_packed, uv);
#ifdef USE_AREA_SHAPES
	if ((area_shadows.data[p_light].mode & AREA_SHADOW_FLAG_ALL_AROUND) != 0u) {
		vec3 normal;
		vec2 lo, hi;
		if (!area_shadow_surface_map(p_packed, area_shadows.data[p_light].half_size, p_pos, p_normal, v, normal, grid_weight, lo, hi)) {
			r_weight = 0.0; // A repeated point (seam or pole) of the surface grid.
			return 1.0;
		}
		p_normal = normal;
	}
#endif
	float dist = length(v);
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

// Per-sample penumbra filter (ours; thesis 6.1's PCF sized by the sub-light each map stands for).
// Sample point s of an n x n grid stands for its cell of the light, [u - c/2, u + c/2] x [v - c/2, v + c/2]
// clipped to [0,1]^2 with c = 1/(n - 1): the cells tile the rectangle and their areas are the trapezoid
// weights. An ADAPTIVE tree point stands for the quarters of its leaves (area_shadow_tree_cell(); the box
// around them, exact where the leaves around the point have one size). One map (den 0) stands for the whole
// light.
// r_lo, r_hi: the cell's corners as offsets from s in light space (metres).
void area_shadow_cell(uint p_packed, vec2 p_uv, vec2 p_half_size, out vec2 r_lo, out vec2 r_hi) {
	vec2 lo = vec2(0.0);
	vec2 hi = vec2(1.0);
#ifdef AREA_SHADOWS_TREE
	if ((p_packed & AREA_SHADOW_TREE_MAP) != 0u) {
		float w;
		area_shadow_tree_cell(p_packed, w, lo, hi);
		lo += p_uv;
		hi += p_uv;
	} else
#endif
	{
		float den = float((p_packed >> 20u) & 0xFu);
		if (den > 0.0) {
			float c = 1.0 / den;
			lo = max(p_uv - 0.5 * c, vec2(0.0));
			hi = min(p_uv + 0.5 * c, vec2(1.0));
		}
	}
	r_lo = (lo - p_uv) * 2.0 * p_half_size;
	r_hi = (hi - p_uv) * 2.0 * p_half_size;
}

// The receiver point p + p_offset (p = sample point + p_v, the offset parallel to the light), slid along the
// ray from the sample point onto the receiver's tangent plane (normal p_normal through p). Returned relative
// to the sample point.
vec3 area_shadow_on_receiver(vec3 p_v, vec3 p_normal, vec2 p_offset) {
	vec3 dir = p_v + vec3(p_offset, 0.0);
	float den = dot(p_normal, dir);
	float num = dot(p_normal, p_v);
	if (den > -1e-4 * length(dir) || num >= 0.0) {
		return dir; // Grazing or behind: keep the point parallel to the light.
	}
	return dir * (num / den);
}

// Atlas coordinate (pixels) of light-space direction p_v in map p_packed, clamped inside its quadrant.
vec2 area_shadow_atlas_pixel(uint p_light, uint p_packed, vec3 p_v) {
	uint quadrant;
	vec2 quv;
	area_shadow_octant_project(p_v, quadrant, quv);
	uint qsize = area_shadows.data[p_light].quadrant_size;
	vec2 origin = vec2(area_shadow_quadrant_origin(p_packed, quadrant, area_shadows.data[p_light].atlas_subdivision, qsize, area_shadows.data[p_light].tile_size));
	return clamp(origin + quv * float(qsize), origin + 0.5, origin + float(qsize) - 0.5);
}

// Blocker search of one map for the filtered lookup: p_taps^2 gathers (4 texels each) at p + p_k_search * delta
// for delta on the cell's n-rooks pattern (as area_shadow_filtered(), shifted by p_shift). Widens
// r_ratio_range to every blocker's distance ratio d_blocker / d_receiver and counts the blockers.
void area_shadow_blocker_search(uint p_light, uint p_packed, vec3 p_v, vec3 p_normal, vec2 p_lo, vec2 p_hi, vec2 p_shift, int p_taps, float p_k_search, float p_margin_texels, float p_texel_per_m, inout vec2 r_ratio_range, inout float r_blockers) {
	float inv_scale = 1.0 / area_shadows.data[p_light].depth_scale;
	float atlas_texel = area_shadows.data[p_light].atlas_texel;
	float inv_count = 1.0 / float(p_taps * p_taps);
	for (int a = 0; a < p_taps; a++) {
		for (int b = 0; b < p_taps; b++) {
			vec2 f = (vec2(float(a * p_taps + b), float(b * p_taps + a)) + p_shift) * inv_count;
			vec3 x = area_shadow_on_receiver(p_v, p_normal, mix(p_lo, p_hi, f) * p_k_search);
			if (x.z >= 0.0) {
				continue;
			}
			float d_r = length(x);
			// Surfaces within 3 % of the receiver are not counted (their penumbra is under a few texels, and the
			// receiver itself, seen at a grazing angle, must not drag the range to hard shadows); the filter's
			// last step still compares with the receiver, so contact shadows stay.
			float limit = min(d_r - p_margin_texels * d_r * p_texel_per_m, 0.97 * d_r);
			vec4 g = textureGather(sampler2D(area_shadow_atlas, area_shadow_sampler), area_shadow_atlas_pixel(p_light, p_packed, x) * atlas_texel, 0) * inv_scale;
			vec4 r = g / d_r;
			bvec4 blocked = lessThan(g, vec4(limit));
			vec4 lo = mix(vec4(1e6), r, vec4(blocked));
			vec4 hi = mix(vec4(-1e6), r, vec4(blocked));
			r_ratio_range.x = min(r_ratio_range.x, min(min(lo.x, lo.y), min(lo.z, lo.w)));
			r_ratio_range.y = max(r_ratio_range.y, max(max(hi.x, hi.y), max(hi.z, hi.w)));
			r_blockers += dot(vec4(blocked), vec4(1.0));
		}
	}
}

// Filtered lookup of one map: the mean over p_taps^2 offsets delta of the cell (an n-rooks pattern, p_taps^2
// distinct positions on each axis, shifted by p_shift: different for maps sharing a row or column, so an
// n x n grid's edges get n^2 p_taps^2 steps instead of n) of whether the ray from the receiver p to the
// cell point s + delta is blocked. That ray meets depth fraction r = d_blocker / d_receiver where the ray
// from s towards p + k delta does, k = 1/r - 1 (similar triangles), r d_receiver away from s; it is taken
// as blocked where the map sees a surface nearer than that point (bilinear compare), tested at
// AREA_SHADOW_MARCH_STEPS fractions spanning the blockers' range p_ratio (a short march along the ray in
// the map: a box's top edge and its base cast penumbrae of different widths). Each tap point is slid onto
// the receiver's tangent plane (exact depths on planar receivers: no acne from the width of the kernel).
// p_near (x: the nearest blocker's ratio, y: the end of the near layer; x = 0: no near layer): a first step at
// ratio p_near.x, k = 1 / p_near.x - 1 (the ray point is then beside the light point s + delta, where a bar
// in front of the light is), blocked by surfaces up to p_near.y; the march then ignores those surfaces. The
// near step uses the whole cell (the march's offsets are p_facing times it) and the direction to p + k delta
// itself, not slid onto the receiver: the test is exact for any receiver orientation.
// The near layer's code is compiled only with AREA_SHADOWS_NEAR_LAYER (some light of the view has a caster
// close enough to it, AreaShadowRendererRD::FLAG_NEAR_LAYER): a SIMD rasterizer (llvmpipe) runs untaken
// branches too, and the untaken step cost every shadowed frame 7-10 % (doc/shadows.md "The default").
float area_shadow_filtered(uint p_light, uint p_packed, vec3 p_v, vec3 p_normal, vec2 p_lo, vec2 p_hi, float p_facing, vec2 p_shift, vec2 p_ratio, vec2 p_near, float p_min_k, int p_taps, float p_bias_texels, float p_texel_per_m) {
	float scale = area_shadows.data[p_light].depth_scale;
	float atlas_texel = area_shadows.data[p_light].atlas_texel;
	float inv_count = 1.0 / float(p_taps * p_taps);
	float lit = 0.0;
	for (int a = 0; a < p_taps; a++) {
		for (int b = 0; b < p_taps; b++) {
			vec2 f = (vec2(float(a * p_taps + b), float(b * p_taps + a)) + p_shift) * inv_count;
			vec2 cell_delta = mix(p_lo, p_hi, f);
			vec2 delta = cell_delta * p_facing;
			float tap = 1.0;
#ifdef AREA_SHADOWS_NEAR_LAYER
			if (p_near.x > 0.0) {
				vec3 x = p_v + vec3(cell_delta * (1.0 / p_near.x - 1.0), 0.0);
				if (x.z < 0.0) {
					tap = textureLod(sampler2DShadow(area_shadow_atlas, area_shadow_compare_sampler), vec3(area_shadow_atlas_pixel(p_light, p_packed, x) * atlas_texel, length(x) * p_near.y * scale), 0.0);
				}
			}
#endif
			for (int m = 0; m < AREA_SHADOW_MARCH_STEPS; m++) {
				// Step m covers ratios up to its end (a surface anywhere before it blocks).
				float t0 = float(m) / float(AREA_SHADOW_MARCH_STEPS);
				float t1 = float(m + 1) / float(AREA_SHADOW_MARCH_STEPS);
				float r_mid = mix(p_ratio.x, p_ratio.y, 0.5 * (t0 + t1));
				float r_end = m + 1 == AREA_SHADOW_MARCH_STEPS ? 1.0 : mix(p_ratio.x, p_ratio.y, t1);
				float k = max(1.0 / max(r_mid, 1.0 / (1.0 + AREA_SHADOW_MAX_K)) - 1.0, p_min_k);
				vec3 x = area_shadow_on_receiver(p_v, p_normal, delta * k);
				if (x.z >= 0.0) {
					continue;
				}
				float d = length(x);
				float receiver = (d * r_end - d * p_texel_per_m * p_bias_texels) * scale;
				vec2 pixel = area_shadow_atlas_pixel(p_light, p_packed, x) * atlas_texel;
				float step_lit = textureLod(sampler2DShadow(area_shadow_atlas, area_shadow_compare_sampler), vec3(pixel, receiver), 0.0);
#ifdef AREA_SHADOWS_NEAR_LAYER
				if (p_near.x > 0.0) { // Texels of the near layer do not block here (the near step judged them).
					step_lit = min(step_lit + 1.0 - textureLod(sampler2DShadow(area_shadow_atlas, area_shadow_compare_sampler), vec3(pixel, d * p_near.y * scale), 0.0), 1.0);
				}
#endif
				tap = min(tap, step_lit);
			}
			lit += tap;
		}
	}
	return lit * inv_count;
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

// Visibility through the per-sample penumbra filter: (1) a blocker search pooled over the light's maps gives
// one blocker distance ratio (the occluders are the same for every sub-light); no blocker: lit. (2) Each map
// is filtered over the penumbra its own cell casts, k = d_receiver / d_blocker - 1, at least
// pcf_radius texels (shadow_blur), and weighted as in area_shadow_pcf (cell area x form factor).
float area_shadow_sample_filtered(uint p_light, uint p_count, vec3 p_pos, vec3 p_normal) {
	vec2 half_size = area_shadows.data[p_light].half_size;
	float texel_per_m = 2.0 * AREA_SHADOW_OCTANT_HALF_X / float(area_shadows.data[p_light].quadrant_size);
	float normal_bias = area_shadows.data[p_light].normal_bias;
	float bias_texels = area_shadows.data[p_light].bias * 10.0;
	// Pattern shift of a map: golden-ratio steps of its other coordinate, so the maps of one row (or
	// column), which throw the same edge positions across it, sample between each other's points.
	// Taps per axis of each map's patterns (search and filter): the light's maps x taps stay about constant.
	int taps = p_count <= 4u ? 6 : (p_count <= 9u ? 4 : (p_count <= 25u ? 3 : 1));
	// The search runs on every lit pixel in range (the filter only where it finds blockers): sparser.
	int search_taps = p_count <= 4u ? 4 : (p_count <= 9u ? 2 : 1);
#ifdef USE_AREA_SHAPES
	// Sphere or tube: each map's offset, normal and cell in its own frame (area_shadow_surface_map()).
	bool all_around = (area_shadows.data[p_light].mode & AREA_SHADOW_FLAG_ALL_AROUND) != 0u;
#endif
	vec2 ratio = vec2(1e6, -1e6);
	float blockers = 0.0;
	for (uint i = 0u; i < p_count; i++) {
		uint packed = area_shadows.data[p_light].maps[i];
		vec2 uv = area_shadow_map_uv(packed);
		vec3 v = p_pos - vec3((uv - 0.5) * 2.0 * half_size, 0.0);
		vec3 normal = p_normal;
		vec2 lo, hi;
#ifdef USE_AREA_SHAPES
		float surface_weight;
		if (all_around && !area_shadow_surface_map(packed, half_size, p_pos, p_normal, v, normal, surface_weight, lo, hi)) {
			continue;
		}
#endif
		v += normal * (normal_bias * length(v) * texel_per_m);
		if (v.z >= 0.0) {
			continue;
		}
#ifdef USE_AREA_SHAPES
		if (!all_around)
#endif
		{
			area_shadow_cell(packed, uv, half_size, lo, hi);
		}
		float cos_theta = clamp(dot(normal, -v) / max(length(v), 1e-6), 0.05, 1.0);
		float slope = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, 8.0);
		vec2 shift = fract(uv.yx * 0.61803399);
		area_shadow_blocker_search(p_light, packed, v, normal, lo, hi, shift, search_taps, AREA_SHADOW_SEARCH_K, bias_texels + 2.0 * slope, texel_per_m, ratio, blockers);
	}
	if (blockers == 0.0) {
		return 1.0;
	}
	// A blocker in the near layer (ratio under 1 / (1 + AREA_SHADOW_MAX_K)): its own step; the layer reaches
	// AREA_SHADOW_NEAR_DEPTH times its distance (a bar's thickness), at most to the march's first ratio.
	float near_cut = 1.0 / (1.0 + AREA_SHADOW_MAX_K);
	vec2 near = vec2(0.0);
#ifdef AREA_SHADOWS_NEAR_LAYER
	if (ratio.x < near_cut) {
		near.x = max(ratio.x, 1.0 / (1.0 + AREA_SHADOW_NEAR_MAX_K));
		near.y = min(near.x * AREA_SHADOW_NEAR_DEPTH, near_cut);
	}
#endif
	ratio = clamp(ratio, vec2(near_cut), vec2(1.0));
	float min_blur = area_shadows.data[p_light].pcf_radius;
	float visibility = 0.0;
	float total = 0.0;
	for (uint i = 0u; i < p_count; i++) {
		uint packed = area_shadows.data[p_light].maps[i];
		vec2 uv = area_shadow_map_uv(packed);
		vec3 v = p_pos - vec3((uv - 0.5) * 2.0 * half_size, 0.0);
		vec3 normal = p_normal;
		float grid_weight = area_shadow_map_weight(packed, uv);
		vec2 lo, hi;
#ifdef USE_AREA_SHAPES
		if (all_around && !area_shadow_surface_map(packed, half_size, p_pos, p_normal, v, normal, grid_weight, lo, hi)) {
			continue;
		}
#endif
		float dist = length(v);
		float w = grid_weight * max(-v.z, 0.0) * max(dot(normal, -v), 0.0) / max(dist * dist * dist * dist, 1e-12);
		v += normal * (normal_bias * dist * texel_per_m);
		float lit = 1.0;
		if (v.z < 0.0) {
#ifdef USE_AREA_SHAPES
			if (!all_around)
#endif
			{
				area_shadow_cell(packed, uv, half_size, lo, hi);
			}
			float cos_theta = clamp(dot(normal, -v) / max(length(v), 1e-6), 0.05, 1.0);
			float slope = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, 8.0);
			// shadow_blur: the box is at least pcf_radius texels wide at the receiver.
			float extent = max(max(hi.x - lo.x, hi.y - lo.y), 1e-4);
			float min_k = min_blur * dist * texel_per_m / extent;
			// Receivers steep to the light (a box's sides): their tangent plane is a poor stand-in beyond a
			// few texels (taps slide under the floor or into the box), so the kernel fades to shadow_blur's.
			float facing = clamp(normal.z * 2.0 - 0.4, 0.0, 1.0);
			vec2 shift = fract(vec2(0.5, 0.5) + uv.yx * 0.61803399);
			lit = area_shadow_filtered(p_light, packed, v, normal, lo, hi, facing, shift, ratio, near, min_k / max(facing, 1e-3), taps, bias_texels + slope, texel_per_m);
		}
		visibility += lit * w;
		total += w;
	}
	return total > 0.0 ? visibility / total : 1.0;
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
	uint mode = area_shadows.data[p_light_index].mode;
	if ((mode & AREA_SHADOW_MODE_MASK) == AREA_SHADOW_MODE_PCSS) {
		return area_shadow_pcss(p_light_index, area_shadows.data[p_light_index].maps[0], pos, normal);
	}
#endif
#ifdef AREA_SHADOWS_PCF
#ifndef AREA_SHADOWS_PCSS
	uint mode = area_shadows.data[p_light_index].mode;
#endif
	if ((mode & AREA_SHADOW_FLAG_SAMPLE_FILTER) != 0u) {
		return area_shadow_sample_filtered(p_light_index, count, pos, normal);
	}
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
