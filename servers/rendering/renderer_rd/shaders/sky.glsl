/**************************************************************************/
/*  sky.glsl                                                              */
/**************************************************************************/
/* Sky background of the Forward+ renderer (SkyRD, effects/sky_rd.h): a   */
/* fullscreen triangle at the far plane, drawn after the opaque pass with */
/* depth test LESS_OR_EQUAL, so it covers exactly the pixels no geometry  */
/* wrote. Each pixel evaluates the sky (sky_inc.glsl: Procedural or      */
/* PhysicalSkyMaterial) along its world-space view ray; the C++ twin (and */
/* the formulas) is servers/rendering/sky_model.h, which the SH ambient,   */
/* and the Embree reference use. Output: linear HDR radiance.             */

#[vertex]

#version 450

void main() {
	// Fullscreen triangle: (-1,-1), (3,-1), (-1,3) at depth 1 (the far plane of the Vulkan depth range).
	vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2)) * 2.0 - 1.0;
	gl_Position = vec4(p, 1.0, 1.0);
}

#[fragment]

#version 450

#include "sky_inc.glsl"

layout(location = 0) out vec4 frag_color;

void main() {
	vec2 ndc = gl_FragCoord.xy / sky.viewport_size.xy * 2.0 - 1.0;
	vec4 far_view = sky.view_from_clip * vec4(ndc, 1.0, 1.0);
	vec4 near_view = sky.view_from_clip * vec4(ndc, 0.0, 1.0);
	vec3 view_dir = far_view.xyz / far_view.w - near_view.xyz / near_view.w;
	vec3 dir = normalize(mat3(sky.world_from_view) * view_dir);
	frag_color = vec4(sky_evaluate(dir), 1.0);
}
