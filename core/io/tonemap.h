/**************************************************************************/
/*  tonemap.h                                                             */
/**************************************************************************/
/* godot-area: tonemapping of a scene-linear HDR Image into 8-bit sRGB    */
/* RGBA bytes (PNG previews and the editor viewport only; EXR keeps the   */
/* raw linear values). Per pixel, in this order:                          */
/*   1. exposure:  rgb *= exposure * 2^exposure_ev (tonemap_exposure of   */
/*      the Environment, a multiplier, times the preview's --exposure EV); */
/*   2. curve (Godot 4's Environment.tonemap_mode, published formulas):   */
/*      MODE_LINEAR     clamp to [0, 1] (tonemap_white unused);           */
/*      MODE_REINHARD   Reinhard et al. 2002 eq. 4 with white point w:    */
/*                      f(x) = x (1 + x / w^2) / (1 + x);                 */
/*      MODE_FILMIC     Hable 2010 ("Uncharted 2") curve                  */
/*                      h(x) = (x(Ax + CB) + DE) / (x(Ax + B) + DF) - E/F,*/
/*                      A .22 B .30 C .10 D .20 E .01 F .30, with Godot's */
/*                      exposure bias 2 on x and w: f = h(2x) / h(2w);   */
/*      MODE_ACES       Hill's fit of the ACES RRT + ODT (the sRGB->RRT  */
/*                      matrix, rational (x(x+a)-b)/(x(cx+d)+e) with      */
/*                      a .0245786 b .000090537 c .983729 d .432951      */
/*                      e .238081, ODT->sRGB matrix), Godot's bias 1.8,   */
/*                      divided by the curve at the white point;          */
/*      MODE_AGX        Sobotka's AgX as fitted by Wrensch 2023 ("Minimal */
/*                      AgX"): inset matrix, log2 in [-12.47393,          */
/*                      4.026069] EV, 6th order polynomial, inverse       */
/*                      matrix, display gamma 2.2 undone (tonemap_white   */
/*                      unused, as in Godot 4.4);                         */
/*      MODE_ACES_FITTED Narkowicz 2015 x(2.51x + .03)/(x(2.43x + .59) +  */
/*                      .14): the preview curve of scenes without an      */
/*                      Environment (a godot-area choice, not Godot's).   */
/*      Every result is clamped to [0, 1] per channel.                    */
/*   3. sRGB OETF (IEC 61966-2-1), then round(v * 255).                   */
/* Negative values and NaN become 0, +infinity the curve's limit. Alpha  */
/* is clamped to [0, 1] and scaled to 0..255 without steps 1-3.          */

#pragma once

#include "core/io/image.h"

#include <cstdint>
#include <vector>

class Tonemap {
public:
	enum Mode {
		MODE_LINEAR,
		MODE_ACES_FITTED,
		MODE_REINHARD,
		MODE_FILMIC,
		MODE_ACES,
		MODE_AGX,
		MODE_MAX,
	};

	// Godot's Environment tonemap parameters (defaults as Godot's: Linear, exposure 1, white 1).
	struct Settings {
		Mode mode = MODE_LINEAR;
		float exposure = 1.0f; // tonemap_exposure, a multiplier (> 0).
		float white = 1.0f; // tonemap_white (Reinhard, Filmic, ACES), > 0.
	};

	// Godot's Environment.tonemap_mode values (0 Linear, 1 Reinhard, 2 Filmic, 3 ACES, 4 AgX) -> Mode.
	// Returns false for any other value.
	static bool mode_from_godot(int p_tonemap_mode, Mode &r_mode);

	// Scalar building blocks, exposed for tests and other tools. Inputs >= 0 expected.
	static float aces_fitted(float p_x); // Output in [0, 1].
	static float reinhard(float p_x, float p_white);
	static float filmic(float p_x, float p_white);
	// Cross-channel curves (in place, linear sRGB primaries).
	static void aces(float *r_rgb, float p_white);
	static void agx(float *r_rgb);
	static float linear_to_srgb(float p_x); // Input in [0, 1].
	// Steps 1-2 for one pixel: exposure and curve, clamped to [0, 1] (display-linear).
	static void map_linear(float *r_rgb, const Settings &p_settings, float p_exposure_ev = 0.0f);
	// Steps 1-3 for one colour channel of a per-channel mode (LINEAR, ACES_FITTED, REINHARD, FILMIC).
	static uint8_t map_channel(float p_linear, float p_exposure_ev, Mode p_mode = MODE_ACES_FITTED);
	static uint8_t map_alpha(float p_alpha);

	// Returns width * height * 4 bytes (RGBA, top row first); empty if the image is empty.
	static std::vector<uint8_t> apply(const Image &p_hdr, float p_exposure_ev = 0.0f, Mode p_mode = MODE_ACES_FITTED);
	static std::vector<uint8_t> apply(const Image &p_hdr, const Settings &p_settings, float p_exposure_ev = 0.0f);
};
