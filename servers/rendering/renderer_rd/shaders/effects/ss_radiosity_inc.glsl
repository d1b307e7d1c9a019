/**************************************************************************/
/*  ss_radiosity_inc.glsl                                                 */
/**************************************************************************/
/* The terms of image-space radiosity (ISR; seed 003, Rohleder, §4.3-4.5) */
/* shared by ss_radiosity.glsl and ss_radiosity_composite.glsl; the GPU  */
/* tests (tests/servers/test_ss_radiosity.cpp) run these very functions  */
/* against hand-computed values.                                          */
/*                                                                        */
/* Spaces: view space (camera at the origin looking down -Z). "Linear     */
/* depth" d is -z_view (> 0 in front of the camera; 0 marks "no surface").*/

#define ISR_PI 3.14159265358979

// §4.3 (eqs. 23-24), written with the projection's own terms instead of the frustum corner vectors:
// for clip = P * view (column-major P[c][r]), x_ndc = (P00 x + P20 z + P30) / w with w = P23 z + P33,
// so x = (x_ndc w - P20 z - P30) / P00 (y likewise with P11, P21, P31) and z = -d. For a perspective
// P (P23 = -1, P33 = 0) this is the seed's f_o + x f_u + y f_v scaled by the linear depth; the same
// line also holds for orthographic projections. p_xy = (P00, P11, P20, P21), p_zw = (P30, P31, P23, P33).
vec3 isr_view_position(vec2 p_ndc, float p_depth, vec4 p_xy, vec4 p_zw) {
	float z = -p_depth;
	float w = p_zw.z * z + p_zw.w;
	return vec3((p_ndc.x * w - p_xy.z * z - p_zw.x) / p_xy.x, (p_ndc.y * w - p_xy.w * z - p_zw.y) / p_xy.y, z);
}

// Linear depth d from a depth-buffer value: depth = (P22 z + P32) / (P23 z + P33) solved for z.
float isr_linear_depth(float p_depth, float p_p22, float p_p32, float p_p23, float p_p33) {
	return -(p_p32 - p_depth * p_p33) / (p_depth * p_p23 - p_p22);
}

// World-space area of one pixel of a p_width x p_height image at linear depth p_depth, on a plane
// facing the camera: (2 w / (P00 W)) (2 w / |P11| H), w the clip w at that depth.
float isr_pixel_area(float p_depth, vec2 p_size, vec4 p_xy, vec4 p_zw) {
	float w = p_zw.z * -p_depth + p_zw.w;
	return (2.0 * w / (abs(p_xy.x) * p_size.x)) * (2.0 * w / (abs(p_xy.y) * p_size.y));
}

// Eq. 6, the differential form factor cos(theta_p) cos(theta_x) dA_x / (pi r^2) from the patch at p
// (normal p_np) to the patch at x (normal p_nx, area p_area), regularised as a disk of area dA_x,
// cos cos dA / (pi r^2 + dA): equal to eq. 6 when dA << r^2 and never above 1 when the patch is close
// (neighbouring pixels in a corner). p_normal_rejection (Godot's ssil_normal_rejection, 0..1) blends
// cos(theta_x) from |cos| (0: patches facing away still emit) to max(cos, 0) (1: they do not).
float isr_form_factor(vec3 p_p, vec3 p_np, vec3 p_x, vec3 p_nx, float p_area, float p_normal_rejection) {
	vec3 d = p_x - p_p;
	float r2 = dot(d, d);
	if (!(r2 > 0.0)) {
		return 0.0;
	}
	vec3 w = d * inversesqrt(r2);
	float cos_p = dot(p_np, w);
	if (cos_p <= 0.0) {
		return 0.0; // Behind the receiver.
	}
	float cos_x_signed = -dot(p_nx, w);
	float cos_x = mix(abs(cos_x_signed), max(cos_x_signed, 0.0), p_normal_rejection);
	return cos_p * cos_x * p_area / (ISR_PI * r2 + p_area);
}

// Eq. 25, the radiance at p reflected from the patch at x: rho_p F_px L_x. The seed writes a further
// 2 pi / N, the solid angle a sample stands for when the N samples cover the hemisphere. Our samples
// cover a disk of S pixels on screen instead, and the share each stands for is its patch area
// dA_x = (S / N) * pixel area, already inside F (eq. 6); writing both would count that share twice.
// The sum over samples is then the Monte Carlo estimate of rho / pi * integral(L cos(theta) d omega)
// over the visible neighbourhood. rho_p is applied at full resolution (composition).
vec3 isr_patch_radiance(vec3 p_rho, float p_form_factor, vec3 p_radiance) {
	return p_rho * p_form_factor * p_radiance;
}

