/**************************************************************************/
/*  area_light_ltc_inc.glsl                                               */
/**************************************************************************/
/* Rectangular area lights shaded with linearly transformed cosines       */
/* (Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light       */
/* Shading with Linearly Transformed Cosines"; thesis section 5.4).       */
/*                                                                        */
/* Reflected radiance of one light at a shading point (contract units):   */
/*   L_o = L_e W(d) [ albedo * FF_cos(P) + spec * FF_cos(M^-1 P) * F ]    */
/* P = the rectangle seen from the point in a frame with z = N,           */
/* FF_cos(Q) = (1 / pi) integral over Q (clipped to z >= 0) of cos dl,    */
/* i.e. the cosine form factor of the polygon (Lambert 1760: a sum of     */
/* edge integrals), F = f0 fn + (f90 - f0) fg (thesis eq. 5.10) with fg   */
/* moved to the Schlick weight of the lit part of the lobe                */
/* (ltc_polygon_fresnel, issue #18).                                      */
/*                                                                        */
/* Diffuse: the EXACT Lambert integral (M = identity). Burley materials   */
/* use the same Lambert integral (there is no closed form for Burley's    */
/* view/light-dependent retro-reflection over a polygon; the difference   */
/* is a few % at grazing angles and roughness 1, as Godot's own Burley vs */
/* Lambert).                                                              */
/*                                                                        */
/* Horizon: the polygon is CLIPPED (Sutherland-Hodgman against one plane  */
/* at a time), exact, unlike the sphere form-factor approximation of      */
/* Heitz 2017. ONE clip in the shading frame to the receiver's plane      */
/* z >= 0 serves both lobes (ltc_rect_form_factors): it is the diffuse    */
/* horizon, and the surface horizon of the specular lobe (issue #18: at   */
/* grazing views D = D_o(M^-1 l) has mass below the receiver's plane,     */
/* where the BRDF times cos is 0; a light crossing that plane was 1.24x   */
/* too bright on a floor seen at 10 degrees). The clipped polygon mapped  */
/* by M^-1 is clipped again to the cosine space's z >= 0 only where a     */
/* mapped vertex is below it. A rectangle wholly above the receiver's     */
/* plane is not clipped at all (the fast path: 4 corners, 2 integrals;    */
/* a real branch on GPUs. llvmpipe runs every side of an if under a lane  */
/* mask and a loop only while a lane is in it, so there the savings come  */
/* from running each integral once, looped to the vertex count).          */
/*                                                                        */
/* Edge integral precision (thesis section 5.4.4): for unit vectors a, b  */
/* the edge term is theta * normalize(a x b).z. Near-antipodal a, b make  */
/* a x b tiny and its direction noisy; for such edges (dot < -0.5, i.e.   */
/* wider than 120 degrees) the circle's normal comes from a and the       */
/* projected midpoint m instead: the point of the 3D segment closest to   */
/* the shading point, which lies on the spherical edge between a and b    */
/* (thesis fig. 5.20) more than 30 degrees from a. The thesis integrates  */
/* the two arcs (a, m) and (m, b); they share the circle, so one normal   */
/* and the whole angle theta = atan(|a x b|, a.b) (accurate over the      */
/* whole range in absolute terms; acos is not near +-1) give the same     */
/* sum for one atan instead of two.                                       */
/* Heitz et al.'s original edge integral (a x b).z * theta / sin(theta)   */
/* with theta = acos(a.b), no split, explodes there: the stress test      */
/* tests/servers/test_area_light_ltc_precision.cpp evaluates it in        */
/* float32 beside this shader.                                            */
/*                                                                        */
/* Methods (defines set by the per-method shader versions):               */
/*   AREA_METHOD_LTC_POLYNOMIAL: the matrix and Fresnel terms come from   */
/*     degree-5 polynomials (thesis section 5.4.3, appendix C) on 2 x 2   */
/*     patches of (roughness, theta_v) blended by smoothsteps, fitted by  */
/*     `godot-area ltc-fit --polynomial` into ltc_poly_coeffs_inc.glsl    */
/*     (compiled-in constants, no binding). Without it no polynomial      */
/*     code is compiled.                                                  */
/*   The LUT fetch is compiled unless only AREA_METHOD_LTC_POLYNOMIAL is  */
/*     defined (with both AREA_METHOD_LTC and AREA_METHOD_LTC_POLYNOMIAL, */
/*     p_polynomial picks at run time).                                   */
/*   AREA_METHOD_LTC_2LOBE: the two-lobe LTC (issue #18,                  */
/*     modules/ltc_fit/ltc_two_lobe.h), light_process_area_ltc_2lobe,     */
/*     reading layers 2-5 of the LUT texture; compiled only with it.      */
/* Entry points: light_process_area_ltc(..., bool p_polynomial, ...) and  */
/* light_process_area(...) (= the LUT path, for existing callers).        */
/*                                                                        */
/* Needs, declared before inclusion: light_data_inc.glsl (AreaLightData), */
/* brdf_inc.glsl (M_PI), and (LUT path only) the bindings ltc_lut_texture */
/* (texture2DArray made by LTCLutRD) and ltc_lut_sampler (linear, clamp). */

