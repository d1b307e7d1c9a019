/**************************************************************************/
/*  ss_radiosity.glsl                                                     */
/**************************************************************************/
/* Image-space radiosity (seed 003, Rohleder, Listing 3 and §4.2-4.4),    */
/* the coarse passes; C++: renderer_rd/effects/ss_radiosity_rd.h, push    */
/* constant mirror SSRadiosityRD::PassPushConstant. Variants:             */
/*   MODE_DOWNSAMPLE: full-resolution colour (the opaque pass's outgoing  */
/*     radiance L), view normals and depth -> coarse L (rgb) and coarse   */
/*     normal + linear depth (xyz, w; w = 0: no surface). The seed        */
/*     averages each 2x2 block; averaging depth across a silhouette would */
/*     invent a surface between the two, so only the texels within 5 % of */
/*     the block's nearest depth are averaged.                            */
/*   MODE_ISR: per coarse pixel, N samples on a golden-angle spiral (a    */
/*     per-pixel rotation, isr_pixel_noise) inside the screen disk of the */
/*     world radius ssil_radius / ssao_radius; each sample is a patch of  */
/*     S / N pixels (S = disk area): indirect light from eqs. 6 and 25,   */
/*     occlusion from eq. 26. Out: rgb = sum F L (rho applied later),     */
/*     a = sum of occlusion terms.                                        */
/*   MODE_BLUR: one direction of the separable depth-aware Gaussian blur  */
/*     (§4.2): taps off the centre's tangent plane are rejected, by       */
/*     ssil_sharpness for rgb and ssao_sharpness for a.                   */

#[compute]

#version 450

#include "ss_radiosity_inc.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// Mirror: SSRadiosityRD::PassPushConstant (112 bytes).
layout(push_constant, std430) uniform Params {
	vec4 proj_xy; // P00, P11, P20, P21 of the depth-corrected clip_from_view.
	vec4 proj_zw; // P30, P31, P23, P33.
	vec4 proj_depth; // P22, P32, coarse width, coarse height.
	vec4 ssil; // radius (m), normal rejection, enabled (0/1), max disk radius (coarse pixels).
	vec4 ssao; // radius (m), horizon, detail, enabled (0/1).
	vec4 blur; // direction x, y; ssil sharpness, ssao sharpness.
	uvec4 misc; // sample count, full width, full height, full / coarse scale (1 or 2).
}
params;

#ifdef MODE_DOWNSAMPLE
layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform texture2D color_texture; // Full-resolution HDR colour (L).
layout(set = 0, binding = 2) uniform texture2D depth_texture; // Full-resolution depth buffer.
layout(set = 0, binding = 3) uniform texture2D normal_texture; // View normals (xyz).
layout(set = 0, binding = 4, rgba16f) uniform restrict writeonly image2D coarse_radiance;
layout(set = 0, binding = 5, rgba32f) uniform restrict writeonly image2D coarse_normal_depth;

void main() {
	ivec2 c = ivec2(gl_GlobalInvocationID.xy);
	ivec2 coarse_size = ivec2(params.proj_depth.zw);
	if (any(greaterThanEqual(c, coarse_size))) {
		return;
	}
	int scale = int(params.misc.w);
	ivec2 full_size = ivec2(params.misc.yz);
	float depths[4];
	float nearest = 1e30;
	for (int i = 0; i < scale * scale; i++) {
		ivec2 f = min(c * scale + ivec2(i % scale, i / scale), full_size - 1);
		float z = texelFetch(sampler2D(depth_texture, nearest_sampler), f, 0).r;
		depths[i] = z < 1.0 ? isr_linear_depth(z, params.proj_depth.x, params.proj_depth.y, params.proj_zw.z, params.proj_zw.w) : 0.0;
		if (depths[i] > 0.0) {
			nearest = min(nearest, depths[i]);
		}
	}
	vec3 radiance = vec3(0.0);
	vec3 normal = vec3(0.0);
	float depth = 0.0;
	float count = 0.0;
	for (int i = 0; i < scale * scale; i++) {
		if (depths[i] > 0.0 && depths[i] <= nearest * 1.05) {
			ivec2 f = min(c * scale + ivec2(i % scale, i / scale), full_size - 1);
			radiance += texelFetch(sampler2D(color_texture, nearest_sampler), f, 0).rgb;
			normal += texelFetch(sampler2D(normal_texture, nearest_sampler), f, 0).xyz;
			depth += depths[i];
			count += 1.0;
		}
	}
	if (count > 0.0) {
		radiance /= count;
		depth /= count;
		float l = length(normal);
		normal = l > 0.0 ? normal / l : vec3(0.0, 0.0, 1.0);
	}
	imageStore(coarse_radiance, c, vec4(radiance, 1.0));
	imageStore(coarse_normal_depth, c, vec4(normal, depth));
}
#endif

