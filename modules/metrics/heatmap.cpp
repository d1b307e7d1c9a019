/**************************************************************************/
/*  heatmap.cpp                                                           */
/**************************************************************************/
/* godot-area: false-colour error images, see heatmap.h.                  */

#include "modules/metrics/heatmap.h"

#include "core/error/error_macros.h"
#include "drivers/png/png_writer.h"

#include <cmath>
#include <cstdint>

namespace {

// Key colours (sRGB) at the listed positions t. Approximate, chosen by eye (see heatmap.h).
struct HeatmapKey {
	float t, r, g, b;
};
constexpr HeatmapKey HEATMAP_KEYS[] = {
	{ 0.0f, 0.00f, 0.00f, 0.02f },
	{ 0.25f, 0.23f, 0.06f, 0.44f },
	{ 0.5f, 0.55f, 0.16f, 0.51f },
	{ 0.75f, 0.87f, 0.29f, 0.41f },
	{ 0.875f, 0.98f, 0.55f, 0.38f },
	{ 1.0f, 0.99f, 0.99f, 0.75f },
};
constexpr int HEATMAP_KEY_COUNT = sizeof(HEATMAP_KEYS) / sizeof(HEATMAP_KEYS[0]);

bool _fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

} // namespace

Color Heatmap::map(float p_t) {
	const float t = std::isnan(p_t) ? 0.0f : Math::clamp(p_t, 0.0f, 1.0f);
	for (int i = 1; i < HEATMAP_KEY_COUNT; i++) {
		const HeatmapKey &k0 = HEATMAP_KEYS[i - 1];
		const HeatmapKey &k1 = HEATMAP_KEYS[i];
		if (t <= k1.t || i == HEATMAP_KEY_COUNT - 1) {
			const float w = Math::clamp((t - k0.t) / (k1.t - k0.t), 0.0f, 1.0f);
			return Color(Math::lerp(k0.r, k1.r, w), Math::lerp(k0.g, k1.g, w), Math::lerp(k0.b, k1.b, w), 1.0f);
		}
	}
	return Color(HEATMAP_KEYS[0].r, HEATMAP_KEYS[0].g, HEATMAP_KEYS[0].b, 1.0f);
}

bool Heatmap::write_png(const std::vector<float> &p_per_pixel_error, int p_width, int p_height, float p_max_value, const String &p_path, String *r_error) {
	if (p_width <= 0 || p_height <= 0) {
		return _fail(r_error, vformat("Heatmap: invalid size %dx%d.", p_width, p_height));
	}
	const size_t count = (size_t)p_width * (size_t)p_height;
	if (p_per_pixel_error.size() != count) {
		return _fail(r_error, vformat("Heatmap: %zu error values do not match %dx%d.", p_per_pixel_error.size(), p_width, p_height));
	}
	if (!(p_max_value > 0.0f) || !std::isfinite(p_max_value)) {
		return _fail(r_error, vformat("Heatmap: max value must be positive and finite (got %g).", double(p_max_value)));
	}
	std::vector<uint8_t> rgba(count * 4);
	for (size_t i = 0; i < count; i++) {
		const Color c = map(p_per_pixel_error[i] / p_max_value);
		rgba[i * 4 + 0] = uint8_t(std::lround(c.r * 255.0f));
		rgba[i * 4 + 1] = uint8_t(std::lround(c.g * 255.0f));
		rgba[i * 4 + 2] = uint8_t(std::lround(c.b * 255.0f));
		rgba[i * 4 + 3] = 255;
	}
	String error;
	if (!PNGWriter::save_rgba8(rgba, p_width, p_height, p_path, &error)) {
		return _fail(r_error, vformat("Heatmap: cannot write \"%s\": %s", p_path.c_str(), error.c_str()));
	}
	return true;
}
