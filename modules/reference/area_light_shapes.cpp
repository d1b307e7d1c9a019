/**************************************************************************/
/*  area_light_shapes.cpp                                                 */
/**************************************************************************/

#include "modules/reference/area_light_shapes.h"

#include "modules/reference/forward_lights.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ReferenceBRDF {

static constexpr double SHAPE_MIS_MIN_ALPHA = 1e-4; // As area_light_integrate(): below it the GGX lobe is a mirror.
static constexpr float SHAPE_RAY_EPSILON = 1e-6f;

// Nearest t > epsilon of |p_o + t p_d - p_c| = p_r (unit p_d); false when the ray misses.
static bool _ray_sphere(const Vector3 &p_o, const Vector3 &p_d, const Vector3 &p_c, float p_r, float &r_t) {
	const Vector3 oc = p_o - p_c;
	const double b = oc.dot(p_d);
	const double c = double(oc.dot(oc)) - double(p_r) * double(p_r);
	const double disc = b * b - c;
	if (!(disc >= 0.0)) {
		return false;
	}
	const double sq = std::sqrt(disc);
	double t = -b - sq;
	if (!(t > SHAPE_RAY_EPSILON)) {
		t = -b + sq;
	}
	if (!(t > SHAPE_RAY_EPSILON)) {
		return false;
	}
	r_t = float(t);
	return true;
}

bool area_light_shape_intersect(const AreaLightData &p_light, const Vector3 &p_origin, const Vector3 &p_dir, float &r_t, Vector3 &r_normal) {
	switch (p_light.shape) {
		case AREA_LIGHT_SHAPE_SPHERE: {
			const float r = 0.5f * p_light.size_x;
			if (!_ray_sphere(p_origin, p_dir, p_light.center, r, r_t)) {
				return false;
			}
			r_normal = (p_origin + p_dir * r_t - p_light.center) / r;
			return true;
		}
		case AREA_LIGHT_SHAPE_DISK: {
			const float cos_light = -p_dir.dot(p_light.emit_dir);
			const float front = area_light_front_distance(p_light, p_origin);
			if (!(cos_light > 0.0f) || !(front > 0.0f)) {
				return false; // One-sided: only rays from the lit side towards the front face.
			}
			r_t = front / cos_light;
			const Vector3 rel = p_origin + p_dir * r_t - p_light.center;
			const float u = rel.dot(p_light.axis_x) / (0.5f * p_light.size_x);
			const float v = rel.dot(p_light.axis_y) / (0.5f * p_light.size_y);
			if (!(u * u + v * v <= 1.0f)) {
				return false;
			}
			r_normal = p_light.emit_dir;
			return true;
		}
		case AREA_LIGHT_SHAPE_TUBE: {
			// The capsule is the union of the open cylinder and the two end spheres: its first hit is the
			// nearest of their first hits (a ray entering through a flat end of the cylinder meets the
			// sphere there first).
			const float r = 0.5f * p_light.size_y;
			const float half_len = 0.5f * p_light.size_x;
			const Vector3 axis = p_light.axis_x;
			const Vector3 a = p_light.center - axis * half_len;
			float best = std::numeric_limits<float>::infinity();
			const Vector3 oa = p_origin - a;
			const Vector3 dp = p_dir - axis * p_dir.dot(axis);
			const Vector3 op = oa - axis * oa.dot(axis);
			const double qa = dp.dot(dp);
			if (qa > 1e-12 && half_len > 0.0f) {
				const double qb = op.dot(dp);
				const double qc = double(op.dot(op)) - double(r) * r;
				const double disc = qb * qb - qa * qc;
				if (disc >= 0.0) {
					const double sq = std::sqrt(disc);
					const double roots[2] = { (-qb - sq) / qa, (-qb + sq) / qa };
					for (double s : roots) {
						const double z = oa.dot(axis) + s * p_dir.dot(axis);
						if (s > SHAPE_RAY_EPSILON && z >= 0.0 && z <= 2.0 * half_len) {
							best = float(s);
							r_normal = (op + dp * float(s)).normalized();
							break;
						}
					}
				}
			}
			const Vector3 ends[2] = { a, p_light.center + axis * half_len };
			for (const Vector3 &end : ends) {
				float t;
				if (_ray_sphere(p_origin, p_dir, end, r, t) && t < best) {
					best = t;
					r_normal = (p_origin + p_dir * t - end) / r;
				}
			}
			if (!std::isfinite(best)) {
				return false;
			}
			r_t = best;
			return true;
		}
		default:
			return false;
	}
}

