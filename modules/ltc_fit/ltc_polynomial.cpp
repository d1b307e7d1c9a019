/**************************************************************************/
/*  ltc_polynomial.cpp                                                    */
/**************************************************************************/
/* godot-area: least-squares patch polynomials for the LTC lookup table  */
/* (see ltc_polynomial.h).                                                */

#include "modules/ltc_fit/ltc_polynomial.h"

#include "core/error/error_macros.h"
#include "core/io/file_io.h"
#include "modules/ltc_fit/ltc_fitter.h"

#include "servers/rendering/renderer_rd/ltc_poly_data.inc"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

static_assert(sizeof(LTC_POLY_COEFFS) / sizeof(LTC_POLY_COEFFS[0]) == LTCPolynomial::COEFFS, "ltc_poly_data.inc has the wrong size (regenerate it with `godot-area ltc-fit --polynomial`).");

const char *LTCPolynomial::COMPONENT_NAMES[LTCPolynomial::COMPONENTS] = { "a", "b", "c", "d", "e", "fn", "fg" };
const char *LTCPolynomial::DEFAULT_INC_PATH = "servers/rendering/renderer_rd/ltc_poly_data.inc";
const char *LTCPolynomial::DEFAULT_GLSL_PATH = "servers/rendering/renderer_rd/shaders/ltc_poly_coeffs_inc.glsl";

static const double POLY_PI = 3.14159265358979323846;

static double _seam_theta() {
	return LTCPolynomial::SEAM_THETA_DEGREES * POLY_PI / 180.0;
}

static double _blend_theta() {
	return LTCPolynomial::BLEND_THETA_DEGREES * POLY_PI / 180.0;
}

// GLSL smoothstep(p_e0, p_e1, p_v).
template <typename T>
static T _smoothstep(T p_e0, T p_e1, T p_v) {
	T t = (p_v - p_e0) / (p_e1 - p_e0);
	t = std::min(std::max(t, T(0)), T(1));
	return t * t * (T(3) - T(2) * t);
}

LTCPolynomial::Patch LTCPolynomial::get_patch(int p_patch) {
	Patch patch;
	ERR_FAIL_INDEX_V_MSG(p_patch, PATCHES, patch, vformat("LTC polynomial: patch %d does not exist.", p_patch));
	const bool high_theta = p_patch / 2 == 1, high_r = p_patch % 2 == 1;
	const double t0 = high_theta ? _seam_theta() - _blend_theta() : 0.0;
	const double t1 = high_theta ? POLY_PI / 2.0 : _seam_theta() + _blend_theta();
	const double r0 = high_r ? SEAM_ROUGHNESS - BLEND_ROUGHNESS : 0.0;
	const double r1 = high_r ? 1.0 : SEAM_ROUGHNESS + BLEND_ROUGHNESS;
	patch.x_center = get_x(0.5 * (r0 + r1));
	patch.x_half = 0.5 * (r1 - r0);
	patch.y_center = get_y(0.5 * (t0 + t1));
	patch.y_half = 0.5 * (t1 - t0);
	return patch;
}

void LTCPolynomial::get_weights(double p_roughness, double p_theta, double *r_weights) {
	const double wt = _smoothstep(_seam_theta() - _blend_theta(), _seam_theta() + _blend_theta(), p_theta);
	const double wr = _smoothstep(SEAM_ROUGHNESS - BLEND_ROUGHNESS, SEAM_ROUGHNESS + BLEND_ROUGHNESS, p_roughness);
	r_weights[0] = (1.0 - wt) * (1.0 - wr);
	r_weights[1] = (1.0 - wt) * wr;
	r_weights[2] = wt * (1.0 - wr);
	r_weights[3] = wt * wr;
}

void LTCPolynomial::monomials(double p_s, double p_t, double *r_terms) {
	int at = 0;
	double si = 1.0;
	for (int i = 0; i <= DEGREE; i++) {
		double term = si;
		for (int j = 0; j <= DEGREE - i; j++) {
			r_terms[at++] = term;
			term *= p_t;
		}
		si *= p_s;
	}
}

double LTCPolynomial::evaluate(const double *p_coeffs, double p_s, double p_t) {
	double terms[TERMS];
	monomials(p_s, p_t, terms);
	double sum = 0.0;
	for (int k = 0; k < TERMS; k++) {
		sum += p_coeffs[k] * terms[k];
	}
	return sum;
}

