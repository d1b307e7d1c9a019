/**************************************************************************/
/*  renderer_scene_cull.h                                                 */
/**************************************************************************/
/* godot-area: scenarios, cameras and instances, and per-viewport frustum */
/* culling (Godot's RendererSceneCull, reduced: no BVH, no light/geometry */
/* pairing). Bounds are recomputed from storage on every cull, so storage */
/* changes (mesh surfaces, light range/angle) need no dependency tracking.*/
/* Geometry is culled by its world AABB; omni lights by their range      */
/* sphere; spot lights by the exact spherical-sector (cone) bound; area  */
/* lights by the sphere of thesis eq. 5.1 around the rectangle's centre  */
/* (radius = range + half the diagonal); directional lights are never    */
/* culled. Each visible shadowed area light gets its shadow casters:     */
/* every mesh instance (on screen or not) on its shadow_caster_mask      */
/* whose bound meets its influence box (a + 2r) x (b + 2r) x r           */
/* (RenderSceneData::shadow_geometry, LightInstance::shadow_casters).    */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/renderer_scene_render.h"

#include <unordered_map>
#include <unordered_set>

class RendererSceneCull {
public:
	struct Camera {
		float fovy_degrees = 75.0f; // Godot's Camera3D defaults.
		float z_near = 0.05f;
		float z_far = 4000.0f;
		Transform3D transform; // world_from_view.
		uint32_t cull_mask = 0xFFFFF;
		RID environment;
	};

	struct Scenario {
		RID environment;
		// Insertion order (kept deterministic for tests and rendering). A removed instance leaves a null
		// slot that every loop skips; the list is compacted once half of it is null, so adding and
		// removing are amortised O(1) and freeing a whole scene is linear.
		std::vector<RID> instances;
		std::unordered_map<RID, size_t> slot; // Instance -> its index in instances.
		size_t null_slots = 0;
	};

	struct Instance {
		RS::InstanceType base_type = RS::INSTANCE_NONE;
		RID base;
		RID scenario;
		Transform3D transform; // world_from_object.
		bool visible = true;
		uint32_t layer_mask = 1;
		RID material_override;
		RS::ShadowCastingSetting cast_shadows = RS::SHADOW_CASTING_SETTING_ON;
	};

	// Counters of the last build_render_scene_data() call.
	struct CullStats {
		int geometry_visible = 0;
		int geometry_culled = 0; // Outside the frustum (hidden or layer-masked instances are not counted).
		int lights_visible = 0; // Omni, spot and area lights.
		int lights_culled = 0;
		int directional_lights = 0;
		int area_shadow_casters = 0; // Distinct instances in RenderSceneData::shadow_geometry.
		int area_shadow_casters_offscreen = 0; // Of those, outside the camera frustum.
	};

private:
	RID_Owner<Camera, true> camera_owner{ "Camera" };
	RID_Owner<Scenario, true> scenario_owner{ "Scenario" };
	RID_Owner<Instance, true> instance_owner{ "Instance" };
	// Base (mesh, light) or override material -> the instances that reference it, so freeing a base
	// touches only its users (notify_base_freed) instead of every instance.
	std::unordered_map<RID, std::unordered_set<RID>> dependents;
	void _dependency_set(RID p_instance, RID p_old, RID p_new);
	CullStats last_stats;

	void _scenario_remove_instance(RID p_scenario, RID p_instance);
	void _scenario_add_instance(Scenario &r_scenario, RID p_instance);
	AABB _instance_get_world_aabb(const Instance &p_instance) const;
	void _fill_area_shadow_casters(const Scenario &p_scenario, RenderSceneData &r_data);
	void _resolve_environment(RID p_camera_env, RID p_scenario_env, const Color &p_default_clear, RenderSceneData::EnvironmentData &r_env) const;

public:
	// Returns true when a sphere lies completely outside one of the (outward-facing) planes.
	static bool is_sphere_culled(const std::vector<Plane> &p_planes, const Vector3 &p_center, real_t p_radius);
	// Returns true when a spherical sector (cone of half-angle p_angle_degrees around unit p_axis,
	// apex p_apex, capped at p_range) lies completely outside one of the planes.
	static bool is_cone_culled(const std::vector<Plane> &p_planes, const Vector3 &p_apex, const Vector3 &p_axis, real_t p_range, real_t p_angle_degrees);
	// Returns true when the world bound p_aabb meets an area light's influence box p_light_box (light space;
	// p_world_from_light orthonormal): the world AABBs of both overlap and p_aabb's bound in light space
	// overlaps p_light_box (both tests conservative, together tighter for rotated lights).
	static bool area_light_box_intersects(const Transform3D &p_world_from_light, const AABB &p_light_box, const AABB &p_aabb);

