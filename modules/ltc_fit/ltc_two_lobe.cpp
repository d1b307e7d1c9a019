/**************************************************************************/
/*  ltc_two_lobe.cpp                                                      */
/**************************************************************************/
/* godot-area: the two-lobe LTC fit (see ltc_two_lobe.h; issue #18).      */

#include "modules/ltc_fit/ltc_two_lobe.h"

#include "core/error/error_macros.h"
#include "modules/ltc_fit/ltc_fitter.h"
#include "modules/ltc_fit/ltc_polygon_objective.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/ltc_fit/nelder_mead.h"
#include "servers/rendering/renderer_rd/ltc_lut_2lobe_data.inc"

#include <algorithm>
#include <cmath>

const char *LTCTwoLobe::DEFAULT_INC_PATH = "servers/rendering/renderer_rd/ltc_lut_2lobe_data.inc";

namespace {

const double CORE_SCALE = 0.5; // The fresh start's second lobe: the 1-lobe M scaled by this (a narrower core),
const double CORE_WEIGHT = 0.3; // with this weight (the first keeps 1 - CORE_WEIGHT).

// The per-lobe parameters x of a stored lobe (see the header); isotropic: (ln m11, w).
void lobe_parameters(const float *p_m, double p_weight, double p_scale, bool p_isotropic, std::vector<double> &r_x) {
	double phi = 0.0, m11 = 1.0, m22 = 1.0, m13 = 0.0;
	LTCFitter::get_free_axis_parameters(p_m, &phi, &m11, &m22, &m13);
	if (!(m11 > 0.0) || !(m22 > 0.0) || !std::isfinite(m13) || !std::isfinite(phi)) {
		m11 = m22 = 1.0;
		m13 = 0.0;
		phi = 0.0;
	}
	if (p_isotropic) {
		r_x.insert(r_x.end(), { std::log(std::sqrt(m11 * m22) * p_scale), p_weight });
	} else {
		r_x.insert(r_x.end(), { std::log(m11 * p_scale), std::log(m22 * p_scale), m13 / m11, phi, p_weight });
	}
}

// x -> the two lobes' stored matrices (float values, as the shader reads them) and weights.
void lobes_from(const std::vector<double> &p_x, bool p_isotropic, double *r_m, double *r_w) {
	const int per_lobe = p_isotropic ? 2 : 5;
	for (int j = 0; j < 2; j++) {
		const double *x = p_x.data() + per_lobe * j;
		if (p_isotropic) {
			const double m = std::exp(x[0]);
			LTCFitter::build_free_axis_matrix(0.0, m, m, 0.0, r_m + 5 * j);
		} else {
			const double m11 = std::exp(x[0]);
			LTCFitter::build_free_axis_matrix(x[3], m11, std::exp(x[1]), x[2] * m11, r_m + 5 * j);
		}
		r_w[j] = double(float(x[per_lobe - 1]));
		for (int k = 0; k < 5; k++) {
			r_m[5 * j + k] = double(float(r_m[5 * j + k]));
		}
	}
}

// The 12 stored values of a 16-float cell that the continuity term compares.
void stored_values(const float *p_cell, double *r_v) {
	const int at[12] = { 0, 1, 2, 3, 4, 7, 8, 9, 10, 11, 12, 13 };
	for (int k = 0; k < 12; k++) {
		r_v[k] = p_cell[at[k]];
	}
}

double cell_distance(const float *p_a, const float *p_b) {
	double va[12], vb[12];
	stored_values(p_a, va);
	stored_values(p_b, vb);
	double d = 0.0;
	for (int k = 0; k < 12; k++) {
		d += (va[k] - vb[k]) * (va[k] - vb[k]);
	}
	return d;
}

} // namespace

