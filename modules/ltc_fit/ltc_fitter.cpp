/**************************************************************************/
/*  ltc_fitter.cpp                                                        */
/**************************************************************************/
/* godot-area: LTC fitting (see ltc_fitter.h for the model and frame).    */

#include "modules/ltc_fit/ltc_fitter.h"

#include "core/error/error_macros.h"
#include "modules/ltc_fit/ltc_polygon_objective.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/ltc_fit/nelder_mead.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace {

const double ENGINE_REFIT_SMOOTHNESS = 1.0; // The --smoothness of the committed engine refit.

struct Vec {
	double x, y, z;
};

inline Vec vec_normalized(const Vec &p_v) {
	double l = std::sqrt(p_v.x * p_v.x + p_v.y * p_v.y + p_v.z * p_v.z);
	return l > 0.0 ? Vec{ p_v.x / l, p_v.y / l, p_v.z / l } : Vec{ 0.0, 0.0, 1.0 };
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals": a microfacet normal h distributed as
// D_v(h) = G1(v) max(0, v.h) D(h) / v.z, from (p_u1, p_u2). Isotropic alpha.
Vec sample_vndf(const Vec &p_v, double p_alpha, double p_u1, double p_u2) {
	Vec vh = vec_normalized(Vec{ p_alpha * p_v.x, p_alpha * p_v.y, p_v.z });
	double lensq = vh.x * vh.x + vh.y * vh.y;
	Vec t1 = lensq > 0.0 ? Vec{ -vh.y / std::sqrt(lensq), vh.x / std::sqrt(lensq), 0.0 } : Vec{ 1.0, 0.0, 0.0 };
	Vec t2 = { vh.y * t1.z - vh.z * t1.y, vh.z * t1.x - vh.x * t1.z, vh.x * t1.y - vh.y * t1.x };
	double r = std::sqrt(p_u1);
	double phi = 2.0 * LTCBRDF::BRDF_PI * p_u2;
	double p1 = r * std::cos(phi);
	double p2 = r * std::sin(phi);
	double s = 0.5 * (1.0 + vh.z);
	p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
	double pz = std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
	Vec nh = { p1 * t1.x + p2 * t2.x + pz * vh.x, p1 * t1.y + p2 * t2.y + pz * vh.y, p1 * t1.z + p2 * t2.z + pz * vh.z };
	return vec_normalized(Vec{ p_alpha * nh.x, p_alpha * nh.y, std::max(0.0, nh.z) });
}

// Reflects v about h.
inline Vec reflect_about(const Vec &p_v, const Vec &p_h) {
	double d = 2.0 * (p_v.x * p_h.x + p_v.y * p_h.y + p_v.z * p_h.z);
	return Vec{ d * p_h.x - p_v.x, d * p_h.y - p_v.y, d * p_h.z - p_v.z };
}

// Density (1/sr) of l when sampled by reflecting v on a visible normal: G1(v) D(h) / (4 v.z).
double pdf_vndf(const Vec &p_v, const Vec &p_l, double p_alpha) {
	Vec h = vec_normalized(Vec{ p_v.x + p_l.x, p_v.y + p_l.y, p_v.z + p_l.z });
	if (h.z <= 0.0 || p_v.z <= 0.0) {
		return 0.0;
	}
	return LTCBRDF::G1_SmithGGX(p_v.z, p_alpha) * LTCBRDF::D_GGX(h.z, p_alpha) / (4.0 * p_v.z);
}

// Builds (a, b, c, d, e) from the frame's dominant direction (p_zx, 0, p_zz) and m11, m22, m13.
void build_matrix(double p_zx, double p_zz, double p_m11, double p_m22, double p_m13, double *r_m) {
	// X = Y x Z = (zz, 0, -zx); columns: m11 X, m22 Y, m13 X + Z.
	r_m[0] = p_m11 * p_zz;
	r_m[1] = p_m13 * p_zz + p_zx;
	r_m[2] = p_m22;
	r_m[3] = -p_m11 * p_zx;
	r_m[4] = -p_m13 * p_zx + p_zz;
}

// Inverse of build_matrix's m11, m22, m13 for any frame (the columns' lengths and skew).
void extract_parameters(const float *p_cell, double *r_m11, double *r_m22, double *r_m13) {
	double a = p_cell[0], b = p_cell[1], c = p_cell[2], d = p_cell[3], e = p_cell[4];
	double m11 = std::sqrt(a * a + d * d);
	*r_m11 = m11;
	*r_m22 = std::fabs(c);
	*r_m13 = m11 > 0.0 ? (a * b + d * e) / m11 : 0.0;
}

// The axis angle phi of a stored matrix: X = (a, 0, d) / m11 = (cos phi, 0, -sin phi).
double extract_axis_angle(const float *p_cell) {
	return std::atan2(-(double)p_cell[3], (double)p_cell[0]);
}

struct BRDFSample {
	Vec l;
	double rho; // Normalised f cos / fn.
	double pdf; // VNDF density.
};

class CellObjective {
public:
	LTCBRDFVariant variant;
	double alpha = 1.0;
	Vec v;
	double inv_fn = 1.0;
	double zx = 0.0, zz = 1.0;
	bool isotropic = false;
	bool free_axis = false; // x[3] = phi, Z = (sin phi, 0, cos phi).
	int norm = 3;
	std::vector<BRDFSample> brdf_samples;
	std::vector<double> grid_u; // Stratum centres (i + 0.5) / n.

	double rho(const Vec &p_l) const {
		double vv[3] = { v.x, v.y, v.z };
		double ll[3] = { p_l.x, p_l.y, p_l.z };
		return LTCBRDF::evaluate(variant, vv, ll, alpha) * std::max(0.0, p_l.z) * inv_fn;
	}

	void matrix_from(const std::vector<double> &p_x, double *r_m) const {
		double m11 = std::exp(p_x[0]);
		double m22 = isotropic ? m11 : std::exp(p_x[1]);
		double m13 = isotropic ? 0.0 : p_x[2] * m11;
		if (free_axis && !isotropic) {
			build_matrix(std::sin(p_x[3]), std::cos(p_x[3]), m11, m22, m13, r_m);
		} else {
			build_matrix(zx, zz, m11, m22, m13, r_m);
		}
	}

	double power(double p_diff) const {
		return norm == 1 ? p_diff : (norm == 2 ? p_diff * p_diff : p_diff * p_diff * p_diff);
	}

	// Returns E3 and, when r_l1 is not null, the L1 distance.
	double error(const double *p_m, double *r_l1) const {
		double e3 = 0.0, e1 = 0.0;
		for (const BRDFSample &s : brdf_samples) {
			double l[3] = { s.l.x, s.l.y, s.l.z };
			double dl = LTCFitter::ltc_evaluate(p_m, l);
			double denom = s.pdf + dl;
			if (denom <= 0.0) {
				continue;
			}
			double diff = std::fabs(s.rho - dl);
			e3 += power(diff) / denom;
			e1 += diff / denom;
		}
		for (double u1 : grid_u) {
			for (double u2 : grid_u) {
				double l[3];
				LTCFitter::ltc_sample(p_m, u1, u2, l);
				double dl = LTCFitter::ltc_evaluate(p_m, l);
				Vec lv = { l[0], l[1], l[2] };
				double pb = pdf_vndf(v, lv, alpha);
				double denom = pb + dl;
				if (denom <= 0.0) {
					continue;
				}
				double diff = std::fabs(rho(lv) - dl);
				e3 += power(diff) / denom;
				e1 += diff / denom;
			}
		}
		// n samples from each density with the balance heuristic: sum g / (p_brdf + p_ltc) / n.
		const double n = (double)grid_u.size() * (double)grid_u.size();
		if (r_l1) {
			*r_l1 = e1 / n;
		}
		return e3 / n;
	}
};

} // namespace

