/**************************************************************************/
/*  area_light_common_inc.glsl                                            */
/**************************************************************************/
/* The definition of an area light that every shading method obeys, and   */
/* the helpers they share: the packed method and shape, the rectangle     */
/* frame and closest point, the spherical rectangle (set-up, sampling,    */
/* solid angle), the range window W(d) and the gate each rectangle method */
/* opens with (area_light_rect_begin).                                    */
/*                                                                        */
/* The contract (scene/3d/light_3d.h, AreaLight3D): one-sided (exactly 0  */
/* on and behind the light plane), exactly 0 for a zero-size or black     */
/* light, and L_o = W(d) * integral f L_e cos dw with                     */
/* L_e = colour * energy * pi / A_n and                                   */
/* W(d) = max(1 - (d/r)^4, 0)^2 * max(d, 1e-4)^(2 - attenuation), applied */
/* once per shading point, outside the integral.                          */
/*                                                                        */
/* Needs, declared before inclusion: light_data_inc.glsl (AreaLightData)  */
/* and brdf_inc.glsl (M_PI). Every method file includes it, so each one   */
/* also compiles on its own (the GPU unit tests include single methods).  */

#ifndef AREA_LIGHT_COMMON_INC_GLSL
#define AREA_LIGHT_COMMON_INC_GLSL

// AreaLightData::shading_method packs the method (bits 0-7) and the stochastic sample count
// (bits 8-23). Must match RendererRD::LightStorage::pack_area_shading_method().
uint area_light_get_method(AreaLightData p_light) {
	return p_light.shading_method & 0xFFu;
}

uint area_light_get_stochastic_samples(AreaLightData p_light) {
	return clamp((p_light.shading_method >> 8u) & 0xFFFFu, 1u, 256u);
}

// Bits 24-31: AREA_SHAPE_* (RendererRD::LightStorage::AREA_METHOD_SHAPE_SHIFT).
uint area_light_get_shape(AreaLightData p_light) {
	return p_light.shading_method >> 24u;
}

// Orthonormal frame of the rectangle: unit axes and half extents (metres). False for a zero-size light.
bool area_light_get_frame(AreaLightData p_light, out vec3 r_x, out vec3 r_y, out vec2 r_half) {
	float lx = length(p_light.half_axis_x);
	float ly = length(p_light.half_axis_y);
	r_half = vec2(lx, ly);
	if (!(lx > 0.0) || !(ly > 0.0)) {
		r_x = vec3(1.0, 0.0, 0.0);
		r_y = vec3(0.0, 1.0, 0.0);
		return false;
	}
	r_x = p_light.half_axis_x / lx;
	r_y = p_light.half_axis_y / ly;
	return true;
}

// The point of the rectangle closest to the plane point with rectangle coordinates p_uv (metres from
// the centre along the unit axes), as coordinates.
vec2 area_light_clamp_uv(vec2 p_uv, vec2 p_half) {
	return clamp(p_uv, -p_half, p_half);
}

// Spherical rectangle seen from a point (Urena, Fajardo and King 2013, "An Area-Preserving
// Parametrization for Spherical Rectangles", section 3): the rectangle in a frame (x, y, z) centred
// at the shading point, with z0 <= 0 the (negated) plane distance, [x0, x1] x [y0, y1] its extents,
// and the quantities of the sampling equations. solid_angle S = g0 + g1 + g2 + g3 - 2 pi (the area of
// the spherical quadrilateral by Girard's theorem).
struct AreaSphericalRect {
	vec3 o; // Shading point.
	vec3 x; // Unit frame.
	vec3 y;
	vec3 z;
	float x0;
	float y0;
	float z0;
	float x1;
	float y1;
	float b0; // n0.z
	float b1; // n2.z
	float k; // 2 pi - g2 - g3
	float solid_angle; // S (sr).
};

