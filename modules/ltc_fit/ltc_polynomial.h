/**************************************************************************/
/*  ltc_polynomial.h                                                      */
/**************************************************************************/
/* godot-area: degree-5 bivariate polynomials fitted by least squares to  */
/* the components k in {a, b, c, d, e, fn, fg} of the LTC lookup table   */
/* LTC_LUT_ENGINE_GGX (thesis section 5.4.3, appendix C):                 */
/*   P_k(x, y) = sum over i + j <= 5 of c_k,ij x^i y^j,                   */
/*   x = 1 + r  (r = PERCEPTUAL roughness in [0, 1], the LUT's column     */
/*               axis, GGX alpha = r^2; as the material's roughness),     */
/*   y = 1 + theta_v (view angle in radians, [0, pi / 2]).                */
/* 21 monomials per component, ordered by i (power of x), then j.         */
/* The samples are the 64 x 64 table cells at their exact (r, theta_v);   */
/* the solver is Householder QR in double on the column-scaled design    */
/* matrix (no normal equations: their condition number is squared).     */
/* `godot-area ltc-fit --polynomial` writes the coefficients to           */
/* servers/rendering/renderer_rd/ltc_poly_data.inc (C++, double) and      */
/* shaders/ltc_poly_coeffs_inc.glsl (compiled into the shader version    */
/* AREA_METHOD_LTC_POLYNOMIAL as constants, no binding).                  */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class LTCPolynomial {
public:
	static constexpr int DEGREE = 5;
	static constexpr int TERMS = (DEGREE + 1) * (DEGREE + 2) / 2; // 21
	static constexpr int COMPONENTS = 7; // a, b, c, d, e, fn, fg (the first 7 floats of a LUT cell).
	static const char *COMPONENT_NAMES[COMPONENTS];
	static const char *DEFAULT_INC_PATH; // Relative to the repository root.
	static const char *DEFAULT_GLSL_PATH;

	struct Fit {
		std::vector<double> coeffs; // COMPONENTS * TERMS.
		double rmse[COMPONENTS] = {}; // sqrt(sum (P_k - k)^2 / N) over the N measured cells (all: size^2).
		double rmse_80[COMPONENTS] = {}; // The same over the rows with theta_v <= 80 degrees (fit_table only).
		double max_error[COMPONENTS] = {}; // max |P_k - k|.
		int max_error_r[COMPONENTS] = {};
		int max_error_t[COMPONENTS] = {};
	};

	// The polynomial's arguments for a LUT cell / a shading input.
	static double get_x(double p_roughness) { return 1.0 + p_roughness; }
	static double get_y(double p_theta) { return 1.0 + p_theta; }

	// Fills the TERMS monomials x^i y^j (i outer, j inner).
	static void monomials(double p_x, double p_y, double *r_terms);
	// P(x, y) for one component's TERMS coefficients, in double and in float (the shader's arithmetic:
	// float coefficients, Horner in y per power of x, as ltc_poly_eval in area_light_ltc_inc.glsl).
	static double evaluate(const double *p_coeffs, double p_x, double p_y);
	static float evaluate_float(const float *p_coeffs, float p_x, float p_y);

	// Least squares min |A x - b| for a row-major p_rows x p_cols matrix (p_rows >= p_cols), Householder QR
	// with column scaling. Returns false (r_x untouched) for bad sizes or a rank-deficient A.
	static bool solve_least_squares(const std::vector<double> &p_a, int p_rows, int p_cols, const std::vector<double> &p_b, std::vector<double> &r_x);

	// Fits every component of a p_size x p_size table in the ltc_lut_data.inc layout (8 floats per cell).
	static bool fit_table(const float *p_table, int p_size, Fit &r_fit);
	// RMSE / max error of given coefficients against a table (fills everything in r_fit but coeffs), over
	// the rows with theta_v <= p_max_theta (radians; the default takes every row).
	static void measure(const float *p_table, int p_size, const std::vector<double> &p_coeffs, Fit &r_fit, double p_max_theta = 10.0);

	// The committed coefficients (ltc_poly_data.inc), COMPONENTS * TERMS doubles.
	static const double *get_builtin_coeffs();

	// File texts with p_command and the per-component errors in their headers.
	static String format_inc(const Fit &p_fit, const String &p_command);
	static String format_glsl(const Fit &p_fit, const String &p_command);
	// Reads the coefficients back from format_inc text.
	static bool parse_inc(const String &p_text, std::vector<double> *r_coeffs, String *r_error);
	static bool save_text(const String &p_path, const String &p_text);
};
