/**************************************************************************/
/*  test_ltc_fit.cpp                                                      */
/**************************************************************************/
/* godot-area: tests for the LTC fitter (modules/ltc_fit) and the         */
/* committed tables servers/rendering/renderer_rd/ltc_lut_data.inc:       */
/* Nelder-Mead on Rosenbrock, re-fits reproduce committed cells, stored   */
/* fn/fg against an independent integration, LTC normalisation, table     */
/* sanity, exact include round trip, thread-count independence and the   */
/* command's argument checks.                                             */

#include "modules/ltc_fit/ltc_fit_command.h"
#include "modules/ltc_fit/ltc_fitter.h"
#include "modules/ltc_fit/ltc_polygon_objective.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/ltc_fit/nelder_mead.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#ifndef GODOT_AREA_ROOT
#define GODOT_AREA_ROOT "."
#endif

namespace TestLTCFit {

static const LTCBRDFVariant VARIANTS[2] = { LTC_BRDF_ENGINE_GGX, LTC_BRDF_SMITH_GGX };

static const float *cell_of(const float *p_table, int p_size, int p_r, int p_t) {
	return p_table + ((size_t)p_t * p_size + p_r) * LTCFitter::FLOATS_PER_CELL;
}

// Independent albedo integrations (the fitter uses visible-normal sampling):
// GGX NDF sampling (h ~ D(h) NoH), 256 x 256 stratified samples, for glossy cells away from grazing;
static void reference_albedo_ndf(LTCBRDFVariant p_variant, double p_alpha, double p_theta, double *r_fn, double *r_fg) {
	const int n = 256;
	const double v[3] = { std::sin(p_theta), 0.0, std::cos(p_theta) };
	double fn = 0.0, fg = 0.0;
	for (int i = 0; i < n; i++) {
		for (int j = 0; j < n; j++) {
			const double u1 = (i + 0.5) / n, u2 = (j + 0.5) / n;
			// Inverse CDF of D(h) NoH for GGX: tan^2(theta_h) = alpha^2 u1 / (1 - u1).
			const double cos_h = 1.0 / std::sqrt(1.0 + p_alpha * p_alpha * u1 / (1.0 - u1));
			const double sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
			const double phi = 2.0 * LTCBRDF::BRDF_PI * u2;
			const double h[3] = { sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h };
			const double voh = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
			if (voh <= 0.0) {
				continue;
			}
			const double l[3] = { 2.0 * voh * h[0] - v[0], 2.0 * voh * h[1] - v[1], 2.0 * voh * h[2] - v[2] };
			if (l[2] <= 0.0) {
				continue;
			}
			const double pdf = LTCBRDF::D_GGX(cos_h, p_alpha) * cos_h / (4.0 * voh);
			const double w = LTCBRDF::evaluate(p_variant, v, l, p_alpha) * l[2] / pdf;
			const double m = 1.0 - voh;
			fn += w;
			fg += w * m * m * m * m * m;
		}
	}
	*r_fn = fn / ((double)n * n);
	*r_fg = fg / ((double)n * n);
}

// and a plain equal-area midpoint grid over the hemisphere (1024 x 1024) for rough cells, which
// also handles grazing views where NDF sampling converges slowly.
static void reference_albedo_grid(LTCBRDFVariant p_variant, double p_alpha, double p_theta, double *r_fn, double *r_fg) {
	const int n = 1024;
	const double v[3] = { std::sin(p_theta), 0.0, std::cos(p_theta) };
	double fn = 0.0, fg = 0.0;
	for (int i = 0; i < n; i++) {
		const double z = (i + 0.5) / n;
		const double s = std::sqrt(1.0 - z * z);
		for (int j = 0; j < n; j++) {
			const double phi = 2.0 * LTCBRDF::BRDF_PI * (j + 0.5) / n;
			const double l[3] = { s * std::cos(phi), s * std::sin(phi), z };
			double h[3] = { v[0] + l[0], v[1] + l[1], v[2] + l[2] };
			const double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
			const double voh = (v[0] * h[0] + v[1] * h[1] + v[2] * h[2]) / hl;
			const double w = LTCBRDF::evaluate(p_variant, v, l, p_alpha) * z;
			const double m = 1.0 - voh;
			fn += w;
			fg += w * m * m * m * m * m;
		}
	}
	const double d_omega = 2.0 * LTCBRDF::BRDF_PI / ((double)n * n);
	*r_fn = fn * d_omega;
	*r_fg = fg * d_omega;
}

TEST_CASE("[LTCFit] Nelder-Mead minimises the Rosenbrock function") {
	int calls = 0;
	NelderMead::Function rosenbrock = [&calls](const std::vector<double> &p_x) {
		calls++;
		const double a = 1.0 - p_x[0];
		const double b = p_x[1] - p_x[0] * p_x[0];
		return a * a + 100.0 * b * b;
	};
	NelderMead::Result res = NelderMead::minimize(rosenbrock, { -1.2, 1.0 }, 0.5, 1e-14, 5000);
	CHECK(res.converged);
	CHECK(res.value < 1e-8);
	CHECK(std::fabs(res.x[0] - 1.0) < 1e-3);
	CHECK(std::fabs(res.x[1] - 1.0) < 1e-3);
	CHECK(res.evaluations == calls);

	// Same input, same output: the minimiser is deterministic.
	NelderMead::Result again = NelderMead::minimize(rosenbrock, { -1.2, 1.0 }, 0.5, 1e-14, 5000);
	CHECK(again.x == res.x);
	CHECK(again.iterations == res.iterations);
}

TEST_CASE("[LTCFit] committed tables are finite, with det M > 0 and fn <= 1") {
	const int n = LTCTableIO::get_builtin_size();
	REQUIRE(n == 64);
	for (LTCBRDFVariant variant : VARIANTS) {
		const float *table = LTCTableIO::get_builtin_table(variant);
		REQUIRE(table != nullptr);
		int bad_finite = 0, bad_det = 0, bad_fn = 0, bad_fg = 0, bad_pad = 0;
		float max_fn = 0.0f;
		for (int t = 0; t < n; t++) {
			for (int r = 0; r < n; r++) {
				const float *c = cell_of(table, n, r, t);
				for (int k = 0; k < 8; k++) {
					bad_finite += std::isfinite(c[k]) ? 0 : 1;
				}
				const double det = (double)c[2] * ((double)c[0] * c[4] - (double)c[1] * c[3]);
				bad_det += det > 0.0 ? 0 : 1;
				bad_fn += (c[5] > 0.0f && c[5] <= 1.0f + 1e-3f) ? 0 : 1;
				bad_fg += (c[6] >= 0.0f && c[6] <= c[5]) ? 0 : 1;
				bad_pad += c[7] == 0.0f ? 0 : 1;
				max_fn = std::max(max_fn, c[5]);
			}
		}
		INFO("variant ", String(LTCBRDF::get_variant_name(variant)), ", max fn ", max_fn);
		CHECK(bad_finite == 0);
		CHECK(bad_det == 0);
		CHECK(bad_fn == 0);
		CHECK(bad_fg == 0);
		CHECK(bad_pad == 0);
	}
}

TEST_CASE("[LTCFit] re-fitting cells from their committed neighbour reproduces the table") {
	// Tolerance: the fit is deterministic, so the same build reproduces the cells bit for bit; 1e-3
	// (relative to the matrix column a cell value belongs to) leaves room for another compiler or
	// optimisation level moving Nelder-Mead to a different point within its 1e-6 objective tolerance.
	const int n = LTCTableIO::get_builtin_size();
	const int cells[][2] = { { 63, 0 }, { 63, 40 }, { 45, 10 }, { 20, 32 }, { 8, 50 }, { 2, 63 }, { 30, 60 }, { 50, 40 }, { 12, 63 } };
	for (LTCBRDFVariant variant : VARIANTS) {
		const float *table = LTCTableIO::get_builtin_table(variant);
		for (const auto &rc : cells) {
			const int r = rc[0], t = rc[1];
			const float *init = r < n - 1 ? cell_of(table, n, r + 1, t) : nullptr;
			// The engine table's grazing block was refitted with the free-axis polygon fit (issue #18).
			const bool refit = variant == LTC_BRDF_ENGINE_GGX && LTCFitter::is_engine_refit_cell(r, t);
			LTCCell cell = LTCFitter::fit_cell(variant, n, r, t, init, refit ? LTCFitter::engine_refit_options() : LTCFitOptions());
			float got[8];
			cell.write(got);
			const float *want = cell_of(table, n, r, t);
			const double col0 = std::max(1e-30, std::sqrt((double)want[0] * want[0] + (double)want[3] * want[3]));
			const double col1 = std::max(1e-30, (double)std::fabs(want[2]));
			const double col2 = std::sqrt((double)want[1] * want[1] + (double)want[4] * want[4]);
			const double scale[7] = { col0, col2, col1, col0, col2, 1.0, 1.0 };
			INFO(String(LTCBRDF::get_variant_name(variant)), " cell ri ", r, " ti ", t);
			for (int k = 0; k < 5; k++) {
				INFO("component ", k, " got ", got[k], " want ", want[k]);
				CHECK(std::fabs((double)got[k] - want[k]) <= 1e-3 * scale[k]);
			}
			CHECK(std::fabs(got[5] - want[5]) <= 1e-6f);
			CHECK(std::fabs(got[6] - want[6]) <= 1e-6f);
			CHECK(std::isfinite(cell.error_l1));
		}
		// A well-conditioned cell fits closely: L1 distance integral |rho - D| (0..2) below 0.1.
		LTCCell good = LTCFitter::fit_cell(variant, n, 45, 10, cell_of(table, n, 46, 10));
		CHECK(good.error_l1 < 0.1);
	}
}

TEST_CASE("[LTCFit] stored fn and fg match an independent albedo integration within 1 %") {
	const int n = LTCTableIO::get_builtin_size();
	const int cells[][2] = { { 63, 0 }, { 32, 20 }, { 16, 40 }, { 8, 56 }, { 48, 63 }, { 4, 10 } };
	for (LTCBRDFVariant variant : VARIANTS) {
		const float *table = LTCTableIO::get_builtin_table(variant);
		for (const auto &rc : cells) {
			const int r = rc[0], t = rc[1];
			double fn = 0.0, fg = 0.0;
			if (r >= 32) {
				reference_albedo_grid(variant, LTCFitter::get_alpha(n, r), LTCFitter::get_theta(n, t), &fn, &fg);
			} else {
				reference_albedo_ndf(variant, LTCFitter::get_alpha(n, r), LTCFitter::get_theta(n, t), &fn, &fg);
			}
			const float *c = cell_of(table, n, r, t);
			INFO(String(LTCBRDF::get_variant_name(variant)), " cell ri ", r, " ti ", t, ": stored fn ", c[5], " reference ", fn, ", stored fg ", c[6], " reference ", fg);
			CHECK(std::fabs(c[5] - fn) <= 0.01 * fn);
			CHECK(std::fabs(c[6] - fg) <= 0.01 * fn);
			CHECK(c[5] <= 1.0f + 1e-3f);
		}
	}
}

TEST_CASE("[LTCFit] fitted LTC distributions integrate to one over the sphere") {
	// Equal-area midpoint grid over the sphere (z uniform in [-1, 1], phi uniform), 1024 x 2048
	// points; the cells are rough enough for the grid to resolve the lobe.
	const int n = LTCTableIO::get_builtin_size();
	const int cells[][2] = { { 63, 0 }, { 40, 20 }, { 28, 45 }, { 50, 63 }, { 24, 8 } };
	const int nz = 1024, nphi = 2048;
	for (LTCBRDFVariant variant : VARIANTS) {
		const float *table = LTCTableIO::get_builtin_table(variant);
		for (const auto &rc : cells) {
			const float *c = cell_of(table, n, rc[0], rc[1]);
			const double m[5] = { c[0], c[1], c[2], c[3], c[4] };
			double sum = 0.0;
			for (int i = 0; i < nz; i++) {
				const double z = -1.0 + 2.0 * (i + 0.5) / nz;
				const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
				for (int j = 0; j < nphi; j++) {
					const double phi = 2.0 * LTCBRDF::BRDF_PI * (j + 0.5) / nphi;
					const double l[3] = { s * std::cos(phi), s * std::sin(phi), z };
					sum += LTCFitter::ltc_evaluate(m, l);
				}
			}
			const double integral = sum * 4.0 * LTCBRDF::BRDF_PI / ((double)nz * nphi);
			INFO(String(LTCBRDF::get_variant_name(variant)), " cell ri ", rc[0], " ti ", rc[1], ": integral ", integral);
			CHECK(std::fabs(integral - 1.0) <= 1e-3);
		}
	}
}

TEST_CASE("[LTCFit] the committed include parses back to the compiled tables bit for bit") {
	const int n = LTCTableIO::get_builtin_size();
	const size_t count = (size_t)n * n * 8;
	const float *engine = LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX);
	const float *smith = LTCTableIO::get_builtin_table(LTC_BRDF_SMITH_GGX);