// p_o: shading point; p_corner: the rectangle corner at -half_x - half_y; p_x, p_y unit axes; p_size the
// full extents. Returns false when the point is (numerically) on the light plane or S is not usable.
bool area_spherical_rect_init(vec3 p_o, vec3 p_corner, vec3 p_x, vec3 p_y, vec2 p_size, out AreaSphericalRect r_rect) {
	r_rect.o = p_o;
	r_rect.x = p_x;
	r_rect.y = p_y;
	r_rect.z = cross(p_x, p_y);
	vec3 d = p_corner - p_o;
	r_rect.x0 = dot(d, r_rect.x);
	r_rect.y0 = dot(d, r_rect.y);
	r_rect.z0 = dot(d, r_rect.z);
	if (r_rect.z0 > 0.0) { // The paper's convention: the rectangle lies on the -z side of the frame.
		r_rect.z0 = -r_rect.z0;
		r_rect.z = -r_rect.z;
	}
	r_rect.x1 = r_rect.x0 + p_size.x;
	r_rect.y1 = r_rect.y0 + p_size.y;
	r_rect.b0 = 0.0;
	r_rect.b1 = 0.0;
	r_rect.k = 0.0;
	r_rect.solid_angle = 0.0;
	if (!(r_rect.z0 < 0.0)) {
		return false;
	}
	vec3 v00 = vec3(r_rect.x0, r_rect.y0, r_rect.z0);
	vec3 v01 = vec3(r_rect.x0, r_rect.y1, r_rect.z0);
	vec3 v10 = vec3(r_rect.x1, r_rect.y0, r_rect.z0);
	vec3 v11 = vec3(r_rect.x1, r_rect.y1, r_rect.z0);
	// Normals of the planes through the origin and each edge (pointing inwards).
	vec3 n0 = normalize(cross(v00, v10));
	vec3 n1 = normalize(cross(v10, v11));
	vec3 n2 = normalize(cross(v11, v01));
	vec3 n3 = normalize(cross(v01, v00));
	// Interior angles of the spherical quadrilateral.
	float g0 = acos(clamp(-dot(n0, n1), -1.0, 1.0));
	float g1 = acos(clamp(-dot(n1, n2), -1.0, 1.0));
	float g2 = acos(clamp(-dot(n2, n3), -1.0, 1.0));
	float g3 = acos(clamp(-dot(n3, n0), -1.0, 1.0));
	r_rect.b0 = n0.z;
	r_rect.b1 = n2.z;
	r_rect.k = 2.0 * M_PI - g2 - g3;
	r_rect.solid_angle = g0 + g1 - r_rect.k;
	return r_rect.solid_angle > 1e-7 && !isnan(r_rect.solid_angle) && !isinf(r_rect.solid_angle);
}

// The point of the rectangle for (u, v) in [0, 1)^2, uniformly distributed in solid angle (paper's
// section 4: invert the solid angle of the sub-rectangle [x0, xu] for u, then the cosine-weighted
// height along the chosen segment for v). pdf = 1 / solid_angle.
vec3 area_spherical_rect_sample(AreaSphericalRect p_rect, float p_u, float p_v) {
	// 1. The x coordinate xu whose sub-rectangle [x0, xu] has solid angle u * S.
	float au = p_u * p_rect.solid_angle + p_rect.k;
	float s = sin(au);
	float fu = (cos(au) * p_rect.b0 - p_rect.b1) / (abs(s) > 1e-12 ? s : 1e-12);
	float cu = inversesqrt(fu * fu + p_rect.b0 * p_rect.b0) * (fu > 0.0 ? 1.0 : -1.0);
	cu = clamp(cu, -1.0, 1.0);
	float xu = -(cu * p_rect.z0) * inversesqrt(max(1.0 - cu * cu, 1e-12));
	xu = clamp(xu, p_rect.x0, p_rect.x1);
	// 2. The y coordinate along the segment x = xu, uniform in the sine of the elevation.
	float dist = sqrt(xu * xu + p_rect.z0 * p_rect.z0);
	float h0 = p_rect.y0 * inversesqrt(dist * dist + p_rect.y0 * p_rect.y0);
	float h1 = p_rect.y1 * inversesqrt(dist * dist + p_rect.y1 * p_rect.y1);
	float hv = h0 + p_v * (h1 - h0);
	float hv2 = hv * hv;
	float yv = hv2 < 1.0 - 1e-6 ? hv * dist * inversesqrt(1.0 - hv2) : p_rect.y1;
	yv = clamp(yv, p_rect.y0, p_rect.y1);
	return p_rect.o + p_rect.x * xu + p_rect.y * yv + p_rect.z * p_rect.z0;
}

