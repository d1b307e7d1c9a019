/**************************************************************************/
/*  light_storage.h                                                       */
/**************************************************************************/
/* godot-area: light storage on the RenderingDevice (Godot's              */
/* RendererRD::LightStorage, reduced to omni and spot lights without      */
/* shadows). Owns the Light records and the per-frame GPU light arrays.   */
/*                                                                        */
/* update_light_buffers() runs once per rendered view and is the ONLY     */
/* place where light units are converted for the GPU (see LightData).    */
/* It also feeds the cluster builder in the same loop, so cluster element */
/* N of a type is always GPU light N of that type (keep it so).           */
/*                                                                        */
/* Area lights (thesis Listing A.2) get their own AreaLightData array and */
/* buffer (binding 5 of the scene shader) and cluster element type        */
/* ELEMENT_TYPE_AREA_LIGHT (an oriented box, thesis section 5.1.1).       */
/*                                                                        */
/* Directional lights are not clustered (Godot keeps them in a separate  */
/* uniform array): update_directional_light_buffer() converts up to       */
/* MAX_DIRECTIONAL_LIGHTS of them into DirectionalLightData, in a buffer  */
/* created on the first frame that has one (a scene without a sun        */
/* allocates nothing).                                                    */

#pragma once

#include "core/math/vector2.h"
#include "servers/rendering/renderer_rd/storage_rd/area_light_atlas.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/storage/light_storage_common.h"

#include <vector>

class ClusterBuilderRD;
class RendererMeshStorage;
class RendererMaterialStorage;

namespace RendererRD {

class LightStorage : public LightStorageCommon {
public:
	/* Definition: GPU mirror */

	// Must match LIGHT_TYPE_* in shaders/light_data_inc.glsl.
	enum LightType {
		LIGHT_TYPE_OMNI = 0,
		LIGHT_TYPE_SPOT = 1,
	};

	// One omni or spot light as the scene shader reads it (std430). Mirror of struct LightData in
	// shaders/light_data_inc.glsl: same names, same order, 64 bytes. All values already in shading units.
	struct LightData {
		float position[3]; // View space, metres.
		float inv_radius; // 1 / range.
		float direction[3]; // View space unit axis the spot shines along (omni: 0, 0, -1).
		float size; // LIGHT_PARAM_SIZE, metres (reserved).
		float color[3]; // srgb_to_linear(color) * energy * pi, negated for negative lights.
		float attenuation; // LIGHT_PARAM_ATTENUATION exponent.
		float cone_attenuation; // Spot: LIGHT_PARAM_SPOT_ATTENUATION. Omni: 0.
		float cone_angle; // Spot: cos(LIGHT_PARAM_SPOT_ANGLE in radians). Omni: -1.
		float specular_amount; // LIGHT_PARAM_SPECULAR.
		uint32_t cull_mask; // light_cull_mask.
	};
	static_assert(sizeof(LightData) == 64, "LightData must match shaders/light_data_inc.glsl (64 bytes).");
	static_assert(sizeof(LightData) % 16 == 0, "LightData must stay a multiple of 16 bytes (std430 array stride).");

	// One area light as the scene shader reads it (std430). Mirror of struct AreaLightData in
	// shaders/light_data_inc.glsl: same names, same order, 96 bytes. Units: see the GLSL side.
	struct AreaLightData {
		float position[3]; // View space centre, metres.
		float inv_radius; // 1 / area_range.
		float half_axis_x[3]; // View space local +X * size.x / 2 (rectangle, disk, tube: half the segment; sphere: local +X * radius).
		float attenuation; // area_attenuation: distance exponent (2 = physical).
		float half_axis_y[3]; // View space local +Y * size.y / 2 (rectangle, disk, tube: its radius; sphere: local +Y * radius).
		float specular_amount; // LIGHT_PARAM_SPECULAR.
		float normal[3]; // View space unit emission direction (local -Z).
		uint32_t shading_method; // Bits 0-7: RS::LightAreaShadingMethod; bits 8-23: stochastic samples; bits 24-31: RS::LightAreaShape.
		float color[3]; // L_e = srgb_to_linear(color) * energy * pi / A_n, negated for negative lights; 0 when the emitting area is 0.
		uint32_t cull_mask; // light_cull_mask.
		float texture_rect[4]; // area_texture: uv rect (x, y, w, h) of its level 0 in the area light atlas; w = 0: untextured.
	};
	static_assert(sizeof(AreaLightData) == 96, "AreaLightData must match shaders/light_data_inc.glsl (96 bytes).");
	static_assert(sizeof(AreaLightData) % 16 == 0, "AreaLightData must stay a multiple of 16 bytes (std430 array stride).");

