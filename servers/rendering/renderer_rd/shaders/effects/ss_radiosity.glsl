/**************************************************************************/
/*  ss_radiosity.glsl                                                     */
/**************************************************************************/
/* Image-space radiosity (seed 003, Rohleder, Listing 3 and §4.2-4.4),    */
/* the coarse passes; C++: renderer_rd/effects/ss_radiosity_rd.h, push    */
/* constant mirror SSRadiosityRD::PassPushConstant. Every coarse buffer   */
/* is RGBA32UI, one texel per tap (isr_pack in ss_radiosity_inc.glsl):    */
/* a colour, a scalar, the view normal and the linear depth. Variants:    */
/*   MODE_DOWNSAMPLE (+ DOWNSAMPLE_HALF for half_size): full-resolution   */
/*     colour (the opaque pass's outgoing radiance L), view normals and   */
/*     depth -> the coarse G-buffer (L, 0, normal, depth; depth 0: no     */
/*     surface). The seed averages each 2x2 block (read in gathers);      */
/*     averaging depth across a silhouette would invent a surface between */
/*     the two, so only the texels within 5 % of the block's nearest      */
/*     depth are averaged.                                                */
/*   MODE_ISR: per coarse pixel, samples of an N-sample golden-angle      */
/*     spiral (rotated per k x k block, isr_pixel_noise; interleaved:     */
/*     each pixel of the block takes every k^2-th sample) inside the      */
/*     screen disk of the world radius ssil_radius / ssao_radius; each    */
/*     sample is a patch of S / N pixels (S = disk area): indirect light  */
/*     from eqs. 6 and 25, occlusion from eq. 26. Out: sum F L (rho       */
/*     applied later), the occlusion sum, the pixel's normal and depth.   */
/*   MODE_BLUR: one pass of the depth-aware blur (§4.2), 3 x 3 linear    */
/*     B-spline taps at stride 1, 2, 4 ... per pass (à trous), which also */
/*     gathers the interleaved samples of a block: taps off the centre's  */
/*     tangent plane are rejected, by ssil_sharpness for the light and    */
/*     ssao_sharpness for the occlusion.                                  */

#[compute]

#version 450

#include "ss_radiosity_inc.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// Mirror: SSRadiosityRD::PassPushConstant (128 bytes).
layout(push_constant, std430) uniform Params {
	vec4 proj_xy; // P00, P11, P20, P21 of the depth-corrected clip_from_view.
	vec4 proj_zw; // P30, P31, P23, P33.
	vec4 proj_depth; // P22, P32, coarse width, coarse height.
	vec4 ssil; // radius (m), normal rejection, enabled (0/1), max disk radius (coarse pixels).
	vec4 ssao; // radius (m), horizon, detail, enabled (0/1).
	vec4 blur; // the pass's stride (coarse pixels), unused; ssil sharpness, ssao sharpness.
	uvec4 misc; // sample count, full width, full height, full / coarse scale (1 or 2).
	uvec4 pattern; // interleave k (k x k pixels share the N-sample pattern), unused x3.
}
params;

#ifdef MODE_DOWNSAMPLE
layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform texture2D color_texture; // Full-resolution HDR colour (L).
layout(set = 0, binding = 2) uniform texture2D depth_texture; // Full-resolution depth buffer.
layout(set = 0, binding = 3) uniform texture2D normal_texture; // View normals (xyz).
layout(set = 0, binding = 4, rgba32ui) uniform restrict writeonly uimage2D coarse_gbuffer;

