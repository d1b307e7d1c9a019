/**************************************************************************/
/*  sky_radiance.glsl                                                     */
/**************************************************************************/
/* Sky reflections (SkyRD): one mip face of the radiance cubemap, the    */
/* sky prefiltered for one roughness. Each texel's direction N stands    */
/* for the reflection vector with N = V = R (Karis 2013, "Real Shading   */
/* in Unreal Engine 4", split sum, first sum): with GGX half vectors H   */
/* drawn from D(H) (N.H) (Walter et al. 2007, eq. 35-36: cos^2 theta_h =  */
/* (1 - u) / (1 + (alpha^2 - 1) u)) on a Hammersley point set, L = 2      */
/* (V.H) H - V, the texel is sum L_sky(L) (N.L) / sum (N.L). The sky is   */
/* evaluated exactly at each L (sky_inc.glsl), not read from a texture:  */
/* no source cubemap and no aliasing of the sun disk into texels. Mip 0  */
/* (roughness 0) is the sky itself (one sample along N).                 */
/* C++: SkyRD::_filter_radiance (push constant mirror                    */
/* SkyRD::RadiancePushConstant).                                          */

#[compute]

#version 450

#include "sky_inc.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba16f, set = 0, binding = 1) uniform restrict writeonly image2D dest_face; // One face of one mip.

layout(push_constant, std430) uniform Params {
	uint face; // Vulkan cube face order: +X, -X, +Y, -Y, +Z, -Z.
	uint size; // Texels per side of this mip.
	float alpha; // GGX alpha of this mip (perceptual roughness squared).
	uint sample_count;
}
params;

// Direction through the centre of texel p_texel of face p_face (Vulkan spec, "Cube Map Face Selection").
vec3 cube_direction(uint p_face, uvec2 p_texel, uint p_size) {
	vec2 st = (vec2(p_texel) + 0.5) / float(p_size) * 2.0 - 1.0;
	float s = st.x, t = st.y;
	vec3 d;
	if (p_face == 0u) {
		d = vec3(1.0, -t, -s);
	} else if (p_face == 1u) {
		d = vec3(-1.0, -t, s);
	} else if (p_face == 2u) {
		d = vec3(s, 1.0, t);
	} else if (p_face == 3u) {
		d = vec3(s, -1.0, -t);
	} else if (p_face == 4u) {
		d = vec3(s, -t, 1.0);
	} else {
		d = vec3(-s, -t, -1.0);
	}
	return normalize(d);
}

// Van der Corput radical inverse in base 2 (the second Hammersley coordinate).
float radical_inverse(uint p_bits) {
	return float(bitfieldReverse(p_bits)) * 2.3283064365386963e-10;
}

void main() {
	uvec2 texel = gl_GlobalInvocationID.xy;
	if (texel.x >= params.size || texel.y >= params.size) {
		return;
	}
	vec3 N = cube_direction(params.face, texel, params.size);
	if (params.sample_count <= 1u || params.alpha <= 0.0) {
		imageStore(dest_face, ivec2(texel), vec4(sky_evaluate(N), 1.0));
		return;
	}
	vec3 up = abs(N.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
	vec3 T = normalize(cross(up, N));
	vec3 B = cross(N, T);
	float a2 = params.alpha * params.alpha;
	vec3 sum = vec3(0.0);
	float weight = 0.0;
	for (uint i = 0u; i < params.sample_count; i++) {
		float u = (float(i) + 0.5) / float(params.sample_count);
		float phi = 6.28318530718 * radical_inverse(i);
		float cos_h = sqrt((1.0 - u) / (1.0 + (a2 - 1.0) * u));
		float sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));
		vec3 H = T * (sin_h * cos(phi)) + B * (sin_h * sin(phi)) + N * cos_h;
		vec3 L = 2.0 * dot(N, H) * H - N;
		float NoL = dot(N, L);
		if (NoL > 0.0) {
			sum += sky_evaluate(normalize(L)) * NoL;
			weight += NoL;
		}
	}
	imageStore(dest_face, ivec2(texel), vec4(sum / max(weight, 1e-6), 1.0));
}
