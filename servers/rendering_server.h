/**************************************************************************/
/*  rendering_server.h                                                    */
/**************************************************************************/
/* godot-area: the rendering server API (Godot's RenderingServer, reduced).*/
/* Pure virtual; RenderingServerDefault implements it. Scene nodes talk   */
/* to rendering only through this class and RIDs. There is no render      */
/* thread: every call runs directly on the caller's thread.               */
/* Enum values follow Godot 4.7 order (they are saved in scene files).    */

#pragma once

#include "core/io/image.h"
#include "core/math/aabb.h"
#include "core/math/color.h"
#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"
#include "core/string/ustring.h"
#include "core/templates/rid.h"

#include <cstdint>
#include <utility>
#include <vector>

class RenderingServer {
	static RenderingServer *singleton;

public:
	// Returns the live server (set by the constructor of the implementation), or nullptr.
	static RenderingServer *get_singleton() { return singleton; }

	/* MESH API enums */

	// Godot's vertex array slots. We pass a SurfaceData struct instead of packed arrays,
	// so these only name the slots; ARRAY_VERTEX..ARRAY_TEX_UV and ARRAY_INDEX are supported.
	enum ArrayType {
		ARRAY_VERTEX,
		ARRAY_NORMAL,
		ARRAY_TANGENT,
		ARRAY_COLOR,
		ARRAY_TEX_UV,
		ARRAY_TEX_UV2,
		ARRAY_CUSTOM0,
		ARRAY_CUSTOM1,
		ARRAY_CUSTOM2,
		ARRAY_CUSTOM3,
		ARRAY_BONES,
		ARRAY_WEIGHTS,
		ARRAY_INDEX,
		ARRAY_MAX
	};

	// One triangle-list surface (simplification of Godot's packed surface arrays).
	// Every per-vertex array is either empty or has vertices.size() entries (tangents: 4 floats
	// per vertex, xyz + binormal sign w). Empty indices mean a non-indexed list (3 vertices per triangle).
	struct SurfaceData {
		std::vector<Vector3> vertices; // ARRAY_VERTEX, object space.
		std::vector<Vector3> normals; // ARRAY_NORMAL, optional.
		std::vector<float> tangents; // ARRAY_TANGENT, optional, 4 per vertex.
		std::vector<Color> colors; // ARRAY_COLOR, optional, linear.
		std::vector<Vector2> uvs; // ARRAY_TEX_UV, optional.
		std::vector<uint32_t> indices; // ARRAY_INDEX, optional, multiple of 3.
		AABB aabb; // Output: mesh_add_surface() computes it from vertices (input is ignored).
	};

	/* MATERIAL API enums (values of StandardMaterial3D's enums) */

	enum MaterialDiffuseMode {
		MATERIAL_DIFFUSE_BURLEY, // Godot's default.
		MATERIAL_DIFFUSE_LAMBERT,
		MATERIAL_DIFFUSE_LAMBERT_WRAP,
		MATERIAL_DIFFUSE_TOON,
	};

	enum MaterialSpecularMode {
		MATERIAL_SPECULAR_SCHLICK_GGX, // Godot's default.
		MATERIAL_SPECULAR_TOON,
		MATERIAL_SPECULAR_DISABLED,
	};

	// How a material's alpha is used (BaseMaterial3D::Transparency, reduced: ALPHA_HASH draws as
	// ALPHA_SCISSOR and ALPHA_DEPTH_PRE_PASS as ALPHA, warned by BaseMaterial3D).
	enum MaterialTransparency {
		MATERIAL_TRANSPARENCY_DISABLED, // Opaque: alpha is ignored.
		MATERIAL_TRANSPARENCY_ALPHA, // Blended over what is behind (after the opaque pass, back to front), no depth write.
		MATERIAL_TRANSPARENCY_ALPHA_SCISSOR, // Opaque where alpha >= alpha_scissor_threshold, a hole elsewhere.
	};

	// Which channel of a roughness or metallic texture is read (BaseMaterial3D::TextureChannel).
	enum MaterialTextureChannel {
		MATERIAL_TEXTURE_CHANNEL_RED,
		MATERIAL_TEXTURE_CHANNEL_GREEN,
		MATERIAL_TEXTURE_CHANNEL_BLUE,
		MATERIAL_TEXTURE_CHANNEL_ALPHA,
		MATERIAL_TEXTURE_CHANNEL_GRAYSCALE,
	};

	// BaseMaterial3D::TextureFilter. The *_WITH_MIPMAPS filters blend the two nearest levels of the
	// texture's mip chain (servers/rendering/storage/texture_mipmaps.h); the anisotropic ones sample as
	// their isotropic filter (no anisotropy here; BaseMaterial3D warns).
	enum MaterialTextureFilter {
		MATERIAL_TEXTURE_FILTER_NEAREST,
		MATERIAL_TEXTURE_FILTER_LINEAR,
		MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS,
		MATERIAL_TEXTURE_FILTER_LINEAR_WITH_MIPMAPS, // Godot's default.
		MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC,
		MATERIAL_TEXTURE_FILTER_LINEAR_WITH_MIPMAPS_ANISOTROPIC,
	};
	// The weights dot()-ed with a texel to read p_channel (GRAYSCALE: the mean of r, g, b, as Godot);
	// the renderers convert the channel here.
	static void material_texture_channel_weights(MaterialTextureChannel p_channel, float r_weights[4]);
	static bool material_texture_filter_is_nearest(MaterialTextureFilter p_filter) {
		return p_filter == MATERIAL_TEXTURE_FILTER_NEAREST || p_filter == MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS || p_filter == MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC;
	}

