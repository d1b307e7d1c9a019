/**************************************************************************/
/*  test_area_light_shader_versions.cpp                                   */
/**************************************************************************/
/* The area shader version key of RenderForwardClustered: the area shadow */
/* lookup (AREA_SHADOWS_PCF / _PCSS) is compiled only into versions for   */
/* views whose area lights have shadow maps, so unshadowed views carry no */
/* shadow code (llvmpipe runs untaken branches, it cost the opaque pass   */
/* of the demo about two thirds of its time); the image of an unshadowed  */
/* light is the same with either version.                                 */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/render_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

namespace TestAreaLightShaderVersions {

using namespace RenderTest;

TEST_CASE("[AreaLight3D][Shadows] area shadow defines of the area version key") {
	const uint32_t ltc = 1u << RS::LIGHT_AREA_SHADING_LTC;
	CHECK(RenderForwardClustered::get_area_method_defines(ltc) == "#define AREA_METHOD_LTC\n");
	CHECK(RenderForwardClustered::get_area_method_defines(ltc | RenderForwardClustered::AREA_VERSION_SHADOWS_PCF) == "#define AREA_METHOD_LTC\n#define AREA_SHADOWS_PCF\n");
	CHECK(RenderForwardClustered::get_area_method_defines(ltc | RenderForwardClustered::AREA_VERSION_SHADOWS_PCSS) == "#define AREA_METHOD_LTC\n#define AREA_SHADOWS_PCSS\n");
	CHECK(RenderForwardClustered::get_area_method_defines(ltc | RenderForwardClustered::AREA_VERSION_SHADOWS_PCF | RenderForwardClustered::AREA_VERSION_SHADOWS_NEAR) == "#define AREA_METHOD_LTC\n#define AREA_SHADOWS_PCF\n#define AREA_SHADOWS_NEAR_LAYER\n");
	CHECK(RenderForwardClustered::get_area_method_defines(ltc | RenderForwardClustered::AREA_VERSION_SHADOWS_PCF | RenderForwardClustered::AREA_VERSION_SHADOWS_TREE) == "#define AREA_METHOD_LTC\n#define AREA_SHADOWS_PCF\n#define AREA_SHADOWS_TREE\n");
	// The shadow bits lie above every method bit.
	CHECK((RenderForwardClustered::AREA_VERSION_METHOD_BITS & (RenderForwardClustered::AREA_VERSION_SHADOWS_PCF | RenderForwardClustered::AREA_VERSION_SHADOWS_PCSS | RenderForwardClustered::AREA_VERSION_SHADOWS_NEAR | RenderForwardClustered::AREA_VERSION_SHADOWS_TREE)) == 0u);
}

TEST_CASE("[AreaLight3D][Shadows] the area shadow lookup is compiled only for views with shadowed area lights") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int S = 24;
		RenderSceneData d = make_scene(camera_looking_down(3.0f), 70.0f, S, S, 20.0f);
		RS::MaterialParams lambert;
		lambert.specular = 0.0f;
		RID mat = f.material(lambert);
		add_geometry(d, f.plane(4.0f), mat);
		// A box between the light and the middle of the plane.
		add_geometry(d, f.mesh(make_box(Vector3(0.3f, 0.3f, 0.3f))), mat, Transform3D(Basis(), Vector3(0, 0.8f, 0)));
		RID light = f.area_light(Vector2(0.6f, 0.6f), 3.0f, 10.0f, 2.0f);
		add_light(d, light, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, 1.8f, 0)));
		RID rt = f.renderer.render_target_create(S, S);
		REQUIRE(rt.is_valid());
		const ShaderRD &shader = f.renderer.get_scene_shader();

		f.renderer.render_scene(d, rt);
		std::vector<float> open = f.renderer.render_target_get_data(rt);
		const uint32_t created_open = shader.get_created_shader_count();
		CHECK(f.renderer.get_area_shader_version_count() == 1);

		// Shadows on: a second version (with the PCF lookup); the plane around the box gets darker.
		f.light_storage.light_set_shadow(light, true);
		f.renderer.render_scene(d, rt);
		std::vector<float> shadowed = f.renderer.render_target_get_data(rt);
		CHECK(shader.get_created_shader_count() == created_open + 1);
		CHECK(f.renderer.get_area_shader_version_count() == 2);
		CHECK(f.renderer.get_compiled_area_method_mask() == (1u << RS::LIGHT_AREA_SHADING_LTC)); // Method bits only.
		REQUIRE(open.size() == shadowed.size());
		double sum_open = 0.0, sum_shadowed = 0.0;
		for (size_t i = 0; i < open.size(); i += 4) {
			sum_open += open[i];
			sum_shadowed += shadowed[i];
		}
		MESSAGE("red sum without / with area shadows: ", sum_open, " / ", sum_shadowed);
		CHECK(sum_open > 1.0);
		CHECK(sum_shadowed < sum_open * 0.98);

		// Shadows off again: the first version is reused and gives the same image.
		f.light_storage.light_set_shadow(light, false);
		f.renderer.render_scene(d, rt);
		std::vector<float> open_again = f.renderer.render_target_get_data(rt);
		CHECK(shader.get_created_shader_count() == created_open + 1);
		REQUIRE(open_again.size() == open.size());
		int differing = 0;
		for (size_t i = 0; i < open.size(); i++) {
			differing += open_again[i] != open[i] ? 1 : 0;
		}
		CHECK(differing == 0);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[AreaLight3D][Render] objects out of every area light's reach are drawn without area-light code, with the same pixels") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		RenderFixture f;
		REQUIRE(f.init());
		const int S = 32;
		RenderSceneData d = make_scene(camera_looking_down(6.0f), 70.0f, S, S, 20.0f);
		RS::MaterialParams params;
		params.roughness = 0.5f;
		RID mat = f.material(params);
		// Patch A under the area light, patch B 3 m away, lit by an omni light only.
		add_geometry(d, f.plane(0.8f), mat);
		add_geometry(d, f.plane(0.8f), mat, Transform3D(Basis(), Vector3(3.0f, 0, 0)));
		RID omni = f.light_storage.light_create(RS::LIGHT_OMNI);
		f.lights.push_back(omni);
		f.light_storage.light_set_param(omni, RS::LIGHT_PARAM_ENERGY, 2.0f);
		f.light_storage.light_set_param(omni, RS::LIGHT_PARAM_RANGE, 3.0f);
		add_light(d, omni, RS::LIGHT_OMNI, Transform3D(Basis(), Vector3(3.0f, 1.0f, 0)));
		// Range 1 m: its influence box spans x in [-1.25, 1.25] and stops short of patch B.
		RID area = f.area_light(Vector2(0.5f, 0.5f), 3.0f, 1.0f, 2.0f);
		add_light(d, area, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(0, 0.5f, 0)));
		RID rt = f.renderer.render_target_create(S, S);
		REQUIRE(rt.is_valid());

		f.renderer.render_scene(d, rt);
		const std::vector<float> per_draw = f.renderer.render_target_get_data(rt);
		CHECK(f.renderer.get_last_frame_rendering_info(RS::RENDERING_INFO_TOTAL_DRAW_CALLS_IN_FRAME) == 2);
		CHECK(f.renderer.get_last_frame_rendering_info(RS::RENDERING_INFO_AREA_LIGHT_DRAW_CALLS_IN_FRAME) == 1);

		// A black area light over patch B with a long range puts B in an area light's box: B is drawn
		// with the area version, which adds exactly 0 for a black light. Every pixel must stay the same.
		RID black = f.area_light(Vector2(0.5f, 0.5f), 0.0f, 10.0f, 2.0f);
		add_light(d, black, RS::LIGHT_AREA, Transform3D(facing_down(), Vector3(3.0f, 0.5f, 0)));
		f.renderer.render_scene(d, rt);
		const std::vector<float> all_area = f.renderer.render_target_get_data(rt);
		CHECK(f.renderer.get_last_frame_rendering_info(RS::RENDERING_INFO_AREA_LIGHT_DRAW_CALLS_IN_FRAME) == 2);
		REQUIRE(per_draw.size() == all_area.size());
		int differing = 0;
		double lit_a = 0.0, lit_b = 0.0;
		for (int y = 0; y < S; y++) {
			for (int x = 0; x < S; x++) {
				const size_t i = (size_t(y) * S + x) * 4;
				for (int c = 0; c < 3; c++) {
					differing += per_draw[i + c] != all_area[i + c] ? 1 : 0;
				}
				const Vector3 p = pixel_on_ground(d, x, y);
				lit_a += (std::fabs(p.x) < 0.7f && std::fabs(p.z) < 0.7f) ? per_draw[i] : 0.0f;
				lit_b += (std::fabs(p.x - 3.0f) < 0.7f && std::fabs(p.z) < 0.7f) ? per_draw[i] : 0.0f;
			}
		}
		MESSAGE("red sums: patch A (area light) ", lit_a, ", patch B (omni only) ", lit_b, "; channels differing between the plain and the area version: ", differing);
		CHECK(lit_a > 1.0);
		CHECK(lit_b > 1.0);
		CHECK(differing == 0);
		f.renderer.render_target_free(rt);
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

} // namespace TestAreaLightShaderVersions
