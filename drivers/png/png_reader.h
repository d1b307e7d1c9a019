/**************************************************************************/
/*  png_reader.h                                                          */
/**************************************************************************/
/* godot-area: reads a PNG file into 8-bit RGBA bytes through libpng      */
/* (any PNG colour type is converted to RGBA; no colour-space change).    */
/* Used by tests and tools that check previews.                           */

#pragma once

#include "core/string/ustring.h"

#include <cstdint>
#include <vector>

class PNGReader {
public:
	// On success fills r_rgba8 with r_width * r_height * 4 bytes, top row first.
	static bool load(const String &p_path, std::vector<uint8_t> &r_rgba8, int &r_width, int &r_height, String *r_error = nullptr);
};
