/**************************************************************************/
/*  area_light_shapes_ltc_inc.glsl                                        */
/**************************************************************************/
/* Disk, sphere and tube lights shaded with linearly transformed cosines  */
/* (Heitz, Dupuy, Hill and Neubelt 2016; the shapes after Heitz and Hill  */
/* 2017, "Real-Time Line- and Disk-Light Shading with Linearly            */
/* Transformed Cosines"). Same LTC frame, matrix fetch (LUT or            */
/* polynomial) and Fresnel terms as the rectangle (area_light_ltc_inc):  */
/*   L_o = L_e W [ albedo FF(E) + spec FF(M^-1 E) F ]                     */
/* E is the light's ELLIPSE seen from the point; a linear map takes an    */
/* ellipse to an ellipse, so M^-1 E is again one (its centre and          */
/* semi-diameters are the transformed ones), and FF(ellipse) is the       */
/* horizon-clipped form factor of its equivalent spherical cap            */
/* (area_ellipse_equivalent_cap, area_cap_form_factor):                   */
/*   DISK   E = the disk itself;                                          */
/*   SPHERE E = the disk through the sphere's centre facing the point     */
/*          with radius r d / sqrt(d^2 - r^2), which bounds the same cone */
/*          as the sphere (its tangent cone), so the diffuse term is the  */
/*          exact cap FF (sin^2 sigma = r^2 / d^2);                       */
/*   TUBE   the segment's facing rectangle (width = diameter; Heitz and   */
/*          Hill's line light as a ribbon) through the rectangle LTC,     */
/*          plus half of each end sphere (the silhouette of a capsule is  */
/*          that rectangle and two half disks).                          */
/* Approximations (measured in doc/methods.md, "Shapes"): the equivalent */
/* cap replaces a thin ellipse by a circle before the horizon clip (exact */
/* when the ellipse is wholly above the horizon); the surface-horizon     */
/* clip of the rectangle's specular (issue #18) is not applied to         */
/* ellipses; a tube seen along its axis counts half its end cap.          */

#ifndef AREA_LIGHT_SHAPES_LTC_INC_GLSL
#define AREA_LIGHT_SHAPES_LTC_INC_GLSL

// The LTC set-up of one shading point (as light_process_area_ltc): receiver frame (z = N), M^-1 and
// the Fresnel weight F.
void area_shape_ltc_setup(vec3 N, vec3 V, float p_roughness, vec3 p_f0, float p_f90, bool p_polynomial, out mat3 r_local_from_view, out mat3 r_m_inv, out vec3 r_fresnel) {
	float NoV = dot(N, V);
	vec3 tx = V - N * NoV;
	if (dot(tx, tx) < 1e-10) {
		tx = abs(N.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
		tx -= N * dot(N, tx);
	}
	vec3 T1 = normalize(tx);
	vec3 T2 = cross(N, T1);
	r_local_from_view = transpose(mat3(T1, T2, N));
	vec4 t0;
	vec4 t1;
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
	// Thesis eqs. 5.7-5.8, as the rectangle: M = [[a, 0, b], [0, c, 0], [d, 0, e]], inverted here.
	float s = 1.0 / (t0.x * t1.x - t0.y * t0.w);
	r_m_inv = mat3(vec3(s * t1.x, 0.0, -s * t0.w), vec3(0.0, 1.0 / t0.z, 0.0), vec3(-s * t0.y, 0.0, s * t0.x));
	r_fresnel = p_f0 * t1.y + (vec3(p_f90) - p_f0) * t1.z; // Thesis eq. 5.10.
}

// Form factor of the ellipse (local frame, z = up) clipped by the horizon.
float area_ltc_ellipse_form_factor(vec3 p_c, vec3 p_v1, vec3 p_v2) {
	vec3 axis;
	float s2 = area_ellipse_equivalent_cap(p_c, p_v1, p_v2, axis);
	return s2 > 0.0 ? area_cap_form_factor(axis.z, s2) : 0.0;
}

// Diffuse and specular form factors (x, y) of a sphere (centre p_c relative to the point, local frame).
vec2 area_ltc_sphere(vec3 p_c, float p_radius, mat3 p_m_inv, bool p_specular) {
	float d2 = dot(p_c, p_c);
	float r2 = p_radius * p_radius;
	if (d2 <= r2 * 1.0001) {
		return vec2(1.0, p_specular ? 1.0 : 0.0); // Inside: every direction sees the light.
	}
	float d = sqrt(d2);
	vec2 ff = vec2(area_cap_form_factor(p_c.z / d, r2 / d2), 0.0);
	if (p_specular) {
		vec3 t1;
		vec3 t2;
		area_shape_basis(p_c / d, t1, t2);
		float rd = p_radius * d * inversesqrt(d2 - r2); // The facing disk with the sphere's tangent cone.
		ff.y = area_ltc_ellipse_form_factor(p_m_inv * p_c, p_m_inv * (t1 * rd), p_m_inv * (t2 * rd));
	}
	return ff;
}

void light_process_area_shape_ltc(AreaLightData p_light, uint p_shape, vec3 p_radiance, vec3 p_vertex, vec3 N, vec3 V, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, bool p_polynomial, inout vec3 r_diffuse, inout vec3 r_specular) {
	mat3 local_from_view;
	mat3 m_inv;
	vec3 fresnel;
	area_shape_ltc_setup(N, V, p_roughness, p_f0, p_f90, p_polynomial, local_from_view, m_inv, fresnel);
	vec3 c = local_from_view * (p_light.position - p_vertex);
	vec2 ff = vec2(0.0);
	if (p_shape == AREA_SHAPE_DISK) {
		vec3 v1 = local_from_view * p_light.half_axis_x;
		vec3 v2 = local_from_view * p_light.half_axis_y;
		ff.x = area_ltc_ellipse_form_factor(c, v1, v2);
		if (p_specular_enabled) {
			ff.y = area_ltc_ellipse_form_factor(m_inv * c, m_inv * v1, m_inv * v2);
		}
	} else if (p_shape == AREA_SHAPE_SPHERE) {
		ff = area_ltc_sphere(c, length(p_light.half_axis_x), m_inv, p_specular_enabled);
	} else {
		// Tube: the facing rectangle (the rectangle LTC) and half of each end sphere.
		AreaLightData rect;
		if (area_tube_facing_rectangle(p_light, p_vertex - p_light.position, p_radiance, rect)) {
			light_process_area_ltc(rect, p_vertex, N, V, p_roughness, p_f0, p_f90, p_specular_enabled, p_polynomial, r_diffuse, r_specular);
		}
		vec3 hx = local_from_view * p_light.half_axis_x;
		float radius = length(p_light.half_axis_y);
		ff = 0.5 * (area_ltc_sphere(c - hx, radius, m_inv, p_specular_enabled) + area_ltc_sphere(c + hx, radius, m_inv, p_specular_enabled));
	}
	r_diffuse += p_radiance * ff.x;
	if (p_specular_enabled) {
		r_specular += p_radiance * p_light.specular_amount * ff.y * fresnel;
	}
}

#endif // AREA_LIGHT_SHAPES_LTC_INC_GLSL
