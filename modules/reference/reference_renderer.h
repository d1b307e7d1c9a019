/**************************************************************************/
/*  reference_renderer.h                                                  */
/**************************************************************************/
/* godot-area: the CPU ground-truth renderer. Traces one primary ray per  */
/* pixel centre (the GPU rasteriser's sample point) through the scene's   */
/* world-space triangles with Embree 3, and shades the hit with the C++   */
/* twins of the GPU shader code (brdf.h, forward_lights.h), reading the   */
/* same storages and RenderSceneData as the GPU renderer. Differences to  */
/* the GPU image are therefore the GPU method's own error (and, with      */
/* shadows on, visibility).                                               */
/*                                                                        */
/* Part of the backend RendererCompositorReference:                       */
/*   new RenderingServerDefault(new RendererCompositorReference(opts));   */

#pragma once

#include "core/templates/rid_owner.h"
#include "modules/reference/area_light.h"
#include "modules/reference/area_light_integrator.h"
#include "modules/reference/forward_lights.h"
#include "modules/reference/sampling.h"
#include "modules/reference/sky_light.h"
#include "modules/reference/sun_light.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/storage/light_storage.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"

#include <cstdint>

class Image;

/*************************************************************************/
/* Definition                                                            */
/*************************************************************************/

struct ReferenceRenderOptions {
	// Sample cap of every adaptive integral of a pixel (area lights; punctual lights are exact).
	int max_samples = 4096;
	// Adaptive integrals stop when their relative standard error is below this (0.002 = 0.2 %).
	float target_relative_error = 0.002f;
	// How area lights are sampled (area_light_integrator.h). MIS (solid angle + GGX visible normals)
	// is robust for glossy lobes under large lights; AREA is the first reference's uniform area sampling.
	ReferenceBRDF::AreaLightSampling area_sampling = ReferenceBRDF::AREA_LIGHT_SAMPLING_MIS;
	// Trace shadow rays (hard shadows for omni and spot lights, one ray per sample of an area light).
	// Off: every light is unoccluded, as in the GPU renderer, which has no shadows yet.
	bool shadows = false;
	// Samples of each directional light's disk per pixel (jittered strata; 0 angular size: one exact
	// evaluation). Rounded down to a square.
	int sun_samples = 64;
	// Directions of the sky (environment light) per pixel for sky ambient (importance-sampled, stratified).
	int sky_samples = 256;
	// Worker threads; 0 = std::thread::hardware_concurrency().
	int threads = 0;
	// Seed of the per-pixel random generators (same seed: bit-identical image).
	uint64_t seed = 0;
	// Print a progress bar on stderr.
	bool progress = false;
	// Diffuse bounces of indirect light (0 = direct only; 1 = one bounce, the image-space radiosity
	// ground truth). Each pixel traces bounce_samples cosine-distributed rays from its surface; the
	// first surface each hits is shaded with the same direct lighting (lights, BRDF, ambient, emission)
	// as a primary hit, its area lights with at most bounce_light_samples samples, its sky ambient
	// with bounce_light_samples directions, and the result reaches the pixel through the diffuse lobe
	// of the pixel's material (albedo * (1 - metallic) times its diffuse BRDF, no specular).
	// A ray that hits nothing brings no light (the sky is counted as ambient, not bounced).
	int bounces = 0;
	int bounce_samples = 64;
	int bounce_light_samples = 16;
};

// Counters of the last render_scene() call.
struct ReferenceRenderStats {
	int width = 0;
	int height = 0;
	int threads = 0;
	uint64_t primary_rays = 0;
	uint64_t shadow_rays = 0;
	uint64_t area_light_samples = 0; // Directions sampled by all area-light integrals (a MIS pair counts 2).
	uint64_t area_light_integrals = 0; // Area-light integrals evaluated (pixel x light, zero ones excluded).
	uint64_t area_light_integrals_converged = 0; // Those that met the error target before the cap.
	uint64_t bounce_rays = 0; // Indirect rays traced (options.bounces).
	// Per pixel (row-major, top row first): the largest relative standard error of the pixel's area-light
	// integrals (0 without any), and the directions they sampled.
	std::vector<float> pixel_relative_error;
	std::vector<uint32_t> pixel_area_samples;
	uint64_t triangles = 0;
	double seconds = 0.0; // Wall time (reported, never asserted).
};

