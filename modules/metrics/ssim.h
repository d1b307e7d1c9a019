/**************************************************************************/
/*  ssim.h                                                                */
/**************************************************************************/
/* godot-area: structural similarity (SSIM) of two single-channel planes, */
/* after Wang, Bovik, Sheikh, Simoncelli, "Image Quality Assessment: From */
/* Error Visibility to Structural Similarity", IEEE TIP 13(4), 2004:      */
/*   SSIM = (2 mx my + C1)(2 sxy + C2)                                    */
/*          / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2))                      */
/* with local statistics from an 11x11 Gaussian window of sigma 1.5,      */
/* C1 = (K1 L)^2, C2 = (K2 L)^2, K1 = 0.01, K2 = 0.03, L = 1 (the paper's */
/* recommended values; inputs are expected in [0, 1]).                    */
/* Borders: the window is truncated at the image edge and renormalised,   */
/* so every pixel gets a value (the paper's code instead drops the        */
/* 5-pixel border); the reported SSIM is the mean over all pixels.        */

#pragma once

#include <vector>

class SSIM {
public:
	static constexpr float K1 = 0.01f;
	static constexpr float K2 = 0.03f;
	static constexpr float DYNAMIC_RANGE = 1.0f; // L.
	static constexpr float WINDOW_SIGMA = 1.5f;
	static constexpr int WINDOW_RADIUS = 5; // 11x11 window.

	// Mean SSIM of two planes of p_width * p_height values (identical planes give exactly 1).
	// Returns NaN (and prints an error) when the plane sizes do not match the dimensions.
	// If r_map is given it receives the per-pixel SSIM.
	static float compute(const std::vector<float> &p_x, const std::vector<float> &p_y, int p_width, int p_height, std::vector<float> *r_map = nullptr);
};
