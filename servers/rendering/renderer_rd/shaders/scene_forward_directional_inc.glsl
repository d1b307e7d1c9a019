/**************************************************************************/
/*  scene_forward_directional_inc.glsl                                    */
/**************************************************************************/
/* Directional light (sun) evaluation for the Forward+ scene shader,      */
/* compiled only into versions with USE_DIRECTIONAL_LIGHTS (views that   */
/* have a DirectionalLight3D). Not clustered: every fragment evaluates    */
/* every directional light, as Godot's light_process_directional loop.   */
/*                                                                        */
/* Units (Godot 4, no physical light units): light.color is               */
/* srgb_to_linear(light_color) * light_energy * pi, so a white Lambert    */
/* surface whose normal makes the angle theta with the light reflects     */
/* light_energy * cos(theta) (the same pi as punctual lights, see         */
/* scene_forward_lights_inc.glsl). The sun is treated as a direction      */
/* here; its disk (light.size) matters for the Embree reference (which   */
/* samples it) and for soft shadows. The cosine over a disk fully above  */
/* the horizon integrates to exactly the centre's cosine (the projected  */
/* solid angle of a spherical cap is pi sin^2(a) cos(theta)), so Lambert */
/* results agree with the reference to rounding.                          */
/*                                                                        */
/* Needs brdf_inc.glsl, light_data_inc.glsl and                           */
/* scene_forward_lights_inc.glsl (light_compute) included before.         */

#ifndef SCENE_FORWARD_DIRECTIONAL_INC_GLSL
#define SCENE_FORWARD_DIRECTIONAL_INC_GLSL

void light_process_directional(DirectionalLightData p_light, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, float p_shadow, inout vec3 r_diffuse, inout vec3 r_specular) {
	vec3 L = -p_light.direction;
	light_compute(N, L, V, p_light.color * p_shadow, p_light.specular_amount, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
}

#endif // SCENE_FORWARD_DIRECTIONAL_INC_GLSL
