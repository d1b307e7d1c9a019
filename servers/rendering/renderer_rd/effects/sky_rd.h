/**************************************************************************/
/*  sky_rd.h                                                              */
/**************************************************************************/
/* godot-area: the sky of the Forward+ renderer (Godot's RendererRD::     */
/* SkyRD, reduced to ProceduralSkyMaterial): the background pass          */
/* (shaders/sky.glsl) and the sky ambient, irradiance spherical harmonics */
/* (sky_model.h) in a uniform buffer that the scene shader reads at       */
/* binding 9 in versions with USE_SKY_AMBIENT. The SH are recomputed on   */
/* the CPU only when the sky model (material, background energy or the   */
/* sun that its disk follows) changes; get_update_count() counts that.   */
/* Nothing is created before the first view with a sky: a scene without  */
/* one has no sky shader, buffer or pipeline.                             */
/*                                                                        */
/* Sky reflections (Environment.reflected_light_source resolved into     */
/* EnvironmentData::sky_reflections): a radiance cubemap of Sky.          */
/* radiance_size texels (RGBA16F) with min(8, log2(size) + 1) mips, 8    */
/* being Godot's rendering/reflections/sky_reflections/roughness_layers. */
/* Mip i holds the sky prefiltered (shaders/sky_radiance.glsl, GGX       */
/* importance sampling) for perceptual roughness (i / (mips - 1))^2:     */
/* Godot filters layer i with roughness i / (layers - 1) and the scene    */
/* shader reads lod = sqrt(roughness) * (layers - 1), so the two meet.   */
/* Filtered on the GPU only when the sky model or the size changes       */
/* (get_radiance_update_count()), timed as the "sky_radiance" pass; the  */
/* scene shader samples it in versions with USE_SKY_REFLECTION.          */

#pragma once

#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/sky_model.h"

#include <algorithm>
#include <map>
#include <vector>

class RendererLightStorage;

class SkyRD {
public:
	struct SkyDataUBO { // Mirror of SkyDataBlock in shaders/sky.glsl (std140).
		float view_from_clip[16];
		float world_from_view[16];
		float viewport_size[4];
		float sky_top[4];
		float sky_horizon[4];
		float ground_bottom[4];
		float ground_horizon[4];
		float curves[4];
		float sun_direction[4];
		float sun_radiance[4];
		float rayleigh_beta[4];
		float mie_beta[4];
		float physical_ground[4];
		float physical_sun[4];
		float physical_disk[4];
	};
	static_assert(sizeof(SkyDataUBO) == 336, "SkyDataUBO must match shaders/sky_inc.glsl.");

	struct RadiancePushConstant { // Mirror of Params in shaders/sky_radiance.glsl.
		uint32_t face;
		uint32_t size;
		float alpha;
		uint32_t sample_count;
	};
	static constexpr int MAX_RADIANCE_MIPS = 8; // Godot's roughness_layers default.
	// GGX samples per texel for mip p_mip (> 0): 8 at mip 1 (a lobe about a texel wide), doubling per mip up
	// to 64 (the rough mips have few texels; their wide lobes over a smooth sky need no more on this test).
	static uint32_t get_radiance_sample_count(int p_mip) { return p_mip <= 0 ? 1u : std::min(64u, 8u << (p_mip - 1)); }
	// Perceptual roughness a mip is filtered for (see above).
	static float get_mip_roughness(int p_mip, int p_mips) {
		const float t = p_mips > 1 ? float(p_mip) / float(p_mips - 1) : 0.0f;
		return t * t;
	}

	// Mirror of SkyAmbient (binding 9) in scene_forward_clustered_inc.glsl: the sky part of the ambient
	// light per SH coefficient, already times ambient_light_sky_contribution / pi (rgb, w unused).
	struct SkyAmbientUBO {
		float sh[9][4];
		float pad[4];
	};
	static_assert(sizeof(SkyAmbientUBO) == 160, "SkyAmbientUBO must match scene_forward_clustered_inc.glsl.");

private:
	ShaderRD shader;
	bool shader_ready = false;
	RID data_ubo;
	RID ambient_ubo;
	RID data_set;
	std::map<RenderingDevice::FramebufferFormatID, RID> pipelines;
	RenderingDevice::VertexFormatID vertex_format = -1;
	bool frame_background = false;
	bool frame_ambient = false;
	uint64_t model_hash = 0;
	bool model_valid = false;
	uint32_t update_count = 0;
	SkyModel model;
	float sh[9][3] = {};

	// Radiance cubemap (sky reflections).
	ShaderRD radiance_shader;
	bool radiance_shader_ready = false;
	RID radiance_pipeline;
	RID radiance_cube;
	RID radiance_sampler;
	std::vector<RID> radiance_sets; // One per (mip, face): the data block and that slice as a storage image.
	int radiance_size = 0;
	int radiance_mips = 0;
	uint64_t radiance_hash = 0;
	bool radiance_valid = false;
	bool radiance_pending = false;
	bool frame_reflections = false;
	uint32_t radiance_update_count = 0;

	bool _ensure_gpu();
	bool _ensure_radiance(int p_size);
	void _fill_model(SkyDataUBO &r_ubo) const;

public:
	// Per frame, outside lists: builds the model, recomputes and uploads the SH if it changed, uploads
	// the background data. Without a sky in the view it does nothing (and allocates nothing).
	bool prepare(const RenderSceneData &p_data, const RendererLightStorage *p_light_storage, const Projection &p_clip_from_view, int p_width, int p_height);
	bool has_frame_background() const { return frame_background; }
	bool has_frame_ambient() const { return frame_ambient; }
	bool has_frame_reflections() const { return frame_reflections; }
	// Records the radiance filter (a compute list) when prepare() found the sky changed; outside lists.
	bool has_pending_radiance() const { return radiance_pending; }
	void filter_radiance();
	RID get_radiance_texture() const { return radiance_cube; }
	RID get_radiance_sampler() const { return radiance_sampler; }
	int get_radiance_mips() const { return radiance_mips; }
	// Times the radiance cubemap was filtered (tests: once per sky change, not per frame).
	uint32_t get_radiance_update_count() const { return radiance_update_count; }
	RID get_ambient_buffer() const { return ambient_ubo; }
	// Records the background into an open draw list on a framebuffer of format p_format (colour + depth).
	void draw_background(RenderingDevice::DrawListID p_list, RenderingDevice::FramebufferFormatID p_format);
	// Times the SH were recomputed (tests: once per sky change, not per frame).
	uint32_t get_update_count() const { return update_count; }
	// True once any sky GPU object exists (tests: a scene without a sky builds none).
	bool has_resources() const { return data_ubo.is_valid() || ambient_ubo.is_valid() || shader_ready || radiance_cube.is_valid() || radiance_shader_ready; }
	const SkyModel &get_model() const { return model; }
	void finalize();
	~SkyRD() { finalize(); }
};
