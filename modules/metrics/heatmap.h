/**************************************************************************/
/*  heatmap.h                                                             */
/**************************************************************************/
/* godot-area: false-colour PNG of a per-pixel error map. The colour map  */
/* is "magma-like" (black -> purple -> red-magenta -> orange -> pale      */
/* yellow, the kind of map the FLIP paper uses for its error images): a   */
/* piecewise-linear ramp through six sRGB key colours picked by eye to    */
/* resemble matplotlib's magma; it is our own approximation, not the      */
/* published table, and is monotonically increasing in lightness.         */

#pragma once

#include "core/math/color.h"
#include "core/string/ustring.h"

#include <vector>

class Heatmap {
public:
	// sRGB-encoded colour (components in [0, 1], alpha 1) for p_t in [0, 1]; p_t is clamped, NaN maps to 0.
	static Color map(float p_t);

	// Writes p_width x p_height values (top row first) as an RGBA8 PNG, value / p_max_value mapped
	// through map(). p_max_value must be positive and finite. False (with r_error) on bad input or
	// when the file cannot be written.
	static bool write_png(const std::vector<float> &p_per_pixel_error, int p_width, int p_height, float p_max_value, const String &p_path, String *r_error = nullptr);
};
