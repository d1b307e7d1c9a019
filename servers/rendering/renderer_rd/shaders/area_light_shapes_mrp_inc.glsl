/**************************************************************************/
/*  area_light_shapes_mrp_inc.glsl                                        */
/**************************************************************************/
/* Disk, sphere and tube lights shaded with the most representative point */
/* (Drobot 2014, "Physically Based Area Lights", GPU Pro 5, sections      */
/* 1.3.3-1.3.4 and 1.4 "sphere, disk, rectangle"; thesis section 5.3 for  */
/* the cone angle and the solid-angle weighting), as the rectangle's MRP  */
/* (area_light_mrp_inc.glsl) with the shape's closest points and solid    */
/* angles:                                                                */
/*   SPHERE diffuse: Drobot 1.4 notes the sphere's diffuse integral has a */
/*          closed form: the horizon-clipped cap form factor (Snyder), so */
/*          the BRDF is evaluated once, at the point of the cap closest   */
/*          to n (Drobot's p_c), weighted so that Lambert is exact;       */
/*          specular: the point of the sphere closest to the reflection   */
/*          ray, weighted by Omega_S, the solid angle shared by the       */
/*          specular cone (thesis eq. 5.5) and the light's cap, from Oat  */
/*          and Sander's smoothstep cap intersection (Drobot eq. 1.21 on   */
/*          the sphere of directions: "spheres prove to be easily solvable */
/*          working exclusively with solid angles", Drobot 1.3.4);        */
/*   DISK   diffuse: Drobot 1.3.3's p_r, p_c and their bisector p_d with  */
/*          the ellipse's closest point (radial clamp), weighted by the   */
/*          disk's form factor (its equivalent cap, Heitz and Hill 2017)  */
/*          over n.l_d, as the sphere (exact for Lambert); specular: the  */
/*          reflection ray's hit clamped to the ellipse, Omega_S from the */
/*          disk-disk intersection of Drobot eq. 1.21 (the cone's         */
/*          footprint as a disk, the ellipse as its equal-area disk);     */
/*   TUBE   the facing rectangle through the rectangle MRP plus half of   */
/*          each end sphere (the capsule's silhouette, as the LTC path).  */
/* Every lobe integral is clamped to 1 (Drobot's energy-conserving        */
/* normalisation), as the rectangle's.                                    */

#ifndef AREA_LIGHT_SHAPES_MRP_INC_GLSL
#define AREA_LIGHT_SHAPES_MRP_INC_GLSL

// Oat and Sander's smoothstep approximation (Drobot eq. 1.21) of the overlap of two disks (or caps) of
// radii p_r0, p_r1 whose centres are p_dist apart, as a fraction of the smaller one's area.
float area_mrp_overlap_fraction(float p_r0, float p_r1, float p_dist) {
	float lo = abs(p_r0 - p_r1);
	float span = max(p_r0 + p_r1 - lo, 1e-6);
	return smoothstep(0.0, 1.0, 1.0 - clamp((p_dist - lo) / span, 0.0, 1.0));
}

// The engine's GGX lobe D V (n.l) at l (light_compute's clamps, roughness floored at 0.02 as the rectangle).
float area_mrp_lobe(vec3 N, vec3 V, vec3 p_l, float p_roughness) {
	float NoL = dot(N, p_l);
	if (NoL <= 0.0) {
		return 0.0;
	}
	float roughness = max(p_roughness, 0.02);
	float alpha = roughness * roughness;
	vec3 H = normalize(V + p_l);
	float NoV = max(dot(N, V), 1e-4);
	float NoH = clamp(dot(N, H), 0.0, 1.0);
	return D_GGX(NoH, alpha) * V_SmithGGXCorrelatedFast(NoV, NoL, alpha) * NoL;
}

