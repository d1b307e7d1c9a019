/**************************************************************************/
/*  test_area_light_cull.cpp                                              */
/**************************************************************************/
/* godot-area: area lights in the server and in scene culling: the        */
/* culling sphere of thesis eq. 5.1 (R = r + sqrt(a^2 + b^2) / 2), a      */
/* light whose centre is outside the frustum but whose rectangle reaches  */
/* into it, the storage bound and version, and RenderSceneData entries of */
/* type LIGHT_AREA. Dummy (CPU-only) backend.                             */

#include "servers/rendering/renderer_scene_cull.h"

#include "core/error/error_macros.h"
#include "servers/rendering/dummy/rasterizer_dummy.h"
#include "servers/rendering/rendering_server_default.h"
#include "servers/rendering/rendering_server_globals.h"
#include "servers/rendering/storage/light_storage.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestAreaLightCull {

struct SilenceErrors {
	std::vector<String> messages;
	ErrorHandlerList handler;
	bool contains(const String &p_text) const {
		for (const String &m : messages) {
			if (m.find(p_text) != String::npos) {
				return true;
			}
		}
		return false;
	}
	SilenceErrors() {
		handler.callback = [this](ErrorHandlerType, const String &p_text) { messages.push_back(p_text); };
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~SilenceErrors() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
};

// Camera at the origin looking down -Z, 60 degrees vertical, 64x32 viewport, near 0.1, far 100.
struct AreaCullFixture {
	RasterizerDummy *rasterizer = new RasterizerDummy;
	RenderingServerDefault *server = new RenderingServerDefault(rasterizer);
	RS *rs = server;
	RendererSceneCull *cull = server->get_scene_cull();
	RID camera = rs->camera_create();
	RID scenario = rs->scenario_create();
	std::vector<RID> owned;

	RID add_instance(RID p_base, const Transform3D &p_transform) {
		RID instance = rs->instance_create();
		rs->instance_set_base(instance, p_base);
		rs->instance_set_transform(instance, p_transform);
		rs->instance_set_scenario(instance, scenario);
		owned.push_back(instance);
		return instance;
	}
	// An area light of the given range and size; returns the instance (r_light: the light resource).
	RID add_area(float p_range, const Vector2 &p_size, const Transform3D &p_transform, RID *r_light = nullptr) {
		RID light = rs->area_light_create();
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, p_range);
		rs->light_area_set_size(light, p_size);
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
	std::vector<Plane> frustum_planes() const {
		Projection projection = Projection::create_perspective(60.0f, 2.0f, 0.1f, 100.0f);
		return projection.get_projection_planes(Transform3D());
	}
	AreaCullFixture() {
		rs->camera_set_perspective(camera, 60.0f, 0.1f, 100.0f);
	}
	~AreaCullFixture() {
		for (auto it = owned.rbegin(); it != owned.rend(); ++it) {
			rs->free(*it);
		}
		rs->free(scenario);
		rs->free(camera);
		delete server;
	}
};

TEST_CASE("[AreaLight3D][SceneCull] the culling radius is range plus half the diagonal (thesis eq. 5.1)") {
	CHECK(RendererLightStorage::compute_area_light_cull_radius(5.0f, Vector2(3, 4)) == doctest::Approx(5.0 + 2.5));
	CHECK(RendererLightStorage::compute_area_light_cull_radius(2.0f, Vector2(0, 0)) == doctest::Approx(2.0));
	CHECK(RendererLightStorage::compute_area_light_cull_radius(0.0f, Vector2(6, 8)) == doctest::Approx(5.0));
	// Every point within `range` of the rectangle is inside the sphere: the farthest such point is a
	// corner pushed out by the range along the diagonal.
	const float r = 1.5f;
	const Vector2 size(4, 1);
	const float R = RendererLightStorage::compute_area_light_cull_radius(r, size);
	const Vector3 corner(size.x * 0.5f, size.y * 0.5f, 0);
	CHECK((corner + corner.normalized() * r).length() == doctest::Approx(R));
}

TEST_CASE("[AreaLight3D][SceneCull] a light whose centre is outside the frustum but whose rectangle reaches in is kept") {
	AreaCullFixture f;
	// The frustum's right plane at depth 10 is at x = 10 * tan(30 deg) * aspect 2 = 11.55. The light centre at
	// x = 16 is 2.92 outside it along the plane's outward normal (0.655, 0, 0.756): more than the range 0.5,
	// less than the eq. 5.1 radius 0.5 + sqrt(12^2 + 0.5^2) / 2 = 6.5.
	const Transform3D wide_xform(Basis(), Vector3(16, 0, -10));
	RID wide_light;
	RID wide = f.add_area(0.5f, Vector2(12, 0.5f), wide_xform, &wide_light); // Half diagonal 6.01: reaches in.
	RID far_light;
	f.add_area(0.5f, Vector2(12, 0.5f), Transform3D(Basis(), Vector3(40, 0, -10)), &far_light); // Far to the right.

	// The test is meaningful: the range sphere alone (an omni light's bound) would be culled.
	const std::vector<Plane> planes = f.frustum_planes();
	CHECK_MESSAGE(RendererSceneCull::is_sphere_culled(planes, wide_xform.origin, 0.5f), "the centre and its range sphere are outside the frustum");
	CHECK_FALSE(RendererSceneCull::is_sphere_culled(planes, wide_xform.origin, RendererLightStorage::compute_area_light_cull_radius(0.5f, Vector2(12, 0.5f))));

	RenderSceneData data = f.cull_scene();
	const RendererSceneCull::CullStats &stats = f.cull->get_last_cull_stats();
	CHECK(stats.lights_visible == 1);
	CHECK(stats.lights_culled == 1);
	REQUIRE(data.lights.size() == 1);
	CHECK(data.lights[0].instance == wide);
	CHECK(data.lights[0].light == wide_light);
	CHECK_MESSAGE(data.lights[0].type == RS::LIGHT_AREA, "area lights reach the renderer with their own type");
	CHECK(data.lights[0].transform.origin.is_equal_approx(Vector3(16, 0, -10)));
	// World bound = the node's box (Listing A.1) moved to the instance.
	CHECK(data.lights[0].aabb.is_equal_approx(AABB(Vector3(16 - 6.5f, -0.75f, -10.5f), Vector3(13, 1.5f, 0.5f))));

	SUBCASE("shrinking the rectangle culls it") {
		f.rs->light_area_set_size(wide_light, Vector2(1, 0.5f));
		data = f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().lights_visible == 0);
		CHECK(data.lights.empty());
	}
	SUBCASE("a larger range brings the far light back") {
		f.rs->light_set_param(far_light, RS::LIGHT_PARAM_RANGE, 30.0f);
		data = f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().lights_visible == 2);
	}
	SUBCASE("behind the camera, out of reach, it is culled") {
		f.rs->instance_set_transform(wide, Transform3D(Basis(), Vector3(0, 0, 10)));
		data = f.cull_scene();
		CHECK(f.cull->get_last_cull_stats().lights_visible == 0);
	}
}

