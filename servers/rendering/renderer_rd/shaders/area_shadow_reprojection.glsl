/**************************************************************************/
/*  area_shadow_reprojection.glsl                                         */
/**************************************************************************/
/* Reprojection pass of adaptive area shadows (thesis 6.3, Schwarzler et  */
/* al.): for each ADAPTIVE light under test (z = light index) and each    */
/* cell of its grid (GridData: the screen rectangle of the light's range  */
/* box at a per-light step; x = cell index) over the camera depth, the    */
/* one-tap shadow-map visibility of the receiver from every sample point  */
/* that is a corner of one of the light's tested quads, as bits: word 0   */
/* bit 0 = the cell has a receiver lit by this light (not sky, in front   */
/* of the light), bit p + 1 = point p sees it. Neighbouring quads share   */
/* their corner points, so each point's map is read once per cell and     */
/* the receiver (depth, normal) is rebuilt once per light, where the      */
/* thesis rendered every quad's four corners again. The banding detector  */
/* (area_shadow_banding.glsl) forms each quad's value, the plain mean of  */
/* its four corners' bits (0, 1/4, ..., 1). Compiled only when a light    */
/* uses ADAPTIVE (AreaShadowAdaptiveRD creates it on demand).             */
/* C++ mirrors: AreaShadowAdaptiveRD::AdaptiveLightData / PointData /     */
/* ReprojectionPushConstant (renderer_rd/effects/area_shadow_adaptive.h). */

#[compute]

#version 450

#include "area_shadow_octant_inc.glsl"
#include "area_shadow_adaptive_inc.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform texture2D camera_depth;
layout(set = 0, binding = 1) uniform sampler nearest_sampler;
layout(set = 0, binding = 2) uniform texture2D shadow_atlas;

layout(set = 0, binding = 3, std430) restrict readonly buffer Lights {
	AdaptiveLightData data[];
}
lights;

layout(set = 0, binding = 4, std430) restrict writeonly buffer Visibility {
	uint data[];
}
visibility;

layout(set = 0, binding = 5, std430) restrict readonly buffer Points {
	PointData data[];
}
points;

layout(push_constant, std430) uniform Params { // 96 bytes.
	mat4 view_from_clip; // Inverse of the (Vulkan depth-corrected) camera projection.
	uvec2 depth_size; // Camera depth buffer.
	uint max_cells; // Largest grid (dispatch x).
	uint light_count;
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

bool point_sees(const AdaptiveLightData p_l, vec2 p_uv, uint p_tile, vec3 p_pos, vec3 p_normal) {
	vec3 sample_pos = vec3((p_uv - 0.5) * 2.0 * p_l.half_size, 0.0);
	vec3 v = p_pos - sample_pos;
	if (v.z >= 0.0) {
		return true; // Not in front of this sample.
	}
	float dist = length(v);
	float texel_world = dist * (2.0 * AREA_SHADOW_OCTANT_HALF_X) / float(p_l.quadrant_size);
	v += p_normal * texel_world; // One texel of normal offset.
	uint quadrant;
	vec2 quv;
	area_shadow_octant_project(v, quadrant, quv);
	int qsize = int(p_l.quadrant_size);
	uvec2 t = uvec2(p_tile % p_l.atlas_subdivision, p_tile / p_l.atlas_subdivision) * p_l.tile_size;
	ivec2 origin = ivec2(t + uvec2(quadrant & 1u, quadrant >> 1u) * p_l.quadrant_size);
	ivec2 texel = clamp(ivec2(floor(quv * float(qsize))), ivec2(0), ivec2(qsize - 1));
	float cos_theta = clamp(dot(p_normal, -v) / max(length(v), 1e-6), 0.05, 1.0);
	float slope = min(sqrt(1.0 - cos_theta * cos_theta) / cos_theta, 8.0);
	float receiver = (length(v) - texel_world * (p_l.bias * 10.0 + slope)) * p_l.depth_scale;
	return texelFetch(sampler2D(shadow_atlas, nearest_sampler), origin + texel, 0).r >= receiver;
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
	uint base = g.offset + id.x * l.words;
	uvec2 cell = uvec2(id.x % g.size.x, id.x / g.size.x);
	ivec2 pixel = ivec2(g.origin + min(cell * g.step + g.step / 2u, g.extent - 1u));
	pixel = min(pixel, ivec2(params.depth_size) - 1);
	float depth = texelFetch(sampler2D(camera_depth, nearest_sampler), pixel, 0).r;
	vec3 pos = vec3(0.0);
	vec3 normal = vec3(0.0, 0.0, 1.0);
	bool receiver = depth < 1.0; // Sky: no receiver.
	if (receiver) {
		vec3 pos_view = view_position(pixel);
		// Normal from the depth buffer (neighbouring pixels), facing the camera.
		vec3 dx = view_position(pixel + ivec2(1, 0)) - pos_view;
		vec3 dy = view_position(pixel + ivec2(0, 1)) - pos_view;
		vec3 n_view = cross(dx, dy);
		n_view = length(n_view) > 1e-12 ? normalize(n_view) : vec3(0.0, 0.0, 1.0);
		if (dot(n_view, pos_view) > 0.0) {
			n_view = -n_view;
		}
		pos = (l.light_from_view * vec4(pos_view, 1.0)).xyz;
		normal = normalize(mat3(l.light_from_view) * n_view);
		receiver = pos.z < 0.0; // Behind the light: not lit by it.
	}
	if (!receiver) {
		for (uint w = 0u; w < l.words; w++) {
			visibility.data[base + w] = 0u;
		}
		return;
	}
	uint word = 1u; // Bit 0: receiver.
	uint w = 0u;
	for (uint p = 0u; p < l.point_count; p++) {
		uint bit = p + 1u;
		if ((bit >> 5u) != w) {
			visibility.data[base + w] = word;
			w = bit >> 5u;
			word = 0u;
		}
		PointData pt = points.data[l.point_offset + p];
		if (point_sees(l, pt.uv, pt.tile, pos, normal)) {
			word |= 1u << (bit & 31u);
		}
	}
	visibility.data[base + w] = word;
	for (w++; w < l.words; w++) {
		visibility.data[base + w] = 0u;
	}
}
