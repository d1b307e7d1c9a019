/**************************************************************************/
/*  sun_light.h                                                           */
/**************************************************************************/
/* godot-area: the DirectionalLight3D of the Embree reference: a sun disk */
/* of angular radius alpha = light_angular_distance / 2 around the        */
/* light's -Z, of uniform radiance, sampled uniformly in solid angle      */
/* (pbrt-v4 4.8 / 4.9: uniform cone sampling, cos(t) = 1 - u (1 - cos a), */
/* pdf = 1 / (2 pi (1 - cos a))).                                         */
/*                                                                        */
/* Units: the GPU's DirectionalLightData::color C = srgb_to_linear(color) */
/* * energy * pi is the irradiance at normal incidence (Godot's "energy  */
/* *= pi"). A uniform disk gives E_perp = L pi sin^2(a) (projected solid  */
/* angle of a cap), so the disk radiance is L = C / (pi sin^2 a). Over a  */
/* disk fully above the horizon the integral of cos is exactly the        */
/* centre's cos times pi sin^2 a, so Lambert receivers see C cos(theta)  */
/* like the GPU's delta direction; glossy lobes see the disk.             */
/* alpha == 0: a delta direction (one exact evaluation).                  */

#pragma once

#include "core/math/basis.h"
#include "core/math/math_funcs.h"
#include "core/math/vector3.h"

#include <cmath>
#include <cstdint>

namespace ReferenceBRDF {

// World-space twin of struct DirectionalLightData (light_data_inc.glsl).
struct DirectionalLightData {
	Vector3 direction = Vector3(0, 0, -1); // World space unit vector the light shines along.
	Vector3 color; // Linear colour * energy * pi (irradiance at normal incidence).
	float size = 0.0f; // Angular radius (radians).
	float specular_amount = 1.0f;
	uint32_t cull_mask = 0xFFFFFFFF;
	bool shadow = false;
};

// Orthonormal tangent frame around unit p_n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
inline void sun_build_frame(const Vector3 &p_n, Vector3 &r_t, Vector3 &r_b) {
	const float sign = std::copysign(1.0f, p_n.z);
	const float a = -1.0f / (sign + p_n.z);
	const float b = p_n.x * p_n.y * a;
	r_t = Vector3(1.0f + sign * p_n.x * p_n.x * a, sign * b, -sign * p_n.x);
	r_b = Vector3(b, sign + p_n.y * p_n.y * a, -p_n.y);
}

// Direction towards the sun for the unit-square point (u, v): uniform over the cap of half angle
// p_light.size around -direction.
inline Vector3 sun_sample_direction(const DirectionalLightData &p_light, double p_u, double p_v) {
	const Vector3 axis = -p_light.direction;
	const double cos_a = std::cos(double(p_light.size));
	const double cos_t = 1.0 - p_u * (1.0 - cos_a);
	const double sin_t = std::sqrt(std::fmax(0.0, 1.0 - cos_t * cos_t));
	const double phi = 2.0 * Math::PI * p_v;
	Vector3 t, b;
	sun_build_frame(axis, t, b);
	return (t * float(sin_t * std::cos(phi)) + b * float(sin_t * std::sin(phi)) + axis * float(cos_t)).normalized();
}

// Radiance of one sample, already divided by the pdf and by the sample count: what light_compute()
// gets per sample so that the mean over p_samples samples estimates the disk integral.
// C / (pi sin^2 a) * 2 pi (1 - cos a) / N = C * 2 (1 - cos a) / (sin^2 a N) = C * 2 / ((1 + cos a) N).
inline Vector3 sun_sample_weight(const DirectionalLightData &p_light, int p_samples) {
	const double cos_a = std::cos(double(p_light.size));
	return p_light.color * float(2.0 / ((1.0 + cos_a) * double(p_samples)));
}

} // namespace ReferenceBRDF
