/**************************************************************************/
/*  image_loader.cpp                                                      */
/**************************************************************************/

#include "core/io/image_loader.h"

#include "core/io/file_io.h"
#include "drivers/png/png_reader.h"
#include "modules/openexr/image_loader_exr.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

// The one stb_image implementation of the program (glTF's embedded images use it too).
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_PSD
#define STBI_NO_PIC
#define STBI_NO_PNM
#define STBI_NO_GIF
#include <stb/stb_image.h>
#include <webp/decode.h>

static String _ext_of(const String &p_path) {
	size_t dot = p_path.rfind('.');
	if (dot == String::npos) {
		return String();
	}
	String e = p_path.substr(dot + 1);
	std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return (char)tolower(c); });
	return e;
}

const std::vector<String> &ImageLoader::get_recognized_extensions() {
	static const std::vector<String> exts = { "png", "jpg", "jpeg", "bmp", "tga", "hdr", "webp", "exr" };
	return exts;
}

bool ImageLoader::recognizes(const String &p_extension) {
	const std::vector<String> &e = get_recognized_extensions();
	return std::find(e.begin(), e.end(), p_extension) != e.end();
}

static bool _from_rgba8(const uint8_t *p_data, int p_w, int p_h, Image &r_image) {
	std::vector<float> f((size_t)p_w * p_h * 4);
	for (size_t i = 0; i < f.size(); i++) {
		f[i] = p_data[i] / 255.0f;
	}
	return r_image.set_data(p_w, p_h, f);
}

// WebP (Godot's default lossy/lossless import format) through libwebp: the file is read with the
// 256 MiB bound, its header checked against Image::MAX_SIZE before decoding.
static bool _load_webp(const String &p_path, Image &r_image, String *r_error) {
	String bytes;
	if (!file_read_bounded(p_path, bytes, r_error)) {
		return false;
	}
	const uint8_t *data = reinterpret_cast<const uint8_t *>(bytes.data());
	int w = 0, h = 0;
	if (!WebPGetInfo(data, bytes.size(), &w, &h)) {
		*r_error = vformat("%s: not a WebP image (bad RIFF/WEBP header).", p_path.c_str());
		return false;
	}
	if (w <= 0 || h <= 0 || w > Image::MAX_SIZE || h > Image::MAX_SIZE) {
		*r_error = vformat("%s: the WebP image is %dx%d; sizes must be 1..%d.", p_path.c_str(), w, h, Image::MAX_SIZE);
		return false;
	}
	std::vector<uint8_t> rgba(size_t(w) * h * 4);
	if (!WebPDecodeRGBAInto(data, bytes.size(), rgba.data(), rgba.size(), w * 4)) {
		*r_error = vformat("%s: cannot decode the WebP image (truncated or corrupt).", p_path.c_str());
		return false;
	}
	return _from_rgba8(rgba.data(), w, h, r_image);
}

bool ImageLoader::load_image(const String &p_path, Image &r_image, String *r_error) {
	r_image.clear();
	String ext = _ext_of(p_path);
	String err;
	bool ok = false;
	std::error_code ec;
	if (!std::filesystem::is_regular_file(std::filesystem::path(p_path), ec)) {
		err = vformat("%s: file not found.", p_path.c_str()); // The caller reports it (no error print here).
	} else if (ext == "png") {
		std::vector<uint8_t> rgba;
		int w = 0, h = 0;
		ok = PNGReader::load(p_path, rgba, w, h, &err) && _from_rgba8(rgba.data(), w, h, r_image);
	} else if (ext == "webp") {
		ok = _load_webp(p_path, r_image, &err);
	} else if (ext == "exr") {
		ok = ImageLoaderEXR::load(p_path, r_image, &err);
	} else if (ext == "hdr") {
		int w = 0, h = 0, n = 0;
		float *data = stbi_loadf(p_path.c_str(), &w, &h, &n, 4);
		if (data) {
			ok = w > 0 && h > 0 && w <= Image::MAX_SIZE && h <= Image::MAX_SIZE && r_image.set_data(w, h, std::vector<float>(data, data + (size_t)w * h * 4));
			stbi_image_free(data);
		}
		if (!ok) {
			err = vformat("%s: cannot read the HDR image (%s).", p_path.c_str(), data ? "bad size" : stbi_failure_reason());
		}
	} else if (recognizes(ext)) {
		int w = 0, h = 0, n = 0;
		uint8_t *data = stbi_load(p_path.c_str(), &w, &h, &n, 4);
		if (data) {
			ok = w > 0 && h > 0 && w <= Image::MAX_SIZE && h <= Image::MAX_SIZE && _from_rgba8(data, w, h, r_image);
			stbi_image_free(data);
		}
		if (!ok) {
			err = vformat("%s: cannot read the image (%s).", p_path.c_str(), data ? "bad size" : stbi_failure_reason());
		}
	} else {
		err = vformat("%s: no image loader for '.%s' files.", p_path.c_str(), ext.c_str());
	}
	if (!ok) {
		r_image.clear();
		if (r_error) {
			*r_error = err;
		}
	}
	return ok;
}
