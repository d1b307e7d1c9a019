/**************************************************************************/
/*  ss_radiosity_rd.h                                                     */
/**************************************************************************/
/* godot-area: image-space radiosity (ISR; seed 003, Rohleder, §4.2-4.5): */
/* one bounce of indirect light and ambient occlusion from the screen's   */
/* own buffers, behind Godot's Environment SSIL and SSAO settings.        */
/*                                                                        */
/* Inputs (§4.2): the opaque pass, in shader versions with                */
/* USE_SS_RADIOSITY (RenderForwardClustered::SCENE_VERSION_SS_RADIOSITY), */
/* writes besides its HDR colour (the outgoing radiance L of direct,      */
/* ambient and emitted light) the view normal, the diffuse albedo rho and */
/* the ambient part of the colour into three RGBA16F targets; depth comes */
/* from the depth pre-pass (linear depth is derived from it, §4.3).       */
/* Passes (Listing 3), after the opaque pass, timestamp "ss_radiosity":   */
/*   downsample -> ISR (eqs. 6, 25, 26; interleaved over k x k pixels)    */
/*   -> blur x blur_passes (3 x 3, a trous) -> composite (bilateral       */
/*   upsampling eqs. 27-28, eq. 29).                                      */
/* Coarse resolution: half of each axis with half_size (Godot's default), */
/* else full. Samples per coarse pixel from the quality level             */
/* (RS::get_ss_radiosity_sample_count: 12/24/48/80/128), interleaved      */
/* over k x k pixels (get_interleave).                                    */
/*                                                                        */
/* Nothing exists before the first view with SSIL or SSAO enabled: no     */
/* shader, pipeline, texture or set (has_resources()); a view without     */
/* either records no pass. Per-render-target textures are freed with the  */
/* target (release_owner).                                                */
/* Shaders: shaders/effects/ss_radiosity*.glsl (terms in                  */
/* ss_radiosity_inc.glsl).                                                */

#pragma once

#include "core/math/projection.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/storage/environment_storage.h"

#include <map>

class SSRadiosityRD {
public:
	/* Definition */

	enum CompositeVariant {
		COMPOSITE_SSIL,
		COMPOSITE_SSAO,
		COMPOSITE_SSIL_SSAO,
		COMPOSITE_MAX,
	};

	// The ISR step, the blur and the composite come in one variant per CompositeVariant (the terms that
	// are on), in that order.
	enum PassVariant {
		PASS_DOWNSAMPLE_HALF, // half_size: 2x2 blocks.
		PASS_DOWNSAMPLE_FULL,
		PASS_ISR_SSIL,
		PASS_ISR_SSAO,
		PASS_ISR_SSIL_SSAO,
		PASS_BLUR_SSIL,
		PASS_BLUR_SSAO,
		PASS_BLUR_SSIL_SSAO,
		PASS_MAX,
	};

	// Mirror of Params in shaders/effects/ss_radiosity.glsl.
	struct PassPushConstant {
		float proj_xy[4]; // P00, P11, P20, P21.
		float proj_zw[4]; // P30, P31, P23, P33.
		float proj_depth[4]; // P22, P32, coarse width, coarse height.
		float ssil[4]; // radius, normal rejection, enabled, max disk radius (coarse pixels).
		float ssao[4]; // radius, horizon, detail, enabled.
		float blur[4]; // the pass's stride (coarse pixels), unused, ssil sharpness, ssao sharpness.
		uint32_t misc[4]; // sample count, full width, full height, scale.
		uint32_t pattern[4]; // interleave k (FrameSettings::interleave), unused x3.
	};
	static_assert(sizeof(PassPushConstant) == 128, "PassPushConstant must match shaders/effects/ss_radiosity.glsl.");
	static_assert(sizeof(PassPushConstant) % 16 == 0, "PassPushConstant must stay a multiple of 16 bytes.");

	// Mirror of Params in shaders/effects/ss_radiosity_composite.glsl.
	struct CompositePushConstant {
		float proj_depth[4]; // P22, P32, P23, P33.
		float sizes[4]; // full width, height, coarse width, height.
		float terms[4]; // ssil intensity (0: SSIL off), ssao intensity, ssao power, ssao light affect.
		float flags[4]; // ssao enabled, eps (relative), match (relative), unused.
	};
	static_assert(sizeof(CompositePushConstant) == 64, "CompositePushConstant must match shaders/effects/ss_radiosity_composite.glsl.");

