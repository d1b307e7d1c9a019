/**************************************************************************/
/*  area_light_shapes_inc.glsl                                            */
/**************************************************************************/
/* Disk, sphere and tube area lights (RS::LightAreaShape; the rectangle   */
/* stays in area_light_{ltc,mrp,mc}_inc.glsl). Compiled only with         */
/* USE_AREA_SHAPES, which RenderForwardClustered sets for a view that has */
/* such a light: a scene of rectangles compiles none of this file.        */
/*                                                                        */
/* Geometry (LightStorage::fill_area_light_data, view space):             */
/*   DISK   ellipse of semi-axes half_axis_x, half_axis_y around position, */
/*          one-sided: emits along normal only (as the rectangle);        */
/*   SPHERE centre position, radius |half_axis_x|, emits outwards         */
/*          everywhere;                                                   */
/*   TUBE   capsule around the segment position +- half_axis_x, radius    */
/*          |half_axis_y|, emits outwards everywhere.                     */
/* The contract is the rectangle's: L_o = W(d) integral f L_e cos dw,     */
/* W(d) as area_light_range_window with d the distance to the closest     */
/* point of the shape (disk: the plane point clamped radially onto the    */
/* ellipse, exact for circles; the reference renderer uses the same d).  */
/*                                                                        */
/* Shared here: the range window per shape, the equivalent spherical cap  */
/* of an elliptic cone (Heitz and Hill 2017, "Real-Time Line- and Disk-   */
/* Light Shading with Linearly Transformed Cosines": an ellipse seen from */
/* a point bounds an elliptic cone; its cosine form factor about its own  */
/* axis is a b / sqrt((1 + a^2)(1 + b^2)), a, b the tangents of its half  */
/* angles, and the cone is replaced by the spherical cap of equal form    */
/* factor), and the horizon-clipped form factor of a spherical cap        */
/* (Snyder 1996, "Area light sources for real-time graphics", the closed  */
/* form for a cap cut by the tangent plane).                              */
/* Methods: area_light_shapes_ltc_inc.glsl, _mrp_inc.glsl, _mc_inc.glsl,  */
/* each compiled only with its AREA_METHOD_* define.                      */

#ifndef AREA_LIGHT_SHAPES_INC_GLSL
#define AREA_LIGHT_SHAPES_INC_GLSL

// Distance from the shading point (p_to_vertex = vertex - position) to the closest point of the shape.
float area_shape_distance(AreaLightData p_light, uint p_shape, vec3 p_to_vertex) {
	if (p_shape == AREA_SHAPE_SPHERE) {
		return max(length(p_to_vertex) - length(p_light.half_axis_x), 0.0);
	}
	if (p_shape == AREA_SHAPE_TUBE) {
		float hx2 = dot(p_light.half_axis_x, p_light.half_axis_x);
		float t = hx2 > 0.0 ? clamp(dot(p_to_vertex, p_light.half_axis_x) / hx2, -1.0, 1.0) : 0.0;
		return max(length(p_to_vertex - p_light.half_axis_x * t) - length(p_light.half_axis_y), 0.0);
	}
	// Disk: the plane point, pulled radially onto the ellipse when outside it.
	float a2 = dot(p_light.half_axis_x, p_light.half_axis_x);
	float b2 = dot(p_light.half_axis_y, p_light.half_axis_y);
	if (!(a2 > 0.0) || !(b2 > 0.0)) {
		return length(p_to_vertex);
	}
	vec2 uv = vec2(dot(p_to_vertex, p_light.half_axis_x) / a2, dot(p_to_vertex, p_light.half_axis_y) / b2); // In semi-axis units.
	float k = length(uv);
	uv /= max(k, 1.0);
	return length(p_to_vertex - p_light.half_axis_x * uv.x - p_light.half_axis_y * uv.y);
}

// The contract's W(d) (area_light_window_at) with the shape's closest-point distance.
float area_shape_range_window(AreaLightData p_light, uint p_shape, vec3 p_to_vertex) {
	return area_light_window_at(p_light, area_shape_distance(p_light, p_shape, p_to_vertex));
}