void LTCCell::write(float *r_out) const {
	r_out[0] = a;
	r_out[1] = b;
	r_out[2] = c;
	r_out[3] = d;
	r_out[4] = e;
	r_out[5] = fn;
	r_out[6] = fg;
	r_out[7] = 0.0f;
}

LTCFitOptions LTCFitter::engine_refit_options() {
	LTCFitOptions options;
	options.free_axis = true;
	options.polygons = true;
	options.smoothness = ENGINE_REFIT_SMOOTHNESS;
	return options;
}

bool LTCFitter::get_three_parameter_engine_table(std::vector<float> &r_table, int p_threads) {
	const int n = LTCTableIO::get_builtin_size();
	const float *src = LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX);
	r_table.assign(src, src + (size_t)n * n * FLOATS_PER_CELL);
	return fit_table(LTC_BRDF_ENGINE_GGX, n, ENGINE_REFIT_R0, ENGINE_REFIT_R1, ENGINE_REFIT_T0, ENGINE_REFIT_T1, p_threads, r_table, nullptr, nullptr);
}

double LTCFitter::get_roughness(int p_size, int p_roughness_index) {
	return p_size > 1 ? (double)p_roughness_index / (double)(p_size - 1) : 1.0;
}

double LTCFitter::get_alpha(int p_size, int p_roughness_index) {
	double r = get_roughness(p_size, p_roughness_index);
	return std::max(r * r, MIN_ALPHA);
}

