/**************************************************************************/
/*  render_test_fixture.h                                                 */
/**************************************************************************/
/* Shared test helper for Forward+ render tests: RD storages + renderer   */
/* (GPU objects freed at the end of each test); the mesh and scene      */
/* helpers are in render_scene_helpers.h.                                 */
/* The RenderingDevice itself comes from rd_test_fixture.h. Usage:        */
/*                                                                        */
/*   RenderTest::RenderFixture f;                                         */
/*   REQUIRE(f.init());                                                   */
/*   RID ground = f.plane(4.0f);                                          */

#pragma once

#include "tests/servers/render_scene_helpers.h"

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <cmath>
#include <vector>

namespace RenderTest {

// What RendererSceneCull hands the renderer for shadowed area lights, for a scene built by hand: every
// instance casts for every light (a hand-built instance has no bound to cull it by).
inline void fill_shadow_casters(RenderSceneData &r_d) {
	r_d.shadow_geometry = r_d.geometry;
	for (RenderSceneData::LightInstance &l : r_d.lights) {
		l.shadow_casters.clear();
		for (uint32_t i = 0; i < uint32_t(r_d.shadow_geometry.size()); i++) {
			l.shadow_casters.push_back(i);
		}
	}
}

// One frame of p_data from p_renderer (Forward+ or the Embree reference) into a render target of the
// view's size, read back as RGBA floats (top row first); the target is freed again.
inline std::vector<float> render_frame(RendererSceneRender &p_renderer, const RenderSceneData &p_data) {
	RID rt = p_renderer.render_target_create(p_data.viewport_width, p_data.viewport_height);
	p_renderer.render_scene(p_data, rt);
	std::vector<float> img = p_renderer.render_target_get_data(rt);
	p_renderer.render_target_free(rt);
	return img;
}

// The Forward+ renderer for hand-built scenes: the caster lists are filled (fill_shadow_casters())
// when the scene has none.
struct SceneRenderer : public RenderForwardClustered {
	using RenderForwardClustered::RenderForwardClustered;
	void render_scene(const RenderSceneData &p_data, RID p_render_target) override {
		if (!p_data.shadow_geometry.empty() || p_data.geometry.empty()) {
			RenderForwardClustered::render_scene(p_data, p_render_target);
			return;
		}
		RenderSceneData data = p_data;
		fill_shadow_casters(data);
		RenderForwardClustered::render_scene(data, p_render_target);
	}
};

// Storages + Forward+ renderer; meshes, materials and lights made through it are freed with it.
struct RenderFixture {
	RendererRD::LightStorage light_storage;
	RendererRD::MeshStorage mesh_storage;
	RendererRD::MaterialStorage material_storage;
	SceneRenderer renderer{ &light_storage, &mesh_storage, &material_storage };
	std::vector<RID> meshes;
	std::vector<RID> materials;
	std::vector<RID> lights;

	// Needs the shared RenderingDevice (rd_test_get_device()).
	bool init(uint32_t p_max_lights = 32) {
		return material_storage.initialize_gpu() && light_storage.initialize_gpu(p_max_lights) && renderer.initialize(p_max_lights);
	}
	~RenderFixture() {
		for (RID m : meshes) {
			mesh_storage.mesh_free(m);
		}
		for (RID m : materials) {
			material_storage.material_free(m);
		}
		for (RID l : lights) {
			light_storage.light_free(l);
		}
		renderer.finalize();
		light_storage.finalize_gpu();
		material_storage.finalize_gpu();
	}
	// A mesh of one surface (tracked).
	RID mesh(const RS::SurfaceData &p_surface) {
		RID m = mesh_storage.mesh_create();
		mesh_storage.mesh_add_surface(m, p_surface);
		meshes.push_back(m);
		return m;
	}
	// Ground plane y = 0, normal +Y, front faces up (tracked).
	RID plane(float p_half) {
		return mesh(make_plane(p_half));
	}
	// A material with p_params (tracked).
	RID material(const RS::MaterialParams &p_params) {
		RID m = material_storage.material_create();
		material_storage.material_set_params(m, p_params);
		materials.push_back(m);
		return m;
	}
	// An area light (LTC unless changed) of size p_size (tracked).
	RID area_light(const Vector2 &p_size, float p_energy, float p_range, float p_attenuation) {
		RID l = light_storage.light_create(RS::LIGHT_AREA);
		light_storage.light_area_set_size(l, p_size);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_ENERGY, p_energy);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_RANGE, p_range);
		light_storage.light_set_param(l, RS::LIGHT_PARAM_ATTENUATION, p_attenuation);
		lights.push_back(l);
		return l;
	}
};

} // namespace RenderTest
