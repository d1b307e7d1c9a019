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
/* Variant ALPHA_TEST (casters whose material is ALPHA_SCISSOR): the      */
/* material's set 1 and shadow_alpha_test_inc.glsl cut the caster.        */

#[vertex]

#version 450

#include "area_shadow_octant_inc.glsl"

layout(location = 0) in vec3 vertex_attrib;
#ifdef ALPHA_TEST
layout(location = 3) in vec2 uv_attrib;
layout(location = 4) in vec4 color_attrib; // ARRAY_COLOR (a stand-in without one: params.w = 0).
#endif

layout(push_constant, std430) uniform DrawData {
	mat4 octant_view_from_model;
	vec4 params; // x: depth_scale (1 / depth range, 1/m), y: z_near, z: z_far (m), w: 1 if the surface has ARRAY_COLOR (ALPHA_TEST).
}
draw;

layout(location = 0) out vec3 octant_pos;
#ifdef ALPHA_TEST
layout(location = 1) out vec2 uv_interp;
layout(location = 2) out vec4 color_interp;
#endif

void main() {
	vec3 p = (draw.octant_view_from_model * vec4(vertex_attrib, 1.0)).xyz;
	octant_pos = p;
#ifdef ALPHA_TEST
	uv_interp = uv_attrib;
	color_interp = draw.params.w != 0.0 ? color_attrib : vec4(1.0);
#endif
	gl_Position = area_shadow_octant_clip(p, draw.params.y, draw.params.z);
}

#[fragment]

#version 450

#ifdef ALPHA_TEST
#include "shadow_alpha_test_inc.glsl"
#endif

layout(push_constant, std430) uniform DrawData {
	mat4 octant_view_from_model;
	vec4 params;
}
draw;

layout(location = 0) in vec3 octant_pos;
#ifdef ALPHA_TEST
layout(location = 1) in vec2 uv_interp;
layout(location = 2) in vec4 color_interp;
#endif

void main() {
#ifdef ALPHA_TEST
	shadow_alpha_test(uv_interp, color_interp);
#endif
	gl_FragDepth = clamp(length(octant_pos) * draw.params.x, 0.0, 1.0);
}