#ifndef AREA_LIGHT_LTC_INC_GLSL
#define AREA_LIGHT_LTC_INC_GLSL

#include "area_light_common_inc.glsl"

// area_texture fetches (vec3(1.0) unless AREA_LIGHT_TEXTURE): included here so every includer has them.
#include "area_light_texture_inc.glsl"

#if defined(AREA_METHOD_LTC_POLYNOMIAL)
#define AREA_LTC_HAS_POLYNOMIAL
#endif
#if !defined(AREA_METHOD_LTC_POLYNOMIAL) || defined(AREA_METHOD_LTC) || defined(AREA_METHOD_LTC_2LOBE)
#define AREA_LTC_HAS_LUT
#endif

// Cells per side of the LUT. Must match LTC_LUT_SIZE in servers/rendering/renderer_rd/ltc_lut_data.inc.
#define LTC_LUT_SIZE 64.0

// Edge from p_v1 to p_v2 (points of the clipped polygon relative to the shading point, not unit), with
// p_a, p_b their unit directions (normalised once per vertex by the caller). Returns the edge's term of
// the vector form factor, theta * n with n the unit normal of the edge's great circle (Arvo 1994); its z
// is the term of the cosine form factor. Callers that read only z let the compiler drop x and y.
vec3 ltc_edge_integral(vec3 p_v1, vec3 p_v2, vec3 p_a, vec3 p_b) {
	// theta * n.z with theta = atan(|a x b|, a.b): accurate in absolute terms over the whole range (acos is
	// not near +-1). Only the direction n of the great circle is ill-conditioned for near-antipodal a, b
	// (a x b tiny and noisy), so for an edge wider than 120 degrees (thesis section 5.4.4) it is taken from
	// the projected midpoint m instead: the point of the 3D segment closest to the shading point, which
	// lies on the arc between a and b (thesis fig. 5.20). The triangle (origin, v1, v2) then has its obtuse
	// angle at the origin, so m is strictly inside the segment and more than 30 degrees from a: |a x m| >=
	// |m| / 2, well conditioned. Same result as the thesis' two arcs (a, m) + (m, b), which share the
	// circle, for one atan instead of two (a software rasterizer evaluates both sides of the branch).
	vec3 c = cross(p_a, p_b);
	float s = length(c);
	float theta = atan(s, dot(p_a, p_b));
	if (!(dot(p_a, p_b) > -0.5)) {
		vec3 e = p_v2 - p_v1;
		float t = clamp(-dot(p_v1, e) / max(dot(e, e), 1e-30), 0.0, 1.0);
		vec3 m = p_v1 + e * t;
		c = cross(p_a, m / max(length(m), 1e-30));
		s = length(c);
	}
	return s < 1e-12 ? vec3(0.0) : c * (theta / s); // 0 for a zero-length edge (a == b).
}

// Slot p_i of a clipped polygon of at most 6 vertices (c0..c5 are named, not an array: no indexed local
// memory, which a software rasterizer handles lane by lane).
vec3 ltc_clip_pick(int p_i, vec3 c0, vec3 c1, vec3 c2, vec3 c3, vec3 c4, vec3 c5) {
	return p_i == 0 ? c0 : (p_i == 1 ? c1 : (p_i == 2 ? c2 : (p_i == 3 ? c3 : (p_i == 4 ? c4 : c5))));
}

