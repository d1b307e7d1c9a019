/**************************************************************************/
/*  area_light_integrator.cpp                                             */
/**************************************************************************/
/* godot-area: the reference estimator of one area light (see .h).        */

#include "modules/reference/area_light_integrator.h"

#include "core/error/error_macros.h"
#include "modules/reference/area_light_texture.h"
#include "modules/reference/forward_lights.h"

#include <algorithm>
#include <cmath>

namespace ReferenceBRDF {

/*************************************************************************/
/* Double-precision helpers (local to the samplers)                       */
/*************************************************************************/

static inline double _dot3(const double *p_a, const double *p_b) {
	return p_a[0] * p_b[0] + p_a[1] * p_b[1] + p_a[2] * p_b[2];
}

static inline void _cross3(const double *p_a, const double *p_b, double *r_c) {
	const double c0 = p_a[1] * p_b[2] - p_a[2] * p_b[1];
	const double c1 = p_a[2] * p_b[0] - p_a[0] * p_b[2];
	const double c2 = p_a[0] * p_b[1] - p_a[1] * p_b[0];
	r_c[0] = c0;
	r_c[1] = c1;
	r_c[2] = c2;
}

// Normalises in place; false (vector unchanged) for a zero or non-finite length.
static inline bool _normalize3(double *r_v) {
	const double len = std::sqrt(_dot3(r_v, r_v));
	if (!(len > 0.0) || !std::isfinite(len)) {
		return false;
	}
	r_v[0] /= len;
	r_v[1] /= len;
	r_v[2] /= len;
	return true;
}

static inline void _to3(const Vector3 &p_v, double *r_v) {
	r_v[0] = p_v.x;
	r_v[1] = p_v.y;
	r_v[2] = p_v.z;
}

/*************************************************************************/
/* Spherical rectangle (Urena, Fajardo, King 2013)                       */
/*************************************************************************/

bool SphericalRectangleSampler::setup(const Vector3 &p_origin, const Vector3 &p_corner, const Vector3 &p_edge_x, const Vector3 &p_edge_y) {
	solid_angle = 0.0;
	double ex[3], ey[3], s[3];
	_to3(p_origin, origin);
	_to3(p_edge_x, ex);
	_to3(p_edge_y, ey);
	_to3(p_corner, s);
	const double len_x = std::sqrt(_dot3(ex, ex));
	const double len_y = std::sqrt(_dot3(ey, ey));
	if (!(len_x > 0.0) || !(len_y > 0.0)) {
		return false;
	}
	for (int i = 0; i < 3; i++) {
		ax[i] = ex[i] / len_x;
		ay[i] = ey[i] / len_y;
	}
	_cross3(ax, ay, az);
	const double d[3] = { s[0] - origin[0], s[1] - origin[1], s[2] - origin[2] };
	x0 = _dot3(d, ax);
	y0 = _dot3(d, ay);
	z0 = _dot3(d, az);
	// The frame's z points away from the origin's side, so the rectangle lies at z = z0 < 0.
	if (z0 > 0.0) {
		az[0] = -az[0];
		az[1] = -az[1];
		az[2] = -az[2];
		z0 = -z0;
	}
	const double extent = std::max(std::max(len_x, len_y), std::sqrt(_dot3(d, d)));
	if (!(-z0 > 1e-7 * extent)) {
		return false; // (Nearly) in the rectangle's plane: the parameterisation degenerates.
	}
	x1 = x0 + len_x;
	y1 = y0 + len_y;
	// Corner directions (local frame) and the unit normals of the four great-circle edges.
	const double v00[3] = { x0, y0, z0 }, v01[3] = { x0, y1, z0 }, v10[3] = { x1, y0, z0 }, v11[3] = { x1, y1, z0 };
	double n0[3], n1[3], n2[3], n3[3];
	_cross3(v00, v10, n0);
	_cross3(v10, v11, n1);
	_cross3(v11, v01, n2);
	_cross3(v01, v00, n3);
	if (!_normalize3(n0) || !_normalize3(n1) || !_normalize3(n2) || !_normalize3(n3)) {
		return false;
	}
	// Interior angles of the spherical quadrilateral; its area is their sum minus 2 pi.
	auto angle = [](const double *p_a, const double *p_b) {
		return std::acos(std::min(std::max(-_dot3(p_a, p_b), -1.0), 1.0));
	};
	const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
	b0 = n0[2];
	b1 = n2[2];
	k = 2.0 * Math::PI - g2 - g3;
	solid_angle = g0 + g1 - k;
	// Below ~1e-7 sr the angle sum cancels too much for a trustworthy pdf: sample the area instead.
	if (!(solid_angle > 1e-7) || !std::isfinite(solid_angle)) {
		solid_angle = 0.0;
		return false;
	}
	return true;
}

void SphericalRectangleSampler::sample(double p_u, double p_v, double r_point[3]) const {
	// u: the sub-rectangle [x0, xu] that subtends solid angle u * S (its area as a function of xu inverted
	// in closed form); v: uniform in h = y / sqrt(xu^2 + y^2 + z0^2) along the chosen column.
	const double au = p_u * solid_angle + k;
	const double fu = (std::cos(au) * b0 - b1) / std::sin(au);
	double cu = (fu > 0.0 ? 1.0 : -1.0) / std::sqrt(fu * fu + b0 * b0);
	if (!std::isfinite(cu)) {
		cu = 0.0;
	}
	cu = std::min(std::max(cu, -1.0), 1.0);
	double xu = -(cu * z0) / std::sqrt(std::max(1.0 - cu * cu, 1e-300));
	if (!std::isfinite(xu)) {
		xu = cu > 0.0 ? x1 : x0;
	}
	xu = std::min(std::max(xu, x0), x1);
	const double dd = std::sqrt(xu * xu + z0 * z0);
	const double h0 = y0 / std::sqrt(dd * dd + y0 * y0);
	const double h1 = y1 / std::sqrt(dd * dd + y1 * y1);
	const double hv = h0 + p_v * (h1 - h0);
	const double hv2 = hv * hv;
	double yv = hv2 < 1.0 - 1e-12 ? hv * dd / std::sqrt(1.0 - hv2) : y1;
	yv = std::min(std::max(yv, y0), y1);
	for (int i = 0; i < 3; i++) {
		r_point[i] = origin[i] + xu * ax[i] + yv * ay[i] + z0 * az[i];
	}
}

/*************************************************************************/
/* GGX visible normals (Heitz 2018)                                      */
/*************************************************************************/

void ggx_vndf_sample_normal(const double p_v[3], double p_alpha, double p_u1, double p_u2, double r_h[3]) {
	// Stretch the view into the alpha = 1 configuration (a hemisphere of normals).
	double vh[3] = { p_alpha * p_v[0], p_alpha * p_v[1], p_v[2] };
	_normalize3(vh);
	// Orthonormal frame around vh.
	const double lensq = vh[0] * vh[0] + vh[1] * vh[1];
	double t1[3] = { 1.0, 0.0, 0.0 };
	if (lensq > 0.0) {
		const double inv = 1.0 / std::sqrt(lensq);
		t1[0] = -vh[1] * inv;
		t1[1] = vh[0] * inv;
		t1[2] = 0.0;
	}
	double t2[3];
	_cross3(vh, t1, t2);
	// A point of the projected hemisphere: a unit disk whose half away from the view is compressed by
	// s = (1 + vh.z) / 2.
	const double r = std::sqrt(p_u1);
	const double phi = 2.0 * Math::PI * p_u2;
	const double p1 = r * std::cos(phi);
	double p2 = r * std::sin(phi);
	const double s = 0.5 * (1.0 + vh[2]);
	p2 = (1.0 - s) * std::sqrt(std::max(1.0 - p1 * p1, 0.0)) + s * p2;
	const double p3 = std::sqrt(std::max(1.0 - p1 * p1 - p2 * p2, 0.0));
	double nh[3];
	for (int i = 0; i < 3; i++) {
		nh[i] = p1 * t1[i] + p2 * t2[i] + p3 * vh[i];
	}
	// Unstretch.
	r_h[0] = p_alpha * nh[0];
	r_h[1] = p_alpha * nh[1];
	r_h[2] = std::max(nh[2], 0.0);
	if (!_normalize3(r_h)) {
		r_h[0] = 0.0;
		r_h[1] = 0.0;
		r_h[2] = 1.0;
	}
}

double ggx_vndf_reflection_pdf(double p_nov, double p_noh, double p_noh2_complement, double p_alpha) {
	if (!(p_nov > 0.0) || !(p_noh > 0.0)) {
		return 0.0;
	}
	const double a2 = p_alpha * p_alpha;
	// D = a2 / (pi (noh^2 (a2 - 1) + 1)^2), with noh^2 (a2 - 1) + 1 = a2 noh^2 + (1 - noh^2).
	const double f = a2 * p_noh * p_noh + p_noh2_complement;
	const double D = a2 / (Math::PI * f * f);
	// Smith G1 of GGX: 2 n.v / (n.v + sqrt(a2 + (1 - a2) (n.v)^2)).
	const double G1 = 2.0 * p_nov / (p_nov + std::sqrt(a2 + (1.0 - a2) * p_nov * p_nov));
	return G1 * D / (4.0 * p_nov);
}

/*************************************************************************/
/* The integral                                                          */
/*************************************************************************/

// Lowest GGX alpha that is importance sampled (roughness 0.01); below, light samples only (the twin's
// D is then a float-precision spike the light samples integrate as well as anything).
static constexpr double AREA_MIS_MIN_ALPHA = 1e-4;
// Lobe window: half-size (m) = AREA_LOBE_SCALE * alpha * t / cos + AREA_LOBE_REACH * (distance from the
// lobe's centre to the rectangle), t the distance along the mirror direction to the light plane.
static constexpr double AREA_LOBE_SCALE = 4.0;
static constexpr double AREA_LOBE_REACH = 3.0;

namespace {

// A rectangle of the light plane, [u0, u1] x [v0, v1] in the light's local metres (axis_x, axis_y from
// its centre), sampled uniformly in solid angle, or in area where that is ill-conditioned.
struct AreaRectStrategy {
	double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
	Vector3 corner, edge_x, edge_y;
	double area = 0.0;
	SphericalRectangleSampler sphere;
	bool solid = false;

