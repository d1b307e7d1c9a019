/**************************************************************************/
/*  tonemap.cpp                                                           */
/**************************************************************************/
/* godot-area: tonemapping (see tonemap.h for the formulas and sources).  */

#include "core/io/tonemap.h"

#include "core/error/error_macros.h"

#include <cmath>

static float _clamp01(float p_x) {
	return p_x > 0.0f ? (p_x < 1.0f ? p_x : 1.0f) : 0.0f; // NaN -> 0.
}

bool Tonemap::mode_from_godot(int p_tonemap_mode, Mode &r_mode) {
	static const Mode modes[5] = { MODE_LINEAR, MODE_REINHARD, MODE_FILMIC, MODE_ACES, MODE_AGX };
	if (p_tonemap_mode < 0 || p_tonemap_mode > 4) {
		return false;
	}
	r_mode = modes[p_tonemap_mode];
	return true;
}

float Tonemap::aces_fitted(float p_x) {
	// Krzysztof Narkowicz, 2015, "ACES Filmic Tone Mapping Curve" (fit of the ACES RRT+ODT).
	const float x = p_x > 0.0f ? p_x : 0.0f;
	const float mapped = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
	return mapped < 1.0f ? mapped : 1.0f;
}

float Tonemap::reinhard(float p_x, float p_white) {
	// Reinhard, Stark, Shirley, Ferwerda 2002, "Photographic Tone Reproduction for Digital Images", eq. 4
	// (L_white = tonemap_white): maps the white point to exactly 1.
	const double x = p_x > 0.0f ? p_x : 0.0f;
	const double w2 = double(p_white) * double(p_white);
	return float(x * (1.0 + x / w2) / (1.0 + x));
}

static double _hable(double p_x) {
	// John Hable 2010, "Uncharted 2: HDR Lighting" (GDC), the filmic curve and its constants.
	const double A = 0.22, B = 0.30, C = 0.10, D = 0.20, E = 0.01, F = 0.30;
	return (p_x * (A * p_x + C * B) + D * E) / (p_x * (A * p_x + B) + D * F) - E / F;
}

float Tonemap::filmic(float p_x, float p_white) {
	// Godot 4 scales input and white point by an exposure bias of 2 before the curve.
	const double bias = 2.0;
	const double x = p_x > 0.0f ? p_x : 0.0f;
	return float(_hable(bias * x) / _hable(bias * double(p_white)));
}

// Stephen Hill's fit of the ACES reference rendering + output transforms, as published with Matt Pettineo's
// BakingLab (MIT): sRGB -> AP1 with the RRT saturation folded in, a rational curve, AP1 -> sRGB.
static const double ACES_INPUT[3][3] = {
	{ 0.59719, 0.35458, 0.04823 },
	{ 0.07600, 0.90834, 0.01566 },
	{ 0.02840, 0.13383, 0.83777 },
};
static const double ACES_OUTPUT[3][3] = {
	{ 1.60475, -0.53108, -0.07367 },
	{ -0.10208, 1.10813, -0.00605 },
	{ -0.00327, -0.07276, 1.07602 },
};

static double _aces_rrt_odt(double p_x) {
	const double a = 0.0245786, b = 0.000090537, c = 0.983729, d = 0.432951, e = 0.238081;
	return (p_x * (p_x + a) - b) / (p_x * (c * p_x + d) + e);
}

static void _mat3_mul(const double p_m[3][3], const double *p_v, double *r_out) {
	for (int i = 0; i < 3; i++) {
		r_out[i] = p_m[i][0] * p_v[0] + p_m[i][1] * p_v[1] + p_m[i][2] * p_v[2];
	}
}

void Tonemap::aces(float *r_rgb, float p_white) {
	const double bias = 1.8; // Godot 4's exposure bias for ACES (input and white point).
	double in[3], rrt[3], curve[3], out[3];
	for (int c = 0; c < 3; c++) {
		in[c] = (r_rgb[c] > 0.0f ? double(r_rgb[c]) : 0.0) * bias;
	}
	_mat3_mul(ACES_INPUT, in, rrt);
	for (int c = 0; c < 3; c++) {
		curve[c] = _aces_rrt_odt(rrt[c]);
	}
	_mat3_mul(ACES_OUTPUT, curve, out);
	const double white = _aces_rrt_odt(double(p_white) * bias);
	for (int c = 0; c < 3; c++) {
		r_rgb[c] = float(out[c] / white);
	}
}

// Benjamin Wrensch 2023, "Minimal AgX Implementation" (iolite engine blog): Troy Sobotka's AgX base with
// Blender's inset matrix (rows below, acting on linear sRGB), its inverse, the log2 range and the polynomial
// fit of the default contrast curve (mean squared error 3.67e-6 on [0, 1]).
static const double AGX_INSET[3][3] = {
	{ 0.842479062253094, 0.0784335999999992, 0.0792237451477643 },
	{ 0.0423282422610123, 0.878468636469772, 0.0791661274605434 },
	{ 0.0423756549057051, 0.0784336, 0.879142973793104 },
};
static const double AGX_OUTSET[3][3] = {
	{ 1.19687900512017, -0.0980208811401368, -0.0990297440797205 },
	{ -0.0528968517574562, 1.15190312990417, -0.0989611768448433 },
	{ -0.0529716355144438, -0.0980434501171241, 1.15107367264116 },
};

