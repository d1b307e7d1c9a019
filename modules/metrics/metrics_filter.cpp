/**************************************************************************/
/*  metrics_filter.cpp                                                    */
/**************************************************************************/
/* godot-area: separable 2D filtering for the image metrics.              */

#include "modules/metrics/metrics_filter.h"

#include <algorithm>
#include <cmath>

void MetricsFilter::filter_separable(const std::vector<float> &p_src, int p_width, int p_height, const std::vector<float> &p_kernel_x, const std::vector<float> &p_kernel_y, std::vector<float> &r_dst) {
	r_dst.clear();
	if (p_width <= 0 || p_height <= 0 || p_src.size() != (size_t)p_width * (size_t)p_height) {
		return;
	}
	if (p_kernel_x.size() % 2 == 0 || p_kernel_y.size() % 2 == 0) {
		return;
	}
	const int rx = int(p_kernel_x.size() / 2);
	const int ry = int(p_kernel_y.size() / 2);
	std::vector<float> tmp((size_t)p_width * p_height);
	// Horizontal pass.
	for (int y = 0; y < p_height; y++) {
		const float *row = &p_src[(size_t)y * p_width];
		float *out = &tmp[(size_t)y * p_width];
		for (int x = 0; x < p_width; x++) {
			double sum = 0.0;
			for (int i = -rx; i <= rx; i++) {
				const int sx = std::clamp(x + i, 0, p_width - 1);
				sum += double(p_kernel_x[i + rx]) * row[sx];
			}
			out[x] = float(sum);
		}
	}
	// Vertical pass.
	r_dst.resize((size_t)p_width * p_height);
	for (int y = 0; y < p_height; y++) {
		float *out = &r_dst[(size_t)y * p_width];
		for (int x = 0; x < p_width; x++) {
			double sum = 0.0;
			for (int j = -ry; j <= ry; j++) {
				const int sy = std::clamp(y + j, 0, p_height - 1);
				sum += double(p_kernel_y[j + ry]) * tmp[(size_t)sy * p_width + x];
			}
			out[x] = float(sum);
		}
	}
}

void MetricsFilter::blur_truncated(const std::vector<float> &p_src, int p_width, int p_height, const std::vector<float> &p_kernel, std::vector<float> &r_dst) {
	r_dst.clear();
	if (p_width <= 0 || p_height <= 0 || p_src.size() != (size_t)p_width * (size_t)p_height || p_kernel.size() % 2 == 0) {
		return;
	}
	const int r = int(p_kernel.size() / 2);
	std::vector<float> tmp((size_t)p_width * p_height);
	for (int y = 0; y < p_height; y++) {
		const float *row = &p_src[(size_t)y * p_width];
		float *out = &tmp[(size_t)y * p_width];
		for (int x = 0; x < p_width; x++) {
			double sum = 0.0;
			double weight = 0.0;
			const int i0 = std::max(-r, -x);
			const int i1 = std::min(r, p_width - 1 - x);
			for (int i = i0; i <= i1; i++) {
				sum += double(p_kernel[i + r]) * row[x + i];
				weight += p_kernel[i + r];
			}
			out[x] = weight > 0.0 ? float(sum / weight) : row[x];
		}
	}
	r_dst.resize((size_t)p_width * p_height);
	for (int y = 0; y < p_height; y++) {
		const int j0 = std::max(-r, -y);
		const int j1 = std::min(r, p_height - 1 - y);
		float *out = &r_dst[(size_t)y * p_width];
		for (int x = 0; x < p_width; x++) {
			double sum = 0.0;
			double weight = 0.0;
			for (int j = j0; j <= j1; j++) {
				sum += double(p_kernel[j + r]) * tmp[(size_t)(y + j) * p_width + x];
				weight += p_kernel[j + r];
			}
			out[x] = weight > 0.0 ? float(sum / weight) : tmp[(size_t)y * p_width + x];
		}
	}
}

std::vector<float> MetricsFilter::gaussian_1d(float p_sigma, int p_radius) {
	const int radius = std::max(0, p_radius);
	std::vector<float> kernel((size_t)(2 * radius + 1));
	const double s = std::max(1e-6, double(p_sigma));
	for (int i = -radius; i <= radius; i++) {
		kernel[i + radius] = float(std::exp(-double(i) * i / (2.0 * s * s)));
	}
	return kernel;
}