double LTCFitter::get_theta(int p_size, int p_angle_index) {
	double u = p_size > 1 ? (double)p_angle_index / (double)(p_size - 1) : 0.0;
	return std::min(MAX_THETA, std::acos(std::max(-1.0, 1.0 - u * u)));
}

double LTCFitter::ltc_evaluate(const double *p_m, const double *p_l) {
	const double a = p_m[0], b = p_m[1], c = p_m[2], d = p_m[3], e = p_m[4];
	const double det2 = a * e - b * d; // det M = c (ae - bd).
	if (det2 == 0.0 || c == 0.0) {
		return 0.0;
	}
	const double s = 1.0 / det2;
	// Thesis eq. (5.8): M^-1 = [[s e, 0, -s b], [0, 1/c, 0], [-s d, 0, s a]].
	const double ox = s * (e * p_l[0] - b * p_l[2]);
	const double oy = p_l[1] / c;
	const double oz = s * (a * p_l[2] - d * p_l[0]);
	const double len2 = ox * ox + oy * oy + oz * oz;
	if (len2 <= 0.0) {
		return 0.0;
	}
	const double len = std::sqrt(len2);
	if (oz <= 0.0) {
		return 0.0;
	}
	const double det_inv = std::fabs(s / c);
	return (oz / len) / LTCBRDF::BRDF_PI * det_inv / (len2 * len);
}

void LTCFitter::ltc_sample(const double *p_m, double p_u1, double p_u2, double *r_l) {
	const double r = std::sqrt(p_u1);
	const double phi = 2.0 * LTCBRDF::BRDF_PI * p_u2;
	const double ox = r * std::cos(phi);
	const double oy = r * std::sin(phi);
	const double oz = std::sqrt(std::max(0.0, 1.0 - p_u1));
	Vec l = vec_normalized(Vec{ p_m[0] * ox + p_m[1] * oz, p_m[2] * oy, p_m[3] * ox + p_m[4] * oz });
	r_l[0] = l.x;
	r_l[1] = l.y;
	r_l[2] = l.z;
}

void LTCFitter::integrate_albedo(LTCBRDFVariant p_variant, double p_alpha, double p_theta, int p_samples, double *r_fn, double *r_fg, double *r_dominant) {
	const Vec v = { std::sin(p_theta), 0.0, std::cos(p_theta) };
	const double vv[3] = { v.x, v.y, v.z };
	double fn = 0.0, fg = 0.0;
	double dir[3] = { 0.0, 0.0, 0.0 };
	for (int i = 0; i < p_samples; i++) {
		for (int j = 0; j < p_samples; j++) {
			const double u1 = (i + 0.5) / p_samples;
			const double u2 = (j + 0.5) / p_samples;
			Vec h = sample_vndf(v, p_alpha, u1, u2);
			Vec l = reflect_about(v, h);
			if (l.z <= 0.0) {
				continue;
			}
			double pdf = pdf_vndf(v, l, p_alpha);
			if (pdf <= 0.0) {
				continue;
			}
			double ll[3] = { l.x, l.y, l.z };
			double w = LTCBRDF::evaluate(p_variant, vv, ll, p_alpha) * l.z / pdf;
			double voh = std::max(0.0, v.x * h.x + v.y * h.y + v.z * h.z);
			double m = 1.0 - voh;
			double m2 = m * m;
			fn += w;
			fg += w * m2 * m2 * m;
			dir[0] += w * l.x;
			dir[1] += w * l.y;
			dir[2] += w * l.z;
		}
	}
	const double n = (double)p_samples * (double)p_samples;
	*r_fn = fn / n;
	*r_fg = fg / n;
	if (r_dominant) {
		// Projected to the xz-plane (the lobe is symmetric in y) and normalised.
		Vec z = vec_normalized(Vec{ dir[0], 0.0, dir[2] });
		r_dominant[0] = z.x;
		r_dominant[1] = 0.0;
		r_dominant[2] = z.z;
	}
}

