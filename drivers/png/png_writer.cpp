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

bool PNGWriter::encode_rgba8(const std::vector<uint8_t> &p_rgba8, int p_width, int p_height, std::vector<uint8_t> &r_png, String *r_error, bool p_drop_alpha, const String &p_path) {
	const String name = p_path.empty() ? String("PNG") : vformat("PNG \"%s\"", p_path.c_str());
	if (p_width <= 0 || p_height <= 0) {
		return _png_write_fail(r_error, vformat("Cannot write %s: image size %dx%d is empty or negative.", name.c_str(), p_width, p_height));
	}
	const size_t expected = (size_t)p_width * (size_t)p_height * 4;
	if (p_rgba8.size() != expected) {
		return _png_write_fail(r_error, vformat("Cannot write %s: %dx%d RGBA needs %zu bytes, got %zu.", name.c_str(), p_width, p_height, expected, p_rgba8.size()));
	}

	png_image image;
	std::memset(&image, 0, sizeof(image));
	image.version = PNG_IMAGE_VERSION;
	image.width = (png_uint_32)p_width;
	image.height = (png_uint_32)p_height;
	image.format = PNG_FORMAT_RGBA; // 8-bit, sRGB-encoded.
	std::vector<uint8_t> rgb;
	const uint8_t *pixels = p_rgba8.data();
	if (p_drop_alpha) {
		image.format = PNG_FORMAT_RGB;
		rgb.resize((size_t)p_width * (size_t)p_height * 3);
		for (size_t i = 0, n = (size_t)p_width * (size_t)p_height; i < n; i++) {
			std::memcpy(&rgb[i * 3], &p_rgba8[i * 4], 3);
		}
		pixels = rgb.data();
	}
	png_alloc_size_t size = 0;
	int ok = png_image_write_get_memory_size(image, size, 0, pixels, 0, nullptr);
	if (ok) {
		r_png.resize(size);
		ok = png_image_write_to_memory(&image, r_png.data(), &size, 0, pixels, 0, nullptr);
		r_png.resize(size);
	}
	if (!ok) {
		const String reason = image.message[0] ? String(image.message) : String("unknown libpng error");
		png_image_free(&image);
		return _png_write_fail(r_error, vformat("Cannot write %s: %s.", name.c_str(), reason.c_str()));
	}
	png_image_free(&image);
	return true;
}

bool PNGWriter::save_rgba8(const std::vector<uint8_t> &p_rgba8, int p_width, int p_height, const String &p_path, String *r_error) {
	if (p_path.empty()) {
		return _png_write_fail(r_error, "Cannot write PNG: the file path is empty.");
	}
	// Encoded in memory, then written atomically (core/io/file_io.h): a failed write leaves no partial PNG.
	std::vector<uint8_t> encoded;
	if (!encode_rgba8(p_rgba8, p_width, p_height, encoded, r_error, false, p_path)) {
		return false;
	}
	String error;
	if (!file_write_atomic(p_path, encoded.data(), encoded.size(), &error)) {
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
