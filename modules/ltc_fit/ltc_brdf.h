/**************************************************************************/
/*  ltc_brdf.h                                                            */
/**************************************************************************/
/* godot-area: the two GGX specular BRDFs the LTC tables are fitted to    */
/* (thesis section 5.4.1 and 5.4.2), evaluated in double precision in the */
/* local shading frame (normal = +z).                                     */
/*                                                                        */
/* LTC_BRDF_ENGINE_GGX: the engine's lobe exactly as                      */
/*   servers/rendering/renderer_rd/shaders/brdf_inc.glsl brdf_specular() computes it with F = 1:        */
/*   D_GGX (thesis eq. 2.6) * V_SmithGGXCorrelatedFast (Hammon 2017,      */
/*   eq. 2.5), alpha = perceptual_roughness^2. The functions below have   */
/*   the GLSL names and formulas; keep them in sync with brdf_inc.glsl.   */
/* LTC_BRDF_SMITH_GGX: GGX with the exact height-correlated Smith term    */
/*   (Heitz 2014): Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2,  */
/*   G2 = 1 / (1 + Lambda(v) + Lambda(l)), f = D G2 / (4 NoL NoV).        */
/*                                                                        */
/* Both return f(v, l) in 1/sr WITHOUT the cosine NoL, and 0 when l or v  */
/* is at or below the horizon.                                            */

#pragma once

#include <algorithm>
#include <cmath>

enum LTCBRDFVariant {
	LTC_BRDF_ENGINE_GGX = 0,
	LTC_BRDF_SMITH_GGX = 1,
	LTC_BRDF_MAX,
};

namespace LTCBRDF {

static constexpr double BRDF_PI = 3.14159265358979323846;

inline const char *get_variant_name(LTCBRDFVariant p_variant) {
	return p_variant == LTC_BRDF_ENGINE_GGX ? "engine" : "smith";
}

// GLSL mix(x, y, a) = x * (1 - a) + y * a.
inline double glsl_mix(double p_x, double p_y, double p_a) {
	return p_x * (1.0 - p_a) + p_y * p_a;
}

// brdf_inc.glsl D_GGX, thesis eq. (2.6): D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2). 1/sr.
inline double D_GGX(double NoH, double alpha) {
	double a2 = alpha * alpha;
	double f = NoH * NoH * (a2 - 1.0) + 1.0;
	return a2 / (BRDF_PI * f * f);
}

// brdf_inc.glsl V_SmithGGXCorrelatedFast (Hammon 2017), thesis eq. (2.5); contains 1 / (4 NoL NoV).
inline double V_SmithGGXCorrelatedFast(double NoV, double NoL, double alpha) {
	return 0.5 / glsl_mix(2.0 * NoL * NoV, NoL + NoV, alpha);
}

// Heitz 2014, Smith Lambda of GGX for a direction with cos(theta) = p_cos_theta > 0.
inline double Lambda_GGX(double p_cos_theta, double alpha) {
	double c2 = p_cos_theta * p_cos_theta;
	double tan2 = std::max(0.0, 1.0 - c2) / c2;
	return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

// Heitz 2014 height-correlated masking-shadowing G2 = 1 / (1 + Lambda(v) + Lambda(l)).
inline double G2_SmithGGXCorrelated(double NoV, double NoL, double alpha) {
	return 1.0 / (1.0 + Lambda_GGX(NoV, alpha) + Lambda_GGX(NoL, alpha));
}

// Smith G1 masking of one direction, 1 / (1 + Lambda). Used by visible-normal sampling.
inline double G1_SmithGGX(double p_cos_theta, double alpha) {
	return 1.0 / (1.0 + Lambda_GGX(p_cos_theta, alpha));
}

// Evaluates the variant's specular lobe f(v, l) (1/sr, F = 1, no cosine) for unit v, l in the
// frame with normal +z. p_alpha is the GGX alpha (= perceptual roughness squared).
inline double evaluate(LTCBRDFVariant p_variant, const double *p_v, const double *p_l, double p_alpha) {
	const double NoV = p_v[2];
	const double NoL = p_l[2];
	if (NoV <= 0.0 || NoL <= 0.0) {
		return 0.0;
	}
	double h[3] = { p_v[0] + p_l[0], p_v[1] + p_l[1], p_v[2] + p_l[2] };
	double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
	if (hl <= 0.0) {
		return 0.0;
	}
	const double NoH = h[2] / hl;
	const double D = D_GGX(NoH, p_alpha);
	if (p_variant == LTC_BRDF_ENGINE_GGX) {
		return D * V_SmithGGXCorrelatedFast(NoV, NoL, p_alpha);
	}
	return D * G2_SmithGGXCorrelated(NoV, NoL, p_alpha) / (4.0 * NoL * NoV);
}

} // namespace LTCBRDF
