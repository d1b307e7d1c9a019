/**************************************************************************/
/*  test_renderer_scene_cull.cpp                                          */
/**************************************************************************/
/* godot-area: RenderingServerDefault + RendererSceneCull on the dummy    */
/* (CPU-only) backend: object lifetime, validation, culling and the       */
/* RenderSceneData handed to the renderer.                                */

#include "servers/rendering/renderer_scene_cull.h"

#include "core/error/error_macros.h"
#include "core/templates/rid_owner.h"
#include "scene/3d/geometry_instance_3d.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering/dummy/rasterizer_dummy.h"
#include "servers/rendering/rendering_server_default.h"
#include "servers/rendering/rendering_server_globals.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

namespace TestRendererSceneCull {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

// A square of half side p_half in the z = 0 plane, normal +Z.
static RS::SurfaceData make_quad(real_t p_half) {
	RS::SurfaceData s;
	PlaneMesh::create_plane_arrays(s, Vector2(p_half * 2, p_half * 2), 0, 0, Vector3(), PlaneMesh::FACE_Z);
	return s;
}

static Transform3D at(const Vector3 &p_origin) {
	return Transform3D(Basis(), p_origin);
}

TEST_CASE("[RenderingServer] singleton and RSG pointers follow the server's lifetime") {
	CHECK(RenderingServer::get_singleton() == nullptr);
	{
		DummyServer server;
		CHECK(RenderingServer::get_singleton() == server.rs);
		CHECK(RSG::light_storage == server.rasterizer->get_light_storage());
		CHECK(RSG::scene == server.rs->get_scene_cull());
	}
	CHECK(RenderingServer::get_singleton() == nullptr);
	CHECK(RSG::light_storage == nullptr);
	CHECK(RSG::scene == nullptr);
}

TEST_CASE("[RenderingServer] creating and freeing every object type leaks no RIDs") {
	const uint64_t leaked_before = RID_AllocBase::get_leaked_total();
	{
		DummyServer server;
		RS *rs = server.rs;
		RID mesh = rs->mesh_create();
		rs->mesh_add_surface(mesh, make_quad(1));
		RID material = rs->material_create();
		RID texture = rs->texture_2d_create_rgba8(2, 2, std::vector<uint8_t>(16, 255));
		REQUIRE(texture.is_valid());
		RS::MaterialParams params;
		params.albedo_texture = texture;
		rs->material_set_params(material, params);
		rs->mesh_surface_set_material(mesh, 0, material);
		RID lights[3] = { rs->directional_light_create(), rs->omni_light_create(), rs->spot_light_create() };
		RID camera = rs->camera_create();
		RID env = rs->environment_create();
		RID scenario = rs->scenario_create();
		rs->scenario_set_environment(scenario, env);
		RID instance = rs->instance_create();
		rs->instance_set_base(instance, mesh);
		rs->instance_set_scenario(instance, scenario);
		RID light_instance = rs->instance_create();
		rs->instance_set_base(light_instance, lights[1]);
		rs->instance_set_scenario(light_instance, scenario);
		RID viewport = rs->viewport_create();
		rs->viewport_set_size(viewport, 8, 8);
		rs->viewport_attach_camera(viewport, camera);
		rs->viewport_set_scenario(viewport, scenario);
		rs->draw();

		SUBCASE("freeing everything") {
			for (RID rid : { viewport, light_instance, instance, scenario, env, camera, lights[0], lights[1], lights[2], texture, material, mesh }) {
				rs->free(rid);
			}
		}
		SUBCASE("freeing resources before the instances that use them") {
			for (RID rid : { mesh, material, texture, lights[0], lights[1], lights[2], env, scenario, camera, viewport, instance, light_instance }) {
				rs->free(rid);
			}
		}
	}
	CHECK(RID_AllocBase::get_leaked_total() == leaked_before);
}

TEST_CASE("[RenderingServer] a RID that is never freed is reported as leaked") {
	const uint64_t leaked_before = RID_AllocBase::get_leaked_total();
	{
		ErrorCatcher errors;
		DummyServer server;
		server.rs->omni_light_create();
		server.rs->instance_create();
		server.engine.stop(); // Deletes the server.
		server.rs = nullptr;
		CHECK(errors.contains("leaked"));
	}
	CHECK_MESSAGE(RID_AllocBase::get_leaked_total() == leaked_before + 2, "The light and the instance must be reported.");
}

TEST_CASE("[RenderingServer] invalid RIDs print errors and return neutral values") {
	DummyServer server;
	RS *rs = server.rs;
	ErrorCatcher errors;
	RID mesh = rs->mesh_create();
	RID light = rs->omni_light_create();

	SUBCASE("free of null, unknown and already freed RIDs") {
		rs->free(RID());
		CHECK(errors.messages.size() == 1);
		rs->free(RID::from_uint64(0xFFFFFFFFFFull));
		CHECK(errors.messages.size() == 2);
		rs->free(mesh);
		CHECK(errors.messages.size() == 2);
		rs->free(mesh);
		CHECK(errors.messages.size() == 3);
		CHECK(errors.contains("invalid or already freed RID"));
		rs->free(light);
	}
	SUBCASE("light calls on a mesh RID") {
		rs->light_set_param(mesh, RS::LIGHT_PARAM_RANGE, 2.0f);
		CHECK(errors.contains("Invalid light RID"));
		CHECK(rs->light_get_param(mesh, RS::LIGHT_PARAM_RANGE) == 0.0f);
		CHECK(rs->light_get_aabb(mesh).size == Vector3());
		rs->free(mesh);
		rs->free(light);
	}
	SUBCASE("mesh calls on a light RID and bad surface indices") {
		CHECK(rs->mesh_get_surface_count(light) == 0);
		rs->mesh_surface_set_material(mesh, 3, RID());
		CHECK(errors.contains("Surface index out of range"));
		CHECK(rs->mesh_surface_get_material(mesh, -1) == RID());
		rs->free(mesh);
		rs->free(light);
	}
	SUBCASE("instance base must be a mesh or a light") {
		RID camera = rs->camera_create();
		RID instance = rs->instance_create();
		rs->instance_set_base(instance, camera);
		CHECK(errors.contains("mesh or a light"));
		rs->instance_set_scenario(instance, camera);
		CHECK(errors.contains("Invalid scenario RID"));
		rs->instance_set_transform(RID(), Transform3D());
		CHECK(errors.contains("Invalid instance RID"));
		for (RID rid : { instance, camera, mesh, light }) {
			rs->free(rid);
		}
	}
}

TEST_CASE("[RenderingServer] light storage defaults and validation") {
	DummyServer server;
	RS *rs = server.rs;
	RID omni = rs->omni_light_create();
	RID directional = rs->directional_light_create();
	RID spot = rs->spot_light_create();

	SUBCASE("storage defaults") {
		CHECK(rs->light_get_type(omni) == RS::LIGHT_OMNI);
		CHECK(rs->light_get_type(spot) == RS::LIGHT_SPOT);
		CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_ENERGY) == doctest::Approx(1.0));
		CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_RANGE) == doctest::Approx(1.0));
		CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_SPECULAR) == doctest::Approx(0.5));
		CHECK(rs->light_get_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE) == doctest::Approx(45.0));
		CHECK(rs->light_get_param(directional, RS::LIGHT_PARAM_INTENSITY) == doctest::Approx(100000.0));
		CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_INTENSITY) == doctest::Approx(1000.0));
		CHECK(RSG::light_storage->light_get_cull_mask(omni) == 0xFFFFFFFFu);
	}
	SUBCASE("rejected values name the parameter and keep the old value") {
		ErrorCatcher errors;
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, 5.0f);
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, NAN);
		CHECK(errors.contains("LIGHT_PARAM_RANGE"));
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, -1.0f);
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, INFINITY);
		CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_RANGE) == doctest::Approx(5.0));
		rs->light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 200.0f);
		CHECK(errors.contains("LIGHT_PARAM_SPOT_ANGLE"));
		CHECK(rs->light_get_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE) == doctest::Approx(45.0));
		rs->light_set_param(omni, RS::LIGHT_PARAM_ENERGY, INFINITY);
		CHECK(errors.contains("LIGHT_PARAM_ENERGY"));
		CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_ENERGY) == doctest::Approx(1.0));
		rs->light_set_param(omni, RS::LightParam(RS::LIGHT_PARAM_MAX), 1.0f);
		CHECK(errors.messages.size() == 6);
	}
	SUBCASE("version bumps only when culling or shadows change") {
		const uint64_t v0 = RSG::light_storage->light_get_version(omni);
		rs->light_set_param(omni, RS::LIGHT_PARAM_ENERGY, 3.0f);
		rs->light_set_color(omni, Color(1, 0, 0));
		CHECK(RSG::light_storage->light_get_version(omni) == v0);
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, 3.0f);
		CHECK(RSG::light_storage->light_get_version(omni) == v0 + 1);
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, 3.0f);
		CHECK_MESSAGE(RSG::light_storage->light_get_version(omni) == v0 + 1, "Setting the same value must not bump the version.");
		rs->light_set_shadow(omni, true);
		CHECK(RSG::light_storage->light_get_version(omni) == v0 + 2);
		CHECK(RSG::light_storage->light_has_shadow(omni));
	}
	SUBCASE("local bounds") {
		rs->light_set_param(omni, RS::LIGHT_PARAM_RANGE, 2.0f);
		CHECK(rs->light_get_aabb(omni).is_equal_approx(AABB(Vector3(-2, -2, -2), Vector3(4, 4, 4))));
		rs->light_set_param(spot, RS::LIGHT_PARAM_RANGE, 4.0f);
		rs->light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 30.0f);
		// Spherical sector along -Z: rim radius 4 * sin(30) = 2, depth 4.
		CHECK(rs->light_get_aabb(spot).is_equal_approx(AABB(Vector3(-2, -2, -4), Vector3(4, 4, 4))));
		rs->light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 120.0f);
		CHECK(rs->light_get_aabb(spot).is_equal_approx(AABB(Vector3(-4, -4, -4), Vector3(8, 8, 8))));
		CHECK(rs->light_get_aabb(directional).size == Vector3());
	}
	for (RID rid : { omni, directional, spot }) {
		rs->free(rid);
	}
}

