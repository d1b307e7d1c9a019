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
/* quadtree's same-depth rule); threads exit early once both are set.     */
/* x = cell index of the quad's light grid, z = query. C++:               */
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
	LightData data[];
}
lights;

layout(set = 0, binding = 3, std430) restrict readonly buffer Queries {
	QueryData data[];
}
queries;

layout(push_constant, std430) uniform Params { // 16 bytes.
	uint max_cells; // Largest grid (dispatch x).
	uint query_count;
	uint pad0;
	uint pad1;
}
params;

bool bit_at(uint p_base, uint p_bit) {
	return ((visibility.data[p_base + (p_bit >> 5u)] >> (p_bit & 31u)) & 1u) != 0u;
}

// The quad's value at a cell: the mean of its corners' bits, -1 without a receiver.
float value_at(GridData p_grid, uint p_words, uvec4 p_corners, ivec2 p_cell) {
	uint base = p_grid.offset + (uint(p_cell.y) * p_grid.size.x + uint(p_cell.x)) * p_words;
	if ((visibility.data[base] & 1u) == 0u) {
		return -1.0;
	}
	uint n = 0u;
	for (uint c = 0u; c < 4u; c++) {
		n += bit_at(base, p_corners[c] + 1u) ? 1u : 0u;
	}
	return float(n) * 0.25;
}

void main() {
	uvec3 id = gl_GlobalInvocationID;
	if (id.z >= params.query_count) {
		return;
	}
	QueryData q = queries.data[id.z];
	LightData l = lights.data[q.light];
	GridData g = l.grid;
	if (id.x >= g.size.x * g.size.y) {
		return;
	}
	uvec2 cell = uvec2(id.x % g.size.x, id.x / g.size.x);
	if (flags.data[id.z] == 3u) {
		return; // Early exit: this quad already bands and has a penumbra.
	}
	ivec2 p = ivec2(cell);
	float v = value_at(g, l.words, q.corners, p);
	if (!(v > 0.0 && v < 1.0)) {
		return; // Lit, umbra or no receiver.
	}
	if ((flags.data[id.z] & 2u) == 0u) {
		atomicOr(flags.data[id.z], 2u); // The quad's penumbra is on screen.
	}
	if (cell.x < 1u || cell.y < 1u || cell.x + 1u >= g.size.x || cell.y + 1u >= g.size.y) {
		return; // Border cells have no full neighbourhood.
	}
	if ((flags.data[id.z] & 1u) != 0u) {
		return;
	}
	for (int y = -1; y <= 1; y++) {
		for (int x = -1; x <= 1; x++) {
			if (value_at(g, l.words, q.corners, p + ivec2(x, y)) != v) {
				return;
			}
		}
	}
	atomicOr(flags.data[id.z], 1u);
}
