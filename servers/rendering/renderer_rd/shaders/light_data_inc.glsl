/**************************************************************************/
/*  light_data_inc.glsl                                                   */
/**************************************************************************/
/* GPU layout of one omni or spot light (std430 storage buffer element).  */
/* Mirror: struct RendererRD::LightStorage::LightData in                  */
/* servers/rendering/renderer_rd/storage_rd/light_storage.h. Same field   */
/* names and order on both sides; 64 bytes, keep it a multiple of 16.     */
/* Every value is in its shading unit already: LightStorage::             */
/* update_light_buffers() is the only place that converts (view space,    */
/* linear colour * energy * pi, inverse range, cosine of the spot angle). */
/*                                                                        */
/* Area lights have their own array of AreaLightData (thesis Listing A.2: */
/* a separate buffer, binding 5 of the scene shader): a rectangle needs   */
/* two axes and a normal, which would bloat every omni/spot entry if the  */
/* two shared one struct. Mirror: RendererRD::LightStorage::              */
/* AreaLightData; 96 bytes, same field names.                             */

#ifndef LIGHT_DATA_INC_GLSL
#define LIGHT_DATA_INC_GLSL

// Must match RendererRD::LightStorage::LightType (light_storage.h).
#define LIGHT_TYPE_OMNI 0
#define LIGHT_TYPE_SPOT 1

struct LightData { // Byte offsets (std430).
	vec3 position; // 0: view space, metres.
	float inv_radius; // 12: 1 / range (1/m).
	vec3 direction; // 16: view space, unit; spot axis (the light shines along it). Unused for omni.
	float size; // 28: light size (m); reserved for soft shadows.
	vec3 color; // 32: linear colour * energy * pi (see scene_forward_lights_inc.glsl); negative lights negative.
	float attenuation; // 44: distance exponent ("omni_attenuation"/"spot_attenuation"), pow(d, -attenuation).
	float cone_attenuation; // 48: spot: "spot_angle_attenuation" exponent of the rim falloff. Omni: 0.
	float cone_angle; // 52: spot: cos(spot_angle), spot_angle being the half angle. Omni: -1.
	float specular_amount; // 56: "light_specular" multiplier of the specular lobe.
	uint cull_mask; // 60: "light_cull_mask" render layers.
};

// Must match RS::LightAreaShadingMethod (servers/rendering_server.h).
#define AREA_SHADING_LTC 0u
#define AREA_SHADING_LTC_POLYNOMIAL 1u
#define AREA_SHADING_MRP 2u
#define AREA_SHADING_STOCHASTIC 3u
#define AREA_SHADING_LTC_2LOBE 5u // 4 is AUTO, resolved on the CPU.

// Must match RS::LightAreaShape (bits 24-31 of AreaLightData::shading_method).
#define AREA_SHAPE_RECTANGLE 0u
#define AREA_SHAPE_DISK 1u
#define AREA_SHAPE_SPHERE 2u
#define AREA_SHAPE_TUBE 3u

struct AreaLightData { // Byte offsets (std430), 96 bytes.
	vec3 position; // 0: view space centre of the rectangle, metres.
	float inv_radius; // 12: 1 / area_range (1/m); range = max distance from any point of the rectangle.
	vec3 half_axis_x; // 16: view space, local +X scaled by area_size.x / 2 (metres); disk: semi-axis; tube: half the segment; sphere: local +X * radius.
	float attenuation; // 28: area_attenuation, distance exponent a of W(d) = window * d^(2 - a) (2 = physical).
	vec3 half_axis_y; // 32: view space, local +Y scaled by area_size.y / 2 (metres); disk: semi-axis; tube: local +Y * radius; sphere: local +Y * radius.
	float specular_amount; // 44: "light_specular" multiplier of the specular lobe.
	vec3 normal; // 48: view space unit emission direction (the light's local -Z); only this side emits.
	uint shading_method; // 60: bits 0-7 AREA_SHADING_*, bits 8-23 stochastic samples, bits 24-31 AREA_SHAPE_* (area_light_get_method()).
	vec3 color; // 64: emitted radiance L_e = linear colour * energy * pi / A_n (A_n = the shape's emitting area when energy is normalised, else 1); 0 for a zero-size light.
	uint cull_mask; // 76: "light_cull_mask" render layers.
	vec4 texture_rect; // 80: area_texture: uv rect (x, y, w, h) of its level 0 in the area light atlas (area_light_atlas.h); w = 0: untextured.
};

// One directional light (std140 array element of the DirectionalLights block), 48 bytes.
// Mirror: RendererRD::LightStorage::DirectionalLightData. Not clustered: every fragment loops over all.
struct DirectionalLightData {
	vec3 direction; // 0: view space unit vector the light shines along (its local -Z); L = -direction.
	float energy; // 12: light_energy * pi (negative for negative lights).
	vec3 color; // 16: linear colour * energy (above): the radiance a unit-cosine Lambert receiver gets times pi.
	float size; // 28: angular radius of the sun disk, radians (light_angular_distance / 2).
	float specular_amount; // 32: "light_specular".
	uint cull_mask; // 36: "light_cull_mask".
	uint flags; // 40: DIRECTIONAL_FLAG_*.
	int shadow_index; // 44: into directional_shadows.data (USE_DIRECTIONAL_SHADOWS), -1: unshadowed.
};

#endif // LIGHT_DATA_INC_GLSL
