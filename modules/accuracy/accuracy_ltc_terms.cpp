/**************************************************************************/
/*  accuracy_ltc_terms.cpp                                                */
/**************************************************************************/
/* godot-area: the LTC error decomposition (see the header). Formulas:    */
/* Heitz et al. 2016 eq. 1 (polygon integral of the LTC) and the shader's */
/* clipping (area_light_ltc_inc.glsl), thesis eq. 5.10 (Fresnel of LTC),  */
/* Schlick's F with brdf_inc.glsl's f90.                                  */

#include "modules/accuracy/accuracy_ltc_terms.h"

#include "core/math/color.h"
#include "modules/ltc_fit/ltc_brdf.h"
#include "modules/ltc_fit/ltc_fitter.h"
#include "modules/ltc_fit/ltc_polygon_objective.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/ltc_fit/ltc_two_lobe.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <thread>

namespace {

const double SPECULAR_AMOUNT = 0.5;

struct Pixel {
	double t[3], a1[3], a2[3], a3[3], a3n[3], a4[3], a5[3], a6[3], t_half[3];
	int ri = 0, ti = 0;
	bool lit = false;
};

struct Frame {
	double o[3], ax[3], ay[3], emit[3]; // Light centre, half axes, emitting direction.
	double eye[3], fwd[3], right[3], up[3], tan_half;
	double f0[3], f90, albedo_d[3], alpha, roughness;
	int n_light;
	const float *table; // The engine LUT read (LTC_LUT_SIZE^2 cells of 8 floats).
	const float *table_2lobe; // The two-lobe table (LTC_LUT_SIZE^2 cells of 16 floats).
	int table_size;
};

inline double dot3(const double *p_a, const double *p_b) {
	return p_a[0] * p_b[0] + p_a[1] * p_b[1] + p_a[2] * p_b[2];
}

void set3(double *r_v, const Vector3 &p_v) {
	r_v[0] = p_v.x, r_v[1] = p_v.y, r_v[2] = p_v.z;
}

// The shader's LUT fetch (ltc_fetch_lut): bilinear between texel centres at (r (N-1), sqrt(1 - NoV) (N-1)),
// of the p_floats floats of a cell (8: the LTC table, 16: the two-lobe table) into r_v.
void lut_filter(const float *p_table, int p_size, int p_floats, double p_roughness, double p_nov, double *r_v) {
	const int n = p_size;
	const double x = std::clamp(p_roughness, 0.0, 1.0) * (n - 1);
	const double y = std::sqrt(1.0 - std::clamp(p_nov, 0.0, 1.0)) * (n - 1);
	const int x0 = std::min(int(x), n - 2), y0 = std::min(int(y), n - 2);
	const double fx = x - x0, fy = y - y0;
	for (int j = 0; j < p_floats; j++) {
		r_v[j] = 0.0;
	}
	for (int k = 0; k < 4; k++) {
		const int dx = k & 1, dy = k >> 1;
		const double w = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
		const float *cell = p_table + (size_t(y0 + dy) * n + x0 + dx) * p_floats;
		for (int j = 0; j < p_floats; j++) {
			r_v[j] += w * cell[j];
		}
	}
}

void lut_fetch(const float *p_table, int p_size, double p_roughness, double p_nov, double *r_m, double *r_fn, double *r_fg, int *r_ri, int *r_ti) {
	const int n = p_size;
	const double x = std::clamp(p_roughness, 0.0, 1.0) * (n - 1);
	const double y = std::sqrt(1.0 - std::clamp(p_nov, 0.0, 1.0)) * (n - 1);
	double v[8];
	lut_filter(p_table, p_size, LTCFitter::FLOATS_PER_CELL, p_roughness, p_nov, v);
	for (int j = 0; j < 5; j++) {
		r_m[j] = v[j];
	}
	*r_fn = v[5];
	*r_fg = v[6];
	*r_ri = int(std::lround(x));
	*r_ti = int(std::lround(y));
}

// The shader's specular integral of the quad p_q (shading frame) for the stored matrix p_m, with or
// without the surface-horizon clip (the objective's twin clips; without it only the cosine space's).
double ltc_integral(const double *p_m, const double *p_q, bool p_clip) {
	if (p_clip) {
		return std::max(0.0, LTCPolygonObjective::ltc_integral(p_m, p_q));
	}
	const double a = p_m[0], b = p_m[1], c = p_m[2], d = p_m[3], e = p_m[4];
	const double s = 1.0 / (a * e - b * d);
	double h[12];
	for (int i = 0; i < 4; i++) {
		const double x = p_q[3 * i], y = p_q[3 * i + 1], z = p_q[3 * i + 2];
		h[3 * i] = s * (e * x - b * z);
		h[3 * i + 1] = y / c;
		h[3 * i + 2] = s * (a * z - d * x);
	}
	return LTCPolygonObjective::form_factor(h, 4);
}

// Sutherland-Hodgman of the n-gon p_v against z >= 0 into r_out (room for n + 1 vertices).
int clip_z(const double *p_v, int p_n, double *r_out) {
	int n = 0;
	for (int i = 0; i < p_n; i++) {
		const double *a = p_v + 3 * i, *b = p_v + 3 * ((i + 1) % p_n);
		if (a[2] > 0.0) {
			r_out[3 * n] = a[0], r_out[3 * n + 1] = a[1], r_out[3 * n + 2] = a[2];
			n++;
		}
		if ((a[2] > 0.0) != (b[2] > 0.0)) {
			const double t = a[2] / (a[2] - b[2]);
			r_out[3 * n] = a[0] + (b[0] - a[0]) * t, r_out[3 * n + 1] = a[1] + (b[1] - a[1]) * t, r_out[3 * n + 2] = 0.0;
			n++;
		}
	}
	return n;
}

// Direction (shading frame) of the vector form factor of the lobe over the quad p_q: the polygon clipped
// to the receiver's plane, mapped by M^-1, clipped to z >= 0; its vector form factor sum theta_i n_i
// (Arvo 1994) is the mean direction of the clamped cosine over it, mapped back by M. False when empty.
bool ltc_mean_direction(const double *p_m, const double *p_q, double *r_dir) {
	const double a = p_m[0], b = p_m[1], c = p_m[2], d = p_m[3], e = p_m[4];
	const double s = 1.0 / (a * e - b * d);
	double h[15], g[18];
	int n = clip_z(p_q, 4, h);
	for (int i = 0; i < n; i++) {
		const double x = h[3 * i], y = h[3 * i + 1], z = h[3 * i + 2];
		h[3 * i] = s * (e * x - b * z), h[3 * i + 1] = y / c, h[3 * i + 2] = s * (a * z - d * x);
	}
	n = clip_z(h, n, g);
	if (n < 3) {
		return false;
	}
	for (int i = 0; i < n; i++) {
		const double l = std::sqrt(dot3(g + 3 * i, g + 3 * i));
		g[3 * i] /= l, g[3 * i + 1] /= l, g[3 * i + 2] /= l;
	}
	double f[3] = {};
	for (int i = 0; i < n; i++) {
		const double *p = g + 3 * i, *q = g + 3 * ((i + 1) % n);
		const double x[3] = { p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0] };
		const double sl = std::sqrt(dot3(x, x));
		if (sl > 0.0) {
			const double th = std::atan2(sl, dot3(p, q)) / sl;
			f[0] += th * x[0], f[1] += th * x[1], f[2] += th * x[2];
		}
	}
	const double sign = f[2] < 0.0 ? -1.0 : 1.0;
	const double o[3] = { sign * (a * f[0] + b * f[2]), sign * c * f[1], sign * (d * f[0] + e * f[2]) };
	const double l = std::sqrt(dot3(o, o));
	if (!(l > 0.0)) {
		return false;
	}
	r_dir[0] = o[0] / l, r_dir[1] = o[1] / l, r_dir[2] = o[2] / l;
	return true;
}