	// AreaLightData::shading_method packs the method (low 8 bits), the stochastic sample count (bits 8-23)
	// and the shape (bits 24-31), so the 96-byte layout stays as it is. Must match area_light_get_method(),
	// _stochastic_samples() and _shape() in shaders/area_light_inc.glsl.
	static constexpr uint32_t AREA_METHOD_MASK = 0xFFu;
	static constexpr uint32_t AREA_METHOD_SAMPLES_SHIFT = 8;
	static constexpr uint32_t AREA_METHOD_SHAPE_SHIFT = 24;
	static uint32_t pack_area_shading_method(RS::LightAreaShadingMethod p_method, int p_samples, RS::LightAreaShape p_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE) {
		return (uint32_t(p_method) & AREA_METHOD_MASK) | ((uint32_t(p_samples) & 0xFFFFu) << AREA_METHOD_SAMPLES_SHIFT) | ((uint32_t(p_shape) & 0xFFu) << AREA_METHOD_SHAPE_SHIFT);
	}
	static RS::LightAreaShape unpack_area_shape(uint32_t p_packed) { return RS::LightAreaShape(p_packed >> AREA_METHOD_SHAPE_SHIFT); }

	// One directional light as the scene shader reads it (std140 array element). Mirror of struct
	// DirectionalLightData in shaders/light_data_inc.glsl: same names, same order, 48 bytes.
	struct DirectionalLightData {
		float direction[3]; // View space unit vector the light shines along (its local -Z); L = -direction.
		float energy; // light_energy * pi (sign: negative lights), the colour kept separate for the sky.
		float color[3]; // srgb_to_linear(light_color) * energy (the value above): radiance of a unit-cosine receiver.
		float size; // Angular radius of the sun disk in radians (light_angular_distance / 2).
		float specular_amount; // LIGHT_PARAM_SPECULAR.
		uint32_t cull_mask; // light_cull_mask.
		uint32_t flags; // DIRECTIONAL_FLAG_*.
		int32_t shadow_index; // Index into the directional shadow block (DirectionalShadowRD), -1: unshadowed.
	};
	static_assert(sizeof(DirectionalLightData) == 48, "DirectionalLightData must match shaders/light_data_inc.glsl (48 bytes).");
	// Header + array of the directional light uniform buffer (std140): count, then the lights.
	static constexpr uint32_t MAX_DIRECTIONAL_LIGHTS = 8; // Godot's MAX_DIRECTIONAL_LIGHTS.
	struct DirectionalLightBlock {
		uint32_t count;
		uint32_t pad[3];
		DirectionalLightData data[MAX_DIRECTIONAL_LIGHTS];
	};
	static_assert(sizeof(DirectionalLightBlock) == 16 + 48 * MAX_DIRECTIONAL_LIGHTS, "DirectionalLightBlock must match the shader's block.");

	// Lights per type uploaded per view (nearest to the camera first); a multiple of 32. The renderer's
	// capacity comes from Godot's project setting rendering/limits/cluster_builder/max_clustered_elements
	// (32..8192, default 512); visible lights beyond it are not drawn and counted in a warning.
	static constexpr uint32_t DEFAULT_MAX_LIGHTS = 512;
	static constexpr uint32_t MAX_LIGHTS_LIMIT = 8192;
	static constexpr const char *SETTING_MAX_CLUSTERED_ELEMENTS = "rendering/limits/cluster_builder/max_clustered_elements";
	// The setting's value (an invalid one is reported and DEFAULT_MAX_LIGHTS used).
	static uint32_t get_project_max_lights();

private:
	/* Private Members */

	// The CPU light record, its owner and _get_light() come from LightStorageCommon.
	using Light = LightRecord;