	// Typed parameters of our one built-in material (StandardMaterial3D's subset), set as a whole
	// with material_set_params(). Simpler than Godot's per-uniform material_set_param(name, Variant).
	// Colours are sRGB as the inspector shows them; the renderer converts them to linear once.
	struct MaterialParams {
		Color albedo = Color(1, 1, 1, 1); // albedo_color (sRGB).
		RID albedo_texture; // albedo_texture (texels sRGB-encoded, decoded by the renderer).
		float roughness = 1.0f; // roughness, 0..1.
		RID roughness_texture; // roughness_texture (linear): roughness *= its roughness_texture_channel.
		MaterialTextureChannel roughness_texture_channel = MATERIAL_TEXTURE_CHANNEL_RED;
		float metallic = 0.0f; // metallic, 0..1.
		RID metallic_texture; // metallic_texture (linear): metallic *= its metallic_texture_channel.
		MaterialTextureChannel metallic_texture_channel = MATERIAL_TEXTURE_CHANNEL_RED;
		Vector3 uv1_scale = Vector3(1, 1, 1); // uv1_scale: UV = UV * scale.xy + offset.xy (z unused: no triplanar).
		Vector3 uv1_offset; // uv1_offset.
		MaterialTextureFilter texture_filter = MATERIAL_TEXTURE_FILTER_LINEAR_WITH_MIPMAPS;
		float specular = 0.5f; // metallic_specular, 0..1 (0.5 = 4% F0).
		RID normal_texture; // normal_texture (linear, OpenGL convention +Y up); used when valid.
		float normal_scale = 1.0f; // normal_scale.
		Color emission = Color(0, 0, 0, 1); // emission (sRGB); black = off.
		float emission_energy = 1.0f; // emission_energy_multiplier.
		MaterialDiffuseMode diffuse_mode = MATERIAL_DIFFUSE_BURLEY;
		MaterialSpecularMode specular_mode = MATERIAL_SPECULAR_SCHLICK_GGX;
		bool unshaded = false; // shading_mode = UNSHADED: output albedo only.
		bool cull_back = true; // cull_mode = BACK (false = DISABLED, two-sided).
		MaterialTransparency transparency = MATERIAL_TRANSPARENCY_DISABLED;
		float alpha_scissor_threshold = 0.5f; // 0..1, ALPHA_SCISSOR only.
		bool vertex_color_use_as_albedo = false; // albedo (rgb and alpha) *= the surface's ARRAY_COLOR.
		bool vertex_color_is_srgb = false; // ARRAY_COLOR rgb is sRGB-encoded (decoded by the renderer).
	};

	// Values of GeometryInstance3D::ShadowCastingSetting (Godot's RS::ShadowCastingSetting).
	enum ShadowCastingSetting {
		SHADOW_CASTING_SETTING_OFF,
		SHADOW_CASTING_SETTING_ON,
		SHADOW_CASTING_SETTING_DOUBLE_SIDED,
		SHADOW_CASTING_SETTING_SHADOWS_ONLY,
	};

	/* LIGHT API enums */

	enum LightType {
		LIGHT_DIRECTIONAL,
		LIGHT_OMNI,
		LIGHT_SPOT,
		LIGHT_AREA, // Rectangle in the light's local XY plane, emitting along local -Z (AreaLight3D).
	};

	enum LightParam {
		LIGHT_PARAM_ENERGY,
		LIGHT_PARAM_INDIRECT_ENERGY,
		LIGHT_PARAM_VOLUMETRIC_FOG_ENERGY,
		LIGHT_PARAM_SPECULAR,
		LIGHT_PARAM_RANGE,
		LIGHT_PARAM_SIZE,
		LIGHT_PARAM_ATTENUATION,
		LIGHT_PARAM_SPOT_ANGLE, // Degrees (half-angle of the cone).
		LIGHT_PARAM_SPOT_ATTENUATION,
		LIGHT_PARAM_SHADOW_MAX_DISTANCE,
		LIGHT_PARAM_SHADOW_SPLIT_1_OFFSET,
		LIGHT_PARAM_SHADOW_SPLIT_2_OFFSET,
		LIGHT_PARAM_SHADOW_SPLIT_3_OFFSET,
		LIGHT_PARAM_SHADOW_FADE_START,
		LIGHT_PARAM_SHADOW_NORMAL_BIAS,
		LIGHT_PARAM_SHADOW_BIAS,
		LIGHT_PARAM_SHADOW_PANCAKE_SIZE,
		LIGHT_PARAM_SHADOW_OPACITY,
		LIGHT_PARAM_SHADOW_BLUR,
		LIGHT_PARAM_TRANSMITTANCE_BIAS,
		LIGHT_PARAM_INTENSITY, // Lumens (omni/spot) or lux (directional); used with physical light units.
		LIGHT_PARAM_MAX
	};

	enum LightBakeMode {
		LIGHT_BAKE_DISABLED,
		LIGHT_BAKE_STATIC,
		LIGHT_BAKE_DYNAMIC,
	};

	enum LightOmniShadowMode {
		LIGHT_OMNI_SHADOW_DUAL_PARABOLOID,
		LIGHT_OMNI_SHADOW_CUBE,
	};

