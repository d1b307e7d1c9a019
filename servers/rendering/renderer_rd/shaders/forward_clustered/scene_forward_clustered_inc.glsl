/**************************************************************************/
/*  scene_forward_clustered_inc.glsl                                      */
/**************************************************************************/
/* Bindings, push constant and flags of the Forward+ scene shader.        */
/* C++ mirrors: RenderForwardClustered::SceneDataUBO, ::DrawPushConstant  */
/* and RendererRD::MaterialStorage::MaterialUBO (render_forward_          */
/* clustered.h, storage_rd/material_storage.h). Same names, same order.   */
/*                                                                        */
/* Descriptor sets by update frequency:                                   */
/*   set 0: per render pass (scene data, lights, clusters, sampler);      */
/*   set 1: per material;                                                 */
/*   per item: the push constant (transforms).                            */
/* Godot puts never-changing samplers in a set of their own; we fold them */
/* into set 0 because MODE_DEPTH declares only set 0, binding 0 (sets     */
/* must stay contiguous).                                                 */
/*                                                                        */
/* Variants (defines, structural): MODE_DEPTH = depth pre-pass, no        */
/* colour output, only the scene data is declared. USE_AREA_LIGHTS =      */
/* colour pass with area lights: declares bindings 5-7 (area light array, */
/* LTC LUT texture and sampler) and compiles the LTC code; chosen at run  */
/* time only for views with area lights, so a scene without area lights  */
/* never compiles nor runs any of it. Cheap toggles (brute-               */
/* force lights, diffuse model) are data: scene flags / material fields.  */

#ifndef SCENE_FORWARD_CLUSTERED_INC_GLSL
#define SCENE_FORWARD_CLUSTERED_INC_GLSL

#include "../light_data_inc.glsl"
#include "../cluster_data_inc.glsl"

// Scene flags. Must match RenderForwardClustered::SceneFlags.
#define SCENE_FLAG_FORCE_ALL_LIGHTS 1u // Brute force: every light for every fragment, clusters ignored.
#define SCENE_FLAG_DEBUG_CLUSTER 2u // Debug view: output the element count of cluster type debug_cluster_type.

// Draw flags. Must match RenderForwardClustered::DRAW_FLAG_*.
#define DRAW_FLAG_HAS_COLOR 1u

/*************************************************************************/
/* Set 0: render pass data                                               */
/*************************************************************************/

layout(set = 0, binding = 0, std140) uniform SceneDataBlock { // 336 bytes; running std140 offsets.
	mat4 clip_from_view; // 0: projection with Vulkan depth correction (y flipped, depth 0..1).
	mat4 view_from_clip; // 64
	mat4 view_from_world; // 128
	mat4 world_from_view; // 192
	vec2 viewport_size; // 256: pixels.
	float z_near; // 264
	float z_far; // 268: metres: the depth the cluster slices cover (ClusterBuilderRD::get_slice_depth(), <= the camera far).
	vec4 ambient_light; // 272: rgb = linear ambient colour * energy, a unused.
	uint omni_light_count; // 288
	uint spot_light_count; // 292
	uint cluster_tiles_x; // 296
	uint cluster_tile_count; // 300
	uint cluster_words_per_type; // 304
	uint flags; // 308: SCENE_FLAG_*.
	uint area_light_count; // 312
	uint debug_cluster_type; // 316: CLUSTER_ELEMENT_TYPE_* shown by SCENE_FLAG_DEBUG_CLUSTER.
	uint cluster_tile_size; // 320: pixels (ClusterBuilderRD::get_tile_size()).
	uint pad_scene0; // 324
	uint pad_scene1; // 328
	uint pad_scene2; // 332
}
scene_data;

#ifndef MODE_DEPTH

layout(set = 0, binding = 1, std430) restrict readonly buffer OmniLights {
	LightData data[];
}
omni_lights;

layout(set = 0, binding = 2, std430) restrict readonly buffer SpotLights {
	LightData data[];
}
spot_lights;

layout(set = 0, binding = 3, std430) restrict readonly buffer ClusterBuffer {
	uint data[]; // Layout: cluster_data_inc.glsl.
}
cluster_buffer;

// Set 0 binding 4 (and sampler binding 10): the area light atlas, declared in area_light_texture_inc.glsl and
// only in versions with AREA_LIGHT_TEXTURE. Material textures use their material's sampler (set 1, binding 5).

#ifdef USE_AREA_LIGHTS
// Thesis Listing A.2: area lights in their own buffer.
layout(set = 0, binding = 5, std430) restrict readonly buffer AreaLights {
	AreaLightData data[];
}
area_lights;

layout(set = 0, binding = 6) uniform texture2DArray ltc_lut_texture; // LTCLutRD: layer 0 (a, b, c, d), layer 1 (e, fn, fg, 0); 2-5 LTC_2LOBE.
layout(set = 0, binding = 7) uniform sampler ltc_lut_sampler; // Linear, clamp to edge.
#endif

#ifdef USE_DIRECTIONAL_LIGHTS
// Directional lights (not clustered, as Godot's): only in versions of views that have one.
#define MAX_DIRECTIONAL_LIGHTS 8 // RendererRD::LightStorage::MAX_DIRECTIONAL_LIGHTS.
layout(set = 0, binding = 8, std140) uniform DirectionalLights {
	uint count;
	uint pad0;
	uint pad1;
	uint pad2;
	DirectionalLightData data[MAX_DIRECTIONAL_LIGHTS];
}
directional_lights;
#endif

#ifdef USE_SKY_AMBIENT
// Sky ambient (SkyRD): irradiance SH of the sky, already times ambient_light_sky_contribution / pi.
layout(set = 0, binding = 9, std140) uniform SkyAmbient {
	vec4 sh[9]; // rgb per coefficient (Ramamoorthi & Hanrahan order: Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22).
	vec4 pad;
}
sky_ambient;
#endif

#ifdef USE_SKY_REFLECTION
// Sky reflections (SkyRD): the radiance cubemap, mip i prefiltered for perceptual roughness (i / (mips - 1))^2.
layout(set = 0, binding = 20) uniform textureCube sky_radiance_texture;
layout(set = 0, binding = 21) uniform sampler sky_radiance_sampler; // Trilinear, clamp.
#endif

// Set 1: the material (MaterialStorage::material_get_uniform_set()).
#include "../material_block_inc.glsl"

#endif // !MODE_DEPTH

/*************************************************************************/
/* Per item: push constant                                               */
/*************************************************************************/

layout(push_constant, std430) uniform DrawData { // 128 bytes.
	mat4 world_from_model; // 0
	vec4 normal_matrix[3]; // 64: columns of inverse(transpose(world_from_model.basis)), xyz used.
	uint layer_mask; // 112: instance render layers, matched with LightData.cull_mask.
	uint flags; // 116: DRAW_FLAG_*.
	uint pad0; // 120
	uint pad1; // 124
}
draw;

#endif // SCENE_FORWARD_CLUSTERED_INC_GLSL
