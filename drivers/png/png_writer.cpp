/**************************************************************************/
/*  png_writer.cpp                                                        */
/**************************************************************************/
/* godot-area: 8-bit RGBA PNG writer (libpng simplified API).             */

#include "drivers/png/png_writer.h"
#include "core/io/file_io.h"

#include "core/error/error_macros.h"

#include <png.h>

#include <cstring>

static bool _png_write_fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

bool PNGWriter::save_rgba8(const std::vector<uint8_t> &p_rgba8, int p_width, int p_height, const String &p_path, String *r_error) {
	if (p_path.empty()) {
		return _png_write_fail(r_error, "Cannot write PNG: the file path is empty.");
	}
	if (p_width <= 0 || p_height <= 0) {
		return _png_write_fail(r_error, vformat("Cannot write PNG \"%s\": image size %dx%d is empty or negative.", p_path.c_str(), p_width, p_height));
	}
	const size_t expected = (size_t)p_width * (size_t)p_height * 4;
	if (p_rgba8.size() != expected) {
		return _png_write_fail(r_error, vformat("Cannot write PNG \"%s\": %dx%d RGBA needs %zu bytes, got %zu.", p_path.c_str(), p_width, p_height, expected, p_rgba8.size()));
	}

	png_image image;
	std::memset(&image, 0, sizeof(image));
	image.version = PNG_IMAGE_VERSION;
	image.width = (png_uint_32)p_width;
	image.height = (png_uint_32)p_height;
	image.format = PNG_FORMAT_RGBA; // 8-bit, sRGB-encoded.
	// Encoded in memory, then written atomically (core/io/file_io.h): a failed write leaves no partial PNG.
	png_alloc_size_t size = 0;
	int ok = png_image_write_get_memory_size(image, size, 0, p_rgba8.data(), 0, nullptr);
	std::vector<uint8_t> encoded;
	if (ok) {
		encoded.resize(size);
		ok = png_image_write_to_memory(&image, encoded.data(), &size, 0, p_rgba8.data(), 0, nullptr);
	}
	if (!ok) {
		const String reason = image.message[0] ? String(image.message) : String("unknown libpng error");
		png_image_free(&image);
		return _png_write_fail(r_error, vformat("Cannot write PNG \"%s\": %s.", p_path.c_str(), reason.c_str()));
	}
	png_image_free(&image);
	String error;
	if (!file_write_atomic(p_path, encoded.data(), size, &error)) {
		return _png_write_fail(r_error, vformat("Cannot write PNG: %s", error.c_str()));
	}
	return true;
}

bool PNGWriter::save(const Image &p_image, const String &p_path, String *r_error, float p_exposure_ev, Tonemap::Mode p_mode) {
	Tonemap::Settings settings;
	settings.mode = p_mode;
	return save(p_image, p_path, r_error, p_exposure_ev, settings);
}

bool PNGWriter::save(const Image &p_image, const String &p_path, String *r_error, float p_exposure_ev, const Tonemap::Settings &p_tonemap) {
	if (p_image.is_empty()) {
		return _png_write_fail(r_error, vformat("Cannot write PNG \"%s\": the image is empty.", p_path.c_str()));
	}
	const std::vector<uint8_t> bytes = Tonemap::apply(p_image, p_tonemap, p_exposure_ev);
	if (bytes.empty()) {
		return _png_write_fail(r_error, vformat("Cannot write PNG \"%s\": tonemapping failed.", p_path.c_str()));
	}
	return save_rgba8(bytes, p_image.get_width(), p_image.get_height(), p_path, r_error);
}
