/**************************************************************************/
/*  area_light_texture_inc.glsl                                           */
/**************************************************************************/
/* Textured area lights (AreaLight3D.area_texture): the emitted radiance  */
/* at a point of the rectangle is L_e times the texture's linear,         */
/* premultiplied colour there. The image reads upright from the lit side: */
/* uv = (0.5 - x / a, 0.5 - y / b) for the point (x, y) metres from the   */
/* centre along the light's local +X and +Y (a, b = area_size).           */
/*                                                                        */
/* The atlas (storage_rd/area_light_atlas.h, a 3D texture) holds per     */
/* texture level 0 (C x C texels) and Gaussian-prefiltered levels L       */
/* (sigma = 2^L level-0 texels, i.e. 2^L / C in uv) as depth slices. A    */
/* footprint of sigma (uv) reads level log2(sigma C): one trilinear fetch */
/* blends the two nearest levels.                                         */
/*                                                                        */
/* LTC (Heitz, Dupuy, Hill and Neubelt 2016, section 6, "Textured         */
/* polygons"): L_o ~ FF(P) * T(P), FF the form factor of the polygon in   */
/* the LTC's cosine space and T the texture prefiltered by the lobe,      */
/* looked up for specular where the vector form factor of the lit         */
/* polygon in M^-1 space (ltc_rect_form_factors' r_specular_vector, no    */
/* second evaluation) meets the quad's plane (the lobe's centre of mass   */
/* on the light), for diffuse at the foot of the perpendicular from the   */
/* shading point (the paper's choice; measured: diffuse relative RMSE     */
/* 0.14 at the foot vs 0.21 at the form factor's hit, specular 0.45 at    */
/* the hit vs 0.64 at the foot, tests/servers/test_area_light_texture),   */
/* with the footprint the plane distance over the polygon's size in that  */
/* space:                                                                 */
/*   sigma = k h / sqrt(A),  k = 1/2,                                     */
/* h the plane distance, A the area. At the lobe's foot the clamped       */
/* cosine seen from height h, projected on the plane, has the density     */
/* (h^2 / (h^2 + r^2))^2 / (pi h^2) = exp(-2 r^2 / h^2) + O(r^4) around   */
/* its foot, the Gaussian of sigma = h / 2 (matched at the peak, where    */
/* the light is; the heavy tail beyond the light does not count because   */
/* the prefilter is normalised over the light).                           */
/* ONE fetch serves both lobes (issue 21, T1: each trilinear fetch costs  */
/* about 0.07 of an untextured light on llvmpipe, where a branch skips    */
/* nothing): the two lookups are Gaussians (uv_d, sigma_d), (uv_s,        */
/* sigma_s); mixed with the weight t of the specular lobe in the pixel's  */
/* radiance (known before the fetch), the single Gaussian of the same     */
/* mean and variance is uv = mix(uv_d, uv_s, t), sigma^2 = mix(sigma_d^2, */
/* sigma_s^2, t) + t (1 - t) |uv_s - uv_d|^2. Exact where one lobe        */
/* dominates (t = 0 or 1); where both matter both get the mixture's blur. */
/*                                                                        */
/* MRP (Drobot 2014, section 1.3.5, eqs. 1.24 and 1.28): the result of    */
/* each lobe is multiplied by the prefiltered texture at its most         */
/* representative point, p_d for diffuse with the footprint of the plane  */
/* distance (as LTC: sigma = k d^2 / r, d = |p_d - p|, r the plane        */
/* distance), p_s for specular with the footprint                         */
/* of the importance cone projected on the plane (radius rho = t tan of   */
/* the cone's half angle, Drobot fig. 1.20; sigma = rho / 2: the cone     */
/* edge taken as two standard deviations).                                */
/*                                                                        */
/* Stochastic: each sample point is fetched exactly (level 0, bilinear),  */
/* so the estimator stays unbiased for the textured light.                */
/*                                                                        */
/* Without AREA_LIGHT_TEXTURE every function returns vec3(1.0) and no     */
/* atlas binding exists (the version of a view without textured lights). */
/* Needs light_data_inc.glsl (AreaLightData) and brdf_inc.glsl (M_PI).    */