// Solid angle (sr) of the whole rectangle seen from p_vertex; 0 on or behind the plane.
float area_light_solid_angle(AreaLightData p_light, vec3 p_vertex, vec3 p_x, vec3 p_y, vec2 p_half) {
	AreaSphericalRect rect;
	vec3 corner = p_light.position - p_x * p_half.x - p_y * p_half.y;
	if (!area_spherical_rect_init(p_vertex, corner, p_x, p_y, p_half * 2.0, rect)) {
		return 0.0;
	}
	return rect.solid_angle;
}

// Distance attenuation of upstream Godot 4.7's area light (its class reference and shader):
// d = distance from the shading point to the closest point of the light, r = area_range,
// a = area_attenuation (a distance exponent, as omni_attenuation):
//   W(d) = max(1 - (d/r)^4, 0)^2 * max(d, 1e-4)^(2 - a).
// The integral over the rectangle already falls off as the inverse square, so a = 2 leaves it
// physical and only the range window applies; W is exactly 0 for d >= r.
float area_light_window_at(AreaLightData p_light, float p_distance) {
	float nd = p_distance * p_light.inv_radius;
	if (nd >= 1.0) {
		return 0.0;
	}
	nd *= nd;
	nd *= nd;
	float window = 1.0 - nd;
	window *= window;
	// pow(x, 0) = 1: a = 2 costs nothing but the window.
	return window * pow(max(p_distance, 1e-4), 2.0 - p_light.attenuation);
}

// W(d) of a rectangle: d to the closest point of the rectangle.
float area_light_range_window(AreaLightData p_light, vec3 p_to_vertex) {
	float ax2 = dot(p_light.half_axis_x, p_light.half_axis_x);
	float ay2 = dot(p_light.half_axis_y, p_light.half_axis_y);
	float u = ax2 > 0.0 ? clamp(dot(p_to_vertex, p_light.half_axis_x) / ax2, -1.0, 1.0) : 0.0;
	float v = ay2 > 0.0 ? clamp(dot(p_to_vertex, p_light.half_axis_y) / ay2, -1.0, 1.0) : 0.0;
	return area_light_window_at(p_light, length(p_to_vertex - p_light.half_axis_x * u - p_light.half_axis_y * v));
}

// What the gate of a rectangle method (area_light_rect_begin) hands on: where the shading point lies
// relative to the light, the light's frame, and L_e W(d).
struct AreaRectSetup {
	vec3 to_vertex; // Shading point - light centre.
	float plane_dist; // Its distance to the light plane (> 0: in front of the emitting side).
	vec3 ax; // Unit axes and half extents (metres) of the rectangle (area_light_get_frame).
	vec3 ay;
	vec2 half_size;
	vec3 radiance; // L_e W(d): the colour times the range window, applied once outside the integral.
};

// The gate every rectangle method opens with (the contract above): the shading point strictly in front
// of the emitting side, a light with a size and a colour (LightStorage sets the colour of a zero-size
// light to 0), and an open range window. False where the light adds exactly 0, before any method's
// maths runs on degenerate input.
bool area_light_rect_begin(AreaLightData p_light, vec3 p_vertex, out AreaRectSetup r_setup) {
	r_setup.to_vertex = p_vertex - p_light.position;
	r_setup.plane_dist = dot(r_setup.to_vertex, p_light.normal);
	r_setup.radiance = vec3(0.0);
	bool has_size = area_light_get_frame(p_light, r_setup.ax, r_setup.ay, r_setup.half_size);
	if (!(r_setup.plane_dist > 0.0) || p_light.color == vec3(0.0) || !has_size) {
		return false;
	}
	float window = area_light_range_window(p_light, r_setup.to_vertex);
	if (!(window > 0.0)) {
		return false;
	}
	r_setup.radiance = p_light.color * window;
	return true;
}

#endif // AREA_LIGHT_COMMON_INC_GLSL
