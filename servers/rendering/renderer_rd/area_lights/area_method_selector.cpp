/**************************************************************************/
/*  area_method_selector.cpp                                              */
/**************************************************************************/
/* godot-area: AUTO area shading resolution (see area_method_selector.h). */

#include "servers/rendering/renderer_rd/area_lights/area_method_selector.h"

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {
#include "servers/rendering/renderer_rd/area_lights/area_method_error_table.inc"

float median_of(std::vector<float> &r_values) {
	std::sort(r_values.begin(), r_values.end());
	const size_t n = r_values.size();
	return (n % 2) ? r_values[n / 2] : 0.5f * (r_values[n / 2 - 1] + r_values[n / 2]);
}

// Distance from p_point to the closest point of p_box (0 inside).
float distance_to_box(const AABB &p_box, const Vector3 &p_point) {
	Vector3 lo = p_box.position;
	Vector3 hi = p_box.position + p_box.size;
	Vector3 d;
	for (int i = 0; i < 3; i++) {
		d[i] = std::fmax(std::fmax(lo[i] - p_point[i], p_point[i] - hi[i]), 0.0f);
	}
	return d.length();
}

bool is_unset(const AABB &p_box) {
	return p_box.size.x <= 0.0f && p_box.size.y <= 0.0f && p_box.size.z <= 0.0f;
}
} // namespace

static_assert(AreaMethodSelector::CANDIDATE_COUNT == int(RS::LIGHT_AREA_SHADING_AUTO), "AUTO chooses among the methods listed before it.");

float AreaMethodSelector::get_error_budget() {
	GLOBAL_DEF(SETTING_DEFAULT_ROUGHNESS, DEFAULT_ROUGHNESS);
	float v = float(GLOBAL_DEF(SETTING_ERROR_BUDGET, DEFAULT_ERROR_BUDGET).to_float());
	if (!std::isfinite(v) || v < 0.0f) {
		ERR_PRINT(vformat("%s must be a finite value >= 0 (mean LDR-FLIP); got %g. Using %g.", SETTING_ERROR_BUDGET, double(v), double(DEFAULT_ERROR_BUDGET)));
		return DEFAULT_ERROR_BUDGET;
	}
	return v;
}

float AreaMethodSelector::get_default_roughness() {
	GLOBAL_DEF(SETTING_ERROR_BUDGET, DEFAULT_ERROR_BUDGET);
	float v = float(GLOBAL_DEF(SETTING_DEFAULT_ROUGHNESS, DEFAULT_ROUGHNESS).to_float());
	if (!std::isfinite(v) || v < 0.0f || v > 1.0f) {
		ERR_PRINT(vformat("%s must be in 0..1; got %g. Using %g.", SETTING_DEFAULT_ROUGHNESS, double(v), double(DEFAULT_ROUGHNESS)));
		return DEFAULT_ROUGHNESS;
	}
	return v;
}

int AreaMethodSelector::get_roughness_bin_count() {
	return TABLE_ROUGHNESS_BINS;
}

int AreaMethodSelector::get_size_bin_count() {
	return TABLE_SIZE_BINS;
}

int AreaMethodSelector::get_table_mc_samples() {
	return TABLE_MC_SAMPLES;
}

int AreaMethodSelector::roughness_bin(float p_roughness) {
	if (!std::isfinite(p_roughness)) {
		return TABLE_ROUGHNESS_BINS - 1;
	}
	int best = 0;
	for (int i = 1; i < TABLE_ROUGHNESS_BINS; i++) {
		if (std::fabs(TABLE_ROUGHNESS[i] - p_roughness) < std::fabs(TABLE_ROUGHNESS[best] - p_roughness)) {
			best = i;
		}
	}
	return best;
}

int AreaMethodSelector::size_bin(float p_size_over_distance) {
	if (!(p_size_over_distance >= 0.0f)) { // NaN too.
		return 0;
	}
	int bin = 0;
	while (bin < TABLE_SIZE_BINS - 1 && p_size_over_distance >= TABLE_SIZE_EDGES[bin]) {
		bin++;
	}
	return bin;
}