TEST_CASE("[AreaLight3D][SceneCull] storage bound, validation and version of area lights") {
	AreaCullFixture f;
	RS *rs = f.rs;
	RID light = rs->area_light_create();
	REQUIRE(light.is_valid());
	CHECK(rs->light_get_type(light) == RS::LIGHT_AREA);
	CHECK(rs->light_area_get_size(light) == Vector2(1, 1));
	CHECK(rs->light_area_get_normalize_energy(light));
	CHECK(rs->light_area_get_shading_method(light) == RS::LIGHT_AREA_SHADING_LTC);

	rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, 2.0f);
	rs->light_area_set_size(light, Vector2(3, 1));
	CHECK(rs->light_get_aabb(light).is_equal_approx(AABB(Vector3(-3.5f, -2.5f, -2), Vector3(7, 5, 2))));
	CHECK(rs->light_get_aabb(light).is_equal_approx(RendererLightStorage::compute_light_aabb(RS::LIGHT_AREA, 2.0f, 45.0f, Vector2(3, 1))));

	const uint64_t v0 = RSG::light_storage->light_get_version(light);
	rs->light_area_set_size(light, Vector2(3, 1));
	CHECK_MESSAGE(RSG::light_storage->light_get_version(light) == v0, "an unchanged size does not bump the version");
	rs->light_area_set_size(light, Vector2(2, 1));
	CHECK_MESSAGE(RSG::light_storage->light_get_version(light) > v0, "a new size changes the culling bound: version bump");
	const uint64_t v1 = RSG::light_storage->light_get_version(light);
	rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, 3.0f);
	CHECK(RSG::light_storage->light_get_version(light) > v1);
	const uint64_t v2 = RSG::light_storage->light_get_version(light);
	rs->light_area_set_normalize_energy(light, false);
	CHECK_FALSE(rs->light_area_get_normalize_energy(light));
	CHECK_MESSAGE(RSG::light_storage->light_get_version(light) == v2, "energy normalisation does not affect culling");

	{
		SilenceErrors errors;
		rs->light_area_set_size(light, Vector2(-1, 2));
		CHECK(errors.contains("must not be negative"));
		rs->light_area_set_size(light, Vector2(NAN, 2));
		rs->light_area_set_size(light, Vector2(INFINITY, 2));
		CHECK(errors.contains("finite"));
		CHECK(rs->light_area_get_size(light) == Vector2(2, 1));
		rs->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, -1.0f);
		CHECK(errors.contains("LIGHT_PARAM_ATTENUATION"));
		CHECK(rs->light_get_param(light, RS::LIGHT_PARAM_ATTENUATION) == doctest::Approx(1.0));
		rs->light_area_set_shading_method(light, RS::LightAreaShadingMethod(RS::LIGHT_AREA_SHADING_MAX));
		CHECK(rs->light_area_get_shading_method(light) == RS::LIGHT_AREA_SHADING_LTC);
		// Area calls on a light of another type are refused.
		RID omni = rs->omni_light_create();
		rs->light_area_set_size(omni, Vector2(4, 4));
		CHECK(errors.contains("not an area light"));
		rs->free(omni);
		// Invalid RIDs give neutral values.
		CHECK(rs->light_area_get_size(RID()) == Vector2());
	}
	// Omni lights keep their signed attenuation.
	RID omni = rs->omni_light_create();
	rs->light_set_param(omni, RS::LIGHT_PARAM_ATTENUATION, -1.0f);
	CHECK(rs->light_get_param(omni, RS::LIGHT_PARAM_ATTENUATION) == doctest::Approx(-1.0));
	rs->free(omni);
	rs->free(light);
}

} // namespace TestAreaLightCull