// The first coefficient of the row i (power of s) in the i-outer, j-inner order.
static int _row_start(int p_i) {
	return p_i * (LTCPolynomial::DEGREE + 1) - p_i * (p_i - 1) / 2;
}

float LTCPolynomial::evaluate_float(const float *p_coeffs, float p_s, float p_t) {
	// Horner in s over Q_i(t) (Horner in t), from the highest power down: as the generated GLSL.
	float sum = 0.0f;
	for (int i = DEGREE; i >= 0; i--) {
		const float *row = p_coeffs + _row_start(i);
		float q = row[DEGREE - i];
		for (int j = DEGREE - i - 1; j >= 0; j--) {
			q = q * p_t + row[j];
		}
		sum = i == DEGREE ? q : sum * p_s + q;
	}
	return sum;
}

double LTCPolynomial::evaluate_component(const double *p_coeffs, int p_component, double p_roughness, double p_theta) {
	ERR_FAIL_NULL_V(p_coeffs, 0.0);
	ERR_FAIL_INDEX_V(p_component, COMPONENTS, 0.0);
	double w[PATCHES];
	get_weights(p_roughness, p_theta, w);
	double sum = 0.0;
	for (int p = 0; p < PATCHES; p++) {
		if (w[p] > 0.0) {
			const Patch patch = get_patch(p);
			const double s = (get_x(p_roughness) - patch.x_center) / patch.x_half;
			const double t = (get_y(p_theta) - patch.y_center) / patch.y_half;
			sum += w[p] * evaluate(p_coeffs + ((size_t)p * COMPONENTS + p_component) * TERMS, s, t);
		}
	}
	return sum;
}

float LTCPolynomial::evaluate_component_float(const float *p_coeffs, int p_component, float p_roughness, float p_theta) {
	ERR_FAIL_NULL_V(p_coeffs, 0.0f);
	ERR_FAIL_INDEX_V(p_component, COMPONENTS, 0.0f);
	const float seam_t = (float)_seam_theta(), blend_t = (float)_blend_theta();
	const float wt = _smoothstep(seam_t - blend_t, seam_t + blend_t, p_theta);
	const float wr = _smoothstep((float)(SEAM_ROUGHNESS - BLEND_ROUGHNESS), (float)(SEAM_ROUGHNESS + BLEND_ROUGHNESS), p_roughness);
	const float w[PATCHES] = { (1.0f - wt) * (1.0f - wr), (1.0f - wt) * wr, wt * (1.0f - wr), wt * wr };
	const float x = 1.0f + p_roughness, y = 1.0f + p_theta;
	float sum = 0.0f;
	for (int p = 0; p < PATCHES; p++) {
		if (w[p] > 0.0f) {
			const Patch patch = get_patch(p);
			const float s = (x - (float)patch.x_center) * (float)(1.0 / patch.x_half);
			const float t = (y - (float)patch.y_center) * (float)(1.0 / patch.y_half);
			sum += w[p] * evaluate_float(p_coeffs + ((size_t)p * COMPONENTS + p_component) * TERMS, s, t);
		}
	}
	return sum;
}

