/**************************************************************************/
/*  ltc_polynomial.cpp                                                    */
/**************************************************************************/
/* godot-area: least-squares polynomial fit of the LTC lookup table      */
/* (see ltc_polynomial.h).                                                */

#include "modules/ltc_fit/ltc_polynomial.h"

#include "core/error/error_macros.h"
#include "modules/ltc_fit/ltc_fitter.h"

#include "servers/rendering/renderer_rd/ltc_poly_data.inc"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

static_assert(sizeof(LTC_POLY_COEFFS) / sizeof(LTC_POLY_COEFFS[0]) == LTCPolynomial::COMPONENTS * LTCPolynomial::TERMS, "ltc_poly_data.inc has the wrong size.");

const char *LTCPolynomial::COMPONENT_NAMES[LTCPolynomial::COMPONENTS] = { "a", "b", "c", "d", "e", "fn", "fg" };
const char *LTCPolynomial::DEFAULT_INC_PATH = "servers/rendering/renderer_rd/ltc_poly_data.inc";
const char *LTCPolynomial::DEFAULT_GLSL_PATH = "shaders/ltc_poly_coeffs_inc.glsl";

void LTCPolynomial::monomials(double p_x, double p_y, double *r_terms) {
	int at = 0;
	double xi = 1.0;
	for (int i = 0; i <= DEGREE; i++) {
		double term = xi;
		for (int j = 0; j <= DEGREE - i; j++) {
			r_terms[at++] = term;
			term *= p_y;
		}
		xi *= p_x;
	}
}

double LTCPolynomial::evaluate(const double *p_coeffs, double p_x, double p_y) {
	double terms[TERMS];
	monomials(p_x, p_y, terms);
	double sum = 0.0;
	for (int k = 0; k < TERMS; k++) {
		sum += p_coeffs[k] * terms[k];
	}
	return sum;
}

