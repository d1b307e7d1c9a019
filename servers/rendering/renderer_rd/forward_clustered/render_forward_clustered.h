/**************************************************************************/
/*  render_forward_clustered.h                                            */
/**************************************************************************/
/* godot-area: the Forward+ renderer on the RenderingDevice (Godot's      */
/* RendererSceneRenderImplementation::RenderForwardClustered, reduced).   */
/*                                                                        */
/* One render_scene() records and submits, in order:                      */
/*   1. depth pre-pass   (scene shader variant MODE_DEPTH, depth only);   */
/*   2. cluster build    (ClusterBuilderRD compute dispatch);             */
/*   3. opaque pass      (colour variant, depth test LESS_OR_EQUAL        */
/*      against the pre-pass, no depth write) into an RGBA16F HDR target  */
/*      cleared to the background colour * energy (linear);              */
/*   3b. SSIL / SSAO (effects/ss_radiosity_rd.h, image-space radiosity), */
/*      only when the environment enables one: the opaque pass then also */
/*      writes normal, albedo and ambient targets (USE_SS_RADIOSITY);    */
/*   4. sky background (effects/sky_rd.h, only with background_mode Sky). */
/* then swap_buffers() (frames in flight: no wait for this frame); the   */
/* pass timestamps (capture_timestamp) are get_last_frame_profile(),     */
/* which waits for that frame if needed: "area_shadows" (the area        */
/* shadow map passes; only in frames with shadowed area lights, ~0 when   */
/* no map is redrawn), "depth_prepass", "area_reprojection" and          */
/* "area_banding" (ADAPTIVE area shadows, only in frames with quad tests, */
/* recorded after the depth pre-pass whose depth they read),             */
/* "cluster_build", "opaque", "ss_radiosity" (only with SSIL/SSAO),      */
/* "sky" (only with a sky background) in ms; "directional_shadows" (the   */
/* sun's split depth passes, after "area_shadows"; only in frames with a  */
/* shadowed directional light); "sky_radiance" (the sky reflections'     */
/* cubemap filter, after it; only in frames whose sky changed).          */
/*                                                                        */
/* Area lights: the colour pass uses variant SCENE_SHADER_COLOR_AREA      */
/* (USE_AREA_LIGHTS) only when the view has area lights, from a ShaderRD  */
/* version per combination of the shading methods the view's area lights */
/* use (AREA_METHOD_LTC, _LTC_POLYNOMIAL, _MRP, _STOCHASTIC defines; the  */
/* set comes from LightStorage::get_area_shading_method_mask() each      */
/* frame). Each version is compiled on first use, so scenes without area */
/* lights compile no area code and a method nobody uses is never         */
/* compiled. The LTC LUT texture is uploaded on the first area frame.     */
/* The area shadow lookup is part of the version key as well             */
/* (AREA_SHADOWS_PCF / AREA_SHADOWS_PCSS, from the lights that have maps  */
/* this frame): views without area shadows carry no shadow code, which   */
/* llvmpipe would otherwise run for every pixel (it predicates branches). */
/*                                                                        */
/* Debug view: RS::VIEWPORT_DEBUG_DRAW_CLUSTER_OMNI_LIGHTS / _SPOT_LIGHTS */
/* / _AREA_LIGHTS write the per-pixel cluster element count of that type  */
/* into every colour channel.                                             */
/*                                                                        */
/* Shaders: shaders/forward_clustered/scene_forward_clustered.glsl and    */
/* its includes; GPU struct mirrors below are static_asserted.            */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/renderer_rd/cluster_builder_rd.h"
#include "servers/rendering/renderer_rd/directional_shadow_rd.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_renderer.h"
#include "servers/rendering/renderer_rd/effects/ltc_lut_rd.h"
#include "servers/rendering/renderer_rd/effects/sky_rd.h"
#include "servers/rendering/renderer_rd/effects/ss_radiosity_rd.h"
#include "servers/rendering/renderer_rd/shader_rd.h"
#include "servers/rendering/renderer_scene_render.h"

#include <map>
#include <utility>
#include <vector>

