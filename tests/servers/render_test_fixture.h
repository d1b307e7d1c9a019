/**************************************************************************/
/*  render_test_fixture.h                                                 */
/**************************************************************************/
/* Shared test helper for Forward+ render tests: RD storages + renderer   */
/* (GPU objects freed at the end of each test) and small mesh helpers.    */
/* The RenderingDevice itself comes from rd_test_fixture.h. Usage:        */
/*                                                                        */
/*   RenderTest::RenderFixture f;                                         */
/*   REQUIRE(f.init());                                                   */
/*   RID ground = f.plane(4.0f);                                          */

#pragma once

#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"

#include "core/math/math_funcs.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <cmath>
#include <vector>

namespace RenderTest {

// Appends a quad centred at p_center with half axes p_u, p_v; its front (normal p_u x p_v) is
// clockwise as seen from the front (Godot's winding).
inline void add_quad(RS::SurfaceData &r_s, const Vector3 &p_center, const Vector3 &p_u, const Vector3 &p_v) {
	uint32_t base = uint32_t(r_s.vertices.size());
	Vector3 n = p_u.cross(p_v).normalized();
	Vector3 corners[4] = { p_center - p_u - p_v, p_center + p_u - p_v, p_center + p_u + p_v, p_center - p_u + p_v };
	for (int i = 0; i < 4; i++) {
		r_s.vertices.push_back(corners[i]);
		r_s.normals.push_back(n);
	}
	uint32_t idx[6] = { 0, 2, 1, 0, 3, 2 };
	for (int i = 0; i < 6; i++) {
		r_s.indices.push_back(base + idx[i]);
	}
}

// Square y = 0 of half side p_half_size, normal +Y.
inline RS::SurfaceData make_plane(float p_half_size) {
	RS::SurfaceData s;
	add_quad(s, Vector3(), Vector3(0, 0, p_half_size), Vector3(p_half_size, 0, 0));
	return s;
}

// Closed box of half extents p_half around the origin, normals outward (BoxMesh's arrays, without
// tangents and UVs so add_quad() can extend it).
inline RS::SurfaceData make_box(const Vector3 &p_half) {
	RS::SurfaceData s;
	BoxMesh::create_box_arrays(s, p_half * 2, 0, 0, 0);
	s.tangents.clear();
	s.uvs.clear();
	return s;
}

// A view of p_w x p_h pixels from p_cam (near 0.05 m) on a black background, no ambient light.
inline RenderSceneData make_scene(const Transform3D &p_cam, float p_fovy, int p_w, int p_h, float p_z_far) {
	RenderSceneData d;
	d.cam_transform = p_cam;
	d.z_near = 0.05f;
	d.z_far = p_z_far;
	d.fovy_degrees = p_fovy;
	d.cam_projection = Projection::create_perspective(p_fovy, float(p_w) / float(p_h), d.z_near, d.z_far);
	d.viewport_width = p_w;
	d.viewport_height = p_h;
	d.environment.has_environment = true;
	d.environment.background = RS::ENV_BG_COLOR;
	d.environment.bg_color = Color(0, 0, 0, 1);
	d.environment.bg_energy = 1.0f;
	d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
	d.environment.ambient_color = Color(0, 0, 0, 1);
	d.environment.ambient_energy = 0.0f;
	return d;
}

// Adds one mesh instance (material override, world transform) to a scene.
inline void add_geometry(RenderSceneData &r_d, RID p_mesh, RID p_material, const Transform3D &p_xform = Transform3D()) {
	RenderSceneData::GeometryInstance g;
	g.mesh = p_mesh;
	g.material_override = p_material;
	g.transform = p_xform;
	r_d.geometry.push_back(g);
}

// Adds one visible light instance to a scene.
inline void add_light(RenderSceneData &r_d, RID p_light, RS::LightType p_type, const Transform3D &p_xform) {
	RenderSceneData::LightInstance l;
	l.light = p_light;
	l.type = p_type;
	l.transform = p_xform;
	r_d.lights.push_back(l);
}

// Camera at height p_height looking along -Y with -Z as screen-up.
inline Transform3D camera_looking_down(float p_height) {
	return Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, p_height, 0));
}

// Light basis whose local -Z (emission) points to world -Y; local X stays world X, local Y becomes world -Z.
inline Basis facing_down() {
	return Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
}

// World point on y = 0 seen through the centre of pixel (p_px, p_py) (top row first).
inline Vector3 pixel_on_ground(const RenderSceneData &p_d, int p_px, int p_py) {
	float t = std::tan(Math::deg_to_rad(p_d.fovy_degrees) * 0.5f);
	float aspect = float(p_d.viewport_width) / float(p_d.viewport_height);
	float x_ndc = (p_px + 0.5f) / p_d.viewport_width * 2.0f - 1.0f;
	float y_ndc = 1.0f - (p_py + 0.5f) / p_d.viewport_height * 2.0f;
	Vector3 dir = p_d.cam_transform.basis.xform(Vector3(x_ndc * t * aspect, y_ndc * t, -1.0f));
	Vector3 o = p_d.cam_transform.origin;
	return o + dir * (-o.y / dir.y);
}

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
