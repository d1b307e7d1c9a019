/**************************************************************************/
/*  reference_light_sampling.cpp                                          */
/**************************************************************************/

#include "modules/reference/reference_light_sampling.h"

#include "core/math/math_funcs.h"
#include "modules/reference/area_light_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ReferenceBRDF {

// True when a segment from p_origin along unit p_dir up to p_tfar hits any surface (both faces).
bool reference_occluded(RTCScene p_scene, const Vector3 &p_origin, const Vector3 &p_dir, float p_tfar) {
	RTCRay ray;
	ray.org_x = p_origin.x;
	ray.org_y = p_origin.y;
	ray.org_z = p_origin.z;
	ray.dir_x = p_dir.x;
	ray.dir_y = p_dir.y;
	ray.dir_z = p_dir.z;
	ray.tnear = 0.0f;
	ray.tfar = p_tfar;
	ray.time = 0.0f;
	ray.mask = 0xFFFFFFFF;
	ray.id = 0;
	ray.flags = 0;
	RTCIntersectContext context;
	rtcInitIntersectContext(&context);
	rtcOccluded1(p_scene, &context, &ray);
	return ray.tfar < 0.0f; // Embree sets tfar to -inf on a hit.
}

// Outgoing radiance at the shading point from one area light, added to r_radiance: the estimator of
// area_light_integrator.h (options.area_sampling; MIS by default) with the adaptive stopping rule of
// the options, and one shadow ray per sample (Embree) when shadows are on.
void reference_shade_area_light(RTCScene p_scene, const ReferenceRenderOptions &p_options, const AreaLightData &p_light, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays, uint64_t &r_samples, uint64_t &r_integrals, uint64_t &r_converged, float &r_max_relative_error, Vector3 &r_radiance) {
	AdaptiveIntegrationSettings settings;
	settings.max_samples = std::max(p_options.max_samples, 1);
	settings.target_relative_error = p_options.target_relative_error;
	AreaLightOcclusionTest occluded;
	if (p_options.shadows) {
		occluded = [p_scene](const Vector3 &p_origin, const Vector3 &p_dir, float p_max_distance) {
			return reference_occluded(p_scene, p_origin, p_dir, p_max_distance);
		};
	}
	// Disks, spheres and tubes: their own estimator (real shape geometry, MIS of shape and BRDF samples).
	const AreaLightIntegral integral = p_light.shape == AREA_LIGHT_SHAPE_RECTANGLE ? area_light_integrate(p_light, p_point, p_options.area_sampling, settings, r_rng, occluded)
																				   : area_light_shape_integrate(p_light, p_point, settings, r_rng, occluded);
	if (!integral.evaluated) {
		return;
	}
	r_shadow_rays += integral.shadow_rays;
	r_samples += uint64_t(integral.samples);
	r_integrals++;
	r_converged += integral.converged ? 1 : 0;
	r_max_relative_error = std::max(r_max_relative_error, float(integral.relative_error));
	r_radiance += integral.radiance;
}

// One directional light: the mean of light_compute() over jittered strata of the sun disk (sun_light.h), one
// shadow ray per sample (to infinity) when shadows are on and the light has shadow_enabled. Accumulates like a punctual light.
void reference_shade_sun(RTCScene p_scene, const ReferenceRenderOptions &p_options, const DirectionalLightData &p_sun, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays, Vector3 &r_diffuse, Vector3 &r_specular) {
	int strata = 1;
	if (p_sun.size > 0.0f) {
		strata = std::max(1, int(std::sqrt(double(std::max(p_options.sun_samples, 1)))));
	}
	const int count = strata * strata;
	const Vector3 weight = p_sun.size > 0.0f ? sun_sample_weight(p_sun, count) : p_sun.color;
	for (int i = 0; i < count; i++) {
		Vector3 L = -p_sun.direction;
		if (p_sun.size > 0.0f) {
			const double u = (double(i % strata) + r_rng.next_double()) / strata;
			const double v = (double(i / strata) + r_rng.next_double()) / strata;
			L = sun_sample_direction(p_sun, u, v);
		}
		if (p_point.N.dot(L) <= 0.0f) {
			continue;
		}
		if (p_options.shadows && p_sun.shadow) { // As the GPU: only a sun with shadow_enabled casts shadows.
			const Vector3 side = p_point.ng.dot(L) >= 0.0f ? p_point.ng : -p_point.ng;
			r_shadow_rays++;
			if (reference_occluded(p_scene, p_point.vertex + side * p_point.offset, L, std::numeric_limits<float>::infinity())) {
				continue;
			}
		}
		light_compute(p_point.N, L, p_point.V, weight, p_sun.specular_amount, p_point.diffuse_mode, p_point.roughness, p_point.f0, p_point.f90, p_point.specular_enabled, r_diffuse, r_specular);
	}
}