	uint32_t max_lights = DEFAULT_MAX_LIGHTS;
	RID omni_light_buffer; // LightData[max_lights]
	RID spot_light_buffer; // LightData[max_lights]
	RID area_light_buffer; // AreaLightData[max_lights]
	uint32_t omni_light_count = 0;
	uint32_t spot_light_count = 0;
	uint32_t area_light_count = 0;
	uint32_t dropped_light_count = 0; // Visible lights of the last update not drawn (over max_lights).
	uint32_t warned_dropped_count = 0; // The count last warned about (a steady overflow warns once).
	uint32_t area_shading_method_mask = 0; // Bit m set: an uploaded area light uses RS::LightAreaShadingMethod m.
	uint32_t area_shape_mask = 0; // Bit s set: an uploaded area light has RS::LightAreaShape s.
	std::vector<LightData> omni_data;
	std::vector<LightData> spot_data;
	std::vector<AreaLightData> area_data;
	RID directional_light_buffer; // DirectionalLightBlock; created by the first frame with a directional light.
	DirectionalLightBlock directional_block = {};
	uint32_t directional_dropped = 0; // Directional lights beyond MAX_DIRECTIONAL_LIGHTS in the last update.
	std::vector<uint32_t> directional_source_indices; // GPU directional light i came from p_lights[i'].
	std::vector<uint32_t> area_source_indices; // GPU area light i came from p_lights[area_source_indices[i]].
	// area_texture: the atlas (nothing allocated until a visible area light has a texture) and where the
	// texels come from (the renderer's material storage, set once by the renderer).
	AreaLightAtlas area_atlas;
	const RendererMaterialStorage *texture_source = nullptr;
	bool area_textured = false; // Some area light of the last update is textured.
	// area_texture applies to rectangles only (upstream's only shape): a disk, sphere or tube with a
	// texture takes no atlas slot and is drawn untextured; counted and warned when the count changes.
	uint32_t area_untextured_shapes = 0;
	uint32_t warned_untextured_shapes = 0;
	// AUTO shading (AreaMethodSelector): receivers of the next update_light_buffers() only (then cleared).
	const std::vector<RenderSceneData::GeometryInstance> *auto_geometry = nullptr;
	const RendererMeshStorage *auto_mesh_storage = nullptr;
	const RendererMaterialStorage *auto_material_storage = nullptr;

public:
	/* Public Methods: GPU side */

	// Creates the light buffers (needs an initialized RenderingDevice). p_max_lights is rounded up to 32.
	bool initialize_gpu(uint32_t p_max_lights = DEFAULT_MAX_LIGHTS);
	// Frees the GPU buffers (before RenderingDevice::finalize()).
	void finalize_gpu();
	bool is_gpu_initialized() const { return omni_light_buffer.is_valid(); }

	// Converts the visible omni/spot/area lights of one view into LightData / AreaLightData (view space), sorts each type by
	// distance to the camera, keeps the nearest max_lights, uploads both arrays and adds every kept light
	// to p_cluster_builder (may be null) in GPU index order. Records buffer updates: call outside lists.
	void update_light_buffers(const std::vector<RenderSceneData::LightInstance> &p_lights, const Transform3D &p_view_from_world, ClusterBuilderRD *p_cluster_builder);

	// Converts the directional lights of one view (scene order; the first MAX_DIRECTIONAL_LIGHTS,
	// the rest dropped with a counted warning) into the directional block and uploads it. Creates the
	// buffer on the first call with a light; without lights it uploads nothing. Call outside lists.
	void update_directional_light_buffer(const std::vector<RenderSceneData::LightInstance> &p_lights, const Transform3D &p_view_from_world);
	// Fills one DirectionalLightData (the unit conversion: view-space direction, linear colour * energy * pi,
	// angular radius in radians).
	bool fill_directional_light_data(RID p_light, const Transform3D &p_world_from_light, const Transform3D &p_view_from_world, DirectionalLightData &r_data) const;
	RID get_directional_light_buffer() const { return directional_light_buffer; }
	// DirectionalShadowRD::prepare(): the shadow of GPU directional light p_index this frame (-1: none);
	// upload_directional_light_buffer() sends the block again after such changes.
	void directional_light_set_shadow_index(uint32_t p_index, int32_t p_shadow_index) {
		if (p_index < directional_block.count) {
			directional_block.data[p_index].shadow_index = p_shadow_index;
		}
	}
	void upload_directional_light_buffer();
	uint32_t get_directional_light_count() const { return directional_block.count; }
	uint32_t get_directional_lights_dropped() const { return directional_dropped; }
	const DirectionalLightBlock &get_directional_light_block() const { return directional_block; }
	// For GPU directional light i of the last update, its index in the p_lights given.
	const std::vector<uint32_t> &get_directional_light_source_indices() const { return directional_source_indices; }