bool LTCPolynomial::solve_least_squares(const std::vector<double> &p_a, int p_rows, int p_cols, const std::vector<double> &p_b, std::vector<double> &r_x) {
	ERR_FAIL_COND_V_MSG(p_cols < 1 || p_rows < p_cols, false, vformat("Least squares needs rows >= cols >= 1, got %d x %d.", p_rows, p_cols));
	ERR_FAIL_COND_V_MSG(p_a.size() != (size_t)p_rows * p_cols || p_b.size() != (size_t)p_rows, false, "Least squares: the matrix or right-hand side has the wrong size.");
	std::vector<double> a = p_a;
	std::vector<double> b = p_b;
	const int m = p_rows, n = p_cols;
	// Column scaling (equilibration): every column gets unit norm.
	std::vector<double> scale(n, 1.0);
	for (int j = 0; j < n; j++) {
		double s = 0.0;
		for (int i = 0; i < m; i++) {
			s += a[(size_t)i * n + j] * a[(size_t)i * n + j];
		}
		s = std::sqrt(s);
		ERR_FAIL_COND_V_MSG(!(s > 0.0) || !std::isfinite(s), false, vformat("Least squares: column %d is zero or not finite.", j));
		scale[j] = 1.0 / s;
		for (int i = 0; i < m; i++) {
			a[(size_t)i * n + j] *= scale[j];
		}
	}
	// Householder QR: A = Q R, R stored in the upper triangle of a, Q^T applied to b on the way.
	std::vector<double> v(m);
	double max_diag = 0.0;
	for (int k = 0; k < n; k++) {
		double norm = 0.0;
		for (int i = k; i < m; i++) {
			norm += a[(size_t)i * n + k] * a[(size_t)i * n + k];
		}
		norm = std::sqrt(norm);
		const double x0 = a[(size_t)k * n + k];
		const double alpha = x0 >= 0.0 ? -norm : norm; // R_kk; the sign avoids cancellation in v0.
		for (int i = k; i < m; i++) {
			v[i] = a[(size_t)i * n + k];
		}
		v[k] -= alpha;
		double vv = 0.0;
		for (int i = k; i < m; i++) {
			vv += v[i] * v[i];
		}
		if (vv > 0.0) {
			for (int j = k; j < n; j++) {
				double dot = 0.0;
				for (int i = k; i < m; i++) {
					dot += v[i] * a[(size_t)i * n + j];
				}
				const double f = 2.0 * dot / vv;
				for (int i = k; i < m; i++) {
					a[(size_t)i * n + j] -= f * v[i];
				}
			}
			double dot = 0.0;
			for (int i = k; i < m; i++) {
				dot += v[i] * b[i];
			}
			const double f = 2.0 * dot / vv;
			for (int i = k; i < m; i++) {
				b[i] -= f * v[i];
			}
		}
		max_diag = std::max(max_diag, std::fabs(a[(size_t)k * n + k]));
	}
	for (int k = 0; k < n; k++) {
		ERR_FAIL_COND_V_MSG(!(std::fabs(a[(size_t)k * n + k]) > 1e-14 * max_diag), false, vformat("Least squares: the matrix is rank deficient (column %d).", k));
	}
	// Back substitution R x = (Q^T b)[0, n).
	std::vector<double> x(n);
	for (int k = n - 1; k >= 0; k--) {
		double s = b[k];
		for (int j = k + 1; j < n; j++) {
			s -= a[(size_t)k * n + j] * x[j];
		}
		x[k] = s / a[(size_t)k * n + k];
	}
	for (int j = 0; j < n; j++) {
		x[j] *= scale[j];
		ERR_FAIL_COND_V_MSG(!std::isfinite(x[j]), false, "Least squares: the solution is not finite.");
	}
	r_x = x;
	return true;
}

bool LTCPolynomial::fit_table(const float *p_table, int p_size, Fit &r_fit) {
	ERR_FAIL_NULL_V_MSG(p_table, false, "LTC polynomial fit: no table.");
	ERR_FAIL_COND_V_MSG(p_size < 16, false, vformat("LTC polynomial fit: a %dx%d table is too coarse for %d patches of degree %d.", p_size, p_size, PATCHES, DEGREE));
	// One row per cell: the four patches' monomials times the patch weights, so that the least-squares
	// solution is the best blended fit (not four separate fits averaged in the blend zones).
	const int rows = p_size * p_size, cols = PATCHES * TERMS;
	std::vector<double> design((size_t)rows * cols, 0.0);
	for (int t = 0; t < p_size; t++) {
		const double theta = LTCFitter::get_theta(p_size, t);
		for (int r = 0; r < p_size; r++) {
			const double roughness = (double)r / (p_size - 1);
			double w[PATCHES];
			get_weights(roughness, theta, w);
			double *row = &design[((size_t)t * p_size + r) * cols];
			for (int p = 0; p < PATCHES; p++) {
				if (w[p] <= 0.0) {
					continue;
				}
				const Patch patch = get_patch(p);
				double terms[TERMS];
				monomials((get_x(roughness) - patch.x_center) / patch.x_half, (get_y(theta) - patch.y_center) / patch.y_half, terms);
				for (int j = 0; j < TERMS; j++) {
					row[p * TERMS + j] = w[p] * terms[j];
				}
			}
		}
	}
	Fit fit;
	fit.coeffs.assign((size_t)COEFFS, 0.0);
	for (int k = 0; k < COMPONENTS; k++) {
		std::vector<double> rhs(rows);
		for (int i = 0; i < rows; i++) {
			rhs[i] = p_table[(size_t)i * LTCFitter::FLOATS_PER_CELL + k];
		}
		std::vector<double> x;
		ERR_FAIL_COND_V_MSG(!solve_least_squares(design, rows, cols, rhs, x), false, vformat("LTC polynomial fit of component %s failed.", COMPONENT_NAMES[k]));
		for (int p = 0; p < PATCHES; p++) {
			for (int j = 0; j < TERMS; j++) {
				fit.coeffs[((size_t)p * COMPONENTS + k) * TERMS + j] = x[(size_t)p * TERMS + j];
			}
		}
	}
	Fit below_80;
	measure(p_table, p_size, fit.coeffs, below_80, 80.0 * POLY_PI / 180.0);
	measure(p_table, p_size, fit.coeffs, fit);
	for (int k = 0; k < COMPONENTS; k++) {
		fit.rmse_80[k] = below_80.rmse[k];
	}
	r_fit = fit;
	return true;
}

