/**************************************************************************/
/*  renderer_scene_cull.cpp                                               */
/**************************************************************************/

#include "servers/rendering/renderer_scene_cull.h"

#include "core/error/error_macros.h"
#include "servers/rendering/rendering_server_globals.h"
#include "servers/rendering/storage/environment_storage.h"
#include "servers/rendering/storage/light_storage.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

/* BOUNDS */

bool RendererSceneCull::is_sphere_culled(const std::vector<Plane> &p_planes, const Vector3 &p_center, real_t p_radius) {
	for (const Plane &plane : p_planes) {
		if (plane.distance_to(p_center) > p_radius) {
			return true;
		}
	}
	return false;
}

bool RendererSceneCull::is_cone_culled(const std::vector<Plane> &p_planes, const Vector3 &p_apex, const Vector3 &p_axis, real_t p_range, real_t p_angle_degrees) {
	// The lit volume of a spot is a spherical sector: points apex + s * u with s in [0, range] and u within
	// the half-angle theta of the axis. Against an outward plane with normal n, its smallest signed distance is
	//   distance(apex) + range * min(0, min_u n.u),  min_u n.u = cos(min(pi, alpha + theta)),  alpha = angle(n, axis),
	// because the direction in the cap farthest from n is rotated from the axis towards -n by at most theta.
	// The sector is outside when that minimum is still positive. Exact per plane, so it is as tight as
	// plane-by-plane testing allows (tighter than both the range sphere and the cone's AABB).
	const real_t theta = Math::deg_to_rad(std::fmin(std::fmax(p_angle_degrees, real_t(0)), real_t(180)));
	for (const Plane &plane : p_planes) {
		const real_t cos_alpha = Math::clamp(plane.normal.dot(p_axis), real_t(-1), real_t(1));
		const real_t extent = std::acos(cos_alpha) + theta;
		const real_t min_dot = extent >= real_t(Math::PI) ? real_t(-1) : std::cos(extent);
		const real_t min_distance = plane.distance_to(p_apex) + p_range * std::fmin(real_t(0), min_dot);
		if (min_distance > real_t(CMP_EPSILON)) {
			return true;
		}
	}
	return false;
}

bool RendererSceneCull::area_light_box_intersects(const Transform3D &p_world_from_light, const AABB &p_light_box, const AABB &p_aabb) {
	if (!p_world_from_light.xform(p_light_box).intersects(p_aabb)) {
		return false;
	}
	// Orthonormal basis: the inverse is the transpose (as Transform3D::xform_inv).
	Transform3D light_from_world;
	light_from_world.basis = p_world_from_light.basis.transposed();
	light_from_world.origin = -light_from_world.basis.xform(p_world_from_light.origin);
	return light_from_world.xform(p_aabb).intersects(p_light_box);
}

/* CAMERA */

RID RendererSceneCull::camera_allocate() {
	return camera_owner.make_rid();
}

void RendererSceneCull::camera_set_perspective(RID p_camera, float p_fovy_degrees, float p_z_near, float p_z_far) {
	Camera *camera = camera_owner.get_or_null(p_camera);
	ERR_FAIL_NULL_MSG(camera, "Invalid camera RID.");
	ERR_FAIL_COND_MSG(!std::isfinite(p_fovy_degrees) || p_fovy_degrees <= 0.0f || p_fovy_degrees >= 180.0f,
			vformat("Camera field of view must be between 0 and 180 degrees (exclusive), got %s.", rtos(p_fovy_degrees).c_str()));
	ERR_FAIL_COND_MSG(!std::isfinite(p_z_near) || !std::isfinite(p_z_far) || p_z_near <= 0.0f || p_z_far <= p_z_near,
			vformat("Camera planes must satisfy 0 < near < far, got near %s, far %s.", rtos(p_z_near).c_str(), rtos(p_z_far).c_str()));
	camera->fovy_degrees = p_fovy_degrees;
	camera->z_near = p_z_near;
	camera->z_far = p_z_far;
}

