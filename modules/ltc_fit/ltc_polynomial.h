/**************************************************************************/
/*  ltc_polynomial.h                                                      */
/**************************************************************************/
/* godot-area: degree-5 least-squares polynomials for the components      */
/* k in {a, b, c, d, e, fn, fg} of the LTC lookup table LTC_LUT_ENGINE_GGX */
/* (thesis section 5.4.3, appendix C), in                                 */
/*   x = 1 + r  (r = PERCEPTUAL roughness in [0, 1], the LUT's column     */
/*               axis, GGX alpha = r^2; as the material's roughness),     */
/*   y = 1 + theta_v (view angle in radians, [0, pi / 2]).                */
/* One polynomial per component over the whole table misses fn by far    */
/* (RMSE 0.022: fn falls steeply at grazing angles on glossy surfaces),   */
/* so the domain is split into 2 x 2 PATCHES at theta_v = 80 deg and      */
/* r = 0.2, and per component                                             */
/*   P_k(r, theta) = sum over patches p of w_p(r, theta) P_k,p(x, y),     */
/* w_p = products of smoothsteps across the seams (+-5 deg, +-0.05; a     */
/* partition of unity, so P_k is smooth: no visible seam). Each P_k,p is  */
/* a degree-5 polynomial in (x, y), stored in the centred and scaled      */
/* variables s = (x - x_p) / hx_p, t = (y - y_p) / hy_p of its patch      */
/* (the same polynomial space; the raw monomials x^i y^j over a narrow    */
/* patch have coefficients ~1e5 and lose everything in float):            */
/*   P_k,p = sum over i + j <= 5 of c_p,k,ij s^i t^j,                     */
/* 21 coefficients ordered by i (power of s), then j. The four patches'   */
/* coefficients of a component are ONE least-squares fit of the blended   */
/* P_k to the 64 x 64 table cells (84 unknowns; Householder QR in double  */
/* on the column-scaled design matrix, no normal equations).              */
/* `godot-area ltc-fit --polynomial` writes the coefficients to           */
/* servers/rendering/renderer_rd/ltc_poly_data.inc (C++, double) and      */
/* servers/rendering/renderer_rd/shaders/ltc_poly_coeffs_inc.glsl (one function per patch with the      */
/* coefficients as literal vec4 constants, blended by                     */
/* ltc_fetch_polynomial in area_light_ltc_inc.glsl; no binding).          */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class LTCPolynomial {
public:
	static constexpr int DEGREE = 5;
	static constexpr int TERMS = (DEGREE + 1) * (DEGREE + 2) / 2; // 21
	static constexpr int COMPONENTS = 7; // a, b, c, d, e, fn, fg (the first 7 floats of a LUT cell).
	static constexpr int PATCHES = 4; // 2 (theta_v) x 2 (roughness); patch p = theta_half * 2 + roughness_half.
	static constexpr int COEFFS = PATCHES * COMPONENTS * TERMS; // Layout [patch][component][term].
	static constexpr double SEAM_THETA_DEGREES = 80.0;
	static constexpr double BLEND_THETA_DEGREES = 5.0; // Half width of the blend across the seam.
	static constexpr double SEAM_ROUGHNESS = 0.2;
	static constexpr double BLEND_ROUGHNESS = 0.05;
	static const char *COMPONENT_NAMES[COMPONENTS];
	static const char *DEFAULT_INC_PATH; // Relative to the repository root.
	static const char *DEFAULT_GLSL_PATH;

	struct Fit {
		std::vector<double> coeffs; // COEFFS.
		double rmse[COMPONENTS] = {}; // sqrt(sum (P_k - k)^2 / N) over the N measured cells (all: size^2).
		double rmse_80[COMPONENTS] = {}; // The same over the rows with theta_v <= 80 degrees (fit_table only).
		double max_error[COMPONENTS] = {}; // max |P_k - k|.
		int max_error_r[COMPONENTS] = {};
		int max_error_t[COMPONENTS] = {};
	};

	// A patch's centre and half extent in x = 1 + r and y = 1 + theta_v (its extent includes the blend
	// zones): s = (x - x_center) / x_half, t = (y - y_center) / y_half lie in [-1, 1] on the patch.
	struct Patch {
		double x_center = 0.0;
		double x_half = 1.0;
		double y_center = 0.0;
		double y_half = 1.0;
	};
	static Patch get_patch(int p_patch);
	// The blend weights w_p(r, theta) (sum 1, each in [0, 1]), r perceptual roughness, theta radians.
	static void get_weights(double p_roughness, double p_theta, double *r_weights);

	// The polynomial's arguments for a LUT cell / a shading input.
	static double get_x(double p_roughness) { return 1.0 + p_roughness; }
	static double get_y(double p_theta) { return 1.0 + p_theta; }

	// Fills the TERMS monomials s^i t^j (i outer, j inner).
	static void monomials(double p_s, double p_t, double *r_terms);
	// One polynomial (TERMS coefficients) at (s, t), in double and in float (the shader's arithmetic:
	// float coefficients, Horner in s over Horner in t, as the generated ltc_poly_patch_N functions).
	static double evaluate(const double *p_coeffs, double p_s, double p_t);
	static float evaluate_float(const float *p_coeffs, float p_s, float p_t);
	// The blended P_k(r, theta) for all COEFFS coefficients p_coeffs; the float version mirrors
	// ltc_fetch_polynomial (before its guards), float constants included.
	static double evaluate_component(const double *p_coeffs, int p_component, double p_roughness, double p_theta);
	static float evaluate_component_float(const float *p_coeffs, int p_component, float p_roughness, float p_theta);

	// Least squares min |A x - b| for a row-major p_rows x p_cols matrix (p_rows >= p_cols), Householder QR
	// with column scaling. Returns false (r_x untouched) for bad sizes or a rank-deficient A.
	static bool solve_least_squares(const std::vector<double> &p_a, int p_rows, int p_cols, const std::vector<double> &p_b, std::vector<double> &r_x);

	// Fits every component of a p_size x p_size table in the ltc_lut_data.inc layout (8 floats per cell).
	static bool fit_table(const float *p_table, int p_size, Fit &r_fit);
	// RMSE / max error of given coefficients against a table (fills everything in r_fit but coeffs), over
	// the rows with theta_v <= p_max_theta (radians; the default takes every row).
	static void measure(const float *p_table, int p_size, const std::vector<double> &p_coeffs, Fit &r_fit, double p_max_theta = 10.0);

	// The committed coefficients (ltc_poly_data.inc), COEFFS doubles.
	static const double *get_builtin_coeffs();

	// File texts with p_command and the per-component errors in their headers.
	static String format_inc(const Fit &p_fit, const String &p_command);
	static String format_glsl(const Fit &p_fit, const String &p_command);
	// Reads the COEFFS coefficients back from format_inc text.
	static bool parse_inc(const String &p_text, std::vector<double> *r_coeffs, String *r_error);
	static bool save_text(const String &p_path, const String &p_text);
};