namespace RendererRD {
class LightStorage;
class MeshStorage;
class MaterialStorage;
} // namespace RendererRD

class RenderForwardClustered : public RendererSceneRender {
public:
	/* Definition */

	// Variant index = position in the define list given to ShaderRD.
	enum SceneShaderVariant {
		SCENE_SHADER_COLOR,
		SCENE_SHADER_DEPTH, // MODE_DEPTH
		SCENE_SHADER_COLOR_AREA, // USE_AREA_LIGHTS: colour pass with area lights.
		SCENE_SHADER_COLOR_FORCE_ALL, // MODE_FORCE_ALL_LIGHTS: brute-force reference (tests).
		SCENE_SHADER_COLOR_AREA_FORCE_ALL, // USE_AREA_LIGHTS + MODE_FORCE_ALL_LIGHTS.
		SCENE_SHADER_COLOR_DEBUG, // MODE_DEBUG_CLUSTER: cluster debug view.
		SCENE_SHADER_COLOR_AREA_DEBUG, // USE_AREA_LIGHTS + MODE_DEBUG_CLUSTER.
		SCENE_SHADER_MAX,
	};

	// Must match SCENE_FLAG_* in shaders/forward_clustered/scene_forward_clustered_inc.glsl.
	enum SceneFlags {
		SCENE_FLAG_FORCE_ALL_LIGHTS = 1,
		SCENE_FLAG_DEBUG_CLUSTER = 2,
	};

	// Must match BRDF_DIFFUSE_* in shaders/brdf_inc.glsl.
	enum DiffuseMode {
		DIFFUSE_MODE_BURLEY = 0,
		DIFFUSE_MODE_LAMBERT = 1,
	};

	// Mirror of SceneDataBlock (set 0, binding 0, std140) in scene_forward_clustered_inc.glsl.
	struct SceneDataUBO {
		float clip_from_view[16];
		float view_from_clip[16];
		float view_from_world[16];
		float world_from_view[16];
		float viewport_size[2];
		float z_near;
		float z_far;
		float ambient_light[4];
		uint32_t omni_light_count;
		uint32_t spot_light_count;
		uint32_t cluster_tiles_x;
		uint32_t cluster_tile_count;
		uint32_t cluster_words_per_type;
		uint32_t flags; // SceneFlags.
		uint32_t area_light_count;
		uint32_t debug_cluster_type; // ClusterBuilderRD::ElementType shown by SCENE_FLAG_DEBUG_CLUSTER.
		uint32_t cluster_tile_size; // Pixels.
		uint32_t pad_scene0;
		uint32_t pad_scene1;
		uint32_t pad_scene2;
	};
	static_assert(sizeof(SceneDataUBO) == 336, "SceneDataUBO must match scene_forward_clustered_inc.glsl.");
	static_assert(sizeof(SceneDataUBO) % 16 == 0, "SceneDataUBO must stay a multiple of 16 bytes.");

	// DrawData::flags (DRAW_FLAG_* in scene_forward_clustered_inc.glsl).
	static constexpr uint32_t DRAW_FLAG_HAS_COLOR = 1; // The surface has ARRAY_COLOR (else the shader reads white).

	// Mirror of the DrawData push constant in scene_forward_clustered_inc.glsl.
	struct DrawPushConstant {
		float world_from_model[16];
		float normal_matrix[12]; // 3 columns of 4 floats (xyz used).
		uint32_t layer_mask;
		uint32_t flags;
		uint32_t pad0;
		uint32_t pad1;
	};
	static_assert(sizeof(DrawPushConstant) == 128, "DrawPushConstant must match scene_forward_clustered_inc.glsl.");
	static_assert(sizeof(DrawPushConstant) % 16 == 0, "DrawPushConstant must stay a multiple of 16 bytes.");

	static constexpr RD::DataFormat HDR_FORMAT = RD::DATA_FORMAT_R16G16B16A16_SFLOAT;
	static constexpr RD::DataFormat DEPTH_FORMAT = RD::DATA_FORMAT_D32_SFLOAT;

private:
	/* Private Members */

