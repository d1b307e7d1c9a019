/**************************************************************************/
/*  directional_shadow_depth.glsl                                         */
/**************************************************************************/
/* Depth-only pass of one DirectionalLight3D shadow split               */
/* (DirectionalShadowRD). The push constant maps the model to the       */
/* split's orthographic box: x, y in -1..1 over the box, depth 0 at the  */
/* side nearest the light and 1 at its far side (linear: an orthographic */
/* projection), so the lookup compares linear depths.                    */
/* Variant ALPHA_TEST (casters whose material is ALPHA_SCISSOR): the      */
/* material's set 1 and shadow_alpha_test_inc.glsl cut the caster.        */

#[vertex]

#version 450

layout(location = 0) in vec3 vertex_attrib;
#ifdef ALPHA_TEST
layout(location = 3) in vec2 uv_attrib;
layout(location = 4) in vec4 color_attrib; // ARRAY_COLOR (a stand-in without one: has_color = 0).
#endif

layout(push_constant, std430) uniform DrawData {
	mat4 clip_from_model; // DirectionalShadowRD::Split::get_clip_from_world() * world_from_model.
#ifdef ALPHA_TEST
	uvec4 has_color; // x: 1 if the surface has ARRAY_COLOR.
#endif
}
draw;

#ifdef ALPHA_TEST
layout(location = 0) out vec2 uv_interp;
layout(location = 1) out vec4 color_interp;
#endif

void main() {
	gl_Position = draw.clip_from_model * vec4(vertex_attrib, 1.0);
#ifdef ALPHA_TEST
	uv_interp = uv_attrib;
	color_interp = draw.has_color.x != 0u ? color_attrib : vec4(1.0);
#endif
}

#[fragment]

#version 450

#ifdef ALPHA_TEST
#include "shadow_alpha_test_inc.glsl"

layout(location = 0) in vec2 uv_interp;
layout(location = 1) in vec4 color_interp;
#endif

void main() {
#ifdef ALPHA_TEST
	shadow_alpha_test(uv_interp, color_interp);
#endif
}