// Schlick's weight (1 - v.h)^5 of the light direction p_l for the view p_v.
double schlick_weight(const double *p_v, const double *p_l) {
	double h[3] = { p_v[0] + p_l[0], p_v[1] + p_l[1], p_v[2] + p_l[2] };
	const double hl = std::sqrt(dot3(h, h));
	return hl > 0.0 ? std::pow(std::clamp(1.0 - dot3(p_v, h) / hl, 0.0, 1.0), 5.0) : 0.0;
}

// The shader's Fresnel weight of one lobe p_m over the quad p_q (ltc_polygon_fresnel): Schlick's weight at
// the polygon's mean direction plus the gap between fg / fn and the weight at the lobe's axis M z in
// proportion to the lobe's integral p_coverage. p_fn, p_fg: the table's.
double polygon_fresnel_weight(const double *p_m, const double *p_q, const double *p_v, double p_fn, double p_fg, double p_coverage) {
	double l_mean[3], w = p_fn > 0.0 ? p_fg / p_fn : 0.0;
	if (ltc_mean_direction(p_m, p_q, l_mean)) {
		double axis[3] = { p_m[1], 0.0, p_m[4] };
		const double al = std::sqrt(dot3(axis, axis));
		axis[0] /= al, axis[2] /= al;
		w = std::clamp(schlick_weight(p_v, l_mean) + p_coverage * (w - schlick_weight(p_v, axis)), 0.0, 1.0);
	}
	return w;
}