#ifndef AREA_LIGHT_TEXTURE_INC_GLSL
#define AREA_LIGHT_TEXTURE_INC_GLSL

// MRP's diffuse footprint per metre of plane distance: the LTC's k (the same clamped cosine).
#define AREA_TEXTURE_MRP_DIFFUSE_SIGMA 0.5

#ifdef AREA_LIGHT_TEXTURE

layout(set = 0, binding = 4) uniform texture3D area_light_atlas; // AreaLightAtlas: RGBA16F linear, premultiplied; depth = level.
layout(set = 0, binding = 10) uniform sampler area_light_atlas_sampler; // Linear, clamp to edge, no mipmaps.

// The diffuse albedo of the shading point (channel mean of albedo * (1 - metallic)): the diffuse lobe's
// weight in the LTC's single fetch (area_texture_ltc). Set by the fragment shader before its light loop.
float area_texture_diffuse_albedo = 1.0;

// k: footprint sigma per unit of plane distance over the light's size (see above).
#define AREA_TEXTURE_FOOTPRINT 0.5

// Trilinear fetch at p_uv in [0, 1]^2 (clamped half a texel inside the slot, so no other slot bleeds in)
// and level p_lod in [0, levels - 1]: slices floor(lod) and floor(lod) + 1 blended by fract(lod).
vec3 area_texture_fetch(vec4 p_rect, vec2 p_uv, float p_lod) {
	ivec3 size = textureSize(sampler3D(area_light_atlas, area_light_atlas_sampler), 0);
	float half_texel = 0.5 / (p_rect.w * float(size.y)); // The slot's C texels per side.
	vec2 uv = clamp(p_uv, vec2(half_texel), vec2(1.0 - half_texel));
	float z = (clamp(p_lod, 0.0, float(size.z - 1)) + 0.5) / float(size.z);
	return textureLod(sampler3D(area_light_atlas, area_light_atlas_sampler), vec3(p_rect.xy + uv * p_rect.zw, z), 0.0).rgb;
}

// The texture at p_uv prefiltered with a Gaussian of p_sigma_uv (uv units): 1 for an untextured light.
vec3 area_texture_filtered(AreaLightData p_light, vec2 p_uv, float p_sigma_uv) {
	if (!(p_light.texture_rect.z > 0.0)) {
		return vec3(1.0);
	}
	float size = p_light.texture_rect.w * float(textureSize(sampler3D(area_light_atlas, area_light_atlas_sampler), 0).y);
	return area_texture_fetch(p_light.texture_rect, p_uv, log2(max(p_sigma_uv * size, 1e-6)));
}

// uv of the plane point p_coords (metres from the centre along the light's unit +X, +Y), p_half = a/2, b/2.
vec2 area_texture_uv(vec2 p_coords, vec2 p_half) {
	return vec2(0.5) - 0.5 * p_coords / p_half;
}

// Stochastic: the exact texture (level 0, bilinear) at p_rel = a point of the light minus its centre.
vec3 area_texture_point(AreaLightData p_light, vec3 p_rel, vec3 p_ax, vec3 p_ay, vec2 p_half) {
	if (!(p_light.texture_rect.z > 0.0)) {
		return vec3(1.0);
	}
	vec2 uv = area_texture_uv(vec2(dot(p_rel, p_ax), dot(p_rel, p_ay)), p_half);
	return area_texture_fetch(p_light.texture_rect, uv, 0.0);
}

// MRP: the texture at the representative point p_coords (light-plane metres) for a footprint of
// p_sigma metres.
vec3 area_texture_mrp(AreaLightData p_light, vec2 p_coords, vec2 p_half, float p_sigma) {
	if (!(p_light.texture_rect.z > 0.0)) {
		return vec3(1.0);
	}
	return area_texture_filtered(p_light, area_texture_uv(p_coords, p_half), p_sigma / (2.0 * sqrt(p_half.x * p_half.y)));
}