float AreaMethodSelector::predict_error(RS::LightAreaShadingMethod p_method, float p_size_over_distance, float p_roughness, int p_samples) {
	const int m = int(p_method);
	if (m < 0 || m >= CANDIDATE_COUNT) {
		return std::numeric_limits<float>::infinity();
	}
	float e = TABLE_ERROR[m][roughness_bin(p_roughness)][size_bin(p_size_over_distance)];
	if (p_method == RS::LIGHT_AREA_SHADING_STOCHASTIC) {
		const int n = std::max(p_samples, 1);
		e *= std::sqrt(float(TABLE_MC_SAMPLES) / float(n));
	}
	return e;
}

float AreaMethodSelector::relative_cost(RS::LightAreaShadingMethod p_method, int p_samples) {
	const int m = int(p_method);
	if (m < 0 || m >= CANDIDATE_COUNT) {
		return std::numeric_limits<float>::infinity();
	}
	if (p_method == RS::LIGHT_AREA_SHADING_STOCHASTIC) {
		return TABLE_COST[m] + TABLE_COST_PER_MC_SAMPLE * float(std::max(p_samples, 1));
	}
	return TABLE_COST[m];
}

RS::LightAreaShadingMethod AreaMethodSelector::choose(float p_size_over_distance, float p_roughness, float p_budget, int p_samples) {
	int cheapest = -1;
	int most_accurate = 0;
	float best_error = std::numeric_limits<float>::infinity();
	for (int m = 0; m < CANDIDATE_COUNT; m++) {
		const RS::LightAreaShadingMethod method = RS::LightAreaShadingMethod(m);
		const float e = predict_error(method, p_size_over_distance, p_roughness, p_samples);
		if (e < best_error) {
			best_error = e;
			most_accurate = m;
		}
		if (e <= p_budget && (cheapest < 0 || relative_cost(method, p_samples) < relative_cost(RS::LightAreaShadingMethod(cheapest), p_samples))) {
			cheapest = m;
		}
	}
	return RS::LightAreaShadingMethod(cheapest >= 0 ? cheapest : most_accurate);
}

AreaMethodSelector::Estimate AreaMethodSelector::estimate(const Transform3D &p_world_from_light, const Vector2 &p_size, const AABB &p_light_aabb, const Vector3 &p_camera_position,
		const std::vector<RenderSceneData::GeometryInstance> *p_geometry, const RendererMeshStorage *p_mesh_storage,
		const RendererMaterialStorage *p_material_storage, float p_default_roughness) {
	Estimate est;
	const Vector3 centre = p_world_from_light.origin;
	const float extent = std::fmax(std::fmax(p_size.x, p_size.y), 0.0f);
	std::vector<float> distances;
	std::vector<float> roughness;
	if (p_geometry) {
		const bool any_box = is_unset(p_light_aabb);
		for (const RenderSceneData::GeometryInstance &g : *p_geometry) {
			if (!any_box && !is_unset(g.aabb) && !p_light_aabb.intersects(g.aabb)) {
				continue;
			}
			est.receivers++;
			distances.push_back(distance_to_box(g.aabb, centre));
			if (!p_material_storage) {
				continue;
			}
			if (g.material_override.is_valid()) {
				roughness.push_back(p_material_storage->material_get_params(g.material_override).roughness);
				continue;
			}
			const int surfaces = p_mesh_storage ? p_mesh_storage->mesh_get_surface_count(g.mesh) : 0;
			for (int s = 0; s < surfaces; s++) {
				RID mat = p_mesh_storage->mesh_surface_get_material(g.mesh, s);
				roughness.push_back(mat.is_valid() ? p_material_storage->material_get_params(mat).roughness : RS::MaterialParams().roughness);
			}
		}
	}
	// A receiver that contains the light centre says nothing about the distance: keep d >= 5 % of the size.
	float d = distances.empty() ? (p_camera_position - centre).length() : median_of(distances);
	d = std::fmax(d, std::fmax(0.05f * extent, 1e-3f));
	est.size_over_distance = extent / d;
	est.roughness = roughness.empty() ? p_default_roughness : median_of(roughness);
	return est;
}