	/* CAMERA */
	// Creates a camera with Camera3D defaults.
	RID camera_allocate();
	// Sets a perspective projection (validated: 0 < fov < 180, 0 < near < far).
	void camera_set_perspective(RID p_camera, float p_fovy_degrees, float p_z_near, float p_z_far);
	// Sets world_from_view.
	void camera_set_transform(RID p_camera, const Transform3D &p_transform);
	// Sets the visible layers.
	void camera_set_cull_mask(RID p_camera, uint32_t p_layers);
	// Sets the camera environment override.
	void camera_set_environment(RID p_camera, RID p_env);
	// Returns true if p_rid is a camera.
	bool is_camera(RID p_rid) const { return camera_owner.owns(p_rid); }

	/* SCENARIO */
	// Creates an empty scenario.
	RID scenario_allocate();
	// Sets the scenario environment.
	void scenario_set_environment(RID p_scenario, RID p_env);
	// Returns true if p_rid is a scenario.
	bool is_scenario(RID p_rid) const { return scenario_owner.owns(p_rid); }
	// Returns the number of instances in a scenario (0 if invalid).
	int scenario_get_instance_count(RID p_scenario) const;

	/* INSTANCE */
	// Creates an instance with no base and no scenario.
	RID instance_allocate();
	// Sets the base (mesh or light RID of the current storages, or RID()).
	void instance_set_base(RID p_instance, RID p_base);
	// Moves the instance to a scenario (RID() removes it).
	void instance_set_scenario(RID p_instance, RID p_scenario);
	// Sets world_from_object.
	void instance_set_transform(RID p_instance, const Transform3D &p_transform);
	// Shows or hides.
	void instance_set_visible(RID p_instance, bool p_visible);
	// Sets render layers.
	void instance_set_layer_mask(RID p_instance, uint32_t p_mask);
	// Sets the material override.
	void instance_geometry_set_material_override(RID p_instance, RID p_material);
	void instance_geometry_set_cast_shadows_setting(RID p_instance, RS::ShadowCastingSetting p_setting);
	// Returns the world AABB of the base (empty if none or directional).
	AABB instance_get_aabb(RID p_instance) const;
	// Returns the base type.
	RS::InstanceType instance_get_base_type(RID p_instance) const;
	// Returns true if p_rid is an instance.
	bool is_instance(RID p_rid) const { return instance_owner.owns(p_rid); }

	/* LIFETIME */
	// Frees a camera, scenario or instance; returns false if p_rid is none of them.
	// A freed scenario releases its instances (they stay alive, with no scenario).
	bool free(RID p_rid);
	// Detaches a freed base (mesh/light) from every instance that used it.
	void notify_base_freed(RID p_base);
	// Removes a freed environment from every camera and scenario that used it.
	void notify_environment_freed(RID p_env);

	/* CULLING */
	// Culls p_scenario for p_camera at a p_width x p_height viewport and fills r_data.
	// Returns false (with an error) for invalid RIDs or sizes.
	bool build_render_scene_data(RID p_camera, RID p_scenario, int p_width, int p_height, const Color &p_default_clear_color, RenderSceneData &r_data);
	// Culls, then calls RSG::scene_render->render_scene() into p_render_target. p_area_shadow_atlas_*: the
	// viewport's area shadow atlas (0 = the renderer's default), passed on in RenderSceneData.
	void render_camera(RID p_camera, RID p_scenario, int p_width, int p_height, const Color &p_default_clear_color, RS::ViewportDebugDraw p_debug_draw, RID p_render_target, int p_area_shadow_atlas_size = 0, int p_area_shadow_atlas_subdivision = 0);
	// Counters of the last cull (tests read them).
	const CullStats &get_last_cull_stats() const { return last_stats; }
};