// Sky ambient at the shading point: E(N) / pi of the sky (the Lambert radiance factor the GPU's SH ambient
// approximates), estimated with options.sky_samples directions drawn from the sky's luminance (sky_light.h),
// stratified along the distribution; shadow rays only when shadows are on (the GPU has no ambient occlusion).
Vector3 reference_sky_irradiance(RTCScene p_scene, const ReferenceRenderOptions &p_options, const ReferenceSkyLight &p_sky, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays) {
	const int count = std::max(p_options.sky_samples, 1);
	Vector3 sum;
	for (int i = 0; i < count; i++) {
		double pdf = 0.0;
		const Vector3 dir = p_sky.sample((double(i) + r_rng.next_double()) / count, r_rng.next_double(), pdf);
		const float cos_n = p_point.N.dot(dir);
		if (cos_n <= 0.0f || !(pdf > 0.0)) {
			continue;
		}
		if (p_options.shadows) {
			const Vector3 side = p_point.ng.dot(dir) >= 0.0f ? p_point.ng : -p_point.ng;
			r_shadow_rays++;
			if (reference_occluded(p_scene, p_point.vertex + side * p_point.offset, dir, std::numeric_limits<float>::infinity())) {
				continue;
			}
		}
		sum += p_sky.evaluate(dir) * float(double(cos_n) / (Math::PI * pdf));
	}
	return sum / float(count);
}

// Sky reflections at the shading point: the exact integral of sky(L) f_spec(L, V) (N.L) over the hemisphere,
// with the specular BRDF of the GPU's direct lights (brdf.h: GGX D, Hammon's V, Schlick F), estimated with
// options.sky_samples half vectors drawn from D(H) (N.H) on a jittered grid (Walter et al. 2007, eq. 35-36),
// pdf(L) = D (N.H) / (4 V.H). The estimator f (N.L) / pdf = 4 F V_vis (N.L) (V.H) / (N.H) has no D in it, so
// it stays exact for a mirror (roughness 0). Shadow rays only when shadows are on.
Vector3 reference_sky_specular(RTCScene p_scene, const ReferenceRenderOptions &p_options, const ReferenceSkyLight &p_sky, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays) {
	using namespace ReferenceBRDF;
	const int grid = std::max(int(std::sqrt(double(std::max(p_options.sky_samples, 1)))), 1);
	const int count = grid * grid;
	const Vector3 &N = p_point.N;
	const Vector3 &V = p_point.V;
	const float NoV = std::max(N.dot(V), 1e-4f);
	const float alpha = p_point.roughness * p_point.roughness;
	const float a2 = alpha * alpha;
	const Vector3 axis = std::fabs(N.y) < 0.999f ? Vector3(0, 1, 0) : Vector3(1, 0, 0);
	const Vector3 T = axis.cross(N).normalized();
	const Vector3 B = N.cross(T);
	Vector3 sum;
	for (int i = 0; i < count; i++) {
		const double u = (double(i / grid) + r_rng.next_double()) / grid;
		const double v = (double(i % grid) + r_rng.next_double()) / grid;
		const double cos_h = std::sqrt((1.0 - u) / (1.0 + (double(a2) - 1.0) * u));
		const double sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
		const double phi = 2.0 * Math::PI * v;
		const Vector3 H = (T * float(sin_h * std::cos(phi)) + B * float(sin_h * std::sin(phi)) + N * float(cos_h)).normalized();
		const float VoH = V.dot(H);
		if (VoH <= 0.0f) {
			continue;
		}
		const Vector3 L = (H * (2.0f * VoH) - V).normalized();
		const float NoL = N.dot(L);
		const float NoH = std::max(N.dot(H), 1e-6f);
		if (NoL <= 0.0f) {
			continue;
		}
		if (p_options.shadows) {
			const Vector3 side = p_point.ng.dot(L) >= 0.0f ? p_point.ng : -p_point.ng;
			r_shadow_rays++;
			if (reference_occluded(p_scene, p_point.vertex + side * p_point.offset, L, std::numeric_limits<float>::infinity())) {
				continue;
			}
		}
		const Vector3 F = F_Schlick(p_point.f0, p_point.f90, glsl_clamp(L.dot(H), 0.0f, 1.0f));
		const float vis = V_SmithGGXCorrelatedFast(NoV, NoL, alpha);
		sum += p_sky.evaluate(L) * F * (4.0f * vis * NoL * VoH / NoH);
	}
	return sum / float(count);
}

} // namespace ReferenceBRDF
