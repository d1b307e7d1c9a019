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
	if (env.sky_type == RS::SKY_MATERIAL_PHYSICAL) {
		return SkyModel::from_physical(env.physical_sky, env.bg_energy, sun, sun_dir, sun_color, sun_energy, sun_size);
	}
	return SkyModel::from_procedural(env.sky, env.bg_energy, sun, sun_dir, sun_color, sun_energy, sun_size);
}

SkyModel SkyModel::from_physical(const RS::PhysicalSkyParams &p_params, float p_bg_energy, bool p_sun, const Vector3 &p_sun_direction, const Color &p_sun_color, float p_sun_energy, float p_sun_angular_distance_deg) {
	SkyModel m;
	m.type = TYPE_PHYSICAL;
	m.sun_enabled = p_sun;
	m.exposure = p_params.energy_multiplier * p_bg_energy;
	m.physical_ground = _lin(p_params.ground_color);
	m.mie_eccentricity = p_params.mie_eccentricity;
	if (!p_sun) {
		return m;
	}
	Vector3 d = p_sun_direction.normalized();
	m.sun_direction = d == Vector3() ? Vector3(0, 1, 0) : d;
	m.sun_zenith_cos = std::fmin(std::fmax(m.sun_direction.y, -1.0f), 1.0f);
	m.sun_energy = std::fmax(0.0f, 0.757f * m.sun_zenith_cos) * p_sun_energy;
	m.sun_fade = 1.0f - std::fmin(std::fmax(1.0f - std::exp(m.sun_direction.y), 0.0f), 1.0f);
	m.rayleigh_beta = _lin(p_params.rayleigh_color) * ((p_params.rayleigh_coefficient - (1.0f - m.sun_fade)) * 1.0e-4f);
	m.mie_beta = _lin(p_params.mie_color) * (p_params.turbidity * p_params.mie_coefficient * 4.34e-4f);
	m.physical_sun_color = _lin(p_sun_color);
	const float size = Math::deg_to_rad(p_sun_angular_distance_deg) * p_params.sun_disk_scale;
	m.sun_size = Math::deg_to_rad(p_sun_angular_distance_deg);
	m.disk_cos_outer = std::cos(size);
	m.disk_cos_inner = std::cos(size * 0.5f);
	m.sun_radiance = m.physical_sun_color * m.sun_energy; // For reference: the disk's unextinguished colour.
	return m;
}

static float _smoothstep(float p_e0, float p_e1, float p_x) {
	const float t = std::fmin(std::fmax((p_x - p_e0) / (p_e1 - p_e0), 0.0f), 1.0f);
	return t * t * (3.0f - 2.0f * t);
}

Vector3 SkyModel::evaluate_physical(const Vector3 &p_dir) const {
	if (!sun_enabled) {
		return Vector3();
	}
	const float pi = float(Math::PI);
	const float mu = std::fmax(0.0f, p_dir.y);
	const float optical_mass = 1.0f / (mu + 0.15f * std::pow(3.885f + 54.5f * mu, -1.253f));
	auto ex = [](float p_v) { return std::exp(p_v); };
	const Vector3 depth = rayleigh_beta * (8.4e3f * optical_mass) + mie_beta * (1.25e3f * optical_mass);
	const Vector3 extinction(ex(-depth.x), ex(-depth.y), ex(-depth.z));
	const float c = p_dir.dot(sun_direction);
	const float half = c * 0.5f + 0.5f;
	const float phase_r = (3.0f / (16.0f * pi)) * (1.0f + half * half);
	const float g = mie_eccentricity;
	const float phase_m = (1.0f / (4.0f * pi)) * (1.0f - g * g) / std::pow(std::fmax(1.0f + g * g - 2.0f * g * c, 1e-6f), 1.5f);
	const Vector3 beta_sum = rayleigh_beta + mie_beta;
	const Vector3 num = (rayleigh_beta * phase_r + mie_beta * phase_m) * sun_energy;
	const Vector3 scatter(num.x / std::fmax(beta_sum.x, 1e-12f), num.y / std::fmax(beta_sum.y, 1e-12f), num.z / std::fmax(beta_sum.z, 1e-12f));
	const float horizon_mix = std::fmin(std::fmax(std::pow(1.0f - sun_zenith_cos, 5.0f), 0.0f), 1.0f);
	const float ground_mix = _smoothstep(-0.1f, 0.1f, p_dir.y);
	Vector3 result;
	for (int k = 0; k < 3; k++) {
		float lin = std::pow(std::fmax(scatter[k] * (1.0f - extinction[k]), 0.0f), 1.5f);
		lin *= 1.0f + (std::pow(std::fmax(scatter[k] * extinction[k], 0.0f), 0.5f) - 1.0f) * horizon_mix;
		lin *= physical_ground[k] + (1.0f - physical_ground[k]) * ground_mix;
		float disk = 0.0f;
		if (disk_cos_inner > disk_cos_outer) {
			disk = _smoothstep(disk_cos_outer, disk_cos_inner, c);
		}
		const float col = lin + sun_energy * extinction[k] * disk * physical_sun_color[k];
		result[k] = std::pow(std::fmax(col, 0.0f), 1.0f / (1.2f + 1.2f * sun_fade)) * exposure;
	}
	return result;
}

Vector3 SkyModel::evaluate(const Vector3 &p_dir) const {
	return type == TYPE_PHYSICAL ? evaluate_physical(p_dir) : evaluate_procedural(p_dir);
}

Vector3 SkyModel::evaluate_procedural(const Vector3 &p_dir) const {
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
	const Vector3 vectors[10] = { sky_top, sky_horizon, ground_bottom, ground_horizon, sun_direction, sun_radiance, rayleigh_beta, mie_beta, physical_ground, physical_sun_color };
	for (const Vector3 &v : vectors) {
		mix(&v.x, sizeof(float));
		mix(&v.y, sizeof(float));
		mix(&v.z, sizeof(float));
	}
	const float scalars[13] = { sky_curve, ground_curve, sun_angle_max, sun_curve, sun_size, mie_eccentricity, sun_fade, sun_energy, sun_zenith_cos, exposure, disk_cos_outer, disk_cos_inner, float(type) };
	mix(scalars, sizeof(scalars));
	const uint8_t sun = sun_enabled ? 1 : 0;
	mix(&sun, 1);
	return h;
}