	RID get_omni_light_buffer() const { return omni_light_buffer; }
	RID get_spot_light_buffer() const { return spot_light_buffer; }
	RID get_area_light_buffer() const { return area_light_buffer; }
	uint32_t get_omni_light_count() const { return omni_light_count; }
	uint32_t get_spot_light_count() const { return spot_light_count; }
	uint32_t get_area_light_count() const { return area_light_count; }
	// Bit m is set when an area light of the last update_light_buffers() uses RS::LightAreaShadingMethod m
	// (the renderer compiles only these methods). 0 without area lights.
	uint32_t get_area_shading_method_mask() const { return area_shading_method_mask; }
	// Bit s is set when an area light of the last update_light_buffers() has RS::LightAreaShape s (the
	// renderer compiles the shape code only when some bit other than RECTANGLE's is set). 0 without area lights.
	uint32_t get_area_shape_mask() const { return area_shape_mask; }
	// area_texture: the material storage whose textures lights refer to (the renderer sets it once).
	void set_area_texture_source(const RendererMaterialStorage *p_material_storage) { texture_source = p_material_storage; }
	// True when some area light of the last update_light_buffers() has its texture in the atlas (the renderer
	// then compiles the texture code and binds the atlas); false for a scene without textured lights.
	bool has_textured_area_lights() const { return area_textured; }
	// Visible non-rectangle area lights of the last update whose area_texture was ignored.
	uint32_t get_untextured_shape_count() const { return area_untextured_shapes; }
	const AreaLightAtlas &get_area_light_atlas() const { return area_atlas; }
	uint32_t get_max_lights() const { return max_lights; }
	// Visible lights (all types) of the last update_light_buffers() beyond the capacity, so not drawn.
	uint32_t get_dropped_light_count() const { return dropped_light_count; }
	// CPU copies of the last upload (tests).
	const std::vector<LightData> &get_omni_light_data() const { return omni_data; }
	const std::vector<LightData> &get_spot_light_data() const { return spot_data; }
	const std::vector<AreaLightData> &get_area_light_data() const { return area_data; }
	// For GPU area light i of the last update, its index in the p_lights given (area shadows use it).
	const std::vector<uint32_t> &get_area_light_source_indices() const { return area_source_indices; }

	// AUTO area shading (servers/rendering/renderer_rd/area_lights/area_method_selector.h). The renderer gives the
	// visible geometry of the view before update_light_buffers(), which uses it (receiver distance and
	// dominant roughness per AUTO light) and then forgets it; without it AUTO falls back to the camera
	// distance and the default-roughness setting. Pointers must stay valid until that call.
	void set_area_auto_receivers(const std::vector<RenderSceneData::GeometryInstance> *p_geometry, const RendererMeshStorage *p_mesh_storage, const RendererMaterialStorage *p_material_storage);
	struct AreaAutoChoice {
		RS::LightAreaShadingMethod requested = RS::LIGHT_AREA_SHADING_LTC; // The light's setting (may be AUTO).
		RS::LightAreaShadingMethod method = RS::LIGHT_AREA_SHADING_LTC; // Uploaded (never AUTO).
		float size_over_distance = 0.0f; // AUTO only.
		float roughness = 0.0f; // AUTO only.
		float predicted_error = 0.0f; // AUTO only: mean LDR-FLIP predicted for `method`.
	};
	// Per GPU area light of the last update (same order as get_area_light_data()).
	const std::vector<AreaAutoChoice> &get_area_auto_choices() const { return area_auto_choices; }

	// Fills one LightData from an omni/spot light record and its world transform (the unit conversion).
	bool fill_light_data(RID p_light, const Transform3D &p_world_from_light, const Transform3D &p_view_from_world, LightData &r_data) const;
	// Fills one AreaLightData from an area light record and its world transform (the unit conversion:
	// view-space centre, half axes and normal, inverse range, L_e per the area light contract).
	bool fill_area_light_data(RID p_light, const Transform3D &p_world_from_light, const Transform3D &p_view_from_world, AreaLightData &r_data) const;

	/* Public Methods: RendererLightStorage (light_create, setters, getters: LightStorageCommon) */

	LightStorage() :
			LightStorageCommon("RendererRD::Light", RS::LIGHT_OMNI_SHADOW_CUBE) {}
	~LightStorage();

private:
	std::vector<AreaAutoChoice> area_auto_choices; // See get_area_auto_choices().
};

} // namespace RendererRD
