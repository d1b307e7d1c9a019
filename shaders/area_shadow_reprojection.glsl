/**************************************************************************/
/*  area_shadow_reprojection.glsl                                         */
/**************************************************************************/
/* Reprojection pass of adaptive area shadows (thesis 6.3, Schwarzler et  */
/* al.): for each tested quad of an area light (z = query index) and each */
/* cell of its light's grid (GridData: the screen rectangle of the light's*/
/* range box at a per-light step; x = cell index) over the camera depth,  */
/* visibility of the receiver from the quad's four corner samples: the    */
/* plain mean of four one-tap shadow-map tests (0, 1/4, ..., 1), written  */
/* to values[grid.offset + cell]; -1 where there is no                    */
/* receiver (far plane) or it is behind the light. The banding detector   */
/* (area_shadow_banding.glsl) reads it. Compiled only when a light uses   */
/* ADAPTIVE (AreaShadowAdaptiveRD creates it on demand).                  */
/* C++ mirrors: AreaShadowAdaptiveRD::QueryData / ReprojectionPushConstant*/
/* (servers/rendering/renderer_rd/area_shadow_adaptive.h).                */

#[compute]

#version 450

#include "area_shadow_octant_inc.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct QueryData { // std430, 144 bytes.
	mat4 light_from_view; // View space -> light space (emission along -Z).
	vec2 half_size; // Rectangle half extents (m).
	float depth_scale; // Stored depth = distance * depth_scale.
	float bias; // Constant bias in receiver texels (shadow_bias).
	vec4 corner_uv[2]; // (u0, v0, u1, v1) of the four corners: xy, zw of [0] and [1].
	uvec4 corner_tile; // Atlas tile of each corner's map.
	uint atlas_subdivision;
	uint quadrant_size;
	uint tile_size;
	uint pad;
};

layout(set = 0, binding = 0) uniform texture2D camera_depth;
layout(set = 0, binding = 1) uniform sampler nearest_sampler;
layout(set = 0, binding = 2) uniform texture2D shadow_atlas;

layout(set = 0, binding = 3, std430) restrict readonly buffer Queries {
	QueryData data[];
}
queries;

layout(set = 0, binding = 4, std430) restrict writeonly buffer Values {
	float data[];
}
values;

struct GridData { // std430, 32 bytes: one query's cells over the depth buffer.
	uvec2 origin; // Depth pixels.
	uvec2 size; // Cells.
	uint step; // Depth pixels per cell.
	uint offset; // First value of the query.
	uvec2 extent; // Depth pixels covered.
};

layout(set = 0, binding = 5, std430) restrict readonly buffer Grids {
	GridData data[];
}
grids;

layout(push_constant, std430) uniform Params { // 96 bytes.
	mat4 view_from_clip; // Inverse of the (Vulkan depth-corrected) camera projection.
	uvec2 depth_size; // Camera depth buffer.
	uint max_cells; // Largest grid (dispatch x).
	uint query_count;
	uint pad0;
	uint pad1;
	uint pad2;
	uint pad3;
}
params;

vec3 view_position(ivec2 p_pixel) {
	ivec2 px = clamp(p_pixel, ivec2(0), ivec2(params.depth_size) - 1);
	float depth = texelFetch(sampler2D(camera_depth, nearest_sampler), px, 0).r;
	vec2 ndc = (vec2(px) + 0.5) / vec2(params.depth_size) * 2.0 - 1.0;
	vec4 v = params.view_from_clip * vec4(ndc, depth, 1.0);
	return v.xyz / v.w;
}

float corner_visibility(const QueryData p_q, vec2 p_uv, uint p_tile, vec3 p_pos, vec3 p_normal) {
	vec3 sample_pos = vec3((p_uv - 0.5) * 2.0 * p_q.half_size, 0.0);
	vec3 v = p_pos - sample_pos;
	if (v.z >= 0.0) {
		return 1.0; // Not in front of this sample.
	}
	float dist = length(v);
	float texel_world = dist * (2.0 * AREA_SHADOW_OCTANT_HALF_X) / float(p_q.quadrant_size);
	v += p_normal * texel_world; // One texel of normal offset.
	uint quadrant;
	vec2 quv;
	area_shadow_octant_project(v, quadrant, quv);
	int qsize = int(p_q.quadrant_size);
	uvec2 t = uvec2(p_tile % p_q.atlas_subdivision, p_tile / p_q.atlas_subdivision) * p_q.tile_size;
	ivec2 origin = ivec2(t + uvec2(quadrant & 1u, quadrant >> 1u) * p_q.quadrant_size);
	ivec2 texel = clamp(ivec2(floor(quv * float(qsize))), ivec2(0), ivec2(qsize - 1));
	float cos_theta = clamp(dot(p_normal, -v) / max(length(v), 1e-6), 0.05, 1.0);
	float slope = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, 8.0);
	float receiver = (length(v) - texel_world * (p_q.bias * 10.0 + slope)) * p_q.depth_scale;
	return texelFetch(sampler2D(shadow_atlas, nearest_sampler), origin + texel, 0).r >= receiver ? 1.0 : 0.0;
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
	uint index = g.offset + id.x;
	uvec2 cell = uvec2(id.x % g.size.x, id.x / g.size.x);
	ivec2 pixel = ivec2(g.origin + min(cell * g.step + g.step / 2u, g.extent - 1u));
	pixel = min(pixel, ivec2(params.depth_size) - 1);
	float depth = texelFetch(sampler2D(camera_depth, nearest_sampler), pixel, 0).r;
	if (depth >= 1.0) {
		values.data[index] = -1.0; // Sky: no receiver.
		return;
	}
	QueryData q = queries.data[id.z];
	vec3 pos_view = view_position(pixel);
	// Normal from the depth buffer (neighbouring pixels), facing the camera.
	vec3 dx = view_position(pixel + ivec2(1, 0)) - pos_view;
	vec3 dy = view_position(pixel + ivec2(0, 1)) - pos_view;
	vec3 n_view = cross(dx, dy);
	n_view = length(n_view) > 1e-12 ? normalize(n_view) : vec3(0.0, 0.0, 1.0);
	if (dot(n_view, pos_view) > 0.0) {
		n_view = -n_view;
	}
	vec3 pos = (q.light_from_view * vec4(pos_view, 1.0)).xyz;
	vec3 normal = normalize(mat3(q.light_from_view) * n_view);
	if (pos.z >= 0.0) {
		values.data[index] = -1.0; // Behind the light: not lit by it.
		return;
	}
	float vis = corner_visibility(q, q.corner_uv[0].xy, q.corner_tile.x, pos, normal);
	vis += corner_visibility(q, q.corner_uv[0].zw, q.corner_tile.y, pos, normal);
	vis += corner_visibility(q, q.corner_uv[1].xy, q.corner_tile.z, pos, normal);
	vis += corner_visibility(q, q.corner_uv[1].zw, q.corner_tile.w, pos, normal);
	values.data[index] = vis * 0.25;
}