	enum LightDirectionalShadowMode {
		LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL,
		LIGHT_DIRECTIONAL_SHADOW_PARALLEL_2_SPLITS,
		LIGHT_DIRECTIONAL_SHADOW_PARALLEL_4_SPLITS,
	};

	enum LightDirectionalSkyMode {
		LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY,
		LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_ONLY,
		LIGHT_DIRECTIONAL_SKY_MODE_SKY_ONLY,
	};

	// How an area light is shaded. Values equal AreaLight3D::AreaShadingMethod (saved in scene
	// files as integers); new methods are appended, never inserted.
	enum LightAreaShadingMethod {
		LIGHT_AREA_SHADING_LTC, // Linearly transformed cosines (Heitz et al. 2016), fitted LUT.
		LIGHT_AREA_SHADING_LTC_POLYNOMIAL, // LTC with the matrix from a fitted polynomial instead of the LUT.
		LIGHT_AREA_SHADING_MRP, // Most representative point (Drobot 2014; thesis section 5.3).
		LIGHT_AREA_SHADING_STOCHASTIC, // Monte Carlo, area_stochastic_samples per light (thesis section 5.2).
		LIGHT_AREA_SHADING_AUTO, // Per light per frame, the cheapest method whose predicted error fits the project's
		// rendering/lights_and_shadows/area_light_error_budget (resolved on the CPU; the GPU never sees AUTO).
		LIGHT_AREA_SHADING_LTC_2LOBE, // LTC with two lobes (issue #18): accurate at grazing views, two integrals.
		LIGHT_AREA_SHADING_MAX, // Keep last: the number of methods (append new ones above).
	};
	// The emitting shape of an area light. Values equal AreaLight3D::AreaShape (saved in scene files as
	// integers); new shapes are appended, never inserted. What light_area_set_size() means per shape:
	enum LightAreaShape {
		LIGHT_AREA_SHAPE_RECTANGLE, // size.x (local X) by size.y (local Y) in the XY plane, one-sided along -Z (upstream's).
		LIGHT_AREA_SHAPE_DISK, // Ellipse with diameters size.x (local X) and size.y (local Y) in the XY plane, one-sided along -Z.
		LIGHT_AREA_SHAPE_SPHERE, // Sphere of diameter size.x (size.y unused), emitting outwards everywhere.
		LIGHT_AREA_SHAPE_TUBE, // Capsule: a segment of length size.x along local X, radius size.y / 2, emitting outwards everywhere.
		LIGHT_AREA_SHAPE_MAX, // Keep last.
	};
	// Bounds of light_area_set_stochastic_samples() (samples per strategy and shading point).
	static constexpr int LIGHT_AREA_STOCHASTIC_SAMPLES_MIN = 1;
	static constexpr int LIGHT_AREA_STOCHASTIC_SAMPLES_MAX = 256;
	static constexpr int LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT = 8;
	// How an area light's shadows are drawn (values equal AreaLight3D::AreaShadowMode; appended only).
	enum LightAreaShadowMode {
		LIGHT_AREA_SHADOW_FIXED, // area_shadow_grid^2 shadow maps over the light, averaged PCF (thesis 6.1).
		LIGHT_AREA_SHADOW_PCSS_BASELINE, // One map from the light centre with PCSS (upstream Godot's approach).
		LIGHT_AREA_SHADOW_ADAPTIVE, // Quadtree of maps grown and pruned over frames by shadow reprojection (thesis 6.3;
		// AreaShadowAdaptiveRD). Until its renderer wiring lands it draws the HEURISTIC grid.
		LIGHT_AREA_SHADOW_HEURISTIC, // Grid from a CPU estimate of the on-screen penumbra (thesis 6.5).
		LIGHT_AREA_SHADOW_MAX,
	};
	// Bounds of light_area_set_shadow_grid() (grid x grid sample maps).
	static constexpr int LIGHT_AREA_SHADOW_GRID_MIN = 2;
	static constexpr int LIGHT_AREA_SHADOW_GRID_MAX = 9;
	static constexpr int LIGHT_AREA_SHADOW_GRID_DEFAULT = 5; // 25 maps: the cheapest grid without banding (doc/shadows.md, "The default").

	/* ENVIRONMENT API enums */

	enum EnvironmentBG {
		ENV_BG_CLEAR_COLOR,
		ENV_BG_COLOR,
		ENV_BG_SKY,
		ENV_BG_CANVAS,
		ENV_BG_KEEP,
		ENV_BG_CAMERA_FEED,
		ENV_BG_MAX
	};

	enum EnvironmentAmbientSource {
		ENV_AMBIENT_SOURCE_BG,
		ENV_AMBIENT_SOURCE_DISABLED,
		ENV_AMBIENT_SOURCE_COLOR,
		ENV_AMBIENT_SOURCE_SKY,
	};

