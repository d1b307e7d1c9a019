/**************************************************************************/
/*  test_area_shadow_casters.cpp                                          */
/**************************************************************************/
/* godot-area: area shadows through the RenderingServer (lavapipe,        */
/* validation on): casters come from the scene cull (an occluder the      */
/* camera does not see still shadows the visible floor, and moving it     */
/* redraws the maps), the per-viewport atlas size (RS                     */
/* area_shadow_atlas_set_size, with its validation), the "area_shadows"  */
/* profiler entry, the oriented influence-box test, and the inspector     */
/* visibility of the area_shadow_* properties.                            */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "modules/benchmark/penumbra_scene.h"
#include "scene/3d/light_3d.h"
#include "servers/rendering/renderer_rd/renderer_compositor_rd.h"
#include "servers/rendering/renderer_scene_cull.h"
#include "servers/rendering/rendering_server_default.h"
#include "servers/rendering/rendering_server_globals.h"
#include "tests/scene/scene_test_fixture.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

namespace TestAreaShadowCasters {

// Axis-aligned box of half extents p_half around the origin (clockwise front faces seen from outside).
static RS::SurfaceData make_box(const Vector3 &p_half) {
	return PenumbraScene::make_box(Vector3(), p_half);
}

static Basis facing_down() {
	return Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
}

static bool has_pass(const std::vector<std::pair<String, double>> &p_profile, const String &p_name) {
	for (const std::pair<String, double> &e : p_profile) {
		if (e.first == p_name) {
			return e.second >= 0.0;
		}
	}
	return false;
}

// A floor, an area light 2 m above it and an occluder at 1.2 m; the camera is 0.6 m above the floor,
// looking down, so the occluder is behind it (culled from the camera's geometry).
struct ServerScene {
	RendererCompositorRD *compositor = nullptr;
	RenderingServerDefault *rs = nullptr;
	RID floor_mesh, box_mesh, mat, light, env, scenario, floor_instance, box_instance, light_instance, camera, viewport;
	static constexpr int W = 24;
	static constexpr int H = 24;

	bool init() {
		compositor = new RendererCompositorRD;
		if (!compositor->initialize(64)) {
			delete compositor;
			compositor = nullptr;
			return false;
		}
		rs = new RenderingServerDefault(compositor);
		compositor->get_render_forward_clustered()->area_shadow_atlas_set_size(512, 4); // Small default.
		floor_mesh = rs->mesh_create();
		rs->mesh_add_surface(floor_mesh, make_box(Vector3(4.0f, 0.01f, 4.0f)));
		box_mesh = rs->mesh_create();
		rs->mesh_add_surface(box_mesh, make_box(Vector3(0.3f, 0.3f, 0.3f)));
		mat = rs->material_create();
		RS::MaterialParams mp;
		mp.albedo = Color(0.8f, 0.8f, 0.8f, 1.0f);
		mp.specular = 0.0f;
		mp.specular_mode = RS::MATERIAL_SPECULAR_DISABLED;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		mp.cull_back = false;
		rs->material_set_params(mat, mp);
		rs->mesh_surface_set_material(floor_mesh, 0, mat);
		rs->mesh_surface_set_material(box_mesh, 0, mat);
		light = rs->area_light_create();
		rs->light_area_set_size(light, Vector2(1.0f, 1.0f));
		rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, 2.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, 10.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 2.0f);
		rs->light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, 1.0f);
		rs->light_area_set_shadow_grid(light, 2);
		env = rs->environment_create();
		rs->environment_set_background(env, RS::ENV_BG_COLOR);
		rs->environment_set_bg_color(env, Color(0, 0, 0, 1));
		rs->environment_set_ambient_light(env, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
		scenario = rs->scenario_create();
		rs->scenario_set_environment(scenario, env);
		floor_instance = rs->instance_create();
		rs->instance_set_base(floor_instance, floor_mesh);
		rs->instance_set_scenario(floor_instance, scenario);
		box_instance = rs->instance_create();
		rs->instance_set_base(box_instance, box_mesh);
		rs->instance_set_scenario(box_instance, scenario);
		rs->instance_set_transform(box_instance, Transform3D(Basis(), Vector3(0, 1.2f, 0)));
		light_instance = rs->instance_create();
		rs->instance_set_base(light_instance, light);
		rs->instance_set_scenario(light_instance, scenario);
		rs->instance_set_transform(light_instance, Transform3D(facing_down(), Vector3(0, 2.0f, 0)));
		camera = rs->camera_create();
		rs->camera_set_perspective(camera, 60.0f, 0.05f, 20.0f);
		rs->camera_set_transform(camera, Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, 0.6f, 0)));
		viewport = rs->viewport_create();
		rs->viewport_set_size(viewport, W, H);
		rs->viewport_attach_camera(viewport, camera);
		rs->viewport_set_scenario(viewport, scenario);
		return true;
	}
	float centre() {
		rs->draw();
		Image img = rs->viewport_get_texture_data(viewport);
		return img.get_width() == W ? img.get_pixel(W / 2, H / 2).r : -1.0f;
	}
	AreaShadowRendererRD &shadows() { return compositor->get_render_forward_clustered()->get_area_shadow_renderer(); }
	~ServerScene() {
		if (!rs) {
			return;
		}
		for (RID r : { viewport, camera, light_instance, box_instance, floor_instance, scenario, env, light, mat, box_mesh, floor_mesh }) {
			rs->free(r);
		}
		delete rs; // Deletes the compositor.
	}
};

