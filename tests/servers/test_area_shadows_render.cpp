/**************************************************************************/
/*  test_area_shadows_render.cpp                                          */
/**************************************************************************/
/* godot-area: area-light soft shadows in the Forward+ renderer on        */
/* lavapipe (validation on) against the Embree reference with shadow rays */
/* on: a box above a plane under a large light (a wide penumbra). The     */
/* visibility (shadowed / unshadowed image, so the shading method's own   */
/* error cancels) approaches the reference's as the sample maps grow      */
/* (4 -> 9 -> 25 -> 81) and beats the one-map PCSS baseline from 25 maps; */
/* an unoccluded plane renders as without shadows (no acne); a static     */
/* scene redraws no map after the first frame. The sweep behind the doc   */
/* tables is `bench --sweep shadows` (modules/benchmark/shadows_sweep.h). */

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "modules/reference/reference_renderer.h"
#include "scene/3d/light_3d.h"
#include "scene/main/node.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/rendering_server_globals.h"
#include "tests/scene/scene_test_fixture.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace TestAreaShadowsRender {

static const int W = 48;
static const int H = 48;

static RS::SurfaceData make_plane(float p_half) {
	RS::SurfaceData s;
	s.vertices = { Vector3(-p_half, 0, -p_half), Vector3(p_half, 0, -p_half), Vector3(p_half, 0, p_half), Vector3(-p_half, 0, p_half) };
	s.normals = { Vector3(0, 1, 0), Vector3(0, 1, 0), Vector3(0, 1, 0), Vector3(0, 1, 0) };
	s.indices = { 0, 1, 2, 0, 2, 3 };
	return s;
}

// Axis-aligned box centred at p_center with half extent p_half (24 vertices, outward normals).
static RS::SurfaceData make_box(const Vector3 &p_center, float p_half) {
	RS::SurfaceData s;
	for (int axis = 0; axis < 3; axis++) {
		for (int sign = -1; sign <= 1; sign += 2) {
			Vector3 n;
			n[axis] = float(sign);
			Vector3 u, v;
			u[(axis + 1) % 3] = p_half;
			v[(axis + 2) % 3] = p_half;
			Vector3 c = p_center + n * p_half;
			uint32_t base = uint32_t(s.vertices.size());
			Vector3 corners[4] = { c - u - v, c + u - v, c + u + v, c - u + v };
			for (int i = 0; i < 4; i++) {
				s.vertices.push_back(corners[i]);
				s.normals.push_back(n);
			}
			s.indices.insert(s.indices.end(), { base, base + 1, base + 2, base, base + 2, base + 3 });
		}
	}
	return s;
}

static Basis facing_down() {
	return Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
}

static RenderSceneData make_scene() {
	RenderSceneData d;
	d.cam_transform = Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0.3f, 3.2f, 0.2f));
	d.z_near = 0.05f;
	d.z_far = 20.0f;
	d.fovy_degrees = 60.0f;
	d.cam_projection = Projection::create_perspective(60.0f, float(W) / float(H), d.z_near, d.z_far);
	d.viewport_width = W;
	d.viewport_height = H;
	d.environment.has_environment = true;
	d.environment.background = RS::ENV_BG_COLOR;
	d.environment.bg_color = Color(0, 0, 0, 1);
	return d;
}

static const Vector2 LIGHT_SIZE(1.6f, 1.6f);
static const float LIGHT_HEIGHT = 1.5f;
static const float BOX_HALF = 0.25f;
static const Vector3 BOX_CENTER(0.0f, 0.55f, 0.0f);

static RS::MaterialParams lambert() {
	RS::MaterialParams mp;
	mp.albedo = Color(0.8f, 0.8f, 0.8f, 1.0f);
	mp.specular = 0.0f;
	mp.specular_mode = RS::MATERIAL_SPECULAR_DISABLED;
	mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
	mp.roughness = 1.0f;
	mp.cull_back = false;
	return mp;
}

