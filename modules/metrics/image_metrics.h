/**************************************************************************/
/*  image_metrics.h                                                       */
/**************************************************************************/
/* godot-area: error metrics between a rendered image and a reference     */
/* (the `compare` CLI command). All metrics ignore alpha. Definitions:    */
/*   RMSE      sqrt(mean over pixels and R, G, B of (a - b)^2), linear.   */
/*   relMSE    mean over pixels and R, G, B of (a - b)^2 / (b^2 + 0.01),  */
/*             b = reference; eps = 1e-2 as common in rendering papers    */
/*             (keeps dark reference pixels from dominating).             */
/*   relRMSE   relative RMSE in radiance: sqrt(sum (a - b)^2 / sum b^2)   */
/*             over pixels and R, G, B (an energy-weighted error that no  */
/*             tone map flattens; black pixels of both add nothing, so    */
/*             it does not depend on how much background is in view).     */
/*   ratio     mean brightness ratio sum a / sum b over pixels and R, G,  */
/*             B (> 1: the image is too bright). Both are NaN (JSON null) */
/*             when the reference is black.                               */
/*   MAE       ISR thesis eq. (19): mean over the 3wh values of |a - b|.  */
/*   Pearson   ISR thesis eq. (20), population statistics, on luminance   */
/*             lum = 0.27 R + 0.67 G + 0.06 B (ISR eq. (17)) of linear    */
/*             values. Convention when a standard deviation is 0: 1 if    */
/*             the two luminance planes are identical, else 0.            */
/*   SSIM      Wang et al. 2004 (see ssim.h) on the eq. (17) luminance of */
/*             the sRGB-encoded (IEC 61966-2-1 OETF) values of each       */
/*             channel clamped to [0, 1].                                 */
/*   FLIP      mean LDR-FLIP (flip.h) of the linear values clamped to     */
/*             [0, 1] (our LDR input); its per-pixel map is the heatmap.  */
/*   HDR-FLIP  optional, mean HDR-FLIP (flip.h) of the linear values.     */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"
#include "modules/metrics/flip.h"

#include <vector>

class ImageMetrics {
public:
	static constexpr double RELATIVE_MSE_EPSILON = 1e-2;

	struct Options {
		float ppd = FLIP::DEFAULT_PPD; // Pixels per degree for FLIP.
		bool hdr_flip = true; // Also compute HDR-FLIP (costs one LDR-FLIP per exposure).
	};

	struct Result {
		int width = 0;
		int height = 0;
		double rmse = 0.0;
		double relative_mse = 0.0;
		double relative_rmse = 0.0; // sqrt(sum (a - b)^2 / sum b^2); NaN if the reference is black.
		double brightness_ratio = 1.0; // sum a / sum b; NaN if the reference is black.
		double mae = 0.0;
		double pearson = 1.0;
		double ssim = 1.0;
		double flip = 0.0; // Mean LDR-FLIP.
		bool has_hdr_flip = false;
		double hdr_flip = 0.0; // Mean HDR-FLIP (when has_hdr_flip).
		FLIP::HDRExposures hdr_exposures;
		float ppd = FLIP::DEFAULT_PPD;
		std::vector<float> flip_map; // Per-pixel LDR-FLIP in [0, 1], width * height, top row first.
		std::vector<float> hdr_flip_map; // Per-pixel HDR-FLIP (empty unless has_hdr_flip).

		// One JSON object: {"width":..,"height":..,"rmse":..,"relative_mse":..,"mae":..,"pearson":..,
		// "ssim":..,"flip":..,"ppd":..[,"hdr_flip":..,"hdr_flip_exposures":{"start":..,"stop":..,"count":..}]}
		String to_json() const;
		// Human-readable, one metric per line.
		String to_text() const;
	};

	// p_image is compared against p_reference (they play different roles only in relMSE). Fails, with
	// a message naming the problem in r_error, on empty images, mismatched sizes or non-finite pixels.
	static bool compare(const Image &p_image, const Image &p_reference, Result *r_result, String *r_error, const Options &p_options);
	static bool compare(const Image &p_image, const Image &p_reference, Result *r_result, String *r_error = nullptr); // Default Options.

	// Loads two files (.exr through OpenEXR, .png as sRGB-encoded 8-bit decoded to linear) and compares
	// them. If p_heatmap_path is not empty, also writes the per-pixel LDR-FLIP as a false-colour PNG
	// (see heatmap.h; scale 0..1).
	static bool compare_files(const String &p_image_path, const String &p_reference_path, Result *r_result, String *r_error, const Options &p_options, const String &p_heatmap_path = String());

	// Loads an .exr or .png file into a linear image (helper of compare_files).
	static bool load_image(const String &p_path, Image &r_image, String *r_error = nullptr);

	// ISR eq. (17) luminance.
	static float luminance(float p_r, float p_g, float p_b) { return 0.27f * p_r + 0.67f * p_g + 0.06f * p_b; }
};
