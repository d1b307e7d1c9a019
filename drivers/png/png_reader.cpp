/**************************************************************************/
/*  png_reader.cpp                                                        */
/**************************************************************************/
/* godot-area: PNG reader to 8-bit RGBA (libpng simplified API).          */

#include "drivers/png/png_reader.h"

#include "core/error/error_macros.h"
#include "core/io/image.h"

#include <png.h>

#include <cstring>
#include <filesystem>

static bool _png_read_fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

bool PNGReader::load(const String &p_path, std::vector<uint8_t> &r_rgba8, int &r_width, int &r_height, String *r_error) {
	r_rgba8.clear();
	r_width = 0;
	r_height = 0;
	std::error_code ec;
	if (p_path.empty() || !std::filesystem::is_regular_file(p_path, ec)) {
		return _png_read_fail(r_error, vformat("Cannot read PNG \"%s\": file not found.", p_path.c_str()));
	}

	png_image image;
	std::memset(&image, 0, sizeof(image));
	image.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&image, p_path.c_str())) {
		const String reason = image.message[0] ? String(image.message) : String("unknown error");
		png_image_free(&image);
		return _png_read_fail(r_error, vformat("Cannot read PNG \"%s\": not a valid PNG file (libpng: %s).", p_path.c_str(), reason.c_str()));
	}
	if (image.width == 0 || image.height == 0 || image.width > (png_uint_32)Image::MAX_SIZE || image.height > (png_uint_32)Image::MAX_SIZE) {
		const String message = vformat("Cannot read PNG \"%s\": unsupported size %ux%u.", p_path.c_str(), (unsigned)image.width, (unsigned)image.height);
		png_image_free(&image);
		return _png_read_fail(r_error, message);
	}
	image.format = PNG_FORMAT_RGBA;
	std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(image));
	if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) {
		const String reason = image.message[0] ? String(image.message) : String("unknown error");
		png_image_free(&image);
		return _png_read_fail(r_error, vformat("Cannot read PNG \"%s\": corrupt or truncated pixel data (libpng: %s).", p_path.c_str(), reason.c_str()));
	}
	r_width = (int)image.width;
	r_height = (int)image.height;
	r_rgba8 = std::move(pixels);
	png_image_free(&image);
	return true;
}