void RendererSceneCull::camera_set_transform(RID p_camera, const Transform3D &p_transform) {
	Camera *camera = camera_owner.get_or_null(p_camera);
	ERR_FAIL_NULL_MSG(camera, "Invalid camera RID.");
	ERR_FAIL_COND_MSG(!p_transform.is_finite(), "Camera transform must be finite.");
	camera->transform = p_transform;
}

void RendererSceneCull::camera_set_cull_mask(RID p_camera, uint32_t p_layers) {
	Camera *camera = camera_owner.get_or_null(p_camera);
	ERR_FAIL_NULL_MSG(camera, "Invalid camera RID.");
	camera->cull_mask = p_layers;
}

void RendererSceneCull::camera_set_environment(RID p_camera, RID p_env) {
	Camera *camera = camera_owner.get_or_null(p_camera);
	ERR_FAIL_NULL_MSG(camera, "Invalid camera RID.");
	ERR_FAIL_COND_MSG(p_env.is_valid() && !(RSG::environment_storage && RSG::environment_storage->is_environment(p_env)), "Invalid environment RID.");
	camera->environment = p_env;
}

/* SCENARIO */

RID RendererSceneCull::scenario_allocate() {
	return scenario_owner.make_rid();
}

void RendererSceneCull::scenario_set_environment(RID p_scenario, RID p_env) {
	Scenario *scenario = scenario_owner.get_or_null(p_scenario);
	ERR_FAIL_NULL_MSG(scenario, "Invalid scenario RID.");
	ERR_FAIL_COND_MSG(p_env.is_valid() && !(RSG::environment_storage && RSG::environment_storage->is_environment(p_env)), "Invalid environment RID.");
	scenario->environment = p_env;
}

int RendererSceneCull::scenario_get_instance_count(RID p_scenario) const {
	const Scenario *scenario = scenario_owner.get_or_null(p_scenario);
	ERR_FAIL_NULL_V_MSG(scenario, 0, "Invalid scenario RID.");
	return (int)(scenario->instances.size() - scenario->null_slots);
}

void RendererSceneCull::_scenario_remove_instance(RID p_scenario, RID p_instance) {
	Scenario *scenario = scenario_owner.get_or_null(p_scenario);
	if (!scenario) {
		return;
	}
	auto it = scenario->slot.find(p_instance);
	if (it == scenario->slot.end()) {
		return;
	}
	scenario->instances[it->second] = RID();
	scenario->slot.erase(it);
	scenario->null_slots++;
	if (scenario->null_slots * 2 > scenario->instances.size()) {
		std::vector<RID> live;
		live.reserve(scenario->slot.size());
		for (const RID &rid : scenario->instances) {
			if (rid.is_valid()) {
				scenario->slot[rid] = live.size();
				live.push_back(rid);
			}
		}
		scenario->instances.swap(live);
		scenario->null_slots = 0;
	}
}

void RendererSceneCull::_scenario_add_instance(Scenario &r_scenario, RID p_instance) {
	r_scenario.slot[p_instance] = r_scenario.instances.size();
	r_scenario.instances.push_back(p_instance);
}

void RendererSceneCull::_dependency_set(RID p_instance, RID p_old, RID p_new) {
	if (p_old == p_new) {
		return;
	}
	if (p_old.is_valid()) {
		auto it = dependents.find(p_old);
		if (it != dependents.end()) {
			it->second.erase(p_instance);
			if (it->second.empty()) {
				dependents.erase(it);
			}
		}
	}
	if (p_new.is_valid()) {
		dependents[p_new].insert(p_instance);
	}
}

/* INSTANCE */

RID RendererSceneCull::instance_allocate() {
	return instance_owner.make_rid();
}

void RendererSceneCull::instance_set_base(RID p_instance, RID p_base) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	if (p_base.is_null()) {
		_dependency_set(p_instance, instance->base, RID());
		instance->base = RID();
		instance->base_type = RS::INSTANCE_NONE;
		return;
	}
	if (RSG::mesh_storage && RSG::mesh_storage->owns_mesh(p_base)) {
		instance->base_type = RS::INSTANCE_MESH;
	} else if (RSG::light_storage && RSG::light_storage->owns_light(p_base)) {
		instance->base_type = RS::INSTANCE_LIGHT;
	} else {
		ERR_FAIL_MSG("Instance base must be a mesh or a light RID; the base is unchanged.");
	}
	_dependency_set(p_instance, instance->base, p_base);
	instance->base = p_base;
}

