/**************************************************************************/
/*  reference_texture.cpp                                                 */
/**************************************************************************/
/* godot-area: reference texture sampling (see the header: Vulkan 1.3     */
/* sections 16 and 16.6; Igehy 1999 ray differentials).                   */

#include "modules/reference/reference_texture.h"

#include <algorithm>
#include <cmath>

Color reference_sample_texture_nearest(const Image &p_image, const Vector2 &p_uv) {
	const int w = p_image.get_width();
	const int h = p_image.get_height();
	if (w <= 0 || h <= 0) {
		return Color(1, 1, 1, 1);
	}
	auto wrap = [](float p_t, int p_n) { long i = long(std::floor(p_t * float(p_n))) % p_n; return int(i < 0 ? i + p_n : i); };
	const float *t = p_image.ptr() + (size_t(wrap(p_uv.y, h)) * w + wrap(p_uv.x, w)) * 4;
	return Color(t[0], t[1], t[2], t[3]);
}

Color reference_sample_texture_bilinear(const Image &p_image, const Vector2 &p_uv) {
	const int w = p_image.get_width();
	const int h = p_image.get_height();
	if (w <= 0 || h <= 0) {
		return Color(1, 1, 1, 1);
	}
	const std::vector<float> &data = p_image.get_data();
	// Vulkan LINEAR: texel space coordinate u * size - 0.5, weights from its fraction, REPEAT wrap.
	float fx = p_uv.x * float(w) - 0.5f;
	float fy = p_uv.y * float(h) - 0.5f;
	float x0f = std::floor(fx);
	float y0f = std::floor(fy);
	float ax = fx - x0f;
	float ay = fy - y0f;
	auto wrap = [](long p_i, int p_n) { long m = p_i % p_n; return int(m < 0 ? m + p_n : m); };
	int x0 = wrap(long(x0f), w), x1 = wrap(long(x0f) + 1, w);
	int y0 = wrap(long(y0f), h), y1 = wrap(long(y0f) + 1, h);
	float out[4];
	for (int c = 0; c < 4; c++) {
		float t00 = data[(size_t(y0) * w + x0) * 4 + c];
		float t10 = data[(size_t(y0) * w + x1) * 4 + c];
		float t01 = data[(size_t(y1) * w + x0) * 4 + c];
		float t11 = data[(size_t(y1) * w + x1) * 4 + c];
		out[c] = (t00 * (1.0f - ax) + t10 * ax) * (1.0f - ay) + (t01 * (1.0f - ax) + t11 * ax) * ay;
	}
	return Color(out[0], out[1], out[2], out[3]);
}

Color reference_sample_texture_lod(const Image &p_base, const std::vector<Image> *p_levels, const Vector2 &p_uv, float p_lod, bool p_nearest) {
	auto level_sample = [&](int p_level) {
		const Image &image = p_level == 0 ? p_base : (*p_levels)[p_level - 1];
		return p_nearest ? reference_sample_texture_nearest(image, p_uv) : reference_sample_texture_bilinear(image, p_uv);
	};
	const int q = p_levels ? int(p_levels->size()) : 0; // Highest level.
	if (!(p_lod > 0.0f) || q == 0) {
		return level_sample(0); // Magnification (or NaN, or no chain): the base level.
	}
	// Section 16.6, mipmapMode LINEAR: d = min(lambda, q); levels floor(d) and floor(d) + 1, weight frac(d).
	const float d = std::min(p_lod, float(q));
	const int lower = int(std::floor(d));
	const float frac = d - float(lower);
	if (lower >= q || frac == 0.0f) {
		return level_sample(lower);
	}
	const Color a = level_sample(lower), b = level_sample(lower + 1);
	return a * (1.0f - frac) + b * frac;
}

bool reference_ray_plane_uv(const Vector3 &p_origin, const Vector3 &p_dir, const Vector3 p_positions[3], const Vector2 p_uvs[3], Vector2 &r_uv) {
	const Vector3 e1 = p_positions[1] - p_positions[0], e2 = p_positions[2] - p_positions[0];
	const Vector3 n = e1.cross(e2);
	const float denom = p_dir.dot(n);
	if (!(std::fabs(denom) > 1e-12f * n.length())) {
		return false;
	}
	const Vector3 p = p_origin + p_dir * ((p_positions[0] - p_origin).dot(n) / denom);
	// Barycentric coordinates of p (Cramer's rule on e1, e2).
	const Vector3 e = p - p_positions[0];
	const float d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
	const float de1 = e.dot(e1), de2 = e.dot(e2);
	const float det = d11 * d22 - d12 * d12;
	if (!(std::fabs(det) > 0.0f)) {
		return false;
	}
	const float b1 = (d22 * de1 - d12 * de2) / det;
	const float b2 = (d11 * de2 - d12 * de1) / det;
	r_uv = p_uvs[0] * (1.0f - b1 - b2) + p_uvs[1] * b1 + p_uvs[2] * b2;
	return std::isfinite(r_uv.x) && std::isfinite(r_uv.y);
}
