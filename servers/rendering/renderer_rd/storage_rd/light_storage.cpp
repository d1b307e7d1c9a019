/**************************************************************************/
/*  light_storage.cpp                                                     */
/**************************************************************************/

#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "servers/rendering/renderer_rd/area_lights/area_method_selector.h"
#include "servers/rendering/renderer_rd/cluster_builder_rd.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/storage/material_storage.h"

#include <algorithm>
#include <cmath>

using namespace RendererRD;

/* GPU side */

uint32_t LightStorage::get_project_max_lights() {
	const int64_t v = GLOBAL_DEF(SETTING_MAX_CLUSTERED_ELEMENTS, int64_t(DEFAULT_MAX_LIGHTS)).to_int();
	if (v < 32 || v > int64_t(MAX_LIGHTS_LIMIT)) {
		ERR_PRINT(vformat("%s must be 32..%u; got %lld. Using %u.", SETTING_MAX_CLUSTERED_ELEMENTS, MAX_LIGHTS_LIMIT, (long long)v, DEFAULT_MAX_LIGHTS));
		return DEFAULT_MAX_LIGHTS;
	}
	return uint32_t(v);
}

bool LightStorage::initialize_gpu(uint32_t p_max_lights) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL_V_MSG(rd, false, "LightStorage::initialize_gpu() needs an initialized RenderingDevice.");
	ERR_FAIL_COND_V_MSG(p_max_lights == 0, false, "LightStorage: the maximum light count must be at least 1.");
	finalize_gpu();
	max_lights = (p_max_lights + 31) / 32 * 32;
	uint32_t size = max_lights * sizeof(LightData);
	omni_light_buffer = rd->storage_buffer_create(size);
	spot_light_buffer = rd->storage_buffer_create(size);
	area_light_buffer = rd->storage_buffer_create(max_lights * sizeof(AreaLightData));
	rd->set_resource_name(omni_light_buffer, "LightStorage omni lights");
	rd->set_resource_name(spot_light_buffer, "LightStorage spot lights");
	rd->set_resource_name(area_light_buffer, "LightStorage area lights");
	omni_light_count = 0;
	spot_light_count = 0;
	area_light_count = 0;
	return omni_light_buffer.is_valid() && spot_light_buffer.is_valid() && area_light_buffer.is_valid();
}

void LightStorage::finalize_gpu() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd) {
		if (omni_light_buffer.is_valid()) {
			rd->free(omni_light_buffer);
		}
		if (spot_light_buffer.is_valid()) {
			rd->free(spot_light_buffer);
		}
		if (area_light_buffer.is_valid()) {
			rd->free(area_light_buffer);
		}
		if (directional_light_buffer.is_valid()) {
			rd->free(directional_light_buffer);
		}
	}
	area_atlas.finalize();
	area_textured = false;
	directional_light_buffer = RID();
	directional_block = {};
	omni_light_buffer = RID();
	spot_light_buffer = RID();
	area_light_buffer = RID();
}

LightStorage::~LightStorage() {
	finalize_gpu();
}