TEST_CASE("[RenderingServer] mesh surfaces are validated and bounded") {
	DummyServer server;
	RS *rs = server.rs;
	ErrorCatcher errors;
	RID mesh = rs->mesh_create();
	rs->mesh_add_surface(mesh, make_quad(1));
	REQUIRE(rs->mesh_get_surface_count(mesh) == 1);
	CHECK(rs->mesh_get_aabb(mesh).is_equal_approx(AABB(Vector3(-1, -1, 0), Vector3(2, 2, 0))));
	CHECK(errors.messages.empty());

	RS::SurfaceData bad = make_quad(1);
	bad.indices[2] = 7;
	rs->mesh_add_surface(mesh, bad);
	CHECK(errors.contains("ARRAY_INDEX[2] = 7 is out of range"));
	bad = make_quad(1);
	bad.normals.pop_back();
	rs->mesh_add_surface(mesh, bad);
	CHECK(errors.contains("ARRAY_NORMAL"));
	CHECK(rs->mesh_get_surface_count(mesh) == 1);

	RS::SurfaceData moved = make_quad(1);
	for (Vector3 &v : moved.vertices) {
		v = v + Vector3(0, 0, 3);
	}
	rs->mesh_add_surface(mesh, moved);
	CHECK(rs->mesh_get_surface_count(mesh) == 2);
	CHECK(rs->mesh_get_aabb(mesh).is_equal_approx(AABB(Vector3(-1, -1, 0), Vector3(2, 2, 3))));
	CHECK(RSG::mesh_storage->mesh_get_surface(mesh, 1)->aabb.position.z == doctest::Approx(3.0));

	rs->mesh_clear(mesh);
	CHECK(rs->mesh_get_surface_count(mesh) == 0);
	rs->free(mesh);
}