// LTC, both lobes from ONE fetch: the prefiltered texture for the quad p_q (corners at local (-x, -y),
// (+x, -y), (+x, +y), (-x, +y) of the light, relative to the shading point, in the receiver frame).
// Diffuse looks up at the foot of the perpendicular, specular where p_spec_vector (the vector form
// factor of the lit polygon in M^-1 space, ltc_rect_form_factors) meets the quad mapped by M^-1
// (p_m = M). The fetch reads the single Gaussian that matches the mean and variance of the two
// lookups' Gaussians mixed by the lobes' radiance (known before the fetch: the diffuse form factor
// p_diffuse times area_texture_diffuse_albedo, the specular lobe's p_specular = coverage times its
// Fresnel weight): exact where one lobe dominates, the mixture's blur where both matter.
vec3 area_texture_ltc(AreaLightData p_light, vec3 p_q[4], mat3 p_m, vec3 p_spec_vector, float p_diffuse, vec3 p_specular) {
	if (!(p_light.texture_rect.z > 0.0)) {
		return vec3(1.0);
	}
	vec3 e1 = p_q[1] - p_q[0];
	vec3 e2 = p_q[3] - p_q[0];
	vec3 n = cross(e1, e2); // |n| = A.
	float nn = dot(n, n);
	float plane = dot(n, p_q[0]); // |n| times the signed plane distance h.
	bool valid = nn > 0.0 && abs(plane) > 1e-12 * nn;
	// uv of a point p of the plane: 1 - ((p - q0).(e2 x n), (p - q0).(n x e1)) / nn.
	vec3 u_axis = cross(e2, n);
	vec3 v_axis = cross(n, e1);
	// Diffuse: the foot n plane / nn, footprint sigma = k h / sqrt(A) = k |plane| / |n|^(3/2) (squared below).
	vec3 foot = n * (plane / nn) - p_q[0];
	vec2 uv_d = valid ? vec2(1.0) - vec2(dot(foot, u_axis), dot(foot, v_axis)) / nn : vec2(0.5);
	float k2_plane2 = AREA_TEXTURE_FOOTPRINT * AREA_TEXTURE_FOOTPRINT * plane * plane;
	float var_d = valid ? k2_plane2 / (nn * sqrt(nn)) : 1.0; // No usable direction: the light's average.
	// Specular, without mapping the corners: a linear map keeps the uv of a point of the quad, so the
	// hit of the vector form factor f on M^-1 P, mapped by M, is the hit of M f on P; and M^-1 P has
	// the normal det(M^-1) M^T n and the plane value det(M^-1) plane, hence
	// k h / sqrt(A) = k |plane| sqrt(|det M|) / |M^T n|^(3/2) there.
	vec3 g = p_m * p_spec_vector;
	float gn = dot(g, n);
	bool valid_s = valid && gn * gn > 1e-18 * nn * dot(g, g);
	vec3 hit = g * (plane / gn) - p_q[0];
	vec2 uv_s = valid_s ? vec2(1.0) - vec2(dot(hit, u_axis), dot(hit, v_axis)) / nn : vec2(0.5);
	vec3 mn = n * p_m; // M^T n.
	float mnn = dot(mn, mn);
	float var_s = valid_s ? k2_plane2 * abs(determinant(p_m)) / (mnn * sqrt(mnn)) : 1.0;
	float w_specular = (p_specular.r + p_specular.g + p_specular.b) * (1.0 / 3.0);
	float w = p_diffuse * area_texture_diffuse_albedo + w_specular;
	float t = w > 0.0 ? w_specular / w : 0.0;
	vec2 d = uv_s - uv_d;
	float variance = mix(var_d, var_s, t) + t * (1.0 - t) * dot(d, d);
	return area_texture_filtered(p_light, mix(uv_d, uv_s, t), sqrt(variance));
}

#else // AREA_LIGHT_TEXTURE

// No textured light in this view: constant 1 (folded away by the compiler), no atlas binding.
vec3 area_texture_point(AreaLightData p_light, vec3 p_rel, vec3 p_ax, vec3 p_ay, vec2 p_half) {
	return vec3(1.0);
}

vec3 area_texture_mrp(AreaLightData p_light, vec2 p_coords, vec2 p_half, float p_sigma) {
	return vec3(1.0);
}

vec3 area_texture_ltc(AreaLightData p_light, vec3 p_q[4], mat3 p_m, vec3 p_spec_vector, float p_diffuse, vec3 p_specular) {
	return vec3(1.0);
}

#endif // AREA_LIGHT_TEXTURE

#endif // AREA_LIGHT_TEXTURE_INC_GLSL
