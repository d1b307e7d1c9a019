/**************************************************************************/
/*  area_light_mrp_inc.glsl                                               */
/**************************************************************************/
/* Rectangular area lights shaded with the most representative point     */
/* (MRP): thesis section 5.3, after Drobot 2014 ("Physically Based Area   */
/* Lights", GPU Pro 5, sections 1.3.3 and 1.3.4). One BRDF evaluation per */
/* lobe at a single point of the light, weighted by a solid angle.        */
/*                                                                        */
/* Diffuse (Drobot 1.3.3, thesis eqs. 5.2 and 5.3):                       */
/*   p_r = the point of the rectangle closest to the projection p_p of    */
/*         the shading point p on the light plane (maximum of 1/r^2);     */
/*   p_c = the point of the rectangle closest to p', the hit of the ray   */
/*         p + t n on the light plane (maximum of cos theta). When that   */
/*         ray does not reach the plane (n . n_l >= 0), eq. 5.2 gives the */
/*         direction p'' = (n_l x n) x n_l parallel to the plane instead  */
/*         (the limit of tilting the ray toward the plane);               */
/*   eq. 5.3: d = normalize(^pp_c + ^pp_r), the angle bisector;           */
/*   p_d = the rectangle point closest to the hit of p + t d.             */
/*   Drobot eq. 1.16 with the exact solid angle Omega of the rectangle:   */
/*   diffuse = L_e W Omega f_d(l_d) (n . l_d), f_d the material's Burley  */
/*   or Lambert term (thesis: Burley instead of Drobot's Lambert).        */
/* Specular (Drobot 1.3.4 as modified by the thesis):                     */
/*   p_s = the hit of the reflection ray r = reflect(-v, n) on the light  */
/*         plane, clamped to the rectangle (thesis: instead of the centre */
/*         of the cone/rectangle intersection);                           */
/*   cone apex angle alpha(r) = pi sqrt(r) / 4 + 0.1 (thesis eq. 5.5,     */
/*         r the perceptual roughness; replaces Drobot's eq. 1.18), solid */
/*         angle Omega_C = 2 pi (1 - cos(alpha / 2));                     */
/*   Omega_S = the part of Omega_C that falls on the light: Omega_C times */
/*         the fraction of the cone footprint's bounding box (an ellipse  */
/*         on the plane, semi-axes rho / |r . n_l| and rho, rho = t       */
/*         tan(alpha / 2)) covered by the rectangle, at most Omega;       */
/*   specular = L_e W F min(D V (n . l_s) Omega (Omega_S / Omega), 1):   */
/*         the point-light value at p_s times the light's solid           */
/*         angle, scaled by the solid-angle ratio Omega_S / Omega (thesis */
/*         section 5.3), and clamped so that D V cos integrated over the  */
/*         light never exceeds 1 (Drobot's energy-conserving              */
/*         normalisation; F applied after the clamp).                     */
/* Degenerate cases: on or behind the plane exactly 0; the reflection ray */
/* parallel to the plane or pointing away uses the rectangle point        */
/* farthest along r's in-plane direction (the limit of the hit point);    */
/* no division can reach 0 (every t has its denominator bounded).         */
/*                                                                        */
/* Includes area_light_common_inc.glsl (the contract's gate               */
/* area_light_rect_begin and the rectangle helpers). Needs, declared      */
/* before: brdf_inc.glsl.                                                 */

#ifndef AREA_LIGHT_MRP_INC_GLSL
#define AREA_LIGHT_MRP_INC_GLSL

#include "area_light_common_inc.glsl"

// Thesis eq. 5.5: the specular cone's apex (full opening) angle in radians from perceptual roughness.
float area_mrp_cone_angle(float p_roughness) {
	return M_PI * sqrt(clamp(p_roughness, 0.0, 1.0)) * 0.25 + 0.1;
}

// Rectangle coordinates (metres along the unit axes from the centre) of the point p_point of the plane.
vec2 area_mrp_plane_uv(AreaLightData p_light, vec3 p_ax, vec3 p_ay, vec3 p_point) {
	vec3 rel = p_point - p_light.position;
	return vec2(dot(rel, p_ax), dot(rel, p_ay));
}

