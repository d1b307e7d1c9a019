/**************************************************************************/
/*  penumbra_scene.cpp                                                    */
/**************************************************************************/
/* godot-area: the penumbra scene of the shadow benchmarks (see the       */
/* header).                                                               */

#include "modules/benchmark/penumbra_scene.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering/storage/light_storage.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"
#include "servers/rendering_server.h"

#include <algorithm>
#include <cmath>

Vector3 PenumbraScene::box_half_extents(const Settings &p_settings) {
	const float h = p_settings.box_half;
	return Vector3(h, p_settings.box_half_height < 0.0f ? h : p_settings.box_half_height, p_settings.box_half_depth < 0.0f ? h : p_settings.box_half_depth);
}

RS::SurfaceData PenumbraScene::make_plane(float p_half) {
	RS::SurfaceData s;
	PlaneMesh::create_plane_arrays(s, Vector2(p_half * 2, p_half * 2), 0, 0, Vector3(), PlaneMesh::FACE_Y);
	return s;
}

RS::SurfaceData PenumbraScene::make_box(const Vector3 &p_center, const Vector3 &p_half) {
	RS::SurfaceData s;
	BoxMesh::create_box_arrays(s, p_half * 2, 0, 0, 0);
	for (Vector3 &v : s.vertices) {
		v += p_center;
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

bool PenumbraScene::create_in_server(RenderingServer *p_rs, int p_width, int p_height, const Settings &p_settings) {
	ERR_FAIL_NULL_V_MSG(p_rs, false, "PenumbraScene: no RenderingServer.");
	free();
	rs = p_rs;
	view_width = p_width;
	view_height = p_height;
	scenario = rs->scenario_create();
	environment = rs->environment_create();
	rs->environment_set_background(environment, RS::ENV_BG_COLOR);
	rs->environment_set_bg_color(environment, Color(0, 0, 0, 1));
	rs->environment_set_ambient_light(environment, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
	rs->scenario_set_environment(scenario, environment);
	floor_mesh = rs->mesh_create();
	rs->mesh_add_surface(floor_mesh, make_plane(p_settings.floor_half));
	box_mesh = rs->mesh_create();
	rs->mesh_add_surface(box_mesh, make_box(p_settings.box_center, box_half_extents(p_settings)));
	material = rs->material_create();
	rs->material_set_params(material, lambert());
	light = rs->area_light_create();
	rs->light_area_set_size(light, p_settings.light_size);
	rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, p_settings.light_energy);
	rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, p_settings.light_range);
	rs->light_set_param(light, RS::LIGHT_PARAM_ATTENUATION, 0.0f);
	RID *instances[3] = { &floor_instance, &box_instance, &light_instance };
	const RID bases[3] = { floor_mesh, box_mesh, light };
	for (int i = 0; i < 3; i++) {
		*instances[i] = rs->instance_create();
		rs->instance_set_base(*instances[i], bases[i]);
		rs->instance_set_scenario(*instances[i], scenario);
		if (i < 2) {
			rs->instance_geometry_set_material_override(*instances[i], material);
		}
	}
	rs->instance_set_transform(light_instance, light_transform(p_settings));
	camera = rs->camera_create();
	viewport = rs->viewport_create();
	rs->viewport_set_size(viewport, p_width, p_height);
	rs->viewport_set_scenario(viewport, scenario);
	rs->viewport_attach_camera(viewport, camera);
	rs->viewport_set_active(viewport, true);
	set_view(make_top_view(p_width));
	if (!viewport.is_valid() || !light.is_valid() || !floor_instance.is_valid()) {
		free();
		ERR_FAIL_V_MSG(false, "PenumbraScene: the RenderingServer refused to create the scene's objects.");
	}
	return true;
}

void PenumbraScene::set_view(const RenderSceneData &p_view) {
	ERR_FAIL_NULL_MSG(rs, "PenumbraScene::set_view: the scene is not in a server.");
	rs->camera_set_perspective(camera, p_view.fovy_degrees, p_view.z_near, p_view.z_far);
	rs->camera_set_transform(camera, p_view.cam_transform);
}

void PenumbraScene::set_light_transform(const Transform3D &p_transform) {
	ERR_FAIL_NULL_MSG(rs, "PenumbraScene::set_light_transform: the scene is not in a server.");
	rs->instance_set_transform(light_instance, p_transform);
}

std::vector<float> PenumbraScene::render() {
	ERR_FAIL_NULL_V_MSG(rs, std::vector<float>(), "PenumbraScene::render: the scene is not in a server.");
	rs->draw();
	return rs->viewport_get_texture_data(viewport).get_data();
}

void PenumbraScene::free() {
	if (!rs) {
		return;
	}
	const RID rids[] = { viewport, camera, light_instance, box_instance, floor_instance, light, material, box_mesh, floor_mesh, scenario, environment };
	for (RID r : rids) {
		if (r.is_valid()) {
			rs->free(r);
		}
	}
	rs = nullptr;
	viewport = camera = light_instance = box_instance = floor_instance = light = material = box_mesh = floor_mesh = scenario = environment = RID();
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

std::vector<float> PenumbraScene::visibility_image(const std::vector<float> &p_open, const std::vector<float> &p_shadowed) {
	ERR_FAIL_COND_V_MSG(p_open.size() != p_shadowed.size(), std::vector<float>(), "PenumbraScene::visibility_image: open and shadowed images differ in size.");
	std::vector<float> v(p_open.size() / 4, -1.0f);
	for (size_t i = 0; i < v.size(); i++) {
		if (p_open[i * 4] > 1e-3f) {
			v[i] = std::min(std::max(p_shadowed[i * 4] / p_open[i * 4], 0.0f), 1.5f);
		}
	}
	return v;
}

int PenumbraScene::count_banded_pixels(const std::vector<float> &p_visibility, int p_width, int p_height, int *r_penumbra, float p_step, std::vector<uint8_t> *r_mask) {
	ERR_FAIL_COND_V_MSG(p_width < 1 || p_height < 1 || p_visibility.size() < size_t(p_width) * size_t(p_height), 0, "PenumbraScene::count_banded_pixels: bad image size.");
	const int R = 6; // Window each side (pixels) in which the plateau's two steps are looked for.
	std::vector<uint8_t> banded(size_t(p_width) * size_t(p_height), 0);
	auto penumbra = [](float p_v) { return p_v > 0.02f && p_v < 0.98f; };
	std::vector<float> g;
	// One line (a row or a column): pixel i at p_visibility[p_start + i * p_stride]. g[i]: the signed central
	// step at i (NAN next to unlit pixels).
	auto scan = [&](size_t p_start, size_t p_stride, int p_count) {
		auto at = [&](int p_i) { return p_visibility[p_start + size_t(p_i) * p_stride]; };
		g.assign(size_t(p_count), NAN);
		for (int i = 1; i + 1 < p_count; i++) {
			if (at(i - 1) >= 0.0f && at(i) >= 0.0f && at(i + 1) >= 0.0f) {
				g[i] = 0.5f * (at(i + 1) - at(i - 1));
			}
		}
		for (int i = 1; i + 1 < p_count; i++) {
			if (!penumbra(at(i)) || std::isnan(g[i])) {
				continue;
			}
			// The steepest step going each way within R pixels, stopping at unlit pixels.
			float best[2] = { 0.0f, 0.0f };
			for (int side = 0; side < 2; side++) {
				for (int d = 1; d <= R; d++) {
					int k = side ? i + d : i - d;
					if (k < 0 || k >= p_count || std::isnan(g[k])) {
						break;
					}
					if (std::fabs(g[k]) > std::fabs(best[side])) {
						best[side] = g[k];
					}
				}
			}
			float lo = std::min(std::fabs(best[0]), std::fabs(best[1]));
			if (lo >= p_step && (best[0] > 0.0f) == (best[1] > 0.0f) && std::fabs(g[i]) * 3.0f <= lo) {
				banded[p_start + size_t(i) * p_stride] = 1;
			}
		}
	};
	for (int y = 0; y < p_height; y++) {
		scan(size_t(y) * size_t(p_width), 1, p_width);
	}
	for (int x = 0; x < p_width; x++) {
		scan(size_t(x), size_t(p_width), p_height);
	}
	int count = 0, penumbra_count = 0;
	for (size_t i = 0; i < banded.size(); i++) {
		count += banded[i];
		penumbra_count += penumbra(p_visibility[i]) ? 1 : 0;
	}
	if (r_penumbra) {
		*r_penumbra = penumbra_count;
	}
	if (r_mask) {
		*r_mask = banded;
	}
	return count;
}

PenumbraScene::ShadowError PenumbraScene::shadow_error(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, int p_width,
		const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int p_ref_width, int p_ref_height, int p_step) {
	ShadowError e;
	visibility_error(p_open, p_shadowed, p_width, p_ref_open, p_ref_shadowed, p_ref_width, p_ref_height, p_step, e.rmse);
	ERR_FAIL_COND_V(p_step < 1 || p_width < 1 || p_open.size() != p_shadowed.size() || p_ref_open.size() != p_ref_shadowed.size() || p_ref_open.size() < size_t(p_ref_width) * size_t(p_ref_height) * 4, e);
	const size_t height = p_open.size() / (size_t(p_width) * 4);
	double sum = 0.0, ref_sum = 0.0;
	std::vector<double> rel;
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
			size_t ei = (ey * size_t(p_width) + ex) * 4;
			size_t ri = (size_t(y) * size_t(p_ref_width) + size_t(x)) * 4;
			if (p_open[ei] <= 1e-3f || p_ref_open[ri] <= 1e-3f) {
				continue;
			}
			// Silhouettes: a reference pixel that straddles two surfaces (the box's top and the floor) is a
			// blend the engine's single sample cannot match whatever its shadows; skip pixels whose open
			// image differs from a 4-neighbour's by more than 10 %.
			bool edge = false;
			const int nx[4] = { -1, 1, 0, 0 };
			const int ny[4] = { 0, 0, -1, 1 };
			for (int n = 0; n < 4 && !edge; n++) {
				int x2 = x + nx[n], y2 = y + ny[n];
				if (x2 < 0 || y2 < 0 || x2 >= p_ref_width || y2 >= p_ref_height) {
					continue;
				}
				float o2 = p_ref_open[(size_t(y2) * size_t(p_ref_width) + size_t(x2)) * 4];
				edge = std::fabs(o2 - p_ref_open[ri]) > 0.1f * p_ref_open[ri];
			}
			if (edge) {
				continue;
			}
			double v = std::min(std::max(double(p_shadowed[ei] / p_open[ei]), 0.0), 1.5);
			double vr = std::min(std::max(double(p_ref_shadowed[ri] / p_ref_open[ri]), 0.0), 1.5);
			if (v >= 0.98 && vr >= 0.98) {
				continue;
			}
			sum += (v - vr) * (v - vr);
			ref_sum += vr;
			rel.push_back(std::fabs(v - vr) / std::max(vr, 0.05));
		}
	}
	e.pixels = int(rel.size());
	if (rel.empty()) {
		e.rel_rmse = 0.0;
		e.p99 = 0.0;
		return e;
	}
	e.rel_rmse = std::sqrt(sum / double(rel.size())) / std::max(ref_sum / double(rel.size()), 1e-6);
	size_t k = std::min(rel.size() - 1, size_t(std::ceil(0.99 * double(rel.size()))) - 1);
	std::nth_element(rel.begin(), rel.begin() + k, rel.end());
	e.p99 = rel[k];
	return e;
}
