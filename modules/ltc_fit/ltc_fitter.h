/**************************************************************************/
/*  ltc_fitter.h                                                          */
/**************************************************************************/
/* godot-area: fits linearly transformed cosines (Heitz, Dupuy, Hill and  */
/* Neubelt 2016) to the GGX specular lobe, thesis section 5.4.1.          */
/*                                                                        */
/* Per cell (roughness index ri, view-angle index ti of an N x N table):  */
/*   perceptual roughness r = ri / (N - 1), alpha = max(r^2, MIN_ALPHA);  */
/*   u = ti / (N - 1), cos(theta_v) = 1 - u^2, theta_v clamped to         */
/*   MAX_THETA; v = (sin theta_v, 0, cos theta_v), normal = +z.           */
/* The fitted distribution is D(l) = D_o(M^-1 l / |M^-1 l|) |M^-1| /      */
/* |M^-1 l|^3 with D_o the clamped cosine max(0, z) / pi and              */
/*   M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]],                 */
/* where Z is the BRDF's dominant (average, cosine-weighted) direction    */
/* projected to the xz-plane, Y = +y, X = Y x Z. Written out this is      */
/* eq. 5.6, M = [[a, 0, b], [0, c, 0], [d, 0, e]], det M = m11 m22 > 0.   */
/* Nelder-Mead minimises the L3 error                                     */
/*   E3 = integral over the sphere of |rho(l) - D(l)|^3,                  */
/*   rho(l) = f(v, l) cos(theta_l) / fn,                                  */
/* estimated with a FIXED stratified sample set drawn from both the GGX   */
/* visible-normal distribution and the current LTC, combined with the     */
/* balance heuristic, so every result is deterministic.                   */
/* Search space: x = (ln m11, ln m22, m13 / m11); at theta_v = 0 the fit  */
/* is isotropic, x = (ln m11) with m22 = m11, m13 = 0. Nelder-Mead is     */
/* restarted from its result while that improves; a cell whose fit does   */
/* not overlap the lobe (L1 > FALLBACK_L1) also tries m11 = m22 = alpha.  */
/* Free axis (FitOptions::free_axis, issue #18): Z is not fixed at the    */
/* average direction but a 4th parameter, Z = (sin phi, 0, cos phi),      */
/* x = (ln m11, ln m22, m13 / m11, phi); M keeps the same 5 entries, so   */
/* the shader and the table layout do not change. phi starts from the     */
/* stored matrix (X = M's first column / m11), and a refit also starts   */
/* from the cell's own current value and keeps the better of the two.    */
/* FitOptions::norm picks the objective E_p = integral |rho - D|^p, p in  */
/* {1, 2, 3} (Heitz et al. use 3); the engine table's choice is made by   */
/* the scene error of the accuracy suite (doc/methods.md).                */
/* FitOptions::polygons minimises instead the error of the lobe's         */
/* integrals over a set of test lights (ltc_polygon_objective.h): what    */
/* the shader evaluates and a scene measures. With it, a refit starts    */
/* only from the chain (no second start from the cell itself) and         */
/* FitOptions::smoothness keeps each row on one branch of minima.         */
/* Initialisation (Heitz et al.): every view-angle row is a chain walking */
/* from the roughest cell down, each cell starting from the stored floats */
/* of its rougher neighbour, so a re-fit of one cell from the committed   */
/* table reproduces it exactly.                                           */

#pragma once

#include "modules/ltc_fit/ltc_brdf.h"
#include "modules/ltc_fit/nelder_mead.h"

#include <atomic>
#include <functional>
#include <vector>

class LTCPolygonObjective;

// One fitted table cell. write() gives the 8 floats of the .inc layout: a, b, c, d, e, fn, fg, 0.
struct LTCCell {
	float a = 1.0f;
	float b = 0.0f;
	float c = 1.0f;
	float d = 0.0f;
	float e = 1.0f;
	float fn = 0.0f; // Directional albedo integral f cos dl (F = 1).
	float fg = 0.0f; // Integral f cos (1 - v.h)^5 dl: F = f0 fn + (f90 - f0) fg (thesis eq. 5.10).
	double error_l3 = 0.0; // Minimised objective E_p (E3 unless FitOptions::norm says otherwise).
	double error_l1 = 0.0; // Integral |rho - D| over the sphere, 0 (perfect) to 2 (disjoint).
	int iterations = 0; // Nelder-Mead iterations.