// The Embree reference of the penumbra scene, with and without shadow rays.
static void render_reference(bool p_with_box, std::vector<float> &r_open, std::vector<float> &r_shadowed) {
	RendererDummy::LightStorage ls;
	RendererDummy::MeshStorage ms;
	RendererDummy::MaterialStorage mats;
	ReferenceRenderOptions options;
	options.threads = 2;
	options.target_relative_error = 0.01f;
	options.max_samples = 2048;
	ReferenceRenderer ref(&ls, &ms, &mats, options);
	RID plane = ms.mesh_create();
	ms.mesh_add_surface(plane, make_plane(4.0f));
	RID box = ms.mesh_create();
	ms.mesh_add_surface(box, make_box(BOX_CENTER, BOX_HALF));
	RID mat = mats.material_create();
	mats.material_set_params(mat, lambert());
	RID light = ls.light_create(RS::LIGHT_AREA);
	ls.light_area_set_size(light, LIGHT_SIZE);
	ls.light_set_param(light, RS::LIGHT_PARAM_ENERGY, 2.0f);
	ls.light_set_param(light, RS::LIGHT_PARAM_RANGE, 20.0f);
	ls.light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 0.0f);
	RenderSceneData d = make_scene();
	RenderSceneData::GeometryInstance g;
	g.mesh = plane;
	g.material_override = mat;
	d.geometry.push_back(g);
	if (p_with_box) {
		g.mesh = box;
		d.geometry.push_back(g);
	}
	RenderSceneData::LightInstance li;
	li.light = light;
	li.type = RS::LIGHT_AREA;
	li.transform = Transform3D(facing_down(), Vector3(0, LIGHT_HEIGHT, 0));
	d.lights.push_back(li);
	RID rt = ref.render_target_create(W, H);
	ref.render_scene(d, rt);
	r_open = ref.render_target_get_data(rt);
	options.shadows = true;
	ref.set_options(options);
	ref.render_scene(d, rt);
	r_shadowed = ref.render_target_get_data(rt);
	ref.render_target_free(rt);
	ls.light_free(light);
	ms.mesh_free(plane);
	ms.mesh_free(box);
	mats.material_free(mat);
}

struct ShadowFixture {
	RendererRD::LightStorage light_storage;
	RendererRD::MeshStorage mesh_storage;
	RendererRD::MaterialStorage material_storage;
	RenderForwardClustered renderer{ &light_storage, &mesh_storage, &material_storage };
	RID plane, box, mat, light, rt;
	RenderSceneData scene;

	bool init(bool p_with_box) {
		if (!(material_storage.initialize_gpu() && light_storage.initialize_gpu(32) && renderer.initialize(32))) {
			return false;
		}
		plane = mesh_storage.mesh_create();
		mesh_storage.mesh_add_surface(plane, make_plane(4.0f));
		box = mesh_storage.mesh_create();
		mesh_storage.mesh_add_surface(box, make_box(BOX_CENTER, BOX_HALF));
		mat = material_storage.material_create();
		material_storage.material_set_params(mat, lambert());
		light = light_storage.light_create(RS::LIGHT_AREA);
		light_storage.light_area_set_size(light, LIGHT_SIZE);
		light_storage.light_set_param(light, RS::LIGHT_PARAM_ENERGY, 2.0f);
		light_storage.light_set_param(light, RS::LIGHT_PARAM_RANGE, 20.0f);
		light_storage.light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 0.0f);
		light_storage.light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, 2.0f); // PCF radius 4 texels.
		scene = make_scene();
		RenderSceneData::GeometryInstance g;
		g.mesh = plane;
		g.material_override = mat;
		scene.geometry.push_back(g);
		if (p_with_box) {
			g.mesh = box;
			scene.geometry.push_back(g);
		}
		RenderSceneData::LightInstance li;
		li.light = light;
		li.type = RS::LIGHT_AREA;
		li.transform = Transform3D(facing_down(), Vector3(0, LIGHT_HEIGHT, 0));
		scene.lights.push_back(li);
		rt = renderer.render_target_create(W, H);
		return rt.is_valid();
	}
	std::vector<float> render() {
		renderer.render_scene(scene, rt);
		return renderer.render_target_get_data(rt);
	}
	~ShadowFixture() {
		light_storage.light_free(light);
		mesh_storage.mesh_free(plane);
		mesh_storage.mesh_free(box);
		material_storage.material_free(mat);
		renderer.finalize();
		light_storage.finalize_gpu();
		material_storage.finalize_gpu();
	}
};