vec3 area_mrp_uv_to_point(AreaLightData p_light, vec3 p_ax, vec3 p_ay, vec2 p_uv) {
	return p_light.position + p_ax * p_uv.x + p_ay * p_uv.y;
}

// Where the ray p + t dir meets the light plane, as rectangle coordinates (unclamped). A ray parallel to
// the plane or pointing away (dir . n_l >= -1e-4) is replaced by its limit: the plane projection of p
// pushed far along dir's in-plane direction (p_far metres). r_t: distance along the ray (or p_far).
vec2 area_mrp_plane_hit(AreaLightData p_light, vec3 p_ax, vec3 p_ay, vec3 p_vertex, float p_plane_dist, vec3 p_dir, float p_far, out float r_t) {
	float dn = dot(p_dir, p_light.normal);
	if (dn < -1e-4) {
		r_t = min(p_plane_dist / -dn, p_far);
		return area_mrp_plane_uv(p_light, p_ax, p_ay, p_vertex + p_dir * r_t);
	}
	r_t = p_far;
	vec2 uv_p = area_mrp_plane_uv(p_light, p_ax, p_ay, p_vertex);
	vec2 in_plane = vec2(dot(p_dir, p_ax), dot(p_dir, p_ay));
	float len = length(in_plane);
	return len > 1e-6 ? uv_p + in_plane * (p_far / len) : uv_p;
}

