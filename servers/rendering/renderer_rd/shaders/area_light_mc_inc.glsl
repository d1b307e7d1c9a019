/**************************************************************************/
/*  area_light_mc_inc.glsl                                                */
/**************************************************************************/
/* Rectangular area lights shaded by Monte Carlo integration (thesis      */
/* section 5.2): an UNBIASED estimate of the contract's                   */
/*   L_o = W(d) integral over the rectangle of f(l, v) L_e (n . l) dl     */
/* with the engine's own BRDF (light_compute / brdf_specular), so the     */
/* expected value equals the reference renderer's integral and the error  */
/* falls as N^-1/2 (N = area_stochastic_samples).                         */
/*                                                                        */
/* Diffuse: N directions uniform in the solid angle of the rectangle      */
/* (Urena, Fajardo and King 2013: spherical-rectangle sampling, pdf =     */
/* 1 / Omega), estimator Omega / N sum f_d(l_i) L_e (n . l_i).            */
/* Specular: multiple importance sampling (Veach 1997) of N light samples */
/* (pdf_L = 1 / Omega) and N samples of the GGX distribution of visible   */
/* normals (Heitz 2018; pdf_B(l) = G1(v) D(h) / (4 n.v), with the exact   */
/* Smith G1 of GGX; a sample counts when its ray hits the rectangle),     */
/* combined with the balance heuristic: with equal sample counts every    */
/* sample contributes f (n.l) L_e / (N (pdf_L + pdf_B)). Views from below */
/* the surface (n.v <= 0) use light samples only (pdf_B = 0).             */
/* The thesis' separate diffuse and specular sample sets are kept, with   */
/* its temporal-stability seeds: specular from the pixel coordinate,      */
/* diffuse from the world position quantized to AREA_MC_DIFFUSE_SEED_STEP */
/* metres (stable while the camera moves). Plain (unstratified) random    */
/* numbers from a PCG hash, so the RMSE slope is exactly -1/2.            */
/*                                                                        */
/* Includes area_light_common_inc.glsl (the contract's gate               */
/* area_light_rect_begin and the rectangle helpers). Needs, declared      */
/* before: brdf_inc.glsl, light_compute, and in the fragment stage        */
/* gl_FragCoord and scene_data.world_from_view.                           */

#ifndef AREA_LIGHT_MC_INC_GLSL
#define AREA_LIGHT_MC_INC_GLSL

#include "area_light_common_inc.glsl"

// World-space cell (metres) that shares one diffuse seed (thesis 5.2: about a pixel's footprint).
#define AREA_MC_DIFFUSE_SEED_STEP 0.005

// The PCG output permutation (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically
// Good Algorithms for Random Number Generation") applied to one LCG step, used as an integer hash.
uint area_mc_hash(uint p_x) {
	uint state = p_x * 747796405u + 2891336453u;
	uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
	return (word >> 22u) ^ word;
}

// Two uniform numbers in [0, 1) for sample p_index of the stream p_seed (24 bits each).
vec2 area_mc_random2(uint p_seed, uint p_index) {
	uint h0 = area_mc_hash(p_seed ^ area_mc_hash(p_index * 2u + 1u));
	uint h1 = area_mc_hash(h0 ^ 0x9E3779B9u);
	return vec2(float(h0 >> 8u), float(h1 >> 8u)) * (1.0 / 16777216.0);
}

// GGX distribution of visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals"): a microfacet normal in the tangent frame (z = n) for the view p_v (v.z > 0): the view is
// stretched into the alpha = 1 configuration, a point of the projected hemisphere is sampled there
// (a disk whose far half is warped by s = (1 + v.z) / 2), and the normal is stretched back.
vec3 area_mc_sample_vndf(vec3 p_v, float p_alpha, vec2 p_u) {
	vec3 vh = normalize(vec3(p_alpha * p_v.x, p_alpha * p_v.y, p_v.z));
	float lensq = vh.x * vh.x + vh.y * vh.y;
	vec3 t1 = lensq > 1e-12 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
	vec3 t2 = cross(vh, t1);
	float r = sqrt(p_u.x);
	float phi = 2.0 * M_PI * p_u.y;
	float d1 = r * cos(phi);
	float d2 = r * sin(phi);
	float s = 0.5 * (1.0 + vh.z);
	d2 = (1.0 - s) * sqrt(max(1.0 - d1 * d1, 0.0)) + s * d2;
	vec3 nh = d1 * t1 + d2 * t2 + sqrt(max(1.0 - d1 * d1 - d2 * d2, 0.0)) * vh;
	return normalize(vec3(p_alpha * nh.x, p_alpha * nh.y, max(nh.z, 0.0)));
}

// Density (1/sr) of the reflected direction p_l under VNDF sampling: G1(v) D(h) / (4 n.v), h = the half
// vector; 0 where the sampler cannot produce it (n.h <= 0). p_nov > 0 (the true n.v).
float area_mc_vndf_pdf(vec3 N, vec3 V, vec3 p_l, float p_nov, float p_alpha) {
	vec3 h = normalize(V + p_l);
	float noh = dot(N, h);
	if (noh <= 0.0) {
		return 0.0;
	}
	float a2 = p_alpha * p_alpha;
	float f = noh * noh * (a2 - 1.0) + 1.0;
	float d = a2 / (M_PI * f * f);
	float g1 = 2.0 * p_nov / (p_nov + sqrt(a2 + (1.0 - a2) * p_nov * p_nov));
	return g1 * d / (4.0 * p_nov);
}