// Appends p_v as vertex n of the clipped polygon when p_emit and n < 6 (Sutherland-Hodgman output).
void ltc_clip_emit(bool p_emit, vec3 p_v, inout int n, inout vec3 c0, inout vec3 c1, inout vec3 c2, inout vec3 c3, inout vec3 c4, inout vec3 c5) {
	if (!p_emit || n >= 6) {
		return;
	}
	c0 = n == 0 ? p_v : c0;
	c1 = n == 1 ? p_v : c1;
	c2 = n == 2 ? p_v : c2;
	c3 = n == 3 ? p_v : c3;
	c4 = n == 4 ? p_v : c4;
	c5 = n == 5 ? p_v : c5;
	n++;
}

// Sutherland-Hodgman clipping of the polygon p_n, p0..p4 (at most 5 vertices) to z >= 0: r_n (at most 6)
// vertices r0..r5. A quad gives at most 5.
void ltc_clip_polygon(int p_n, vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec3 p4, out int r_n, out vec3 r0, out vec3 r1, out vec3 r2, out vec3 r3, out vec3 r4, out vec3 r5) {
	r0 = vec3(0.0);
	r1 = vec3(0.0);
	r2 = vec3(0.0);
	r3 = vec3(0.0);
	r4 = vec3(0.0);
	r5 = vec3(0.0);
	r_n = 0;
	for (int i = 0; i < min(p_n, 5); i++) {
		vec3 a = ltc_clip_pick(i, p0, p1, p2, p3, p4, p4);
		vec3 b = i + 1 < p_n ? ltc_clip_pick(i + 1, p0, p1, p2, p3, p4, p4) : p0;
		bool a_in = a.z > 0.0;
		bool b_in = b.z > 0.0;
		ltc_clip_emit(a_in, a, r_n, r0, r1, r2, r3, r4, r5);
		vec3 p = mix(a, b, a.z / (a.z - b.z));
		p.z = 0.0;
		ltc_clip_emit(a_in != b_in, p, r_n, r0, r1, r2, r3, r4, r5);
	}
}

// Vector form factor sum theta_i n_i of the closed polygon p_n, c0..c5 (3 to 6 vertices, every one
// with z >= 0: already clipped), in the polygon's winding. abs(.z) / (2 pi) is the cosine form factor
// (Lambert: 1/2 sum theta_i n.gamma_i, divided by pi), and the vector, turned to z >= 0, points along
// the mean direction of the clamped cosine over the polygon (Arvo 1994).
vec3 ltc_polygon_vector(int p_n, vec3 c0, vec3 c1, vec3 c2, vec3 c3, vec3 c4, vec3 c5) {
	// The edges in order, each vertex picked and normalised once. The trip count is the lanes' largest
	// p_n (4 for a rectangle above the horizon): a software rasterizer runs a loop body only while some
	// lane is in it, but every side of an if.
	vec3 sum = vec3(0.0);
	vec3 first = c0 / max(length(c0), 1e-30);
	vec3 v1 = c0;
	vec3 a = first;
	for (int i = 0; i < p_n; i++) {
		bool last = i + 1 >= p_n;
		vec3 v2 = last ? c0 : ltc_clip_pick(i + 1, c0, c1, c2, c3, c4, c5);
		vec3 b = last ? first : v2 / max(length(v2), 1e-30);
		sum += ltc_edge_integral(v1, v2, a, b);
		v1 = v2;
		a = b;
	}
	return sum;
}

// (1 / pi) integral of cos over the spherical projection of the closed polygon p_n, c0..c5 (as
// ltc_polygon_vector), i.e. the cosine form factor. In [0, 1]; independent of the winding.
float ltc_polygon_integral(int p_n, vec3 c0, vec3 c1, vec3 c2, vec3 c3, vec3 c4, vec3 c5) {
	return abs(ltc_polygon_vector(p_n, c0, c1, c2, c3, c4, c5).z) * (0.5 / M_PI);
}

// Cosine form factor of the quad p_q (a planar convex polygon not containing the origin) clipped to
// z >= 0, i.e. the integral of the normalised clamped cosine D_o = max(z, 0) / pi over it. In [0, 1].
float ltc_polygon_form_factor(vec3 p_q[4]) {
	int n;
	vec3 c0, c1, c2, c3, c4, c5;
	ltc_clip_polygon(4, p_q[0], p_q[1], p_q[2], p_q[3], p_q[3], n, c0, c1, c2, c3, c4, c5);
	return n < 3 ? 0.0 : ltc_polygon_integral(n, c0, c1, c2, c3, c4, c5);
}

