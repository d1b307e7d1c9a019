/**************************************************************************/
/*  texture_mipmaps.cpp                                                   */
/**************************************************************************/
/* godot-area: mip chains and Vulkan's level of detail (see the header:   */
/* Williams 1983; Vulkan 1.3 section 16.6).                               */

#include "servers/rendering/storage/texture_mipmaps.h"

#include "core/math/color.h"

#include <algorithm>
#include <cmath>

int texture_mipmap_level_count(int p_width, int p_height) {
	int levels = 1;
	for (int d = std::max(p_width, p_height); d > 1; d >>= 1) {
		levels++;
	}
	return levels;
}

// One axis of the area-weighted box: destination texel i covers source [i * s, (i + 1) * s),
// s = p_src / p_dst; each source texel weighs the length of its overlap (total s).
struct _BoxTap {
	int first = 0;
	std::vector<float> weights;
};

static std::vector<_BoxTap> _box_taps(int p_src, int p_dst) {
	std::vector<_BoxTap> taps(p_dst);
	const double scale = double(p_src) / double(p_dst);
	for (int i = 0; i < p_dst; i++) {
		const double lo = i * scale, hi = (i + 1) * scale;
		const int first = int(std::floor(lo));
		const int last = std::min(p_src - 1, int(std::ceil(hi)) - 1);
		taps[i].first = first;
		for (int j = first; j <= last; j++) {
			const double overlap = std::min(hi, double(j + 1)) - std::max(lo, double(j));
			taps[i].weights.push_back(float(std::max(0.0, overlap) / scale));
		}
	}
	return taps;
}

// p_src (linear values) -> p_dst_w x p_dst_h, horizontal pass then vertical pass.
static std::vector<float> _downsample(const std::vector<float> &p_src, int p_w, int p_h, int p_dst_w, int p_dst_h) {
	const std::vector<_BoxTap> tx = _box_taps(p_w, p_dst_w), ty = _box_taps(p_h, p_dst_h);
	std::vector<float> rows(size_t(p_dst_w) * p_h * 4, 0.0f);
	for (int y = 0; y < p_h; y++) {
		for (int x = 0; x < p_dst_w; x++) {
			float *out = &rows[(size_t(y) * p_dst_w + x) * 4];
			for (size_t k = 0; k < tx[x].weights.size(); k++) {
				const float *in = &p_src[(size_t(y) * p_w + tx[x].first + k) * 4];
				for (int c = 0; c < 4; c++) {
					out[c] += in[c] * tx[x].weights[k];
				}
			}
		}
	}
	std::vector<float> out(size_t(p_dst_w) * p_dst_h * 4, 0.0f);
	for (int y = 0; y < p_dst_h; y++) {
		for (size_t k = 0; k < ty[y].weights.size(); k++) {
			const float w = ty[y].weights[k];
			const float *in = &rows[size_t(ty[y].first + k) * p_dst_w * 4];
			float *o = &out[size_t(y) * p_dst_w * 4];
			for (int i = 0; i < p_dst_w * 4; i++) {
				o[i] += in[i] * w;
			}
		}
	}
	return out;
}

void texture_mipmaps_generate(const Image &p_base, bool p_srgb, std::vector<Image> &r_levels) {
	r_levels.clear();
	if (p_base.is_empty()) {
		return;
	}
	int w = p_base.get_width(), h = p_base.get_height();
	std::vector<float> linear = p_base.get_data();
	if (p_srgb) {
		for (size_t i = 0; i < linear.size(); i += 4) {
			for (int c = 0; c < 3; c++) {
				linear[i + c] = Color::srgb_to_linear_channel(linear[i + c]);
			}
		}
	}
	const int count = texture_mipmap_level_count(w, h);
	r_levels.reserve(count - 1);
	for (int level = 1; level < count; level++) {
		const int dw = std::max(1, w >> 1), dh = std::max(1, h >> 1);
		linear = _downsample(linear, w, h, dw, dh);
		w = dw;
		h = dh;
		std::vector<float> stored = linear;
		if (p_srgb) {
			for (size_t i = 0; i < stored.size(); i += 4) {
				for (int c = 0; c < 3; c++) {
					stored[i + c] = Color::linear_to_srgb_channel(std::max(0.0f, stored[i + c]));
				}
			}
		}
		Image image;
		image.set_data(w, h, stored);
		r_levels.push_back(std::move(image));
	}
}

float texture_mipmap_lod(const Vector2 &p_duv_dx, const Vector2 &p_duv_dy, int p_width, int p_height) {
	const float rx = std::hypot(p_duv_dx.x * float(p_width), p_duv_dx.y * float(p_height));
	const float ry = std::hypot(p_duv_dy.x * float(p_width), p_duv_dy.y * float(p_height));
	return std::log2(std::max(rx, ry)); // log2(0) = -inf: magnification.
}