void RendererSceneCull::instance_set_scenario(RID p_instance, RID p_scenario) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	if (instance->scenario == p_scenario) {
		return;
	}
	if (p_scenario.is_valid()) {
		Scenario *scenario = scenario_owner.get_or_null(p_scenario);
		ERR_FAIL_NULL_MSG(scenario, "Invalid scenario RID.");
		_scenario_remove_instance(instance->scenario, p_instance);
		_scenario_add_instance(*scenario, p_instance);
	} else {
		_scenario_remove_instance(instance->scenario, p_instance);
	}
	instance->scenario = p_scenario;
}

void RendererSceneCull::instance_set_transform(RID p_instance, const Transform3D &p_transform) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	ERR_FAIL_COND_MSG(!p_transform.is_finite(), "Instance transform must be finite; the old transform is kept.");
	instance->transform = p_transform;
}

void RendererSceneCull::instance_set_visible(RID p_instance, bool p_visible) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	instance->visible = p_visible;
}

void RendererSceneCull::instance_set_layer_mask(RID p_instance, uint32_t p_mask) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	instance->layer_mask = p_mask;
}

void RendererSceneCull::instance_geometry_set_material_override(RID p_instance, RID p_material) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	ERR_FAIL_COND_MSG(p_material.is_valid() && !(RSG::material_storage && RSG::material_storage->owns_material(p_material)), "Invalid material RID for the material override.");
	_dependency_set(p_instance, instance->material_override, p_material);
	instance->material_override = p_material;
}

void RendererSceneCull::instance_geometry_set_cast_shadows_setting(RID p_instance, RS::ShadowCastingSetting p_setting) {
	Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_MSG(instance, "Invalid instance RID.");
	ERR_FAIL_COND_MSG(int(p_setting) < 0 || int(p_setting) > int(RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY), vformat("cast_shadow must be 0..3 (Off, On, Double-Sided, Shadows Only); got %d.", int(p_setting)));
	instance->cast_shadows = p_setting;
}

AABB RendererSceneCull::_instance_get_world_aabb(const Instance &p_instance) const {
	switch (p_instance.base_type) {
		case RS::INSTANCE_MESH:
			if (RSG::mesh_storage && RSG::mesh_storage->owns_mesh(p_instance.base)) {
				return p_instance.transform.xform(RSG::mesh_storage->mesh_get_aabb(p_instance.base));
			}
			break;
		case RS::INSTANCE_LIGHT:
			if (RSG::light_storage && RSG::light_storage->owns_light(p_instance.base) && RSG::light_storage->light_get_type(p_instance.base) != RS::LIGHT_DIRECTIONAL) {
				return p_instance.transform.xform(RSG::light_storage->light_get_aabb(p_instance.base));
			}
			break;
		case RS::INSTANCE_NONE:
			break;
	}
	return AABB();
}

AABB RendererSceneCull::instance_get_aabb(RID p_instance) const {
	const Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_V_MSG(instance, AABB(), "Invalid instance RID.");
	return _instance_get_world_aabb(*instance);
}

RS::InstanceType RendererSceneCull::instance_get_base_type(RID p_instance) const {
	const Instance *instance = instance_owner.get_or_null(p_instance);
	ERR_FAIL_NULL_V_MSG(instance, RS::INSTANCE_NONE, "Invalid instance RID.");
	return instance->base_type;
}

/* LIFETIME */

bool RendererSceneCull::free(RID p_rid) {
	if (Instance *instance = instance_owner.get_or_null(p_rid)) {
		_scenario_remove_instance(instance->scenario, p_rid);
		_dependency_set(p_rid, instance->base, RID());
		_dependency_set(p_rid, instance->material_override, RID());
		instance_owner.free(p_rid);
		return true;
	}
	if (camera_owner.owns(p_rid)) {
		camera_owner.free(p_rid);
		return true;
	}
	if (Scenario *scenario = scenario_owner.get_or_null(p_rid)) {
		for (const RID &rid : scenario->instances) {
			if (Instance *instance = instance_owner.get_or_null(rid)) {
				instance->scenario = RID();
			}
		}
		scenario_owner.free(p_rid);
		return true;
	}
	return false;
}