// Diffuse and specular form factors of the rectangle p_q (receiver frame, z = N) with ONE clip
// (Heitz et al. 2016, section 4: the integral of the LTC D = D_o(M^-1 l) over P is that of D_o over
// M^-1 P, so the specular polygon is the shading-frame polygon mapped by M^-1).
// Clipping commutes with a linear map when the plane is mapped with it: M^-1 sends the segment
// mix(a, b, t) to mix(M^-1 a, M^-1 b, t), so the point where an edge leaves the half-space {n.x >= 0} is
// sent to where the mapped edge leaves its image {(M^T n).y >= 0}. Two planes bound the lit part:
// - the receiver's plane z >= 0: the whole diffuse horizon (M = identity) and the surface horizon of the
//   specular lobe (no lobe mass below the surface, issue #18). Clipped ONCE here, in the shading frame,
//   and the clipped polygon serves both lobes;
// - the cosine space's horizon z_o >= 0 of the specular lobe, in the shading frame a z - d x >= 0: a
//   different plane (d != 0), crossed only by polygons reaching near the horizon on the side the lobe
//   leans to. The mapped polygon is clipped to it only where one of its vertices has z_o < 0 (a real
//   branch; its image under M^-1 is exactly z_o >= 0, so clipping there is the same clip).
// Fast path: a rectangle wholly above the receiver's plane (every corner z > 0, the common case) is not
// clipped at all: its four corners are the diffuse polygon, and M^-1 of them the specular one.
// ltc_rect_clip is that shared clip (r_n < 3: wholly below the receiver's plane, nothing is lit; the
// two-lobe LTC maps its result by both lobes' M^-1), ltc_specular_integral one lobe's integral over it.
// r_specular is left 0 unless p_specular_enabled. r_specular_vector: the specular polygon's vector form
// factor in the cosine space, turned to z >= 0 (its direction mapped by M is the mean direction of the
// lobe over the light), 0 where r_specular is 0.
void ltc_rect_clip(vec3 p_q[4], out int r_n, out vec3 c0, out vec3 c1, out vec3 c2, out vec3 c3, out vec3 c4, out vec3 c5) {
	r_n = 4;
	c0 = p_q[0];
	c1 = p_q[1];
	c2 = p_q[2];
	c3 = p_q[3];
	c4 = p_q[3];
	c5 = p_q[3];
	if (!(min(min(p_q[0].z, p_q[1].z), min(p_q[2].z, p_q[3].z)) > 0.0)) {
		ltc_clip_polygon(4, p_q[0], p_q[1], p_q[2], p_q[3], p_q[3], r_n, c0, c1, c2, c3, c4, c5);
	}
}

// The specular integral of one LTC (p_m_inv) over the polygon p_n, c0..c4 that ltc_rect_clip left
// (at least 3 vertices, z >= 0): r_specular and r_specular_vector as ltc_rect_form_factors gives them.
void ltc_specular_integral(int p_n, vec3 c0, vec3 c1, vec3 c2, vec3 c3, vec3 c4, mat3 p_m_inv, out float r_specular, out vec3 r_specular_vector) {
	r_specular = 0.0;
	r_specular_vector = vec3(0.0);
	vec3 s0 = p_m_inv * c0, s1 = p_m_inv * c1, s2 = p_m_inv * c2, s3 = p_m_inv * c3, s4 = p_m_inv * c4;
	// Slots past n hold a copy of a corner (fast path) or 0 (after a clip): neither turns z_min negative.
	float z_min = min(min(min(s0.z, s1.z), min(s2.z, s3.z)), s4.z);
	int m = p_n;
	vec3 d0 = s0, d1 = s1, d2 = s2, d3 = s3, d4 = s4, d5 = s4;
	if (z_min < 0.0) {
		ltc_clip_polygon(p_n, s0, s1, s2, s3, s4, m, d0, d1, d2, d3, d4, d5);
	}
	if (m >= 3) {
		vec3 v = ltc_polygon_vector(m, d0, d1, d2, d3, d4, d5);
		r_specular_vector = v.z < 0.0 ? -v : v;
		r_specular = r_specular_vector.z * (0.5 / M_PI);
	}
}