// The engine's specular lobe times the cosine for light direction p_l (light_compute's clamps), per channel.
vec3 area_mc_specular_lobe(vec3 N, vec3 V, vec3 p_l, float p_roughness, vec3 p_f0, float p_f90) {
	float nol = dot(N, p_l);
	if (nol <= 0.0) {
		return vec3(0.0);
	}
	vec3 h = normalize(V + p_l);
	float nov = max(dot(N, V), 1e-4);
	float noh = clamp(dot(N, h), 0.0, 1.0);
	float loh = clamp(dot(p_l, h), 0.0, 1.0);
	return brdf_specular(nov, nol, noh, loh, p_roughness, p_f0, p_f90) * nol;
}

void light_process_area_stochastic(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	AreaRectSetup lr;
	if (!area_light_rect_begin(p_light, p_vertex, lr)) {
		return;
	}
	vec3 nl = p_light.normal;
	AreaSphericalRect rect;
	vec3 corner = p_light.position - lr.ax * lr.half_size.x - lr.ay * lr.half_size.y;
	if (!area_spherical_rect_init(p_vertex, corner, lr.ax, lr.ay, lr.half_size * 2.0, rect)) {
		return;
	}
	float omega = rect.solid_angle;
	uint n = area_light_get_stochastic_samples(p_light);
	float inv_n = 1.0 / float(n);

	// Seeds: a per-light stream (camera-independent light data), then thesis 5.2's stable seeds.
	uint light_seed = area_mc_hash(floatBitsToUint(p_light.color.r) ^ area_mc_hash(floatBitsToUint(p_light.color.g) ^ area_mc_hash(floatBitsToUint(p_light.color.b) ^ area_mc_hash(floatBitsToUint(p_light.inv_radius)))));
	uvec2 pixel = uvec2(gl_FragCoord.xy);
	uint specular_seed = area_mc_hash(pixel.x ^ area_mc_hash(pixel.y ^ area_mc_hash(light_seed ^ 0x5BD1E995u)));
	vec3 world = (scene_data.world_from_view * vec4(p_vertex, 1.0)).xyz;
	ivec3 cell = ivec3(floor(world * (1.0 / AREA_MC_DIFFUSE_SEED_STEP)));
	uint diffuse_seed = area_mc_hash(uint(cell.x) ^ area_mc_hash(uint(cell.y) ^ area_mc_hash(uint(cell.z) ^ light_seed)));

	// Diffuse: light (solid-angle) sampling, estimator Omega / N sum f_d L_e cos.
	vec3 diffuse = vec3(0.0);
	vec3 unused_specular = vec3(0.0);
	for (uint i = 0u; i < n; i++) {
		vec2 u = area_mc_random2(diffuse_seed, i);
		vec3 q = area_spherical_rect_sample(rect, u.x, u.y);
		vec3 l = normalize(q - p_vertex);
		vec3 tex = area_texture_point(p_light, q - p_light.position, lr.ax, lr.ay, lr.half_size); // area_texture, exact.
		light_compute(N, l, V, lr.radiance * (omega * inv_n) * tex, 0.0, p_diffuse_mode, p_roughness, p_f0, p_f90, false, diffuse, unused_specular);
	}
	r_diffuse += diffuse;

	if (!p_specular_enabled) {
		return;
	}
	// Specular: MIS (balance heuristic) of light samples and GGX VNDF samples, N of each.
	float pdf_light = 1.0 / omega;
	float nov = dot(N, V);
	bool brdf_sampling = nov > 1e-4;
	float alpha = max(p_roughness * p_roughness, 2e-3); // Sampling lobe; any alpha > 0 keeps the estimate unbiased.
	vec3 t1 = abs(N.z) < 0.999 ? normalize(cross(vec3(0.0, 0.0, 1.0), N)) : vec3(1.0, 0.0, 0.0);
	vec3 t2 = cross(N, t1);
	vec3 v_local = vec3(dot(V, t1), dot(V, t2), nov);
	vec3 sum = vec3(0.0);
	for (uint i = 0u; i < n; i++) {
		// Light strategy.
		vec2 u = area_mc_random2(specular_seed, 2u * i);
		vec3 q = area_spherical_rect_sample(rect, u.x, u.y);
		vec3 l = normalize(q - p_vertex);
		vec3 lobe = area_mc_specular_lobe(N, V, l, p_roughness, p_f0, p_f90) * area_texture_point(p_light, q - p_light.position, lr.ax, lr.ay, lr.half_size);
		if (lobe != vec3(0.0)) {
			float pdf_brdf = brdf_sampling ? area_mc_vndf_pdf(N, V, l, nov, alpha) : 0.0;
			sum += lobe / (pdf_light + pdf_brdf);
		}
		// BRDF strategy: counts only when the reflected ray reaches the rectangle from its front.
		if (!brdf_sampling) {
			continue;
		}
		vec3 m = area_mc_sample_vndf(v_local, alpha, area_mc_random2(specular_seed, 2u * i + 1u));
		vec3 h = t1 * m.x + t2 * m.y + N * m.z;
		vec3 lb = reflect(-V, h);
		float dn = dot(lb, nl);
		if (dn >= 0.0 || dot(N, lb) <= 0.0) {
			continue;
		}
		vec3 hit = p_vertex + lb * (lr.plane_dist / -dn) - p_light.position;
		if (abs(dot(hit, lr.ax)) > lr.half_size.x || abs(dot(hit, lr.ay)) > lr.half_size.y) {
			continue;
		}
		vec3 lobe_b = area_mc_specular_lobe(N, V, lb, p_roughness, p_f0, p_f90) * area_texture_point(p_light, hit, lr.ax, lr.ay, lr.half_size);
		float pdf_b = area_mc_vndf_pdf(N, V, lb, nov, alpha);
		sum += lobe_b / (pdf_light + pdf_b);
	}
	r_specular += lr.radiance * p_light.specular_amount * sum * inv_n;
}

#endif // AREA_LIGHT_MC_INC_GLSL