void main() {
	ivec2 c = ivec2(gl_GlobalInvocationID.xy);
	ivec2 coarse_size = ivec2(params.proj_depth.zw);
	if (any(greaterThanEqual(c, coarse_size))) {
		return;
	}
	// The 2x2 block (one texel with scale 1), one gather per channel, texels ordered as textureGather returns
	// them: (0, 1), (1, 1), (1, 0), (0, 0) (the clamp-to-edge sampler repeats the last row and column).
	vec2 full_size = vec2(params.misc.yz);
#ifdef DOWNSAMPLE_HALF
	vec2 uv = (vec2(c) * 2.0 + 1.0) / full_size; // The block's centre: the four texels around it.
#define ISR_GATHER(m_tex, m_comp) textureGather(sampler2D(m_tex, nearest_sampler), uv, m_comp)
#else // Full size: the pixel's own texel, as the four.
#define ISR_GATHER(m_tex, m_comp) vec4(texelFetch(sampler2D(m_tex, nearest_sampler), c, 0)[m_comp])
#endif
	vec4 z = ISR_GATHER(depth_texture, 0);
	// isr_linear_depth on the four; 0 where no surface (depth 1).
	vec4 d = -(vec4(params.proj_depth.y) - z * params.proj_zw.w) / (z * params.proj_zw.z - vec4(params.proj_depth.x));
	d = mix(vec4(0.0), d, lessThan(z, vec4(1.0)));
	vec4 d_valid = mix(vec4(1e30), d, greaterThan(d, vec4(0.0)));
	float nearest = min(min(d_valid.x, d_valid.y), min(d_valid.z, d_valid.w));
	vec4 sel = vec4(lessThanEqual(d_valid, vec4(nearest * 1.05)));
	vec3 radiance = vec3(0.0);
	vec3 normal = vec3(0.0, 0.0, 1.0);
	float depth = 0.0;
	if (nearest < 1e30) {
		float inv_count = 1.0 / dot(sel, vec4(1.0));
		radiance = vec3(dot(ISR_GATHER(color_texture, 0), sel), dot(ISR_GATHER(color_texture, 1), sel), dot(ISR_GATHER(color_texture, 2), sel)) * inv_count;
		vec3 nsum = vec3(dot(ISR_GATHER(normal_texture, 0), sel), dot(ISR_GATHER(normal_texture, 1), sel), dot(ISR_GATHER(normal_texture, 2), sel));
		depth = dot(d_valid * sel, vec4(1.0)) * inv_count;
		float l = length(nsum);
		normal = l > 0.0 ? nsum / l : vec3(0.0, 0.0, 1.0);
	}
	imageStore(coarse_gbuffer, c, isr_pack(radiance, 0.0, normal, depth));
}
#endif

