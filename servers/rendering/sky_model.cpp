/**************************************************************************/
/*  sky_model.cpp                                                         */
/**************************************************************************/
/* godot-area: sky evaluation and irradiance SH (see sky_model.h).        */

#include "servers/rendering/sky_model.h"

#include "core/math/math_funcs.h"
#include "servers/rendering/storage/light_storage.h"

#include <cmath>
#include <cstring>

static Vector3 _lin(const Color &p_c) {
	Color l = p_c.srgb_to_linear();
	return Vector3(l.r, l.g, l.b);
}

static float _curve_blend(float p_c, float p_curve) {
	// clamp(1 - (1 - c)^(1 / curve), 0, 1); a curve of 0 is a step (1 for any c > 0).
	const float base = std::fmin(std::fmax(1.0f - p_c, 0.0f), 1.0f);
	const float t = p_curve > 0.0f ? 1.0f - std::pow(base, 1.0f / p_curve) : (base < 1.0f ? 1.0f : 0.0f);
	return std::fmin(std::fmax(t, 0.0f), 1.0f);
}

SkyModel SkyModel::from_procedural(const RS::ProceduralSkyParams &p_params, float p_bg_energy, bool p_sun, const Vector3 &p_sun_direction, const Color &p_sun_color, float p_sun_energy, float p_sun_angular_distance_deg) {
	SkyModel m;
	const float e = p_params.energy_multiplier * p_bg_energy;
	m.sky_top = _lin(p_params.sky_top_color) * (p_params.sky_energy_multiplier * e);
	m.sky_horizon = _lin(p_params.sky_horizon_color) * (p_params.sky_energy_multiplier * e);
	m.ground_bottom = _lin(p_params.ground_bottom_color) * (p_params.ground_energy_multiplier * e);
	m.ground_horizon = _lin(p_params.ground_horizon_color) * (p_params.ground_energy_multiplier * e);
	m.sky_curve = p_params.sky_curve;
	m.ground_curve = p_params.ground_curve;
	m.sun_angle_max = Math::deg_to_rad(p_params.sun_angle_max);
	m.sun_curve = p_params.sun_curve;
	m.sun_enabled = p_sun;
	if (p_sun) {
		Vector3 d = p_sun_direction.normalized();
		m.sun_direction = d == Vector3() ? Vector3(0, 1, 0) : d;
		m.sun_radiance = _lin(p_sun_color) * (p_sun_energy * e);
		m.sun_size = Math::deg_to_rad(p_sun_angular_distance_deg);
	}
	return m;
}

SkyModel SkyModel::from_scene_data(const RenderSceneData &p_data, const RendererLightStorage *p_light_storage) {
	const RenderSceneData::EnvironmentData &env = p_data.environment;
	bool sun = false;
	Vector3 sun_dir(0, 1, 0);
	Color sun_color(1, 1, 1, 1);
	float sun_energy = 0.0f, sun_size = 0.0f;
	if (p_light_storage) {
		for (const RenderSceneData::LightInstance &li : p_data.directional_lights) {
			if (!p_light_storage->owns_light(li.light) || p_light_storage->light_directional_get_sky_mode(li.light) == RS::LIGHT_DIRECTIONAL_SKY_MODE_LIGHT_ONLY) {
				continue;
			}
			sun = true;
			sun_dir = li.transform.basis.xform(Vector3(0, 0, 1)); // Towards the light (it shines along -Z).
			sun_color = p_light_storage->light_get_color(li.light);
			sun_energy = p_light_storage->light_get_param(li.light, RS::LIGHT_PARAM_ENERGY);
			sun_size = p_light_storage->light_get_param(li.light, RS::LIGHT_PARAM_SIZE);
			break; // Godot's LIGHT0: the first one.
		}
	}
	return SkyModel::from_procedural(env.sky, env.bg_energy, sun, sun_dir, sun_color, sun_energy, sun_size);
}