// Eq. 26, the occlusion of p (normal p_np) by the sample at x taken as a sphere of radius p_radius:
// 2 pi / N (1 - sqrt(1 - (r / |px|)^2)) max(n . px / |px|, 0). 1 - sqrt(1 - (r/|px|)^2) is the sphere's
// solid angle over 2 pi (clamped where the sphere contains p). Godot's ssao_horizon (0..1) raises the
// cosine's floor: samples less than that far above the tangent plane do not occlude (no self-occlusion
// of slightly curved or tessellated surfaces).
float isr_occlusion(vec3 p_p, vec3 p_np, vec3 p_x, float p_radius, float p_sample_count, float p_horizon) {
	vec3 d = p_x - p_p;
	float l2 = dot(d, d);
	if (!(l2 > 0.0)) {
		return 0.0;
	}
	float s2 = min(p_radius * p_radius / l2, 1.0);
	float c = dot(p_np, d) * inversesqrt(l2);
	c = max(c - p_horizon, 0.0) / max(1.0 - p_horizon, 1e-4);
	return (2.0 * ISR_PI / p_sample_count) * (1.0 - sqrt(1.0 - s2)) * c;
}

// Eqs. 27-28, bilateral upsampling weights of the 2x2 coarse samples around a full-resolution pixel:
// bilinear weights w_b (p_f = position inside the 2x2 block, samples ordered (0,0), (1,0), (0,1), (1,1))
// times w_z = 1 / (eps + |z_p - z_i|), normalised to sum 1. Coarse samples without a surface (z_i = 0)
// get weight 0. eps = p_eps_rel * z_p (the seed leaves eps open; relative, so the weights do not depend
// on scene scale). When no coarse sample matches (every |z_p - z_i| > p_match_rel * z_p: the unnormalised
// weights all nearly vanish, the seed's noted failure case) the nearest-depth sample gets weight 1.
vec4 isr_bilateral_weights(vec2 p_f, vec4 p_z, float p_zp, float p_eps_rel, float p_match_rel) {
	vec4 wb = vec4((1.0 - p_f.x) * (1.0 - p_f.y), p_f.x * (1.0 - p_f.y), (1.0 - p_f.x) * p_f.y, p_f.x * p_f.y);
	vec4 dz = abs(vec4(p_zp) - p_z);
	vec4 valid = vec4(greaterThan(p_z, vec4(0.0)));
	vec4 w = wb * valid / (vec4(p_eps_rel * p_zp) + dz);
	float nearest = 1e30;
	int nearest_i = -1;
	for (int i = 0; i < 4; i++) {
		if (valid[i] > 0.0 && dz[i] < nearest) {
			nearest = dz[i];
			nearest_i = i;
		}
	}
	float sum = dot(w, vec4(1.0));
	if (nearest_i < 0) {
		return vec4(0.0);
	}
	if (nearest > p_match_rel * p_zp || !(sum > 0.0)) {
		vec4 one_hot = vec4(0.0);
		one_hot[nearest_i] = 1.0;
		return one_hot;
	}
	return w / sum;
}

// Interleaved gradient noise (Jimenez 2014, "Next generation post processing in Call of Duty: Advanced
// Warfare"): a per-pixel rotation of the sample spiral, fixed per pixel so a static camera gives
// identical frames; the blur removes the pattern.
float isr_pixel_noise(vec2 p_pixel) {
	return fract(52.9829189 * fract(dot(p_pixel, vec2(0.06711056, 0.00583715))));
}

// The coarse buffers hold one RGBA32UI texel per pixel, so a tap of the ISR step, the blur or the
// upsampling is one fetch: x, y = half floats (r, g), (b, a) of a colour and a scalar (radiance L and
// 0 in the coarse G-buffer; sum F L and the occlusion O in the ISR result), z = the view normal in
// octahedral encoding (Cigolle et al. 2014, "A Survey of Efficient Representations for Independent
// Unit Vectors", §3.3) as two snorm16, w = the linear depth as a float (0: no surface).
vec2 isr_oct_encode(vec3 p_n) {
	vec3 n = p_n / max(abs(p_n.x) + abs(p_n.y) + abs(p_n.z), 1e-20);
	if (n.z < 0.0) {
		vec2 s = vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
		n.xy = (1.0 - abs(n.yx)) * s;
	}
	return n.xy;
}

vec3 isr_oct_decode(vec2 p_e) {
	vec3 n = vec3(p_e, 1.0 - abs(p_e.x) - abs(p_e.y));
	float t = max(-n.z, 0.0);
	n.x += n.x >= 0.0 ? -t : t;
	n.y += n.y >= 0.0 ? -t : t;
	return normalize(n);
}

uvec4 isr_pack(vec3 p_rgb, float p_a, vec3 p_normal, float p_depth) {
	return uvec4(packHalf2x16(p_rgb.rg), packHalf2x16(vec2(p_rgb.b, p_a)), packSnorm2x16(isr_oct_encode(p_normal)), floatBitsToUint(p_depth));
}

vec4 isr_unpack_value(uvec4 p_t) { // (rgb, a).
	return vec4(unpackHalf2x16(p_t.x), unpackHalf2x16(p_t.y));
}

vec3 isr_unpack_normal(uvec4 p_t) {
	return isr_oct_decode(unpackSnorm2x16(p_t.z));
}

float isr_unpack_depth(uvec4 p_t) {
	return uintBitsToFloat(p_t.w);
}