void LTCTwoLobeCell::write(float *r_out) const {
	for (int j = 0; j < 2; j++) {
		for (int k = 0; k < 4; k++) {
			r_out[8 * j + k] = lobes[j][k];
		}
		r_out[8 * j + 4] = lobes[j][4];
	}
	r_out[5] = fn;
	r_out[6] = fg;
	r_out[7] = weights[0];
	r_out[13] = weights[1];
	r_out[14] = 0.0f;
	r_out[15] = 0.0f;
}

void LTCTwoLobeCell::read(const float *p_in) {
	for (int j = 0; j < 2; j++) {
		for (int k = 0; k < 5; k++) {
			lobes[j][k] = p_in[8 * j + k];
		}
	}
	fn = p_in[5];
	fg = p_in[6];
	weights[0] = p_in[7];
	weights[1] = p_in[13];
}

void LTCTwoLobeCell::swap_lobes() {
	for (int k = 0; k < 5; k++) {
		std::swap(lobes[0][k], lobes[1][k]);
	}
	std::swap(weights[0], weights[1]);
}

LTCTwoLobeCell LTCTwoLobe::fit_cell(int p_size, int p_roughness_index, int p_angle_index, const float *p_one_lobe, const float *p_init_or_null, double p_smoothness) {
	LTCTwoLobeCell cell;
	ERR_FAIL_COND_V_MSG(p_size < 2, cell, "The LTC table needs at least 2 x 2 cells.");
	ERR_FAIL_INDEX_V_MSG(p_roughness_index, p_size, cell, "LTC roughness index out of range.");
	ERR_FAIL_INDEX_V_MSG(p_angle_index, p_size, cell, "LTC view-angle index out of range.");
	ERR_FAIL_NULL_V_MSG(p_one_lobe, cell, "The two-lobe fit needs the cell's 1-lobe fit.");
	const double alpha = LTCFitter::get_alpha(p_size, p_roughness_index);
	const double theta = LTCFitter::get_theta(p_size, p_angle_index);
	const bool isotropic = p_angle_index == 0;
	double fn = 0.0, fg = 0.0;
	LTCFitter::integrate_albedo(LTC_BRDF_ENGINE_GGX, alpha, theta, LTCFitter::ALBEDO_SAMPLES, &fn, &fg, nullptr);
	LTCPolygonObjective polygons;
	LTCFitter::build_polygon_objective(LTC_BRDF_ENGINE_GGX, alpha, theta, fn > 0.0 ? 1.0 / fn : 0.0, &polygons);
	cell.fn = p_one_lobe[5];
	cell.fg = p_one_lobe[6];

	double previous[12] = {};
	const bool smooth = p_smoothness > 0.0 && p_init_or_null;
	if (smooth) {
		stored_values(p_init_or_null, previous);
	}
	NelderMead::Function f = [&](const std::vector<double> &p_x) {
		double m[10], w[2];
		lobes_from(p_x, isotropic, m, w);
		for (int j = 0; j < 2; j++) {
			const double *mj = m + 5 * j;
			if (!(w[j] >= 0.0) || !(float(mj[0]) * float(mj[4]) - float(mj[1]) * float(mj[3]) > 0.0f) || !(mj[2] > 0.0)) {
				return 1e300;
			}
		}
		double e = polygons.error_mixture(m, w, 2);
		if (smooth) {
			const double v[12] = { m[0], m[1], m[2], m[3], m[4], w[0], m[5], m[6], m[7], m[8], m[9], w[1] };
			double d2 = 0.0;
			for (int k = 0; k < 12; k++) {
				d2 += (v[k] - previous[k]) * (v[k] - previous[k]);
			}
			e *= 1.0 + p_smoothness * d2;
		}
		return std::isfinite(e) ? e : 1e300;
	};

	std::vector<double> fresh;
	lobe_parameters(p_one_lobe, 1.0 - CORE_WEIGHT, 1.0, isotropic, fresh);
	lobe_parameters(p_one_lobe, CORE_WEIGHT, CORE_SCALE, isotropic, fresh);
	NelderMead::Result res = NelderMead::minimize(f, fresh, 0.1, 1e-6, LTCFitter::MAX_ITERATIONS);
	int iterations = res.iterations;
	if (p_init_or_null) {
		std::vector<double> warm;
		lobe_parameters(p_init_or_null, p_init_or_null[7], 1.0, isotropic, warm);
		lobe_parameters(p_init_or_null + 8, p_init_or_null[13], 1.0, isotropic, warm);
		NelderMead::Result chain = NelderMead::minimize(f, warm, 0.05, 1e-6, LTCFitter::MAX_ITERATIONS);
		iterations += chain.iterations;
		if (chain.value <= res.value) {
			res = chain;
		}
	}
	iterations += LTCFitter::restart_while_improving(f, res);
	// The floor: the 1-lobe cell itself (second lobe a copy with weight 0).
	std::vector<double> one;
	lobe_parameters(p_one_lobe, 1.0, 1.0, isotropic, one);
	lobe_parameters(p_one_lobe, 0.0, 1.0, isotropic, one);
	if (f(one) < res.value) {
		res.x = one;
	}

	double m[10], w[2];
	lobes_from(res.x, isotropic, m, w);
	for (int j = 0; j < 2; j++) {
		for (int k = 0; k < 5; k++) {
			cell.lobes[j][k] = float(m[5 * j + k]);
		}
		cell.weights[j] = float(w[j]);
	}
	cell.error = polygons.error_mixture(m, w, 2);
	double m1[5];
	for (int k = 0; k < 5; k++) {
		m1[k] = p_one_lobe[k];
	}
	cell.error_one_lobe = polygons.error(m1);
	cell.iterations = iterations;
	return cell;
}