bool LightStorage::fill_light_data(RID p_light, const Transform3D &p_world_from_light, const Transform3D &p_view_from_world, LightData &r_data) const {
	const Light *light = light_owner.get_or_null(p_light);
	ERR_FAIL_NULL_V_MSG(light, false, "LightStorage::fill_light_data: invalid light RID.");
	ERR_FAIL_COND_V_MSG(light->type == RS::LIGHT_DIRECTIONAL, false, "LightStorage::fill_light_data: directional lights are not clustered.");
	ERR_FAIL_COND_V_MSG(light->type == RS::LIGHT_AREA, false, "LightStorage::fill_light_data: area lights use fill_area_light_data().");

	Transform3D view_from_light = p_view_from_world * p_world_from_light;
	Vector3 position = view_from_light.origin;
	// Lights shine along their local -Z.
	Vector3 direction = view_from_light.basis.xform(Vector3(0, 0, -1)).normalized();
	if (direction == Vector3()) {
		direction = Vector3(0, 0, -1);
	}

	float range = std::fmax(light->param[RS::LIGHT_PARAM_RANGE], 1e-4f);
	// Unit conversion (the only one): sRGB -> linear, times energy, times pi (Godot 4 without physical
	// light units multiplies the energy by pi so the Lambert 1/pi cancels), sign for negative lights.
	Color linear = light->color.srgb_to_linear();
	float energy = light->param[RS::LIGHT_PARAM_ENERGY] * float(Math::PI) * (light->negative ? -1.0f : 1.0f);

	r_data = LightData();
	r_data.position[0] = position.x;
	r_data.position[1] = position.y;
	r_data.position[2] = position.z;
	r_data.inv_radius = 1.0f / range;
	r_data.direction[0] = direction.x;
	r_data.direction[1] = direction.y;
	r_data.direction[2] = direction.z;
	r_data.size = light->param[RS::LIGHT_PARAM_SIZE];
	r_data.color[0] = linear.r * energy;
	r_data.color[1] = linear.g * energy;
	r_data.color[2] = linear.b * energy;
	r_data.attenuation = light->param[RS::LIGHT_PARAM_ATTENUATION];
	if (light->type == RS::LIGHT_SPOT) {
		r_data.cone_attenuation = light->param[RS::LIGHT_PARAM_SPOT_ATTENUATION];
		r_data.cone_angle = std::cos(Math::deg_to_rad(light->param[RS::LIGHT_PARAM_SPOT_ANGLE]));
	} else {
		r_data.cone_attenuation = 0.0f;
		r_data.cone_angle = -1.0f;
	}
	r_data.specular_amount = light->param[RS::LIGHT_PARAM_SPECULAR];
	r_data.cull_mask = light->cull_mask;
	return true;
}

bool LightStorage::fill_area_light_data(RID p_light, const Transform3D &p_world_from_light, const Transform3D &p_view_from_world, AreaLightData &r_data) const {
	const Light *light = light_owner.get_or_null(p_light);
	ERR_FAIL_NULL_V_MSG(light, false, "LightStorage::fill_area_light_data: invalid light RID.");
	ERR_FAIL_COND_V_MSG(light->type != RS::LIGHT_AREA, false, "LightStorage::fill_area_light_data: the light is not an area light.");

	Transform3D view_from_light = p_view_from_world * p_world_from_light;
	const RS::LightAreaShape shape = light->area_shape;
	const float a = light->area_size.x;
	const float b = light->area_size.y;
	// Half axes keep the node's scale out: the shape is area_size in metres, only the rotation of
	// the transform orients it (as Godot ignores scale for light ranges).
	Vector3 axis_x = view_from_light.basis.xform(Vector3(1, 0, 0)).normalized();
	Vector3 axis_y = view_from_light.basis.xform(Vector3(0, 1, 0)).normalized();
	Vector3 normal = view_from_light.basis.xform(Vector3(0, 0, -1)).normalized();
	if (axis_x == Vector3() || axis_y == Vector3() || normal == Vector3()) {
		axis_x = Vector3(1, 0, 0);
		axis_y = Vector3(0, 1, 0);
		normal = Vector3(0, 0, -1);
	}
	// Per shape (AreaLightData): rectangle and disk the half sizes; sphere the radius a / 2 on both axes;
	// tube half the segment (a / 2) and the radius (b / 2).
	Vector3 hx = axis_x * (a * 0.5f);
	Vector3 hy = axis_y * (shape == RS::LIGHT_AREA_SHAPE_SPHERE ? a * 0.5f : b * 0.5f);
	float range = std::fmax(light->param[RS::LIGHT_PARAM_RANGE], 1e-4f);

	// Unit conversion (the contract): L_e = srgb_to_linear(colour) * energy * pi / A_n,
	// A_n = the shape's emitting area when normalised, else 1; a zero area emits exactly nothing.
	Color linear = light->color.srgb_to_linear();
	float area = compute_area_light_emitting_area(light->area_size, shape);
	float radiance = 0.0f;
	if (area > 0.0f && std::isfinite(area)) {
		float a_n = light->area_normalize_energy ? area : 1.0f;
		radiance = light->param[RS::LIGHT_PARAM_ENERGY] * float(Math::PI) / a_n * (light->negative ? -1.0f : 1.0f);
	}

	r_data = AreaLightData();
	Vector3 c = view_from_light.origin;
	for (int i = 0; i < 3; i++) {
		r_data.position[i] = c[i];
		r_data.half_axis_x[i] = hx[i];
		r_data.half_axis_y[i] = hy[i];
		r_data.normal[i] = normal[i];
	}
	r_data.inv_radius = 1.0f / range;
	r_data.attenuation = light->param[RS::LIGHT_PARAM_ATTENUATION];
	r_data.specular_amount = light->param[RS::LIGHT_PARAM_SPECULAR];
	r_data.shading_method = pack_area_shading_method(light->area_shading_method, light->area_stochastic_samples, shape);
	r_data.color[0] = linear.r * radiance;
	r_data.color[1] = linear.g * radiance;
	r_data.color[2] = linear.b * radiance;
	r_data.cull_mask = light->cull_mask;
	return true;
}