void LTCFitter::build_polygon_objective(LTCBRDFVariant p_variant, double p_alpha, double p_theta, double p_inv_fn, LTCPolygonObjective *r_objective) {
	const Vec v = { std::sin(p_theta), 0.0, std::cos(p_theta) };
	const double vv[3] = { v.x, v.y, v.z };
	const int n = LTCPolygonObjective::SAMPLES;
	std::vector<double> directions, weights;
	directions.reserve(size_t(n) * n * 3);
	weights.reserve(size_t(n) * n);
	for (int i = 0; i < n; i++) {
		for (int j = 0; j < n; j++) {
			Vec h = sample_vndf(v, p_alpha, (i + 0.5) / n, (j + 0.5) / n);
			Vec l = reflect_about(v, h);
			double pdf = pdf_vndf(v, l, p_alpha);
			directions.insert(directions.end(), { l.x, l.y, l.z });
			const double ll[3] = { l.x, l.y, l.z };
			const double rho = LTCBRDF::evaluate(p_variant, vv, ll, p_alpha) * std::max(0.0, l.z) * p_inv_fn;
			weights.push_back(pdf > 0.0 && l.z > 0.0 ? rho / pdf : 0.0);
		}
	}
	r_objective->build(directions, weights);
}

void LTCFitter::build_free_axis_matrix(double p_phi, double p_m11, double p_m22, double p_m13, double *r_m) {
	build_matrix(std::sin(p_phi), std::cos(p_phi), p_m11, p_m22, p_m13, r_m);
}

void LTCFitter::get_free_axis_parameters(const float *p_cell, double *r_phi, double *r_m11, double *r_m22, double *r_m13) {
	extract_parameters(p_cell, r_m11, r_m22, r_m13);
	*r_phi = extract_axis_angle(p_cell);
}

