/**************************************************************************/
/*  area_light_integrator.h                                               */
/**************************************************************************/
/* godot-area: the reference renderer's estimator of one area light at    */
/* one surface point,                                                     */
/*   L_o = W(d) * integral over the rectangle of f(l, v) L_e (n.l) dw,    */
/* (units and W: area_light.h). Strategies (AreaLightSampling):           */
/*  - AREA: uniform over the rectangle's area (the first reference);      */
/*  - SOLID_ANGLE: uniform over the rectangle's solid angle (Urena,       */
/*    Fajardo and King 2013, "An Area-Preserving Parametrization for      */
/*    Spherical Rectangles"), ideal for the Lambert term;                 */
/*  - MIS (default): multiple importance sampling (Veach 1997, power      */
/*    heuristic, one sample per strategy and evaluation) of the whole     */
/*    BRDF (diffuse + specular) with (1) solid-angle samples of the       */
/*    light, (2) BRDF samples: a mixture of cosine-weighted directions    */
/*    (the diffuse lobe, for lights covering much of the hemisphere) and  */
/*    samples of the GGX distribution of visible normals (Heitz 2018,     */
/*    "Sampling the GGX Distribution of Visible Normals", alpha =         */
/*    roughness^2, exact Smith G1), and (3) solid-angle samples of a      */
/*    "lobe window", the part of the light around where the mirror        */
/*    direction meets its plane, used when that point misses the light    */
/*    (the lobe's tail reaches over an edge; GGX samples rarely hit it).  */
/*    Every sample is weighted by the EXACT C++ twin BRDF (brdf.h,        */
/*    Hammon's V): the pdfs are only proposals, so the estimator is       */
/*    unbiased for the engine's BRDF;                                     */
/*  - BRDF: specular by VNDF samples only (a cross-check for tests).      */
/* Samples are stratified (each strategy's own), rounds run until the     */
/* relative standard error target or the cap (integrate_adaptive_points). */
/* Shadows: a callback per sample (light samples: towards the sampled     */
/* point; BRDF samples: towards the point where the ray hits the          */
/* rectangle; a BRDF ray that misses it contributes 0).                   */

#pragma once

#include "modules/reference/area_light.h"
#include "modules/reference/brdf.h"
#include "modules/reference/sampling.h"

#include <cstdint>
#include <functional>

namespace ReferenceBRDF {

enum AreaLightSampling : uint32_t {
	AREA_LIGHT_SAMPLING_AREA = 0, // Uniform over the area (light samples only).
	AREA_LIGHT_SAMPLING_SOLID_ANGLE = 1, // Uniform over the solid angle (light samples only).
	AREA_LIGHT_SAMPLING_MIS = 2, // Solid angle + cosine/GGX VNDF + lobe window, power heuristic (default).
	AREA_LIGHT_SAMPLING_BRDF = 3, // Specular from GGX VNDF samples only; diffuse from solid angle.
};

// Shading inputs of one surface point, shared by every sample of an area-light integral.
struct AreaLightShadingPoint {
	Vector3 vertex; // World position.
	Vector3 N; // Shading normal (unit).
	Vector3 V; // Towards the eye (unit).
	Vector3 ng; // Geometric normal (unit), for the shadow-ray offset.
	float offset = 0.0f; // Shadow-ray origin offset (m).
	uint32_t diffuse_mode = BRDF_DIFFUSE_BURLEY;
	float roughness = 1.0f; // Perceptual; GGX alpha = roughness^2.
	Vector3 f0;
	float f90 = 1.0f;
	bool specular_enabled = true;
	Vector3 diffuse_weight; // albedo * (1 - metallic): what the diffuse sum is multiplied by.
};

// Result of one integral.
struct AreaLightIntegral {
	Vector3 radiance; // W(d) * integral: diffuse (already times diffuse_weight) + specular.
	double relative_error = 0.0; // max over channels of standard error / |value| (0 when exact or under the floor).
	int samples = 0; // Directions evaluated (light samples + BRDF samples).
	bool evaluated = false; // False: exactly 0 without sampling (behind the light, out of range, zero size).
	bool converged = true; // False when the cap stopped the integral before the error target.
	bool brdf_sampling = false; // True when GGX samples were used (MIS / BRDF on a specular lobe).
	uint64_t shadow_rays = 0;
};

// True when the segment from p_origin along unit p_dir up to p_max_distance is blocked.
typedef std::function<bool(const Vector3 &p_origin, const Vector3 &p_dir, float p_max_distance)> AreaLightOcclusionTest;

// Estimates the area light at p_point. p_settings.max_samples caps the DIRECTIONS (one MIS evaluation
// draws one per strategy: two or three);
// p_occluded may be empty (no shadows). Deterministic for a given r_rng state.
AreaLightIntegral area_light_integrate(const AreaLightData &p_light, const AreaLightShadingPoint &p_point, AreaLightSampling p_sampling, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng, const AreaLightOcclusionTest &p_occluded = AreaLightOcclusionTest());

// Uniform sampling of the solid angle of a rectangle seen from a point (Urena et al. 2013), in double
// precision. setup() returns false when the point is (nearly) in the rectangle's plane or the solid
// angle is too small to compute accurately (callers then sample the area instead).
class SphericalRectangleSampler {
	double origin[3] = {};
	double ax[3] = {}, ay[3] = {}, az[3] = {}; // Local frame: rectangle edges and the normal away from the origin's side.
	double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0, z0 = 0.0;
	double b0 = 0.0, b1 = 0.0, k = 0.0, solid_angle = 0.0;

public:
	bool setup(const Vector3 &p_origin, const Vector3 &p_corner, const Vector3 &p_edge_x, const Vector3 &p_edge_y);
	// Steradians (valid after a successful setup()).
	double get_solid_angle() const { return solid_angle; }
	// The world point on the rectangle for (u, v) in [0,1]^2; uniform (u, v) give directions uniform in
	// the solid angle (pdf 1 / get_solid_angle()).
	void sample(double p_u, double p_v, double r_point[3]) const;
};

// GGX (isotropic, alpha) distribution of visible normals for the unit view p_v in a frame whose z is
// the normal (p_v[2] > 0): returns the unit microfacet normal for (u1, u2) in [0,1)^2 (Heitz 2018).
void ggx_vndf_sample_normal(const double p_v[3], double p_alpha, double p_u1, double p_u2, double r_h[3]);
// Solid-angle pdf of the direction reflected about a VNDF normal: G1(v) D(h) / (4 n.v), with h the half
// vector, D the GGX distribution and G1 Smith's exact masking for GGX. p_noh2_complement = 1 - (n.h)^2
// (passed separately for precision); 0 when n.h <= 0 or n.v <= 0.
double ggx_vndf_reflection_pdf(double p_nov, double p_noh, double p_noh2_complement, double p_alpha);

} // namespace ReferenceBRDF