#ifdef MODE_ISR
layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform texture2D coarse_radiance;
layout(set = 0, binding = 2) uniform texture2D coarse_normal_depth;
layout(set = 0, binding = 3, rgba16f) uniform restrict writeonly image2D isr_out;

vec3 coarse_position(ivec2 p_c, float p_depth, vec2 p_size) {
	vec2 ndc = (vec2(p_c) + 0.5) / p_size * 2.0 - 1.0;
	return isr_view_position(ndc, p_depth, params.proj_xy, params.proj_zw);
}

void main() {
	ivec2 c = ivec2(gl_GlobalInvocationID.xy);
	vec2 size = params.proj_depth.zw;
	ivec2 isize = ivec2(size);
	if (any(greaterThanEqual(c, isize))) {
		return;
	}
	vec4 nd = texelFetch(sampler2D(coarse_normal_depth, nearest_sampler), c, 0);
	if (nd.w <= 0.0) {
		imageStore(isr_out, c, vec4(0.0));
		return;
	}
	vec3 n_p = nd.xyz;
	vec3 p = coarse_position(c, nd.w, size);
	float w_p = params.proj_zw.z * p.z + params.proj_zw.w;
	float px_per_m = abs(params.proj_xy.x) * size.x * 0.5 / w_p; // Coarse pixels per metre at p.
	uint n = params.misc.x;
	float inv_n = 1.0 / float(n);
	float rotation = 2.0 * ISR_PI * isr_pixel_noise(vec2(c));
	const float golden_angle = 2.39996323; // pi (3 - sqrt 5).

	vec3 bounce = vec3(0.0);
	float occlusion = 0.0;
	bool ssil_on = params.ssil.z > 0.0;
	bool ssao_on = params.ssao.w > 0.0;
	float r_il = clamp(params.ssil.x * px_per_m, 1.0, params.ssil.w);
	float r_ao = clamp(params.ssao.x * px_per_m, 1.0, params.ssil.w);
	float share_il = ISR_PI * r_il * r_il * inv_n; // Pixels per sample (S / N).
	// ssao_detail: the odd samples form a second, inner set at a quarter of the radius (Godot's
	// detail occlusion), weighted by detail; each set holds N / 2 samples.
	float half_n = max(float(n / 2u), 1.0);
	for (uint i = 0u; i < n; i++) {
		float t = (float(i) + 0.5) * inv_n;
		float a = float(i) * golden_angle + rotation;
		vec2 dir = vec2(cos(a), sin(a)) * sqrt(t);
		if (ssil_on) {
			ivec2 q = ivec2(floor(vec2(c) + 0.5 + dir * r_il));
			if (q != c && all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, isize))) {
				vec4 nx = texelFetch(sampler2D(coarse_normal_depth, nearest_sampler), q, 0);
				if (nx.w > 0.0) {
					vec3 x = coarse_position(q, nx.w, size);
					vec3 px = x - p;
					if (dot(px, px) <= params.ssil.x * params.ssil.x) {
						// The patch: S / N pixels at the sample's depth, tilted by its normal (foreshortening).
						float facing = max(abs(dot(nx.xyz, normalize(x))), 0.1);
						float area = share_il * isr_pixel_area(nx.w, size, params.proj_xy, params.proj_zw) / facing;
						float f = isr_form_factor(p, n_p, x, nx.xyz, area, params.ssil.y);
						bounce += isr_patch_radiance(vec3(1.0), f, texelFetch(sampler2D(coarse_radiance, nearest_sampler), q, 0).rgb);
					}
				}
			}
		}
		if (ssao_on) {
			bool inner = (i & 1u) == 1u;
			float r = inner ? r_ao * 0.25 : r_ao;
			ivec2 q = ivec2(floor(vec2(c) + 0.5 + dir * r));
			if (q != c && all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, isize))) {
				vec4 nx = texelFetch(sampler2D(coarse_normal_depth, nearest_sampler), q, 0);
				if (nx.w > 0.0) {
					vec3 x = coarse_position(q, nx.w, size);
					// Occluder radius: the sphere with the area of the sample's patch (S / (N/2) pixels).
					float patch_area = ISR_PI * r * r / half_n * isr_pixel_area(nx.w, size, params.proj_xy, params.proj_zw);
					float radius = sqrt(patch_area / ISR_PI);
					float o = isr_occlusion(p, n_p, x, radius, half_n, params.ssao.y);
					occlusion += inner ? params.ssao.z * o : o;
				}
			}
		}
	}
	imageStore(isr_out, c, vec4(bounce, occlusion));
}
#endif

