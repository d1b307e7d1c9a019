/**************************************************************************/
/*  nelder_mead.cpp                                                       */
/**************************************************************************/
/* godot-area: deterministic Nelder-Mead minimiser (see nelder_mead.h).   */

#include "modules/ltc_fit/nelder_mead.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>
#include <numeric>

NelderMead::Result NelderMead::minimize(const Function &p_function, const std::vector<double> &p_start, double p_step, double p_tolerance, int p_max_iterations) {
	Result result;
	result.x = p_start;
	const int n = (int)p_start.size();
	ERR_FAIL_COND_V_MSG(n == 0, result, "Nelder-Mead needs at least one parameter.");
	ERR_FAIL_COND_V_MSG(!p_function, result, "Nelder-Mead needs a function to minimise.");

	// Simplex of n + 1 vertices with their values.
	std::vector<std::vector<double>> pts(n + 1, p_start);
	std::vector<double> val(n + 1);
	for (int i = 0; i < n; i++) {
		pts[i + 1][i] += p_step;
	}
	for (int i = 0; i <= n; i++) {
		val[i] = p_function(pts[i]);
		result.evaluations++;
	}

	std::vector<int> order(n + 1);
	std::vector<double> centroid(n), xr(n), xe(n), xc(n);
	auto point_along = [&](std::vector<double> &r_out, double p_t, int p_worst) {
		// r_out = centroid + p_t * (centroid - worst).
		for (int k = 0; k < n; k++) {
			r_out[k] = centroid[k] + p_t * (centroid[k] - pts[p_worst][k]);
		}
	};

	int it = 0;
	for (; it < p_max_iterations; it++) {
		std::iota(order.begin(), order.end(), 0);
		// Stable sort keeps ties in index order, so the result never depends on anything but the inputs.
		std::stable_sort(order.begin(), order.end(), [&](int p_a, int p_b) { return val[p_a] < val[p_b]; });
		const int best = order[0];
		const int worst = order[n];
		const int second_worst = order[n - 1]; // == best when n == 1.

		const double spread = val[worst] - val[best];
		double size = 0.0;
		for (int i = 0; i <= n; i++) {
			for (int k = 0; k < n; k++) {
				size = std::max(size, std::fabs(pts[i][k] - pts[best][k]));
			}
		}
		if (spread <= p_tolerance * (std::fabs(val[best]) + 1e-30) || size < 1e-12) {
			result.converged = true;
			break;
		}

		std::fill(centroid.begin(), centroid.end(), 0.0);
		for (int i = 0; i <= n; i++) {
			if (i == worst) {
				continue;
			}
			for (int k = 0; k < n; k++) {
				centroid[k] += pts[i][k];
			}
		}
		for (int k = 0; k < n; k++) {
			centroid[k] /= n;
		}

		point_along(xr, 1.0, worst);
		const double fr = p_function(xr);
		result.evaluations++;
		if (fr < val[best]) {
			point_along(xe, 2.0, worst);
			const double fe = p_function(xe);
			result.evaluations++;
			if (fe < fr) {
				pts[worst] = xe;
				val[worst] = fe;
			} else {
				pts[worst] = xr;
				val[worst] = fr;
			}
			continue;
		}
		if (fr < val[second_worst]) {
			pts[worst] = xr;
			val[worst] = fr;
			continue;
		}
		// Contraction: outside when the reflected point beats the worst, inside otherwise.
		const bool outside = fr < val[worst];
		point_along(xc, outside ? 0.5 : -0.5, worst);
		const double fc = p_function(xc);
		result.evaluations++;
		if (fc < (outside ? fr : val[worst])) {
			pts[worst] = xc;
			val[worst] = fc;
			continue;
		}
		// Shrink towards the best vertex.
		for (int i = 0; i <= n; i++) {
			if (i == best) {
				continue;
			}
			for (int k = 0; k < n; k++) {
				pts[i][k] = pts[best][k] + 0.5 * (pts[i][k] - pts[best][k]);
			}
			val[i] = p_function(pts[i]);
			result.evaluations++;
		}
	}

	int best = 0;
	for (int i = 1; i <= n; i++) {
		if (val[i] < val[best]) {
			best = i;
		}
	}
	result.x = pts[best];
	result.value = val[best];
	result.iterations = it;
	return result;
}
