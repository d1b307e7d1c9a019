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

#pragma once

#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/sky_model.h"

#include <map>

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
	};
	static_assert(sizeof(SkyDataUBO) == 256, "SkyDataUBO must match shaders/sky.glsl.");

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

	bool _ensure_gpu();

public:
	// Per frame, outside lists: builds the model, recomputes and uploads the SH if it changed, uploads
	// the background data. Without a sky in the view it does nothing (and allocates nothing).
	bool prepare(const RenderSceneData &p_data, const RendererLightStorage *p_light_storage, const Projection &p_clip_from_view, int p_width, int p_height);
	bool has_frame_background() const { return frame_background; }
	bool has_frame_ambient() const { return frame_ambient; }
	RID get_ambient_buffer() const { return ambient_ubo; }
	// Records the background into an open draw list on a framebuffer of format p_format (colour + depth).
	void draw_background(RenderingDevice::DrawListID p_list, RenderingDevice::FramebufferFormatID p_format);
	// Times the SH were recomputed (tests: once per sky change, not per frame).
	uint32_t get_update_count() const { return update_count; }
	// True once any sky GPU object exists (tests: a scene without a sky builds none).
	bool has_resources() const { return data_ubo.is_valid() || ambient_ubo.is_valid() || shader_ready; }
	const SkyModel &get_model() const { return model; }
	void finalize();
	~SkyRD() { finalize(); }
};
