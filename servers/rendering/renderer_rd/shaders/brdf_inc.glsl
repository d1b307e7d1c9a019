/**************************************************************************/
/*  brdf_inc.glsl                                                         */
/**************************************************************************/
/* The surface BRDF of the Forward+ renderer: the thesis' section 2.3     */
/* model (Cook-Torrance GGX specular + Lambert or Burley diffuse), with   */
/* Filament-style names (D_ distribution, V_ visibility, F_ Fresnel,      */
/* Fd_ diffuse) and dot products named NoL, NoV, NoH, LoH.                */
/*                                                                        */
/* Three parts, as Filament's brdf.fs: configuration (constants and the   */
/* diffuse model switch), implementations (one function per equation),   */
/* dispatch (the only functions callers use: brdf_specular/brdf_diffuse). */
/*                                                                        */
/* Roughness convention (Godot's): materials store PERCEPTUAL roughness   */
/* r in [0, 1]. The GGX terms D and V take alpha = r * r (Burley/Disney   */
/* remapping); the Burley diffuse term takes r itself, as Godot 4 does.   */
/*                                                                        */
/* Must match: BRDF_DIFFUSE_* = RenderForwardClustered::DiffuseMode       */
/* (servers/rendering/renderer_rd/forward_clustered/                      */
/* render_forward_clustered.h).                                           */

#ifndef BRDF_INC_GLSL
#define BRDF_INC_GLSL

/*************************************************************************/
/* Configuration                                                         */
/*************************************************************************/

#define M_PI 3.14159265358979323846

// Diffuse model, per material (RenderForwardClustered::DiffuseMode).
#define BRDF_DIFFUSE_BURLEY 0 // Default, as Godot's "diffuse_burley" render mode.
#define BRDF_DIFFUSE_LAMBERT 1

/*************************************************************************/
/* Implementations                                                       */
/*************************************************************************/

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering".
// Thesis equation (2.4): F = f0 + (f90 - f0) (1 - u)^5, with u = v.h (or n.l, n.v for Burley).
// Returns the reflectance (unitless) per channel.
vec3 F_Schlick(vec3 f0, float f90, float u) {
	float m = clamp(1.0 - u, 0.0, 1.0);
	float m2 = m * m;
	float m5 = m2 * m2 * m;
	return f0 + (vec3(f90) - f0) * m5;
}

// Scalar version of equation (2.4), used by the Burley diffuse term.
float F_Schlick(float f0, float f90, float u) {
	float m = clamp(1.0 - u, 0.0, 1.0);
	float m2 = m * m;
	float m5 = m2 * m2 * m;
	return f0 + (f90 - f0) * m5;
}

// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (GGX / Trowbridge-Reitz),
// in the form of Guy and Agopian 2018 (thesis [12]). Thesis equation (2.6):
//   D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2).
// The thesis prints (n.h)(alpha^2-1); the GGX NDF squares n.h, as Godot's and Filament's code do.
// alpha = perceptual_roughness^2. Returns a density per steradian (1/sr).
float D_GGX(float NoH, float alpha) {
	float a2 = alpha * alpha;
	float f = NoH * NoH * (a2 - 1.0) + 1.0;
	return a2 / (M_PI * f * f);
}

// Hammon 2017, "PBR Diffuse Lighting for GGX+Smith Microsurfaces" (GDC): a fast approximation of the
// height-correlated Smith masking-shadowing term that already contains the 1 / (4 (n.l)(n.v)) of
// equation (2.3). Thesis equation (2.5):
//   V = 0.5 / ((1 - alpha) 2 (n.l)(n.v) + alpha ((n.l) + (n.v)))  = 0.5 / mix(2 NoL NoV, NoL + NoV, alpha).
// Unitless. The denominator is > 0 whenever NoL, NoV > 0 (callers clamp them).
float V_SmithGGXCorrelatedFast(float NoV, float NoL, float alpha) {
	return 0.5 / mix(2.0 * NoL * NoV, NoL + NoV, alpha);
}

// Lambert 1760: the ideal diffuse reflector. f_d = 1 / pi (1/sr); the albedo is applied by the caller.
float Fd_Lambert() {
	return 1.0 / M_PI;
}

// Burley 2012, "Physically-Based Shading at Disney". Thesis equation (2.8):
//   f_d = 1/pi F(n, l, 1, f90) F(n, v, 1, f90), f90 = 0.5 + 2 r (l.h)^2.
// Godot 4 feeds the perceptual roughness r here (not alpha); we do the same. Returns 1/sr.
float Fd_Burley(float NoV, float NoL, float LoH, float perceptual_roughness) {
	float f90 = 0.5 + 2.0 * perceptual_roughness * LoH * LoH;
	float light_scatter = F_Schlick(1.0, f90, NoL);
	float view_scatter = F_Schlick(1.0, f90, NoV);
	return light_scatter * view_scatter * (1.0 / M_PI);
}

/*************************************************************************/
/* Dispatch                                                              */
/*************************************************************************/

// f90 used with equation (2.4) for the specular lobe: Filament's/Godot's "specular occlusion" trick,
// f90 = saturate(dot(f0, 50 * 0.33)): reflectances below 2 % (no real material) fade the grazing
// Fresnel peak out, so specular = 0 with f0 = 0 exactly. Godot additionally keeps metals >= metallic.
float brdf_specular_f90(vec3 f0, float metallic) {
	return clamp(dot(f0, vec3(50.0 * 0.33)), metallic, 1.0);
}

// Specular BRDF of equation (2.7): f_r = D V F (1/sr, per channel). Multiply by NoL and the light's
// radiance-like colour to get reflected radiance.
vec3 brdf_specular(float NoV, float NoL, float NoH, float LoH, float perceptual_roughness, vec3 f0, float f90) {
	float alpha = perceptual_roughness * perceptual_roughness;
	float D = D_GGX(NoH, alpha);
	float V = V_SmithGGXCorrelatedFast(NoV, NoL, alpha);
	vec3 F = F_Schlick(f0, f90, LoH);
	return D * V * F;
}

// Split-sum environment BRDF (the second sum of Karis 2013), in Karis' analytic fit of the pre-integrated
// GGX DFG table: "Physically Based Shading on Mobile" (Unreal Engine blog, 2014), after Lazarov 2013 (the
// fit Godot 4 uses). Returns the directional albedo of the specular lobe for reflectance f0 / f90 at NoV,
// given the PERCEPTUAL roughness; multiply by the prefiltered radiance along the reflection vector.
vec3 brdf_env_approx(vec3 f0, float f90, float NoV, float perceptual_roughness) {
	const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
	const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
	vec4 r = perceptual_roughness * c0 + c1;
	float a004 = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
	vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
	return f0 * ab.x + vec3(f90 * ab.y);
}

// Diffuse BRDF without the albedo (1/sr). p_mode is BRDF_DIFFUSE_*.
float brdf_diffuse(uint p_mode, float NoV, float NoL, float LoH, float perceptual_roughness) {
	if (p_mode == BRDF_DIFFUSE_LAMBERT) {
		return Fd_Lambert();
	}
	return Fd_Burley(NoV, NoL, LoH, perceptual_roughness);
}

#endif // BRDF_INC_GLSL
