/**************************************************************************/
/*  area_shadow_banding.glsl                                              */
/**************************************************************************/
/* Banding detector of adaptive area shadows (thesis 6.3): a tested quad  */
/* bands when some penumbra pixel of its reprojection image (0 < v < 1)   */
/* is surrounded by eight pixels of exactly the same value, i.e. its      */
/* four samples leave visible steps wider than a pixel. One flag word per */
/* query: bit 0 banding, bit 1 some cell is in the quad's penumbra (the   */
/* quadtree's same-depth rule); threads exit early once both are set.     */
/* Each query has its own grid (GridData, x = cell index).                */
/* Input: area_shadow_reprojection.glsl's values. C++: AreaShadowAdaptiveRD*/
/* (servers/rendering/renderer_rd/area_shadow_adaptive.h).                */

#[compute]

#version 450

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(set = 0, binding = 0, std430) restrict readonly buffer Values {
	float data[];
}
values;

layout(set = 0, binding = 1, std430) restrict coherent buffer Flags {
	uint data[];
}
flags;

struct GridData { // std430, 32 bytes: as in area_shadow_reprojection.glsl.
	uvec2 origin;
	uvec2 size; // Cells.
	uint step;
	uint offset; // First value of the query.
	uvec2 extent;
};

layout(set = 0, binding = 2, std430) restrict readonly buffer Grids {
	GridData data[];
}
grids;

layout(push_constant, std430) uniform Params { // 16 bytes.
	uint max_cells; // Largest grid (dispatch x).
	uint query_count;
	uint pad0;
	uint pad1;
}
params;

float value_at(GridData p_grid, ivec2 p_cell) {
	return values.data[p_grid.offset + uint(p_cell.y) * p_grid.size.x + uint(p_cell.x)];
}

void main() {
	uvec3 id = gl_GlobalInvocationID;
	if (id.z >= params.query_count) {
		return;
	}
	GridData g = grids.data[id.z];
	if (id.x >= g.size.x * g.size.y) {
		return;
	}
	uvec2 cell = uvec2(id.x % g.size.x, id.x / g.size.x);
	if (flags.data[id.z] == 3u) {
		return; // Early exit: this quad already bands and has a penumbra.
	}
	ivec2 p = ivec2(cell);
	float v = value_at(g, p);
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
			if (value_at(g, p + ivec2(x, y)) != v) {
				return;
			}
		}
	}
	atomicOr(flags.data[id.z], 1u);
}
