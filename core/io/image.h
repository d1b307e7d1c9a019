/**************************************************************************/
/*  image.h                                                               */
/**************************************************************************/
/* godot-area: a float RGBA image in scene-linear values (the renderer's  */
/* readback format, the EXR format, the input of the preview tonemap).    */
/* Pixels are stored row by row, top row first, 4 floats (R, G, B, A)     */
/* per pixel.                                                             */

#pragma once

#include "core/math/color.h"
#include "core/string/ustring.h"

#include <vector>

class Image {
public:
	// Largest accepted side, so a corrupt header cannot ask for gigabytes.
	static constexpr int MAX_SIZE = 16384;
	static constexpr int CHANNELS = 4;

private:
	int width = 0;
	int height = 0;
	std::vector<float> data; // width * height * 4 floats.

public:
	// Allocates p_width x p_height pixels filled with p_fill. Returns false (and leaves the image
	// empty) for sizes that are zero, negative or larger than MAX_SIZE.
	bool create(int p_width, int p_height, const Color &p_fill = Color(0, 0, 0, 1));
	// Takes p_data (width * height * 4 floats, top row first). Returns false on a size mismatch.
	bool set_data(int p_width, int p_height, const std::vector<float> &p_data);
	void clear();

	int get_width() const { return width; }
	int get_height() const { return height; }
	bool is_empty() const { return width == 0 || height == 0; }
	const std::vector<float> &get_data() const { return data; }
	const float *ptr() const { return data.data(); }
	float *ptrw() { return data.data(); }

	// Out-of-range coordinates print an error; get_pixel then returns transparent black.
	Color get_pixel(int p_x, int p_y) const;
	void set_pixel(int p_x, int p_y, const Color &p_color);
	void fill(const Color &p_color);

	// True when every channel of every pixel is finite (no NaN, no infinity). An empty image is finite.
	bool is_finite() const;
	// True when some pixel has an R, G or B value above p_threshold (alpha is ignored).
	bool has_non_black(float p_threshold = 0.0f) const;
	// Largest absolute per-channel difference; -1 if the sizes differ, NaN if a NaN is involved.
	float get_max_difference(const Image &p_other) const;

	Image() {}
	Image(int p_width, int p_height, const Color &p_fill = Color(0, 0, 0, 1)) { create(p_width, p_height, p_fill); }
};