// One pixel: shading point on the plane y = 0 (|x|, |z| <= 5), normal +Y.
void shade(const Frame &p_f, int p_res, int p_x, int p_y, Pixel &r_px) {
	const double nx = (p_x + 0.5) / p_res * 2.0 - 1.0, ny = 1.0 - (p_y + 0.5) / p_res * 2.0;
	double dir[3];
	for (int j = 0; j < 3; j++) {
		dir[j] = p_f.fwd[j] + p_f.tan_half * (nx * p_f.right[j] + ny * p_f.up[j]);
	}
	if (!(dir[1] < 0.0)) {
		return;
	}
	const double t = -p_f.eye[1] / dir[1];
	const double p[3] = { p_f.eye[0] + t * dir[0], 0.0, p_f.eye[2] + t * dir[2] };
	if (std::fabs(p[0]) > 5.0 || std::fabs(p[2]) > 5.0) {
		return;
	}
	double to_p[3] = { p[0] - p_f.o[0], p[1] - p_f.o[1], p[2] - p_f.o[2] };
	if (!(dot3(to_p, p_f.emit) > 0.0)) {
		return; // Behind the one-sided light.
	}
	double v[3] = { p_f.eye[0] - p[0], p_f.eye[1] - p[1], p_f.eye[2] - p[2] };
	const double vl = std::sqrt(dot3(v, v));
	for (double &c : v) {
		c /= vl;
	}
	const double nov = v[1];
	// Frame of the LUT fit: z = N, x = normalize(V - N NoV), y = z cross x.
	double tx[3] = { v[0], 0.0, v[2] };
	double txl = std::sqrt(dot3(tx, tx));
	if (txl < 1e-9) {
		tx[0] = 1.0, tx[2] = 0.0, txl = 1.0;
	}
	tx[0] /= txl, tx[2] /= txl;
	const double ty[3] = { -tx[2], 0.0, tx[0] }; // (0, 1, 0) x tx.
	auto local = [&](const double *w, double *r) {
		r[0] = dot3(w, tx), r[1] = dot3(w, ty), r[2] = w[1];
	};
	double q[12];
	const double su[4] = { -1, 1, 1, -1 }, sv[4] = { -1, -1, 1, 1 };
	for (int i = 0; i < 4; i++) {
		double w[3];
		for (int j = 0; j < 3; j++) {
			w[j] = p_f.o[j] + su[i] * p_f.ax[j] + sv[i] * p_f.ay[j] - p[j];
		}
		local(w, q + 3 * i);
	}
	const double vloc[3] = { std::sqrt(std::max(0.0, 1.0 - nov * nov)), 0.0, nov };
	const double diffuse = LTCPolygonObjective::form_factor(q, 4);

	// Truth and the exact lobe integral (F = 1): midpoint rule over the light's area, at n and n / 2.
	double spec[3] = {}, lobe = 0.0, spec_half[3] = {};
	for (int pass = 0; pass < 2; pass++) {
		const int n = pass == 0 ? p_f.n_light : p_f.n_light / 2;
		const double da = 4.0 * std::sqrt(dot3(p_f.ax, p_f.ax) * dot3(p_f.ay, p_f.ay)) / (double(n) * n);
		double *out = pass == 0 ? spec : spec_half;
		for (int i = 0; i < n; i++) {
			for (int k = 0; k < n; k++) {
				const double u = (i + 0.5) / n * 2.0 - 1.0, w = (k + 0.5) / n * 2.0 - 1.0;
				double d[3];
				for (int j = 0; j < 3; j++) {
					d[j] = p_f.o[j] + u * p_f.ax[j] + w * p_f.ay[j] - p[j];
				}
				const double r2 = dot3(d, d), r = std::sqrt(r2);
				double l[3];
				local(d, l);
				for (double &c : l) {
					c /= r;
				}
				const double cos_l = -dot3(d, p_f.emit) / r;
				if (!(l[2] > 0.0) || !(cos_l > 0.0)) {
					continue;
				}
				const double f = LTCBRDF::evaluate(LTC_BRDF_ENGINE_GGX, vloc, l, p_f.alpha) * l[2] * cos_l / r2 * da;
				double h[3] = { vloc[0] + l[0], vloc[1] + l[1], vloc[2] + l[2] };
				const double hl = std::sqrt(dot3(h, h));
				const double m5 = std::pow(std::clamp(1.0 - dot3(l, h) / hl, 0.0, 1.0), 5.0);
				for (int c = 0; c < 3; c++) {
					out[c] += f * (p_f.f0[c] + (p_f.f90 - p_f.f0[c]) * m5);
				}
				if (pass == 0) {
					lobe += f;
				}
			}
		}
	}
	double fn_x = 0.0, fg_x = 0.0, dominant[3];
	const double theta = std::min(std::acos(std::clamp(nov, 0.0, 1.0)), LTCFitter::MAX_THETA);
	LTCFitter::integrate_albedo(LTC_BRDF_ENGINE_GGX, std::max(p_f.alpha, LTCFitter::MIN_ALPHA), theta, 64, &fn_x, &fg_x, dominant);
	double m[5], fn = 0.0, fg = 0.0;
	lut_fetch(p_f.table, p_f.table_size, p_f.roughness, nov, m, &fn, &fg, &r_px.ri, &r_px.ti);
	const double i_ltc = ltc_integral(m, q, true), i_ltc_n = ltc_integral(m, q, false);
	const double i_rho = fn_x > 0.0 ? lobe / fn_x : 0.0;
	// Fresnel of the lit part of the lobe (the shader's ltc_polygon_fresnel, a4): Schlick's weight at the
	// polygon's mean direction plus, in proportion to the lobe's share the polygon covers (i_ltc), the gap
	// between the lobe's mean weight fg / fn and the weight at its axis M z. a5: the same gap added in
	// full whatever the coverage (the alternative that lost, kept as a measurement).
	double l_mean[3], w_shader = fn > 0.0 ? fg / fn : 0.0, w_alt = w_shader;
	if (ltc_mean_direction(m, q, l_mean)) {
		double axis[3] = { m[1], 0.0, m[4] };
		const double al = std::sqrt(dot3(axis, axis));
		axis[0] /= al, axis[2] /= al;
		const double s_p = schlick_weight(vloc, l_mean), s_a = schlick_weight(vloc, axis);
		w_alt = std::clamp(w_alt + s_p - s_a, 0.0, 1.0);
		w_shader = std::clamp(s_p + i_ltc * (w_shader - s_a), 0.0, 1.0);
	}
	// a6: the two-lobe shader (light_process_area_ltc_2lobe): both lobes' integrals over the same clipped
	// polygon, weighted, each with its own polygon Fresnel.
	double v2[16], spec2[3] = {};
	lut_filter(p_f.table_2lobe, p_f.table_size, LTCTwoLobe::FLOATS_PER_CELL, p_f.roughness, nov, v2);
	for (int lobe = 0; lobe < 2; lobe++) {
		const double m2[5] = { v2[8 * lobe], v2[8 * lobe + 1], v2[8 * lobe + 2], v2[8 * lobe + 3], v2[8 * lobe + 4] };
		const double weight = lobe == 0 ? v2[7] : v2[13];
		const double i2 = ltc_integral(m2, q, true);
		const double w2 = polygon_fresnel_weight(m2, q, vloc, v2[5], v2[6], i2);
		for (int c = 0; c < 3; c++) {
			spec2[c] += weight * i2 * v2[5] * (p_f.f0[c] + (p_f.f90 - p_f.f0[c]) * w2);
		}
	}
	for (int c = 0; c < 3; c++) {
		const double d = p_f.albedo_d[c] * diffuse;
		const double f_exact = p_f.f0[c] * fn_x + (p_f.f90 - p_f.f0[c]) * fg_x;
		const double f_lut = p_f.f0[c] * fn + (p_f.f90 - p_f.f0[c]) * fg;
		r_px.t[c] = d + spec[c];
		r_px.t_half[c] = d + spec_half[c];
		r_px.a1[c] = d + i_rho * f_exact;
		r_px.a2[c] = d + i_rho * f_lut;
		r_px.a3[c] = d + i_ltc * f_lut;
		r_px.a3n[c] = d + i_ltc_n * f_lut;
		r_px.a4[c] = d + i_ltc * fn * (p_f.f0[c] + (p_f.f90 - p_f.f0[c]) * w_shader);
		r_px.a5[c] = d + i_ltc * fn * (p_f.f0[c] + (p_f.f90 - p_f.f0[c]) * w_alt);
		r_px.a6[c] = d + spec2[c];
	}
	r_px.lit = true;
}