// Camera at the origin looking down -Z, 60 degrees vertical FOV, 64x32 viewport (aspect 2).
struct CullFixture {
	DummyServer server;
	RS *rs = server.rs;
	RendererSceneCull *cull = server.rs->get_scene_cull();
	RID camera = rs->camera_create();
	RID scenario = rs->scenario_create();
	RID mesh = rs->mesh_create();
	std::vector<RID> owned;

	RID add_instance(RID p_base, const Transform3D &p_transform) {
		RID instance = rs->instance_create();
		rs->instance_set_base(instance, p_base);
		rs->instance_set_transform(instance, p_transform);
		rs->instance_set_scenario(instance, scenario);
		owned.push_back(instance);
		return instance;
	}
	// Creates a light resource and an instance of it; returns the instance (r_light: the light).
	RID add_light(RS::LightType p_type, float p_range, const Transform3D &p_transform, RID *r_light = nullptr) {
		RID light = p_type == RS::LIGHT_OMNI ? rs->omni_light_create() : (p_type == RS::LIGHT_SPOT ? rs->spot_light_create() : rs->directional_light_create());
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, p_range);
		owned.push_back(light);
		if (r_light) {
			*r_light = light;
		}
		return add_instance(light, p_transform);
	}
	RenderSceneData cull_scene() {
		RenderSceneData data;
		REQUIRE(cull->build_render_scene_data(camera, scenario, 64, 32, Color(0.3f, 0.3f, 0.3f), data));
		return data;
	}
	CullFixture() {
		rs->camera_set_perspective(camera, 60.0f, 0.1f, 100.0f);
		rs->mesh_add_surface(mesh, make_quad(0.5f));
	}
	~CullFixture() {
		for (auto it = owned.rbegin(); it != owned.rend(); ++it) {
			rs->free(*it);
		}
		rs->free(mesh);
		rs->free(scenario);
		rs->free(camera);
	}
};