void LTCPolynomial::measure(const float *p_table, int p_size, const std::vector<double> &p_coeffs, Fit &r_fit, double p_max_theta) {
	ERR_FAIL_NULL_MSG(p_table, "LTC polynomial: no table to measure against.");
	ERR_FAIL_COND_MSG(p_coeffs.size() != (size_t)COEFFS, "LTC polynomial: wrong number of coefficients.");
	for (int k = 0; k < COMPONENTS; k++) {
		double sum2 = 0.0, max_err = 0.0;
		int max_r = 0, max_t = 0, cells = 0;
		for (int t = 0; t < p_size; t++) {
			const double theta = LTCFitter::get_theta(p_size, t);
			if (theta > p_max_theta) {
				continue;
			}
			for (int r = 0; r < p_size; r++) {
				const double want = p_table[((size_t)t * p_size + r) * LTCFitter::FLOATS_PER_CELL + k];
				const double err = evaluate_component(p_coeffs.data(), k, (double)r / (p_size - 1), theta) - want;
				sum2 += err * err;
				cells++;
				if (std::fabs(err) > max_err) {
					max_err = std::fabs(err);
					max_r = r;
					max_t = t;
				}
			}
		}
		r_fit.rmse[k] = cells > 0 ? std::sqrt(sum2 / cells) : 0.0;
		r_fit.max_error[k] = max_err;
		r_fit.max_error_r[k] = max_r;
		r_fit.max_error_t[k] = max_t;
	}
}

const double *LTCPolynomial::get_builtin_coeffs() {
	return LTC_POLY_COEFFS;
}

