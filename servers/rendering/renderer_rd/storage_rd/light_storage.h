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

#pragma once

#include "core/math/vector2.h"
#include "core/templates/rid_owner.h"
#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/storage/light_storage.h"

#include <vector>

class ClusterBuilderRD;
class RendererMeshStorage;
class RendererMaterialStorage;

namespace RendererRD {

class LightStorage : public RendererLightStorage {
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
	// shaders/light_data_inc.glsl: same names, same order, 80 bytes. Units: see the GLSL side.
	struct AreaLightData {
		float position[3]; // View space centre, metres.
		float inv_radius; // 1 / area_range.
		float half_axis_x[3]; // View space local +X * size.x / 2.
		float attenuation; // Range window exponent (area_attenuation).
		float half_axis_y[3]; // View space local +Y * size.y / 2.
		float specular_amount; // LIGHT_PARAM_SPECULAR.
		float normal[3]; // View space unit emission direction (local -Z).
		uint32_t shading_method; // Bits 0-7: RS::LightAreaShadingMethod; bits 8-23: stochastic samples (AREA_METHOD_SAMPLES_SHIFT).
		float color[3]; // L_e = srgb_to_linear(color) * energy * pi / A_n, negated for negative lights; 0 when size.x * size.y == 0.
		uint32_t cull_mask; // light_cull_mask.
	};
	static_assert(sizeof(AreaLightData) == 80, "AreaLightData must match shaders/light_data_inc.glsl (80 bytes).");
	static_assert(sizeof(AreaLightData) % 16 == 0, "AreaLightData must stay a multiple of 16 bytes (std430 array stride).");

	// AreaLightData::shading_method packs the method (low 8 bits) and the stochastic sample count, so the
	// 80-byte layout stays as it is. Must match area_light_get_method()/_samples() in shaders/area_light_inc.glsl.
	static constexpr uint32_t AREA_METHOD_MASK = 0xFFu;
	static constexpr uint32_t AREA_METHOD_SAMPLES_SHIFT = 8;
	static uint32_t pack_area_shading_method(RS::LightAreaShadingMethod p_method, int p_samples) {
		return (uint32_t(p_method) & AREA_METHOD_MASK) | ((uint32_t(p_samples) & 0xFFFFu) << AREA_METHOD_SAMPLES_SHIFT);
	}

	// Lights per type uploaded per view (nearest to the camera first); a multiple of 32.
	static constexpr uint32_t DEFAULT_MAX_LIGHTS = 512;

private:
	/* Private Members */

	struct Light {
		RS::LightType type = RS::LIGHT_OMNI;
		float param[RS::LIGHT_PARAM_MAX] = {};
		Color color = Color(1, 1, 1, 1);
		bool shadow = false;
		bool negative = false;
		bool reverse_cull = false;
		uint32_t cull_mask = 0xFFFFFFFF;
		uint32_t shadow_caster_mask = 0xFFFFFFFF;
		RS::LightBakeMode bake_mode = RS::LIGHT_BAKE_DYNAMIC;
		bool distance_fade = false;
		float distance_fade_begin = 40.0f;
		float distance_fade_shadow = 50.0f;
		float distance_fade_length = 10.0f;
		RS::LightOmniShadowMode omni_shadow_mode = RS::LIGHT_OMNI_SHADOW_CUBE;
		RS::LightDirectionalShadowMode directional_shadow_mode = RS::LIGHT_DIRECTIONAL_SHADOW_ORTHOGONAL;
		bool directional_blend_splits = false;
		RS::LightDirectionalSkyMode directional_sky_mode = RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_AND_SKY;
		Vector2 area_size = Vector2(1, 1); // Metres, local X and Y.
		bool area_normalize_energy = true;
		RS::LightAreaShadingMethod area_shading_method = RS::LIGHT_AREA_SHADING_LTC;
		int area_stochastic_samples = RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT;
		RS::LightAreaShadowMode area_shadow_mode = RS::LIGHT_AREA_SHADOW_FIXED;
		int area_shadow_grid = RS::LIGHT_AREA_SHADOW_GRID_DEFAULT;
		uint64_t version = 0;
	};

	mutable RID_Owner<Light, true> light_owner{ "RendererRD::Light" };

	uint32_t max_lights = DEFAULT_MAX_LIGHTS;
	RID omni_light_buffer; // LightData[max_lights]
	RID spot_light_buffer; // LightData[max_lights]
	RID area_light_buffer; // AreaLightData[max_lights]
	uint32_t omni_light_count = 0;
	uint32_t spot_light_count = 0;
	uint32_t area_light_count = 0;
	uint32_t area_shading_method_mask = 0; // Bit m set: an uploaded area light uses RS::LightAreaShadingMethod m.
	std::vector<LightData> omni_data;
	std::vector<LightData> spot_data;
	std::vector<AreaLightData> area_data;
	std::vector<uint32_t> area_source_indices; // GPU area light i came from p_lights[area_source_indices[i]].
	// AUTO shading (AreaMethodSelector): receivers of the next update_light_buffers() only (then cleared).
	const std::vector<RenderSceneData::GeometryInstance> *auto_geometry = nullptr;
	const RendererMeshStorage *auto_mesh_storage = nullptr;
	const RendererMaterialStorage *auto_material_storage = nullptr;

