/**************************************************************************/
/*  area_light_atlas.cpp                                                  */
/**************************************************************************/

#include "servers/rendering/renderer_rd/storage_rd/area_light_atlas.h"

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"
#include "core/math/color.h"
#include "servers/rendering/rendering_device.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace RendererRD {

uint32_t AreaLightAtlas::get_project_size() {
	const int64_t v = GLOBAL_DEF(SETTING_SIZE, int64_t(DEFAULT_SIZE)).to_int();
	if (v < int64_t(MIN_SIZE) || v > int64_t(MAX_SIZE) || (v & (v - 1)) != 0) {
		ERR_PRINT(vformat("%s must be a power of two in %u..%u; got %lld. Using %u.", SETTING_SIZE, MIN_SIZE, MAX_SIZE, (long long)v, DEFAULT_SIZE));
		return DEFAULT_SIZE;
	}
	return uint32_t(v);
}

namespace {

// IEEE 754 binary16 of p_value, rounded to nearest even (overflow to infinity, underflow through the
// subnormals to zero). The atlas stores half floats: the same accuracy against the reference as floats
// (doc/methods.md section 12) at half the memory.
uint16_t _to_half(float p_value) {
	uint32_t x;
	memcpy(&x, &p_value, sizeof(x));
	const uint32_t sign = (x >> 16) & 0x8000u;
	const uint32_t abs_bits = x & 0x7fffffffu;
	if (abs_bits >= 0x7f800000u) {
		return uint16_t(sign | 0x7c00u | (abs_bits > 0x7f800000u ? 0x200u : 0u)); // Infinity or NaN.
	}
	if (abs_bits >= 0x477ff000u) {
		return uint16_t(sign | 0x7c00u); // Rounds to above 65504: infinity.
	}
	if (abs_bits < 0x38800000u) {
		// Subnormal half (or zero): the value in units of 2^-24, rounded to nearest even.
		if (abs_bits < 0x33000000u) {
			return uint16_t(sign); // Below half of the smallest subnormal.
		}
		const uint32_t mantissa = (abs_bits & 0x7fffffu) | 0x800000u;
		const uint32_t shift = 126u - (abs_bits >> 23); // 14..24 for exponents -15..-25.
		uint32_t h = mantissa >> shift;
		const uint32_t rest = mantissa & ((1u << shift) - 1u);
		const uint32_t half_way = 1u << (shift - 1u);
		if (rest > half_way || (rest == half_way && (h & 1u))) {
			h++;
		}
		return uint16_t(sign | h);
	}
	// Normal: rebias the exponent (127 -> 15), keep 10 mantissa bits, round to nearest even (a carry
	// into the exponent is the correct result).
	uint32_t h = ((abs_bits >> 13) - (112u << 10));
	const uint32_t rest = abs_bits & 0x1fffu;
	if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) {
		h++;
	}
	return uint16_t(sign | h);
}

// Resamples p_count rows of p_src (p_src_n texels each, p_stride floats between texels) to p_dst_n texels:
// a box average of the covered source texels when shrinking, linear interpolation between texel
// centres (clamped at the ends) when enlarging.
void _resample_1d(const float *p_src, int p_src_n, float *p_dst, int p_dst_n) {
	const float scale = float(p_src_n) / float(p_dst_n);
	for (int i = 0; i < p_dst_n; i++) {
		float out[4] = { 0, 0, 0, 0 };
		if (scale > 1.0f) {
			const float a = float(i) * scale, b = float(i + 1) * scale;
			float weight = 0.0f;
			for (int s = int(std::floor(a)); s < int(std::ceil(b)) && s < p_src_n; s++) {
				const float w = std::min(b, float(s + 1)) - std::max(a, float(s));
				for (int c = 0; c < 4; c++) {
					out[c] += w * p_src[s * 4 + c];
				}
				weight += w;
			}
			for (int c = 0; c < 4; c++) {
				out[c] /= weight;
			}
		} else {
			const float x = (float(i) + 0.5f) * scale - 0.5f;
			const int x0 = std::clamp(int(std::floor(x)), 0, p_src_n - 1);
			const int x1 = std::min(x0 + 1, p_src_n - 1);
			const float t = std::clamp(x - float(x0), 0.0f, 1.0f);
			for (int c = 0; c < 4; c++) {
				out[c] = p_src[x0 * 4 + c] * (1.0f - t) + p_src[x1 * 4 + c] * t;
			}
		}
		for (int c = 0; c < 4; c++) {
			p_dst[i * 4 + c] = out[c];
		}
	}
}