// One sphere (centre p_c relative to the shading point, radius p_radius) emitting p_radiance.
void area_mrp_sphere(vec3 p_c, float p_radius, vec3 p_radiance, float p_specular_amount, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	float d = length(p_c);
	if (!(d > 0.0)) {
		return;
	}
	vec3 lc = p_c / d;
	bool inside = d <= p_radius;
	float s2 = inside ? 1.0 : p_radius * p_radius / (d * d);
	float sigma = inside ? M_PI : asin(sqrt(s2));
	// Diffuse: exact Lambert form factor, the BRDF at the cap direction closest to n.
	float ff = inside ? 1.0 : area_cap_form_factor(dot(N, lc), s2);
	if (ff > 0.0) {
		float theta = acos(clamp(dot(N, lc), -1.0, 1.0));
		vec3 l_d = N;
		if (theta > sigma) {
			vec3 t = N - lc * dot(N, lc);
			float tl = length(t);
			l_d = tl > 1e-6 ? normalize(lc * cos(sigma) + (t / tl) * sin(sigma)) : lc;
		}
		float nol = dot(N, l_d);
		if (nol > 1e-6) {
			vec3 diffuse = vec3(0.0);
			vec3 unused_specular = vec3(0.0);
			light_compute(N, l_d, V, p_radiance * (M_PI * ff / nol), 0.0, p_diffuse_mode, p_roughness, p_f0, p_f90, false, diffuse, unused_specular);
			r_diffuse += diffuse;
		}
	}
	if (!p_specular_enabled) {
		return;
	}
	// Specular: the sphere point closest to the reflection ray.
	vec3 R = reflect(-V, N);
	vec3 to_ray = R * dot(p_c, R) - p_c;
	float tr = length(to_ray);
	vec3 closest = p_c + (tr > 1e-9 ? to_ray * min(p_radius / tr, 1.0) : vec3(0.0));
	vec3 l_s = normalize(closest);
	float lobe = area_mrp_lobe(N, V, l_s, p_roughness);
	if (!(lobe > 0.0)) {
		return;
	}
	float half_angle = 0.5 * area_mrp_cone_angle(p_roughness);
	float omega_light = inside ? 4.0 * M_PI : 2.0 * M_PI * (1.0 - sqrt(1.0 - s2));
	float omega_cone = 2.0 * M_PI * (1.0 - cos(half_angle));
	float delta = acos(clamp(dot(R, lc), -1.0, 1.0));
	float omega_s = min(omega_light, omega_cone) * (inside ? 1.0 : area_mrp_overlap_fraction(sigma, half_angle, delta));
	if (!(omega_s > 0.0)) {
		return;
	}
	vec3 H = normalize(V + l_s);
	float LoH = clamp(dot(l_s, H), 0.0, 1.0);
	r_specular += p_radiance * p_specular_amount * min(lobe * omega_s, 1.0) * F_Schlick(p_f0, p_f90, LoH);
}

// The ellipse point (semi-axes p_half) closest-ish to plane coordinates p_uv: radial clamp (exact for a circle).
vec2 area_mrp_ellipse_clamp(vec2 p_uv, vec2 p_half) {
	float k = length(p_uv / p_half);
	return k > 1.0 ? p_uv / k : p_uv;
}

