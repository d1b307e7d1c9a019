/**************************************************************************/
/*  tonemap.h                                                             */
/**************************************************************************/
/* godot-area: the preview tonemap that turns a scene-linear HDR Image    */
/* into 8-bit sRGB RGBA bytes (for PNG previews only; EXR keeps the raw   */
/* linear values). Per colour channel, in this order:                     */
/*   1. exposure:  x *= 2^exposure_ev   (stops; 0 leaves values as-is)    */
/*   2. curve:     MODE_ACES_FITTED (default) — Narkowicz 2015, "ACES     */
/*                 Filmic Tone Mapping Curve":                            */
/*                   f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14)    */
/*                 applied per channel, clamped to [0, 1]; f(0) = 0 and  */
/*                 f is monotonically increasing for x >= 0. Note it     */
/*                 already includes the ~0.6 exposure bias of the fit.   */
/*                 MODE_LINEAR — clamp to [0, 1] only (no curve).         */
/*   3. sRGB OETF (IEC 61966-2-1), then round(v * 255).                   */
/* Negative values and NaN become 0, +infinity becomes 255. Alpha is      */
/* clamped to [0, 1] and scaled to 0..255 without exposure, curve or      */
/* OETF. No dithering.                                                    */

#pragma once

#include "core/io/image.h"

#include <cstdint>
#include <vector>

class Tonemap {
public:
	enum Mode {
		MODE_LINEAR,
		MODE_ACES_FITTED,
		MODE_MAX,
	};

	// Scalar building blocks, exposed for tests and for other tools.
	static float aces_fitted(float p_x); // Input >= 0 expected; output in [0, 1].
	static float linear_to_srgb(float p_x); // Input in [0, 1].
	// Steps 1-3 for one colour channel.
	static uint8_t map_channel(float p_linear, float p_exposure_ev, Mode p_mode = MODE_ACES_FITTED);
	static uint8_t map_alpha(float p_alpha);

	// Returns width * height * 4 bytes (RGBA, top row first); empty if the image is empty.
	static std::vector<uint8_t> apply(const Image &p_hdr, float p_exposure_ev = 0.0f, Mode p_mode = MODE_ACES_FITTED);
};