#ifdef MODE_ISR
layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform utexture2D coarse_gbuffer;
layout(set = 0, binding = 2, rgba32ui) uniform restrict writeonly uimage2D isr_out;

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
	uvec4 centre = texelFetch(usampler2D(coarse_gbuffer, nearest_sampler), c, 0);
	float d_p = isr_unpack_depth(centre);
	if (d_p <= 0.0) {
		imageStore(isr_out, c, centre); // No surface: depth 0 (the value is 0 too).
		return;
	}
	vec3 n_p = isr_unpack_normal(centre);
	vec3 p = coarse_position(c, d_p, size);
	float w_p = params.proj_zw.z * p.z + params.proj_zw.w;
	float px_per_m = abs(params.proj_xy.x) * size.x * 0.5 / w_p; // Coarse pixels per metre at p.
	uint n = params.misc.x;
	// Interleaved sampling: the k x k pixels of a block share one rotation of the N-sample spiral and
	// each takes every (k^2)-th sample of it, from its slot on; the depth-aware blur gathers the block
	// again, so each coarse pixel still sees the N samples of the pattern (seed §4.4) at 1 / k^2 of
	// the cost per pixel. Each sample keeps the patch of the full pattern (S / N pixels, so the
	// regularised form factor and the occluder spheres are those of N samples) and the pixel's sum of
	// its m samples is scaled by N / m: an estimate on its own, whose block mean is the full sum.
	uint k = params.pattern.x;
	uint kk = k * k;
	uint slot = uint(c.y % int(k)) * k + uint(c.x % int(k));
	uint m = slot < n ? (n - slot + kk - 1u) / kk : 0u;
	float inv_n = 1.0 / float(n);
	float rotation = 2.0 * ISR_PI * isr_pixel_noise(vec2(c / int(k)));
	const float golden_angle = 2.39996323; // pi (3 - sqrt 5).
	// The pixel's samples i = slot + j k^2 lie at angles slot * golden_angle + rotation + j * (k^2 golden_angle):
	// the unit direction turns by a fixed step per sample (one complex product instead of a cos and a sin).
	float a0 = float(slot) * golden_angle + rotation;
	vec2 unit = vec2(cos(a0), sin(a0));
	vec2 turn = vec2(cos(float(kk) * golden_angle), sin(float(kk) * golden_angle));

	vec3 bounce = vec3(0.0);
	float occlusion = 0.0;
	float r_il = clamp(params.ssil.x * px_per_m, 1.0, params.ssil.w);
	float r_ao = clamp(params.ssao.x * px_per_m, 1.0, params.ssil.w);
	float share_il = ISR_PI * r_il * r_il * inv_n; // Pixels per sample (S / N).
	// ssao_detail: every other sample of the pixel's subset (of the pattern: i / k^2 odd) forms a
	// second, inner set at a quarter of the radius (Godot's detail occlusion), weighted by detail;
	// each set holds N / 2 samples of the pattern.
	float half_n = max(float(n / 2u), 1.0);
	for (uint j = 0u; j < m; j++) {
		uint i = slot + j * kk;
		float t = (float(i) + 0.5) * inv_n;
		vec2 dir = unit * sqrt(t);
		unit = vec2(unit.x * turn.x - unit.y * turn.y, unit.x * turn.y + unit.y * turn.x);
#ifdef USE_SSIL
		{
			ivec2 q = ivec2(floor(vec2(c) + 0.5 + dir * r_il));
			if (q != c && all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, isize))) {
				uvec4 tx = texelFetch(usampler2D(coarse_gbuffer, nearest_sampler), q, 0);
				float d_x = isr_unpack_depth(tx);
				if (d_x > 0.0) {
					vec3 x = coarse_position(q, d_x, size);
					vec3 px = x - p;
					if (dot(px, px) <= params.ssil.x * params.ssil.x) {
						// The patch: S / N pixels at the sample's depth, tilted by its normal (foreshortening).
						vec3 n_x = isr_unpack_normal(tx);
						float facing = max(abs(dot(n_x, normalize(x))), 0.1);
						float area = share_il * isr_pixel_area(d_x, size, params.proj_xy, params.proj_zw) / facing;
						float f = isr_form_factor(p, n_p, x, n_x, area, params.ssil.y);
						bounce += isr_patch_radiance(vec3(1.0), f, isr_unpack_value(tx).rgb);
					}
				}
			}
		}
#endif
#ifdef USE_SSAO
		{
			bool inner = (j & 1u) == 1u;
			float r = inner ? r_ao * 0.25 : r_ao;
			ivec2 q = ivec2(floor(vec2(c) + 0.5 + dir * r));
			if (q != c && all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, isize))) {
				float d_x = isr_unpack_depth(texelFetch(usampler2D(coarse_gbuffer, nearest_sampler), q, 0));
				if (d_x > 0.0) {
					vec3 x = coarse_position(q, d_x, size);
					// Occluder radius: the sphere with the area of the sample's patch (S / (N/2) pixels).
					float patch_area = ISR_PI * r * r / half_n * isr_pixel_area(d_x, size, params.proj_xy, params.proj_zw);
					float radius = sqrt(patch_area / ISR_PI);
					float o = isr_occlusion(p, n_p, x, radius, half_n, params.ssao.y);
					occlusion += inner ? params.ssao.z * o : o;
				}
			}
		}
#endif
	}
	float scale = m > 0u ? float(n) / float(m) : 0.0;
	imageStore(isr_out, c, uvec4(isr_pack(bounce * scale, occlusion * scale, n_p, d_p).xy, centre.zw));
}
#endif

#ifdef MODE_BLUR
layout(set = 0, binding = 0) uniform sampler nearest_sampler;
layout(set = 0, binding = 1) uniform utexture2D isr_in;
layout(set = 0, binding = 2, rgba32ui) uniform restrict writeonly uimage2D isr_out;