void area_mrp_disk(AreaLightData p_light, vec3 p_radiance, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	vec3 ax;
	vec3 ay;
	vec2 half_size;
	if (!area_light_get_frame(p_light, ax, ay, half_size)) {
		return;
	}
	vec3 nl = p_light.normal;
	vec3 to_vertex = p_vertex - p_light.position;
	float plane_dist = dot(to_vertex, nl);
	vec3 cap_axis;
	float s2 = area_ellipse_equivalent_cap(p_light.position - p_vertex, p_light.half_axis_x, p_light.half_axis_y, cap_axis);
	float omega = 2.0 * M_PI * s2 / (1.0 + sqrt(max(1.0 - s2, 0.0))); // 2 pi (1 - cos sigma), stable for small lights.
	if (!(omega > 0.0)) {
		return;
	}
	float far = 1e3 * (half_size.x + half_size.y + plane_dist + length(to_vertex));
	// Diffuse: Drobot 1.3.3 (p_r, p_c, bisector p_d) with the ellipse's closest points.
	vec2 uv_r = area_mrp_ellipse_clamp(area_mrp_plane_uv(p_light, ax, ay, p_vertex), half_size);
	vec3 dir_r = normalize(area_mrp_uv_to_point(p_light, ax, ay, uv_r) - p_vertex);
	vec3 dir_c = dir_r;
	if (dot(N, nl) < -1e-4) {
		float t;
		vec2 uv_c = area_mrp_ellipse_clamp(area_mrp_plane_hit(p_light, ax, ay, p_vertex, plane_dist, N, far, t), half_size);
		dir_c = normalize(area_mrp_uv_to_point(p_light, ax, ay, uv_c) - p_vertex);
	} else {
		vec3 p2 = cross(cross(nl, N), nl); // Thesis eq. 5.2.
		if (dot(p2, p2) > 1e-12) {
			dir_c = normalize(p2);
		}
	}
	vec3 bisector = dir_c + dir_r;
	vec3 dir_d = dot(bisector, bisector) > 1e-12 ? normalize(bisector) : dir_r;
	float t_d;
	vec2 uv_d = area_mrp_ellipse_clamp(area_mrp_plane_hit(p_light, ax, ay, p_vertex, plane_dist, dir_d, far, t_d), half_size);
	vec3 l_d = normalize(area_mrp_uv_to_point(p_light, ax, ay, uv_d) - p_vertex);
	// Weight: the disk's horizon-clipped form factor (its equivalent cap) over n.l_d, so that Lambert is
	// exact where the cap is (Drobot eq. 1.16's Omega (n.l_d) overestimates large disks: 2 / (1 + cos sigma)).
	float ff = area_cap_form_factor(dot(N, cap_axis), s2);
	float nol_d = dot(N, l_d);
	if (ff > 0.0 && nol_d > 1e-6) {
		vec3 diffuse = vec3(0.0);
		vec3 unused_specular = vec3(0.0);
		light_compute(N, l_d, V, p_radiance * (M_PI * ff / nol_d), 0.0, p_diffuse_mode, p_roughness, p_f0, p_f90, false, diffuse, unused_specular);
		r_diffuse += diffuse;
	}
	if (!p_specular_enabled) {
		return;
	}
	vec3 R = reflect(-V, N);
	float t_s;
	vec2 uv_hit = area_mrp_plane_hit(p_light, ax, ay, p_vertex, plane_dist, R, far, t_s);
	vec2 uv_s = area_mrp_ellipse_clamp(uv_hit, half_size);
	vec3 to_s = area_mrp_uv_to_point(p_light, ax, ay, uv_s) - p_vertex;
	vec3 l_s = normalize(to_s);
	float lobe = area_mrp_lobe(N, V, l_s, p_roughness);
	if (!(lobe > 0.0)) {
		return;
	}
	float half_angle = 0.5 * area_mrp_cone_angle(p_roughness);
	float omega_cone = 2.0 * M_PI * (1.0 - cos(half_angle));
	vec2 centre = uv_hit;
	float dist = t_s;
	float cos_hit = -dot(R, nl);
	if (!(cos_hit > 1e-4)) {
		centre = uv_s;
		dist = length(to_s);
		cos_hit = -dot(l_s, nl);
	}
	// Drobot eq. 1.21: footprint disk (radius rho, stretched by the slant to keep its area) against the
	// light's equal-area disk, in the ellipse's scaled coordinates.
	float rho = dist * tan(half_angle) * inversesqrt(max(cos_hit, 0.05));
	float r_light = sqrt(half_size.x * half_size.y);
	float d_centre = length(centre / half_size) * r_light;
	float shared_area = min(rho, r_light) * min(rho, r_light) * area_mrp_overlap_fraction(rho, r_light, d_centre);
	float omega_s = min(omega_cone * shared_area / max(rho * rho, 1e-12), omega);
	if (!(omega_s > 0.0)) {
		return;
	}
	vec3 H = normalize(V + l_s);
	float LoH = clamp(dot(l_s, H), 0.0, 1.0);
	r_specular += p_radiance * p_light.specular_amount * min(lobe * omega_s, 1.0) * F_Schlick(p_f0, p_f90, LoH);
}

void light_process_area_shape_mrp(AreaLightData p_light, uint p_shape, vec3 p_radiance, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	vec3 c = p_light.position - p_vertex;
	if (p_shape == AREA_SHAPE_DISK) {
		area_mrp_disk(p_light, p_radiance, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
	} else if (p_shape == AREA_SHAPE_SPHERE) {
		area_mrp_sphere(c, length(p_light.half_axis_x), p_radiance, p_light.specular_amount, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
	} else {
		AreaLightData rect;
		if (area_tube_facing_rectangle(p_light, p_vertex - p_light.position, p_radiance, rect)) {
			light_process_area_mrp(rect, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		}
		float radius = length(p_light.half_axis_y);
		vec3 half_radiance = p_radiance * 0.5;
		area_mrp_sphere(c - p_light.half_axis_x, radius, half_radiance, p_light.specular_amount, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		area_mrp_sphere(c + p_light.half_axis_x, radius, half_radiance, p_light.specular_amount, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
	}
}

#endif // AREA_LIGHT_SHAPES_MRP_INC_GLSL