void RendererSceneCull::notify_base_freed(RID p_base) {
	auto it = dependents.find(p_base);
	if (it == dependents.end()) {
		return;
	}
	for (const RID &rid : it->second) {
		Instance *instance = instance_owner.get_or_null(rid);
		if (instance && instance->base == p_base) {
			instance->base = RID();
			instance->base_type = RS::INSTANCE_NONE;
		}
		if (instance && instance->material_override == p_base) {
			instance->material_override = RID();
		}
	}
	dependents.erase(it);
}

void RendererSceneCull::notify_environment_freed(RID p_env) {
	for (const RID &rid : camera_owner.get_owned_list()) {
		Camera *camera = camera_owner.get_or_null(rid);
		if (camera && camera->environment == p_env) {
			camera->environment = RID();
		}
	}
	for (const RID &rid : scenario_owner.get_owned_list()) {
		Scenario *scenario = scenario_owner.get_or_null(rid);
		if (scenario && scenario->environment == p_env) {
			scenario->environment = RID();
		}
	}
}

/* CULLING */

void RendererSceneCull::_resolve_environment(RID p_camera_env, RID p_scenario_env, const Color &p_default_clear, RenderSceneData::EnvironmentData &r_env) const {
	r_env = RenderSceneData::EnvironmentData();
	r_env.bg_color = p_default_clear;
	const RendererEnvironmentStorage::Environment *env = nullptr;
	if (RSG::environment_storage) {
		env = RSG::environment_storage->environment_get(p_camera_env);
		if (!env) {
			env = RSG::environment_storage->environment_get(p_scenario_env);
		}
	}
	if (!env) {
		return; // Default clear colour, no ambient light.
	}
	r_env.has_environment = true;
	const RendererEnvironmentStorage::Sky *sky = RSG::environment_storage->sky_get(env->sky);
	const RendererEnvironmentStorage::SkyMaterial *sky_material = sky ? RSG::environment_storage->sky_material_get(sky->material) : nullptr;
	if (sky_material) {
		r_env.sky_type = sky_material->type;
		r_env.sky = sky_material->procedural;
		r_env.physical_sky = sky_material->physical;
		r_env.sky_radiance_size = sky->radiance_size;
	}
	switch (env->background) {
		case RS::ENV_BG_COLOR:
			r_env.background = RS::ENV_BG_COLOR;
			r_env.bg_color = env->bg_color;
			break;
		case RS::ENV_BG_CLEAR_COLOR:
			break;
		case RS::ENV_BG_SKY:
			if (sky_material) {
				r_env.background = RS::ENV_BG_SKY;
			} else {
				WARN_PRINT_ONCE("Environment background_mode is Sky but it has no Sky with a sky_material; drawing black.");
				r_env.background = RS::ENV_BG_COLOR;
				r_env.bg_color = Color(0, 0, 0, 1);
			}
			break;
		default:
			WARN_PRINT_ONCE("Only the CLEAR_COLOR, COLOR and SKY environment backgrounds are supported; using the default clear colour.");
			break;
	}
	r_env.bg_energy = env->bg_energy;
	r_env.ss_lighting = RSG::environment_storage->get_ss_lighting(env == RSG::environment_storage->environment_get(p_camera_env) ? p_camera_env : p_scenario_env);
	r_env.ambient_source = env->ambient_source;
	switch (env->ambient_source) {
		case RS::ENV_AMBIENT_SOURCE_BG:
			if (r_env.background == RS::ENV_BG_SKY) {
				// A sky background lights the scene as sky ambient (Godot), all of it from the sky.
				r_env.sky_ambient = true;
				r_env.ambient_sky_contribution = 1.0f;
				r_env.ambient_color = Color(0, 0, 0, 1);
				r_env.ambient_energy = env->ambient_energy;
				break;
			}
			// With a colour background, the background lights the scene (colour times background energy).
			r_env.ambient_color = r_env.bg_color;
			r_env.ambient_energy = r_env.bg_energy;
			break;
		case RS::ENV_AMBIENT_SOURCE_COLOR:
			r_env.ambient_color = env->ambient_color;
			r_env.ambient_energy = env->ambient_energy;
			break;
		case RS::ENV_AMBIENT_SOURCE_SKY:
			if (!sky_material) {
				WARN_PRINT_ONCE("Environment ambient_light_source is Sky but it has no Sky with a sky_material; ambient light is disabled.");
				r_env.ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
				break;
			}
			r_env.sky_ambient = true;
			r_env.ambient_sky_contribution = env->ambient_sky_contribution;
			r_env.ambient_color = env->ambient_color;
			r_env.ambient_energy = env->ambient_energy;
			break;
		case RS::ENV_AMBIENT_SOURCE_DISABLED:
			break;
	}
	if (r_env.ambient_source == RS::ENV_AMBIENT_SOURCE_DISABLED) {
		r_env.ambient_color = Color(0, 0, 0, 1);
		r_env.ambient_energy = 0.0f;
		r_env.sky_ambient = false;
	}
	// reflected_light_source (Godot): BG reflects the sky only under a sky background; SKY always; DISABLED never.
	r_env.sky_reflections = sky_material && (env->reflection_source == RS::ENV_REFLECTION_SOURCE_SKY || (env->reflection_source == RS::ENV_REFLECTION_SOURCE_BG && r_env.background == RS::ENV_BG_SKY));
	r_env.has_sky = sky_material && (r_env.background == RS::ENV_BG_SKY || r_env.sky_ambient || r_env.sky_reflections);
}

