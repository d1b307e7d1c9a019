/**************************************************************************/
/*  penumbra_scene.cpp                                                    */
/**************************************************************************/
/* godot-area: the penumbra scene of the shadow benchmarks (see the       */
/* header).                                                               */

#include "modules/benchmark/penumbra_scene.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "servers/rendering/storage/light_storage.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"

#include <algorithm>
#include <cmath>

RS::SurfaceData PenumbraScene::make_plane(float p_half) {
	RS::SurfaceData s;
	s.vertices = { Vector3(-p_half, 0, -p_half), Vector3(p_half, 0, -p_half), Vector3(p_half, 0, p_half), Vector3(-p_half, 0, p_half) };
	s.normals = { Vector3(0, 1, 0), Vector3(0, 1, 0), Vector3(0, 1, 0), Vector3(0, 1, 0) };
	s.indices = { 0, 1, 2, 0, 2, 3 };
	return s;
}

RS::SurfaceData PenumbraScene::make_box(const Vector3 &p_center, const Vector3 &p_half) {
	RS::SurfaceData s;
	for (int axis = 0; axis < 3; axis++) {
		for (int sign = -1; sign <= 1; sign += 2) {
			Vector3 n;
			n[axis] = float(sign);
			Vector3 u, v;
			u[(axis + 1) % 3] = p_half[(axis + 1) % 3];
			v[(axis + 2) % 3] = p_half[(axis + 2) % 3];
			Vector3 c = p_center + n * p_half[axis];
			uint32_t base = uint32_t(s.vertices.size());
			Vector3 corners[4] = { c - u - v, c + u - v, c + u + v, c - u + v };
			for (int i = 0; i < 4; i++) {
				s.vertices.push_back(corners[i]);
				s.normals.push_back(n);
			}
			s.indices.insert(s.indices.end(), { base, base + 2, base + 1, base, base + 3, base + 2 }); // Clockwise front faces.
		}
	}
	return s;
}

RS::MaterialParams PenumbraScene::lambert() {
	RS::MaterialParams mp;
	mp.albedo = Color(0.8f, 0.8f, 0.8f, 1.0f);
	mp.specular = 0.0f;
	mp.specular_mode = RS::MATERIAL_SPECULAR_DISABLED;
	mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
	mp.roughness = 1.0f;
	mp.cull_back = false;
	return mp;
}

Transform3D PenumbraScene::light_transform(const Settings &p_settings) {
	return Transform3D(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f), Vector3(0, p_settings.light_height, 0));
}

RenderSceneData PenumbraScene::make_view(const Vector3 &p_position, const Vector3 &p_target, int p_width, int p_height, float p_fovy) {
	RenderSceneData d;
	Vector3 forward = p_target - p_position;
	Vector3 up(0, 1, 0);
	if (std::fabs(forward.normalized().dot(up)) > 0.999f) {
		up = Vector3(0, 0, -1);
	}
	d.cam_transform = Transform3D(Basis::looking_at(forward, up), p_position);
	d.z_near = 0.05f;
	d.z_far = 20.0f;
	d.fovy_degrees = p_fovy;
	d.cam_projection = Projection::create_perspective(p_fovy, float(p_width) / float(std::max(p_height, 1)), d.z_near, d.z_far);
	d.viewport_width = p_width;
	d.viewport_height = p_height;
	d.environment.has_environment = true;
	d.environment.background = RS::ENV_BG_COLOR;
	d.environment.bg_color = Color(0, 0, 0, 1);
	return d;
}

RenderSceneData PenumbraScene::make_top_view(int p_resolution) {
	RenderSceneData d = make_view(Vector3(0.3f, 3.2f, 0.2f), Vector3(0.3f, 0.0f, 0.2f), p_resolution, p_resolution);
	d.cam_transform.basis = Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)); // Exactly the sweep's view.
	return d;
}