	// Godot's SSAO/SSIL quality levels (same order). godot-area computes both in one image-space
	// radiosity pass (renderer_rd/effects/ss_radiosity_rd.h); the level picks its samples per pixel:
	// VERY_LOW 12, LOW 24, MEDIUM 48, HIGH 80, ULTRA 128 (the seed evaluated 24, 48 and 80).
	enum EnvironmentSSAOQuality {
		ENV_SSAO_QUALITY_VERY_LOW,
		ENV_SSAO_QUALITY_LOW,
		ENV_SSAO_QUALITY_MEDIUM,
		ENV_SSAO_QUALITY_HIGH,
		ENV_SSAO_QUALITY_ULTRA,
	};
	enum EnvironmentSSILQuality {
		ENV_SSIL_QUALITY_VERY_LOW,
		ENV_SSIL_QUALITY_LOW,
		ENV_SSIL_QUALITY_MEDIUM,
		ENV_SSIL_QUALITY_HIGH,
		ENV_SSIL_QUALITY_ULTRA,
	};
	// Samples per pixel of a quality level (12, 24, 48, 80, 128); 48 for an out-of-range value.
	static int get_ss_radiosity_sample_count(int p_quality);

	/* VIEWPORT API enums */

	// Godot 4's list, in order. The CLUSTER_* modes draw per-tile element counts.
	enum RenderingInfo {
		RENDERING_INFO_AREA_SHADOW_MAPS_IN_FRAME, // Shadow maps (sample points) the area lights averaged.
		RENDERING_INFO_AREA_SHADOW_DRAW_CALLS_IN_FRAME, // Draw calls of the area shadow depth pass.
		RENDERING_INFO_TOTAL_DRAW_CALLS_IN_FRAME, // Draw calls of the colour passes, opaque and transparent (Godot's name).
		RENDERING_INFO_AREA_LIGHT_DRAW_CALLS_IN_FRAME, // Of those, drawn with area-light shader code.
		RENDERING_INFO_MAX,
	};

	enum ViewportDebugDraw {
		VIEWPORT_DEBUG_DRAW_DISABLED,
		VIEWPORT_DEBUG_DRAW_UNSHADED,
		VIEWPORT_DEBUG_DRAW_LIGHTING,
		VIEWPORT_DEBUG_DRAW_OVERDRAW,
		VIEWPORT_DEBUG_DRAW_WIREFRAME,
		VIEWPORT_DEBUG_DRAW_NORMAL_BUFFER,
		VIEWPORT_DEBUG_DRAW_VOXEL_GI_ALBEDO,
		VIEWPORT_DEBUG_DRAW_VOXEL_GI_LIGHTING,
		VIEWPORT_DEBUG_DRAW_VOXEL_GI_EMISSION,
		VIEWPORT_DEBUG_DRAW_SHADOW_ATLAS,
		VIEWPORT_DEBUG_DRAW_DIRECTIONAL_SHADOW_ATLAS,
		VIEWPORT_DEBUG_DRAW_SCENE_LUMINANCE,
		VIEWPORT_DEBUG_DRAW_SSAO,
		VIEWPORT_DEBUG_DRAW_SSIL,
		VIEWPORT_DEBUG_DRAW_PSSM_SPLITS,
		VIEWPORT_DEBUG_DRAW_DECAL_ATLAS,
		VIEWPORT_DEBUG_DRAW_SDFGI,
		VIEWPORT_DEBUG_DRAW_SDFGI_PROBES,
		VIEWPORT_DEBUG_DRAW_GI_BUFFER,
		VIEWPORT_DEBUG_DRAW_DISABLE_LOD,
		VIEWPORT_DEBUG_DRAW_CLUSTER_OMNI_LIGHTS,
		VIEWPORT_DEBUG_DRAW_CLUSTER_SPOT_LIGHTS,
		VIEWPORT_DEBUG_DRAW_CLUSTER_DECALS,
		VIEWPORT_DEBUG_DRAW_CLUSTER_REFLECTION_PROBES,
		VIEWPORT_DEBUG_DRAW_OCCLUDERS,
		VIEWPORT_DEBUG_DRAW_MOTION_VECTORS,
		VIEWPORT_DEBUG_DRAW_INTERNAL_BUFFER,
		// godot-area addition (appended to keep Godot's values): per-pixel count of area lights in the pixel's cluster.
		VIEWPORT_DEBUG_DRAW_CLUSTER_AREA_LIGHTS,
	};

	/* INSTANCE API enums */

	enum InstanceType {
		INSTANCE_NONE,
		INSTANCE_MESH,
		INSTANCE_LIGHT,
	};

	/* MESH API */