void main() {
	ivec2 c = ivec2(gl_GlobalInvocationID.xy);
	vec2 size = params.proj_depth.zw;
	ivec2 isize = ivec2(size);
	if (any(greaterThanEqual(c, isize))) {
		return;
	}
	uvec4 centre = texelFetch(usampler2D(isr_in, nearest_sampler), c, 0);
	float d_p = isr_unpack_depth(centre);
	if (d_p <= 0.0) {
		imageStore(isr_out, c, centre);
		return;
	}
	vec2 ndc_c = (vec2(c) + 0.5) / size * 2.0 - 1.0;
	vec3 p = isr_view_position(ndc_c, d_p, params.proj_xy, params.proj_zw);
	int stride = int(params.blur.x);
	vec2 inv_p = 1.0 / params.proj_xy.xy; // isr_view_position below, with its divisions as products.
	vec3 n_p = isr_unpack_normal(centre);
	// Plane distance tolerance relative to depth: sharpness 0 -> 50 %, 1 -> 0.5 % of d.
#ifdef USE_SSIL
	float inv_tol_il = 1.0 / (mix(0.5, 0.005, params.blur.z) * d_p);
	vec3 sum_rgb = vec3(0.0);
	float w_rgb = 0.0;
#endif
#ifdef USE_SSAO
	float inv_tol_ao = 1.0 / (mix(0.5, 0.005, params.blur.w) * d_p);
	float sum_a = 0.0;
	float w_a = 0.0;
#endif
	// 3 x 3 taps, the linear B-spline (1, 2, 1) / 4 in each axis, at the pass's stride (à trous: 1, 2, 4,
	// ... coarse pixels; Dammertz et al. 2010, "Edge-Avoiding A-Trous Wavelet Transform for fast Global
	// Illumination Filtering", with the 3-tap spline): the stride-1 pass cancels the period-2 patterns
	// of the interleaved samples and the stride-2 pass the period-4 ones, exactly on flat surfaces; two
	// passes reach +-3 pixels with 18 taps in two dispatches (on a CPU Vulkan driver each dispatch over
	// the coarse image costs about as much as 4 taps; doc/isr.md, Cost).
	const float taps[3] = float[](0.25, 0.5, 0.25);
	for (int ky = -1; ky <= 1; ky++) {
		for (int kx = -1; kx <= 1; kx++) {
			ivec2 q = clamp(c + ivec2(kx, ky) * stride, ivec2(0), isize - 1);
			float g = taps[kx + 1] * taps[ky + 1];
			uvec4 t = texelFetch(usampler2D(isr_in, nearest_sampler), q, 0);
			float d_q = isr_unpack_depth(t);
			if (d_q <= 0.0) {
				continue;
			}
			float z = -d_q;
			float w = params.proj_zw.z * z + params.proj_zw.w;
			vec2 ndc_q = (vec2(q) + 0.5) / size * 2.0 - 1.0;
			vec3 x = vec3((ndc_q * w - params.proj_xy.zw * z - params.proj_zw.xy) * inv_p, z);
			// Distance from the centre's tangent plane only: a tap on a surface at an angle lies off
			// the plane unless it is next to the crease. (A further weight by normal agreement,
			// max(n_p . n_q, 0), lowered the share of improved pixels of bench --sweep isr from
			// 98.7 % to 98.0 %, doc/isr.md.)
			float plane = abs(dot(n_p, x - p));
			vec4 v = isr_unpack_value(t);
#ifdef USE_SSIL
			float wi = g * exp(-plane * inv_tol_il);
			sum_rgb += v.rgb * wi;
			w_rgb += wi;
#endif
#ifdef USE_SSAO
			float wa = g * exp(-plane * inv_tol_ao);
			sum_a += v.a * wa;
			w_a += wa;
#endif
		}
	}
	vec3 rgb = vec3(0.0);
	float a = 0.0;
#ifdef USE_SSIL
	rgb = w_rgb > 0.0 ? sum_rgb / w_rgb : vec3(0.0);
#endif
#ifdef USE_SSAO
	a = w_a > 0.0 ? sum_a / w_a : 0.0;
#endif
	imageStore(isr_out, c, uvec4(packHalf2x16(rgb.rg), packHalf2x16(vec2(rgb.b, a)), centre.zw));
}
#endif