int LTCTwoLobe::order_lobes(int p_size, std::vector<float> &r_table) {
	ERR_FAIL_COND_V(r_table.size() != size_t(p_size) * p_size * FLOATS_PER_CELL, 0);
	int swapped = 0;
	for (int t = 0; t < p_size; t++) {
		for (int r = p_size - 1; r >= 0; r--) {
			float *cell = &r_table[(size_t(t) * p_size + r) * FLOATS_PER_CELL];
			LTCTwoLobeCell other;
			other.read(cell);
			other.swap_lobes();
			float alt[FLOATS_PER_CELL];
			std::copy(cell, cell + FLOATS_PER_CELL, alt);
			other.write(alt);
			double keep = 0.0, swap = 0.0;
			if (r + 1 < p_size) {
				const float *n = &r_table[(size_t(t) * p_size + r + 1) * FLOATS_PER_CELL];
				keep += cell_distance(cell, n);
				swap += cell_distance(alt, n);
			}
			if (t > 0) {
				const float *n = &r_table[(size_t(t - 1) * p_size + r) * FLOATS_PER_CELL];
				keep += cell_distance(cell, n);
				swap += cell_distance(alt, n);
			}
			if (swap < keep) {
				std::copy(alt, alt + FLOATS_PER_CELL, cell);
				swapped++;
			}
		}
	}
	return swapped;
}