bool PenumbraScene::create(RendererLightStorage *p_light_storage, RendererMeshStorage *p_mesh_storage, RendererMaterialStorage *p_material_storage, RenderSceneData &r_scene, const Settings &p_settings) {
	ERR_FAIL_NULL_V_MSG(p_light_storage, false, "PenumbraScene: no light storage.");
	ERR_FAIL_NULL_V_MSG(p_mesh_storage, false, "PenumbraScene: no mesh storage.");
	ERR_FAIL_NULL_V_MSG(p_material_storage, false, "PenumbraScene: no material storage.");
	free();
	light_storage = p_light_storage;
	mesh_storage = p_mesh_storage;
	material_storage = p_material_storage;
	floor_mesh = mesh_storage->mesh_create();
	mesh_storage->mesh_add_surface(floor_mesh, make_plane(p_settings.floor_half));
	box_mesh = mesh_storage->mesh_create();
	mesh_storage->mesh_add_surface(box_mesh, make_box(p_settings.box_center, p_settings.box_half));
	material = material_storage->material_create();
	material_storage->material_set_params(material, lambert());
	light = light_storage->light_create(RS::LIGHT_AREA);
	if (!floor_mesh.is_valid() || !box_mesh.is_valid() || !material.is_valid() || !light.is_valid()) {
		free();
		ERR_FAIL_V_MSG(false, "PenumbraScene: a storage refused to create the scene's objects.");
	}
	light_storage->light_area_set_size(light, p_settings.light_size);
	light_storage->light_set_param(light, RS::LIGHT_PARAM_ENERGY, p_settings.light_energy);
	light_storage->light_set_param(light, RS::LIGHT_PARAM_RANGE, p_settings.light_range);
	light_storage->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 2.0f);
	RenderSceneData::GeometryInstance g;
	g.mesh = floor_mesh;
	g.material_override = material;
	r_scene.geometry.push_back(g);
	g.mesh = box_mesh;
	r_scene.geometry.push_back(g);
	RenderSceneData::LightInstance li;
	li.light = light;
	li.type = RS::LIGHT_AREA;
	li.transform = light_transform(p_settings);
	r_scene.lights.push_back(li);
	return true;
}

void PenumbraScene::free() {
	if (light.is_valid()) {
		light_storage->light_free(light);
	}
	if (floor_mesh.is_valid()) {
		mesh_storage->mesh_free(floor_mesh);
	}
	if (box_mesh.is_valid()) {
		mesh_storage->mesh_free(box_mesh);
	}
	if (material.is_valid()) {
		material_storage->material_free(material);
	}
	light = RID();
	floor_mesh = RID();
	box_mesh = RID();
	material = RID();
}

void PenumbraScene::visibility_error(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, int p_width,
		const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int p_ref_width, int p_ref_height,
		int p_step, double &r_rmse, double *r_penumbra_rmse) {
	r_rmse = 1.0;
	if (r_penumbra_rmse) {
		*r_penumbra_rmse = -1.0;
	}
	ERR_FAIL_COND_MSG(p_step < 1 || p_width < 1 || p_ref_width < 1 || p_ref_height < 1, "PenumbraScene::visibility_error: bad image size or step.");
	ERR_FAIL_COND_MSG(p_open.size() != p_shadowed.size() || p_ref_open.size() != p_ref_shadowed.size(), "PenumbraScene::visibility_error: open and shadowed images differ in size.");
	ERR_FAIL_COND_MSG(p_ref_open.size() < size_t(p_ref_width) * size_t(p_ref_height) * 4, "PenumbraScene::visibility_error: the reference image is smaller than its size.");
	const size_t height = p_open.size() / (size_t(p_width) * 4);
	double sum = 0.0, penumbra_sum = 0.0;
	int n = 0, penumbra_n = 0;
	for (int y = 0; y < p_ref_height; y++) {
		size_t ey = size_t(y) * p_step + p_step / 2;
		if (ey >= height) {
			break;
		}
		for (int x = 0; x < p_ref_width; x++) {
			size_t ex = size_t(x) * p_step + p_step / 2;
			if (ex >= size_t(p_width)) {
				break;
			}
			size_t e = (ey * size_t(p_width) + ex) * 4;
			size_t r = (size_t(y) * size_t(p_ref_width) + size_t(x)) * 4;
			if (p_open[e] <= 1e-3f || p_ref_open[r] <= 1e-3f) {
				continue;
			}
			double v = std::min(std::max(double(p_shadowed[e] / p_open[e]), 0.0), 1.5);
			double vr = std::min(std::max(double(p_ref_shadowed[r] / p_ref_open[r]), 0.0), 1.5);
			double d2 = (v - vr) * (v - vr);
			sum += d2;
			n++;
			if (vr > 0.02 && vr < 0.98) {
				penumbra_sum += d2;
				penumbra_n++;
			}
		}
	}
	if (n > 0) {
		r_rmse = std::sqrt(sum / n);
	}
	if (r_penumbra_rmse && penumbra_n > 0) {
		*r_penumbra_rmse = std::sqrt(penumbra_sum / penumbra_n);
	}
}