	static constexpr RenderingDevice::DataFormat GBUFFER_FORMAT = RenderingDevice::DATA_FORMAT_R16G16B16A16_SFLOAT;
	// Every coarse buffer: one texel per tap (isr_pack in shaders/effects/ss_radiosity_inc.glsl).
	static constexpr RenderingDevice::DataFormat COARSE_FORMAT = RenderingDevice::DATA_FORMAT_R32G32B32A32_UINT;
	// Interleaved sampling: k x k coarse pixels share the N-sample pattern, k = min(MAX_INTERLEAVE,
	// floor(sqrt(N))) so that every pixel of a block gets at least one sample.
	static constexpr uint32_t MAX_INTERLEAVE = 4;
	// Bilateral upsampling (eqs. 27-28): eps and the "no coarse sample matches" limit, relative to depth.
	static constexpr float BILATERAL_EPS_RELATIVE = 0.001f;
	static constexpr float BILATERAL_MATCH_RELATIVE = 0.1f;
	// The disk of samples never exceeds this fraction of the coarse image height, in coarse pixels.
	static constexpr float MAX_DISK_FRACTION = 0.5f;

	// What one frame uses, from the environment's settings.
	struct FrameSettings {
		bool ssil = false;
		bool ssao = false;
		uint32_t sample_count = 48;
		uint32_t interleave = 4; // k of the k x k interleaved sampling (get_interleave).
		bool half_size = true;
		int blur_passes = 2;
		bool is_active() const { return ssil || ssao; }
	};
	static FrameSettings get_frame_settings(const ScreenSpaceLightingSettings &p_settings);
	static uint32_t get_interleave(uint32_t p_sample_count);

private:
	/* Private Members */

	struct Buffers {
		int width = 0;
		int height = 0;
		int coarse_width = 0;
		int coarse_height = 0;
		RID color; // Not owned: the render target's.
		RID depth; // Not owned.
		RID normal; // View normal (xyz).
		RID albedo; // Diffuse albedo (rgb).
		RID ambient; // Ambient part of the colour (rgb).
		RID coarse_gbuffer; // COARSE_FORMAT: radiance, normal, linear depth.
		RID isr[2]; // COARSE_FORMAT, ping-pong of the ISR result and the blur: sum F L, O, normal, depth.
		RID fb_gbuffer; // { color, normal, albedo, ambient, depth }: the opaque pass.
		RID fb_composite; // { color }.
		// Downsample; ISR into isr[0] and into isr[1]; blur isr[0] -> isr[1] and isr[1] -> isr[0] per variant;
		// composite per variant (reads isr[0], where the last blur pass writes).
		RID sets[3 + 2 * COMPOSITE_MAX + COMPOSITE_MAX];
	};

	ShaderRD pass_shader;
	ShaderRD composite_shader;
	bool shaders_ready = false;
	RID pass_pipelines[PASS_MAX];
	std::map<std::pair<RenderingDevice::FramebufferFormatID, int>, RID> composite_pipelines; // (format, variant).
	RID sampler;
	RenderingDevice::VertexFormatID vertex_format = -1;
	std::map<RID, Buffers> buffers; // Key: the render target.
	uint32_t last_pass_count = 0;

	bool _ensure_shaders();
	void _free_buffers(Buffers &r_b);
	bool _make_sets(Buffers &r_b);

public:
	/* Public Methods */

	// Per frame with SSIL or SSAO, outside lists: makes the render target's buffers (first use, or size or
	// half_size changed) and returns its G-buffer framebuffer for the opaque pass (RID() on failure).
	RID prepare(RID p_owner, RID p_color, RID p_depth, int p_width, int p_height, const FrameSettings &p_frame);
	// Records the passes after the opaque pass (timestamp p_timestamp; clip_from_view depth-corrected).
	bool render(RID p_owner, const Projection &p_clip_from_view, const ScreenSpaceLightingSettings &p_settings, const FrameSettings &p_frame, const String &p_timestamp);
	// Dispatches + draws recorded by the last render() (0 in a frame without it).
	uint32_t get_last_pass_count() const { return last_pass_count; }
	void begin_frame() { last_pass_count = 0; }
	// Frees p_owner's buffers (the render target is being freed).
	void release_owner(RID p_owner);
	// True once any GPU object exists (tests: a scene without SSIL/SSAO builds none).
	bool has_resources() const { return shaders_ready || sampler.is_valid() || !buffers.empty(); }
	// Test access: the render target's coarse result (RID() if none).
	RID get_isr_texture(RID p_owner) const;
	void finalize();
	~SSRadiosityRD() { finalize(); }
};
