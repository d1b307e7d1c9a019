/**************************************************************************/
/*  ss_radiosity_composite.glsl                                           */
/**************************************************************************/
/* Image-space radiosity, lighting phase (seed 003, §4.5, Listing 7):     */
/* bilateral upsampling of the blurred coarse result (eqs. 27-28) and     */
/* composition (eq. 29) into the HDR colour target, as a fullscreen       */
/* triangle blended ONE, SRC_ALPHA over the opaque pass's colour C:       */
/*   C' = C f + ambient (v - f) + k_ISR rho E                             */
/* with v = pow(saturate(1 - ssao_intensity O), ssao_power) the AO        */
/* visibility from the occlusion O of eq. 26, f = saturate(v + 1 - k_SSAO)*/
/* eq. 29's direct-light factor with k_SSAO = ssao_light_affect, the      */
/* ambient part scaled by v alone (eq. 29 with k_SSAO = 1, as Godot's     */
/* SSAO darkens ambient light), k_ISR = ssil_intensity, rho the diffuse   */
/* albedo and E the upsampled sum F L of eq. 25. Pixels without geometry  */
/* are left alone. Variants: USE_SSIL, USE_SSAO (each reads only the      */
/* targets its terms need). C++: renderer_rd/effects/ss_radiosity_rd.h,   */
/* mirror SSRadiosityRD::CompositePushConstant.                           */

#[vertex]

#version 450

void main() {
	vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2)) * 2.0 - 1.0;
	gl_Position = vec4(p, 0.0, 1.0);
}

#[fragment]

#version 450

#include "ss_radiosity_inc.glsl"

layout(push_constant, std430) uniform Params { // Mirror: SSRadiosityRD::CompositePushConstant (64 bytes).
	vec4 proj_depth; // P22, P32, P23, P33.
	vec4 sizes; // full width, height, coarse width, height.
	vec4 terms; // ssil_intensity (0 when SSIL is off), ssao_intensity, ssao_power, ssao_light_affect.
	vec4 flags; // ssao enabled (0/1), eps (relative), match (relative), unused.
}
params;

layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform texture2D depth_texture;
#ifdef USE_SSIL
layout(set = 0, binding = 2) uniform texture2D albedo_texture; // Diffuse albedo rho (rgb).
#endif
#ifdef USE_SSAO
layout(set = 0, binding = 3) uniform texture2D ambient_texture; // Ambient part of C (rgb).
#endif
layout(set = 0, binding = 4) uniform utexture2D isr_texture; // Coarse, blurred (isr_pack): sum F L, O, normal, depth.

layout(location = 0) out vec4 frag_color;

void main() {
	ivec2 fp = ivec2(gl_FragCoord.xy);
	float z = texelFetch(sampler2D(depth_texture, nearest_sampler), fp, 0).r;
	if (z >= 1.0) {
		discard; // Background: no surface, nothing to add.
	}
	float zp = isr_linear_depth(z, params.proj_depth.x, params.proj_depth.y, params.proj_depth.z, params.proj_depth.w);
	vec2 coarse = params.sizes.zw;
	vec2 cpos = (vec2(fp) + 0.5) * coarse / params.sizes.xy - 0.5;
	vec2 base = floor(cpos);
	vec2 f = cpos - base;
	// The 2x2 coarse texels around the pixel in gathers (one per packed word used), reordered from
	// textureGather's (0, 1), (1, 1), (1, 0), (0, 0) to (0, 0), (1, 0), (0, 1), (1, 1); the clamp-to-edge
	// sampler repeats the border texels.
	vec2 uv = (base + 1.0) / coarse;
	vec4 zs = uintBitsToFloat(textureGather(usampler2D(isr_texture, nearest_sampler), uv, 3).wzxy);
	uvec4 rg = textureGather(usampler2D(isr_texture, nearest_sampler), uv, 0).wzxy;
	uvec4 ba = textureGather(usampler2D(isr_texture, nearest_sampler), uv, 1).wzxy;
	vec4 w = isr_bilateral_weights(f, zs, zp, params.flags.y, params.flags.z);
	vec4 isr = vec4(0.0);
	for (int i = 0; i < 4; i++) {
		isr += vec4(unpackHalf2x16(rg[i]), unpackHalf2x16(ba[i])) * w[i];
	}

	vec3 added = vec3(0.0);
	float fd = 1.0;
#ifdef USE_SSAO
	float v = pow(clamp(1.0 - params.terms.y * isr.a, 0.0, 1.0), params.terms.z);
	fd = clamp(v + 1.0 - params.terms.w, 0.0, 1.0); // Eq. 29: saturate(L_SSAO + 1 - k_SSAO).
	added += texelFetch(sampler2D(ambient_texture, nearest_sampler), fp, 0).rgb * (v - fd);
#endif
#ifdef USE_SSIL
	added += params.terms.x * texelFetch(sampler2D(albedo_texture, nearest_sampler), fp, 0).rgb * isr.rgb;
#endif
	frag_color = vec4(added, fd);
}
