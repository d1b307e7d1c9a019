/**************************************************************************/
/*  ssim.cpp                                                              */
/**************************************************************************/
/* godot-area: SSIM (Wang et al. 2004), see ssim.h.                       */

#include "modules/metrics/ssim.h"

#include "core/error/error_macros.h"
#include "modules/metrics/metrics_filter.h"

#include <cmath>
#include <limits>

float SSIM::compute(const std::vector<float> &p_x, const std::vector<float> &p_y, int p_width, int p_height, std::vector<float> *r_map) {
	const size_t count = (size_t)std::max(0, p_width) * (size_t)std::max(0, p_height);
	ERR_FAIL_COND_V_MSG(count == 0 || p_x.size() != count || p_y.size() != count, std::numeric_limits<float>::quiet_NaN(),
			vformat("SSIM: planes of %zu and %zu values do not match %dx%d.", p_x.size(), p_y.size(), p_width, p_height));

	const std::vector<float> window = MetricsFilter::gaussian_1d(WINDOW_SIGMA, WINDOW_RADIUS);
	std::vector<float> xx(count), yy(count), xy(count);
	for (size_t i = 0; i < count; i++) {
		xx[i] = p_x[i] * p_x[i];
		yy[i] = p_y[i] * p_y[i];
		xy[i] = p_x[i] * p_y[i];
	}
	std::vector<float> mx, my, mxx, myy, mxy;
	MetricsFilter::blur_truncated(p_x, p_width, p_height, window, mx);
	MetricsFilter::blur_truncated(p_y, p_width, p_height, window, my);
	MetricsFilter::blur_truncated(xx, p_width, p_height, window, mxx);
	MetricsFilter::blur_truncated(yy, p_width, p_height, window, myy);
	MetricsFilter::blur_truncated(xy, p_width, p_height, window, mxy);

	const double c1 = double(K1 * DYNAMIC_RANGE) * double(K1 * DYNAMIC_RANGE);
	const double c2 = double(K2 * DYNAMIC_RANGE) * double(K2 * DYNAMIC_RANGE);
	if (r_map) {
		r_map->resize(count);
	}
	double total = 0.0;
	for (size_t i = 0; i < count; i++) {
		const double ux = mx[i];
		const double uy = my[i];
		// Variances can come out slightly negative from float rounding (C2 keeps the denominator
		// positive). Identical inputs give bit-identical numerator and denominator, hence exactly 1.
		const double vx = double(mxx[i]) - ux * ux;
		const double vy = double(myy[i]) - uy * uy;
		const double cxy = double(mxy[i]) - ux * uy;
		const double num = (2.0 * ux * uy + c1) * (2.0 * cxy + c2);
		const double den = (ux * ux + uy * uy + c1) * (vx + vy + c2);
		const double s = num / den;
		if (r_map) {
			(*r_map)[i] = float(s);
		}
		total += s;
	}
	return float(total / double(count));
}
