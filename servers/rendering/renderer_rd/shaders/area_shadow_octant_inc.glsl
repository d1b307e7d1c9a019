/**************************************************************************/
/*  area_shadow_octant_inc.glsl                                           */
/**************************************************************************/
/* The four-view mapping of an area-light shadow map (one tile): the lit  */
/* half-space z < 0 of a sample point (light space: emission along -Z) is */
/* split into the four octants sign(x), sign(y); each is rendered by a    */
/* perspective view along the octant diagonal d = (sx, sy, -1)/sqrt(3)    */
/* with right r = (sy, -sx, 0)/sqrt(2) and up u = (sx, sy, 2)/sqrt(6).    */
/* The octant's three edges project (on the plane at distance 1 along d)  */
/* to x in [-sqrt(3/2), sqrt(3/2)], y in [-sqrt(2), sqrt(1/2)], so an     */
/* off-centre frustum with a small margin covers it exactly once.         */
/* Quadrant q = (sx > 0 ? 1 : 0) + (sy > 0 ? 2 : 0) of the tile.          */
/* C++ mirror: AreaShadowRendererRD (area_shadow_renderer.cpp) builds the */
/* same axes and uses the same constants.                                 */

#ifndef AREA_SHADOW_OCTANT_INC_GLSL
#define AREA_SHADOW_OCTANT_INC_GLSL

#define AREA_SHADOW_OCTANT_MARGIN 1.04
#define AREA_SHADOW_OCTANT_HALF_X (1.2247449 * AREA_SHADOW_OCTANT_MARGIN)
#define AREA_SHADOW_OCTANT_CENTER_Y (-0.35355339)
#define AREA_SHADOW_OCTANT_HALF_Y (1.0606602 * AREA_SHADOW_OCTANT_MARGIN)

// p: octant view space (x right, y up, z forward). Vulkan clip space; depth is overwritten by the
// fragment shader, z here only keeps the near/far clipping.
vec4 area_shadow_octant_clip(vec3 p_pos, float p_near, float p_far) {
	float zf = p_pos.z;
	float z = (zf - p_near) * (p_far / (p_far - p_near));
	return vec4(p_pos.x / AREA_SHADOW_OCTANT_HALF_X, (p_pos.y - AREA_SHADOW_OCTANT_CENTER_Y * zf) / AREA_SHADOW_OCTANT_HALF_Y, z, zf);
}

// Light-space offset v from the sample point (v.z < 0) to the octant quadrant and its [0,1]^2
// coordinate inside the quadrant.
void area_shadow_octant_project(vec3 p_v, out uint r_quadrant, out vec2 r_uv) {
	float sx = p_v.x >= 0.0 ? 1.0 : -1.0;
	float sy = p_v.y >= 0.0 ? 1.0 : -1.0;
	vec3 d = vec3(sx, sy, -1.0) * 0.57735027;
	vec3 r = vec3(sy, -sx, 0.0) * 0.70710678;
	vec3 u = vec3(sx, sy, 2.0) * 0.40824829;
	float zf = max(dot(p_v, d), 1e-6);
	vec2 ndc = vec2(dot(p_v, r) / (zf * AREA_SHADOW_OCTANT_HALF_X), (dot(p_v, u) / zf - AREA_SHADOW_OCTANT_CENTER_Y) / AREA_SHADOW_OCTANT_HALF_Y);
	r_uv = clamp(ndc * 0.5 + 0.5, vec2(0.0), vec2(1.0));
	r_quadrant = (sx > 0.0 ? 1u : 0u) + (sy > 0.0 ? 2u : 0u);
}

#endif // AREA_SHADOW_OCTANT_INC_GLSL