static void _append_header(std::ostringstream &r_out, const char *p_file, const LTCPolynomial::Fit &p_fit, const String &p_command, const char *p_comment_prefix) {
	char line[160];
	snprintf(line, sizeof(line), "/*  %-70s*/", p_file);
	r_out << "/**************************************************************************/\n";
	r_out << line << "\n";
	r_out << "/**************************************************************************/\n";
	const String blank = String(p_comment_prefix).substr(0, String(p_comment_prefix).find_last_not_of(' ') + 1);
	r_out << "/* GENERATED FILE, do not edit: degree-" << LTCPolynomial::DEGREE << " least-squares polynomials for the LTC\n";
	r_out << p_comment_prefix << "lookup table LTC_LUT_ENGINE_GGX (thesis section 5.4.3, appendix C), written by\n";
	r_out << p_comment_prefix << "modules/ltc_fit (ltc_polynomial.cpp) with the command:\n";
	r_out << p_comment_prefix << "  " << p_command << "\n";
	r_out << blank << "\n";
	r_out << p_comment_prefix << "x = 1 + r (r = perceptual roughness, the LUT's axis; GGX alpha = r^2), y = 1 + theta_v\n";
	r_out << p_comment_prefix << "(radians). The domain is split into " << LTCPolynomial::PATCHES << " patches: theta_v below / above "
		  << LTCPolynomial::SEAM_THETA_DEGREES << " deg (blend +-" << LTCPolynomial::BLEND_THETA_DEGREES << " deg)\n";
	r_out << p_comment_prefix << "times r below / above " << LTCPolynomial::SEAM_ROUGHNESS << " (blend +-" << LTCPolynomial::BLEND_ROUGHNESS
		  << "); patch p = 2 * theta_half + r_half. Per component\n";
	r_out << p_comment_prefix << "k in (a, b, c, d, e, fn, fg): P_k = sum_p w_p P_k,p, w_p = products of smoothsteps across\n";
	r_out << p_comment_prefix << "the seams (sum 1). P_k,p = sum over i + j <= " << LTCPolynomial::DEGREE << " of c_p,k,ij s^i t^j, a degree-"
		  << LTCPolynomial::DEGREE << " polynomial in (x, y)\n";
	r_out << p_comment_prefix << "in its patch's centred variables s = (x - x_p) / hx_p, t = (y - y_p) / hy_p (in [-1, 1] on\n";
	r_out << p_comment_prefix << "the patch, blend zones included); " << LTCPolynomial::TERMS << " coefficients ordered by i, then j. The "
		  << LTCPolynomial::PATCHES << " x " << LTCPolynomial::TERMS << " coefficients\n";
	r_out << p_comment_prefix << "of a component are one least-squares fit of the blended P_k to the 64 x 64 table cells\n";
	r_out << p_comment_prefix << "(Householder QR in double).\n";
	r_out << blank << "\n";
	r_out << p_comment_prefix << "Error against the table: RMSE = sqrt(sum (P_k - k)^2 / N) over all N cells, over the\n";
	r_out << p_comment_prefix << "cells with theta_v <= 80 deg, and max |P_k - k| (all cells):\n";
	for (int k = 0; k < LTCPolynomial::COMPONENTS; k++) {
		char buf[160];
		snprintf(buf, sizeof(buf), "  %-2s RMSE %.5f (%.5f up to 80 deg), max %.5f at (ri %d, ti %d)", LTCPolynomial::COMPONENT_NAMES[k], p_fit.rmse[k], p_fit.rmse_80[k],
				p_fit.max_error[k], p_fit.max_error_r[k], p_fit.max_error_t[k]);
		r_out << p_comment_prefix << buf << "\n";
	}
	r_out << blank << "\n";
	r_out << p_comment_prefix << "The thesis (appendix C) fits one polynomial per component over the whole table; for our\n";
	r_out << p_comment_prefix << "table that leaves fn at RMSE 0.022 (max 0.26 at grazing angles on glossy surfaces).\n";
	r_out << " */\n";
}

String LTCPolynomial::format_inc(const Fit &p_fit, const String &p_command) {
	ERR_FAIL_COND_V_MSG(p_fit.coeffs.size() != (size_t)COEFFS, String(), "LTC polynomial: wrong number of coefficients.");
	std::ostringstream o;
	_append_header(o, "ltc_poly_data.inc", p_fit, p_command, " * ");
	o << "\n#pragma once\n\n";
	o << "// [patch][component][term]\n";
	o << "static const double LTC_POLY_COEFFS[" << PATCHES << " * " << COMPONENTS << " * " << TERMS << "] = {\n";
	char buf[64];
	for (int p = 0; p < PATCHES; p++) {
		for (int k = 0; k < COMPONENTS; k++) {
			o << "\t";
			for (int j = 0; j < TERMS; j++) {
				snprintf(buf, sizeof(buf), "%.17g", p_fit.coeffs[((size_t)p * COMPONENTS + k) * TERMS + j]);
				o << buf << (j + 1 < TERMS ? ", " : ",");
			}
			o << " // patch " << p << ", " << COMPONENT_NAMES[k] << "\n";
		}
	}
	o << "};\n";
	return o.str();
}

// A GLSL float literal of the float nearest to p_value.
static String _glsl_float(double p_value) {
	char buf[64];
	snprintf(buf, sizeof(buf), "%.9g", (double)(float)p_value);
	String s = buf;
	if (s.find_first_of(".e") == String::npos) {
		s += ".0";
	}
	return s;
}

