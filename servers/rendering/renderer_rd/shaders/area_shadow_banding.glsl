/**************************************************************************/
/*  area_shadow_banding.glsl                                              */
/**************************************************************************/
/* Banding detector of adaptive area shadows (thesis 6.3): a tested quad  */
/* bands when some penumbra pixel of its reprojection image (0 < v < 1)   */
/* is surrounded by eight pixels of exactly the same value, i.e. its      */
/* four samples leave visible steps wider than a pixel. A quad's value at */
/* a cell is the plain mean of its four corners' visibility bits written  */
/* by area_shadow_reprojection.glsl (-1: no receiver). One flag word per  */
/* query: bit 0 banding, bit 1 some cell is in the quad's penumbra (the   */
/* quadtree's same-depth rule). One thread per light and cell (x = cell,  */
/* z = light) loads the 3 x 3 cells' bits once and tests every quad of    */
/* the light there. C++:                                                  */
/* AreaShadowAdaptiveRD (servers/rendering/renderer_rd/                   */
/* area_shadow_adaptive.h).                                               */

#[compute]

#version 450

#include "area_shadow_adaptive_inc.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(set = 0, binding = 0, std430) restrict readonly buffer Visibility {
	uint data[];
}
visibility;

layout(set = 0, binding = 1, std430) restrict coherent buffer Flags {
	uint data[];
}
flags;

layout(set = 0, binding = 2, std430) restrict readonly buffer Lights {
	AdaptiveLightData data[];
}
lights;

layout(set = 0, binding = 3, std430) restrict readonly buffer Queries {
	QueryData data[];
}
queries;

layout(push_constant, std430) uniform Params { // 16 bytes.
	uint max_cells; // Largest grid (dispatch x).
	uint light_count;
	uint pad0;
	uint pad1;
}
params;

// The visibility words of the 3 x 3 cells around this thread's cell (index (dy + 1) * 3 + dx + 1), loaded
// once and shared by all the light's quads.
uint nb[9][AREA_SHADOW_ADAPTIVE_MAX_WORDS];

bool bit_at(uint p_cell, uint p_bit) {
	return ((nb[p_cell][p_bit >> 5u] >> (p_bit & 31u)) & 1u) != 0u;
}

// A quad's value at one of the 3 x 3 cells: the mean of its corners' bits, -1 without a receiver.
float value_at(uint p_cell, uvec4 p_corners) {
	if ((nb[p_cell][0] & 1u) == 0u) {
		return -1.0;
	}
	uint n = 0u;
	for (uint c = 0u; c < 4u; c++) {
		n += bit_at(p_cell, p_corners[c] + 1u) ? 1u : 0u;
	}
	return float(n) * 0.25;
}

void main() {
	uvec3 id = gl_GlobalInvocationID;
	if (id.z >= params.light_count) {
		return;
	}
	AdaptiveLightData l = lights.data[id.z];
	GridData g = l.grid;
	if (id.x >= g.size.x * g.size.y) {
		return;
	}
	ivec2 cell = ivec2(id.x % g.size.x, id.x / g.size.x);
	uint base = g.offset + id.x * l.words;
	if ((visibility.data[base] & 1u) == 0u) {
		return; // No receiver here: no quad has a penumbra at this cell.
	}
	bool interior = cell.x >= 1 && cell.y >= 1 && cell.x + 1 < int(g.size.x) && cell.y + 1 < int(g.size.y);
	for (int k = 0; k < 9; k++) {
		ivec2 c = cell + ivec2(k % 3 - 1, k / 3 - 1);
		bool inside = c.x >= 0 && c.y >= 0 && c.x < int(g.size.x) && c.y < int(g.size.y);
		uint b = g.offset + (uint(c.y) * g.size.x + uint(c.x)) * l.words;
		for (uint w = 0u; w < uint(AREA_SHADOW_ADAPTIVE_MAX_WORDS); w++) {
			nb[k][w] = inside && w < l.words ? visibility.data[b + w] : 0u;
		}
	}
	for (uint i = 0u; i < l.query_count; i++) {
		uint q = l.query_offset + i;
		uvec4 corners = queries.data[q].corners;
		float v = value_at(4u, corners);
		if (!(v > 0.0 && v < 1.0)) {
			continue; // Lit or umbra for this quad.
		}
		uint f = flags.data[q];
		if ((f & 2u) == 0u) {
			atomicOr(flags.data[q], 2u); // The quad's penumbra is on screen.
		}
		if (!interior || (f & 1u) != 0u) {
			continue; // Border cells have no full neighbourhood; or it already bands.
		}
		bool plateau = true;
		for (uint k = 0u; k < 9u && plateau; k++) {
			plateau = value_at(k, corners) == v;
		}
		if (plateau) {
			atomicOr(flags.data[q], 1u);
		}
	}
}
