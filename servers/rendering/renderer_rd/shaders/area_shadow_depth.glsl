/**************************************************************************/
/*  area_shadow_depth.glsl                                                */
/**************************************************************************/
/* Depth-only pass of one area-light shadow map view (AreaShadowRendererRD). */
/* A map covers the lit half-space of ONE sample point on the light with  */
/* four perspective views, one per octant of the front hemisphere (see    */
/* area_shadow_octant_inc.glsl and doc/shadows.md). The vertex shader     */
/* gets octant_view_from_model (x: right, y: up, z: forward = distance    */
/* along the octant axis); the fragment writes the Euclidean distance to  */
/* the sample point times depth_scale (1 / depth range), so the lookup     */
/* compares distances in metres, independent of the view.                 */

#[vertex]

#version 450

#include "area_shadow_octant_inc.glsl"

layout(location = 0) in vec3 vertex_attrib;

layout(push_constant, std430) uniform DrawData {
	mat4 octant_view_from_model;
	vec4 params; // x: depth_scale (1 / depth range, 1/m), y: z_near, z: z_far (m), w: unused.
}
draw;

layout(location = 0) out vec3 octant_pos;

void main() {
	vec3 p = (draw.octant_view_from_model * vec4(vertex_attrib, 1.0)).xyz;
	octant_pos = p;
	gl_Position = area_shadow_octant_clip(p, draw.params.y, draw.params.z);
}

#[fragment]

#version 450

layout(push_constant, std430) uniform DrawData {
	mat4 octant_view_from_model;
	vec4 params;
}
draw;

layout(location = 0) in vec3 octant_pos;

void main() {
	gl_FragDepth = clamp(length(octant_pos) * draw.params.x, 0.0, 1.0);
}