// RMS difference of the visibility (shadowed / open) over pixels the light reaches.
static double visibility_rmse(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed) {
	double sum = 0.0;
	int n = 0;
	for (size_t i = 0; i < p_open.size(); i += 4) {
		if (p_open[i] <= 1e-3f || p_ref_open[i] <= 1e-3f) {
			continue;
		}
		double v = std::min(std::max(double(p_shadowed[i] / p_open[i]), 0.0), 1.5);
		double vr = std::min(std::max(double(p_ref_shadowed[i] / p_ref_open[i]), 0.0), 1.5);
		sum += (v - vr) * (v - vr);
		n++;
	}
	return n > 0 ? std::sqrt(sum / n) : 1.0;
}

TEST_CASE("[AreaLight3D][Shadows] the penumbra approaches the reference as shadow maps grow and beats the PCSS baseline") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	std::vector<float> ref_open, ref_shadowed;
	render_reference(true, ref_open, ref_shadowed);
	{
		ShadowFixture f;
		REQUIRE(f.init(true));
		REQUIRE(f.renderer.area_shadow_atlas_set_size(1008, 9)); // 81 tiles of 112 px.
		std::vector<float> open = f.render();
		f.light_storage.light_set_shadow(f.light, true);

		double err[4] = {};
		const int grids[4] = { 2, 3, 5, 9 };
		for (int k = 0; k < 4; k++) {
			f.light_storage.light_area_set_shadow_grid(f.light, grids[k]);
			std::vector<float> shadowed = f.render();
			CHECK(f.renderer.get_area_shadow_renderer().get_atlas().light_get_tile_count(f.light.get_id()) == uint32_t(grids[k] * grids[k]));
			err[k] = visibility_rmse(open, shadowed, ref_open, ref_shadowed);
			MESSAGE("maps ", grids[k] * grids[k], ": visibility RMSE vs reference ", err[k]);
		}
		f.light_storage.light_area_set_shadow_mode(f.light, RS::LIGHT_AREA_SHADOW_PCSS_BASELINE);
		std::vector<float> pcss = f.render();
		double err_pcss = visibility_rmse(open, pcss, ref_open, ref_shadowed);
		MESSAGE("PCSS baseline (1 map): visibility RMSE vs reference ", err_pcss);

		CHECK(err[1] < err[0]);
		CHECK(err[2] < err[1]);
		CHECK(err[3] <= err[2] * 1.05);
		CHECK(err[2] < err_pcss);
		CHECK(err[3] < err_pcss);
		CHECK(err[2] < 0.03);
		RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
	}
}