bool RendererSceneCull::build_render_scene_data(RID p_camera, RID p_scenario, int p_width, int p_height, const Color &p_default_clear_color, RenderSceneData &r_data) {
	last_stats = CullStats();
	const Camera *camera = camera_owner.get_or_null(p_camera);
	ERR_FAIL_NULL_V_MSG(camera, false, "Invalid camera RID.");
	const Scenario *scenario = scenario_owner.get_or_null(p_scenario);
	ERR_FAIL_NULL_V_MSG(scenario, false, "Invalid scenario RID.");
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0, false, vformat("Viewport size %dx%d is invalid.", p_width, p_height));

	r_data = RenderSceneData();
	r_data.cam_transform = camera->transform;
	r_data.cam_projection = Projection::create_perspective(camera->fovy_degrees, real_t(p_width) / real_t(p_height), camera->z_near, camera->z_far);
	r_data.z_near = camera->z_near;
	r_data.z_far = camera->z_far;
	r_data.fovy_degrees = camera->fovy_degrees;
	r_data.viewport_width = p_width;
	r_data.viewport_height = p_height;
	r_data.camera_cull_mask = camera->cull_mask;
	_resolve_environment(camera->environment, scenario->environment, p_default_clear_color, r_data.environment);

	const std::vector<Plane> planes = r_data.cam_projection.get_projection_planes(camera->transform);

	for (const RID &rid : scenario->instances) {
		const Instance *instance = instance_owner.get_or_null(rid);
		if (!instance || !instance->visible) {
			continue;
		}
		if (instance->base_type == RS::INSTANCE_MESH) {
			if (!RSG::mesh_storage || !RSG::mesh_storage->owns_mesh(instance->base)) {
				continue;
			}
			if ((instance->layer_mask & camera->cull_mask) == 0) {
				continue;
			}
			const AABB aabb = _instance_get_world_aabb(*instance);
			if (!aabb.intersects_convex_shape(planes)) {
				last_stats.geometry_culled++;
				continue;
			}
			RenderSceneData::GeometryInstance geometry;
			geometry.instance = rid;
			geometry.mesh = instance->base;
			geometry.material_override = (RSG::material_storage && RSG::material_storage->owns_material(instance->material_override)) ? instance->material_override : RID();
			geometry.transform = instance->transform;
			geometry.aabb = aabb;
			geometry.layer_mask = instance->layer_mask;
			geometry.cast_shadows = instance->cast_shadows;
			r_data.geometry.push_back(geometry);
			last_stats.geometry_visible++;
		} else if (instance->base_type == RS::INSTANCE_LIGHT) {
			if (!RSG::light_storage || !RSG::light_storage->owns_light(instance->base)) {
				continue;
			}
			RenderSceneData::LightInstance light;
			light.instance = rid;
			light.light = instance->base;
			light.type = RSG::light_storage->light_get_type(instance->base);
			light.transform = instance->transform;
			if (light.type == RS::LIGHT_DIRECTIONAL) {
				r_data.directional_lights.push_back(light);
				last_stats.directional_lights++;
				continue;
			}
			light.aabb = _instance_get_world_aabb(*instance);
			const Vector3 scale = instance->transform.basis.get_scale();
			const real_t range = RSG::light_storage->light_get_param(instance->base, RS::LIGHT_PARAM_RANGE) * std::fmax(scale.x, std::fmax(scale.y, scale.z));
			bool culled;
			if (light.type == RS::LIGHT_OMNI) {
				culled = is_sphere_culled(planes, instance->transform.origin, range);
			} else if (light.type == RS::LIGHT_AREA) {
				// Thesis eq. 5.1: every point of the rectangle lights up to `range` away, so the sphere
				// around its centre has radius range + half the diagonal (scaled like the range: conservative).
				const real_t max_scale = std::fmax(scale.x, std::fmax(scale.y, scale.z));
				const Vector2 size = RSG::light_storage->light_area_get_size(instance->base);
				const RS::LightAreaShape shape = RSG::light_storage->light_area_get_shape(instance->base);
				const real_t radius = RendererLightStorage::compute_area_light_cull_radius(range, size * max_scale, shape);
				culled = is_sphere_culled(planes, instance->transform.origin, radius);
			} else {
				const Vector3 axis = (-instance->transform.basis.get_column(2)).normalized();
				const real_t angle = RSG::light_storage->light_get_param(instance->base, RS::LIGHT_PARAM_SPOT_ANGLE);
				culled = is_cone_culled(planes, instance->transform.origin, axis, range, angle);
			}
			if (culled) {
				last_stats.lights_culled++;
				continue;
			}
			r_data.lights.push_back(light);
			last_stats.lights_visible++;
		}
	}
	_fill_area_shadow_casters(*scenario, r_data);
	// Shadowed suns cast from every mesh of the scenario, seen or not (DirectionalShadowRD culls them per
	// split): the meshes missing from geometry and shadow_geometry join shadow_geometry, listed by no light.
	uint32_t sun_caster_mask = 0;
	for (const RenderSceneData::LightInstance &light : r_data.directional_lights) {
		sun_caster_mask |= RSG::light_storage->light_has_shadow(light.light) ? RSG::light_storage->light_get_shadow_caster_mask(light.light) : 0u;
	}
	if (sun_caster_mask != 0) {
		std::set<uint64_t> known;
		for (const std::vector<RenderSceneData::GeometryInstance> *list : { &r_data.geometry, &r_data.shadow_geometry }) {
			for (const RenderSceneData::GeometryInstance &g : *list) {
				known.insert(g.instance.get_id());
			}
		}
		for (const RID &rid : scenario->instances) {
			const Instance *instance = instance_owner.get_or_null(rid);
			if (!instance || !instance->visible || instance->base_type != RS::INSTANCE_MESH || !RSG::mesh_storage || !RSG::mesh_storage->owns_mesh(instance->base) || (instance->layer_mask & sun_caster_mask) == 0 || instance->cast_shadows == RS::SHADOW_CASTING_SETTING_OFF || known.count(rid.get_id())) {
				continue;
			}
			RenderSceneData::GeometryInstance geometry;
			geometry.instance = rid;
			geometry.mesh = instance->base;
			geometry.material_override = (RSG::material_storage && RSG::material_storage->owns_material(instance->material_override)) ? instance->material_override : RID();
			geometry.transform = instance->transform;
			geometry.aabb = _instance_get_world_aabb(*instance);
			geometry.layer_mask = instance->layer_mask;
			geometry.cast_shadows = instance->cast_shadows;
			r_data.shadow_geometry.push_back(geometry);
		}
	}
	return true;
}

