/**************************************************************************/
/*  material_block_inc.glsl                                               */
/**************************************************************************/
/* Set 1 of every pass that reads a material: the MaterialBlock uniform   */
/* buffer, its textures and sampler (C++ mirror: RendererRD::Material-    */
/* Storage::MaterialUBO and material_get_uniform_set()). The scene shader */
/* and the alpha-test variants of the shadow depth shaders declare it     */
/* from here, identically, so one material set serves all of them.       */

#ifndef MATERIAL_BLOCK_INC_GLSL
#define MATERIAL_BLOCK_INC_GLSL

// Material flags. Must match RendererRD::MaterialStorage::MaterialFlags.
#define MATERIAL_FLAG_ALBEDO_TEXTURE 1u
#define MATERIAL_FLAG_NORMAL_MAP 2u
#define MATERIAL_FLAG_UNSHADED 4u
#define MATERIAL_FLAG_SPECULAR_DISABLED 8u
#define MATERIAL_FLAG_ROUGHNESS_TEXTURE 16u
#define MATERIAL_FLAG_METALLIC_TEXTURE 32u
#define MATERIAL_FLAG_ALPHA_SCISSOR 64u
#define MATERIAL_FLAG_VERTEX_COLOR 128u
#define MATERIAL_FLAG_VERTEX_COLOR_SRGB 256u

layout(set = 1, binding = 0, std140) uniform MaterialBlock { // 112 bytes.
	vec4 albedo; // 0: linear rgb, alpha.
	vec4 emission; // 16: linear rgb * emission energy.
	float roughness; // 32: perceptual roughness.
	float metallic; // 36
	float specular; // 40: 0.5 = 4 % f0.
	float normal_scale; // 44
	uint flags; // 48: MATERIAL_FLAG_*.
	uint diffuse_mode; // 52: BRDF_DIFFUSE_*.
	float alpha_scissor_threshold; // 56: MATERIAL_FLAG_ALPHA_SCISSOR discards alpha below it.
	uint pad1; // 60
	vec4 uv1; // 64: uv1_scale.xy, uv1_offset.xy.
	vec4 roughness_channel; // 80: weights of the roughness texture's channels.
	vec4 metallic_channel; // 96
}
material;

layout(set = 1, binding = 1) uniform texture2D albedo_texture; // sRGB-encoded texels (decoded in the shader).
layout(set = 1, binding = 2) uniform texture2D normal_texture; // Linear, OpenGL convention (+Y up).
layout(set = 1, binding = 3) uniform texture2D roughness_texture; // Linear; white without one.
layout(set = 1, binding = 4) uniform texture2D metallic_texture; // Linear; white without one.
layout(set = 1, binding = 5) uniform sampler material_texture_sampler; // Repeat; nearest or linear per texture_filter.

#endif // MATERIAL_BLOCK_INC_GLSL
