/**************************************************************************/
/*  image_saver_exr.h                                                     */
/**************************************************************************/
/* godot-area: writes an Image as a scene-linear OpenEXR file (channels   */
/* R, G, B, A; HALF or FLOAT; ZIP compression, lossless). No colour       */
/* transform is applied, so values round-trip as stored (thesis §5.5).    */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

class ImageSaverEXR {
public:
	// p_half: store 16-bit half floats (values beyond +-65504 become infinity) instead of
	// 32-bit floats. Returns false and fills r_error (naming the file) on any failure.
	static bool save(const Image &p_image, const String &p_path, bool p_half = false, String *r_error = nullptr);
};