TEST_CASE("[AreaLight3D][Shadows] an unoccluded plane renders as without shadows (no acne) and a static scene redraws nothing") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE_MESSAGE(rd != nullptr, "A Vulkan device (lavapipe) is required.");
	{
		ShadowFixture f;
		REQUIRE(f.init(false));
		REQUIRE(f.renderer.area_shadow_atlas_set_size(512, 4));
		std::vector<float> open = f.render();
		f.light_storage.light_set_shadow(f.light, true);
		f.light_storage.light_area_set_shadow_grid(f.light, 3);
		std::vector<float> shadowed = f.render();
		AreaShadowRendererRD &shadows = f.renderer.get_area_shadow_renderer();
		CHECK(shadows.get_last_draw_count() == 9);
		double worst = 0.0;
		for (size_t i = 0; i < open.size(); i += 4) {
			if (open[i] > 1e-3f) {
				worst = std::max(worst, double(std::fabs(shadowed[i] - open[i]) / open[i]));
			}
		}
		MESSAGE("unoccluded plane: worst relative difference with shadows on ", worst);
		CHECK(worst < 0.01);
		// Static scene: no map is redrawn after the first frame.
		for (int frame = 0; frame < 3; frame++) {
			f.render();
			CHECK(shadows.get_last_draw_count() == 0);
		}
		// Moving the light redraws its maps once.
		f.scene.lights[0].transform.origin.x += 0.1f;
		f.render();
		CHECK(shadows.get_last_draw_count() == 9);
		f.render();
		CHECK(shadows.get_last_draw_count() == 0);
		// Shadows off: the tiles go back to the atlas.
		f.light_storage.light_set_shadow(f.light, false);
		f.render();
		CHECK(shadows.get_atlas().get_free_tile_count() == 16);
		RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
	}
}

TEST_CASE("[AreaLight3D][Shadows] shadow properties: defaults, server values, bad input and a .tscn round trip") {
	SceneTest::DummyServer server;
	AreaLight3D *light = new AreaLight3D;
	CHECK(light->get("area_shadow_mode").to_int() == AreaLight3D::AREA_SHADOW_FIXED);
	CHECK(light->get("area_shadow_grid").to_int() == 3);
	CHECK(int(AreaLight3D::AREA_SHADOW_PCSS_BASELINE) == int(RS::LIGHT_AREA_SHADOW_PCSS_BASELINE));
	RID rid = light->get_light();
	CHECK(RSG::light_storage->light_area_get_shadow_grid(rid) == 3);
	bool valid = false;
	light->set("shadow_enabled", true, &valid);
	CHECK(valid);
	light->set("area_shadow_grid", 5, &valid);
	CHECK(valid);
	light->set("area_shadow_mode", 1, &valid);
	CHECK(valid);
	CHECK(RSG::light_storage->light_has_shadow(rid));
	CHECK(RSG::light_storage->light_area_get_shadow_grid(rid) == 5);
	CHECK(RSG::light_storage->light_area_get_shadow_mode(rid) == RS::LIGHT_AREA_SHADOW_PCSS_BASELINE);
	{
		SceneTest::ErrorCatcher errors;
		light->set_area_shadow_grid(1);
		light->set_area_shadow_grid(10);
		light->set("area_shadow_mode", 7);
		CHECK(errors.contains("area_shadow_grid"));
		CHECK(errors.contains("area_shadow_mode"));
	}
	CHECK(light->get_area_shadow_grid() == 5);
	CHECK(light->get_area_shadow_mode() == AreaLight3D::AREA_SHADOW_PCSS_BASELINE);
	delete light;

	const String text = R"TSCN([gd_scene format=3]

[node name="Root" type="Node3D"]

[node name="Panel" type="AreaLight3D" parent="."]
shadow_enabled = true
area_shadow_mode = 1
area_shadow_grid = 9
)TSCN";
	String error;
	Node *root = ResourceFormatText::load_scene_from_string(text, "area_shadows.tscn", &error);
	REQUIRE_MESSAGE(root != nullptr, error);
	AreaLight3D *panel = Object::cast_to<AreaLight3D>(root->get_node_or_null("Panel"));
	REQUIRE(panel);
	CHECK(panel->get_area_shadow_grid() == 9);
	CHECK(RSG::light_storage->light_area_get_shadow_grid(panel->get_light()) == 9);
	String saved = ResourceFormatText::save_scene_to_string(root);
	CHECK_MESSAGE(saved.find("area_shadow_grid = 9") != String::npos, saved);
	CHECK_MESSAGE(saved.find("area_shadow_mode = 1") != String::npos, saved);
	delete root;
}

// The error and timing sweep (doc/shadows.md) is `godot-area bench --sweep shadows` (modules/benchmark/shadows_sweep.h).

} // namespace TestAreaShadowsRender