	struct RenderTarget {
		int width = 0;
		int height = 0;
		RID color; // HDR_FORMAT.
		RID depth; // DEPTH_FORMAT.
		RID fb_depth; // { depth }
		RID fb_color; // { color, depth }
	};

	RendererRD::LightStorage *light_storage = nullptr;
	RendererRD::MeshStorage *mesh_storage = nullptr;
	RendererRD::MaterialStorage *material_storage = nullptr;

	ShaderRD scene_shader;
	ClusterBuilderRD cluster_builder;
	LTCLutRD ltc_lut; // Uploaded on the first frame with area lights.
	SkyRD sky; // Sky background and SH ambient; nothing exists before the first view with a sky.
	SSRadiosityRD ss_radiosity; // SSIL/SSAO; nothing exists before the first view that enables one.
	AreaShadowRendererRD area_shadows; // Area soft shadows: atlas, depth passes, bindings 12-14 of the area variant.
	DirectionalShadowRD directional_shadows; // Sun shadows: own atlas, one depth pass per split, bindings 16-19.
	RID_Owner<RenderTarget> render_target_owner{ "RenderForwardClustered::RenderTarget" };

	RID scene_ubo;
	RID scene_set_color; // Set 0 of the colour variant (invalid after the cluster buffer changes).
	RID scene_set_depth; // Set 0 of the depth variant.
	RID scene_set_cluster_buffer; // Cluster buffer scene_set_color was made with.
	// One scene shader version per set of area shading methods and area shadow lookups in use. Key: bit m =
	// RS::LightAreaShadingMethod m, plus AREA_VERSION_SHADOWS_PCF / _PCSS (a view whose lights cast no area
	// shadows gets no shadow code: software rasterizers run every branch of a shader, taken or not).
	struct AreaVersion {
		RID version; // ShaderRD version with the AREA_METHOD_* defines.
		RID scene_set; // Set 0 of its SCENE_SHADER_COLOR_AREA variant.
		RID scene_set_cluster_buffer; // Cluster buffer scene_set was made with.
		RID scene_set_shadow_atlas; // Area shadow atlas texture scene_set was made with (RID() without area lights).
		RID scene_set_directional_buffer; // Directional light buffer scene_set was made with (RID() without).
		RID scene_set_sky_buffer; // Sky ambient buffer scene_set was made with (RID() without).
		RID scene_set_directional_shadow_atlas; // Directional shadow atlas scene_set was made with (RID() without).
		RID scene_set_sky_radiance; // Sky radiance cubemap scene_set was made with (RID() without).
		RID scene_set_area_light_atlas; // Area light (texture) atlas scene_set was made with (RID() without).
	};
	std::map<uint32_t, AreaVersion> area_versions;
	uint32_t compiled_area_method_mask = 0; // Union of the keys of the area versions compiled so far.
	uint32_t compiled_feature_mask = 0; // Union of the SCENE_VERSION_* feature bits compiled so far.
	bool compiled_area_shapes = false; // Some compiled area version has AREA_VERSION_SHAPES.
	bool area_texture_compiled = false; // Some compiled version has AREA_VERSION_TEXTURE.
	std::map<uint64_t, RID> pipelines; // Key: variant | cull mode << 8 | framebuffer format << 16 | version key << 32.

	bool force_all_lights = false;
	bool area_code_disabled = false; // Benchmark baseline (set_debug_disable_area_lights).
	bool initialized = false;
	// Pass times of the newest frame of this renderer whose GPU work completed (frames in flight:
	// they arrive with the frame's fence, frame_queue_size frames later, at a flush, or when
	// get_last_frame_profile() waits for the last drawn frame).
	mutable std::vector<std::pair<String, double>> last_profile;
	mutable uint64_t last_profile_frame = 0; // Its RenderingDevice frame serial.
	mutable std::vector<std::pair<uint64_t, String>> pending_profiles; // (frame serial, timestamp prefix).
	uint32_t last_area_shadow_tests = 0; // ADAPTIVE quads tested by the last render_scene().
	uint64_t last_draw_calls = 0; // Colour-pass draws (opaque and transparent) of the last render_scene().
	uint64_t last_area_draw_calls = 0; // Of those, drawn with the area-light shader version.
	uint64_t frame_counter = 0;

