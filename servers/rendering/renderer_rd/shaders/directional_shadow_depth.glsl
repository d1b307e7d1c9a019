/**************************************************************************/
/*  directional_shadow_depth.glsl                                         */
/**************************************************************************/
/* Depth-only pass of one DirectionalLight3D shadow split               */
/* (DirectionalShadowRD). The push constant maps the model to the       */
/* split's orthographic box: x, y in -1..1 over the box, depth 0 at the  */
/* side nearest the light and 1 at its far side (linear: an orthographic */
/* projection), so the lookup compares linear depths.                    */

#[vertex]

#version 450

layout(location = 0) in vec3 vertex_attrib;

layout(push_constant, std430) uniform DrawData {
	mat4 clip_from_model; // DirectionalShadowRD::Split::get_clip_from_world() * world_from_model.
}
draw;

void main() {
	gl_Position = draw.clip_from_model * vec4(vertex_attrib, 1.0);
}

#[fragment]

#version 450

void main() {
}