	void write(float *r_out) const;
};

// How a cell is fitted (the defaults are the 3-parameter L3 fit of Heitz et al. 2016).
struct LTCFitOptions {
	bool free_axis = false; // Fit the lobe axis too (4 parameters).
	int norm = 3; // Objective integral |rho - D|^norm, norm in {1, 2, 3}.
	bool polygons = false; // Objective: the polygon-integral error of ltc_polygon_objective.h (norm unused).
	// Continuity: the objective is multiplied by 1 + smoothness * sum_j (m_j - m_j,prev)^2 over the five
	// matrix entries of the chain's previous (rougher) cell, so a row does not jump between two nearly
	// equal minima (linear filtering between cells of different minima gives neither lobe).
	double smoothness = 0.0;
};

class LTCFitter {
public:
	static constexpr double MIN_ALPHA = 1e-4; // GGX alpha floor (roughness index 0 is a mirror otherwise).
	static constexpr double MAX_THETA = 1.57; // View angle ceiling in radians (the last row would be grazing).
	static constexpr int FIT_SAMPLES = 32; // Per axis: 32 x 32 BRDF samples + 32 x 32 LTC samples per evaluation.
	static constexpr int ALBEDO_SAMPLES = 128; // Per axis, for fn, fg and the dominant direction.
	static constexpr int MAX_ITERATIONS = 250; // Nelder-Mead iteration cap per cell.
	static constexpr int MAX_RESTARTS = 6; // Nelder-Mead restarts from the best point while it improves.
	static constexpr double FALLBACK_L1 = 1.0; // Above this L1 distance a second start (m11 = m22 = alpha) is tried.
	static constexpr int FLOATS_PER_CELL = 8;

	// The committed engine table (ltc_lut_data.inc, issue #18): the cells roughness index
	// ENGINE_REFIT_R0..R1 x view-angle index ENGINE_REFIT_T0..T1 (roughness >= 0.19, every view angle)
	// were refitted with engine_refit_options(), each row's chain starting from the default at roughness
	// 1; the glossier cells (near-mirror lobes smaller than the objective's 3-degree test lights: their
	// refit diverged) and the whole Smith table keep the 3-parameter L3 fit:
	//   godot-area ltc-fit --brdf engine --cells 12:63,0:63 --free-axis --polygons --smoothness 1
	static constexpr int ENGINE_REFIT_R0 = 12;
	static constexpr int ENGINE_REFIT_R1 = 63;
	static constexpr int ENGINE_REFIT_T0 = 0;
	static constexpr int ENGINE_REFIT_T1 = 63;
	static LTCFitOptions engine_refit_options();
	// The committed engine table with the refit block fitted again as the 3-parameter L3 fit (each row's
	// chain starts from the default at roughness 1, as the full fit did, so this reproduces the table the
	// block replaced, bit for bit in the same build). The LUT-free polynomials (LTC_POLYNOMIAL) are fitted
	// to it: degree-5 patches cannot follow the refit table (fitted to the grazing block alone,
	// LTC_POLYNOMIAL regressed: plane_r0.1_m1_2x0.5_far relRMSE 0.027 -> 0.62; to the full refit, a and b
	// keep RMSE 0.021 and 0.040 against 0.004 and 0.002 here).
	static bool get_three_parameter_engine_table(std::vector<float> &r_table, int p_threads = 0);
	static bool is_engine_refit_cell(int p_roughness_index, int p_angle_index) {
		return p_roughness_index >= ENGINE_REFIT_R0 && p_roughness_index <= ENGINE_REFIT_R1 && p_angle_index >= ENGINE_REFIT_T0 && p_angle_index <= ENGINE_REFIT_T1;
	}