	// How a colour pipeline treats depth and colour: opaque (depth from the pre-pass), alpha scissor
	// (not in the pre-pass: writes its own depth), alpha blend (after the opaque pass, no depth write).
	enum PipelineMode {
		PIPELINE_MODE_OPAQUE,
		PIPELINE_MODE_DEPTH_WRITE,
		PIPELINE_MODE_BLEND,
	};
	RID _get_pipeline(SceneShaderVariant p_variant, RD::PolygonCullMode p_cull, RD::FramebufferFormatID p_format, uint32_t p_area_methods = 0, PipelineMode p_mode = PIPELINE_MODE_OPAQUE);
	// p_area_methods: 0 = no area lights, else the area version key of the view (method mask | shadow bits).
	bool _ensure_scene_sets(uint32_t p_area_methods);
	// The colour shader p_variant of the version for key p_key (area key | SCENE_VERSION_* bits); key 0 is the
	// default version. Area variants need area method bits and the others none. Compiled on first use.
	RID _get_version_shader(uint32_t p_key, SceneShaderVariant p_variant);
	static bool _is_area_variant(SceneShaderVariant p_variant) { return p_variant == SCENE_SHADER_COLOR_AREA || p_variant == SCENE_SHADER_COLOR_AREA_FORCE_ALL || p_variant == SCENE_SHADER_COLOR_AREA_DEBUG; }
	// AREA_VERSION_SHADOWS_* bits for the area shadow data of this frame (area_shadows.prepare() ran).
	uint32_t _get_area_shadow_version_bits() const;
	void _free_render_target(RenderTarget *p_rt);
	void _read_profile(const String &p_prefix) const;
	void _update_profile() const;

public:
	/* Public Methods */

	// Compiles the scene shader variants, sets up the cluster builder and the storages' GPU parts.
	// Needs an initialized RenderingDevice. Returns false (with an error) on failure.
	bool initialize(uint32_t p_max_lights_per_type = 512);
	// Frees every GPU object (render targets included) before RenderingDevice::finalize().
	void finalize();
	bool is_initialized() const { return initialized; }