void LightStorage::update_light_buffers(const std::vector<RenderSceneData::LightInstance> &p_lights, const Transform3D &p_view_from_world, ClusterBuilderRD *p_cluster_builder) {
	ERR_FAIL_COND_MSG(!is_gpu_initialized(), "LightStorage::update_light_buffers() called before initialize_gpu().");
	RenderingDevice *rd = RenderingDevice::get_singleton();

	struct Sorted {
		float distance_sq;
		uint32_t index; // In p_lights (ties keep scene order).
		LightData data;
		float range;
		float spot_angle;
	};
	struct SortedArea {
		float distance_sq;
		uint32_t index;
		AreaLightData data;
		float range;
	};
	std::vector<Sorted> omnis;
	std::vector<Sorted> spots;
	std::vector<SortedArea> areas;
	// AUTO area lights are resolved here, per light and frame (the GPU only sees concrete methods).
	const Vector3 camera_position = p_view_from_world.affine_inverse().origin;
	float auto_budget = -1.0f;
	float auto_default_roughness = 0.5f;
	std::vector<AreaAutoChoice> auto_choices(p_lights.size());
	for (uint32_t i = 0; i < p_lights.size(); i++) {
		const RenderSceneData::LightInstance &li = p_lights[i];
		const Light *light = light_owner.get_or_null(li.light);
		ERR_CONTINUE_MSG(!light, "update_light_buffers: a visible light instance has an invalid light RID; skipped.");
		if (light->type == RS::LIGHT_DIRECTIONAL) {
			continue;
		}
		if (light->type == RS::LIGHT_AREA) {
			SortedArea s;
			if (!fill_area_light_data(li.light, li.transform, p_view_from_world, s.data)) {
				continue;
			}
			AreaAutoChoice &choice = auto_choices[i];
			choice.requested = light->area_shading_method;
			choice.method = light->area_shading_method;
			if (light->area_shading_method == RS::LIGHT_AREA_SHADING_AUTO) {
				if (auto_budget < 0.0f) {
					auto_budget = AreaMethodSelector::get_error_budget();
					auto_default_roughness = AreaMethodSelector::get_default_roughness();
				}
				AreaMethodSelector::Estimate est = AreaMethodSelector::estimate(li.transform, light->area_size, li.aabb, camera_position, auto_geometry,
						auto_mesh_storage, auto_material_storage, auto_default_roughness);
				choice.method = AreaMethodSelector::choose(est.size_over_distance, est.roughness, auto_budget, light->area_stochastic_samples);
				choice.size_over_distance = est.size_over_distance;
				choice.roughness = est.roughness;
				choice.predicted_error = AreaMethodSelector::predict_error(choice.method, est.size_over_distance, est.roughness, light->area_stochastic_samples);
				s.data.shading_method = pack_area_shading_method(choice.method, light->area_stochastic_samples, light->area_shape);
			}
			Vector3 p(s.data.position[0], s.data.position[1], s.data.position[2]);
			s.distance_sq = p.length_squared();
			s.index = i;
			s.range = std::fmax(light->param[RS::LIGHT_PARAM_RANGE], 1e-4f);
			areas.push_back(s);
			continue;
		}
		Sorted s;
		if (!fill_light_data(li.light, li.transform, p_view_from_world, s.data)) {
			continue;
		}
		Vector3 p(s.data.position[0], s.data.position[1], s.data.position[2]);
		s.distance_sq = p.length_squared();
		s.index = i;
		s.range = std::fmax(light->param[RS::LIGHT_PARAM_RANGE], 1e-4f);
		s.spot_angle = Math::deg_to_rad(light->param[RS::LIGHT_PARAM_SPOT_ANGLE]);
		(light->type == RS::LIGHT_OMNI ? omnis : spots).push_back(s);
	}
	auto nearest_first = [](const Sorted &a, const Sorted &b) {
		return a.distance_sq != b.distance_sq ? a.distance_sq < b.distance_sq : a.index < b.index;
	};
	std::sort(omnis.begin(), omnis.end(), nearest_first);
	std::sort(spots.begin(), spots.end(), nearest_first);
	std::sort(areas.begin(), areas.end(), [](const SortedArea &a, const SortedArea &b) {
		return a.distance_sq != b.distance_sq ? a.distance_sq < b.distance_sq : a.index < b.index;
	});
	// Over capacity: the farthest are dropped, and said so once per change of the counts (not every frame).
	const size_t over_area = areas.size() > max_lights ? areas.size() - max_lights : 0;
	const size_t over_omni = omnis.size() > max_lights ? omnis.size() - max_lights : 0;
	const size_t over_spot = spots.size() > max_lights ? spots.size() - max_lights : 0;
	dropped_light_count = uint32_t(over_area + over_omni + over_spot);
	if (dropped_light_count != 0 && dropped_light_count != warned_dropped_count) {
		WARN_PRINT(vformat("%u visible lights exceed the renderer's capacity of %u per type and are not drawn (farthest first: %u of %u area, %u of %u omni, %u of %u spot). Raise the project setting %s (up to %u).",
				dropped_light_count, max_lights, uint32_t(over_area), uint32_t(areas.size()), uint32_t(over_omni), uint32_t(omnis.size()), uint32_t(over_spot), uint32_t(spots.size()),
				SETTING_MAX_CLUSTERED_ELEMENTS, MAX_LIGHTS_LIMIT));
	}
	warned_dropped_count = dropped_light_count;
	if (areas.size() > max_lights) {
		areas.resize(max_lights);
	}
	if (omnis.size() > max_lights) {
		omnis.resize(max_lights);
	}
	if (spots.size() > max_lights) {
		spots.resize(max_lights);
	}

	omni_data.clear();
	spot_data.clear();
	// Cluster element N of a type == GPU light N of that type: both are filled here, in this order.
	for (const Sorted &s : omnis) {
		omni_data.push_back(s.data);
		if (p_cluster_builder) {
			p_cluster_builder->add_light(ClusterBuilderRD::ELEMENT_TYPE_OMNI_LIGHT, Vector3(s.data.position[0], s.data.position[1], s.data.position[2]), s.range);
		}
	}
	for (const Sorted &s : spots) {
		spot_data.push_back(s.data);
		if (p_cluster_builder) {
			p_cluster_builder->add_light(ClusterBuilderRD::ELEMENT_TYPE_SPOT_LIGHT, Vector3(s.data.position[0], s.data.position[1], s.data.position[2]), s.range,
					Vector3(s.data.direction[0], s.data.direction[1], s.data.direction[2]), s.spot_angle);
		}
	}
	area_data.clear();
	area_source_indices.clear();
	area_auto_choices.clear();
	area_shading_method_mask = 0;
	area_shape_mask = 0;
	auto_geometry = nullptr; // Consumed: valid for this update only.
	auto_mesh_storage = nullptr;
	auto_material_storage = nullptr;
	// area_texture: slots for the textures of the kept lights (built on first use), then their rects. A
	// scene without textured lights never touches the atlas.
	area_textured = false;
	area_untextured_shapes = 0;
	bool any_texture = false;
	for (const SortedArea &s : areas) {
		const Light *light = light_owner.get_or_null(p_lights[s.index].light);
		if (light && light->area_texture.is_valid()) {
			if (unpack_area_shape(s.data.shading_method) != RS::LIGHT_AREA_SHAPE_RECTANGLE) {
				area_untextured_shapes++; // No slot: drawn untextured (texture_rect stays 0), warned below.
				continue;
			}
			if (!any_texture) {
				area_atlas.begin_update();
				any_texture = true;
			}
			const Image *image = texture_source && texture_source->owns_texture(light->area_texture) ? texture_source->texture_get_image(light->area_texture) : nullptr;
			area_atlas.request(light->area_texture, image);
		}
	}
	if (any_texture || area_atlas.get_slot_count() > 0) {
		if (!any_texture) {
			area_atlas.begin_update(); // Ages the slots of lights that lost their texture or left the view.
		}
		area_atlas.end_update();
	}
	for (SortedArea &s : areas) {
		const Light *light = light_owner.get_or_null(p_lights[s.index].light);
		if (light && light->area_texture.is_valid() && unpack_area_shape(s.data.shading_method) == RS::LIGHT_AREA_SHAPE_RECTANGLE && area_atlas.get_rect(light->area_texture, s.data.texture_rect)) {
			area_textured = true;
		}
	}
	if (area_untextured_shapes != warned_untextured_shapes) {
		if (area_untextured_shapes > 0) {
			WARN_PRINT(vformat("%u visible area lights have an area_texture but are not rectangles; area_texture applies to rectangles only (as upstream's AreaLight3D), so they are drawn untextured.", area_untextured_shapes));
		}
		warned_untextured_shapes = area_untextured_shapes;
	}
	for (const SortedArea &s : areas) {
		area_data.push_back(s.data);
		area_source_indices.push_back(s.index);
		area_auto_choices.push_back(auto_choices[s.index]);
		area_shading_method_mask |= 1u << (s.data.shading_method & AREA_METHOD_MASK);
		const RS::LightAreaShape shape = unpack_area_shape(s.data.shading_method);
		area_shape_mask |= 1u << uint32_t(shape);
		if (p_cluster_builder && is_area_shape_two_sided(shape)) {
			// Sphere and tube emit all around: a box centred on the light, grown by the range on every side
			// (sphere: radius |half_axis_x|; tube: segment half_axis_x, radius |half_axis_y|).
			const AreaLightData &d = s.data;
			const Vector3 hx(d.half_axis_x[0], d.half_axis_x[1], d.half_axis_x[2]);
			const Vector3 hy(d.half_axis_y[0], d.half_axis_y[1], d.half_axis_y[2]);
			const Vector3 n(d.normal[0], d.normal[1], d.normal[2]);
			Vector3 ax = hy.cross(n).normalized(); // Local X, also for a zero-length segment.
			if (ax == Vector3()) {
				ax = std::fabs(n.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
				ax = (ax - n * n.dot(ax)).normalized();
			}
			const bool sphere = shape == RS::LIGHT_AREA_SHAPE_SPHERE;
			const float radius = sphere ? hx.length() : hy.length();
			const float half_length = sphere ? 0.0f : hx.length();
			const Vector3 ext(half_length + radius + s.range, radius + s.range, radius + s.range);
			p_cluster_builder->add_area_light_box(Vector3(d.position[0], d.position[1], d.position[2]), ax, n, ext, s.range + half_length + radius);
		} else if (p_cluster_builder) {
			const AreaLightData &d = s.data;
			p_cluster_builder->add_area_light(Vector3(d.position[0], d.position[1], d.position[2]), Vector3(d.half_axis_x[0], d.half_axis_x[1], d.half_axis_x[2]),
					Vector3(d.half_axis_y[0], d.half_axis_y[1], d.half_axis_y[2]), Vector3(d.normal[0], d.normal[1], d.normal[2]), s.range);
		}
	}
	omni_light_count = uint32_t(omni_data.size());
	spot_light_count = uint32_t(spot_data.size());
	area_light_count = uint32_t(area_data.size());
	if (area_light_count) {
		rd->buffer_update(area_light_buffer, 0, area_light_count * sizeof(AreaLightData), area_data.data());
	}
	if (omni_light_count) {
		rd->buffer_update(omni_light_buffer, 0, omni_light_count * sizeof(LightData), omni_data.data());
	}
	if (spot_light_count) {
		rd->buffer_update(spot_light_buffer, 0, spot_light_count * sizeof(LightData), spot_data.data());
	}
}

void LightStorage::set_area_auto_receivers(const std::vector<RenderSceneData::GeometryInstance> *p_geometry, const RendererMeshStorage *p_mesh_storage, const RendererMaterialStorage *p_material_storage) {
	auto_geometry = p_geometry;
	auto_mesh_storage = p_mesh_storage;
	auto_material_storage = p_material_storage;
}

/* Directional lights (not clustered) */

bool LightStorage::fill_directional_light_data(RID p_light, const Transform3D &p_world_from_light, const Transform3D &p_view_from_world, DirectionalLightData &r_data) const {
	const Light *light = light_owner.get_or_null(p_light);
	ERR_FAIL_NULL_V_MSG(light, false, "LightStorage::fill_directional_light_data: invalid light RID.");
	ERR_FAIL_COND_V_MSG(light->type != RS::LIGHT_DIRECTIONAL, false, "LightStorage::fill_directional_light_data: the light is not directional.");
	Vector3 direction = (p_view_from_world.basis * p_world_from_light.basis).xform(Vector3(0, 0, -1)).normalized();
	if (direction == Vector3()) {
		direction = Vector3(0, 0, -1);
	}
	// Same conversion as fill_light_data(): linear colour * energy * pi (Godot without physical units), so a
	// white Lambert surface facing the sun reflects exactly light_energy.
	const Color linear = light->color.srgb_to_linear();
	const float energy = light->param[RS::LIGHT_PARAM_ENERGY] * float(Math::PI) * (light->negative ? -1.0f : 1.0f);
	r_data = DirectionalLightData();
	for (int i = 0; i < 3; i++) {
		r_data.direction[i] = direction[i];
	}
	r_data.energy = energy;
	r_data.color[0] = linear.r * energy;
	r_data.color[1] = linear.g * energy;
	r_data.color[2] = linear.b * energy;
	// light_angular_distance is the disk's angular diameter in degrees (Godot: 0.5 for the Sun seen from Earth).
	r_data.size = Math::deg_to_rad(std::fmin(std::fmax(light->param[RS::LIGHT_PARAM_SIZE], 0.0f), 90.0f)) * 0.5f;
	r_data.specular_amount = light->param[RS::LIGHT_PARAM_SPECULAR];
	r_data.cull_mask = light->cull_mask;
	r_data.flags = 0;
	r_data.shadow_index = -1; // DirectionalShadowRD::prepare() sets it for shadowed lights in view.
	return true;
}

void LightStorage::update_directional_light_buffer(const std::vector<RenderSceneData::LightInstance> &p_lights, const Transform3D &p_view_from_world) {
	directional_block.count = 0;
	directional_source_indices.clear();
	directional_dropped = 0;
	for (uint32_t i = 0; i < p_lights.size(); i++) {
		const Light *light = light_owner.get_or_null(p_lights[i].light);
		ERR_CONTINUE_MSG(!light || light->type != RS::LIGHT_DIRECTIONAL, "update_directional_light_buffer: a directional light instance has an invalid or non-directional light RID; skipped.");
		if (directional_block.count == MAX_DIRECTIONAL_LIGHTS) {
			directional_dropped++;
			continue;
		}
		if (fill_directional_light_data(p_lights[i].light, p_lights[i].transform, p_view_from_world, directional_block.data[directional_block.count])) {
			directional_source_indices.push_back(i);
			directional_block.count++;
		}
	}
	if (directional_dropped) {
		WARN_PRINT(vformat("LightStorage: %d directional lights beyond the first %d of the view are ignored (Godot's limit).", int(directional_dropped), int(MAX_DIRECTIONAL_LIGHTS)));
	}
	if (directional_block.count == 0) {
		return; // Nothing to upload; a scene without a sun never creates the buffer.
	}
	upload_directional_light_buffer();
}

void LightStorage::upload_directional_light_buffer() {
	if (directional_block.count == 0) {
		return;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL_MSG(rd, "upload_directional_light_buffer: no RenderingDevice.");
	if (!directional_light_buffer.is_valid()) {
		directional_light_buffer = rd->uniform_buffer_create(sizeof(DirectionalLightBlock));
		ERR_FAIL_COND_MSG(!directional_light_buffer.is_valid(), "LightStorage: the directional light buffer could not be created.");
		rd->set_resource_name(directional_light_buffer, "LightStorage directional lights");
	}
	rd->buffer_update(directional_light_buffer, 0, sizeof(DirectionalLightBlock), &directional_block);
}
