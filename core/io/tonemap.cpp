/**************************************************************************/
/*  tonemap.cpp                                                           */
/**************************************************************************/
/* godot-area: preview tonemap (see tonemap.h for the exact definition).  */

#include "core/io/tonemap.h"

#include "core/error/error_macros.h"

#include <cmath>

float Tonemap::aces_fitted(float p_x) {
	// Krzysztof Narkowicz, 2015, "ACES Filmic Tone Mapping Curve" (fit of the ACES RRT+ODT).
	const float x = p_x > 0.0f ? p_x : 0.0f;
	const float mapped = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
	return mapped < 1.0f ? mapped : 1.0f;
}

float Tonemap::linear_to_srgb(float p_x) {
	// IEC 61966-2-1 OETF; computed in double so 8-bit rounding does not depend on float pow.
	const double x = p_x;
	const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
	return (float)encoded;
}

static uint8_t _to_byte(double p_unit) {
	if (!(p_unit > 0.0)) { // Also NaN.
		return 0;
	}
	if (p_unit >= 1.0) {
		return 255;
	}
	return (uint8_t)std::lround(p_unit * 255.0);
}

uint8_t Tonemap::map_channel(float p_linear, float p_exposure_ev, Mode p_mode) {
	if (std::isnan(p_linear) || !(p_linear > 0.0f)) {
		return 0;
	}
	float x = p_linear * std::exp2(p_exposure_ev);
	if (std::isnan(x)) {
		return 0;
	}
	switch (p_mode) {
		case MODE_ACES_FITTED:
			x = std::isinf(x) ? 1.0f : aces_fitted(x);
			break;
		case MODE_LINEAR:
		default:
			x = x < 1.0f ? x : 1.0f;
			break;
	}
	return _to_byte(linear_to_srgb(x));
}

uint8_t Tonemap::map_alpha(float p_alpha) {
	return _to_byte(p_alpha);
}

std::vector<uint8_t> Tonemap::apply(const Image &p_hdr, float p_exposure_ev, Mode p_mode) {
	std::vector<uint8_t> out;
	ERR_FAIL_COND_V_MSG(p_hdr.is_empty(), out, "Cannot tonemap an empty image.");
	ERR_FAIL_INDEX_V_MSG((int)p_mode, (int)MODE_MAX, out, "Unknown tonemap mode.");
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_exposure_ev), out, "Tonemap exposure must be finite.");
	const std::vector<float> &data = p_hdr.get_data();
	out.resize(data.size());
	for (size_t i = 0; i < data.size(); i += Image::CHANNELS) {
		out[i + 0] = map_channel(data[i + 0], p_exposure_ev, p_mode);
		out[i + 1] = map_channel(data[i + 1], p_exposure_ev, p_mode);
		out[i + 2] = map_channel(data[i + 2], p_exposure_ev, p_mode);
		out[i + 3] = map_alpha(data[i + 3]);
	}
	return out;
}
