/**************************************************************************/
/*  accuracy_ltc_terms.h                                                  */
/**************************************************************************/
/* godot-area: where the LTC error of an accuracy scene comes from        */
/* (issue #18, item "which part errs"). For a plane scene of the suite    */
/* (accuracy_scenes.h) every pixel's shading point is found by the same   */
/* pixel-centre ray as the engine and the reference, and the radiance of  */
/* the light is evaluated in double precision five ways, each changing    */
/* one approximation of area_light_ltc_inc.glsl:                          */
/*   T   truth: Lambert form factor + integral over the rectangle of      */
/*       f(v, l) F_Schlick(l.h) cos dl (midpoint rule over the light's    */
/*       area, brdf_inc.glsl's lobe; what the Embree reference estimates) */
/*   A1  Fresnel as LTC applies it: the exact lobe integral times         */
/*       (f0 fn + (f90 - f0) fg) / fn with exact fn, fg (thesis eq. 5.10) */
/*   A2  norm term of the LUT: the exact normalised lobe integral times   */
/*       the LUT's bilinear fn, fg                                        */
/*   A3  the shader (its C++ twin): LUT matrix filtered bilinearly,       */
/*       surface-horizon clip, M^-1, cosine clip, edge sum, LUT's F       */
/*       with thesis eq. 5.10's Fresnel (the shader before issue #18's    */
/*       polygon Fresnel)                                                 */
/*   A3n the same without the surface-horizon clip                        */
/*   A4  the shader as built: A3 with ltc_polygon_fresnel                 */
/*   A5  A4 with the Fresnel gap added whatever the coverage (the         */
/*       alternative that lost)                                           */
/*   A6  the two-lobe shader (LTC_2LOBE, ltc_lut_2lobe_data.inc): A4 with */
/*       two weighted lobes, each with its own polygon Fresnel            */
/* so relRMSE(A1, T) is the Fresnel error, (A2, A1) the LUT's fn/fg, (A3, */
/* A2) the lobe shape, (A3n, T) the total without the clip, and (A4, T)   */
/* the total, to compare with the suite's engine-vs-Embree number. The    */
/* lobe error is also split by the LUT cell each pixel reads (nearest     */
/* texel).                                                                */
/* Diffuse is the exact Lambert polygon integral in every variant (the    */
/* suite's materials are Lambert), so it only enters the denominators.   */

#pragma once

#include "modules/accuracy/accuracy_scenes.h"

#include <vector>

class AccuracyLTCTerms {
public:
	struct Cell {
		int roughness_index = 0;
		int angle_index = 0;
		double share = 0.0; // Of the summed squared lobe-shape error of the image.
	};

	struct Result {
		String scene_id;
		int pixels = 0; // Pixels that hit the plane and see the light.
		double total = 0.0; // relRMSE(A4, T): the shader as built.
		double total_ratio = 1.0; // sum A4 / sum T.
		double eq510 = 0.0; // relRMSE(A3, T): with thesis eq. 5.10's Fresnel.
		double eq510_ratio = 1.0;
		double fresnel = 0.0; // relRMSE(A1, T).
		double fresnel_ratio = 1.0;
		double norm = 0.0; // relRMSE(A2, A1).
		double norm_ratio = 1.0;
		double lobe = 0.0; // relRMSE(A3, A2).
		double lobe_ratio = 1.0;
		double no_clip = 0.0; // relRMSE(A3n, T).
		double no_clip_ratio = 1.0;
		double fresnel_alt = 0.0; // relRMSE(A5, T).
		double fresnel_alt_ratio = 1.0;
		double two_lobe = 0.0; // relRMSE(A6, T): the two-lobe shader (LTC_2LOBE).
		double two_lobe_ratio = 1.0;
		double truth_convergence = 0.0; // relRMSE of T at p_light_samples against T at half as many per axis.
		int angle_index_min = 0; // LUT rows (view angle) the pixels read.
		int angle_index_max = 0;
		std::vector<Cell> worst_cells; // Up to 3, by share of the lobe error.
	};

	// Evaluates p_scene (plane receivers and rectangle lights only: false otherwise, r_error set) at
	// p_resolution^2 pixels, integrating the truth with p_light_samples^2 midpoints over the light.
	// p_table: an engine LUT to read instead of the built-in one (LTC_LUT_SIZE^2 * 8 floats, e.g. a
	// candidate refit), or nullptr.
	static bool evaluate(const AccuracyScenes::Scene &p_scene, int p_resolution, int p_light_samples, Result *r_result, String *r_error, const std::vector<float> *p_table = nullptr);

	// One line per result: the five numbers and the cells.
	static String format(const Result &p_result);
};