	int size = 0;
	std::vector<float> e, s;
	String error;
	REQUIRE(LTCTableIO::load_inc(String(GODOT_AREA_ROOT) + "/" + LTCTableIO::DEFAULT_INC_PATH, &size, &e, &s, &error));
	CHECK(size == n);
	REQUIRE(e.size() == count);
	REQUIRE(s.size() == count);
	CHECK(std::memcmp(e.data(), engine, count * sizeof(float)) == 0);
	CHECK(std::memcmp(s.data(), smith, count * sizeof(float)) == 0);

	// format -> parse is exact too, including awkward values.
	std::vector<float> a(engine, engine + count), b(smith, smith + count);
	a[0] = 1.0f;
	a[1] = -0.0f;
	a[2] = 1e-38f;
	a[3] = 0.1f;
	a[4] = 3.40282e38f;
	const String text = LTCTableIO::format_inc(n, a, b, "test", "none");
	std::vector<float> a2, b2;
	REQUIRE(LTCTableIO::parse_inc(text, &size, &a2, &b2, &error));
	CHECK(std::memcmp(a2.data(), a.data(), count * sizeof(float)) == 0);
	CHECK(std::memcmp(b2.data(), b.data(), count * sizeof(float)) == 0);

	// Malformed text is rejected with a message, never a crash.
	CHECK_FALSE(LTCTableIO::parse_inc("", &size, &a2, &b2, &error));
	CHECK_FALSE(error.empty());
	CHECK_FALSE(LTCTableIO::parse_inc("static const int LTC_LUT_SIZE = 2;\nLTC_LUT_ENGINE_GGX[2] = { 1.0f, 2.0f };", &size, &a2, &b2, &error));
	CHECK_FALSE(LTCTableIO::parse_inc(text.substr(0, text.size() / 2), &size, &a2, &b2, &error));
}

