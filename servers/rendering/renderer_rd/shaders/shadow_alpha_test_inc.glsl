/**************************************************************************/
/*  shadow_alpha_test_inc.glsl                                            */
/**************************************************************************/
/* Alpha test of a shadow caster (the ALPHA_TEST variant of               */
/* area_shadow_depth.glsl and directional_shadow_depth.glsl): Godot's     */
/* BaseMaterial3D with transparency ALPHA_SCISSOR casts a cut-out shadow: */
/* the fragment is dropped where ALPHA < alpha_scissor_threshold, ALPHA   */
/* being albedo_color.a times the albedo texture's alpha (at uv1_scale,   */
/* uv1_offset) times COLOR.a when vertex_color_use_as_albedo, as in the   */
/* colour pass (forward_clustered/scene_forward_clustered.glsl). Opaque   */
/* casters draw with the variant without this code; ALPHA (blended)      */
/* casters are not drawn at all (Godot: they cast no shadow).             */

#ifndef SHADOW_ALPHA_TEST_INC_GLSL
#define SHADOW_ALPHA_TEST_INC_GLSL

#include "material_block_inc.glsl"

// p_uv: the mesh's UV; p_color: its ARRAY_COLOR (white when the surface has none).
void shadow_alpha_test(vec2 p_uv, vec4 p_color) {
	float alpha = material.albedo.a;
	if ((material.flags & MATERIAL_FLAG_ALBEDO_TEXTURE) != 0u) {
		vec2 uv = p_uv * material.uv1.xy + material.uv1.zw;
		alpha *= texture(sampler2D(albedo_texture, material_texture_sampler), uv).a;
	}
	if ((material.flags & MATERIAL_FLAG_VERTEX_COLOR) != 0u) {
		alpha *= p_color.a;
	}
	if (alpha < material.alpha_scissor_threshold) {
		discard;
	}
}

#endif // SHADOW_ALPHA_TEST_INC_GLSL
