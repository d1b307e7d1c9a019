/**************************************************************************/
/*  area_light.h                                                          */
/**************************************************************************/
/* godot-area: rectangular area lights in the CPU reference renderer:     */
/* the light's world-space frame, its emitted radiance and range window   */
/* exactly as the area-light contract defines them (the GPU shader must   */
/* use the same units):                                                   */
/*   L_e = srgb_to_linear(colour) * energy * pi / A_n, A_n = a * b when   */
/*         normalize_energy, else 1; a * b == 0 emits exactly 0;          */
/*   L_o(x) = W(d) * integral over the rectangle of f(l, v) L_e (n.l) dw, */
/*         one-sided: only points strictly in front (local -Z) are lit;   */
/*   W(d) = max(1 - (d / r)^4, 0)^2 * max(d, 1e-4)^(2 - attenuation),     */
/*         d = distance from x to the closest point of the rectangle,     */
/*         d >= r gives exactly 0 (upstream Godot 4.7's area light).      */
/* The integral itself (solid-angle and GGX samples combined by MIS,      */
/* shadow rays by callback) is area_light_integrate() in                  */
/* area_light_integrator.h.                                               */

#pragma once

#include "core/io/image.h"
#include "core/math/color.h"
#include "core/math/math_funcs.h"
#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ReferenceBRDF {

// The emitting shape (values equal RS::LightAreaShape; area_light_shapes.h integrates the non-rectangles):
// DISK an ellipse of diameters size_x, size_y (one-sided, as the rectangle); SPHERE diameter size_x;
// TUBE a capsule of segment size_x along axis_x and diameter size_y (both emit outwards everywhere).
enum AreaLightShape : uint32_t {
	AREA_LIGHT_SHAPE_RECTANGLE = 0,
	AREA_LIGHT_SHAPE_DISK = 1,
	AREA_LIGHT_SHAPE_SPHERE = 2,
	AREA_LIGHT_SHAPE_TUBE = 3,
};

// Emitting area of a shape of size (x, y): rectangle x y, disk pi x y / 4, sphere pi x^2, tube pi y (x + y).
inline float area_light_shape_area(AreaLightShape p_shape, float p_x, float p_y) {
	const float pi = float(Math::PI);
	switch (p_shape) {
		case AREA_LIGHT_SHAPE_DISK:
			return pi * p_x * p_y * 0.25f;
		case AREA_LIGHT_SHAPE_SPHERE:
			return pi * p_x * p_x;
		case AREA_LIGHT_SHAPE_TUBE:
			return pi * p_y * (p_x + p_y);
		default:
			return p_x * p_y;
	}
}

// One area light in world space.
struct AreaLightData {
	Vector3 center; // World position of the rectangle's centre (the node origin).
	Vector3 axis_x = Vector3(1, 0, 0); // Unit world direction of the light's local +X (extent size.x).
	Vector3 axis_y = Vector3(0, 1, 0); // Unit world direction of the light's local +Y (extent size.y).
	Vector3 emit_dir = Vector3(0, 0, -1); // Unit world direction of local -Z: the lit side.
	float size_x = 0.0f; // Metres.
	float size_y = 0.0f; // Metres.
	Vector3 radiance; // L_e per channel (W / (m^2 sr) in engine units), negative for negative lights.
	float range = 0.0f; // Metres from the closest point of the rectangle.
	float attenuation = 1.0f; // area_attenuation: distance exponent (2 = physical, window only).
	float specular_amount = 1.0f; // "light_specular".
	uint32_t cull_mask = 0xFFFFFFFF;
	AreaLightShape shape = AREA_LIGHT_SHAPE_RECTANGLE;
	// area_texture texels (float RGBA, sRGB-encoded; owned by the material storage), null when untextured:
	// the emitted radiance at a point is radiance times area_light_texture_at() (area_light_texture.h).
	const Image *texture = nullptr;

	float get_area() const { return area_light_shape_area(shape, size_x, size_y); }
};

