/**************************************************************************/
/*  image.cpp                                                             */
/**************************************************************************/
/* godot-area: a float RGBA image in scene-linear values.                 */

#include "core/io/image.h"

#include "core/error/error_macros.h"

#include <cmath>

bool Image::create(int p_width, int p_height, const Color &p_fill) {
	clear();
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0, false, vformat("Image size must be positive, got %dx%d.", p_width, p_height));
	ERR_FAIL_COND_V_MSG(p_width > MAX_SIZE || p_height > MAX_SIZE, false, vformat("Image size %dx%d exceeds the maximum of %d per side.", p_width, p_height, MAX_SIZE));
	width = p_width;
	height = p_height;
	data.resize((size_t)width * (size_t)height * CHANNELS);
	fill(p_fill);
	return true;
}

bool Image::set_data(int p_width, int p_height, const std::vector<float> &p_data) {
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0, false, vformat("Image size must be positive, got %dx%d.", p_width, p_height));
	ERR_FAIL_COND_V_MSG(p_width > MAX_SIZE || p_height > MAX_SIZE, false, vformat("Image size %dx%d exceeds the maximum of %d per side.", p_width, p_height, MAX_SIZE));
	const size_t expected = (size_t)p_width * (size_t)p_height * CHANNELS;
	ERR_FAIL_COND_V_MSG(p_data.size() != expected, false, vformat("Image data for %dx%d RGBA needs %zu floats, got %zu.", p_width, p_height, expected, p_data.size()));
	width = p_width;
	height = p_height;
	data = p_data;
	return true;
}

void Image::clear() {
	width = 0;
	height = 0;
	data.clear();
}

Color Image::get_pixel(int p_x, int p_y) const {
	ERR_FAIL_INDEX_V_MSG(p_x, width, Color(0, 0, 0, 0), "Pixel x coordinate is outside the image.");
	ERR_FAIL_INDEX_V_MSG(p_y, height, Color(0, 0, 0, 0), "Pixel y coordinate is outside the image.");
	const float *p = &data[((size_t)p_y * width + p_x) * CHANNELS];
	return Color(p[0], p[1], p[2], p[3]);
}

void Image::set_pixel(int p_x, int p_y, const Color &p_color) {
	ERR_FAIL_INDEX_MSG(p_x, width, "Pixel x coordinate is outside the image.");
	ERR_FAIL_INDEX_MSG(p_y, height, "Pixel y coordinate is outside the image.");
	float *p = &data[((size_t)p_y * width + p_x) * CHANNELS];
	p[0] = p_color.r;
	p[1] = p_color.g;
	p[2] = p_color.b;
	p[3] = p_color.a;
}

void Image::fill(const Color &p_color) {
	for (size_t i = 0; i < data.size(); i += CHANNELS) {
		data[i + 0] = p_color.r;
		data[i + 1] = p_color.g;
		data[i + 2] = p_color.b;
		data[i + 3] = p_color.a;
	}
}

bool Image::is_finite() const {
	for (float v : data) {
		if (!std::isfinite(v)) {
			return false;
		}
	}
	return true;
}

bool Image::has_non_black(float p_threshold) const {
	for (size_t i = 0; i < data.size(); i += CHANNELS) {
		if (data[i + 0] > p_threshold || data[i + 1] > p_threshold || data[i + 2] > p_threshold) {
			return true;
		}
	}
	return false;
}

float Image::get_max_difference(const Image &p_other) const {
	if (width != p_other.width || height != p_other.height) {
		return -1.0f;
	}
	float max_diff = 0.0f;
	for (size_t i = 0; i < data.size(); i++) {
		const float diff = std::fabs(data[i] - p_other.data[i]);
		if (std::isnan(diff)) {
			return diff; // A NaN on either side makes the images incomparable.
		}
		if (diff > max_diff) {
			max_diff = diff;
		}
	}
	return max_diff;
}
