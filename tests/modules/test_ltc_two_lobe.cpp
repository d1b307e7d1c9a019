/**************************************************************************/
/*  test_ltc_two_lobe.cpp                                                 */
/**************************************************************************/
/* godot-area: the two-lobe LTC (modules/ltc_fit/ltc_two_lobe.h, issue    */
/* #18): a grazing cell's fit beats its 1-lobe cell on the polygon        */
/* objective, the lobe-order pass undoes a swap, the committed table is   */
/* sane (finite, invertible, non-negative weights, one lobe outside the   */
/* fitted block, never worse than the 1-lobe table), and the include      */
/* round-trips through the writer.                                        */

#include "modules/ltc_fit/ltc_fitter.h"
#include "modules/ltc_fit/ltc_polygon_objective.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/ltc_fit/ltc_two_lobe.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

namespace TestLTCTwoLobe {

static const float *one_lobe_cell(int p_r, int p_t) {
	const int n = LTCTableIO::get_builtin_size();
	return LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX) + (size_t(p_t) * n + p_r) * LTCFitter::FLOATS_PER_CELL;
}

static const float *two_lobe_cell(int p_r, int p_t) {
	const int n = LTCTableIO::get_builtin_size();
	return LTCTwoLobe::get_builtin_table() + (size_t(p_t) * n + p_r) * LTCTwoLobe::FLOATS_PER_CELL;
}

// The polygon objective of a 16-float cell and of the cell's 1-lobe matrix.
static void objectives(int p_r, int p_t, const float *p_cell, double *r_two, double *r_one) {
	const int n = LTCTableIO::get_builtin_size();
	const double alpha = LTCFitter::get_alpha(n, p_r), theta = LTCFitter::get_theta(n, p_t);
	double fn = 0.0, fg = 0.0;
	LTCFitter::integrate_albedo(LTC_BRDF_ENGINE_GGX, alpha, theta, LTCFitter::ALBEDO_SAMPLES, &fn, &fg, nullptr);
	LTCPolygonObjective objective;
	LTCFitter::build_polygon_objective(LTC_BRDF_ENGINE_GGX, alpha, theta, 1.0 / fn, &objective);
	double m[10], w[2] = { p_cell[7], p_cell[13] }, m1[5];
	for (int k = 0; k < 5; k++) {
		m[k] = p_cell[k];
		m[5 + k] = p_cell[8 + k];
		m1[k] = one_lobe_cell(p_r, p_t)[k];
	}
	*r_two = objective.error_mixture(m, w, 2);
	*r_one = objective.error(m1);
}

TEST_CASE("[LTCTwoLobe] a grazing cell's two-lobe fit halves the 1-lobe polygon error") {
	// Roughness 0.5, theta_v ~ 78 degrees: the cell the TV-over-a-floor scenes read (doc/accuracy.md 5.1).
	const int n = LTCTableIO::get_builtin_size();
	const int r = 32, t = 56;
	const LTCTwoLobeCell cell = LTCTwoLobe::fit_cell(n, r, t, one_lobe_cell(r, t), nullptr, 0.0);
	MESSAGE("E 1-lobe " << cell.error_one_lobe << ", 2-lobe " << cell.error << ", weights " << cell.weights[0] << " " << cell.weights[1]);
	CHECK(std::isfinite(cell.error));
	CHECK(cell.error < 0.5 * cell.error_one_lobe);
	for (int j = 0; j < 2; j++) {
		CHECK(cell.weights[j] >= 0.0f);
		CHECK(cell.lobes[j][2] > 0.0f);
		CHECK(cell.lobes[j][0] * cell.lobes[j][4] - cell.lobes[j][1] * cell.lobes[j][3] > 0.0f);
	}
	CHECK(cell.fn == one_lobe_cell(r, t)[5]);
	CHECK(cell.fg == one_lobe_cell(r, t)[6]);
}