// relRMSE and brightness ratio of p_a against p_b (accessors (pixel, channel)) over every lit pixel and channel.
template <typename A, typename B>
void compare_with(const std::vector<Pixel> &p_px, A p_a, B p_b, double *r_rel, double *r_ratio) {
	double se = 0.0, sb2 = 0.0, sa = 0.0, sb = 0.0;
	for (const Pixel &px : p_px) {
		if (!px.lit) {
			continue;
		}
		for (int c = 0; c < 3; c++) {
			const double a = p_a(px, c), b = p_b(px, c);
			se += (a - b) * (a - b);
			sb2 += b * b;
			sa += a;
			sb += b;
		}
	}
	*r_rel = sb2 > 0.0 ? std::sqrt(se / sb2) : 0.0;
	*r_ratio = sb > 0.0 ? sa / sb : 1.0;
}

} // namespace

bool AccuracyLTCTerms::evaluate(const AccuracyScenes::Scene &p_scene, int p_resolution, int p_light_samples, Result *r_result, String *r_error, const std::vector<float> *p_table) {
	if (p_scene.receiver != AccuracyScenes::RECEIVER_PLANE || p_scene.shape != RS::LIGHT_AREA_SHAPE_RECTANGLE) {
		*r_error = vformat("LTC terms: %s is not a plane lit by a rectangle (only those are decomposed).", p_scene.id.c_str());
		return false;
	}
	if (p_resolution < 1 || p_resolution > 1024 || p_light_samples < 4 || p_light_samples > 4096) {
		*r_error = vformat("LTC terms: resolution %d (1..1024) or light samples %d (4..4096) out of range.", p_resolution, p_light_samples);
		return false;
	}
	Frame f;
	const Basis &lb = p_scene.light_transform.basis;
	set3(f.o, p_scene.light_transform.origin);
	set3(f.ax, lb.get_column(0).normalized() * (p_scene.light_size.x * 0.5f));
	set3(f.ay, lb.get_column(1).normalized() * (p_scene.light_size.y * 0.5f));
	set3(f.emit, -lb.get_column(2).normalized());
	const Transform3D cam = AccuracyScenes::camera_transform(p_scene);
	set3(f.eye, cam.origin);
	set3(f.fwd, -cam.basis.get_column(2).normalized());
	set3(f.right, cam.basis.get_column(0).normalized());
	set3(f.up, cam.basis.get_column(1).normalized());
	f.tan_half = std::tan(AccuracyScenes::CAMERA_FOVY * 0.5 * Math::PI / 180.0);
	// The suite's material (accuracy_scenes.cpp build()): albedo sRGB (0.9, 0.75, 0.6), specular 0.5.
	const Color albedo = Color(0.9f, 0.75f, 0.6f).srgb_to_linear();
	const double lin[3] = { albedo.r, albedo.g, albedo.b };
	const double metallic = p_scene.metallic;
	double f0_dot = 0.0;
	for (int c = 0; c < 3; c++) {
		f.f0[c] = 0.04 * (1.0 - metallic) + lin[c] * metallic;
		f.albedo_d[c] = lin[c] * (1.0 - metallic);
		f0_dot += f.f0[c] * 50.0 * 0.33;
	}
	f.f90 = std::clamp(f0_dot, metallic, 1.0);
	// The suite leaves light_specular at its default, 0.5 (Godot's; light_storage.cpp): the specular
	// radiance is halved on both sides, which weighs it against the diffuse of dielectrics.
	for (int c = 0; c < 3; c++) {
		f.f0[c] *= SPECULAR_AMOUNT;
	}
	f.f90 *= SPECULAR_AMOUNT;
	f.roughness = p_scene.roughness;
	f.alpha = double(p_scene.roughness) * p_scene.roughness;
	f.n_light = p_light_samples;
	f.table_size = LTCTableIO::get_builtin_size();
	f.table = LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX);
	f.table_2lobe = LTCTwoLobe::get_builtin_table();
	if (p_table) {
		if (p_table->size() != size_t(f.table_size) * f.table_size * LTCFitter::FLOATS_PER_CELL) {
			*r_error = vformat("LTC terms: the table has %zu floats, the engine's LUT %d x %d x 8.", p_table->size(), f.table_size, f.table_size);
			return false;
		}
		f.table = p_table->data();
	}

	std::vector<Pixel> px(size_t(p_resolution) * p_resolution);
	const int threads = std::max(1, std::min(8, int(std::thread::hardware_concurrency())));
	std::vector<std::thread> pool;
	for (int k = 0; k < threads; k++) {
		pool.emplace_back([&, k]() {
			for (int y = k; y < p_resolution; y += threads) {
				for (int x = 0; x < p_resolution; x++) {
					shade(f, p_resolution, x, y, px[size_t(y) * p_resolution + x]);
				}
			}
		});
	}
	for (std::thread &t : pool) {
		t.join();
	}

	Result &r = *r_result;
	r = Result();
	r.scene_id = p_scene.id;
	auto T = [](const Pixel &q, int c) { return q.t[c]; };
	auto T2 = [](const Pixel &q, int c) { return q.t_half[c]; };
	auto A1 = [](const Pixel &q, int c) { return q.a1[c]; };
	auto A2 = [](const Pixel &q, int c) { return q.a2[c]; };
	auto A3 = [](const Pixel &q, int c) { return q.a3[c]; };
	auto A3n = [](const Pixel &q, int c) { return q.a3n[c]; };
	auto A4 = [](const Pixel &q, int c) { return q.a4[c]; };
	auto A5 = [](const Pixel &q, int c) { return q.a5[c]; };
	auto A6 = [](const Pixel &q, int c) { return q.a6[c]; };
	compare_with(px, A6, T, &r.two_lobe, &r.two_lobe_ratio);
	compare_with(px, A5, T, &r.fresnel_alt, &r.fresnel_alt_ratio);
	compare_with(px, A4, T, &r.total, &r.total_ratio);
	compare_with(px, A3, T, &r.eq510, &r.eq510_ratio);
	compare_with(px, A1, T, &r.fresnel, &r.fresnel_ratio);
	compare_with(px, A2, A1, &r.norm, &r.norm_ratio);
	compare_with(px, A3, A2, &r.lobe, &r.lobe_ratio);
	compare_with(px, A3n, T, &r.no_clip, &r.no_clip_ratio);
	double unused = 0.0;
	compare_with(px, T2, T, &r.truth_convergence, &unused);

	std::map<int, double> per_cell;
	double lobe_sum = 0.0;
	r.angle_index_min = 1 << 30;
	r.angle_index_max = -1;
	for (const Pixel &q : px) {
		if (!q.lit) {
			continue;
		}
		r.pixels++;
		r.angle_index_min = std::min(r.angle_index_min, q.ti);
		r.angle_index_max = std::max(r.angle_index_max, q.ti);
		double e = 0.0;
		for (int c = 0; c < 3; c++) {
			e += (q.a3[c] - q.a2[c]) * (q.a3[c] - q.a2[c]);
		}
		per_cell[q.ti * 1000 + q.ri] += e;
		lobe_sum += e;
	}
	std::vector<std::pair<double, int>> cells;
	for (const auto &kv : per_cell) {
		cells.push_back({ kv.second, kv.first });
	}
	std::sort(cells.rbegin(), cells.rend());
	for (size_t i = 0; i < cells.size() && i < 3; i++) {
		Cell c;
		c.angle_index = cells[i].second / 1000;
		c.roughness_index = cells[i].second % 1000;
		c.share = lobe_sum > 0.0 ? cells[i].first / lobe_sum : 0.0;
		r.worst_cells.push_back(c);
	}
	if (r.pixels == 0) {
		r.angle_index_min = r.angle_index_max = 0;
	}
	return true;
}

