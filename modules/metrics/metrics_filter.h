/**************************************************************************/
/*  metrics_filter.h                                                      */
/**************************************************************************/
/* godot-area: separable 2D filtering of single-channel float planes, the */
/* building block of the SSIM and FLIP image metrics. Planes are stored   */
/* row by row, top row first, one float per pixel.                        */

#pragma once

#include <vector>

class MetricsFilter {
public:
	// Separable correlation: r_dst(x, y) = sum_ij kx[i] * ky[j] * src(x + i - rx, y + j - ry), where the
	// kernels have odd sizes 2 * rx + 1 and 2 * ry + 1 and are centred. Pixels outside the plane take the
	// value of the nearest edge pixel (clamp to edge). Kernels of even size are rejected (r_dst is cleared).
	static void filter_separable(const std::vector<float> &p_src, int p_width, int p_height, const std::vector<float> &p_kernel_x, const std::vector<float> &p_kernel_y, std::vector<float> &r_dst);

	// Separable smoothing with a non-negative kernel used in both directions. Taps that fall outside the
	// plane are dropped and the remaining weights renormalised to sum to 1 (so every output is a weighted
	// mean of in-image pixels only; used by SSIM for a window that shrinks at the borders).
	static void blur_truncated(const std::vector<float> &p_src, int p_width, int p_height, const std::vector<float> &p_kernel, std::vector<float> &r_dst);

	// Unnormalised 1D Gaussian exp(-x^2 / (2 sigma^2)) sampled at integer x in [-p_radius, p_radius].
	static std::vector<float> gaussian_1d(float p_sigma, int p_radius);
};