TEST_CASE("[AreaLight3D][Shadows] an off-screen occluder between the light and a visible floor casts a shadow; moving it redraws") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ServerScene s;
		REQUIRE(s.init());
		float open = s.centre();
		REQUIRE(open > 0.01f);
		CHECK(RSG::scene->get_last_cull_stats().geometry_visible == 1); // The camera sees the floor only.
		CHECK(RSG::scene->get_last_cull_stats().area_shadow_casters == 0); // Shadows off: no caster list.
		CHECK_FALSE(has_pass(s.rs->get_frame_profile(), "area_shadows")); // No shadowed light: no entry.
		CHECK(has_pass(s.rs->get_frame_profile(), "depth_prepass"));

		s.rs->light_set_shadow(s.light, true);
		float shadowed = s.centre();
		const RendererSceneCull::CullStats &stats = RSG::scene->get_last_cull_stats();
		CHECK(stats.geometry_visible == 1);
		CHECK(stats.area_shadow_casters == 2);
		CHECK(stats.area_shadow_casters_offscreen == 1);
		MESSAGE("floor centre: open ", open, ", with the off-screen occluder ", shadowed);
		CHECK(shadowed < 0.1f * open); // Umbra: the occluder hides the whole light from the centre.
		CHECK(s.shadows().get_last_draw_count() == 4);

		// The profiler lists the shadow pass on its own.
		std::vector<std::pair<String, double>> profile = s.rs->get_frame_profile();
		CHECK(has_pass(profile, "area_shadows"));
		CHECK(has_pass(profile, "depth_prepass"));
		CHECK(has_pass(profile, "opaque"));
		REQUIRE(profile.size() >= 2);
		CHECK(profile[0].first == "area_shadows"); // Recorded first (the maps precede the scene passes).

		// Static: nothing redrawn. The occluder moves (still off-screen, in range): the maps are redrawn.
		s.centre();
		CHECK(s.shadows().get_last_draw_count() == 0);
		s.rs->instance_set_transform(s.box_instance, Transform3D(Basis(), Vector3(0.05f, 1.2f, 0)));
		s.centre();
		CHECK(s.shadows().get_last_draw_count() == 4);
		// Out of the light's influence box: no longer a caster, the floor is lit again.
		s.rs->instance_set_transform(s.box_instance, Transform3D(Basis(), Vector3(40.0f, 1.2f, 0)));
		float moved_away = s.centre();
		CHECK(RSG::scene->get_last_cull_stats().area_shadow_casters == 1);
		CHECK(s.shadows().get_last_draw_count() == 4);
		CHECK(moved_away == doctest::Approx(open).epsilon(0.01));
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Shadows] RenderingServer reports ADAPTIVE tests until the subdivision settles") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ServerScene s;
		REQUIRE(s.init());
		s.rs->light_set_shadow(s.light, true);
		s.centre();
		CHECK(s.rs->get_frame_area_shadow_tests() == 0); // FIXED: nothing to refine.
		s.rs->light_area_set_shadow_mode(s.light, RS::LIGHT_AREA_SHADOW_ADAPTIVE);
		// Look at the penumbra beside the occluder, tested at full resolution.
		s.rs->camera_set_transform(s.camera, Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0.6f, 0.6f, 0)));
		REQUIRE(s.shadows().set_adaptive_reprojection_divisor(1));
		s.centre();
		s.centre();
		CHECK(s.rs->get_frame_area_shadow_tests() > 0); // The root quad's first answers are being tested.
		int frames = 0;
		while (s.rs->get_frame_area_shadow_tests() > 0 && frames < 32) {
			s.centre();
			frames++;
		}
		MESSAGE("ADAPTIVE settled after ", frames, " more frames with ", s.shadows().light_get_shadow_map_count(s.light_instance), " maps");
		CHECK(frames < 32);
		CHECK(s.shadows().light_get_shadow_map_count(s.light_instance) > 4); // It refined before settling.
		for (int i = 0; i < 3; i++) {
			s.centre();
			CHECK(s.rs->get_frame_area_shadow_tests() == 0); // Settled lights are not tested again.
		}
		// The camera moves: the light is tested again (with the 16-tile atlas full, prune tests only: its
		// leaves are tested until idle so that their parents can be).
		s.rs->camera_set_transform(s.camera, Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0.7f, 0.6f, 0)));
		s.centre();
		CHECK(s.rs->get_frame_area_shadow_tests() > 0);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Shadows] area_shadow_atlas_set_size sizes each viewport's atlas and rejects bad values") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ServerScene s;
		REQUIRE(s.init());
		s.rs->light_set_shadow(s.light, true);
		s.rs->area_shadow_atlas_set_size(s.viewport, 1024, 8);
		CHECK(s.rs->area_shadow_atlas_get_size(s.viewport) == 1024);
		CHECK(s.rs->area_shadow_atlas_get_subdivision(s.viewport) == 8);
		{
			SceneTest::ErrorCatcher errors;
			s.rs->area_shadow_atlas_set_size(s.viewport, 1000, 8);
			CHECK(errors.contains("power of two"));
			s.rs->area_shadow_atlas_set_size(s.viewport, 128, 2);
			s.rs->area_shadow_atlas_set_size(s.viewport, 32768, 2);
			s.rs->area_shadow_atlas_set_size(s.viewport, 1024, 0);
			CHECK(errors.contains("subdivision"));
			s.rs->area_shadow_atlas_set_size(s.viewport, 1024, 65);
			s.rs->area_shadow_atlas_set_size(s.viewport, 256, 32);
			CHECK(errors.contains("at least 16 px"));
			s.rs->area_shadow_atlas_set_size(RID(), 1024, 8);
			CHECK(errors.contains("invalid viewport"));
			CHECK(errors.messages.size() == 7);
		}
		CHECK(s.rs->area_shadow_atlas_get_size(s.viewport) == 1024); // Old values kept.
		CHECK(s.rs->area_shadow_atlas_get_subdivision(s.viewport) == 8);

		// A second viewport keeps the renderer's default: two atlases of different sizes.
		RID second = s.rs->viewport_create();
		s.rs->viewport_set_size(second, 8, 8);
		s.rs->viewport_attach_camera(second, s.camera);
		s.rs->viewport_set_scenario(second, s.scenario);
		s.rs->draw();
		CHECK(s.shadows().get_atlas_count() == 2);
		CHECK(s.shadows().get_atlas().get_size() == 512); // The second viewport's (drawn last): the default.
		CHECK(s.shadows().get_atlas().get_subdivision() == 4);
		s.rs->viewport_set_active(second, false);
		s.rs->draw();
		CHECK(s.shadows().get_atlas().get_size() == 1024);
		CHECK(s.shadows().get_atlas().get_subdivision() == 8);
		CHECK(s.shadows().get_atlas().light_get_tile_count(s.light_instance.get_id()) == 4);
		s.rs->free(second); // Frees its render target and with it its atlas.
		CHECK(s.shadows().get_atlas_count() == 1);
		s.rs->area_shadow_atlas_set_size(s.viewport, 0, 0); // Back to the default.
		CHECK(s.rs->area_shadow_atlas_get_size(s.viewport) == 0);
		s.rs->draw();
		CHECK(s.shadows().get_atlas().get_size() == 512);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RendererSceneCull] the area light influence box test follows the light's orientation") {
	// Light 1 x 1, range 1: box (-1.5..1.5, -1.5..1.5, -1..0) in light space, rotated 45 degrees about Y.
	const AABB box(Vector3(-1.5f, -1.5f, -1.0f), Vector3(3.0f, 3.0f, 1.0f));
	const Transform3D world_from_light(Basis::from_axis_angle(Vector3(0, 1, 0), float(Math::PI) * 0.25f), Vector3());
	const AABB world = world_from_light.xform(box);
	// A small bound in a corner of the world AABB but outside the rotated box.
	const AABB corner(world.position + Vector3(0.01f, 1.0f, 0.01f), Vector3(0.05f, 0.05f, 0.05f));
	CHECK(world.intersects(corner));
	CHECK_FALSE(RendererSceneCull::area_light_box_intersects(world_from_light, box, corner));
	// Just in front of the light's centre: inside. Behind the light (local z > 0): outside.
	CHECK(RendererSceneCull::area_light_box_intersects(world_from_light, box, AABB(world_from_light.xform(Vector3(0, 0, -0.5f)), Vector3(0.1f, 0.1f, 0.1f))));
	CHECK_FALSE(RendererSceneCull::area_light_box_intersects(world_from_light, box, AABB(world_from_light.xform(Vector3(0, 0, 0.6f)), Vector3(0.1f, 0.1f, 0.1f))));
}

