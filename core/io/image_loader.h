/**************************************************************************/
/*  image_loader.h                                                        */
/**************************************************************************/
/* godot-area: reads image files for textures, by extension, through      */
/* Debian-packaged libraries: PNG with libpng (drivers/png), JPEG, BMP,   */
/* TGA and Radiance HDR with stb_image (libstb-dev), WebP (lossy and     */
/* lossless) with libwebp, OpenEXR with OpenEXR (modules/openexr).        */
/* 8-bit files give texels/255 as stored                                  */
/* (colour textures stay sRGB-encoded; the renderer decodes them), HDR    */
/* and EXR give their linear floats.                                      */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

#include <vector>

class ImageLoader {
public:
	// Extensions (lower case, no dot) load_image() reads.
	static const std::vector<String> &get_recognized_extensions();
	static bool recognizes(const String &p_extension);
	// Returns false with r_error naming the file on a missing, corrupt or unsupported file.
	static bool load_image(const String &p_path, Image &r_image, String *r_error = nullptr);
};
