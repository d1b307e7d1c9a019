/**************************************************************************/
/*  test_rendering_server_debug.cpp                                       */
/**************************************************************************/
/* godot-area: the RenderingServer's debug entries that benchmarks use   */
/* instead of reaching into the renderer: the per-method fragment        */
/* sources (bench --sweep methods --spirv-sources) and the area-light    */
/* baseline switch (bench --targets, P4); and the area shadow filter     */
/* (RS::area_shadow_filter_set_mode), which the shadow sweeps switch.     */

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"
#include "scene/main/godot_instance.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering_server.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestRenderingServerDebug {

// A floor lit by one omni light and, when p_area, one shadowed area light above it; returns one
// frame and, in r_labels, the debug labels the frame's passes recorded.
// p_occluder adds a 0.6 m box between the area light and the floor (a penumbra for the shadow filter).
static Image render_floor(RenderingServer *p_rs, bool p_area, std::vector<String> *r_labels = nullptr, bool p_occluder = false) {
	std::vector<RID> owned;
	RS::SurfaceData surface;
	PlaneMesh::create_plane_arrays(surface, Vector2(8, 8), 0, 0, Vector3(), PlaneMesh::FACE_Y);
	RID mesh = p_rs->mesh_create();
	p_rs->mesh_add_surface(mesh, surface);
	RID scenario = p_rs->scenario_create();
	RID env = p_rs->environment_create();
	p_rs->environment_set_background(env, RS::ENV_BG_COLOR);
	p_rs->environment_set_bg_color(env, Color(0, 0, 0, 1));
	p_rs->environment_set_ambient_light(env, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
	p_rs->scenario_set_environment(scenario, env);
	RID floor = p_rs->instance_create();
	p_rs->instance_set_base(floor, mesh);
	p_rs->instance_set_scenario(floor, scenario);
	owned.insert(owned.end(), { mesh, env, scenario, floor });
	auto add_light = [&](RID p_light, const Transform3D &p_xform) {
		p_rs->light_set_param(p_light, RS::LIGHT_PARAM_ENERGY, 2.0f);
		p_rs->light_set_param(p_light, RS::LIGHT_PARAM_RANGE, 10.0f);
		RID inst = p_rs->instance_create();
		p_rs->instance_set_base(inst, p_light);
		p_rs->instance_set_scenario(inst, scenario);
		p_rs->instance_set_transform(inst, p_xform);
		owned.insert(owned.end(), { p_light, inst });
	};
	add_light(p_rs->omni_light_create(), Transform3D(Basis(), Vector3(-1, 1.5f, 0)));
	if (p_occluder) {
		RS::SurfaceData box;
		BoxMesh::create_box_arrays(box, Vector3(0.6f, 0.1f, 0.6f), 0, 0, 0);
		RID box_mesh = p_rs->mesh_create();
		p_rs->mesh_add_surface(box_mesh, box);
		RID box_inst = p_rs->instance_create();
		p_rs->instance_set_base(box_inst, box_mesh);
		p_rs->instance_set_scenario(box_inst, scenario);
		p_rs->instance_set_transform(box_inst, Transform3D(Basis(), Vector3(1, 0.7f, 0)));
		owned.insert(owned.end(), { box_mesh, box_inst });
	}
	if (p_area) {
		RID area = p_rs->area_light_create();
		p_rs->light_area_set_size(area, Vector2(1, 1));
		p_rs->light_set_shadow(area, true);
		// Local -Z (the emitting side) turned to world -Y.
		add_light(area, Transform3D(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f), Vector3(1, 1.5f, 0)));
	}
	RID camera = p_rs->camera_create();
	p_rs->camera_set_perspective(camera, 60.0f, 0.05f, 50.0f);
	p_rs->camera_set_transform(camera, Transform3D(Basis::looking_at(Vector3(0, -1, -1).normalized(), Vector3(0, 1, 0)), Vector3(0, 3, 3)));
	RID viewport = p_rs->viewport_create();
	p_rs->viewport_set_size(viewport, 48, 32);
	p_rs->viewport_attach_camera(viewport, camera);
	p_rs->viewport_set_scenario(viewport, scenario);
	owned.insert(owned.end(), { camera, viewport });
	p_rs->draw();
	if (r_labels) {
		*r_labels = RenderingDevice::get_singleton()->get_captured_label_names();
	}
	Image image = p_rs->viewport_get_texture_data(viewport);
	for (auto it = owned.rbegin(); it != owned.rend(); ++it) {
		p_rs->free(*it);
	}
	return image;
}

static double difference(const Image &p_a, const Image &p_b) {
	double sum = 0.0;
	for (size_t i = 0; i < p_a.get_data().size() && i < p_b.get_data().size(); i++) {
		sum += std::fabs(double(p_a.get_data()[i]) - double(p_b.get_data()[i]));
	}
	return sum;
}