TEST_CASE("[LTCFit] fit_table does not depend on the thread count") {
	const int n = 64;
	std::vector<float> one((size_t)n * n * 8, 0.0f), many((size_t)n * n * 8, 0.0f);
	REQUIRE(LTCFitter::fit_table(LTC_BRDF_SMITH_GGX, n, 58, 63, 0, 2, 1, one, nullptr, nullptr));
	std::atomic<int> done(0);
	REQUIRE(LTCFitter::fit_table(LTC_BRDF_SMITH_GGX, n, 58, 63, 0, 2, 3, many, nullptr, &done));
	CHECK(done.load() == 6 * 3);
	CHECK(std::memcmp(one.data(), many.data(), one.size() * sizeof(float)) == 0);
	CHECK(one[((size_t)1 * n + 60) * 8 + 2] > 0.0f); // A fitted cell was written.
	CHECK(one[((size_t)3 * n + 60) * 8 + 2] == 0.0f); // A cell outside the range was not.

	// Bad ranges fail cleanly.
	CHECK_FALSE(LTCFitter::fit_table(LTC_BRDF_SMITH_GGX, n, 5, 2, 0, 1, 1, one, nullptr, nullptr));
	CHECK_FALSE(LTCFitter::fit_table(LTC_BRDF_SMITH_GGX, n, 0, 64, 0, 1, 1, one, nullptr, nullptr));
	std::vector<float> small(10);
	CHECK_FALSE(LTCFitter::fit_table(LTC_BRDF_SMITH_GGX, n, 0, 1, 0, 1, 1, small, nullptr, nullptr));
}

