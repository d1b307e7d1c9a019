/**************************************************************************/
/*  area_shadow_banding.glsl                                              */
/**************************************************************************/
/* Banding detector of adaptive area shadows (thesis 6.3): a tested quad  */
/* bands when some penumbra pixel of its reprojection image (0 < v < 1)   */
/* is surrounded by eight pixels of exactly the same value, i.e. its      */
/* four samples leave visible steps wider than a pixel. One flag per      */
/* query (flags[query] = 1); threads exit early once the flag is set.     */
/* Input: area_shadow_reprojection.glsl's values. C++: AreaShadowAdaptiveRD*/
/* (servers/rendering/renderer_rd/area_shadow_adaptive.h).                */

#[compute]

#version 450

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0, std430) restrict readonly buffer Values {
	float data[];
}
values;

layout(set = 0, binding = 1, std430) restrict coherent buffer Flags {
	uint data[];
}
flags;

layout(push_constant, std430) uniform Params { // 16 bytes.
	uvec2 size; // Reprojection grid.
	uint query_count;
	uint pad;
}
params;

float value_at(uint p_query, ivec2 p_pixel) {
	return values.data[(p_query * params.size.y + uint(p_pixel.y)) * params.size.x + uint(p_pixel.x)];
}

void main() {
	uvec3 id = gl_GlobalInvocationID;
	if (id.z >= params.query_count || id.x < 1u || id.y < 1u || id.x + 1u >= params.size.x || id.y + 1u >= params.size.y) {
		return; // Border pixels have no full neighbourhood.
	}
	if (flags.data[id.z] != 0u) {
		return; // Early exit: this quad already bands.
	}
	ivec2 p = ivec2(id.xy);
	float v = value_at(id.z, p);
	if (!(v > 0.0 && v < 1.0)) {
		return; // Lit, umbra or no receiver.
	}
	for (int y = -1; y <= 1; y++) {
		for (int x = -1; x <= 1; x++) {
			if (value_at(id.z, p + ivec2(x, y)) != v) {
				return;
			}
		}
	}
	atomicOr(flags.data[id.z], 1u);
}