AreaLightIntegral area_light_shape_integrate(const AreaLightData &p_light, const AreaLightShadingPoint &p_point, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng, const AreaLightOcclusionTest &p_occluded) {
	AreaLightIntegral out;
	const float area = p_light.get_area();
	if (p_light.shape == AREA_LIGHT_SHAPE_RECTANGLE || !(area > 0.0f) || p_light.radiance == Vector3()) {
		return out;
	}
	if (p_light.shape == AREA_LIGHT_SHAPE_DISK && !(area_light_front_distance(p_light, p_point.vertex) > 0.0f)) {
		return out; // One-sided, as the rectangle.
	}
	const float window = area_light_window(area_light_closest_distance(p_light, p_point.vertex), p_light.range, p_light.attenuation);
	if (window <= 0.0f) {
		return out;
	}
	out.evaluated = true;
	const Vector3 x = p_point.vertex;
	const double pi = Math::PI;

	// Sphere: the cone of directions it fills (inside it: every direction).
	const float radius = 0.5f * (p_light.shape == AREA_LIGHT_SHAPE_SPHERE ? p_light.size_x : p_light.size_y);
	const Vector3 to_center = p_light.center - x;
	const double dist = to_center.length();
	const bool inside = p_light.shape == AREA_LIGHT_SHAPE_SPHERE && dist <= radius;
	double one_minus_cos = 2.0; // 1 - cos(sigma): 2 = the whole sphere of directions.
	if (p_light.shape == AREA_LIGHT_SHAPE_SPHERE && !inside) {
		const double s2 = double(radius) * radius / (dist * dist);
		one_minus_cos = s2 / (1.0 + std::sqrt(std::max(1.0 - s2, 0.0)));
	}
	const double sphere_pdf = 1.0 / (2.0 * pi * one_minus_cos);
	Vector3 lc = dist > 0.0 ? to_center / float(dist) : p_point.N;
	Vector3 t1 = (std::fabs(lc.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0)).cross(lc).normalized();
	Vector3 t2 = lc.cross(t1);
	// Tube frame and the cylinder's share of the area.
	const float half_len = 0.5f * p_light.size_x;
	const double cylinder_share = p_light.shape == AREA_LIGHT_SHAPE_TUBE ? (2.0 * pi * radius * p_light.size_x) / double(area) : 0.0;

	// Solid-angle pdf of the light strategy for a direction whose first hit is at distance p_t with
	// outward normal p_n (0 when it sees the back of the shape).
	auto light_pdf = [&](const Vector3 &p_L, float p_t, const Vector3 &p_n) -> double {
		if (p_light.shape == AREA_LIGHT_SHAPE_SPHERE) {
			return inside ? 1.0 / (4.0 * pi) : sphere_pdf;
		}
		const double cos_l = -double(p_L.dot(p_n));
		return cos_l > 0.0 ? double(p_t) * p_t / (double(area) * cos_l) : 0.0;
	};
	// A light sample: the target point on the shape, its unit direction and its pdf (false: nothing).
	auto sample_light = [&](const double *p_uv, Vector3 &r_target, Vector3 &r_L, double &r_pdf) -> bool {
		const double u = p_uv[0], v = p_uv[1];
		Vector3 point, normal;
		if (p_light.shape == AREA_LIGHT_SHAPE_SPHERE) {
			Vector3 dir;
			if (inside) {
				const double z = 1.0 - 2.0 * u, s = std::sqrt(std::max(1.0 - z * z, 0.0)), phi = 2.0 * pi * v;
				dir = Vector3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
			} else {
				const double omc = u * one_minus_cos;
				const double cos_t = 1.0 - omc, sin_t = std::sqrt(std::max(omc * (2.0 - omc), 0.0)), phi = 2.0 * pi * v;
				dir = (lc * float(cos_t) + (t1 * float(std::cos(phi)) + t2 * float(std::sin(phi))) * float(sin_t)).normalized();
			}
			float t;
			if (!_ray_sphere(x, dir, p_light.center, radius, t)) {
				t = float(std::max(double(to_center.dot(dir)), 0.0)); // The rim, numerically grazing.
			}
			r_target = x + dir * t;
			r_L = dir;
			r_pdf = inside ? 1.0 / (4.0 * pi) : sphere_pdf;
			return true;
		}
		if (p_light.shape == AREA_LIGHT_SHAPE_DISK) {
			const double rho = std::sqrt(u), phi = 2.0 * pi * v;
			point = p_light.center + p_light.axis_x * float(0.5 * p_light.size_x * rho * std::cos(phi)) + p_light.axis_y * float(0.5 * p_light.size_y * rho * std::sin(phi));
			normal = p_light.emit_dir;
		} else {
			const Vector3 ey = p_light.axis_y;
			const Vector3 ez = p_light.axis_x.cross(ey);
			const double phi = 2.0 * pi * v;
			if (u < cylinder_share) {
				const double s = u / cylinder_share;
				normal = ey * float(std::cos(phi)) + ez * float(std::sin(phi));
				point = p_light.center + p_light.axis_x * float(p_light.size_x * (s - 0.5)) + normal * radius;
			} else {
				const double s = (u - cylinder_share) / std::max(1.0 - cylinder_share, 1e-12);
				const double z = 1.0 - 2.0 * s, sr = std::sqrt(std::max(1.0 - z * z, 0.0));
				normal = p_light.axis_x * float(z) + ey * float(sr * std::cos(phi)) + ez * float(sr * std::sin(phi));
				point = p_light.center + p_light.axis_x * (z >= 0.0 ? half_len : -half_len) + normal * radius;
			}
		}
		const Vector3 to_point = point - x;
		const float d2 = to_point.length_squared();
		if (!(d2 > 0.0f)) {
			return false;
		}
		r_L = to_point / std::sqrt(d2);
		r_target = point;
		const double cos_l = -double(r_L.dot(normal));
		if (!(cos_l > 0.0)) {
			return false; // The back of the shape: hidden by the (convex) shape itself, or not emitting (disk).
		}
		r_pdf = double(d2) / (double(area) * cos_l);
		return true;
	};

	// BRDF strategy: cosine / GGX VNDF mixture (as area_light_integrate()).
	const double alpha = double(p_point.roughness) * double(p_point.roughness);
	const double nov = double(p_point.N.dot(p_point.V));
	const bool has_specular = p_point.specular_enabled && p_light.specular_amount != 0.0f && (p_point.f0 != Vector3() || p_point.f90 != 0.0f);
	const bool has_diffuse = p_point.diffuse_weight != Vector3();
	const bool use_vndf = has_specular && alpha >= SHAPE_MIS_MIN_ALPHA && nov > 1e-6;
	double cos_share = 0.0;
	if (has_diffuse) {
		const double d = (double(p_point.diffuse_weight.x) + p_point.diffuse_weight.y + p_point.diffuse_weight.z) / 3.0;
		const double s = (double(p_point.f0.x) + p_point.f0.y + p_point.f0.z) / 3.0;
		cos_share = use_vndf ? std::min(0.5, std::max(d, 0.0) / (std::max(d, 0.0) + std::max(s, 0.04))) : 1.0;
	}
	const bool use_brdf = use_vndf || cos_share > 0.0;
	out.brdf_sampling = use_brdf;
	const Vector3 n = p_point.N.normalized();
	const Vector3 tn = (std::fabs(n.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0)).cross(n).normalized();
	const Vector3 bn = n.cross(tn);
	const double v_local[3] = { p_point.V.dot(tn), p_point.V.dot(bn), p_point.V.dot(n) };
	auto brdf_pdf = [&](const Vector3 &p_L) -> double {
		double pdf = cos_share > 0.0 ? cos_share * std::max(double(n.dot(p_L)), 0.0) / pi : 0.0;
		if (cos_share < 1.0) {
			Vector3 h = (p_point.V + p_L);
			if (h.length_squared() > 0.0f) {
				h.normalize();
				const Vector3 c = n.cross(h);
				pdf += (1.0 - cos_share) * ggx_vndf_reflection_pdf(nov, n.dot(h), c.dot(c), alpha);
			}
		}
		return pdf;
	};

	uint64_t shadow_rays = 0;
	auto visible = [&](const Vector3 &p_L, const Vector3 &p_target) -> bool {
		if (!p_occluded) {
			return true;
		}
		const Vector3 side = p_point.ng.dot(p_L) >= 0.0f ? p_point.ng : -p_point.ng;
		const Vector3 origin = x + side * p_point.offset;
		const Vector3 to_target = p_target - origin;
		const float d = to_target.length();
		if (!(d > 2.0f * p_point.offset)) {
			return true;
		}
		shadow_rays++;
		return !p_occluded(origin, to_target / d, d - p_point.offset);
	};
	// Adds the BRDF at direction p_L (towards p_target on the shape) over p_own with the power heuristic.
	auto evaluate = [&](const Vector3 &p_L, const Vector3 &p_target, double p_own, double p_other, double *r_value) {
		if (!(p_own > 0.0) || !std::isfinite(p_own) || !(n.dot(p_L) > 0.0f)) {
			return;
		}
		const double weight = use_brdf ? p_own * p_own / (p_own * p_own + p_other * p_other) : 1.0;
		if (!(weight > 0.0) || !visible(p_L, p_target)) {
			return;
		}
		Vector3 diffuse, specular;
		light_compute(p_point.N, p_L, p_point.V, p_light.radiance, p_light.specular_amount, p_point.diffuse_mode, p_point.roughness, p_point.f0, p_point.f90, p_point.specular_enabled, diffuse, specular);
		const Vector3 d = has_diffuse ? diffuse * p_point.diffuse_weight : Vector3();
		r_value[0] += weight * (double(d.x) + double(specular.x)) / p_own;
		r_value[1] += weight * (double(d.y) + double(specular.y)) / p_own;
		r_value[2] += weight * (double(d.z) + double(specular.z)) / p_own;
	};
	auto light_strategy = [&](const double *p_uv, double *r_value) {
		Vector3 target, L;
		double pdf;
		if (sample_light(p_uv, target, L, pdf)) {
			evaluate(L, target, pdf, use_brdf ? brdf_pdf(L) : 0.0, r_value);
		}
	};
	auto brdf_strategy = [&](const double *p_uv, double *r_value) {
		Vector3 L;
		if (p_uv[0] < cos_share) {
			const double u = p_uv[0] / cos_share;
			const double r = std::sqrt(u), phi = 2.0 * pi * p_uv[1];
			L = tn * float(r * std::cos(phi)) + bn * float(r * std::sin(phi)) + n * float(std::sqrt(std::max(1.0 - u, 0.0)));
		} else {
			double hl[3];
			ggx_vndf_sample_normal(v_local, alpha, (p_uv[0] - cos_share) / (1.0 - cos_share), p_uv[1], hl);
			const Vector3 h = tn * float(hl[0]) + bn * float(hl[1]) + n * float(hl[2]);
			L = h * (2.0f * p_point.V.dot(h)) - p_point.V;
		}
		if (!(L.length_squared() > 0.0f)) {
			return;
		}
		L.normalize();
		float t;
		Vector3 hit_normal;
		if (!area_light_shape_intersect(p_light, x, L, t, hit_normal)) {
			return;
		}
		evaluate(L, x + L * t, brdf_pdf(L), light_pdf(L, t, hit_normal), r_value);
	};

	AdaptiveIntegrationSettings settings = p_settings;
	AdaptiveIntegrationResult result;
	int directions = 1;
	if (use_brdf) {
		directions = 2;
		settings.max_samples = std::max(1, p_settings.max_samples / 2);
		ReferenceIntegrandPoints integrand = [&](const double *p_points, double *r_value) {
			r_value[0] = r_value[1] = r_value[2] = 0.0;
			light_strategy(p_points, r_value);
			brdf_strategy(p_points + 2, r_value);
		};
		result = integrate_adaptive_points(integrand, 2, 3, settings, r_rng);
	} else {
		ReferenceIntegrand integrand = [&](double p_u, double p_v, double *r_value) {
			r_value[0] = r_value[1] = r_value[2] = 0.0;
			const double uv[2] = { p_u, p_v };
			light_strategy(uv, r_value);
		};
		result = integrate_adaptive(integrand, 3, settings, r_rng);
	}
	if (result.value.size() != 3) {
		out.evaluated = false;
		return out;
	}
	out.samples = result.samples * directions;
	out.relative_error = result.relative_error;
	out.converged = result.converged;
	out.shadow_rays = shadow_rays;
	out.radiance = Vector3(float(result.value[0]), float(result.value[1]), float(result.value[2])) * window;
	return out;
}

} // namespace ReferenceBRDF