	// RendererSceneRender.
	void render_scene(const RenderSceneData &p_data, RID p_render_target) override;
	RID render_target_create(int p_width, int p_height) override;
	bool render_target_free(RID p_rid) override;
	bool owns_render_target(RID p_rid) const override { return render_target_owner.owns(p_rid); }
	std::vector<float> render_target_get_data(RID p_render_target) override;
	std::vector<std::pair<String, double>> get_last_frame_profile() const override;
	uint32_t get_last_frame_area_shadow_tests() const override { return last_area_shadow_tests; }
	uint64_t get_last_frame_rendering_info(RS::RenderingInfo p_info) const override;
	void set_debug_force_all_lights(bool p_enable) override { force_all_lights = p_enable; }
	bool is_debug_force_all_lights() const { return force_all_lights; }
	// Benchmark baseline (bench --targets, P4): true skips every area-light step of a frame (area shadow
	// begin/prepare/draw/adaptive passes, AUTO receivers) and builds only the omni and spot clusters, as a
	// build without the area-light code would. For scenes WITHOUT area lights only: area lights are not drawn.
	void set_debug_disable_area_lights(bool p_disable) override { area_code_disabled = p_disable; }
	void area_shadow_filter_set_mode(RS::AreaShadowFilter p_filter) override { area_shadows.set_sample_penumbra_filter(p_filter == RS::AREA_SHADOW_FILTER_PENUMBRA); }
	RS::AreaShadowFilter area_shadow_filter_get_mode() const override { return area_shadows.is_sample_penumbra_filter_enabled() ? RS::AREA_SHADOW_FILTER_PENUMBRA : RS::AREA_SHADOW_FILTER_PCF; }
	std::vector<std::pair<String, String>> get_debug_scene_shader_sources() const override;
	// The scene shader (tests check which variants were compiled).
	const ShaderRD &get_scene_shader() const { return scene_shader; }
	// SCENE_SHADER_COLOR_AREA: true once any area-method version has compiled it.
	bool is_scene_shader_variant_compiled(SceneShaderVariant p_variant) const;
	// Bit m (RS::LightAreaShadingMethod m) is set when a compiled area shader version contains method m's code.
	uint32_t get_compiled_area_method_mask() const { return compiled_area_method_mask; }
	bool is_area_method_compiled(RS::LightAreaShadingMethod p_method) const { return (compiled_area_method_mask >> uint32_t(p_method)) & 1u; }
	// True once some compiled area version holds the disk/sphere/tube code (USE_AREA_SHAPES).
	bool is_area_shape_code_compiled() const { return compiled_area_shapes; }
	// Number of area shader versions (method combinations) compiled so far.
	int get_area_shader_version_count() const;
	// Bits of an area version key above the method bits: the area shadow lookups compiled in
	// (area_light_shadow_inc.glsl). PCF: some light of the view has shadow maps in a grid mode (FIXED,
	// HEURISTIC, ADAPTIVE); PCSS: some light has its PCSS_BASELINE map. Neither: no shadow code at all.
	static constexpr uint32_t AREA_VERSION_SHADOWS_PCF = 1u << 8;
	static constexpr uint32_t AREA_VERSION_SHADOWS_PCSS = 1u << 9;
	// "#define AREA_SHADOWS_NEAR_LAYER\n": some grid-mode light has a caster close enough to its sample points
	// for the filter's near-layer step (AreaShadowRendererRD::FLAG_NEAR_LAYER). Without it the step's code is
	// not compiled: a SIMD rasterizer (llvmpipe) paid 7-10 % of every shadowed frame for it untaken.
	static constexpr uint32_t AREA_VERSION_SHADOWS_NEAR = 1u << 17;
	// "#define AREA_SHADOWS_TREE\n": some light is ADAPTIVE (its maps are tree points with their own cells,
	// AreaShadowRendererRD::pack_tree_map()); a view of grid lights compiles no tree code (it cost the FIXED
	// default 4 % of its shadowed frame on llvmpipe).
	static constexpr uint32_t AREA_VERSION_SHADOWS_TREE = 1u << 18;
	// USE_AREA_SHAPES: some area light of the view is a disk, sphere or tube (area_light_shapes_inc.glsl);
	// a view of rectangles only compiles no shape code.
	static constexpr uint32_t AREA_VERSION_SHAPES = 1u << 16;
	// "#define AREA_LIGHT_TEXTURE\n": some area light of the view has an area_texture in the atlas
	// (area_light_texture_inc.glsl, bindings 4 and 10). Without it no texture code and no atlas.
	static constexpr uint32_t AREA_VERSION_TEXTURE = 1u << 13;
	static constexpr uint32_t AREA_VERSION_METHOD_BITS = (1u << RS::LIGHT_AREA_SHADING_MAX) - 1u;
	// Every bit that only area-light code reads (methods, area shadows, shapes, area_texture).
	static constexpr uint32_t AREA_VERSION_ALL_BITS = AREA_VERSION_METHOD_BITS | AREA_VERSION_SHADOWS_PCF | AREA_VERSION_SHADOWS_PCSS | AREA_VERSION_SHADOWS_NEAR | AREA_VERSION_SHADOWS_TREE | AREA_VERSION_SHAPES | AREA_VERSION_TEXTURE;
	static_assert(RS::LIGHT_AREA_SHADING_MAX <= 8, "The area version key keeps the shading methods in bits 0-7.");
	// The AREA_METHOD_* defines of a method mask ("#define AREA_METHOD_LTC\n..."), as given to ShaderRD; with
	// AREA_VERSION_SHADOWS_PCF / _PCSS also "#define AREA_SHADOWS_PCF\n" / "#define AREA_SHADOWS_PCSS\n".
	static String get_area_method_defines(uint32_t p_area_methods);
	// Feature bits of a scene version key, above the area bits: USE_DIRECTIONAL_LIGHTS when the view has a
	// directional light (binding 8, scene_forward_directional_inc.glsl). A view without any feature and without
	// area lights uses the default version, which has none of this code.
	static constexpr uint32_t SCENE_VERSION_DIRECTIONAL = 1u << 10;
	static constexpr uint32_t SCENE_VERSION_SKY_AMBIENT = 1u << 11; // USE_SKY_AMBIENT: binding 9, the sky's SH.
	// USE_SS_RADIOSITY: the colour pass also writes the image-space radiosity inputs (locations 1-3).
	static constexpr uint32_t SCENE_VERSION_SS_RADIOSITY = 1u << 12;
	// USE_DIRECTIONAL_SHADOWS: some directional light of the view casts shadows this frame (bindings 16-19,
	// directional_shadow_rd.h); always together with SCENE_VERSION_DIRECTIONAL.
	static constexpr uint32_t SCENE_VERSION_DIRECTIONAL_SHADOWS = 1u << 14;
	// USE_SKY_REFLECTION: the view's environment reflects the sky (bindings 20-21, SkyRD's radiance cubemap).
	static constexpr uint32_t SCENE_VERSION_SKY_REFLECTION = 1u << 15;
	static constexpr uint32_t SCENE_VERSION_FEATURE_BITS = SCENE_VERSION_DIRECTIONAL | SCENE_VERSION_SKY_AMBIENT | SCENE_VERSION_SS_RADIOSITY | SCENE_VERSION_DIRECTIONAL_SHADOWS | SCENE_VERSION_SKY_REFLECTION;
	// Every bit of a version key means one thing (the pipeline cache keys on all 32 of them).
	static_assert(((AREA_VERSION_METHOD_BITS | AREA_VERSION_SHADOWS_PCF | AREA_VERSION_SHADOWS_PCSS | AREA_VERSION_SHAPES | AREA_VERSION_TEXTURE) & SCENE_VERSION_FEATURE_BITS) == 0, "Area and scene version bits overlap.");
	static_assert((AREA_VERSION_METHOD_BITS & (AREA_VERSION_SHADOWS_PCF | AREA_VERSION_SHADOWS_PCSS | AREA_VERSION_SHAPES | AREA_VERSION_TEXTURE)) == 0 && (AREA_VERSION_SHAPES & AREA_VERSION_TEXTURE) == 0, "Area version bits overlap.");
	// get_area_method_defines() plus the feature defines of p_key.
	static String get_scene_version_defines(uint32_t p_key);
	// SCENE_VERSION_* bits of every version compiled so far (tests: a scene without a sun compiles none).
	uint32_t get_compiled_feature_mask() const { return compiled_feature_mask; }
	// True once a version with the area-light texture code (AREA_VERSION_TEXTURE) has compiled.
	bool is_area_texture_compiled() const { return area_texture_compiled; }