	Light *_get_light(RID p_light, const char *p_caller) const;

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

	RID get_omni_light_buffer() const { return omni_light_buffer; }
	RID get_spot_light_buffer() const { return spot_light_buffer; }
	RID get_area_light_buffer() const { return area_light_buffer; }
	uint32_t get_omni_light_count() const { return omni_light_count; }
	uint32_t get_spot_light_count() const { return spot_light_count; }
	uint32_t get_area_light_count() const { return area_light_count; }
	// Bit m is set when an area light of the last update_light_buffers() uses RS::LightAreaShadingMethod m
	// (the renderer compiles only these methods). 0 without area lights.
	uint32_t get_area_shading_method_mask() const { return area_shading_method_mask; }
	uint32_t get_max_lights() const { return max_lights; }
	// CPU copies of the last upload (tests).
	const std::vector<LightData> &get_omni_light_data() const { return omni_data; }
	const std::vector<LightData> &get_spot_light_data() const { return spot_data; }
	const std::vector<AreaLightData> &get_area_light_data() const { return area_data; }
	// For GPU area light i of the last update, its index in the p_lights given (area shadows use it).
	const std::vector<uint32_t> &get_area_light_source_indices() const { return area_source_indices; }

	// AUTO area shading (servers/rendering/renderer_rd/area_method_selector.h). The renderer gives the
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

	/* Public Methods: RendererLightStorage */

	RID light_create(RS::LightType p_type) override;
	bool light_free(RID p_rid) override;
	bool owns_light(RID p_rid) const override { return light_owner.owns(p_rid); }

	void light_set_param(RID p_light, RS::LightParam p_param, float p_value) override;
	void light_set_color(RID p_light, const Color &p_color) override;
	void light_set_shadow(RID p_light, bool p_enabled) override;
	void light_set_negative(RID p_light, bool p_enable) override;
	void light_set_cull_mask(RID p_light, uint32_t p_mask) override;
	void light_set_shadow_caster_mask(RID p_light, uint32_t p_mask) override;
	void light_set_reverse_cull_face_mode(RID p_light, bool p_enabled) override;
	void light_set_bake_mode(RID p_light, RS::LightBakeMode p_mode) override;
	void light_set_distance_fade(RID p_light, bool p_enabled, float p_begin, float p_shadow, float p_length) override;
	void light_omni_set_shadow_mode(RID p_light, RS::LightOmniShadowMode p_mode) override;
	void light_directional_set_shadow_mode(RID p_light, RS::LightDirectionalShadowMode p_mode) override;
	void light_directional_set_blend_splits(RID p_light, bool p_enable) override;
	void light_directional_set_sky_mode(RID p_light, RS::LightDirectionalSkyMode p_mode) override;
	void light_area_set_size(RID p_light, const Vector2 &p_size) override;
	void light_area_set_normalize_energy(RID p_light, bool p_enable) override;
	void light_area_set_shading_method(RID p_light, RS::LightAreaShadingMethod p_method) override;
	void light_area_set_stochastic_samples(RID p_light, int p_samples) override;
	void light_area_set_shadow_mode(RID p_light, RS::LightAreaShadowMode p_mode) override;
	void light_area_set_shadow_grid(RID p_light, int p_grid) override;

	RS::LightType light_get_type(RID p_light) const override;
	float light_get_param(RID p_light, RS::LightParam p_param) const override;
	Color light_get_color(RID p_light) const override;
	bool light_has_shadow(RID p_light) const override;
	bool light_is_negative(RID p_light) const override;
	uint32_t light_get_cull_mask(RID p_light) const override;
	uint32_t light_get_shadow_caster_mask(RID p_light) const override;
	bool light_get_reverse_cull_face_mode(RID p_light) const override;
	RS::LightBakeMode light_get_bake_mode(RID p_light) const override;
	bool light_is_distance_fade_enabled(RID p_light) const override;
	float light_get_distance_fade_begin(RID p_light) const override;
	float light_get_distance_fade_shadow(RID p_light) const override;
	float light_get_distance_fade_length(RID p_light) const override;
	RS::LightOmniShadowMode light_omni_get_shadow_mode(RID p_light) const override;
	RS::LightDirectionalShadowMode light_directional_get_shadow_mode(RID p_light) const override;
	bool light_directional_get_blend_splits(RID p_light) const override;
	RS::LightDirectionalSkyMode light_directional_get_sky_mode(RID p_light) const override;
	Vector2 light_area_get_size(RID p_light) const override;
	bool light_area_get_normalize_energy(RID p_light) const override;
	RS::LightAreaShadingMethod light_area_get_shading_method(RID p_light) const override;
	int light_area_get_stochastic_samples(RID p_light) const override;
	RS::LightAreaShadowMode light_area_get_shadow_mode(RID p_light) const override;
	int light_area_get_shadow_grid(RID p_light) const override;
	AABB light_get_aabb(RID p_light) const override;
	uint64_t light_get_version(RID p_light) const override;

	LightStorage() {}
	~LightStorage();

private:
	std::vector<AreaAutoChoice> area_auto_choices; // See get_area_auto_choices().
};

} // namespace RendererRD
