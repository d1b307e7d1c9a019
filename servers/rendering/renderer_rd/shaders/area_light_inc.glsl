/**************************************************************************/
/*  area_light_inc.glsl                                                   */
/**************************************************************************/
/* Per-light dispatch of the area-light shading methods.                  */
/*                                                                        */
/* Methods are compiled in by defines (RenderForwardClustered makes one   */
/* shader version per combination of methods its visible area lights      */
/* use, so code of an unused method is never compiled):                   */
/*   AREA_METHOD_LTC             area_light_ltc_inc.glsl (LUT)            */
/*   AREA_METHOD_LTC_POLYNOMIAL  area_light_ltc_inc.glsl (polynomial)     */
/*   AREA_METHOD_LTC_2LOBE       area_light_ltc_inc.glsl (two lobes)      */
/*   AREA_METHOD_MRP             area_light_mrp_inc.glsl (thesis 5.3)     */
/*   AREA_METHOD_STOCHASTIC      area_light_mc_inc.glsl (thesis 5.2)      */
/*   USE_AREA_SHAPES             area_light_shapes_inc.glsl: disk, sphere */
/*                               and tube lights (only when a view has    */
/*                               one; rectangles need none of it)         */
/* Every method obeys the same definition of the light and shares its     */
/* helpers: area_light_common_inc.glsl.                                   */
/*                                                                        */
/* Needs, included before: brdf_inc.glsl, light_data_inc.glsl,            */
/* scene_forward_lights_inc.glsl (light_compute), and the bindings that   */
/* area_light_ltc_inc.glsl needs. Fragment stage only (the stochastic     */
/* method seeds from gl_FragCoord and scene_data.world_from_view).        */

#include "area_light_common_inc.glsl"

// Method implementations (each keeps its own include guard).
// area_texture fetches (no-ops returning 1 unless AREA_LIGHT_TEXTURE), used by every method below.
#include "area_light_texture_inc.glsl"
#include "area_light_ltc_inc.glsl"
#ifdef AREA_METHOD_MRP
#include "area_light_mrp_inc.glsl"
#endif
#ifdef AREA_METHOD_STOCHASTIC
#include "area_light_mc_inc.glsl"
#endif
#ifdef USE_AREA_SHAPES
#include "area_light_shapes_inc.glsl"
#endif

#ifndef AREA_LIGHT_DISPATCH_GLSL
#define AREA_LIGHT_DISPATCH_GLSL

// Adds one area light with the light's own shading method (one call per light). Vectors in view space;
// N, V unit. r_diffuse accumulates diffuse light without the albedo, r_specular reflected specular
// radiance (as light_compute). A method whose code is not compiled into this version adds nothing
// (the renderer always compiles the methods of every uploaded light).
void light_process_area_method(AreaLightData p_light, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	uint method = area_light_get_method(p_light);
#ifdef USE_AREA_SHAPES
	if (area_light_get_shape(p_light) != AREA_SHAPE_RECTANGLE) {
		light_process_area_shape(p_light, method, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_LTC
	if (method == AREA_SHADING_LTC) {
		light_process_area_ltc(p_light, p_vertex, N, V, p_roughness, p_f0, p_f90, p_specular_enabled, false, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_LTC_POLYNOMIAL
	if (method == AREA_SHADING_LTC_POLYNOMIAL) {
		light_process_area_ltc(p_light, p_vertex, N, V, p_roughness, p_f0, p_f90, p_specular_enabled, true, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_LTC_2LOBE
	if (method == AREA_SHADING_LTC_2LOBE) {
		light_process_area_ltc_2lobe(p_light, p_vertex, N, V, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_MRP
	if (method == AREA_SHADING_MRP) {
		light_process_area_mrp(p_light, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		return;
	}
#endif
#ifdef AREA_METHOD_STOCHASTIC
	if (method == AREA_SHADING_STOCHASTIC) {
		light_process_area_stochastic(p_light, p_vertex, N, V, p_diffuse_mode, p_roughness, p_f0, p_f90, p_specular_enabled, r_diffuse, r_specular);
		return;
	}
#endif
}

#endif // AREA_LIGHT_DISPATCH_GLSL