LTCCell LTCFitter::fit_cell(LTCBRDFVariant p_variant, int p_size, int p_roughness_index, int p_angle_index, const float *p_init_or_null, const LTCFitOptions &p_options, const float *p_self_or_null) {
	LTCCell cell;
	ERR_FAIL_INDEX_V_MSG((int)p_variant, (int)LTC_BRDF_MAX, cell, "Unknown LTC BRDF variant.");
	ERR_FAIL_COND_V_MSG(p_size < 2, cell, "The LTC table needs at least 2 x 2 cells.");
	ERR_FAIL_INDEX_V_MSG(p_roughness_index, p_size, cell, "LTC roughness index out of range.");
	ERR_FAIL_INDEX_V_MSG(p_angle_index, p_size, cell, "LTC view-angle index out of range.");

	CellObjective obj;
	obj.variant = p_variant;
	obj.alpha = get_alpha(p_size, p_roughness_index);
	const double theta = get_theta(p_size, p_angle_index);
	obj.v = Vec{ std::sin(theta), 0.0, std::cos(theta) };
	obj.isotropic = p_angle_index == 0;
	ERR_FAIL_COND_V_MSG(p_options.norm < 1 || p_options.norm > 3, cell, vformat("LTC fit norm must be 1, 2 or 3, got %d.", p_options.norm));
	obj.free_axis = p_options.free_axis;
	obj.norm = p_options.norm;

	double fn = 0.0, fg = 0.0, dominant[3];
	integrate_albedo(p_variant, obj.alpha, theta, ALBEDO_SAMPLES, &fn, &fg, dominant);
	cell.fn = (float)fn;
	cell.fg = (float)fg;
	obj.inv_fn = fn > 0.0 ? 1.0 / fn : 0.0;
	if (obj.isotropic) {
		obj.zx = 0.0;
		obj.zz = 1.0;
	} else {
		obj.zx = dominant[0];
		obj.zz = dominant[2];
	}

	obj.grid_u.resize(FIT_SAMPLES);
	for (int i = 0; i < FIT_SAMPLES; i++) {
		obj.grid_u[i] = (i + 0.5) / FIT_SAMPLES;
	}
	obj.brdf_samples.reserve(FIT_SAMPLES * FIT_SAMPLES);
	for (double u1 : obj.grid_u) {
		for (double u2 : obj.grid_u) {
			BRDFSample s;
			Vec h = sample_vndf(obj.v, obj.alpha, u1, u2);
			s.l = reflect_about(obj.v, h);
			s.pdf = pdf_vndf(obj.v, s.l, obj.alpha);
			s.rho = obj.rho(s.l);
			obj.brdf_samples.push_back(s);
		}
	}

	// A start x from stored floats (the chain's rougher neighbour, or the cell itself); default without.
	auto start_from = [&](const float *p_cell) {
		double m11 = 1.0, m22 = 1.0, m13 = 0.0;
		double phi = std::atan2(obj.zx, obj.zz);
		if (p_cell) {
			extract_parameters(p_cell, &m11, &m22, &m13);
			if (!(m11 > 0.0) || !(m22 > 0.0) || !std::isfinite(m13)) {
				WARN_PRINT("LTC fit: unusable initial cell, starting from the default.");
				m11 = m22 = 1.0;
				m13 = 0.0;
			} else if (obj.free_axis) {
				phi = extract_axis_angle(p_cell);
			}
		}
		if (obj.isotropic) {
			return std::vector<double>{ std::log(std::sqrt(m11 * m22)) };
		}
		if (obj.free_axis) {
			return std::vector<double>{ std::log(m11), std::log(m22), m13 / m11, phi };
		}
		return std::vector<double>{ std::log(m11), std::log(m22), m13 / m11 };
	};
	std::vector<double> x0 = start_from(p_init_or_null);
	LTCPolygonObjective polygons;
	if (p_options.polygons) {
		build_polygon_objective(p_variant, obj.alpha, theta, obj.inv_fn, &polygons);
	}
	double previous[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
	const bool smooth = p_options.smoothness > 0.0 && p_init_or_null;
	for (int j = 0; j < 5 && smooth; j++) {
		previous[j] = p_init_or_null[j];
	}
	NelderMead::Function f = [&obj, &polygons, &p_options, &previous, smooth](const std::vector<double> &p_x) {
		double m[5];
		obj.matrix_from(p_x, m);
		if (p_options.polygons) {
			// Scored as stored: float entries, and a matrix the shader can invert (a e - b d > 0 in float).
			for (double &v : m) {
				v = double(float(v));
			}
			if (!(float(m[0]) * float(m[4]) - float(m[1]) * float(m[3]) > 0.0f) || !(m[2] > 0.0)) {
				return 1e300;
			}
		}
		double e = p_options.polygons ? polygons.error(m) : obj.error(m, nullptr);
		if (smooth) {
			double d2 = 0.0;
			for (int j = 0; j < 5; j++) {
				d2 += (m[j] - previous[j]) * (m[j] - previous[j]);
			}
			e *= 1.0 + p_options.smoothness * d2;
		}
		return std::isfinite(e) ? e : 1e300;
	};
	// Nelder-Mead, restarted from its own result (fresh simplex) while that still improves: a collapsed
	// simplex is the usual way the method stalls on the elongated valleys of grazing, glossy cells.
	NelderMead::Result res = NelderMead::minimize(f, x0, 0.1, 1e-6, MAX_ITERATIONS);
	int iterations = res.iterations;
	if (p_self_or_null && p_self_or_null != p_init_or_null && !p_options.polygons) {
		// A refit also starts from the cell's own value: never worse than the table it replaces.
		NelderMead::Result own = NelderMead::minimize(f, start_from(p_self_or_null), 0.05, 1e-6, MAX_ITERATIONS);
		iterations += own.iterations;
		if (own.value < res.value) {
			res = own;
		}
	}
	iterations += restart_while_improving(f, res);

	// A start that does not overlap the lobe at all (possible at grazing, near-mirror cells) leaves the
	// objective flat; then also try a start sized to the lobe, m11 = m22 = alpha, and keep the better.
	double l1 = 0.0;
	{
		double m[5];
		obj.matrix_from(res.x, m);
		obj.error(m, &l1);
	}
	if (l1 > FALLBACK_L1) {
		std::vector<double> x1;
		if (obj.isotropic) {
			x1 = { std::log(obj.alpha) };
		} else if (obj.free_axis) {
			x1 = { std::log(obj.alpha), std::log(obj.alpha), 0.0, std::atan2(obj.zx, obj.zz) };
		} else {
			x1 = { std::log(obj.alpha), std::log(obj.alpha), 0.0 };
		}
		NelderMead::Result alt = NelderMead::minimize(f, x1, 0.1, 1e-6, MAX_ITERATIONS);
		iterations += alt.iterations;
		if (alt.value < res.value) {
			res = alt;
		}
	}

	double m[5];
	obj.matrix_from(res.x, m);
	cell.a = (float)m[0];
	cell.b = (float)m[1];
	cell.c = (float)m[2];
	cell.d = (float)m[3];
	cell.e = (float)m[4];
	// Report the error of the stored (float) matrix.
	double mf[5] = { cell.a, cell.b, cell.c, cell.d, cell.e };
	cell.error_l3 = obj.error(mf, &cell.error_l1);
	if (p_options.polygons) {
		cell.error_l3 = polygons.error(mf);
	}
	cell.iterations = iterations;
	return cell;
}

bool LTCFitter::fit_table(LTCBRDFVariant p_variant, int p_size, int p_r0, int p_r1, int p_t0, int p_t1, int p_threads, std::vector<float> &r_table, std::vector<LTCCell> *r_cells, std::atomic<int> *r_done,
		const LTCFitOptions &p_options) {
	ERR_FAIL_INDEX_V_MSG((int)p_variant, (int)LTC_BRDF_MAX, false, "Unknown LTC BRDF variant.");
	ERR_FAIL_COND_V_MSG(p_size < 2, false, "The LTC table needs at least 2 x 2 cells.");
	ERR_FAIL_COND_V_MSG(p_r0 < 0 || p_r1 >= p_size || p_r0 > p_r1, false, vformat("Bad LTC roughness range %d:%d for size %d.", p_r0, p_r1, p_size));
	ERR_FAIL_COND_V_MSG(p_t0 < 0 || p_t1 >= p_size || p_t0 > p_t1, false, vformat("Bad LTC view-angle range %d:%d for size %d.", p_t0, p_t1, p_size));
	ERR_FAIL_COND_V_MSG(r_table.size() != (size_t)p_size * p_size * FLOATS_PER_CELL, false, "The LTC table buffer has the wrong size.");
	if (r_cells) {
		r_cells->resize((size_t)p_size * p_size);
	}

	auto chain = [&](int t) {
		const float *init = nullptr;
		if (p_r1 < p_size - 1) {
			init = &r_table[((size_t)t * p_size + p_r1 + 1) * FLOATS_PER_CELL];
		}
		for (int r = p_r1; r >= p_r0; r--) {
			float *out = &r_table[((size_t)t * p_size + r) * FLOATS_PER_CELL];
			float self[FLOATS_PER_CELL];
			std::copy(out, out + FLOATS_PER_CELL, self);
			LTCCell cell = fit_cell(p_variant, p_size, r, t, init, p_options, p_options.free_axis ? self : nullptr);
			cell.write(out);
			if (r_cells) {
				(*r_cells)[(size_t)t * p_size + r] = cell;
			}
			init = out;
			if (r_done) {
				r_done->fetch_add(1);
			}
		}
	};
	run_chains(p_threads, p_t0, p_t1, chain);
	return true;
}

int LTCFitter::restart_while_improving(const NelderMead::Function &p_function, NelderMead::Result &r_result) {
	int iterations = 0;
	for (int restart = 0; restart < MAX_RESTARTS; restart++) {
		NelderMead::Result again = NelderMead::minimize(p_function, r_result.x, 0.05, 1e-6, MAX_ITERATIONS);
		iterations += again.iterations;
		const bool better = again.value < r_result.value * (1.0 - 1e-4);
		if (again.value < r_result.value) {
			r_result = again;
		}
		if (!better) {
			break;
		}
	}
	return iterations;
}

void LTCFitter::run_chains(int p_threads, int p_t0, int p_t1, const std::function<void(int)> &p_chain) {
	std::atomic<int> next_chain(p_t0);
	auto worker = [&]() {
		for (int t = next_chain.fetch_add(1); t <= p_t1; t = next_chain.fetch_add(1)) {
			p_chain(t);
		}
	};
	int threads = p_threads > 0 ? p_threads : (int)std::thread::hardware_concurrency();
	threads = std::max(1, std::min(threads, p_t1 - p_t0 + 1));
	std::vector<std::thread> pool;
	for (int i = 1; i < threads; i++) {
		pool.emplace_back(worker);
	}
	worker();
	for (std::thread &th : pool) {
		th.join();
	}
}