void ltc_rect_form_factors(vec3 p_q[4], bool p_specular_enabled, mat3 p_m_inv, out float r_diffuse, out float r_specular, out vec3 r_specular_vector) {
	r_diffuse = 0.0;
	r_specular = 0.0;
	r_specular_vector = vec3(0.0);
	int n;
	vec3 c0, c1, c2, c3, c4, c5;
	ltc_rect_clip(p_q, n, c0, c1, c2, c3, c4, c5);
	if (n < 3) {
		return; // Wholly below the receiver's plane: neither lobe sees it.
	}
	r_diffuse = ltc_polygon_integral(n, c0, c1, c2, c3, c4, c5);
	if (p_specular_enabled) {
		ltc_specular_integral(n, c0, c1, c2, c3, c4, p_m_inv, r_specular, r_specular_vector);
	}
}

// Schlick's weight (1 - v.h)^5 (thesis eq. 2.4) of the unit light direction p_l for the unit view p_v.
float ltc_schlick_weight(vec3 p_v, vec3 p_l) {
	vec3 h = p_v + p_l;
	float m = clamp(1.0 - dot(p_v, h) * inversesqrt(max(dot(h, h), 1e-30)), 0.0, 1.0);
	float m2 = m * m;
	return m2 * m2 * m;
}

// The Fresnel integral of the specular lobe over the light (issue #18). Thesis eq. 5.10 takes the lobe's
// Schlick weight averaged over the whole hemisphere, fg / fn; a light that covers only part of the lobe
// sees the weight of that part, which at grazing views differs a lot (the mirror direction of a TV over
// a floor seen at 10 degrees has (1 - v.h)^5 = 0.39, the whole lobe's average far less: LTC was 8-16 %
// too dark there, from Fresnel alone). The weight is taken at the polygon's mean direction (its vector
// form factor mapped by M, from p_vector), exact for a small light, plus the gap between the lobe's mean
// weight fg / fn and the weight at the lobe's own mean direction (the axis M z = (b, 0, e)) in proportion
// to the share of the lobe the light covers (p_coverage, the LTC integral), so a light covering the whole
// lobe keeps eq. 5.10 exactly. p_v: the view in the fitter's frame; p_t0 = (a, b, c, d), p_t1 = (e, fn,
// fg, 0). Returns the effective (fn, fg), fg in [0, fn].
vec2 ltc_polygon_fresnel(vec3 p_v, vec4 p_t0, vec4 p_t1, vec3 p_vector, float p_coverage) {
	vec3 l_mean = vec3(p_t0.x * p_vector.x + p_t0.y * p_vector.z, p_t0.z * p_vector.y, p_t0.w * p_vector.x + p_t1.x * p_vector.z);
	vec3 axis = vec3(p_t0.y, 0.0, p_t1.x);
	float ll = dot(l_mean, l_mean);
	if (!(ll > 1e-30)) {
		return p_t1.yz;
	}
	float w_mean = ltc_schlick_weight(p_v, l_mean * inversesqrt(ll));
	float w_axis = ltc_schlick_weight(p_v, axis * inversesqrt(max(dot(axis, axis), 1e-30)));
	return vec2(p_t1.y, clamp(p_t1.y * w_mean + p_coverage * (p_t1.z - p_t1.y * w_axis), 0.0, p_t1.y));
}

#ifdef AREA_LTC_HAS_LUT

// LUT lookup, exact formula of the ltc_lut_data.inc header: u = (roughness, sqrt(1 - NoV)) mapped to
// texel centres. r_t0 = (a, b, c, d), r_t1 = (e, fn, fg, 0).
void ltc_fetch_lut(float p_roughness, float p_NoV, out vec4 r_t0, out vec4 r_t1) {
	vec2 uv = vec2(clamp(p_roughness, 0.0, 1.0), sqrt(1.0 - clamp(p_NoV, 0.0, 1.0)));
	uv = uv * ((LTC_LUT_SIZE - 1.0) / LTC_LUT_SIZE) + 0.5 / LTC_LUT_SIZE;
	r_t0 = textureLod(sampler2DArray(ltc_lut_texture, ltc_lut_sampler), vec3(uv, 0.0), 0.0);
	r_t1 = textureLod(sampler2DArray(ltc_lut_texture, ltc_lut_sampler), vec3(uv, 1.0), 0.0);
}

#endif // AREA_LTC_HAS_LUT

#ifdef AREA_LTC_HAS_POLYNOMIAL

// LTC_POLY_* seams and ltc_poly_patch_0..3 (generated by `godot-area ltc-fit --polynomial`; see
// modules/ltc_fit/ltc_polynomial.h): each patch function returns (a, b, c, d) and (e, fn, fg, 0).
#include "ltc_poly_coeffs_inc.glsl"