#ifdef MODE_BLUR
layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform texture2D isr_in;
layout(set = 0, binding = 2) uniform texture2D coarse_normal_depth;
layout(set = 0, binding = 3, rgba16f) uniform restrict writeonly image2D isr_out;

void main() {
	ivec2 c = ivec2(gl_GlobalInvocationID.xy);
	vec2 size = params.proj_depth.zw;
	ivec2 isize = ivec2(size);
	if (any(greaterThanEqual(c, isize))) {
		return;
	}
	vec4 nd = texelFetch(sampler2D(coarse_normal_depth, nearest_sampler), c, 0);
	if (nd.w <= 0.0) {
		imageStore(isr_out, c, vec4(0.0));
		return;
	}
	vec2 ndc_c = (vec2(c) + 0.5) / size * 2.0 - 1.0;
	vec3 p = isr_view_position(ndc_c, nd.w, params.proj_xy, params.proj_zw);
	// Plane distance tolerance relative to depth: sharpness 0 -> 50 %, 1 -> 0.5 % of d.
	float tol_il = mix(0.5, 0.005, params.blur.z) * nd.w;
	float tol_ao = mix(0.5, 0.005, params.blur.w) * nd.w;
	ivec2 step_dir = ivec2(params.blur.xy);
	vec3 sum_rgb = vec3(0.0);
	float sum_a = 0.0;
	float w_rgb = 0.0;
	float w_a = 0.0;
	// 7 taps, Gaussian sigma = 2 coarse pixels.
	for (int k = -3; k <= 3; k++) {
		ivec2 q = clamp(c + step_dir * k, ivec2(0), isize - 1);
		vec4 nq = texelFetch(sampler2D(coarse_normal_depth, nearest_sampler), q, 0);
		if (nq.w <= 0.0) {
			continue;
		}
		vec2 ndc_q = (vec2(q) + 0.5) / size * 2.0 - 1.0;
		vec3 x = isr_view_position(ndc_q, nq.w, params.proj_xy, params.proj_zw);
		float plane = abs(dot(nd.xyz, x - p));
		float g = exp(-float(k * k) / 8.0);
		float wi = g * exp(-plane / tol_il) * max(dot(nd.xyz, nq.xyz), 0.0);
		float wa = g * exp(-plane / tol_ao);
		vec4 v = texelFetch(sampler2D(isr_in, nearest_sampler), q, 0);
		sum_rgb += v.rgb * wi;
		w_rgb += wi;
		sum_a += v.a * wa;
		w_a += wa;
	}
	imageStore(isr_out, c, vec4(w_rgb > 0.0 ? sum_rgb / w_rgb : vec3(0.0), w_a > 0.0 ? sum_a / w_a : 0.0));
}
#endif
