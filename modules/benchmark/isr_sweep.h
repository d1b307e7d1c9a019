/**************************************************************************/
/*  isr_sweep.h                                                           */
/**************************************************************************/
/* godot-area: the image-space radiosity evaluation of the seed (003,     */
/* §3.3-3.4, §5): for one frame, three images of the same view -- direct  */
/* only (I_DL), ISR (I_ISR) from the Forward+ renderer with SSIL on, and  */
/* the one-bounce truth (I_POV) from the Embree reference with bounces 1  */
/* -- and their comparison: mean error delta (eq. 19) and Pearson         */
/* correlation (eq. 20, on eq. 17 luminance) through modules/metrics, the */
/* quality function f_q (eq. 21), the mean-error gain                     */
/* (delta_DL - delta_ISR) / delta_DL, and the share of the pixels that    */
/* receive indirect light on which ISR is closer to the truth (§5.3.2:    */
/* 99.05 % in the seed). bench --sweep isr (isr_sweep_command.h) runs it  */
/* over camera paths and times the pass.                                  */

#pragma once

#include "modules/benchmark/isr_sweep_scenes.h"
#include "modules/reference/reference_renderer.h"

#include <vector>

struct IsrImages {
	int width = 0;
	int height = 0;
	std::vector<float> direct; // RGBA floats, top row first.
	std::vector<float> isr;
	std::vector<float> truth;
};

struct IsrQuality {
	double mean_error_dl = 0.0; // Eq. 19, delta(I_POV, I_DL).
	double mean_error_isr = 0.0; // Eq. 19, delta(I_POV, I_ISR).
	double mean_error_gain = 0.0; // (delta_DL - delta_ISR) / delta_DL.
	double pearson_dl = 0.0; // Eq. 20 (luminance) of I_DL against I_POV.
	double pearson_isr = 0.0;
	int quality = 0; // Eq. 21, f_q(I_POV, I_ISR, I_DL): 1 = ISR closer, -1 = DL closer.
	int indirect_pixels = 0; // Pixels whose truth exceeds direct by more than the threshold.
	int improved_pixels = 0; // Of those, the ones where ISR is closer (eq. 19 per pixel).
	double improved_share = 0.0; // improved_pixels / indirect_pixels.
};

class IsrSweep {
public:
	// A pixel "receives indirect light" when lum(truth) - lum(direct) exceeds this share of lum(truth)
	// plus INDIRECT_ABSOLUTE (the reference's noise floor at the test's sample counts).
	static constexpr double INDIRECT_RELATIVE = 0.05;
	static constexpr double INDIRECT_ABSOLUTE = 1e-3;

	// SSIL settings of the evaluation: Godot's defaults, SSAO off (no ambient in the scenes).
	static ScreenSpaceLightingSettings default_settings();

	// Direct-only and ISR images of frame p_frame from the Forward+ renderer (one renderer, the two
	// interleaved). False with r_error if the GPU is missing or rendering fails.
	static bool render_gpu(const IsrScene &p_scene, int p_frame, int p_width, int p_height, const ScreenSpaceLightingSettings &p_settings, IsrImages &r_images, String *r_error);
	// The one-bounce truth of the same frame (Embree reference, bounces 1, shadows off as the GPU).
	static bool render_truth(const IsrScene &p_scene, int p_frame, int p_width, int p_height, const ReferenceRenderOptions &p_options, IsrImages &r_images, String *r_error);
	// Reference options of the evaluation (bounces 1; p_bounce_samples rays per pixel).
	static ReferenceRenderOptions truth_options(int p_bounce_samples);

	static bool evaluate(const IsrImages &p_images, IsrQuality &r_quality, String *r_error);
};