// Normalised separable Gaussian blur (sigma in texels) of a square p_n x p_n float RGBA image, in place.
void _gaussian_blur(std::vector<float> &r_texels, int p_n, float p_sigma) {
	const int radius = std::max(1, int(std::ceil(3.0f * p_sigma)));
	std::vector<float> kernel(2 * radius + 1);
	for (int k = -radius; k <= radius; k++) {
		kernel[k + radius] = std::exp(-0.5f * float(k * k) / (p_sigma * p_sigma));
	}
	std::vector<float> tmp(r_texels.size());
	for (int pass = 0; pass < 2; pass++) {
		const std::vector<float> &src = pass == 0 ? r_texels : tmp;
		std::vector<float> &dst = pass == 0 ? tmp : r_texels;
		for (int y = 0; y < p_n; y++) {
			for (int x = 0; x < p_n; x++) {
				float out[4] = { 0, 0, 0, 0 };
				float weight = 0.0f;
				const int at = pass == 0 ? x : y;
				for (int k = std::max(-radius, -at); k <= radius && at + k < p_n; k++) {
					const int sx = pass == 0 ? x + k : x;
					const int sy = pass == 0 ? y : y + k;
					const float w = kernel[k + radius];
					const float *t = &src[(size_t(sy) * p_n + sx) * 4];
					for (int c = 0; c < 4; c++) {
						out[c] += w * t[c];
					}
					weight += w;
				}
				float *d = &dst[(size_t(y) * p_n + x) * 4];
				for (int c = 0; c < 4; c++) {
					d[c] = out[c] / weight;
				}
			}
		}
	}
}

} // namespace

std::vector<Image> AreaLightAtlas::build_levels(const Image &p_image, uint32_t p_size) {
	std::vector<Image> levels;
	ERR_FAIL_COND_V_MSG(p_image.is_empty(), levels, "AreaLightAtlas::build_levels: the image is empty.");
	ERR_FAIL_COND_V_MSG(p_size == 0 || (p_size & (p_size - 1)) != 0, levels, "AreaLightAtlas::build_levels: the size must be a power of two.");
	const int w = p_image.get_width(), h = p_image.get_height(), n = int(p_size);
	// Linear, premultiplied colour (as upstream: rgb * alpha), then rows to n texels, then columns.
	std::vector<float> linear(size_t(w) * h * 4);
	for (int i = 0; i < w * h; i++) {
		const float *t = p_image.ptr() + size_t(i) * 4;
		const Color c = Color(t[0], t[1], t[2], t[3]).srgb_to_linear();
		const float a = std::clamp(t[3], 0.0f, 1.0f);
		linear[size_t(i) * 4 + 0] = std::max(c.r, 0.0f) * a;
		linear[size_t(i) * 4 + 1] = std::max(c.g, 0.0f) * a;
		linear[size_t(i) * 4 + 2] = std::max(c.b, 0.0f) * a;
		linear[size_t(i) * 4 + 3] = a;
	}
	std::vector<float> rows(size_t(n) * h * 4);
	for (int y = 0; y < h; y++) {
		_resample_1d(&linear[size_t(y) * w * 4], w, &rows[size_t(y) * n * 4], n);
	}
	std::vector<float> level(size_t(n) * n * 4);
	std::vector<float> column_src(size_t(h) * 4), column_dst(size_t(n) * 4);
	for (int x = 0; x < n; x++) {
		for (int y = 0; y < h; y++) {
			memcpy(&column_src[size_t(y) * 4], &rows[(size_t(y) * n + x) * 4], 4 * sizeof(float));
		}
		_resample_1d(column_src.data(), h, column_dst.data(), n);
		for (int y = 0; y < n; y++) {
			memcpy(&level[(size_t(y) * n + x) * 4], &column_dst[size_t(y) * 4], 4 * sizeof(float));
		}
	}
	Image base;
	base.set_data(n, n, level);
	levels.push_back(base);
	// Level L from level L-1: the extra blur that takes sigma_(L-1) to sigma_L (in level L-1 texels), then a
	// 2 x 2 box average.
	for (uint32_t l = 1; (n >> l) >= 1; l++) {
		const int src_n = n >> (l - 1);
		const float s_prev = get_level_sigma(l - 1), s_now = get_level_sigma(l);
		const float extra = std::sqrt(s_now * s_now - s_prev * s_prev) / float(1u << (l - 1));
		std::vector<float> blurred = levels.back().get_data();
		_gaussian_blur(blurred, src_n, extra);
		const int dst_n = src_n / 2;
		std::vector<float> down(size_t(dst_n) * dst_n * 4);
		for (int y = 0; y < dst_n; y++) {
			for (int x = 0; x < dst_n; x++) {
				for (int c = 0; c < 4; c++) {
					const float sum = blurred[(size_t(2 * y) * src_n + 2 * x) * 4 + c] + blurred[(size_t(2 * y) * src_n + 2 * x + 1) * 4 + c] + blurred[(size_t(2 * y + 1) * src_n + 2 * x) * 4 + c] + blurred[(size_t(2 * y + 1) * src_n + 2 * x + 1) * 4 + c];
					down[(size_t(y) * dst_n + x) * 4 + c] = sum * 0.25f;
				}
			}
		}
		Image next;
		next.set_data(dst_n, dst_n, down);
		levels.push_back(next);
	}
	return levels;
}