TEST_CASE("[LTCFit] ltc-fit command rejects bad arguments") {
	CHECK(ltc_fit_command({ "--bogus" }) == 2);
	CHECK(ltc_fit_command({ "--size" }) == 2);
	CHECK(ltc_fit_command({ "--size", "1" }) == 2);
	CHECK(ltc_fit_command({ "--size", "abc" }) == 2);
	CHECK(ltc_fit_command({ "--brdf", "phong" }) == 2);
	CHECK(ltc_fit_command({ "--cells", "5:2,0:1" }) == 2);
	CHECK(ltc_fit_command({ "--cells", "0:1" }) == 2);
	CHECK(ltc_fit_command({ "--cells", "0:70,0:1" }) == 2);
	CHECK(ltc_fit_command({ "ltc-fit", "--threads", "-3" }) == 2);
	CHECK(ltc_fit_command({ "-o", "" }) == 2);
	// A different size needs both variants (the other would be kept from the 64 x 64 table).
	CHECK(ltc_fit_command({ "--size", "8", "--brdf", "engine" }) == 2);
	CHECK(ltc_fit_command({ "--norm", "4" }) == 2);
	CHECK(ltc_fit_command({ "--smoothness", "-1" }) == 2);
	CHECK(ltc_fit_command({ "--smoothness", "x" }) == 2);
	// A valid partial fit prints and returns 0 without writing a file.
	CHECK(ltc_fit_command({ "ltc-fit", "--brdf", "engine", "--cells", "63:63,0:1" }) == 0);
}

