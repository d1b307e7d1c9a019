/**************************************************************************/
/*  flip.h                                                                */
/**************************************************************************/
/* godot-area: the FLIP image difference evaluator, written from the      */
/* description in Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom,  */
/* Fairchild, "FLIP: A Difference Evaluator for Alternating Images",      */
/* Proc. ACM Comput. Graph. Interact. Tech. 3(2) (HPG 2020).              */
/*                                                                        */
/* LDR-FLIP gives a per-pixel perceived difference in [0, 1] between a    */
/* reference and a test image seen at a given number of pixels per degree */
/* of visual angle (PPD). Pipeline (constants documented in flip.cpp):    */
/*   colour: linear RGB -> YCxCz -> per-channel CSF Gaussian filter ->    */
/*           linear RGB, clamp -> L*a*b* -> Hunt adjustment -> HyAB       */
/*           distance ^ 0.7 -> map to [0, 1] with cmax, pc, pt -> dEc     */
/*   feature: achromatic channel -> edge (1st Gaussian derivative) and    */
/*           point (2nd derivative) magnitudes ->                         */
/*           dEf = (max difference / sqrt(2)) ^ 0.5                       */
/*   final:  dE = dEc ^ (1 - dEf)                                         */
/*                                                                        */
/* Our LDR input convention: the images hold scene-linear RGB; each       */
/* channel is clamped to [0, 1] and used as the paper's linear RGB (the   */
/* paper decodes sRGB files to linear first; we skip that step because    */
/* our images are linear already). Alpha is ignored.                      */
/*                                                                        */
/* HDR-FLIP (Andersson et al., "Visualizing Errors in Rendered High       */
/* Dynamic Range Images", Eurographics 2021 short paper): LDR-FLIP of     */
/* exposure-bracketed, ACES-tonemapped copies (Narkowicz fit of 0.6 x),   */
/* per-pixel max over the exposures.                                      */
/* See compute_hdr.                                                       */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

#include <vector>

class FLIP {
public:
	// Pixels per degree for an observer 0.7 m from a 0.7 m wide monitor showing 3840 pixels across:
	// 0.7 * (3840 / 0.7) * pi / 180 = 67.02 (the default viewing condition of the FLIP paper).
	static constexpr float DEFAULT_PPD = 67.0206f;

	// Pixels per degree for a viewing distance and a monitor width (both in metres) and a horizontal
	// resolution: d * (px / w) * pi / 180 (small-angle approximation, as in the paper).
	static float compute_ppd(float p_distance_m, float p_monitor_width_m, float p_monitor_width_px);

	// Per-pixel LDR-FLIP of p_test against p_reference (same size, non-empty, finite). r_map receives
	// width * height values in [0, 1], top row first; r_mean (optional) the mean. False on bad input,
	// with the reason in r_error.
	static bool compute_ldr(const Image &p_test, const Image &p_reference, float p_ppd, std::vector<float> &r_map, float *r_mean = nullptr, String *r_error = nullptr);

	struct HDRExposures {
		float start_exposure = 0.0f; // Stops (the images are scaled by 2^exposure before tonemapping).
		float stop_exposure = 0.0f;
		int count = 0;
	};

	// HDR-FLIP: the exposure range is derived from the reference's luminance (see flip.cpp), the
	// per-pixel result is the max over the exposures of LDR-FLIP of the ACES-tonemapped images.
	// r_exposures (optional) reports the range used.
	static bool compute_hdr(const Image &p_test, const Image &p_reference, float p_ppd, std::vector<float> &r_map, float *r_mean = nullptr, HDRExposures *r_exposures = nullptr, String *r_error = nullptr);

	// LDR-FLIP on planar data: p_test_rgb / p_reference_rgb hold 3 floats per pixel (linear RGB,
	// already in [0, 1]). No validation beyond sizes; used by compute_ldr and compute_hdr.
	static void compute_ldr_rgb(const std::vector<float> &p_test_rgb, const std::vector<float> &p_reference_rgb, int p_width, int p_height, float p_ppd, std::vector<float> &r_map);
};