bool LTCTwoLobe::fit_table(int p_size, int p_r0, int p_r1, int p_t0, int p_t1, int p_threads, double p_smoothness, const std::vector<float> &p_one_lobe, std::vector<float> &r_table,
		std::vector<LTCTwoLobeCell> *r_cells, std::atomic<int> *r_done) {
	ERR_FAIL_COND_V_MSG(p_size < 2, false, "The LTC table needs at least 2 x 2 cells.");
	ERR_FAIL_COND_V_MSG(p_r0 < 0 || p_r1 >= p_size || p_r0 > p_r1, false, vformat("Bad LTC roughness range %d:%d for size %d.", p_r0, p_r1, p_size));
	ERR_FAIL_COND_V_MSG(p_t0 < 0 || p_t1 >= p_size || p_t0 > p_t1, false, vformat("Bad LTC view-angle range %d:%d for size %d.", p_t0, p_t1, p_size));
	ERR_FAIL_COND_V_MSG(p_one_lobe.size() != size_t(p_size) * p_size * LTCFitter::FLOATS_PER_CELL, false, "The 1-lobe LTC table has the wrong size.");
	const size_t cells = size_t(p_size) * p_size;
	r_table.assign(cells * FLOATS_PER_CELL, 0.0f);
	for (size_t i = 0; i < cells; i++) {
		LTCTwoLobeCell one;
		const float *src = &p_one_lobe[i * LTCFitter::FLOATS_PER_CELL];
		for (int j = 0; j < 2; j++) {
			for (int k = 0; k < 5; k++) {
				one.lobes[j][k] = src[k];
			}
		}
		one.fn = src[5];
		one.fg = src[6];
		one.write(&r_table[i * FLOATS_PER_CELL]);
	}
	if (r_cells) {
		r_cells->assign(cells, LTCTwoLobeCell());
	}
	auto chain = [&](int t) {
		const float *init = p_r1 < p_size - 1 ? &r_table[(size_t(t) * p_size + p_r1 + 1) * FLOATS_PER_CELL] : nullptr;
		for (int r = p_r1; r >= p_r0; r--) {
			const size_t i = size_t(t) * p_size + r;
			LTCTwoLobeCell cell = fit_cell(p_size, r, t, &p_one_lobe[i * LTCFitter::FLOATS_PER_CELL], init, p_smoothness);
			cell.write(&r_table[i * FLOATS_PER_CELL]);
			if (r_cells) {
				(*r_cells)[i] = cell;
			}
			init = &r_table[i * FLOATS_PER_CELL];
			if (r_done) {
				r_done->fetch_add(1);
			}
		}
	};
	LTCFitter::run_chains(p_threads, p_t0, p_t1, chain);
	order_lobes(p_size, r_table);
	return true;
}

const float *LTCTwoLobe::get_builtin_table() {
	return LTC_LUT_ENGINE_GGX_2LOBE;
}

String LTCTwoLobe::format_inc(int p_size, const std::vector<float> &p_table, const String &p_command, const String &p_stats) {
	ERR_FAIL_COND_V_MSG(p_table.size() != size_t(p_size) * p_size * FLOATS_PER_CELL, String(), "The two-lobe LTC table has the wrong size.");
	String o = "/**************************************************************************/\n"
			   "/*  ltc_lut_2lobe_data.inc                                                */\n"
			   "/**************************************************************************/\n"
			   "/* GENERATED FILE, do not edit: godot-area two-lobe LTC lookup table\n"
			   " * (issue #18; modules/ltc_fit/ltc_two_lobe.h describes the model and the fit),\n"
			   " * written by modules/ltc_fit with the command:\n";
	o += " *   " + p_command + "\n *\n * Fit statistics:\n";
	for (const String &line : string_split(p_stats, '\n')) {
		if (!line.empty()) {
			o += " *   " + line + "\n";
		}
	}
	o += " *\n * LAYOUT: N = LTC_LUT_2LOBE_SIZE (= LTC_LUT_SIZE, the same parametrisation as\n"
		 " * ltc_lut_data.inc); cell (ti, ri) starts at float (ti * N + ri) * 16, four RGBA texels\n"
		 " *   (a1, b1, c1, d1), (e1, fn, fg, w1), (a2, b2, c2, d2), (e2, w2, 0, 0):\n"
		 " * two matrices M = [[a, 0, b], [0, c, 0], [d, 0, e]] (thesis eq. 5.6, not inverted) and their\n"
		 " * weights; the lobe is w1 D_M1 + w2 D_M2, fn and fg as in ltc_lut_data.inc.\n */\n\n"
		 "#pragma once\n\n";
	o += vformat("static const int LTC_LUT_2LOBE_SIZE = %d;\n\n", p_size);
	o += LTCTableIO::format_array("LTC_LUT_ENGINE_GGX_2LOBE", p_size, FLOATS_PER_CELL, p_table);
	return o;
}
