/**************************************************************************/
/*  image_loader_exr.h                                                    */
/**************************************************************************/
/* godot-area: reads a scanline or tiled OpenEXR file into an Image.      */
/* Channels R, G, B, A are read (HALF, FLOAT or UINT converted to float); */
/* a missing A reads as 1, a file with only Y (luminance) fills R, G, B   */
/* with Y, other missing colour channels read as 0. The data window is    */
/* read; its origin is dropped.                                           */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

class ImageLoaderEXR {
public:
	// Returns false and fills r_error (naming the file) for missing, corrupt or truncated
	// files; r_image is left empty then.
	static bool load(const String &p_path, Image &r_image, String *r_error = nullptr);
};