struct RTCFilterFunctionNArguments; // Embree.

class ReferenceRenderer : public RendererSceneRender {
public:
	/*************************************************************************/
	/* Public Methods                                                        */
	/*************************************************************************/

	void render_scene(const RenderSceneData &p_data, RID p_render_target) override;
	RID render_target_create(int p_width, int p_height) override;
	bool render_target_free(RID p_rid) override;
	bool owns_render_target(RID p_rid) const override { return render_target_owner.owns(p_rid); }
	// Linear RGBA floats, top row first; opaque black before the first render.
	std::vector<float> render_target_get_data(RID p_render_target) override;
	// One entry ("reference", wall milliseconds of the last frame).
	std::vector<std::pair<String, double>> get_last_frame_profile() const override;
	// No effect: the reference always shades every light.
	void set_debug_force_all_lights(bool p_enable) override {}

	void set_options(const ReferenceRenderOptions &p_options) { options = p_options; }
	const ReferenceRenderOptions &get_options() const { return options; }
	const ReferenceRenderStats &get_last_stats() const { return last_stats; }

	// Storages are not owned; they must outlive the renderer.
	ReferenceRenderer(RendererLightStorage *p_light_storage, RendererMeshStorage *p_mesh_storage, RendererMaterialStorage *p_material_storage, const ReferenceRenderOptions &p_options = ReferenceRenderOptions());
	~ReferenceRenderer() override;

	/*************************************************************************/
	/* Private Members                                                       */
	/*************************************************************************/
private:
	struct RenderTarget {
		int width = 0;
		int height = 0;
		std::vector<float> data;
	};

	// Material parameters in shading units (as RendererRD::MaterialStorage::_make_ubo converts them).
	struct ShadingMaterial {
		Vector3 albedo = Vector3(1, 1, 1); // Linear.
		float alpha = 1.0f;
		Vector3 emission; // Linear * emission energy.
		float roughness = 1.0f;
		float metallic = 0.0f;
		float specular = 0.5f;
		float normal_scale = 1.0f;
		uint32_t diffuse_mode = ReferenceBRDF::BRDF_DIFFUSE_BURLEY;
		bool unshaded = false;
		bool specular_enabled = true;
		bool cull_back = true;
		// A texture: its base level and, for the mipmap filters, levels 1..n (valid during render_scene()).
		struct Texture {
			const Image *image = nullptr;
			const std::vector<Image> *levels = nullptr;
		};
		// Albedo (sRGB chain), normal, roughness, metallic; roughness and metallic are read through their
		// channel weights.
		Texture textures[4];
		float roughness_channel[4] = { 1, 0, 0, 0 };
		float metallic_channel[4] = { 1, 0, 0, 0 };
		Vector2 uv1_scale = Vector2(1, 1);
		Vector2 uv1_offset;
		bool nearest = false; // texture_filter NEAREST*: Vulkan NEAREST instead of LINEAR.
		bool mipmaps = false; // texture_filter *_WITH_MIPMAPS*: sampled at the ray differentials' level.
		// ALPHA_SCISSOR: cut-out geometry (rays pass where alpha < the threshold, shadow rays too).
		// ALPHA: composited over what the ray meets behind it; casts no shadow (as Godot).
		RS::MaterialTransparency transparency = RS::MATERIAL_TRANSPARENCY_DISABLED;
		float alpha_scissor_threshold = 0.5f;
		bool vertex_color = false; // vertex_color_use_as_albedo: albedo and alpha *= the surface's colours.
		bool vertex_color_srgb = false; // vertex_color_is_srgb: their rgb is decoded first.
	};