// Form factor (1/pi of the projected solid angle) of a spherical cap of angular radius sigma
// (p_sin2_sigma = sin^2 sigma) whose axis makes cos theta = p_cos_theta with the normal, clipped by the
// horizon: Snyder 1996. Fully above (theta + sigma <= pi/2): sin^2 sigma cos theta; fully below: 0;
// otherwise, with x = cot sigma, y = -x cot theta:
//   pi FF = (cos theta acos y - x sin theta sqrt(1 - y^2)) sin^2 sigma + atan(sin theta sqrt(1 - y^2) / x).
float area_cap_form_factor(float p_cos_theta, float p_sin2_sigma) {
	float s2 = clamp(p_sin2_sigma, 0.0, 1.0);
	float c = clamp(p_cos_theta, -1.0, 1.0);
	if (s2 >= 1.0 - 1e-6) {
		return 0.5 + 0.5 * c; // The limit sigma -> pi/2: a hemisphere of directions about the axis.
	}
	float sin_sigma = sqrt(s2);
	if (c >= sin_sigma) {
		return s2 * c;
	}
	if (c <= -sin_sigma) {
		return 0.0;
	}
	float sin_theta = sqrt(max(1.0 - c * c, 1e-12));
	float x = sqrt(max(1.0 - s2, 1e-12) / max(s2, 1e-12));
	float y = clamp(-x * c / sin_theta, -1.0, 1.0);
	float sy = sin_theta * sqrt(max(1.0 - y * y, 0.0));
	return max(((c * acos(y) - x * sy) * s2 + atan(sy, x)) / M_PI, 0.0);
}

// The elliptic cone from the origin through the ellipse (centre p_c, conjugate semi-diameters p_v1,
// p_v2; any origin not in its plane). Returns sin^2 of the half angle of the spherical cap of equal form
// factor (Heitz and Hill 2017) and r_axis, the cone's unit axis towards the ellipse.
// The cone is w^T Q w = 0 with Q^-1 = S = v1 v1^T + v2 v2^T - c c^T (S = M diag(1, 1, -1) M^T for
// M = [v1 v2 c]); in S's eigenbasis its eigenvalues e1, e2 > 0 > e3 give tan^2 = e1 / |e3|, e2 / |e3|,
// so FF = sqrt(e1 e2) / sqrt((|e3| + e1)(|e3| + e2)). e1 e2 = det(M)^2 / |e3| (det S = -det(M)^2) keeps
// small, far lights precise in 32-bit floats.
float area_ellipse_equivalent_cap(vec3 p_c, vec3 p_v1, vec3 p_v2, out vec3 r_axis) {
	r_axis = normalize(p_c);
	mat3 s = outerProduct(p_v1, p_v1) + outerProduct(p_v2, p_v2) - outerProduct(p_c, p_c);
	float det_m = dot(p_c, cross(p_v1, p_v2));
	if (!(abs(det_m) > 0.0)) {
		return 0.0; // Seen edge-on: no solid angle.
	}
	// Smallest eigenvalue: the trigonometric solution of the characteristic cubic (Smith 1961), then one
	// Newton step on det(S - e I) = 0.
	float tr = s[0][0] + s[1][1] + s[2][2];
	float q = tr / 3.0;
	float p1 = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
	float p2 = (s[0][0] - q) * (s[0][0] - q) + (s[1][1] - q) * (s[1][1] - q) + (s[2][2] - q) * (s[2][2] - q) + 2.0 * p1;
	float p = sqrt(max(p2 / 6.0, 1e-30));
	mat3 b = (s - mat3(q)) * (1.0 / p);
	float r = clamp(determinant(b) * 0.5, -1.0, 1.0);
	float phi = acos(r) / 3.0;
	float e3 = q + 2.0 * p * cos(phi + 2.0 * M_PI / 3.0);
	float minors = s[0][0] * s[1][1] - s[0][1] * s[0][1] + s[0][0] * s[2][2] - s[0][2] * s[0][2] + s[1][1] * s[2][2] - s[1][2] * s[1][2];
	float det_s = -det_m * det_m;
	float f = ((e3 - tr) * e3 + minors) * e3 - det_s;
	float df = (3.0 * e3 - 2.0 * tr) * e3 + minors;
	if (abs(df) > 0.0) {
		e3 -= f / df;
	}
	if (!(e3 < 0.0)) {
		return 0.0;
	}
	float neg = -e3;
	float prod = det_m * det_m / neg; // e1 e2
	float sum = max(tr - e3, 0.0); // e1 + e2
	float ff = sqrt(prod / max(neg * neg + neg * sum + prod, 1e-30));
	// Axis: the eigenvector of e3, the largest cross product of two rows of S - e3 I.
	mat3 m = s - mat3(e3);
	vec3 c01 = cross(m[0], m[1]);
	vec3 c02 = cross(m[0], m[2]);
	vec3 c12 = cross(m[1], m[2]);
	float l01 = dot(c01, c01);
	float l02 = dot(c02, c02);
	float l12 = dot(c12, c12);
	vec3 axis = l01 > l02 ? (l01 > l12 ? c01 : c12) : (l02 > l12 ? c02 : c12);
	float len = length(axis);
	if (len > 0.0 && !isnan(len) && !isinf(len)) {
		axis /= len;
		r_axis = dot(axis, p_c) < 0.0 ? -axis : axis;
	}
	return clamp(ff, 0.0, 1.0); // The form factor about the axis is sin^2 of the equivalent cap's half angle.
}