TEST_CASE("[SceneCull] objects outside the frustum are culled, objects in front are not") {
	CullFixture f;
	RID mesh_front = f.add_instance(f.mesh, at(Vector3(0, 0, -5)));
	f.add_instance(f.mesh, at(Vector3(0, 0, 5))); // Behind the camera.
	f.add_instance(f.mesh, at(Vector3(50, 0, -5))); // Far to the right.
	f.add_instance(f.mesh, at(Vector3(0, 0, -150))); // Beyond the far plane.
	RID omni_front = f.add_light(RS::LIGHT_OMNI, 2.0f, at(Vector3(1, 0, -4)));
	RID omni_behind;
	f.add_light(RS::LIGHT_OMNI, 2.0f, at(Vector3(0, 0, 6)), &omni_behind); // Behind, sphere does not reach the near plane.
	RID omni_touching = f.add_light(RS::LIGHT_OMNI, 2.0f, at(Vector3(0, 0, 1.5f))); // Behind, but its sphere crosses the near plane.

	const RenderSceneData data = f.cull_scene();
	const RendererSceneCull::CullStats &stats = f.cull->get_last_cull_stats();
	CHECK(stats.geometry_visible == 1);
	CHECK(stats.geometry_culled == 3);
	CHECK(stats.lights_visible == 2);
	CHECK(stats.lights_culled == 1);
	REQUIRE(data.geometry.size() == 1);
	CHECK(data.geometry[0].instance == mesh_front);
	CHECK(data.geometry[0].mesh == f.mesh);
	REQUIRE(data.lights.size() == 2);
	CHECK(data.lights[0].instance == omni_front);
	CHECK(data.lights[1].instance == omni_touching);
	CHECK(data.lights[0].type == RS::LIGHT_OMNI);

	SUBCASE("turning the camera around swaps what is visible") {
		f.rs->camera_set_transform(f.camera, Transform3D(Basis::from_axis_angle(Vector3(0, 1, 0), real_t(Math::PI)), Vector3()));
		const RenderSceneData turned = f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().geometry_visible == 1);
		REQUIRE(turned.geometry.size() == 1);
		CHECK(turned.geometry[0].transform.origin.is_equal_approx(Vector3(0, 0, 5)));
		CHECK(f.cull->get_last_cull_stats().lights_visible == 2);
	}
	SUBCASE("moving an instance updates its bound") {
		f.rs->instance_set_transform(mesh_front, at(Vector3(0, 0, 5)));
		f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().geometry_visible == 0);
		CHECK(f.rs->instance_get_aabb(mesh_front).is_equal_approx(AABB(Vector3(-0.5f, -0.5f, 5), Vector3(1, 1, 0))));
	}
	SUBCASE("a larger range brings a light back") {
		f.rs->light_set_param(omni_behind, RS::LIGHT_PARAM_RANGE, 7.0f);
		f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().lights_visible == 3);
	}
}