	void setup(const AreaLightData &p_light, const Vector3 &p_vertex, double p_u0, double p_u1, double p_v0, double p_v1, bool p_allow_solid) {
		u0 = p_u0;
		u1 = p_u1;
		v0 = p_v0;
		v1 = p_v1;
		corner = p_light.center + p_light.axis_x * float(u0) + p_light.axis_y * float(v0);
		edge_x = p_light.axis_x * float(u1 - u0);
		edge_y = p_light.axis_y * float(v1 - v0);
		area = (u1 - u0) * (v1 - v0);
		solid = p_allow_solid && sphere.setup(p_vertex, corner, edge_x, edge_y);
	}
	Vector3 sample(const double *p_uv) const {
		if (solid) {
			double q[3];
			sphere.sample(p_uv[0], p_uv[1], q);
			return Vector3(float(q[0]), float(q[1]), float(q[2]));
		}
		return corner + edge_x * float(p_uv[0]) + edge_y * float(p_uv[1]);
	}
	// Solid-angle pdf of a direction reaching the light plane at local (u, v), distance^2 p_dist2, cosine
	// p_cos_light there; p_inside skips the bounds test (the strategy's own samples).
	double pdf(double p_u, double p_v, double p_dist2, double p_cos_light, bool p_inside) const {
		if (!p_inside && (p_u < u0 || p_u > u1 || p_v < v0 || p_v > v1)) {
			return 0.0;
		}
		if (solid) {
			return 1.0 / sphere.get_solid_angle();
		}
		return p_cos_light > 0.0 ? p_dist2 / (area * p_cos_light) : INFINITY;
	}
};

} // namespace

AreaLightIntegral area_light_integrate(const AreaLightData &p_light, const AreaLightShadingPoint &p_point, AreaLightSampling p_sampling, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng, const AreaLightOcclusionTest &p_occluded) {
	AreaLightIntegral out;
	const float area = p_light.get_area();
	if (!(area > 0.0f) || p_light.radiance == Vector3()) {
		return out;
	}
	const float front = area_light_front_distance(p_light, p_point.vertex);
	if (!(front > 0.0f)) {
		return out; // One-sided: nothing on or behind the light plane is lit.
	}
	const float window = area_light_window(area_light_closest_distance(p_light, p_point.vertex), p_light.range, p_light.attenuation);
	if (window <= 0.0f) {
		return out;
	}
	out.evaluated = true;
	const double half_x = 0.5 * double(p_light.size_x), half_y = 0.5 * double(p_light.size_y);

	// Strategy 0: the whole light, by solid angle (area for AREA or when ill-conditioned).
	AreaRectStrategy light_rect;
	light_rect.setup(p_light, p_point.vertex, -half_x, half_x, -half_y, half_y, p_sampling != AREA_LIGHT_SAMPLING_AREA);

	// Strategy 1: GGX visible normals, on a specular lobe seen from above the shading normal.
	const double alpha = double(p_point.roughness) * double(p_point.roughness);
	const double nov = double(p_point.N.dot(p_point.V));
	const bool has_specular = p_point.specular_enabled && p_light.specular_amount != 0.0f && (p_point.f0 != Vector3() || p_point.f90 != 0.0f);
	const bool has_diffuse = p_point.diffuse_weight != Vector3();
	const bool use_vndf = (p_sampling == AREA_LIGHT_SAMPLING_MIS || p_sampling == AREA_LIGHT_SAMPLING_BRDF) && has_specular && alpha >= AREA_MIS_MIN_ALPHA && nov > 1e-6;
	// MIS: the BRDF strategy is a mixture of cosine-weighted samples (the diffuse lobe, chosen with
	// probability cos_share, at most 1/2) and GGX samples, and the whole BRDF (diffuse + specular) is
	// weighted over all strategies. Cosine samples matter under lights covering much of the hemisphere,
	// where the cosine factor makes solid-angle samples noisy.
	double cos_share = 0.0;
	if (p_sampling == AREA_LIGHT_SAMPLING_MIS && has_diffuse) {
		const double d = (double(p_point.diffuse_weight.x) + p_point.diffuse_weight.y + p_point.diffuse_weight.z) / 3.0;
		const double s = (double(p_point.f0.x) + p_point.f0.y + p_point.f0.z) / 3.0;
		cos_share = use_vndf ? std::min(0.5, std::max(d, 0.0) / (std::max(d, 0.0) + std::max(s, 0.04))) : 1.0;
	}
	const bool use_brdf = use_vndf || cos_share > 0.0;
	const bool brdf_only = p_sampling == AREA_LIGHT_SAMPLING_BRDF && use_brdf; // Light samples carry the diffuse term only.
	out.brdf_sampling = use_brdf;

	double n[3], t[3], b[3], v_local[3] = { 0.0, 0.0, 1.0 }, v[3];
	_to3(p_point.N, n);
	_normalize3(n);
	_to3(p_point.V, v);
	{
		const double helper[3] = { std::fabs(n[0]) < 0.9 ? 1.0 : 0.0, std::fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0 };
		_cross3(helper, n, t);
		_normalize3(t);
		_cross3(n, t, b);
		v_local[0] = _dot3(v, t);
		v_local[1] = _dot3(v, b);
		v_local[2] = _dot3(v, n);
	}

	// Strategy 2 (MIS only): the lobe window, a sub-rectangle of the light around the point where the
	// mirror direction meets the light plane, sampled by solid angle: the part of the light where a narrow
	// lobe (or its tail) lies, which neither the whole-light samples (too sparse there) nor the GGX samples
	// (mostly missing the light when the lobe straddles or misses its edge) cover densely.
	AreaRectStrategy lobe_rect;
	bool use_lobe = false;
	if (use_vndf && !brdf_only) {
		double e[3];
		_to3(p_light.emit_dir, e);
		double r[3];
		for (int i = 0; i < 3; i++) {
			r[i] = 2.0 * nov * n[i] - v[i];
		}
		const double cos_r = -_dot3(r, e);
		if (cos_r > 1e-3) {
			const double dist = double(front) / cos_r;
			double c[3], rel[3], ax[3], ay[3];
			_to3(p_light.axis_x, ax);
			_to3(p_light.axis_y, ay);
			for (int i = 0; i < 3; i++) {
				c[i] = double(p_point.vertex[i]) + r[i] * dist;
				rel[i] = c[i] - double(p_light.center[i]);
			}
			const double cu = _dot3(rel, ax), cv = _dot3(rel, ay);
			const double du = std::max(std::fabs(cu) - half_x, 0.0), dv = std::max(std::fabs(cv) - half_y, 0.0);
			const double h = AREA_LOBE_SCALE * alpha * dist / cos_r + AREA_LOBE_REACH * std::sqrt(du * du + dv * dv);
			const double u0 = std::max(cu - h, -half_x), u1 = std::min(cu + h, half_x);
			const double v0 = std::max(cv - h, -half_y), v1 = std::min(cv + h, half_y);
			// Only where the mirror direction misses the light (a lobe centred on the light is sampled
			// almost perfectly by the GGX samples, and a third strategy would only take samples from
			// them), and when the window is a proper, non-degenerate part of the light.
			const bool outside = du > 0.0 || dv > 0.0;
			if (outside && u1 - u0 > 1e-6 * half_x && v1 - v0 > 1e-6 * half_y && (u1 - u0) * (v1 - v0) < 0.5 * 4.0 * half_x * half_y) {
				lobe_rect.setup(p_light, p_point.vertex, u0, u1, v0, v1, true);
				use_lobe = true;
			}
		}
	}

	const Vector3 emit_dir = p_light.emit_dir;
	// pdf of the BRDF strategy (cosine / GGX mixture) for direction p_L.
	auto brdf_pdf = [&](const Vector3 &p_L) -> double {
		const double l[3] = { p_L.x, p_L.y, p_L.z };
		double pdf = cos_share > 0.0 ? cos_share * std::max(_dot3(n, l), 0.0) / Math::PI : 0.0;
		if (cos_share < 1.0) {
			double h[3] = { v[0] + l[0], v[1] + l[1], v[2] + l[2] };
			if (_normalize3(h)) {
				double c[3];
				_cross3(n, h, c);
				pdf += (1.0 - cos_share) * ggx_vndf_reflection_pdf(nov, _dot3(n, h), _dot3(c, c), alpha);
			}
		}
		return pdf;
	};
	uint64_t shadow_rays = 0;
	// Shadow test towards the rectangle point p_target (true = visible).
	auto visible = [&](const Vector3 &p_L, const Vector3 &p_target) -> bool {
		if (!p_occluded) {
			return true;
		}
		const Vector3 side = p_point.ng.dot(p_L) >= 0.0f ? p_point.ng : -p_point.ng;
		const Vector3 origin = p_point.vertex + side * p_point.offset;
		const Vector3 to_target = p_target - origin;
		const float d = to_target.length();
		if (!(d > 2.0f * p_point.offset)) {
			return true;
		}
		shadow_rays++;
		return !p_occluded(origin, to_target / d, d - p_point.offset);
	};

	enum {
		STRATEGY_LIGHT,
		STRATEGY_BRDF,
		STRATEGY_LOBE,
	};
	// Evaluates the direction towards p_target (a point of the light) drawn by p_strategy, adding the
	// diffuse term (light strategy only) over its pdf and the specular term weighted by the power
	// heuristic over every specular strategy in use.
	auto evaluate = [&](int p_strategy, const Vector3 &p_target, double *r_value) {
		const Vector3 to_light = p_target - p_point.vertex;
		const float dist2 = to_light.length_squared();
		if (!(dist2 > 0.0f)) {
			return;
		}
		const Vector3 L = to_light / std::sqrt(dist2);
		const double cos_light = -double(L.dot(emit_dir));
		if (!(cos_light > 0.0) || !(p_point.N.dot(L) > 0.0f)) {
			return;
		}
		const Vector3 rel = p_target - p_light.center;
		const double u = double(rel.dot(p_light.axis_x)), w = double(rel.dot(p_light.axis_y));
		const double p_light_pdf = light_rect.pdf(u, w, dist2, cos_light, true);
		const double p_brdf_pdf = use_brdf ? brdf_pdf(L) : 0.0;
		const double p_lobe_pdf = use_lobe ? lobe_rect.pdf(u, w, dist2, cos_light, p_strategy == STRATEGY_LOBE) : 0.0;
		const double own = p_strategy == STRATEGY_LIGHT ? p_light_pdf : (p_strategy == STRATEGY_BRDF ? p_brdf_pdf : p_lobe_pdf);
		if (!(own > 0.0) || !std::isfinite(own)) {
			return;
		}
		// Weights. MIS: power heuristic over every strategy in use, for diffuse and specular alike.
		// BRDF mode: specular from the GGX samples alone, diffuse from the light samples alone.
		double spec_weight, diffuse_weight;
		if (brdf_only) {
			spec_weight = p_strategy == STRATEGY_BRDF ? 1.0 : 0.0;
			diffuse_weight = p_strategy == STRATEGY_LIGHT ? 1.0 : 0.0;
		} else if (!use_brdf) {
			spec_weight = diffuse_weight = 1.0;
		} else {
			const double ql = p_light_pdf / own, qb = p_brdf_pdf / own, qw = p_lobe_pdf / own;
			spec_weight = 1.0 / (ql * ql + qb * qb + qw * qw);
			if (!std::isfinite(spec_weight)) {
				spec_weight = 0.0;
			}
			diffuse_weight = spec_weight;
		}
		const bool diffuse_here = has_diffuse && diffuse_weight > 0.0;
		if (!diffuse_here && spec_weight == 0.0) {
			return;
		}
		if (!visible(L, p_target)) {
			return;
		}
		Vector3 diffuse, specular;
		// area_texture: the exact emitted radiance at this point of the light (area_light_texture.h).
		const Vector3 emitted = p_light.texture ? p_light.radiance * area_light_texture_at(p_light.texture, float(u), float(w), p_light.size_x, p_light.size_y) : p_light.radiance;
		light_compute(p_point.N, L, p_point.V, emitted, p_light.specular_amount, p_point.diffuse_mode, p_point.roughness, p_point.f0, p_point.f90, p_point.specular_enabled, diffuse, specular);
		const Vector3 d = diffuse_here ? diffuse * p_point.diffuse_weight : Vector3();
		r_value[0] += (diffuse_weight * double(d.x) + spec_weight * double(specular.x)) / own;
		r_value[1] += (diffuse_weight * double(d.y) + spec_weight * double(specular.y)) / own;
		r_value[2] += (diffuse_weight * double(d.z) + spec_weight * double(specular.z)) / own;
	};

	// One BRDF sample (a cosine-weighted direction with probability cos_share, else the mirror of V
	// about a GGX visible normal); counts when its ray reaches the rectangle.
	auto brdf_sample = [&](const double *p_uv, double *r_value) {
		double dir[3];
		if (p_uv[0] < cos_share) {
			// Malley's method: uniform on the unit disk, lifted to the hemisphere.
			const double u = p_uv[0] / cos_share;
			const double r = std::sqrt(u), phi = 2.0 * Math::PI * p_uv[1];
			const double x = r * std::cos(phi), y = r * std::sin(phi), z = std::sqrt(std::max(1.0 - u, 0.0));
			for (int i = 0; i < 3; i++) {
				dir[i] = x * t[i] + y * b[i] + z * n[i];
			}
		} else {
			double hl[3];
			ggx_vndf_sample_normal(v_local, alpha, (p_uv[0] - cos_share) / (1.0 - cos_share), p_uv[1], hl);
			double h[3];
			for (int i = 0; i < 3; i++) {
				h[i] = hl[0] * t[i] + hl[1] * b[i] + hl[2] * n[i];
			}
			const double voh = _dot3(v, h);
			for (int i = 0; i < 3; i++) {
				dir[i] = 2.0 * voh * h[i] - v[i];
			}
		}
		if (!_normalize3(dir)) {
			return;
		}
		// Ray / light plane: vertex + s dir reaches the plane at s = front / (-dir.emit_dir).
		const double cos_light = -(dir[0] * emit_dir.x + dir[1] * emit_dir.y + dir[2] * emit_dir.z);
		if (!(cos_light > 0.0)) {
			return;
		}
		const double s = double(front) / cos_light;
		const Vector3 hit = Vector3(float(p_point.vertex.x + dir[0] * s), float(p_point.vertex.y + dir[1] * s), float(p_point.vertex.z + dir[2] * s));
		const Vector3 rel = hit - p_light.center;
		if (std::fabs(rel.dot(p_light.axis_x)) > float(half_x) || std::fabs(rel.dot(p_light.axis_y)) > float(half_y)) {
			return; // Misses the rectangle.
		}
		evaluate(STRATEGY_BRDF, hit, r_value);
	};

	AdaptiveIntegrationSettings settings = p_settings;
	AdaptiveIntegrationResult result;
	int directions_per_evaluation = 1;
	if (use_brdf) {
		// One sample per strategy: [light (when it carries anything)], GGX, [lobe window].
		const bool light_needed = !brdf_only || has_diffuse;
		const int points = (light_needed ? 1 : 0) + 1 + (use_lobe ? 1 : 0);
		directions_per_evaluation = points;
		settings.max_samples = std::max(1, p_settings.max_samples / points);
		ReferenceIntegrandPoints integrand = [&](const double *p_points, double *r_value) {
			r_value[0] = r_value[1] = r_value[2] = 0.0;
			int k = 0;
			if (light_needed) {
				evaluate(STRATEGY_LIGHT, light_rect.sample(p_points + 2 * k++), r_value);
			}
			brdf_sample(p_points + 2 * k++, r_value);
			if (use_lobe) {
				evaluate(STRATEGY_LOBE, lobe_rect.sample(p_points + 2 * k++), r_value);
			}
		};
		result = integrate_adaptive_points(integrand, points, 3, settings, r_rng);
	} else {
		ReferenceIntegrand integrand = [&](double p_u, double p_v, double *r_value) {
			r_value[0] = r_value[1] = r_value[2] = 0.0;
			const double uv[2] = { p_u, p_v };
			evaluate(STRATEGY_LIGHT, light_rect.sample(uv), r_value);
		};
		result = integrate_adaptive(integrand, 3, settings, r_rng);
	}
	if (result.value.size() != 3) {
		out.evaluated = false;
		return out;
	}
	out.samples = result.samples * directions_per_evaluation;
	out.relative_error = result.relative_error;
	out.converged = result.converged;
	out.shadow_rays = shadow_rays;
	out.radiance = Vector3(float(result.value[0]), float(result.value[1]), float(result.value[2])) * window;
	return out;
}

} // namespace ReferenceBRDF