std::vector<float> AreaLightAtlas::pack_slot(const std::vector<Image> &p_levels) {
	ERR_FAIL_COND_V(p_levels.empty(), std::vector<float>());
	const int n = p_levels[0].get_width();
	const size_t slice = size_t(n) * n * 4;
	std::vector<float> out(slice * p_levels.size(), 0.0f);
	std::vector<float> rows, column_src, column_dst(size_t(n) * 4);
	for (size_t l = 0; l < p_levels.size(); l++) {
		const int ln = p_levels[l].get_width();
		float *dst = &out[slice * l];
		if (ln == n) {
			memcpy(dst, p_levels[l].ptr(), slice * sizeof(float));
			continue;
		}
		rows.assign(size_t(n) * ln * 4, 0.0f);
		for (int y = 0; y < ln; y++) {
			_resample_1d(p_levels[l].ptr() + size_t(y) * ln * 4, ln, &rows[size_t(y) * n * 4], n);
		}
		column_src.assign(size_t(ln) * 4, 0.0f);
		for (int x = 0; x < n; x++) {
			for (int y = 0; y < ln; y++) {
				memcpy(&column_src[size_t(y) * 4], &rows[(size_t(y) * n + x) * 4], 4 * sizeof(float));
			}
			_resample_1d(column_src.data(), ln, column_dst.data(), n);
			for (int y = 0; y < n; y++) {
				memcpy(&dst[(size_t(y) * n + x) * 4], &column_dst[size_t(y) * 4], 4 * sizeof(float));
			}
		}
	}
	return out;
}

bool AreaLightAtlas::_find_free_row(uint32_t &r_row) const {
	std::vector<bool> taken(rows, false);
	for (const auto &kv : slots) {
		if (kv.second.row < rows) {
			taken[kv.second.row] = true;
		}
	}
	for (uint32_t r = 0; r < rows; r++) {
		if (!taken[r]) {
			r_row = r;
			return true;
		}
	}
	return false;
}

void AreaLightAtlas::begin_update() {
	for (auto &kv : slots) {
		kv.second.used = false;
	}
	dropped = 0;
}

bool AreaLightAtlas::request(RID p_texture, const Image *p_image) {
	if (!p_texture.is_valid() || !p_image || p_image->is_empty()) {
		return false;
	}
	if (size == 0) {
		size = get_project_size();
	}
	auto it = slots.find(p_texture.get_id());
	if (it == slots.end()) {
		uint32_t row = 0;
		if (!_find_free_row(row)) {
			const uint32_t max_rows = MAX_ATLAS_HEIGHT / size;
			if (rows >= max_rows) {
				dropped++;
				return false;
			}
			row = rows;
			rows = std::max(1u, rows * 2);
		}
		Slot slot;
		slot.source = p_texture;
		slot.row = row;
		slot.texels = pack_slot(build_levels(*p_image, size));
		builds++;
		it = slots.emplace(p_texture.get_id(), std::move(slot)).first;
		dirty = true;
	}
	it->second.used = true;
	it->second.unused_updates = 0;
	return true;
}

