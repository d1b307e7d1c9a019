/**************************************************************************/
/*  apng_writer.h                                                         */
/**************************************************************************/
/* godot-area: animated PNG (APNG) files from 8-bit frames, for the       */
/* README's camera-path animation (render --frames N --path ... --apng). */
/* Each frame is compressed by PNGWriter (libpng); this file only re-     */
/* wraps the frames' IDAT data as APNG chunks (APNG specification 1.0:    */
/* acTL, fcTL, fdAT), so any PNG viewer shows frame 0 and browsers play   */
/* the animation. Every frame covers the whole canvas (no sub-rectangle  */
/* or blending), so the file is as large as the frames' PNGs together.   */

#pragma once

#include "core/string/ustring.h"

#include <cstdint>
#include <vector>

class APNGWriter {
public:
	// p_frames: each p_width * p_height * 4 bytes of sRGB-encoded RGBA, top row first; written as opaque
	// 8-bit RGB. Each frame is shown p_delay_ms milliseconds; the animation loops forever. Written
	// atomically (no partial file on failure).
	static bool save_rgba8(const std::vector<std::vector<uint8_t>> &p_frames, int p_width, int p_height, int p_delay_ms, const String &p_path, String *r_error = nullptr);
};