TEST_CASE("[SceneCull] a shadowed sun adds the meshes the camera does not see to the shadow geometry") {
	CullFixture f;
	f.add_instance(f.mesh, at(Vector3(0, 0, -5)));
	RID behind = f.add_instance(f.mesh, at(Vector3(0, 0, 5))); // Behind the camera: may shadow the view.
	RID sun;
	f.add_light(RS::LIGHT_DIRECTIONAL, 1.0f, Transform3D(), &sun);
	CHECK(f.cull_scene().shadow_geometry.empty()); // Unshadowed sun: nothing more.
	f.rs->light_set_shadow(sun, true);
	const RenderSceneData data = f.cull_scene();
	REQUIRE(data.geometry.size() == 1);
	REQUIRE(data.shadow_geometry.size() == 1);
	CHECK(data.shadow_geometry[0].instance == behind);
	f.rs->light_set_shadow_caster_mask(sun, 0u);
	CHECK(f.cull_scene().shadow_geometry.empty());
}

TEST_CASE("[SceneCull] cast_shadow: Off leaves the shadow casters, Shadows Only reaches the renderer flagged, bad values are refused") {
	CullFixture f;
	RID front = f.add_instance(f.mesh, at(Vector3(0, 0, -5)));
	RID behind = f.add_instance(f.mesh, at(Vector3(0, 0, 5))); // Behind the camera: only a shadow caster.
	RID sun;
	f.add_light(RS::LIGHT_DIRECTIONAL, 1.0f, Transform3D(), &sun);
	f.rs->light_set_shadow(sun, true);
	RenderSceneData data = f.cull_scene();
	REQUIRE(data.geometry.size() == 1);
	CHECK(data.geometry[0].cast_shadows == RS::SHADOW_CASTING_SETTING_ON); // Godot's default.
	REQUIRE(data.shadow_geometry.size() == 1);

	f.rs->instance_geometry_set_cast_shadows_setting(behind, RS::SHADOW_CASTING_SETTING_OFF);
	f.rs->instance_geometry_set_cast_shadows_setting(front, RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY);
	data = f.cull_scene();
	CHECK(data.shadow_geometry.empty()); // Off: not a caster of the sun.
	REQUIRE(data.geometry.size() == 1);
	CHECK(data.geometry[0].cast_shadows == RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY); // The colour passes skip it.

	{
		ErrorCatcher errors;
		f.rs->instance_geometry_set_cast_shadows_setting(front, RS::ShadowCastingSetting(7));
		CHECK(errors.messages.size() == 1);
		CHECK(errors.contains("cast_shadow must be 0..3"));
	}
	CHECK(f.cull_scene().geometry[0].cast_shadows == RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY); // Unchanged.

	// The node property reaches the server (GeometryInstance3D::cast_shadow).
	GeometryInstance3D node;
	node.set_base(f.mesh);
	f.rs->instance_set_scenario(node.get_instance(), f.scenario);
	f.rs->instance_set_transform(node.get_instance(), at(Vector3(0, 0, 6)));
	CHECK(f.cull_scene().shadow_geometry.size() == 1);
	node.set_cast_shadows_setting(GeometryInstance3D::SHADOW_CASTING_SETTING_OFF);
	CHECK(f.cull_scene().shadow_geometry.empty());
	f.rs->instance_set_scenario(node.get_instance(), RID());
}