void RendererSceneCull::_fill_area_shadow_casters(const Scenario &p_scenario, RenderSceneData &r_data) {
	// Godot's _light_instance_update_shadow(): a light's casters are the instances in its range, whether
	// the camera sees them or not (an occluder behind the camera still shadows the visible floor).
	std::vector<std::pair<RID, AABB>> meshes; // Every visible mesh instance of the scenario, lazily.
	std::map<uint64_t, uint32_t> index_of; // Instance id -> index in r_data.shadow_geometry.
	std::set<uint64_t> on_screen; // Camera-visible instance ids (statistics).
	bool gathered = false;
	for (RenderSceneData::LightInstance &light : r_data.lights) {
		if (light.type != RS::LIGHT_AREA || !RSG::light_storage->light_has_shadow(light.light)) {
			continue;
		}
		if (!gathered) {
			gathered = true;
			for (const RenderSceneData::GeometryInstance &g : r_data.geometry) {
				on_screen.insert(g.instance.get_id());
			}
			for (const RID &rid : p_scenario.instances) {
				const Instance *instance = instance_owner.get_or_null(rid);
				if (instance && instance->visible && instance->base_type == RS::INSTANCE_MESH && RSG::mesh_storage && RSG::mesh_storage->owns_mesh(instance->base) && instance->cast_shadows != RS::SHADOW_CASTING_SETTING_OFF) {
					meshes.push_back(std::make_pair(rid, _instance_get_world_aabb(*instance)));
				}
			}
		}
		// Same frame as the renderer's shadow pass: orthonormalised light transform, light-space range box.
		const Transform3D world_from_light(light.transform.basis.orthonormalized(), light.transform.origin);
		const AABB box = RSG::light_storage->light_get_aabb(light.light);
		const uint32_t caster_mask = RSG::light_storage->light_get_shadow_caster_mask(light.light);
		for (const std::pair<RID, AABB> &m : meshes) {
			const Instance *instance = instance_owner.get_or_null(m.first);
			if ((instance->layer_mask & caster_mask) == 0 || !area_light_box_intersects(world_from_light, box, m.second)) {
				continue;
			}
			auto it = index_of.find(m.first.get_id());
			if (it == index_of.end()) {
				RenderSceneData::GeometryInstance geometry;
				geometry.instance = m.first;
				geometry.mesh = instance->base;
				geometry.material_override = (RSG::material_storage && RSG::material_storage->owns_material(instance->material_override)) ? instance->material_override : RID();
				geometry.transform = instance->transform;
				geometry.aabb = m.second;
				geometry.layer_mask = instance->layer_mask;
				geometry.cast_shadows = instance->cast_shadows;
				it = index_of.emplace(m.first.get_id(), uint32_t(r_data.shadow_geometry.size())).first;
				r_data.shadow_geometry.push_back(geometry);
				last_stats.area_shadow_casters++;
				if (!on_screen.count(m.first.get_id())) {
					last_stats.area_shadow_casters_offscreen++;
				}
			}
			light.shadow_casters.push_back(it->second);
		}
	}
}

void RendererSceneCull::render_camera(RID p_camera, RID p_scenario, int p_width, int p_height, const Color &p_default_clear_color, RS::ViewportDebugDraw p_debug_draw, RID p_render_target, int p_area_shadow_atlas_size, int p_area_shadow_atlas_subdivision) {
	ERR_FAIL_NULL_MSG(RSG::scene_render, "No scene renderer is set up.");
	RenderSceneData data;
	if (!build_render_scene_data(p_camera, p_scenario, p_width, p_height, p_default_clear_color, data)) {
		return;
	}
	data.debug_draw = p_debug_draw;
	data.area_shadow_atlas_size = uint32_t(std::max(p_area_shadow_atlas_size, 0));
	data.area_shadow_atlas_subdivision = uint32_t(std::max(p_area_shadow_atlas_subdivision, 0));
	RSG::scene_render->render_scene(data, p_render_target);
}