// A unit vector orthogonal to unit p_n and a second one completing the frame.
void area_shape_basis(vec3 p_n, out vec3 r_t1, out vec3 r_t2) {
	vec3 helper = abs(p_n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
	r_t1 = normalize(cross(helper, p_n));
	r_t2 = cross(p_n, r_t1);
}

// The tube's rectangle facing the shading point (Heitz and Hill 2017 treat a cylinder seen from a point
// as the line's ribbon of its width): the segment by the diameter, its normal towards the point, as
// an AreaLightData for the rectangle methods with its window already applied (inv_radius 0,
// attenuation 2: W = 1 inside the rectangle code). False when the point is on the axis line.
bool area_tube_facing_rectangle(AreaLightData p_light, vec3 p_to_vertex, vec3 p_radiance, out AreaLightData r_rect) {
	r_rect = p_light;
	r_rect.texture_rect = vec4(0.0); // area_texture applies to rectangles only: the ribbon is untextured.
	float hx2 = dot(p_light.half_axis_x, p_light.half_axis_x);
	if (!(hx2 > 0.0)) {
		return false; // A zero-length tube is a sphere: the caps cover it.
	}
	vec3 axis = p_light.half_axis_x * inversesqrt(hx2);
	vec3 w = p_to_vertex - axis * dot(p_to_vertex, axis);
	float wl = length(w);
	if (!(wl > 1e-6)) {
		return false;
	}
	vec3 n = w / wl;
	r_rect.normal = n;
	r_rect.half_axis_y = cross(n, axis) * length(p_light.half_axis_y);
	r_rect.inv_radius = 0.0;
	r_rect.attenuation = 2.0;
	r_rect.color = p_radiance;
	r_rect.shading_method = p_light.shading_method & 0x00FFFFFFu; // A rectangle.
	return true;
}

#endif // AREA_LIGHT_SHAPES_INC_GLSL

#if defined(AREA_METHOD_LTC) || defined(AREA_METHOD_LTC_POLYNOMIAL) || defined(AREA_METHOD_LTC_2LOBE)
#include "area_light_shapes_ltc_inc.glsl"
#endif
#ifdef AREA_METHOD_MRP
#include "area_light_shapes_mrp_inc.glsl"
#endif
#ifdef AREA_METHOD_STOCHASTIC
#include "area_light_shapes_mc_inc.glsl"
#endif

#ifndef AREA_LIGHT_SHAPES_DISPATCH_GLSL
#define AREA_LIGHT_SHAPES_DISPATCH_GLSL

// One disk, sphere or tube light with its method (p_method = area_light_get_method()); as
// light_process_area_method, whose shape branch calls it.
void light_process_area_shape(AreaLightData p_light, uint p_method, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	uint shape = area_light_get_shape(p_light);
	if (p_light.color == vec3(0.0) || shape > AREA_SHAPE_TUBE) {
		return;
	}
	vec3 to_vertex = p_vertex - p_light.position;
	if (shape == AREA_SHAPE_DISK && !(dot(to_vertex, p_light.normal) > 0.0)) {
		return; // One-sided, exactly 0 on and behind the plane.
	}
	float window = area_shape_range_window(p_light, shape, to_vertex);
	if (window <= 0.0) {
		return;
	}
	vec3 radiance = p_light.color * window;
#if defined(AREA_METHOD_LTC) || defined(AREA_METHOD_LTC_POLYNOMIAL) || defined(AREA_METHOD_LTC_2LOBE)
	// LTC_2LOBE: the shapes keep the one-lobe LUT (the two-lobe table is fitted to rectangles' integrals).
	if (p_method == AREA_SHADING_LTC || p_method == AREA_SHADING_LTC_POLYNOMIAL || p_method == AREA_SHADING_LTC_2LOBE) {
		light_process_area_shape_ltc(p_light, shape, radiance, p_vertex, N, V, p_roughness, p_f0, p_f90, p_specular_enabled, p_method == AREA_SHADING_LTC_POLYNOMIAL, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_MRP
	if (p_method == AREA_SHADING_MRP) {
		light_process_area_shape_mrp(p_light, shape, radiance, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_STOCHASTIC
	if (p_method == AREA_SHADING_STOCHASTIC) {
		light_process_area_shape_mc(p_light, shape, radiance, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		return;
	}
#endif
}

#endif // AREA_LIGHT_SHAPES_DISPATCH_GLSL