TEST_CASE("[SceneCull] the spot cone bound culls a spot pointing away whose range sphere is visible") {
	CullFixture f;
	// Spot 2 m behind the camera with range 5: its sphere reaches into the frustum.
	// Pointing away (+Z, a rotation of 180 degrees about Y), the 30-degree cone stays behind the near plane.
	const Transform3D away(Basis::from_axis_angle(Vector3(0, 1, 0), real_t(Math::PI)), Vector3(0, 0, 2));
	RID spot;
	RID spot_away = f.add_light(RS::LIGHT_SPOT, 5.0f, away, &spot);
	f.rs->light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 30.0f);

	const std::vector<Plane> planes = Projection::create_perspective(60.0f, 2.0f, 0.1f, 100.0f).get_projection_planes(Transform3D());
	REQUIRE_MESSAGE(!RendererSceneCull::is_sphere_culled(planes, Vector3(0, 0, 2), 5.0f), "The range sphere alone must not be enough to cull this spot.");

	RenderSceneData data = f.cull_scene();
	CHECK(f.cull->get_last_cull_stats().lights_culled == 1);
	CHECK(data.lights.empty());

	SUBCASE("the same spot pointing at the frustum is visible") {
		f.rs->instance_set_transform(spot_away, at(Vector3(0, 0, 2)));
		data = f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().lights_visible == 1);
		REQUIRE(data.lights.size() == 1);
		CHECK(data.lights[0].type == RS::LIGHT_SPOT);
	}
	SUBCASE("a cone wider than 90 degrees reaches behind its apex") {
		f.rs->light_set_param(spot, RS::LIGHT_PARAM_SPOT_ANGLE, 150.0f);
		f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().lights_visible == 1);
	}
}

TEST_CASE("[SceneCull] cone test against a single plane matches the analytic distance") {
	// Plane z = 0 with outward normal +Z. A cone with apex at z = 1 pointing along -Z with range 2 reaches z = -1.
	const std::vector<Plane> plane = { Plane(Vector3(0, 0, 1), 0.0f) };
	CHECK_FALSE(RendererSceneCull::is_cone_culled(plane, Vector3(0, 0, 1), Vector3(0, 0, -1), 2.0f, 10.0f));
	CHECK(RendererSceneCull::is_cone_culled(plane, Vector3(0, 0, 3), Vector3(0, 0, -1), 2.0f, 10.0f));
	// Sideways axis (+X), half-angle 30: the lowest point is at z = 1 - 2 * sin(30) = 0 -> touching, not culled;
	// at apex z = 1.01 it is culled.
	CHECK_FALSE(RendererSceneCull::is_cone_culled(plane, Vector3(0, 0, 0.99f), Vector3(1, 0, 0), 2.0f, 30.0f));
	CHECK(RendererSceneCull::is_cone_culled(plane, Vector3(0, 0, 1.01f), Vector3(1, 0, 0), 2.0f, 30.0f));
}

TEST_CASE("[SceneCull] directional lights are never culled, hidden and masked instances are skipped") {
	CullFixture f;
	RID sun = f.add_light(RS::LIGHT_DIRECTIONAL, 1.0f, at(Vector3(0, 0, 1000)));
	RID hidden = f.add_instance(f.mesh, at(Vector3(0, 0, -5)));
	f.rs->instance_set_visible(hidden, false);
	RID masked = f.add_instance(f.mesh, at(Vector3(0, 0, -6)));
	f.rs->instance_set_layer_mask(masked, 1 << 3);
	f.rs->camera_set_cull_mask(f.camera, 1);

	RenderSceneData data = f.cull_scene();
	REQUIRE(data.directional_lights.size() == 1);
	CHECK(data.directional_lights[0].instance == sun);
	CHECK(data.directional_lights[0].type == RS::LIGHT_DIRECTIONAL);
	CHECK(f.cull->get_last_cull_stats().directional_lights == 1);
	CHECK(data.geometry.empty());

	f.rs->camera_set_cull_mask(f.camera, 1 | (1 << 3));
	f.rs->instance_set_visible(hidden, true);
	data = f.cull_scene();
	CHECK(data.geometry.size() == 2);
	CHECK(data.geometry[1].layer_mask == (1u << 3));
}