	// One mesh surface of one instance, in world space (one Embree geometry).
	struct Surface {
		std::vector<Vector3> positions; // World.
		std::vector<Vector3> normals; // normal_matrix * object normal (not normalised, as the GPU).
		std::vector<Vector3> tangents; // world basis * object tangent.
		std::vector<Vector3> binormals; // cross(normal, tangent) * sign, per vertex (as the GPU).
		std::vector<Vector2> uvs; // Zero when the surface has none.
		std::vector<Color> colors; // ARRAY_COLOR; empty when the surface has none (white).
		std::vector<uint32_t> indices; // 3 per triangle.
		std::vector<Vector3> face_normals; // (c - a) x (b - a): points to the front (clockwise) side.
		ShadingMaterial material;
		uint32_t layer_mask = 1;
		RS::ShadowCastingSetting cast_shadows = RS::SHADOW_CASTING_SETTING_ON; // Off: no shadow rays hit it; Shadows Only: only they do.
	};

	struct Light {
		RS::LightType type = RS::LIGHT_OMNI;
		ReferenceBRDF::LightData data; // Omni and spot.
		ReferenceBRDF::AreaLightData area; // LIGHT_AREA.
		ReferenceBRDF::DirectionalLightData sun; // LIGHT_DIRECTIONAL.
	};

	struct Frame; // Everything render_scene() sets up for the workers (Embree scene, camera, lights).

	RendererLightStorage *light_storage = nullptr;
	RendererMeshStorage *mesh_storage = nullptr;
	RendererMaterialStorage *material_storage = nullptr;
	ReferenceRenderOptions options;
	ReferenceRenderStats last_stats;
	void *embree_device = nullptr; // RTCDevice.
	mutable RID_Owner<RenderTarget, true> render_target_owner{ "ReferenceRenderTarget" };

	ShadingMaterial _resolve_material(RID p_material) const;
	// Embree filter of a surface with back-face culling or transparency (user data: its Surface):
	// p_occlusion for shadow rays.
	static void _surface_filter(const RTCFilterFunctionNArguments *p_args, bool p_occlusion);
	static void _surface_intersect_filter(const RTCFilterFunctionNArguments *p_args) { _surface_filter(p_args, false); }
	static void _surface_occluded_filter(const RTCFilterFunctionNArguments *p_args) { _surface_filter(p_args, true); }
	// The material alpha of a surface at barycentrics (b1, b2) of triangle p_prim (level 0 of the texture).
	static float _surface_alpha(const Surface &p_surface, uint32_t p_prim, float p_b1, float p_b2);
	bool _build_surface(const RS::SurfaceData &p_data, const Transform3D &p_xform, Surface &r_surface) const;
	bool _make_light(const RenderSceneData::LightInstance &p_instance, Light &r_light) const;
	// Counters of one pixel's shading (summed per thread, then per frame).
	struct PixelCounters {
		uint64_t shadow_rays = 0;
		uint64_t area_samples = 0;
		uint64_t area_integrals = 0;
		uint64_t area_converged = 0;
		float max_relative_error = 0.0f; // This pixel only.
		uint32_t pixel_samples = 0; // This pixel only.
		uint64_t bounce_rays = 0;
	};

	static void _render_rows(const Frame &p_frame, int p_thread, std::vector<float> &r_pixels);
	// The rays through the centres of the next pixel right (0) and down (1) (reference_texture.h).
	struct RayDifferentials {
		Vector3 origins[2];
		Vector3 dirs[2];
	};
	static Color _shade_pixel(const Frame &p_frame, int p_x, int p_y, ReferenceRNG &r_rng, PixelCounters &r_counters);
	// The radiance along a ray (origin, unit direction, length) with p_bounces diffuse bounces left;
	// r_hit says whether it met a surface (else the background is returned).
	// p_diff: the primary ray's differentials (nullptr for bounce rays: textures read level 0).
	static Color _shade_ray(const Frame &p_frame, const ReferenceRenderOptions &p_options, const Vector3 &p_origin, const Vector3 &p_dir, float p_tfar, int p_bounces, ReferenceRNG &r_rng, PixelCounters &r_counters, bool &r_hit, const RayDifferentials *p_diff = nullptr);
};