TEST_CASE("[RenderingServer] get_debug_scene_shader_sources() returns the colour pass per area shading method") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	GodotInstance engine;
	String error;
	REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_RD, &error, 8), error.c_str());
	const std::vector<std::pair<String, String>> sources = engine.get_rendering_server()->get_debug_scene_shader_sources();
	REQUIRE(sources.size() == 11); // base, 5 methods for rectangles, 5 methods with the shape code (AUTO has none).
	CHECK(sources[0].first == "base.frag");
	CHECK(sources[0].second.find("#define USE_AREA_LIGHTS") == String::npos);
	const char *methods[5] = { "LTC", "LTC_POLYNOMIAL", "MRP", "STOCHASTIC", "LTC_2LOBE" };
	for (int m = 0; m < 5; m++) {
		CAPTURE(m);
		CHECK(sources[m + 1].first == String("area_") + methods[m] + ".frag");
		CHECK(sources[m + 1].second.find("#define USE_AREA_LIGHTS") != String::npos);
		CHECK(sources[m + 1].second.find(String("#define AREA_METHOD_") + methods[m] + "\n") != String::npos);
		for (int other = 0; other < 5; other++) {
			if (other != m) {
				CHECK(sources[m + 1].second.find(String("#define AREA_METHOD_") + methods[other] + "\n") == String::npos);
			}
		}
		CHECK(sources[m + 1].second.find("#define USE_AREA_SHAPES") == String::npos);
		CHECK(sources[m + 6].first == String("area_") + methods[m] + "_shapes.frag");
		CHECK(sources[m + 6].second.find(String("#define AREA_METHOD_") + methods[m] + "\n") != String::npos);
		CHECK(sources[m + 6].second.find("#define USE_AREA_SHAPES") != String::npos);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingServer] set_debug_disable_area_lights() leaves a scene without area lights unchanged and drops area lights") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	GodotInstance engine;
	String error;
	REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_RD, &error, 8), error.c_str());
	RenderingServer *rs = engine.get_rendering_server();
	const Image omni_only = render_floor(rs, false);
	const Image both = render_floor(rs, true);
	rs->set_debug_disable_area_lights(true);
	const Image omni_only_off = render_floor(rs, false);
	const Image both_off = render_floor(rs, true);
	rs->set_debug_disable_area_lights(false);
	REQUIRE(omni_only.get_width() == 48);
	REQUIRE(both_off.get_width() == 48);
	double lit = 0.0;
	for (float v : omni_only.get_data()) {
		lit += v;
	}
	CHECK(lit > 1.0); // The omni light reaches the floor.
	CHECK(difference(omni_only, omni_only_off) == 0.0); // The baseline draws the same frame.
	CHECK(difference(omni_only, both) > 1.0); // The area light adds light ...
	CHECK(difference(omni_only, both_off) == 0.0); // ... which the baseline does not draw.
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderForwardClustered] each pass of a frame records a debug label") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	GodotInstance engine;
	String error;
	REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_RD, &error, 8), error.c_str());
	std::vector<String> labels;
	render_floor(engine.get_rendering_server(), false, &labels);
	CHECK(labels == std::vector<String>{ "Render Depth Pre-Pass", "Build Clusters", "Render Opaque Pass" });
	render_floor(engine.get_rendering_server(), true, &labels);
	CHECK(labels == std::vector<String>{ "Render Area Shadow Maps", "Render Depth Pre-Pass", "Area Shadow Adaptive Refinement", "Build Clusters", "Render Opaque Pass" });
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingServer] area_shadow_filter_set_mode() switches the sample maps' filter; the project setting starts it") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	const char *setting = "rendering/lights_and_shadows/area_shadow_filter";
	Image penumbra, pcf, pcf_again;
	{
		GodotInstance engine;
		String error;
		REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_RD, &error, 8), error.c_str());
		RenderingServer *rs = engine.get_rendering_server();
		CHECK(rs->area_shadow_filter_get_mode() == RS::AREA_SHADOW_FILTER_PENUMBRA); // Godot-style default.
		penumbra = render_floor(rs, true, nullptr, true);
		rs->area_shadow_filter_set_mode(RS::AREA_SHADOW_FILTER_PCF);
		CHECK(rs->area_shadow_filter_get_mode() == RS::AREA_SHADOW_FILTER_PCF);
		pcf = render_floor(rs, true, nullptr, true);
		set_error_print_silenced(true);
		rs->area_shadow_filter_set_mode(RS::AreaShadowFilter(7)); // Rejected with an error: PCF is kept.
		set_error_print_silenced(false);
		CHECK(rs->area_shadow_filter_get_mode() == RS::AREA_SHADOW_FILTER_PCF);
		rs->area_shadow_filter_set_mode(RS::AREA_SHADOW_FILTER_PENUMBRA);
		CHECK(difference(render_floor(rs, true, nullptr, true), penumbra) == 0.0);
		RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
	}
	REQUIRE(penumbra.get_width() == 48);
	CHECK(difference(penumbra, pcf) > 0.01); // The box's penumbra is filtered differently.
	ProjectSettings::get_singleton()->set_setting(setting, int(RS::AREA_SHADOW_FILTER_PCF));
	{
		GodotInstance engine;
		String error;
		REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_RD, &error, 8), error.c_str());
		CHECK(engine.get_rendering_server()->area_shadow_filter_get_mode() == RS::AREA_SHADOW_FILTER_PCF);
		pcf_again = render_floor(engine.get_rendering_server(), true, nullptr, true);
	}
	ProjectSettings::get_singleton()->clear_override(setting);
	CHECK(difference(pcf_again, pcf) == 0.0);
}

} // namespace TestRenderingServerDebug