TEST_CASE("[LTCTwoLobe] the lobe-order pass swaps a cell back to its neighbours' order") {
	const int n = LTCTableIO::get_builtin_size();
	const float *src = LTCTwoLobe::get_builtin_table();
	std::vector<float> table(src, src + size_t(n) * n * LTCTwoLobe::FLOATS_PER_CELL);
	CHECK(LTCTwoLobe::order_lobes(n, table) == 0); // The committed table is already ordered.
	// Swap a grazing cell whose lobes differ: the pass puts it back, bit for bit.
	int r = 32, t = 58;
	float *cell = &table[(size_t(t) * n + r) * LTCTwoLobe::FLOATS_PER_CELL];
	REQUIRE(cell[13] > 0.0f);
	std::vector<float> before(cell, cell + LTCTwoLobe::FLOATS_PER_CELL);
	LTCTwoLobeCell c;
	c.read(cell);
	c.swap_lobes();
	c.write(cell);
	CHECK(std::memcmp(cell, before.data(), before.size() * sizeof(float)) != 0);
	CHECK(LTCTwoLobe::order_lobes(n, table) == 1);
	CHECK(std::memcmp(cell, before.data(), before.size() * sizeof(float)) == 0);
}

TEST_CASE("[LTCTwoLobe] the committed table is sane and never worse than the 1-lobe table") {
	const int n = LTCTableIO::get_builtin_size();
	int two_lobe_cells = 0;
	for (int t = 0; t < n; t++) {
		for (int r = 0; r < n; r++) {
			const float *c = two_lobe_cell(r, t);
			for (int k = 0; k < LTCTwoLobe::FLOATS_PER_CELL; k++) {
				REQUIRE(std::isfinite(c[k]));
			}
			CHECK(c[5] == one_lobe_cell(r, t)[5]);
			CHECK(c[6] == one_lobe_cell(r, t)[6]);
			CHECK(c[7] >= 0.0f);
			CHECK(c[13] >= 0.0f);
			for (int j = 0; j < 2; j++) {
				const float *m = c + 8 * j;
				CHECK(m[2] > 0.0f);
				CHECK(m[0] * m[4] - m[1] * m[3] > 0.0f);
			}
			two_lobe_cells += c[13] > 0.0f && c[7] > 0.0f ? 1 : 0;
		}
	}
	MESSAGE(two_lobe_cells << " cells use both lobes");
	CHECK(two_lobe_cells > 500);
	// Outside the fitted block (roughness index < ENGINE_REFIT_R0): the 1-lobe cell with weight 1.
	for (int t : { 0, 30, 63 }) {
		const float *c = two_lobe_cell(5, t);
		CHECK(std::memcmp(c, one_lobe_cell(5, t), 5 * sizeof(float)) == 0);
		CHECK(c[7] == 1.0f);
		CHECK(c[13] == 0.0f);
	}
	// Grazing cells the suite's TV scenes read: the stored cell against its 1-lobe cell.
	for (int t : { 48, 56, 62 }) {
		for (int r : { 16, 32, 47 }) {
			double two = 0.0, one = 0.0;
			objectives(r, t, two_lobe_cell(r, t), &two, &one);
			CHECK_MESSAGE(two <= one * 1.0001, "cell (r ", r, ", t ", t, "): 2-lobe ", two, " 1-lobe ", one);
		}
	}
}

TEST_CASE("[LTCTwoLobe] the include writer prints every float exactly") {
	const int n = 2;
	std::vector<float> table(size_t(n) * n * LTCTwoLobe::FLOATS_PER_CELL, 0.5f);
	table[0] = 0.1f;
	table[1] = -0.0f;
	table[2] = 1.0f;
	const String text = LTCTwoLobe::format_inc(n, table, "test", "none");
	CHECK(text.find("static const int LTC_LUT_2LOBE_SIZE = 2;") != String::npos);
	CHECK(text.find("LTC_LUT_ENGINE_GGX_2LOBE[2 * 2 * 16] = {") != String::npos);
	CHECK(text.find("\t0.100000001f, -0.0f, 1.0f, 0.5f,") != String::npos);
	CHECK(LTCTwoLobe::format_inc(n, std::vector<float>(3), "test", "none").empty());
}

} // namespace TestLTCTwoLobe