float LTCPolynomial::evaluate_float(const float *p_coeffs, float p_x, float p_y) {
	int at = 0;
	float sum = 0.0f;
	float xi = 1.0f;
	for (int i = 0; i <= DEGREE; i++) {
		float inner = 0.0f;
		for (int j = DEGREE - i; j >= 0; j--) {
			inner = inner * p_y + p_coeffs[at + j];
		}
		at += DEGREE - i + 1;
		sum += xi * inner;
		xi *= p_x;
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
	ERR_FAIL_COND_V_MSG(p_size < 6, false, vformat("LTC polynomial fit: a %dx%d table has fewer cells per axis than the degree + 1.", p_size, p_size));
	const int rows = p_size * p_size;
	std::vector<double> design((size_t)rows * TERMS);
	for (int t = 0; t < p_size; t++) {
		const double y = get_y(LTCFitter::get_theta(p_size, t));
		for (int r = 0; r < p_size; r++) {
			const double x = get_x((double)r / (p_size - 1));
			monomials(x, y, &design[((size_t)t * p_size + r) * TERMS]);
		}
	}
	Fit fit;
	fit.coeffs.assign((size_t)COMPONENTS * TERMS, 0.0);
	for (int k = 0; k < COMPONENTS; k++) {
		std::vector<double> rhs(rows);
		for (int i = 0; i < rows; i++) {
			rhs[i] = p_table[(size_t)i * LTCFitter::FLOATS_PER_CELL + k];
		}
		std::vector<double> x;
		ERR_FAIL_COND_V_MSG(!solve_least_squares(design, rows, TERMS, rhs, x), false, vformat("LTC polynomial fit of component %s failed.", COMPONENT_NAMES[k]));
		for (int j = 0; j < TERMS; j++) {
			fit.coeffs[(size_t)k * TERMS + j] = x[j];
		}
	}
	Fit below_80;
	measure(p_table, p_size, fit.coeffs, below_80, 80.0 * LTCBRDF::BRDF_PI / 180.0);
	measure(p_table, p_size, fit.coeffs, fit);
	for (int k = 0; k < COMPONENTS; k++) {
		fit.rmse_80[k] = below_80.rmse[k];
	}
	r_fit = fit;
	return true;
}

void LTCPolynomial::measure(const float *p_table, int p_size, const std::vector<double> &p_coeffs, Fit &r_fit, double p_max_theta) {
	ERR_FAIL_NULL_MSG(p_table, "LTC polynomial: no table to measure against.");
	ERR_FAIL_COND_MSG(p_coeffs.size() != (size_t)COMPONENTS * TERMS, "LTC polynomial: wrong number of coefficients.");
	for (int k = 0; k < COMPONENTS; k++) {
		double sum2 = 0.0, max_err = 0.0;
		int max_r = 0, max_t = 0, cells = 0;
		for (int t = 0; t < p_size; t++) {
			const double theta = LTCFitter::get_theta(p_size, t);
			if (theta > p_max_theta) {
				continue;
			}
			const double y = get_y(theta);
			for (int r = 0; r < p_size; r++) {
				const double x = get_x((double)r / (p_size - 1));
				const double want = p_table[((size_t)t * p_size + r) * LTCFitter::FLOATS_PER_CELL + k];
				const double err = evaluate(&p_coeffs[(size_t)k * TERMS], x, y) - want;
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
	char line[80];
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
	r_out << p_comment_prefix << "P_k(x, y) = sum over i + j <= " << LTCPolynomial::DEGREE << " of c_k,ij x^i y^j, x = 1 + r (r = perceptual\n";
	r_out << p_comment_prefix << "roughness, the LUT's axis; GGX alpha = r^2), y = 1 + theta_v (radians). " << LTCPolynomial::TERMS << " coefficients\n";
	r_out << p_comment_prefix << "per component k in (a, b, c, d, e, fn, fg), ordered by i (power of x), then j.\n";
	r_out << p_comment_prefix << "Fitted over the 64 x 64 table cells (Householder QR in double).\n";
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
	r_out << p_comment_prefix << "Compared with the thesis' appendix C (fitted to Heitz et al.'s GGX table, not ours): a, c, e,\n";
	r_out << p_comment_prefix << "fn, fg have the same shape and similar coefficients (a: 35.43 - 18.86 y ... here, 40.02\n";
	r_out << p_comment_prefix << "- 21.79 y ... there); b and d look swapped (the thesis' b resembles our d and vice versa).\n";
	r_out << " */\n";
}

String LTCPolynomial::format_inc(const Fit &p_fit, const String &p_command) {
	ERR_FAIL_COND_V_MSG(p_fit.coeffs.size() != (size_t)COMPONENTS * TERMS, String(), "LTC polynomial: wrong number of coefficients.");
	std::ostringstream o;
	_append_header(o, "ltc_poly_data.inc", p_fit, p_command, " * ");
	o << "\n#pragma once\n\n";
	o << "static const double LTC_POLY_COEFFS[" << COMPONENTS << " * " << TERMS << "] = {\n";
	char buf[64];
	for (int k = 0; k < COMPONENTS; k++) {
		o << "\t";
		for (int j = 0; j < TERMS; j++) {
			snprintf(buf, sizeof(buf), "%.17g", p_fit.coeffs[(size_t)k * TERMS + j]);
			o << buf << (j + 1 < TERMS ? ", " : ",");
		}
		o << " // " << COMPONENT_NAMES[k] << "\n";
	}
	o << "};\n";
	return o.str();
}

String LTCPolynomial::format_glsl(const Fit &p_fit, const String &p_command) {
	ERR_FAIL_COND_V_MSG(p_fit.coeffs.size() != (size_t)COMPONENTS * TERMS, String(), "LTC polynomial: wrong number of coefficients.");
	std::ostringstream o;
	_append_header(o, "ltc_poly_coeffs_inc.glsl", p_fit, p_command, " * ");
	o << "\n#define LTC_POLY_DEGREE " << DEGREE << "\n";
	o << "#define LTC_POLY_TERMS " << TERMS << "\n\n";
	o << "// Components a, b, c, d, e, fn, fg; each ordered by the power of x, then of y.\n";
	o << "const float LTC_POLY_COEFFS[" << COMPONENTS << " * LTC_POLY_TERMS] = float[](\n";
	char buf[64];
	for (int k = 0; k < COMPONENTS; k++) {
		o << "\t\t";
		for (int j = 0; j < TERMS; j++) {
			snprintf(buf, sizeof(buf), "%.9g", (double)(float)p_fit.coeffs[(size_t)k * TERMS + j]);
			String s = buf;
			if (s.find_first_of(".e") == String::npos) {
				s += ".0";
			}
			const bool last = k + 1 == COMPONENTS && j + 1 == TERMS;
			o << s << (last ? "" : (j + 1 < TERMS ? ", " : ","));
		}
		o << (k + 1 == COMPONENTS ? ");" : "") << " // " << COMPONENT_NAMES[k] << "\n";
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
	while (values.size() < (size_t)COMPONENTS * TERMS) {
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
			*r_error = vformat("LTC_POLY_COEFFS: malformed or non-finite number %d.", (int)values.size());
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
	std::ofstream f(p_path, std::ios::binary);
	ERR_FAIL_COND_V_MSG(!f, false, vformat("Cannot open '%s' for writing.", p_path.c_str()));
	f << p_text;
	f.close();
	ERR_FAIL_COND_V_MSG(!f, false, vformat("Writing '%s' failed.", p_path.c_str()));
	return true;
}