TEST_CASE("[SceneCull] RenderSceneData for a simple setup") {
	CullFixture f;
	const Transform3D cam_transform(Basis::from_axis_angle(Vector3(0, 1, 0), 0.3f), Vector3(1, 2, 3));
	f.rs->camera_set_transform(f.camera, cam_transform);
	const Transform3D mesh_transform = cam_transform * at(Vector3(0, 0, -4));
	RID instance = f.add_instance(f.mesh, mesh_transform);
	RID material = f.rs->material_create();
	f.rs->instance_geometry_set_material_override(instance, material);

	RenderSceneData data = f.cull_scene();
	CHECK(data.cam_transform.is_equal_approx(cam_transform));
	CHECK(data.cam_projection.is_equal_approx(Projection::create_perspective(60.0f, 2.0f, 0.1f, 100.0f)));
	CHECK(data.cam_projection.get_aspect() == doctest::Approx(2.0));
	CHECK(data.z_near == doctest::Approx(0.1));
	CHECK(data.z_far == doctest::Approx(100.0));
	CHECK(data.viewport_width == 64);
	CHECK(data.viewport_height == 32);
	REQUIRE(data.geometry.size() == 1);
	CHECK(data.geometry[0].transform.is_equal_approx(mesh_transform));
	CHECK(data.geometry[0].material_override == material);
	CHECK(data.geometry[0].aabb.is_equal_approx(mesh_transform.xform(AABB(Vector3(-0.5f, -0.5f, 0), Vector3(1, 1, 0)))));

	SUBCASE("no environment: default clear colour, no ambient") {
		CHECK_FALSE(data.environment.has_environment);
		CHECK(data.environment.bg_color.is_equal_approx(Color(0.3f, 0.3f, 0.3f)));
		CHECK(data.environment.ambient_energy == 0.0f);
	}
	SUBCASE("scenario environment, then a camera override") {
		RID env = f.rs->environment_create();
		f.rs->environment_set_background(env, RS::ENV_BG_COLOR);
		f.rs->environment_set_bg_color(env, Color(0.1f, 0.2f, 0.3f));
		f.rs->environment_set_bg_energy(env, 2.0f);
		f.rs->scenario_set_environment(f.scenario, env);
		data = f.cull_scene();
		CHECK(data.environment.has_environment);
		CHECK(data.environment.background == RS::ENV_BG_COLOR);
		CHECK(data.environment.bg_color.is_equal_approx(Color(0.1f, 0.2f, 0.3f)));
		CHECK(data.environment.bg_energy == doctest::Approx(2.0));
		CHECK_MESSAGE(data.environment.ambient_color.is_equal_approx(Color(0.1f, 0.2f, 0.3f)), "Ambient source BG takes the background colour.");
		CHECK(data.environment.ambient_energy == doctest::Approx(2.0));

		RID cam_env = f.rs->environment_create();
		f.rs->environment_set_ambient_light(cam_env, Color(1, 0.5f, 0), RS::ENV_AMBIENT_SOURCE_COLOR, 0.25f);
		f.rs->camera_set_environment(f.camera, cam_env);
		data = f.cull_scene();
		CHECK(data.environment.background == RS::ENV_BG_CLEAR_COLOR);
		CHECK(data.environment.bg_color.is_equal_approx(Color(0.3f, 0.3f, 0.3f)));
		CHECK(data.environment.ambient_color.is_equal_approx(Color(1, 0.5f, 0)));
		CHECK(data.environment.ambient_energy == doctest::Approx(0.25));

		f.rs->free(cam_env);
		data = f.cull_scene();
		CHECK_MESSAGE(data.environment.bg_color.is_equal_approx(Color(0.1f, 0.2f, 0.3f)), "Freeing the camera environment falls back to the scenario's.");
		f.rs->free(env);
		data = f.cull_scene();
		CHECK_FALSE(data.environment.has_environment);
	}
	SUBCASE("freed material override and freed base are dropped") {
		f.rs->free(material);
		data = f.cull_scene();
		REQUIRE(data.geometry.size() == 1);
		CHECK(data.geometry[0].material_override == RID());
		RID mesh2 = f.rs->mesh_create();
		f.rs->mesh_add_surface(mesh2, make_quad(1));
		f.rs->instance_set_base(instance, mesh2);
		f.rs->free(mesh2);
		data = f.cull_scene();
		CHECK(data.geometry.empty());
		CHECK(f.cull->instance_get_base_type(instance) == RS::INSTANCE_NONE);
	}
	if (RSG::material_storage->owns_material(material)) {
		f.rs->free(material);
	}
}