String LTCPolynomial::format_glsl(const Fit &p_fit, const String &p_command) {
	ERR_FAIL_COND_V_MSG(p_fit.coeffs.size() != (size_t)COEFFS, String(), "LTC polynomial: wrong number of coefficients.");
	std::ostringstream o;
	_append_header(o, "ltc_poly_coeffs_inc.glsl", p_fit, p_command, " * ");
	o << "\n#define LTC_POLY_DEGREE " << DEGREE << "\n";
	o << "#define LTC_POLY_TERMS " << TERMS << "\n";
	o << "#define LTC_POLY_PATCHES " << PATCHES << "\n";
	o << "// Seams and blend half widths: theta_v (radians) and perceptual roughness.\n";
	o << "#define LTC_POLY_SEAM_THETA " << _glsl_float(_seam_theta()) << "\n";
	o << "#define LTC_POLY_BLEND_THETA " << _glsl_float(_blend_theta()) << "\n";
	o << "#define LTC_POLY_SEAM_ROUGHNESS " << _glsl_float(SEAM_ROUGHNESS) << "\n";
	o << "#define LTC_POLY_BLEND_ROUGHNESS " << _glsl_float(BLEND_ROUGHNESS) << "\n";
	for (int p = 0; p < PATCHES; p++) {
		const Patch patch = get_patch(p);
		o << "\n// Patch " << p << ": theta_v " << (p / 2 ? "above" : "below") << " the seam, roughness " << (p % 2 ? "above" : "below")
		  << " the seam. r_t0 = (a, b, c, d),\n";
		o << "// r_t1 = (e, fn, fg, 0): Horner in s over Horner in t.\n";
		o << "void ltc_poly_patch_" << p << "(float p_x, float p_y, out vec4 r_t0, out vec4 r_t1) {\n";
		o << "\tfloat s = (p_x - " << _glsl_float(patch.x_center) << ") * " << _glsl_float(1.0 / patch.x_half) << ";\n";
		o << "\tfloat t = (p_y - " << _glsl_float(patch.y_center) << ") * " << _glsl_float(1.0 / patch.y_half) << ";\n";
		for (int half = 0; half < 2; half++) {
			const char *out = half == 0 ? "r_t0" : "r_t1";
			for (int i = DEGREE; i >= 0; i--) {
				// Q_i(t) as nested Horner text over vec4 constants of the four components of this half.
				String q;
				for (int j = DEGREE - i; j >= 0; j--) {
					String c = "vec4(";
					for (int m = 0; m < 4; m++) {
						const int k = half * 4 + m;
						c += k < COMPONENTS ? _glsl_float(p_fit.coeffs[((size_t)p * COMPONENTS + k) * TERMS + _row_start(i) + j]) : String("0.0");
						c += m < 3 ? ", " : ")";
					}
					q = j == DEGREE - i ? c : "(" + q + " * t + " + c + ")";
				}
				if (i == DEGREE) {
					o << "\t" << out << " = " << q << ";\n";
				} else {
					o << "\t" << out << " = " << out << " * s + " << q << ";\n";
				}
			}
		}
		o << "}\n";
	}
	return o.str();
}

bool LTCPolynomial::parse_inc(const String &p_text, std::vector<double> *r_coeffs, String *r_error) {
	ERR_FAIL_NULL_V(r_coeffs, false);
	ERR_FAIL_NULL_V(r_error, false);
	size_t at = p_text.find("LTC_POLY_COEFFS[");
	if (at == String::npos || (at = p_text.find('{', at)) == String::npos) {
		*r_error = "Array LTC_POLY_COEFFS not found.";
		return false;
	}
	at++;
	std::vector<double> values;
	const char *s = p_text.c_str();
	while (values.size() < (size_t)COEFFS) {
		while (s[at] == ' ' || s[at] == '\t' || s[at] == '\n' || s[at] == '\r' || s[at] == ',') {
			at++;
		}
		if (s[at] == '/' && s[at + 1] == '/') {
			while (s[at] != '\0' && s[at] != '\n') {
				at++;
			}
			continue;
		}
		char *end = nullptr;
		const double v = std::strtod(s + at, &end);
		if (end == s + at || !std::isfinite(v)) {
			*r_error = vformat("LTC_POLY_COEFFS: malformed or non-finite number %d (expected %d numbers).", (int)values.size(), COEFFS);
			return false;
		}
		values.push_back(v);
		at = end - s;
	}
	*r_coeffs = values;
	return true;
}

bool LTCPolynomial::save_text(const String &p_path, const String &p_text) {
	ERR_FAIL_COND_V_MSG(p_text.empty(), false, "Refusing to write an empty LTC polynomial file.");
	String error; // Atomic and checked through close (core/io/file_io.h): no partial table on failure.
	ERR_FAIL_COND_V_MSG(!file_write_atomic(p_path, p_text, &error), false, error);
	return true;
}
