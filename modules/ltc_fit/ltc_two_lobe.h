/**************************************************************************/
/*  ltc_two_lobe.h                                                        */
/**************************************************************************/
/* godot-area: the two-lobe LTC (issue #18, item 3). One LTC (Heitz,      */
/* Dupuy, Hill and Neubelt 2016, eq. 1) cannot follow the GGX lobe at     */
/* grazing views: it is too dark near the light's foot and too wide      */
/* laterally (doc/accuracy.md section 5). The lobe is approximated by a   */
/* weighted sum of two LTCs instead,                                      */
/*   rho(l) ~ w1 D_M1(l) + w2 D_M2(l),   w1, w2 >= 0,                     */
/* so the shader integrates two polygons (M1^-1 P and M2^-1 P) and adds   */
/* them with the weights. Each lobe is a free-axis LTC (ltc_fitter.h:     */
/* M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], Z = (sin phi, 0,  */
/* cos phi)); the weights are free (their sum is not tied to 1: the       */
/* surface-horizon clip removes lobe mass at grazing views).              */
/* Objective: the polygon-integral error of ltc_polygon_objective.h with  */
/* I_D = w1 I_D1 + w2 I_D2, scored on the float values the table stores.  */
/* Per cell Nelder-Mead over x = (ln m11, ln m22, m13 / m11, phi, w) per  */
/* lobe (ti = 0: isotropic, (ln m11, w) per lobe), from                   */
/*   - the chain's rougher neighbour (warm start, as the 1-lobe fit),     */
/*   - the cell's 1-lobe fit split into a core (M scaled by 1/2, w 0.3)   */
/*     and the rest (w 0.7),                                              */
/* keeping the lower objective, restarted while it improves; the 1-lobe   */
/* cell itself (w1 = 1, w2 = 0) is the floor, so no cell is worse than    */
/* the 1-lobe table. Continuity: the objective is multiplied by           */
/* 1 + smoothness * sum (entry - neighbour's entry)^2 over the 12 stored  */
/* values of both lobes. Lobe order: the mixture does not change when the */
/* lobes swap, but linear filtering between cells does, so after the fit */
/* each cell, in order of rows ti = 0.. and roughness from 1 down, takes  */
/* the order closer to its already ordered neighbours (ti - 1 and ri + 1).*/
/*                                                                        */
/* Table (LTC_LUT_ENGINE_GGX_2LOBE, ltc_lut_2lobe_data.inc), 16 floats a  */
/* cell, (ti * N + ri) * 16, as four RGBA texels:                         */
/*   (a1, b1, c1, d1), (e1, fn, fg, w1), (a2, b2, c2, d2), (e2, w2, 0, 0) */
/* with fn, fg those of the 1-lobe table (the lobe's albedo integrals).   */
/* Cells outside the fitted block hold the 1-lobe cell (w1 = 1, w2 = 0).  */

#pragma once

#include "modules/ltc_fit/ltc_brdf.h"

#include "core/string/ustring.h"

#include <atomic>
#include <vector>

struct LTCTwoLobeCell {
	float lobes[2][5] = { { 1.0f, 0.0f, 1.0f, 0.0f, 1.0f }, { 1.0f, 0.0f, 1.0f, 0.0f, 1.0f } }; // a, b, c, d, e each.
	float weights[2] = { 1.0f, 0.0f };
	float fn = 0.0f;
	float fg = 0.0f;
	double error = 0.0; // Polygon objective of the stored two-lobe cell.
	double error_one_lobe = 0.0; // The same for the 1-lobe cell it started from.
	int iterations = 0;

	void write(float *r_out) const; // 16 floats, the layout above.
	void read(const float *p_in);
	void swap_lobes();
};

class LTCTwoLobe {
public:
	static constexpr int FLOATS_PER_CELL = 16;
	static constexpr double DEFAULT_SMOOTHNESS = 1.0;
	static const char *DEFAULT_INC_PATH;

	// Fits cell (p_roughness_index, p_angle_index) of the engine GGX table of size p_size. p_one_lobe: the
	// cell's 8 floats in the 1-lobe table (start and floor); p_init_or_null: the chain's rougher
	// neighbour (16 floats) or nullptr.
	static LTCTwoLobeCell fit_cell(int p_size, int p_roughness_index, int p_angle_index, const float *p_one_lobe, const float *p_init_or_null, double p_smoothness);

	// Fills r_table (p_size^2 * 16 floats) from the 1-lobe table p_one_lobe (p_size^2 * 8 floats): the
	// cells roughness [p_r0, p_r1] x angle [p_t0, p_t1] fitted (one chain per view angle, from p_r1 down,
	// on p_threads threads, 0 = hardware concurrency), the others copied as one lobe; then orders the
	// lobes (order_lobes). r_cells (p_size^2, same indexing) receives the fitted cells when not null.
	static bool fit_table(int p_size, int p_r0, int p_r1, int p_t0, int p_t1, int p_threads, double p_smoothness, const std::vector<float> &p_one_lobe, std::vector<float> &r_table,
			std::vector<LTCTwoLobeCell> *r_cells, std::atomic<int> *r_done);

	// The lobe-order pass of the banner over the whole table; returns the number of cells swapped.
	static int order_lobes(int p_size, std::vector<float> &r_table);

	// The committed table (ltc_lut_2lobe_data.inc).
	static const float *get_builtin_table();
	static String format_inc(int p_size, const std::vector<float> &p_table, const String &p_command, const String &p_stats);
};