TEST_CASE("[LTCFit] the polygon objective's form factor matches the closed-form configuration factor") {
	// A 2 x 1 rectangle parallel to the receiver 1.5 above it, one corner straight above the origin
	// (Howell's catalogue): FF = (1 / (2 pi)) (x / sx atan(y / sx) + y / sy atan(x / sy)).
	const double a = 2.0, b = 1.0, h = 1.5;
	const double quad[12] = { 0, 0, h, a, 0, h, a, b, h, 0, b, h };
	const double x = a / h, y = b / h, sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
	const double want = (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * 3.14159265358979323846);
	CHECK(LTCPolygonObjective::form_factor(quad, 4) == doctest::Approx(want).epsilon(1e-9));
	// Wholly below the horizon: 0; half below: the upper half's value.
	const double below[12] = { 0, 0, -1, 1, 0, -1, 1, 1, -1, 0, 1, -1 };
	CHECK(LTCPolygonObjective::form_factor(below, 4) == 0.0);
	// The identity LTC is the clamped cosine: ltc_integral == form_factor.
	const double identity[5] = { 1, 0, 1, 0, 1 };
	CHECK(LTCPolygonObjective::ltc_integral(identity, quad) == doctest::Approx(want).epsilon(1e-12));
	const double singular[5] = { 1, 1, 1, 1, 1 };
	CHECK(LTCPolygonObjective::ltc_integral(singular, quad) < 0.0);
}

TEST_CASE("[LTCFit] the free-axis polygon fit lowers the polygon-integral error of grazing cells") {
	// Cells the floor-under-a-TV view reads (issue #18): roughness 0.3 and 0.5 at theta_v 68 and 80 degrees.
	const int n = LTCTableIO::get_builtin_size();
	const int cells[][2] = { { 19, 47 }, { 32, 57 } };
	for (const auto &rc : cells) {
		const int r = rc[0], t = rc[1];
		INFO("cell ri ", r, " ti ", t);
		// The 3-parameter L3 fit, the 3-parameter polygon fit and the free-axis polygon fit, one start.
		const float *init = LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX) + ((size_t)t * n + r + 1) * LTCFitter::FLOATS_PER_CELL;
		LTCCell fixed_axis = LTCFitter::fit_cell(LTC_BRDF_ENGINE_GGX, n, r, t, init);
		LTCFitOptions polygons_only;
		polygons_only.polygons = true;
		LTCCell scored = LTCFitter::fit_cell(LTC_BRDF_ENGINE_GGX, n, r, t, init, polygons_only);
		LTCCell free_axis = LTCFitter::fit_cell(LTC_BRDF_ENGINE_GGX, n, r, t, init, LTCFitter::engine_refit_options());
		// error_l3 holds the minimised objective (with polygons: the polygon-integral error).
		MESSAGE("polygon error (relative MSE of test-light integrals): fixed-axis polygon fit ", scored.error_l3, ", free-axis polygon fit ", free_axis.error_l3, "; L1 lobe distance: L3 fit ",
				fixed_axis.error_l1, ", free-axis polygon fit ", free_axis.error_l1);
		CHECK(free_axis.error_l3 < scored.error_l3); // The 4th parameter helps on top of the objective.
		CHECK(free_axis.error_l3 < 0.01); // Below 10 % relative RMS over the test lights.
		const double det = (double)free_axis.c * ((double)free_axis.a * free_axis.e - (double)free_axis.b * free_axis.d);
		CHECK(det > 0.0);
	}
}

} // namespace TestLTCFit