// The LUT's components from the polynomials (thesis section 5.4.3): x = 1 + roughness (perceptual,
// the LUT's axis), y = 1 + theta_v; the patches are blended with smoothstep weights across
// theta_v = LTC_POLY_SEAM_THETA and roughness = LTC_POLY_SEAM_ROUGHNESS (sum 1, no seam), and a
// patch is evaluated only where its weight is not 0. Guarded so that M stays invertible: a, c, e >=
// the table's smallest a (2 * alpha floor), a e - b d > 0, fn, fg in [0, 1].
void ltc_fetch_polynomial(float p_roughness, float p_NoV, out vec4 r_t0, out vec4 r_t1) {
	float r = clamp(p_roughness, 0.0, 1.0);
	float theta = acos(clamp(p_NoV, 0.0, 1.0));
	float x = 1.0 + r;
	float y = 1.0 + theta;
	float wt = smoothstep(LTC_POLY_SEAM_THETA - LTC_POLY_BLEND_THETA, LTC_POLY_SEAM_THETA + LTC_POLY_BLEND_THETA, theta);
	float wr = smoothstep(LTC_POLY_SEAM_ROUGHNESS - LTC_POLY_BLEND_ROUGHNESS, LTC_POLY_SEAM_ROUGHNESS + LTC_POLY_BLEND_ROUGHNESS, r);
	vec4 t0 = vec4(0.0);
	vec4 t1 = vec4(0.0);
	vec4 p0;
	vec4 p1;
	float w = (1.0 - wt) * (1.0 - wr);
	if (w > 0.0) {
		ltc_poly_patch_0(x, y, p0, p1);
		t0 += w * p0;
		t1 += w * p1;
	}
	w = (1.0 - wt) * wr;
	if (w > 0.0) {
		ltc_poly_patch_1(x, y, p0, p1);
		t0 += w * p0;
		t1 += w * p1;
	}
	w = wt * (1.0 - wr);
	if (w > 0.0) {
		ltc_poly_patch_2(x, y, p0, p1);
		t0 += w * p0;
		t1 += w * p1;
	}
	w = wt * wr;
	if (w > 0.0) {
		ltc_poly_patch_3(x, y, p0, p1);
		t0 += w * p0;
		t1 += w * p1;
	}
	float a = max(t0.x, 2e-4);
	float b = t0.y;
	float c = max(t0.z, 2e-4);
	float d = t0.w;
	float e = max(t1.x, 2e-4);
	if (a * e - b * d < 1e-8) {
		b = 0.0;
		d = 0.0;
	}
	r_t0 = vec4(a, b, c, d);
	r_t1 = vec4(e, clamp(t1.y, 0.0, 1.0), clamp(t1.z, 0.0, 1.0), 0.0);
}

#endif // AREA_LTC_HAS_POLYNOMIAL