bool AreaLightAtlas::get_rect(RID p_texture, float r_rect[4]) const {
	r_rect[0] = r_rect[1] = r_rect[2] = r_rect[3] = 0.0f;
	auto it = slots.find(p_texture.get_id());
	if (it == slots.end() || !texture.is_valid()) {
		return false;
	}
	const float atlas_h = float(rows * size);
	r_rect[0] = 0.0f;
	r_rect[1] = float(it->second.row * size) / atlas_h;
	r_rect[2] = 1.0f;
	r_rect[3] = float(size) / atlas_h;
	return true;
}

void AreaLightAtlas::_rebuild_texture() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL(rd);
	uint32_t depth = 1;
	while ((size >> (depth - 1)) > 1) {
		depth++;
	}
	const uint32_t width = size, height = rows * size;
	RD::TextureFormat current;
	if (texture.is_valid()) {
		current = rd->texture_get_format(texture);
	}
	if (!texture.is_valid() || current.width != width || current.height != height || current.depth != depth) {
		if (texture.is_valid()) {
			rd->free(texture);
		}
		RD::TextureFormat tf;
		tf.format = RD::DATA_FORMAT_R16G16B16A16_SFLOAT;
		tf.width = width;
		tf.height = height;
		tf.depth = depth;
		tf.texture_type = RD::TEXTURE_TYPE_3D;
		tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
		texture = rd->texture_create(tf);
		ERR_FAIL_COND_MSG(!texture.is_valid(), "AreaLightAtlas: cannot create the area light atlas texture.");
		rd->set_resource_name(texture, "Area light atlas");
	}
	if (!sampler.is_valid()) {
		RD::SamplerState ss;
		ss.mag_filter = RD::SAMPLER_FILTER_LINEAR;
		ss.min_filter = RD::SAMPLER_FILTER_LINEAR; // Along the depth too: two levels blended in one fetch.
		ss.max_lod = 0.0f;
		sampler = rd->sampler_create(ss);
	}
	// Slice z of the atlas holds slice z of every slot, slot `row` at rows [row * C, (row + 1) * C).
	const size_t slot_slice = size_t(size) * size * 4; // Channels of one slot in one slice.
	std::vector<uint8_t> bytes(slot_slice * rows * depth * sizeof(uint16_t), 0);
	uint16_t *dst = reinterpret_cast<uint16_t *>(bytes.data());
	for (const auto &kv : slots) {
		ERR_CONTINUE(kv.second.texels.size() != slot_slice * depth);
		for (uint32_t z = 0; z < depth; z++) {
			uint16_t *out = dst + (size_t(z) * rows + kv.second.row) * slot_slice;
			const float *in = kv.second.texels.data() + size_t(z) * slot_slice;
			for (size_t i = 0; i < slot_slice; i++) {
				out[i] = _to_half(in[i]);
			}
		}
	}
	rd->texture_update(texture, 0, bytes);
	uploads++;
}

void AreaLightAtlas::end_update() {
	for (auto it = slots.begin(); it != slots.end();) {
		if (!it->second.used && ++it->second.unused_updates > KEEP_UNUSED_UPDATES) {
			it = slots.erase(it); // Its texels stay in the atlas until the row is reused (never sampled).
		} else {
			++it;
		}
	}
	if (dropped != warned_dropped) {
		if (dropped > 0) {
			WARN_PRINT(vformat("%u area light textures do not fit the area light atlas (%u textures of %u x %u texels at most, project setting %s); those lights are drawn untextured.",
					dropped, MAX_ATLAS_HEIGHT / std::max(size, 1u), size, size, SETTING_SIZE));
		}
		warned_dropped = dropped;
	}
	if (dirty && !slots.empty()) {
		_rebuild_texture();
	}
	dirty = false;
}

void AreaLightAtlas::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd) {
		if (texture.is_valid()) {
			rd->free(texture);
		}
		if (sampler.is_valid()) {
			rd->free(sampler);
		}
	}
	texture = RID();
	sampler = RID();
	slots.clear();
	rows = 0;
	size = 0;
	dirty = false;
}

AreaLightAtlas::~AreaLightAtlas() {
	ERR_FAIL_COND_MSG(texture.is_valid(), "AreaLightAtlas destroyed without finalize(): its GPU texture leaks.");
}

} // namespace RendererRD
