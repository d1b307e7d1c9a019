/**************************************************************************/
/*  reference_light_sampling.h                                            */
/**************************************************************************/
/* godot-area: the reference renderer's per-light estimators at one       */
/* shading point -- visibility rays, the area light's adaptive integral   */
/* (area_light_integrator.h / area_light_shapes.h), the sun's disk and    */
/* the sky as an environment light for the diffuse and specular lobes.    */
/* Used by ReferenceRenderer::_shade_ray (reference_renderer.cpp).        */

#pragma once

#include "modules/reference/reference_renderer.h"

#include <embree3/rtcore.h>

namespace ReferenceBRDF {

// True when a segment from p_origin along unit p_dir up to p_tfar hits any surface (both faces).
bool reference_occluded(RTCScene p_scene, const Vector3 &p_origin, const Vector3 &p_dir, float p_tfar);

// Outgoing radiance at the shading point from one area light, added to r_radiance: the estimator of
// area_light_integrator.h (options.area_sampling; MIS by default) with the adaptive stopping rule of
// the options, and one shadow ray per sample (Embree) when shadows are on.
void reference_shade_area_light(RTCScene p_scene, const ReferenceRenderOptions &p_options, const AreaLightData &p_light, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays, uint64_t &r_samples, uint64_t &r_integrals, uint64_t &r_converged, float &r_max_relative_error, Vector3 &r_radiance);

// One directional light: the mean of light_compute() over jittered strata of the sun disk (sun_light.h), one
// shadow ray per sample (to infinity) when shadows are on and the light has shadow_enabled. Accumulates like a punctual light.
void reference_shade_sun(RTCScene p_scene, const ReferenceRenderOptions &p_options, const DirectionalLightData &p_sun, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays, Vector3 &r_diffuse, Vector3 &r_specular);

// Sky ambient at the shading point: E(N) / pi of the sky (the Lambert radiance factor the GPU's SH ambient
// approximates), estimated with options.sky_samples directions drawn from the sky's luminance (sky_light.h),
// stratified along the distribution; shadow rays only when shadows are on (the GPU has no ambient occlusion).
Vector3 reference_sky_irradiance(RTCScene p_scene, const ReferenceRenderOptions &p_options, const ReferenceSkyLight &p_sky, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays);

// Sky reflections at the shading point: the exact integral of sky(L) f_spec(L, V) (N.L) over the hemisphere,
// with the specular BRDF of the GPU's direct lights (brdf.h: GGX D, Hammon's V, Schlick F), estimated with
// options.sky_samples half vectors drawn from D(H) (N.H) on a jittered grid (Walter et al. 2007, eq. 35-36),
// pdf(L) = D (N.H) / (4 V.H). The estimator f (N.L) / pdf = 4 F V_vis (N.L) (V.H) / (N.H) has no D in it, so
// it stays exact for a mirror (roughness 0). Shadow rays only when shadows are on.
Vector3 reference_sky_specular(RTCScene p_scene, const ReferenceRenderOptions &p_options, const ReferenceSkyLight &p_sky, const AreaLightShadingPoint &p_point, ReferenceRNG &r_rng, uint64_t &r_shadow_rays);

} // namespace ReferenceBRDF
