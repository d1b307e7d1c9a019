/**************************************************************************/
/*  brdf.h                                                                */
/**************************************************************************/
/* godot-area: the C++ twin of servers/rendering/renderer_rd/shaders/brdf_inc.glsl (the surface BRDF of */
/* the Forward+ renderer), used by the CPU reference renderer. Same       */
/* function names, same argument order, same float arithmetic, so the     */
/* reference renderer shades with provably the same BRDF as the GPU       */
/* (tests/modules/test_brdf_twin.cpp evaluates both and compares).        */
/*                                                                        */
/* Mirrors servers/rendering/renderer_rd/shaders/brdf_inc.glsl as committed in b2cf7ce (md5           */
/* 9739e369...). Any change there must be made here too; the twin test    */
/* (tests/modules/test_brdf_twin.cpp) fails otherwise.                    */
/*                                                                        */
/* Roughness convention (Godot's): perceptual roughness r in [0, 1]; GGX  */
/* D and V take alpha = r * r, Burley diffuse takes r.                    */

#pragma once

#include "core/math/vector3.h"

#include <algorithm>
#include <cmath>

namespace ReferenceBRDF {

/*************************************************************************/
/* Configuration (must match servers/rendering/renderer_rd/shaders/brdf_inc.glsl)                      */
/*************************************************************************/

// M_PI of brdf_inc.glsl, rounded to float as the GLSL constant is.
static constexpr float BRDF_PI = 3.14159265358979323846f;

// Diffuse model per material. Must match BRDF_DIFFUSE_* (brdf_inc.glsl) and
// RenderForwardClustered::DiffuseMode.
enum DiffuseMode : uint32_t {
	BRDF_DIFFUSE_BURLEY = 0,
	BRDF_DIFFUSE_LAMBERT = 1,
};

/*************************************************************************/
/* GLSL built-ins with GLSL semantics                                    */
/*************************************************************************/

inline float glsl_clamp(float p_x, float p_lo, float p_hi) {
	return std::min(std::max(p_x, p_lo), p_hi);
}

// GLSL mix(x, y, a) = x * (1 - a) + y * a (GLSL 4.50 spec, 8.3).
inline float glsl_mix(float p_x, float p_y, float p_a) {
	return p_x * (1.0f - p_a) + p_y * p_a;
}

/*************************************************************************/
/* Implementations                                                       */
/*************************************************************************/

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering".
// Thesis equation (2.4): F = f0 + (f90 - f0) (1 - u)^5. Returns reflectance per channel (unitless).
inline Vector3 F_Schlick(const Vector3 &f0, float f90, float u) {
	float m = glsl_clamp(1.0f - u, 0.0f, 1.0f);
	float m2 = m * m;
	float m5 = m2 * m2 * m;
	return f0 + (Vector3(f90, f90, f90) - f0) * m5;
}

// Scalar version of equation (2.4), used by the Burley diffuse term.
inline float F_Schlick(float f0, float f90, float u) {
	float m = glsl_clamp(1.0f - u, 0.0f, 1.0f);
	float m2 = m * m;
	float m5 = m2 * m2 * m;
	return f0 + (f90 - f0) * m5;
}

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (GGX). Thesis (2.6):
//   D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), alpha = perceptual_roughness^2. Returns 1/sr.
inline float D_GGX(float NoH, float alpha) {
	float a2 = alpha * alpha;
	float f = NoH * NoH * (a2 - 1.0f) + 1.0f;
	return a2 / (BRDF_PI * f * f);
}

// Hammon 2017, "PBR Diffuse Lighting for GGX+Smith Microsurfaces": fast height-correlated Smith term
// including 1 / (4 (n.l)(n.v)). Thesis (2.5): V = 0.5 / mix(2 NoL NoV, NoL + NoV, alpha). Unitless.
inline float V_SmithGGXCorrelatedFast(float NoV, float NoL, float alpha) {
	return 0.5f / glsl_mix(2.0f * NoL * NoV, NoL + NoV, alpha);
}

// Lambert 1760: f_d = 1 / pi (1/sr); the albedo is applied by the caller.
inline float Fd_Lambert() {
	return 1.0f / BRDF_PI;
}

// Burley 2012, "Physically-Based Shading at Disney". Thesis (2.8):
//   f_d = 1/pi F(n, l, 1, f90) F(n, v, 1, f90), f90 = 0.5 + 2 r (l.h)^2, r perceptual. Returns 1/sr.
inline float Fd_Burley(float NoV, float NoL, float LoH, float perceptual_roughness) {
	float f90 = 0.5f + 2.0f * perceptual_roughness * LoH * LoH;
	float light_scatter = F_Schlick(1.0f, f90, NoL);
	float view_scatter = F_Schlick(1.0f, f90, NoV);
	return light_scatter * view_scatter * (1.0f / BRDF_PI);
}

/*************************************************************************/
/* Dispatch                                                              */
/*************************************************************************/

// f90 of the specular lobe: clamp(dot(f0, 50 * 0.33), metallic, 1) (Filament/Godot specular occlusion).
inline float brdf_specular_f90(const Vector3 &f0, float metallic) {
	float s = 50.0f * 0.33f;
	return glsl_clamp(f0.x * s + f0.y * s + f0.z * s, metallic, 1.0f);
}

// Specular BRDF of equation (2.7): f_r = D V F (1/sr, per channel).
inline Vector3 brdf_specular(float NoV, float NoL, float NoH, float LoH, float perceptual_roughness, const Vector3 &f0, float f90) {
	float alpha = perceptual_roughness * perceptual_roughness;
	float D = D_GGX(NoH, alpha);
	float V = V_SmithGGXCorrelatedFast(NoV, NoL, alpha);
	Vector3 F = F_Schlick(f0, f90, LoH);
	return F * (D * V);
}

// Diffuse BRDF without the albedo (1/sr). p_mode is BRDF_DIFFUSE_*.
inline float brdf_diffuse(uint32_t p_mode, float NoV, float NoL, float LoH, float perceptual_roughness) {
	if (p_mode == BRDF_DIFFUSE_LAMBERT) {
		return Fd_Lambert();
	}
	return Fd_Burley(NoV, NoL, LoH, perceptual_roughness);
}

} // namespace ReferenceBRDF