	// Creates an empty mesh resource.
	virtual RID mesh_create() = 0;
	// Appends a surface (validated: sizes must match, indices in range); fills its AABB.
	virtual void mesh_add_surface(RID p_mesh, const SurfaceData &p_surface) = 0;
	// Sets the material used by one surface (RID() clears it).
	virtual void mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) = 0;
	// Returns the material of one surface, or RID().
	virtual RID mesh_surface_get_material(RID p_mesh, int p_surface) const = 0;
	// Returns the number of surfaces (0 for an invalid mesh).
	virtual int mesh_get_surface_count(RID p_mesh) const = 0;
	// Returns the union of the surface AABBs in object space.
	virtual AABB mesh_get_aabb(RID p_mesh) const = 0;
	// Removes all surfaces.
	virtual void mesh_clear(RID p_mesh) = 0;

	/* TEXTURE API */

	// Creates a 2D texture from float RGBA texels (top row first) as stored in the file
	// (colour textures sRGB-encoded, normal maps linear). Returns RID() for an empty image.
	virtual RID texture_2d_create(const Image &p_image) = 0;
	// Same, from 8-bit RGBA texels (p_width * p_height * 4 bytes); converted to float / 255.
	virtual RID texture_2d_create_rgba8(int p_width, int p_height, const std::vector<uint8_t> &p_data) = 0;
	// Returns the texel data kept on the CPU (empty image for an invalid RID).
	virtual Image texture_2d_get(RID p_texture) const = 0;

	/* MATERIAL API */

	// Creates a material with default MaterialParams.
	virtual RID material_create() = 0;
	// Replaces all parameters of a material.
	virtual void material_set_params(RID p_material, const MaterialParams &p_params) = 0;
	// Returns the parameters of a material (defaults for an invalid RID).
	virtual MaterialParams material_get_params(RID p_material) const = 0;

	/* LIGHT API */

	// Creates a directional light resource (storage defaults, not node defaults).
	virtual RID directional_light_create() = 0;
	// Creates an omni light resource.
	virtual RID omni_light_create() = 0;
	// Creates a spot light resource.
	virtual RID spot_light_create() = 0;
	// Creates an area light resource (storage defaults: a 1 x 1 m rectangle, energy normalised, LTC).
	virtual RID area_light_create() = 0;
	// Sets one scalar parameter; NaN/inf or out-of-domain values print an error and are ignored.
	virtual void light_set_param(RID p_light, LightParam p_param, float p_value) = 0;
	// Sets the light colour (sRGB, as the node property).
	virtual void light_set_color(RID p_light, const Color &p_color) = 0;
	// Enables or disables shadow casting.
	virtual void light_set_shadow(RID p_light, bool p_enabled) = 0;
	// Makes the light subtract instead of add.
	virtual void light_set_negative(RID p_light, bool p_enable) = 0;
	// Sets which instance layers the light affects.
	virtual void light_set_cull_mask(RID p_light, uint32_t p_mask) = 0;
	// Sets which instance layers cast shadows from this light.
	virtual void light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) = 0;
	// Renders shadows from back faces.
	virtual void light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) = 0;
	// Sets the GI bake mode (stored only).
	virtual void light_set_bake_mode(RID p_light, LightBakeMode p_bake_mode) = 0;
	// Sets distance fade (begin, shadow and length in metres).
	virtual void light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) = 0;
	// Sets the omni shadow mode.
	virtual void light_omni_set_shadow_mode(RID p_light, LightOmniShadowMode p_mode) = 0;
	// Sets the directional shadow mode.
	virtual void light_directional_set_shadow_mode(RID p_light, LightDirectionalShadowMode p_mode) = 0;
	// Blends between PSSM splits.
	virtual void light_directional_set_blend_splits(RID p_light, bool p_enable) = 0;
	// Sets whether a directional light affects the sky, the scene, or both.
	virtual void light_directional_set_sky_mode(RID p_light, LightDirectionalSkyMode p_mode) = 0;
	// Sets the rectangle of an area light in metres: x along the light's local +X, y along +Y. Both
	// components must be finite and >= 0 (a zero area emits nothing); bad values are ignored with an error.
	virtual void light_area_set_size(RID p_light, const Vector2 &p_size) = 0;
	// True: the emitted radiance is divided by the shape's emitting area A, so the light's power does not
	// change with its size (L_e = colour * energy * pi / A; rectangle A = x y, disk pi x y / 4, sphere
	// pi x^2, tube pi y x + pi y^2); false: L_e = colour * energy * pi.
	virtual void light_area_set_normalize_energy(RID p_light, bool p_enable) = 0;
	// Sets the shading method of an area light.
	virtual void light_area_set_shading_method(RID p_light, LightAreaShadingMethod p_method) = 0;
	// Sets the sample count of LIGHT_AREA_SHADING_STOCHASTIC (per strategy and shading point; 1..256,
	// other values are rejected with an error).
	virtual void light_area_set_stochastic_samples(RID p_light, int p_samples) = 0;
	// Sets how an area light's shadows are drawn (when light_set_shadow is on).
	virtual void light_area_set_shadow_mode(RID p_light, LightAreaShadowMode p_mode) = 0;
	// Sets the sample grid of LIGHT_AREA_SHADOW_FIXED: p_grid x p_grid shadow maps (2..9; others rejected).
	virtual void light_area_set_shadow_grid(RID p_light, int p_grid) = 0;
	// Sets the emitting shape of an area light (what its size means: see LightAreaShape; other values are
	// rejected with an error, the old shape kept).
	virtual void light_area_set_shape(RID p_light, LightAreaShape p_shape) = 0;
	// Sets the texture of an area light (upstream Godot 4.7's area_texture): the emitted radiance at
	// each point of the rectangle is L_e times the texture's linear colour there (texels sRGB-encoded;
	// u runs along the light's local -X, v along -Y, so the image reads upright from the lit side).
	// RID() removes it. The renderer copies the texels into its area-light atlas once, on change.
	virtual void light_area_set_texture(RID p_light, RID p_texture) = 0;
	// Returns the light type (LIGHT_DIRECTIONAL for an invalid RID, with an error).
	virtual LightType light_get_type(RID p_light) const = 0;
	// Returns one scalar parameter (0 for an invalid RID or index).
	virtual float light_get_param(RID p_light, LightParam p_param) const = 0;
	// Returns the local-space bound (omni: cube of side 2 * range; spot: cone AABB; directional: empty;
	// area: the box (a + 2r) x (b + 2r) x r in front of the rectangle, z from -r to 0).
	virtual AABB light_get_aabb(RID p_light) const = 0;
	// Returns the rectangle of an area light (metres; zero with an error for an invalid RID).
	virtual Vector2 light_area_get_size(RID p_light) const = 0;
	// Returns whether an area light normalises its energy by its area.
	virtual bool light_area_get_normalize_energy(RID p_light) const = 0;
	// Returns the shading method of an area light.
	virtual LightAreaShadingMethod light_area_get_shading_method(RID p_light) const = 0;
	// Returns the sample count of the stochastic method.
	virtual int light_area_get_stochastic_samples(RID p_light) const = 0;
	// Returns the shadow mode of an area light.
	virtual LightAreaShadowMode light_area_get_shadow_mode(RID p_light) const = 0;
	// Returns the shadow sample grid of an area light.
	virtual int light_area_get_shadow_grid(RID p_light) const = 0;
	// Returns the emitting shape of an area light (RECTANGLE with an error for an invalid RID).
	virtual LightAreaShape light_area_get_shape(RID p_light) const = 0;
	// Returns the texture of an area light (RID() when untextured).
	virtual RID light_area_get_texture(RID p_light) const = 0;

	/* CAMERA API */

	// Creates a camera (perspective 75 degrees, near 0.05, far 4000, identity transform: Godot's Camera3D defaults).
	virtual RID camera_create() = 0;
	// Sets a perspective projection; p_fovy_degrees is the vertical field of view.
	virtual void camera_set_perspective(RID p_camera, float p_fovy_degrees, float p_z_near, float p_z_far) = 0;
	// Sets the camera-to-world transform (the camera looks down its local -Z).
	virtual void camera_set_transform(RID p_camera, const Transform3D &p_transform) = 0;
	// Sets which instance layers the camera sees.
	virtual void camera_set_cull_mask(RID p_camera, uint32_t p_layers) = 0;
	// Overrides the scenario's environment for this camera (RID() removes the override).
	virtual void camera_set_environment(RID p_camera, RID p_env) = 0;

	/* ENVIRONMENT API */
	// Like Godot, an environment is attached to a scenario (WorldEnvironment) and may be
	// overridden per camera (Camera3D.environment). Without any, the default clear colour is used.

	// Creates an environment (background CLEAR_COLOR, ambient source BG, Godot's defaults).
	virtual RID environment_create() = 0;
	// Sets the background mode (CLEAR_COLOR, COLOR and SKY are drawn; others fall back to CLEAR_COLOR).
	virtual void environment_set_background(RID p_env, EnvironmentBG p_bg) = 0;
	// Sets the background colour (sRGB) used by ENV_BG_COLOR.
	virtual void environment_set_bg_color(RID p_env, const Color &p_color) = 0;
	// Sets the background energy multiplier.
	virtual void environment_set_bg_energy(RID p_env, float p_multiplier) = 0;
	// Sets the ambient light colour (sRGB), its source and energy.
	virtual void environment_set_ambient_light(RID p_env, const Color &p_color, EnvironmentAmbientSource p_ambient = ENV_AMBIENT_SOURCE_BG, float p_energy = 1.0f) = 0;
	// Godot's Environment SSAO and SSIL parameters (meanings and units as Godot's; the mapping onto the
	// image-space radiosity terms is in doc/isr.md). Disabled by default: a view with neither pays nothing.
	virtual void environment_set_ssao(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_power, float p_detail, float p_horizon, float p_sharpness, float p_light_affect, float p_ao_channel_affect) = 0;
	virtual void environment_set_ssil(RID p_env, bool p_enable, float p_radius, float p_intensity, float p_sharpness, float p_normal_rejection) = 0;
	// Global quality (Godot's rendering/environment/ssao|ssil/* project settings): samples per pixel,
	// half resolution (default true: a quarter of the pixels) and blur passes (0..4, default 2 as Godot).
	virtual void environment_set_ssao_quality(EnvironmentSSAOQuality p_quality, bool p_half_size, int p_blur_passes = 2) = 0;
	virtual void environment_set_ssil_quality(EnvironmentSSILQuality p_quality, bool p_half_size, int p_blur_passes = 2) = 0;

	/* SKY API */
	// Godot's ProceduralSkyMaterial parameters (colours sRGB as saved, angles in degrees), pushed as a whole.
	struct ProceduralSkyParams {
		Color sky_top_color = Color(0.385f, 0.454f, 0.55f);
		Color sky_horizon_color = Color(0.6463f, 0.6558f, 0.6708f);
		float sky_curve = 0.15f;
		float sky_energy_multiplier = 1.0f;
		Color ground_bottom_color = Color(0.2f, 0.169f, 0.133f);
		Color ground_horizon_color = Color(0.6463f, 0.6558f, 0.6708f);
		float ground_curve = 0.02f;
		float ground_energy_multiplier = 1.0f;
		float sun_angle_max = 30.0f; // Degrees.
		float sun_curve = 0.15f;
		float energy_multiplier = 1.0f;
		bool operator==(const ProceduralSkyParams &p_o) const {
			return sky_top_color == p_o.sky_top_color && sky_horizon_color == p_o.sky_horizon_color && sky_curve == p_o.sky_curve && sky_energy_multiplier == p_o.sky_energy_multiplier &&
					ground_bottom_color == p_o.ground_bottom_color && ground_horizon_color == p_o.ground_horizon_color && ground_curve == p_o.ground_curve &&
					ground_energy_multiplier == p_o.ground_energy_multiplier && sun_angle_max == p_o.sun_angle_max && sun_curve == p_o.sun_curve && energy_multiplier == p_o.energy_multiplier;
		}
	};
	// Godot's PhysicalSkyMaterial parameters (colours sRGB as saved); night_sky is not drawn (counted warning).
	struct PhysicalSkyParams {
		float rayleigh_coefficient = 2.0f;
		Color rayleigh_color = Color(0.3f, 0.405f, 0.6f);
		float mie_coefficient = 0.005f;
		float mie_eccentricity = 0.8f;
		Color mie_color = Color(0.69f, 0.729f, 0.812f);
		float turbidity = 10.0f;
		float sun_disk_scale = 1.0f;
		Color ground_color = Color(0.1f, 0.07f, 0.034f);
		float energy_multiplier = 1.0f;
		bool use_debanding = true;
		bool has_night_sky = false; // A night_sky texture was set (stored, not drawn).
		bool operator==(const PhysicalSkyParams &p_o) const {
			return rayleigh_coefficient == p_o.rayleigh_coefficient && rayleigh_color == p_o.rayleigh_color && mie_coefficient == p_o.mie_coefficient &&
					mie_eccentricity == p_o.mie_eccentricity && mie_color == p_o.mie_color && turbidity == p_o.turbidity && sun_disk_scale == p_o.sun_disk_scale &&
					ground_color == p_o.ground_color && energy_multiplier == p_o.energy_multiplier && use_debanding == p_o.use_debanding && has_night_sky == p_o.has_night_sky;
		}
	};
	enum SkyMaterialType {
		SKY_MATERIAL_PROCEDURAL,
		SKY_MATERIAL_PHYSICAL,
	};
	// A sky material (ProceduralSkyMaterial or PhysicalSkyMaterial) and a sky (Sky: material + radiance size),
	// as Godot's RS. Setting either parameter block makes the material of that type.
	virtual RID sky_material_create() = 0;
	virtual void sky_material_set_procedural(RID p_material, const ProceduralSkyParams &p_params) = 0;
	virtual void sky_material_set_physical(RID p_material, const PhysicalSkyParams &p_params) = 0;
	virtual RID sky_create() = 0;
	virtual void sky_set_material(RID p_sky, RID p_material) = 0;
	// Radiance cubemap size in pixels (Godot's Sky.radiance_size as a size: 32..2048).
	virtual void sky_set_radiance_size(RID p_sky, int p_size) = 0;
	// The sky of ENV_BG_SKY and of sky ambient (RID() = none).
	virtual void environment_set_sky(RID p_env, RID p_sky) = 0;
	// ambient_light_sky_contribution (0..1): the share of the ambient that comes from the sky.
	virtual void environment_set_ambient_sky_contribution(RID p_env, float p_contribution) = 0;
	// Environment.reflected_light_source (Godot's order and default BG): where glossy surfaces' reflections come
	// from. BG: the sky when background_mode is SKY, none otherwise; DISABLED: none; SKY: the sky whatever the
	// background.
	enum EnvironmentReflectionSource {
		ENV_REFLECTION_SOURCE_BG,
		ENV_REFLECTION_SOURCE_DISABLED,
		ENV_REFLECTION_SOURCE_SKY,
	};
	virtual void environment_set_reflection_source(RID p_env, EnvironmentReflectionSource p_source) = 0;

	/* SCENARIO API */

	// Creates a scenario (a world that instances live in).
	virtual RID scenario_create() = 0;
	// Sets the environment of a scenario (WorldEnvironment); RID() removes it.
	virtual void scenario_set_environment(RID p_scenario, RID p_environment) = 0;

	/* INSTANCE API */

	// Creates an instance with no base and no scenario.
	virtual RID instance_create() = 0;
	// Sets the base resource (mesh or light RID; RID() detaches). The type is taken from the RID.
	virtual void instance_set_base(RID p_instance, RID p_base) = 0;
	// Puts the instance into a scenario (RID() removes it).
	virtual void instance_set_scenario(RID p_instance, RID p_scenario) = 0;
	// Sets the world transform.
	virtual void instance_set_transform(RID p_instance, const Transform3D &p_transform) = 0;
	// Shows or hides the instance.
	virtual void instance_set_visible(RID p_instance, bool p_visible) = 0;
	// Sets the render layers of the instance (matched against light and camera cull masks).
	virtual void instance_set_layer_mask(RID p_instance, uint32_t p_mask) = 0;
	// Overrides the material of every surface (RID() removes the override).
	virtual void instance_geometry_set_material_override(RID p_instance, RID p_material) = 0;
	// GeometryInstance3D::cast_shadow: OFF casts no shadow, SHADOWS_ONLY casts but is not drawn; ON and
	// DOUBLE_SIDED cast from both faces here (the shadow passes and the reference do not cull faces).
	virtual void instance_geometry_set_cast_shadows_setting(RID p_instance, ShadowCastingSetting p_setting) = 0;
	// Returns the world-space AABB of the instance's base (empty for lights of directional type).
	virtual AABB instance_get_aabb(RID p_instance) const = 0;

	/* VIEWPORT API */

	// Creates a viewport (active, size 0: nothing is rendered until viewport_set_size).
	virtual RID viewport_create() = 0;
	// Sets the size in pixels and (re)creates its render target.
	virtual void viewport_set_size(RID p_viewport, int p_width, int p_height) = 0;
	// Enables or disables drawing of the viewport in draw().
	virtual void viewport_set_active(RID p_viewport, bool p_active) = 0;
	// Sets the camera the viewport renders from.
	virtual void viewport_attach_camera(RID p_viewport, RID p_camera) = 0;
	// Sets the scenario the viewport renders.
	virtual void viewport_set_scenario(RID p_viewport, RID p_scenario) = 0;
	// Sets the debug draw mode.
	virtual void viewport_set_debug_draw(RID p_viewport, ViewportDebugDraw p_draw) = 0;
	// Returns the last rendered image (float RGBA, linear HDR, top row first); empty if none.
	virtual Image viewport_get_texture_data(RID p_viewport) const = 0;
	// The RenderingDevice texture the viewport renders into (scene-linear RGBA16F; Godot:
	// viewport_get_texture), for sampling it on the GPU without a readback. Null before the
	// viewport has a size or on a renderer without textures (the dummy one). It changes when
	// the viewport's size does.
	virtual RID viewport_get_texture(RID p_viewport) const = 0;
	// Area-light shadow atlas of the viewport (each viewport has its own, as Godot's shadow atlas):
	// p_size x p_size pixels (a power of two, AREA_SHADOW_ATLAS_SIZE_MIN..MAX) split into p_subdivision x
	// p_subdivision tiles (AREA_SHADOW_ATLAS_SUBDIVISION_MIN..MAX, tiles of at least 16 px), one shadow map
	// per tile. p_size 0 restores the renderer's default (4096 px, 16 x 16). Bad values print an error
	// naming the problem and keep the old ones. Changing the size redraws every map of the viewport.
	virtual void area_shadow_atlas_set_size(RID p_viewport, int p_size, int p_subdivision) = 0;
	// The viewport's atlas size and subdivision (0, 0 while it uses the renderer's default).
	virtual int area_shadow_atlas_get_size(RID p_viewport) const = 0;
	virtual int area_shadow_atlas_get_subdivision(RID p_viewport) const = 0;
	// How each sample map's depth lookup is filtered (Godot's soft_shadow_filter_quality is the same kind
	// of global choice). The project setting rendering/lights_and_shadows/area_shadow_filter gives the
	// start value.
	enum AreaShadowFilter {
		AREA_SHADOW_FILTER_PCF, // The fixed-size PCF kernel of shadow_blur on every map (thesis 6.1 as written).
		AREA_SHADOW_FILTER_PENUMBRA, // Default: filtered over the penumbra of the light cell the map's sample
		// point stands for (shaders/area_light_shadow_inc.glsl, doc/shadows.md "The default").
		AREA_SHADOW_FILTER_MAX,
	};
	virtual void area_shadow_filter_set_mode(AreaShadowFilter p_filter) = 0;
	virtual AreaShadowFilter area_shadow_filter_get_mode() const = 0;
	static constexpr int AREA_SHADOW_ATLAS_SIZE_MIN = 256;
	static constexpr int AREA_SHADOW_ATLAS_SIZE_MAX = 16384;
	static constexpr int AREA_SHADOW_ATLAS_SUBDIVISION_MIN = 1;
	static constexpr int AREA_SHADOW_ATLAS_SUBDIVISION_MAX = 64;

	/* MISC */

	// Sets the colour of ENV_BG_CLEAR_COLOR (Godot's default_clear_color, sRGB).
	virtual void set_default_clear_color(const Color &p_color) = 0;
	// Returns the default clear colour.
	virtual Color get_default_clear_color() const = 0;
	// Renders every active viewport that has a size, a camera and a scenario.
	virtual void draw() = 0;
	// Frees any RID created by this server; prints an error for unknown RIDs.
	virtual void free(RID p_rid) = 0;
	// GPU time of each pass of the last frame, as (pass name, milliseconds).
	virtual std::vector<std::pair<String, double>> get_frame_profile() const = 0;
	// ADAPTIVE area-shadow quads tested by the last draw(), all viewports: 0 once every AREA_SHADOW_ADAPTIVE
	// light has settled (its subdivision refines over frames; a still render draws until this is 0).
	virtual uint32_t get_frame_area_shadow_tests() const = 0;
	// Counters of the last draw(), summed over every viewport (Godot's RenderingServer::get_rendering_info()).
	virtual uint64_t get_rendering_info(RenderingInfo p_info) const = 0;
	// Renderer tests: when true the renderer shades every light per pixel (no clustering).
	virtual void set_debug_force_all_lights(bool p_enable) = 0;
	// Benchmarks: when true the renderer skips its per-frame area-light work (area shadow frame setup,
	// AUTO receiver scan), the baseline a scene without area lights is timed against ("pays nothing").
	virtual void set_debug_disable_area_lights(bool p_disable) = 0;
	// Shader statistics: the colour pass's fragment sources as the renderer composes them, as (file name,
	// GLSL): "base.frag" without area lights, then "area_<METHOD>.frag" per area shading method (rectangles
	// only), then "area_<METHOD>_shapes.frag" per method with the disk, sphere and tube code. Empty for
	// renderers without GLSL.
	virtual std::vector<std::pair<String, String>> get_debug_scene_shader_sources() const = 0;

	RenderingServer();
	virtual ~RenderingServer();
};

typedef RenderingServer RS;