	// Directional (sun) shadows: atlas, splits and passes of the last frame (tests, bench).
	DirectionalShadowRD &get_directional_shadows() { return directional_shadows; }

	// The sky (tests: update count, resources).
	const SkyRD &get_sky() const { return sky; }
	// Image-space radiosity (tests: resources, pass count, coarse result).
	const SSRadiosityRD &get_ss_radiosity() const { return ss_radiosity; }

	// Area soft shadows (atlas, maps, per-frame draws; one atlas per renderer for now).
	AreaShadowRendererRD &get_area_shadow_renderer() { return area_shadows; }
	// Default area shadow atlas size in pixels and tiles per side, for render targets whose viewport sets none
	// (RS::area_shadow_atlas_set_size sets it per viewport through RenderSceneData). False on bad values.
	bool area_shadow_atlas_set_size(int p_size, int p_subdivision) { return p_size > 0 && p_subdivision > 0 && area_shadows.set_atlas_size(uint32_t(p_size), uint32_t(p_subdivision)); }

	// The cluster builder of the last frame (tests read its buffer and counts).
	ClusterBuilderRD *get_cluster_builder() { return &cluster_builder; }
	// The RD texture of a render target's HDR colour (RID() if invalid).
	RID render_target_get_color_texture(RID p_render_target) const override;

	RenderForwardClustered(RendererRD::LightStorage *p_light_storage, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage);
	~RenderForwardClustered();
};