void Tonemap::agx(float *r_rgb) {
	const double min_ev = -12.47393, max_ev = 4.026069;
	double in[3], inset[3], curve[3], out[3];
	for (int c = 0; c < 3; c++) {
		in[c] = r_rgb[c] > 0.0f ? double(r_rgb[c]) : 0.0;
	}
	_mat3_mul(AGX_INSET, in, inset);
	for (int c = 0; c < 3; c++) {
		double ev = std::log2(std::fmax(inset[c], 1e-10));
		ev = std::fmin(std::fmax(ev, min_ev), max_ev);
		const double x = (ev - min_ev) / (max_ev - min_ev);
		const double x2 = x * x, x4 = x2 * x2;
		curve[c] = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
	}
	_mat3_mul(AGX_OUTSET, curve, out);
	for (int c = 0; c < 3; c++) {
		r_rgb[c] = float(std::pow(std::fmax(out[c], 0.0), 2.2)); // The curve is display-encoded; back to linear.
	}
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

void Tonemap::map_linear(float *r_rgb, const Settings &p_settings, float p_exposure_ev) {
	const float scale = p_settings.exposure * std::exp2(p_exposure_ev);
	for (int c = 0; c < 3; c++) {
		float x = r_rgb[c];
		x = (std::isnan(x) || !(x > 0.0f)) ? 0.0f : x * scale;
		// +infinity: a large finite value, so the curves reach their limit instead of inf/inf.
		r_rgb[c] = std::isinf(x) || std::isnan(x) ? 1e30f : x;
	}
	switch (p_settings.mode) {
		case MODE_ACES_FITTED:
			for (int c = 0; c < 3; c++) {
				r_rgb[c] = aces_fitted(r_rgb[c]);
			}
			break;
		case MODE_REINHARD:
			for (int c = 0; c < 3; c++) {
				r_rgb[c] = r_rgb[c] >= 1e30f ? 1.0f : reinhard(r_rgb[c], p_settings.white);
			}
			break;
		case MODE_FILMIC:
			for (int c = 0; c < 3; c++) {
				r_rgb[c] = filmic(r_rgb[c], p_settings.white);
			}
			break;
		case MODE_ACES:
			aces(r_rgb, p_settings.white);
			break;
		case MODE_AGX:
			agx(r_rgb);
			break;
		case MODE_LINEAR:
		default:
			break;
	}
	for (int c = 0; c < 3; c++) {
		r_rgb[c] = _clamp01(r_rgb[c]);
	}
}

uint8_t Tonemap::map_channel(float p_linear, float p_exposure_ev, Mode p_mode) {
	if (std::isnan(p_linear) || !(p_linear > 0.0f)) {
		return 0;
	}
	Settings settings;
	settings.mode = p_mode == MODE_ACES || p_mode == MODE_AGX ? MODE_LINEAR : p_mode; // Cross-channel modes: use apply().
	float rgb[3] = { p_linear, 0.0f, 0.0f };
	map_linear(rgb, settings, p_exposure_ev);
	return _to_byte(linear_to_srgb(rgb[0]));
}

uint8_t Tonemap::map_alpha(float p_alpha) {
	return _to_byte(p_alpha);
}

std::vector<uint8_t> Tonemap::apply(const Image &p_hdr, float p_exposure_ev, Mode p_mode) {
	Settings settings;
	settings.mode = p_mode;
	return apply(p_hdr, settings, p_exposure_ev);
}

std::vector<uint8_t> Tonemap::apply(const Image &p_hdr, const Settings &p_settings, float p_exposure_ev) {
	std::vector<uint8_t> out;
	ERR_FAIL_COND_V_MSG(p_hdr.is_empty(), out, "Cannot tonemap an empty image.");
	ERR_FAIL_INDEX_V_MSG((int)p_settings.mode, (int)MODE_MAX, out, "Unknown tonemap mode.");
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_exposure_ev), out, "Tonemap exposure must be finite.");
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_settings.exposure) || !(p_settings.exposure > 0.0f), out, vformat("tonemap_exposure must be finite and > 0; got %s.", rtos(p_settings.exposure).c_str()));
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_settings.white) || !(p_settings.white > 0.0f), out, vformat("tonemap_white must be finite and > 0; got %s.", rtos(p_settings.white).c_str()));
	const std::vector<float> &data = p_hdr.get_data();
	out.resize(data.size());
	for (size_t i = 0; i < data.size(); i += Image::CHANNELS) {
		float rgb[3] = { data[i + 0], data[i + 1], data[i + 2] };
		map_linear(rgb, p_settings, p_exposure_ev);
		for (int c = 0; c < 3; c++) {
			out[i + c] = _to_byte(linear_to_srgb(rgb[c]));
		}
		out[i + 3] = map_alpha(data[i + 3]);
	}
	return out;
}