void light_process_area_mrp(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	AreaRectSetup lr;
	if (!area_light_rect_begin(p_light, p_vertex, lr)) {
		return;
	}
	vec3 nl = p_light.normal;
	float omega = area_light_solid_angle(p_light, p_vertex, lr.ax, lr.ay, lr.half_size);
	if (!(omega > 0.0)) {
		return;
	}
	// Far enough that clamping a point this far away gives the rectangle's limit point.
	float far = 1e3 * (lr.half_size.x + lr.half_size.y + lr.plane_dist + length(lr.to_vertex));

	// Diffuse: p_r, the rectangle point closest to the plane projection p_p of p (Drobot fig. 1.6).
	vec2 uv_r = area_light_clamp_uv(area_mrp_plane_uv(p_light, lr.ax, lr.ay, p_vertex), lr.half_size);
	vec3 dir_r = normalize(area_mrp_uv_to_point(p_light, lr.ax, lr.ay, uv_r) - p_vertex);
	// p_c: closest to p' (ray along n, Drobot fig. 1.5), or thesis eq. 5.2 when n does not reach the plane.
	vec3 dir_c = dir_r;
	if (dot(N, nl) < -1e-4) {
		float t;
		vec2 uv_c = area_light_clamp_uv(area_mrp_plane_hit(p_light, lr.ax, lr.ay, p_vertex, lr.plane_dist, N, far, t), lr.half_size);
		dir_c = normalize(area_mrp_uv_to_point(p_light, lr.ax, lr.ay, uv_c) - p_vertex);
	} else {
		vec3 p2 = cross(cross(nl, N), nl); // Thesis eq. 5.2: p'' parallel to the light plane.
		if (dot(p2, p2) > 1e-12) {
			dir_c = normalize(p2);
		}
	}
	// Thesis eq. 5.3: the angle bisector of the two directions, then its point on the rectangle (p_d).
	vec3 bisector = dir_c + dir_r;
	vec3 dir_d = dot(bisector, bisector) > 1e-12 ? normalize(bisector) : dir_r;
	float t_d;
	vec2 uv_d = area_light_clamp_uv(area_mrp_plane_hit(p_light, lr.ax, lr.ay, p_vertex, lr.plane_dist, dir_d, far, t_d), lr.half_size);
	vec3 l_d = normalize(area_mrp_uv_to_point(p_light, lr.ax, lr.ay, uv_d) - p_vertex);
	// Drobot eq. 1.16 with the exact solid angle; Burley or Lambert as for punctual lights.
	vec3 diffuse = vec3(0.0);
	vec3 unused_specular = vec3(0.0);
	// area_texture: Drobot eq. 1.24's lookup at p_d, footprint from the plane distance (area_light_texture_inc).
	vec3 tex_d = area_texture_mrp(p_light, uv_d, lr.half_size, AREA_TEXTURE_MRP_DIFFUSE_SIGMA * lr.plane_dist);
	light_compute(N, l_d, V, lr.radiance * omega * tex_d, 0.0, p_diffuse_mode, p_roughness, p_f0, p_f90, false, diffuse, unused_specular);
	r_diffuse += diffuse;

	if (!p_specular_enabled) {
		return;
	}
	// Specular: the reflection ray's point on the plane (or its limit), clamped to the rectangle.
	vec3 R = reflect(-V, N);
	float t_s;
	vec2 uv_hit = area_mrp_plane_hit(p_light, lr.ax, lr.ay, p_vertex, lr.plane_dist, R, far, t_s);
	vec2 uv_s = area_light_clamp_uv(uv_hit, lr.half_size);
	vec3 to_s = area_mrp_uv_to_point(p_light, lr.ax, lr.ay, uv_s) - p_vertex;
	vec3 l_s = normalize(to_s);
	float NoL = dot(N, l_s);
	if (NoL <= 0.0) {
		return;
	}
	// Cone of thesis eq. 5.5 and its footprint on the plane around the reflection hit.
	float half_angle = 0.5 * area_mrp_cone_angle(p_roughness);
	float omega_cone = 2.0 * M_PI * (1.0 - cos(half_angle));
	float rn = dot(R, nl);
	vec2 centre = uv_hit;
	float dist = t_s;
	float cos_hit = -rn;
	if (!(rn < -1e-4)) {
		// No hit: centre the footprint on the clamped point, seen along l_s.
		centre = uv_s;
		dist = length(to_s);
		cos_hit = -dot(l_s, nl);
	}
	float rho = dist * tan(half_angle);
	float stretch = rho / max(cos_hit, 0.05); // Semi-axis along the in-plane direction of the ray.
	vec2 major = vec2(dot(R, lr.ax), dot(R, lr.ay));
	float major_len = length(major);
	major = major_len > 1e-6 ? major / major_len : vec2(1.0, 0.0);
	vec2 extent = sqrt(stretch * stretch * major * major + rho * rho * major.yx * major.yx) + 1e-6;
	vec2 overlap = max(min(centre + extent, lr.half_size) - max(centre - extent, -lr.half_size), vec2(0.0));
	float covered = (overlap.x * overlap.y) / (4.0 * extent.x * extent.y);
	float omega_s = min(omega_cone * covered, omega);
	if (!(omega_s > 0.0)) {
		return;
	}

	// The engine's GGX lobe at l_s (brdf_inc.glsl, with light_compute's clamps). Roughness is floored at
	// 0.02: at alpha = 0 the NDF is 0/0 exactly in the mirror direction, which is where l_s lies.
	float roughness = max(p_roughness, 0.02);
	float alpha = roughness * roughness;
	vec3 H = normalize(V + l_s);
	float NoV = max(dot(N, V), 1e-4);
	float NoH = clamp(dot(N, H), 0.0, 1.0);
	float LoH = clamp(dot(l_s, H), 0.0, 1.0);
	float lobe = D_GGX(NoH, alpha) * V_SmithGGXCorrelatedFast(NoV, NoL, alpha) * NoL;
	// Point-light value times the light's solid angle, scaled by the ratio Omega_S / Omega (thesis 5.3);
	// D V cos over any part of the sphere integrates to at most 1 (energy conservation).
	float integral = min(lobe * omega * (omega_s / omega), 1.0);
	// area_texture: Drobot eq. 1.28's lookup at p_s, footprint from the projected importance cone (rho).
	vec3 tex_s = area_texture_mrp(p_light, area_light_clamp_uv(centre, lr.half_size), lr.half_size, 0.5 * rho);
	r_specular += lr.radiance * p_light.specular_amount * integral * F_Schlick(p_f0, p_f90, LoH) * tex_s;
}

#endif // AREA_LIGHT_MRP_INC_GLSL