Vector3 SkyModel::evaluate(const Vector3 &p_dir) const {
	const float half_pi = float(Math::PI) * 0.5f;
	const float v = std::acos(std::fmin(std::fmax(p_dir.y, -1.0f), 1.0f));
	if (p_dir.y >= 0.0f) {
		Vector3 sky = sky_horizon.lerp(sky_top, _curve_blend(1.0f - v / half_pi, sky_curve));
		if (sun_enabled) {
			const float s = std::acos(std::fmin(std::fmax(sun_direction.dot(p_dir), -1.0f), 1.0f));
			if (s < sun_size) {
				sky = sun_radiance;
			} else if (s < sun_angle_max) {
				const float c2 = (s - sun_size) / std::fmax(sun_angle_max - sun_size, 1e-6f);
				sky = sun_radiance.lerp(sky, _curve_blend(c2, sun_curve));
			}
		}
		return sky;
	}
	return ground_horizon.lerp(ground_bottom, _curve_blend((v - half_pi) / half_pi, ground_curve));
}

void SkyModel::sh_basis(const Vector3 &p_n, float r_y[9]) {
	// Ramamoorthi & Hanrahan 2001, eq. 3 (real SH constants).
	const float x = p_n.x, y = p_n.y, z = p_n.z;
	r_y[0] = 0.282095f;
	r_y[1] = 0.488603f * y;
	r_y[2] = 0.488603f * z;
	r_y[3] = 0.488603f * x;
	r_y[4] = 1.092548f * x * y;
	r_y[5] = 1.092548f * y * z;
	r_y[6] = 0.315392f * (3.0f * z * z - 1.0f);
	r_y[7] = 1.092548f * x * z;
	r_y[8] = 0.546274f * (x * x - y * y);
}

void SkyModel::compute_irradiance_sh(float r_sh[9][3], int p_rows) const {
	double acc[9][3] = {};
	const int rows = p_rows < 8 ? 8 : p_rows;
	const int cols = rows * 2;
	const double d_theta = Math::PI / rows, d_phi = 2.0 * Math::PI / cols;
	for (int i = 0; i < rows; i++) {
		const double theta = (i + 0.5) * d_theta; // From +Y.
		const double weight = std::sin(theta) * d_theta * d_phi; // Solid angle of the cell.
		for (int j = 0; j < cols; j++) {
			const double phi = (j + 0.5) * d_phi;
			const Vector3 dir(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
			const Vector3 l = evaluate(dir);
			float y[9];
			sh_basis(dir, y);
			for (int k = 0; k < 9; k++) {
				acc[k][0] += l.x * y[k] * weight;
				acc[k][1] += l.y * y[k] * weight;
				acc[k][2] += l.z * y[k] * weight;
			}
		}
	}
	const double a[9] = { Math::PI, 2.0 * Math::PI / 3.0, 2.0 * Math::PI / 3.0, 2.0 * Math::PI / 3.0, Math::PI / 4.0, Math::PI / 4.0, Math::PI / 4.0, Math::PI / 4.0, Math::PI / 4.0 };
	for (int k = 0; k < 9; k++) {
		for (int c = 0; c < 3; c++) {
			r_sh[k][c] = float(acc[k][c] * a[k]);
		}
	}
}

Vector3 SkyModel::evaluate_sh(const float p_sh[9][3], const Vector3 &p_n) {
	float y[9];
	sh_basis(p_n, y);
	Vector3 e;
	for (int k = 0; k < 9; k++) {
		e += Vector3(p_sh[k][0], p_sh[k][1], p_sh[k][2]) * y[k];
	}
	return e;
}

uint64_t SkyModel::get_hash() const {
	// FNV-1a over the fields (no padding is read: each field is hashed on its own).
	uint64_t h = 1469598103934665603ULL;
	auto mix = [&h](const void *p_data, size_t p_size) {
		const uint8_t *b = static_cast<const uint8_t *>(p_data);
		for (size_t i = 0; i < p_size; i++) {
			h = (h ^ b[i]) * 1099511628211ULL;
		}
	};
	const Vector3 vectors[6] = { sky_top, sky_horizon, ground_bottom, ground_horizon, sun_direction, sun_radiance };
	for (const Vector3 &v : vectors) {
		mix(&v.x, sizeof(float));
		mix(&v.y, sizeof(float));
		mix(&v.z, sizeof(float));
	}
	const float scalars[5] = { sky_curve, ground_curve, sun_angle_max, sun_curve, sun_size };
	mix(scalars, sizeof(scalars));
	const uint8_t sun = sun_enabled ? 1 : 0;
	mix(&sun, 1);
	return h;
}