// The light's rectangle in the frame of the LUT fit (ltc_lut_data.inc): z = N, x = normalize(V - N NoV),
// y = z cross x. Returns NoV.
float ltc_rect_in_frame(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, out vec3 r_q[4]) {
	float NoV = dot(N, V);
	vec3 tx = V - N * NoV;
	if (dot(tx, tx) < 1e-10) {
		// V == N: the lobe is isotropic (b = d = 0, a = c), any tangent works.
		tx = abs(N.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
		tx -= N * dot(N, tx);
	}
	vec3 T1 = normalize(tx);
	vec3 T2 = cross(N, T1);
	mat3 local_from_view = transpose(mat3(T1, T2, N));

	vec3 base = p_light.position - p_vertex;
	vec3 hx = p_light.half_axis_x;
	vec3 hy = p_light.half_axis_y;
	r_q[0] = local_from_view * (base - hx - hy);
	r_q[1] = local_from_view * (base + hx - hy);
	r_q[2] = local_from_view * (base + hx + hy);
	r_q[3] = local_from_view * (base - hx + hy);
	return NoV;
}

// M^-1 of the stored M = [[a, 0, b], [0, c, 0], [d, 0, e]] (row-major; thesis eqs. 5.7-5.8), p_t0 =
// (a, b, c, d), p_e = e. a e - b d > 0 in every cell (ltc_lut_data.inc, ltc_lut_2lobe_data.inc) and in the
// guarded polynomials, so s is finite. We stay in the fitter's frame, so the Godot-frame conjugation of
// eq. 5.9 is not needed. GLSL matrices are column-major: columns of M^-1.
mat3 ltc_inverse(vec4 p_t0, float p_e) {
	float s = 1.0 / (p_t0.x * p_e - p_t0.y * p_t0.w);
	return mat3(vec3(s * p_e, 0.0, -s * p_t0.w), vec3(0.0, 1.0 / p_t0.z, 0.0), vec3(-s * p_t0.y, 0.0, s * p_t0.x));
}

// Adds one area light shaded with LTC. Vectors in view space; N, V unit; p_vertex the shading point.
// r_diffuse accumulates irradiance-weighted diffuse BRDF without albedo (as light_compute does),
// r_specular reflected specular radiance. p_polynomial: take the LTC matrix from the polynomials
// instead of the LUT (only where both are compiled; otherwise the compiled one is used).
void light_process_area_ltc(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, bool p_polynomial, inout vec3 r_diffuse, inout vec3 r_specular) {
	AreaRectSetup lr;
	if (!area_light_rect_begin(p_light, p_vertex, lr)) {
		return;
	}

	vec3 q[4];
	float NoV = ltc_rect_in_frame(p_light, p_vertex, N, V, q);

	vec4 t0 = vec4(1.0, 0.0, 1.0, 0.0); // a, b, c, d
	vec4 t1 = vec4(1.0, 0.0, 0.0, 0.0); // e, fn, fg, 0
	if (p_specular_enabled) {
#if defined(AREA_LTC_HAS_POLYNOMIAL) && defined(AREA_LTC_HAS_LUT)
		if (p_polynomial) {
			ltc_fetch_polynomial(p_roughness, NoV, t0, t1);
		} else {
			ltc_fetch_lut(p_roughness, NoV, t0, t1);
		}
#elif defined(AREA_LTC_HAS_POLYNOMIAL)
		ltc_fetch_polynomial(p_roughness, NoV, t0, t1);
#else
		ltc_fetch_lut(p_roughness, NoV, t0, t1);
#endif
	}
	mat3 m_inv = ltc_inverse(t0, t1.x);

	// Diffuse: the exact Lambert integral, (1/pi) L_e integral cos = L_e FF (albedo applied later);
	// specular: the LTC's integral over the same clipped polygon mapped by M^-1.
	float diffuse;
	float spec;
	vec3 spec_vector;
	ltc_rect_form_factors(q, p_specular_enabled, m_inv, diffuse, spec, spec_vector);
	vec3 F = vec3(0.0);
	if (p_specular_enabled) {
		// Thesis eq. 5.10 with the Fresnel weight of the lit part of the lobe (ltc_polygon_fresnel).
		vec2 fresnel = ltc_polygon_fresnel(vec3(sqrt(max(1.0 - NoV * NoV, 0.0)), 0.0, NoV), t0, t1, spec_vector, spec);
		F = p_f0 * fresnel.x + (vec3(p_f90) - p_f0) * fresnel.y;
	}
	// Texture (area_light_texture_inc.glsl; vec3(1.0) and no work without AREA_LIGHT_TEXTURE): one fetch
	// for both lobes, weighted by their radiance.
	vec3 tex = area_texture_ltc(p_light, q, mat3(vec3(t0.x, 0.0, t0.w), vec3(0.0, t0.z, 0.0), vec3(t0.y, 0.0, t1.x)), spec_vector, diffuse, spec * p_light.specular_amount * F);
	r_diffuse += lr.radiance * diffuse * tex;
	if (p_specular_enabled) {
		r_specular += lr.radiance * p_light.specular_amount * spec * F * tex;
	}
}

#ifdef AREA_METHOD_LTC_2LOBE
// The two-lobe LTC (issue #18; the model and its fit: modules/ltc_fit/ltc_two_lobe.h). The lobe is
// w1 D_M1 + w2 D_M2: the rectangle is clipped once (ltc_rect_clip), mapped by both M^-1 and integrated
// twice; each lobe's integral gets the Fresnel weight of its own lit part (ltc_polygon_fresnel with
// that lobe's matrix and the shared fn, fg). Layers 2-5 of ltc_lut_texture hold the table
// (ltc_lut_2lobe_data.inc): (a1, b1, c1, d1), (e1, fn, fg, w1), (a2, b2, c2, d2), (e2, w2, 0, 0).
void ltc_fetch_lut_2lobe(float p_roughness, float p_NoV, out vec4 r_t0, out vec4 r_t1, out vec4 r_t2, out vec4 r_t3) {
	vec2 uv = vec2(clamp(p_roughness, 0.0, 1.0), sqrt(1.0 - clamp(p_NoV, 0.0, 1.0)));
	uv = uv * ((LTC_LUT_SIZE - 1.0) / LTC_LUT_SIZE) + 0.5 / LTC_LUT_SIZE;
	r_t0 = textureLod(sampler2DArray(ltc_lut_texture, ltc_lut_sampler), vec3(uv, 2.0), 0.0);
	r_t1 = textureLod(sampler2DArray(ltc_lut_texture, ltc_lut_sampler), vec3(uv, 3.0), 0.0);
	r_t2 = textureLod(sampler2DArray(ltc_lut_texture, ltc_lut_sampler), vec3(uv, 4.0), 0.0);
	r_t3 = textureLod(sampler2DArray(ltc_lut_texture, ltc_lut_sampler), vec3(uv, 5.0), 0.0);
}

// light_process_area_ltc (same arguments and units) with the two-lobe table.
void light_process_area_ltc_2lobe(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	AreaRectSetup lr;
	if (!area_light_rect_begin(p_light, p_vertex, lr)) {
		return;
	}
	vec3 q[4];
	float NoV = ltc_rect_in_frame(p_light, p_vertex, N, V, q);
	int n;
	vec3 c0, c1, c2, c3, c4, c5;
	ltc_rect_clip(q, n, c0, c1, c2, c3, c4, c5);
	if (n < 3) {
		return; // Wholly below the receiver's plane.
	}
	float diffuse = ltc_polygon_integral(n, c0, c1, c2, c3, c4, c5);
	vec3 spec = vec3(0.0);
	// The texture (area_light_texture_inc.glsl, vec3(1.0) without AREA_LIGHT_TEXTURE): one fetch for the
	// diffuse lobe and the brighter specular lobe (its M and vector form factor), weighted by their radiance.
	mat3 tex_m = mat3(1.0);
	vec3 tex_vector = vec3(0.0);
	if (p_specular_enabled) {
		vec4 t0, t1, t2, t3;
		ltc_fetch_lut_2lobe(p_roughness, NoV, t0, t1, t2, t3);
		vec3 v = vec3(sqrt(max(1.0 - NoV * NoV, 0.0)), 0.0, NoV);
		float brightest = -1.0;
		for (int lobe = 0; lobe < 2; lobe++) {
			vec4 m0 = lobe == 0 ? t0 : t2;
			vec4 m1 = lobe == 0 ? t1 : vec4(t3.x, t1.y, t1.z, t3.y); // (e, fn, fg, w)
			mat3 m_inv = ltc_inverse(m0, m1.x);
			float integral;
			vec3 vector;
			ltc_specular_integral(n, c0, c1, c2, c3, c4, m_inv, integral, vector);
			vec2 fresnel = ltc_polygon_fresnel(v, m0, m1, vector, integral);
			vec3 lobe_spec = (m1.w * integral) * (p_f0 * fresnel.x + (vec3(p_f90) - p_f0) * fresnel.y);
			spec += lobe_spec;
			float weight = dot(lobe_spec, vec3(1.0));
			if (weight > brightest) {
				brightest = weight;
				tex_m = mat3(vec3(m0.x, 0.0, m0.w), vec3(0.0, m0.z, 0.0), vec3(m0.y, 0.0, m1.x));
				tex_vector = vector;
			}
		}
	}
	vec3 tex = area_texture_ltc(p_light, q, tex_m, tex_vector, diffuse, spec * p_light.specular_amount);
	r_diffuse += lr.radiance * diffuse * tex;
	r_specular += lr.radiance * p_light.specular_amount * spec * tex;
}
#endif // AREA_METHOD_LTC_2LOBE

#ifdef AREA_LTC_HAS_LUT
// The LUT entry point (existing callers): light_process_area_ltc without the polynomials.
void light_process_area(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	light_process_area_ltc(p_light, p_vertex, N, V, p_roughness, p_f0, p_f90, p_specular_enabled, false, r_diffuse, r_specular);
}
#endif

#endif // AREA_LIGHT_LTC_INC_GLSL