static uint32_t usage_of(const Object *p_object, const String &p_name) {
	std::vector<PropertyInfo> list;
	p_object->get_property_list(&list);
	for (const PropertyInfo &p : list) {
		if (p.name == p_name) {
			return p.usage;
		}
	}
	return 0xFFFFFFFFu;
}

TEST_CASE("[AreaLight3D][Shadows] area_shadow_* and shadow_* are hidden in the inspector while shadows are off, and still saved") {
	SceneTest::DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	for (const char *name : { "area_shadow_mode", "area_shadow_grid", "shadow_bias", "shadow_blur", "shadow_normal_bias" }) {
		CHECK_MESSAGE(usage_of(light, name) == uint32_t(PROPERTY_USAGE_NO_EDITOR), name);
	}
	CHECK((usage_of(light, "area_size") & PROPERTY_USAGE_EDITOR) != 0);
	uint32_t changes = light->get_property_list_changed_count();
	light->set_shadow(true);
	CHECK(light->get_property_list_changed_count() > changes);
	for (const char *name : { "area_shadow_mode", "area_shadow_grid", "shadow_bias", "shadow_blur" }) {
		CHECK_MESSAGE(usage_of(light, name) == uint32_t(PROPERTY_USAGE_DEFAULT), name);
	}
	// The PCSS baseline uses one map: the grid does not apply.
	changes = light->get_property_list_changed_count();
	light->set_area_shadow_mode(AreaLight3D::AREA_SHADOW_PCSS_BASELINE);
	CHECK(light->get_property_list_changed_count() > changes);
	CHECK(usage_of(light, "area_shadow_grid") == uint32_t(PROPERTY_USAGE_NO_EDITOR));
	CHECK(usage_of(light, "area_shadow_mode") == uint32_t(PROPERTY_USAGE_DEFAULT));
	delete light;
}

} // namespace TestAreaShadowCasters