TEST_CASE("[SceneCull] removing instances keeps the scenario's order and count; freeing a base touches its users only") {
	CullFixture f;
	// 64 quads in a row in front of the camera (x = index), each its own depth so order is visible.
	std::vector<RID> instances;
	for (int i = 0; i < 64; i++) {
		instances.push_back(f.add_instance(f.mesh, at(Vector3(0.01f * i, 0, -5))));
	}
	CHECK(f.cull->scenario_get_instance_count(f.scenario) == 64);
	// Remove every third one (more than half of the slots are compacted away along the way).
	std::vector<RID> kept;
	for (int i = 0; i < 64; i++) {
		if (i % 3 == 0 || i > 40) {
			f.rs->instance_set_scenario(instances[i], RID());
		} else {
			kept.push_back(instances[i]);
		}
	}
	CHECK(f.cull->scenario_get_instance_count(f.scenario) == int(kept.size()));
	RenderSceneData data = f.cull_scene();
	REQUIRE(data.geometry.size() == kept.size());
	for (size_t i = 0; i < kept.size(); i++) {
		CAPTURE(i);
		CHECK(data.geometry[i].transform.origin.x == doctest::Approx(0.01f * float(i / 2 * 3 + 1 + i % 2))); // Insertion order.
	}
	// Back in: appended at the end.
	f.rs->instance_set_scenario(instances[0], f.scenario);
	data = f.cull_scene();
	REQUIRE(data.geometry.size() == kept.size() + 1);
	CHECK(data.geometry.back().transform.origin.x == doctest::Approx(0.0f));

	// Two meshes; freeing one drops exactly its instances, also after a base change.
	RID other = f.rs->mesh_create();
	f.rs->mesh_add_surface(other, make_quad(0.5f));
	f.rs->instance_set_base(kept[0], other);
	f.rs->instance_set_base(kept[1], other);
	f.rs->instance_set_base(kept[1], f.mesh); // Moved back: no longer a user of 'other'.
	f.rs->free(other);
	CHECK(f.cull->instance_get_base_type(kept[0]) == RS::INSTANCE_NONE);
	CHECK(f.cull->instance_get_base_type(kept[1]) == RS::INSTANCE_MESH);
	data = f.cull_scene();
	CHECK(data.geometry.size() == kept.size()); // kept[0] has no base now; instances[0] came back.
}

TEST_CASE("[RenderingServer] draw renders active viewports through the scene renderer") {
	CullFixture f;
	RasterizerSceneDummy *scene = f.server.rasterizer->get_scene_dummy();
	f.add_instance(f.mesh, at(Vector3(0, 0, -5)));
	RID viewport = f.rs->viewport_create();
	f.rs->viewport_set_size(viewport, 64, 32);
	f.rs->viewport_attach_camera(viewport, f.camera);
	f.rs->viewport_set_scenario(viewport, f.scenario);
	f.rs->viewport_set_debug_draw(viewport, RS::VIEWPORT_DEBUG_DRAW_CLUSTER_OMNI_LIGHTS);

	f.rs->draw();
	CHECK(scene->get_render_count() == 1);
	CHECK(scene->get_last_scene_data().geometry.size() == 1);
	CHECK(scene->get_last_scene_data().viewport_width == 64);
	CHECK(scene->get_last_scene_data().debug_draw == RS::VIEWPORT_DEBUG_DRAW_CLUSTER_OMNI_LIGHTS);
	const Image image = f.rs->viewport_get_texture_data(viewport);
	CHECK(image.get_width() == 64);
	CHECK(image.get_height() == 32);
	CHECK(image.get_pixel(10, 10).is_equal_approx(Color(0, 0, 0, 1)));
	CHECK(f.rs->get_frame_profile().empty());

	f.rs->set_debug_force_all_lights(true);
	CHECK(scene->is_debug_force_all_lights());

	f.rs->viewport_set_active(viewport, false);
	f.rs->draw();
	CHECK_MESSAGE(scene->get_render_count() == 1, "An inactive viewport is not rendered.");
	f.rs->viewport_set_active(viewport, true);
	f.rs->free(f.camera);
	f.camera = f.rs->camera_create();
	f.rs->draw();
	CHECK_MESSAGE(scene->get_render_count() == 1, "A viewport whose camera was freed is not rendered.");
	f.rs->free(viewport);
}

} // namespace TestRendererSceneCull