// L_e of the contract: srgb_to_linear(colour) * energy * pi / A_n (A_n = the shape's emitting area when
// normalising, else 1), negated for negative lights. Exactly zero for a zero area (no division by zero, no NaN).
inline Vector3 area_light_emitted_radiance(const Color &p_srgb_color, float p_energy, bool p_negative, const Vector2 &p_size, bool p_normalize_energy, AreaLightShape p_shape = AREA_LIGHT_SHAPE_RECTANGLE) {
	const float area = area_light_shape_area(p_shape, p_size.x, p_size.y);
	if (!(area > 0.0f)) {
		return Vector3();
	}
	const Color linear = p_srgb_color.srgb_to_linear();
	float scale = p_energy * float(Math::PI) * (p_negative ? -1.0f : 1.0f);
	if (p_normalize_energy) {
		scale /= area;
	}
	return Vector3(linear.r * scale, linear.g * scale, linear.b * scale);
}

// Fills the world frame from world_from_light. Scale is ignored (a light's scale does not change its
// size, as for every Godot light): the axes are normalised columns of the basis.
inline void area_light_set_frame(AreaLightData &r_light, const Transform3D &p_world_from_light) {
	r_light.center = p_world_from_light.origin;
	const Vector3 x = p_world_from_light.basis.get_column(0).normalized();
	const Vector3 y = p_world_from_light.basis.get_column(1).normalized();
	const Vector3 z = p_world_from_light.basis.get_column(2).normalized();
	r_light.axis_x = x == Vector3() ? Vector3(1, 0, 0) : x;
	r_light.axis_y = y == Vector3() ? Vector3(0, 1, 0) : y;
	r_light.emit_dir = z == Vector3() ? Vector3(0, 0, -1) : -z;
}

// Signed distance of p in front of the light plane (> 0 on the lit side).
inline float area_light_front_distance(const AreaLightData &p_light, const Vector3 &p_point) {
	return (p_point - p_light.center).dot(p_light.emit_dir);
}

// Distance from p to the closest point of the shape (metres). Disk: the plane point pulled radially onto
// the ellipse (exact for circles), as the GPU's area_shape_distance (area_light_shapes_inc.glsl).
inline float area_light_closest_distance(const AreaLightData &p_light, const Vector3 &p_point) {
	const Vector3 rel = p_point - p_light.center;
	if (p_light.shape == AREA_LIGHT_SHAPE_SPHERE) {
		return std::max(rel.length() - 0.5f * p_light.size_x, 0.0f);
	}
	if (p_light.shape == AREA_LIGHT_SHAPE_TUBE) {
		const float t = std::clamp(rel.dot(p_light.axis_x), -0.5f * p_light.size_x, 0.5f * p_light.size_x);
		return std::max((rel - p_light.axis_x * t).length() - 0.5f * p_light.size_y, 0.0f);
	}
	if (p_light.shape == AREA_LIGHT_SHAPE_DISK) {
		const float a = 0.5f * p_light.size_x, b = 0.5f * p_light.size_y;
		if (!(a > 0.0f) || !(b > 0.0f)) {
			return rel.length();
		}
		float u = rel.dot(p_light.axis_x) / a, v = rel.dot(p_light.axis_y) / b;
		const float k = std::sqrt(u * u + v * v);
		if (k > 1.0f) {
			u /= k;
			v /= k;
		}
		return (rel - p_light.axis_x * (u * a) - p_light.axis_y * (v * b)).length();
	}
	const float u = rel.dot(p_light.axis_x);
	const float v = rel.dot(p_light.axis_y);
	const float w = rel.dot(p_light.emit_dir);
	const float du = std::max(std::fabs(u) - 0.5f * p_light.size_x, 0.0f);
	const float dv = std::max(std::fabs(v) - 0.5f * p_light.size_y, 0.0f);
	return std::sqrt(du * du + dv * dv + w * w);
}

// Distance attenuation of upstream Godot 4.7's area light, a = area_attenuation a distance exponent:
// W(d) = max(1 - (d / r)^4, 0)^2 * max(d, 1e-4)^(2 - a). The integral over the rectangle already
// falls off as the inverse square, so a = 2 is physical (window only). Exactly 0 for d >= r (and for
// r <= 0). Unitless.
inline float area_light_window(float p_distance, float p_range, float p_attenuation) {
	if (!(p_range > 0.0f) || !(p_distance < p_range)) {
		return 0.0f;
	}
	float nd = p_distance / p_range;
	nd *= nd;
	nd *= nd; // (d / r)^4
	float window = std::max(1.0f - nd, 0.0f);
	window *= window;
	if (p_attenuation == 2.0f) {
		return window;
	}
	return window * std::pow(std::max(p_distance, 1e-4f), 2.0f - p_attenuation);
}

} // namespace ReferenceBRDF
