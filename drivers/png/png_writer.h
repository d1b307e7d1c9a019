/**************************************************************************/
/*  png_writer.h                                                          */
/**************************************************************************/
/* godot-area: writes 8-bit RGBA PNG files through libpng (previews).     */
/* The bytes are written as given and are meant to be sRGB-encoded; the   */
/* Image overload encodes scene-linear values with Tonemap (linear clamp  */
/* by default, so linear 0.5 becomes 188).                                */

#pragma once

#include "core/io/image.h"
#include "core/io/tonemap.h"
#include "core/string/ustring.h"

#include <cstdint>
#include <vector>

class PNGWriter {
public:
	// p_rgba8: p_width * p_height * 4 bytes, sRGB-encoded RGBA, top row first.
	// Encodes to PNG bytes in memory (8-bit RGBA, or RGB with p_drop_alpha). p_path only names the file in errors.
	static bool encode_rgba8(const std::vector<uint8_t> &p_rgba8, int p_width, int p_height, std::vector<uint8_t> &r_png, String *r_error = nullptr, bool p_drop_alpha = false, const String &p_path = String());
	static bool save_rgba8(const std::vector<uint8_t> &p_rgba8, int p_width, int p_height, const String &p_path, String *r_error = nullptr);
	// Encodes a scene-linear image with Tonemap::apply(p_image, p_exposure_ev, p_mode), then saves it.
	static bool save(const Image &p_image, const String &p_path, String *r_error = nullptr, float p_exposure_ev = 0.0f, Tonemap::Mode p_mode = Tonemap::MODE_LINEAR);
	// The same with Godot's tonemap settings (an Environment's tonemap_mode/_exposure/_white).
	static bool save(const Image &p_image, const String &p_path, String *r_error, float p_exposure_ev, const Tonemap::Settings &p_tonemap);
};