	// Table coordinates of a cell (see the banner).
	static double get_roughness(int p_size, int p_roughness_index);
	static double get_alpha(int p_size, int p_roughness_index);
	static double get_theta(int p_size, int p_angle_index);

	// Fits one cell. p_init_or_null: the 8 stored floats of the cell the full fit starts from (the next
	// rougher cell at the same view angle, roughness_index + 1), or nullptr for the default start
	// m11 = m22 = 1, m13 = 0 (used for the roughest column).
	// p_self_or_null: the cell's own current 8 floats, a second start (kept if better) for refits.
	static LTCCell fit_cell(LTCBRDFVariant p_variant, int p_size, int p_roughness_index, int p_angle_index, const float *p_init_or_null, const LTCFitOptions &p_options = LTCFitOptions(),
			const float *p_self_or_null = nullptr);

	// Fits cells roughness [p_r0, p_r1] x angle [p_t0, p_t1] (inclusive) into r_table (p_size^2 * 8 floats,
	// index (angle * p_size + roughness) * 8; it must hold the seed values of the other cells). Each view
	// angle is one chain walking from p_r1 down to p_r0, started from cell p_r1 + 1 of r_table when
	// p_r1 < p_size - 1, from the default otherwise. Chains run on p_threads std::threads (0 = hardware
	// concurrency); the result does not depend on the thread count. r_cells receives the LTCCell of every
	// fitted cell (same indexing, others untouched) when not null; r_done counts finished cells.
	// With p_options.free_axis each cell also starts from its own value in r_table (see fit_cell).
	static bool fit_table(LTCBRDFVariant p_variant, int p_size, int p_r0, int p_r1, int p_t0, int p_t1, int p_threads, std::vector<float> &r_table, std::vector<LTCCell> *r_cells, std::atomic<int> *r_done,
			const LTCFitOptions &p_options = LTCFitOptions());

	// Nelder-Mead restarted from r_result (fresh simplex, step 0.05) while that improves it by more than
	// 1e-4 relative, at most MAX_RESTARTS times: a collapsed simplex is how the method stalls on the
	// elongated valleys of grazing, glossy cells. Returns the iterations spent.
	static int restart_while_improving(const NelderMead::Function &p_function, NelderMead::Result &r_result);
	// Runs p_chain(t) for every view-angle row t in [p_t0, p_t1] on min(p_threads (0 = hardware
	// concurrency), rows) threads, this one included, each taking the next row from a shared counter,
	// and waits for all.
	static void run_chains(int p_threads, int p_t0, int p_t1, const std::function<void(int)> &p_chain);

	// The LTC density D(l) of the stored matrix p_m = (a, b, c, d, e) at unit direction p_l (1/sr).
	static double ltc_evaluate(const double *p_m, const double *p_l);
	// Maps (p_u1, p_u2) in [0, 1)^2 to a unit direction distributed as D (cosine sample, then M, normalised).
	static void ltc_sample(const double *p_m, double p_u1, double p_u2, double *r_l);

	// Builds the polygon-integral objective (ltc_polygon_objective.h) of the lobe rho = f cos * p_inv_fn
	// at (p_alpha, p_theta), from LTCPolygonObjective::SAMPLES^2 visible-normal samples.
	static void build_polygon_objective(LTCBRDFVariant p_variant, double p_alpha, double p_theta, double p_inv_fn, LTCPolygonObjective *r_objective);
	// The stored matrix (a, b, c, d, e) of M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]] with the
	// axis Z = (sin phi, 0, cos phi), and back (m11, m22 = column lengths, m13 the skew, phi the axis).
	static void build_free_axis_matrix(double p_phi, double p_m11, double p_m22, double p_m13, double *r_m);
	static void get_free_axis_parameters(const float *p_cell, double *r_phi, double *r_m11, double *r_m22, double *r_m13);

	// Integrates fn, fg and the dominant direction of f cos at (alpha, theta_v) with
	// p_samples^2 stratified visible-normal samples.
	static void integrate_albedo(LTCBRDFVariant p_variant, double p_alpha, double p_theta, int p_samples, double *r_fn, double *r_fg, double *r_dominant);
};