String AccuracyLTCTerms::format(const Result &p_r) {
	String s = vformat("%-34s total %.4f (%.3f) | 2-lobe %.4f (%.3f) | eq. 5.10 %.4f (%.3f) | fresnel %.4f (%.3f) | fn/fg %.4f (%.3f) | lobe %.4f (%.3f) | no clip %.4f (%.3f) | F full gap %.4f (%.3f) | truth conv %.4f | rows %d-%d | lobe cells",
			p_r.scene_id.c_str(), p_r.total, p_r.total_ratio, p_r.two_lobe, p_r.two_lobe_ratio, p_r.eq510, p_r.eq510_ratio, p_r.fresnel, p_r.fresnel_ratio, p_r.norm, p_r.norm_ratio, p_r.lobe, p_r.lobe_ratio, p_r.no_clip, p_r.no_clip_ratio, p_r.fresnel_alt, p_r.fresnel_alt_ratio,
			p_r.truth_convergence, p_r.angle_index_min, p_r.angle_index_max);
	for (const Cell &c : p_r.worst_cells) {
		s += vformat(" (r%d,t%d)%s %.0f%%", c.roughness_index, c.angle_index, LTCFitter::is_engine_refit_cell(c.roughness_index, c.angle_index) ? "*" : "", c.share * 100.0);
	}
	return s + "\n";
}
