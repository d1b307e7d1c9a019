/**************************************************************************/
/*  flip.cpp                                                              */
/**************************************************************************/
/* godot-area: LDR-FLIP and HDR-FLIP, see flip.h. Every constant below    */
/* names where it comes from. "Paper" = the FLIP paper (HPG 2020);        */
/* section references are to its "colour pipeline" and "feature           */
/* pipeline" parts. Written from the paper; the constants were checked    */
/* against the authors' public description of their reference code        */
/* (facts only, no code taken). Known small deviation: our D65 white and  */
/* RGB<->XYZ matrices are the IEC 61966-2-1 ones (white = row sums), the  */
/* reference code's differ in the 4th-5th digit.                          */

#include "modules/metrics/flip.h"

#include "core/error/error_macros.h"
#include "core/io/tonemap.h"
#include "core/math/math_funcs.h"
#include "modules/metrics/metrics_filter.h"

#include <algorithm>
#include <cmath>

namespace {

// --- Colour spaces ---------------------------------------------------------------------------------
// Linear sRGB (Rec. 709 primaries, D65 white) to CIE XYZ and back: IEC 61966-2-1 matrices. The
// reference white (Xn, Yn, Zn) is XYZ of linear RGB (1, 1, 1), i.e. D65 as these matrices define it.
constexpr float RGB_TO_XYZ[3][3] = {
	{ 0.4124564f, 0.3575761f, 0.1804375f },
	{ 0.2126729f, 0.7151522f, 0.0721750f },
	{ 0.0193339f, 0.1191920f, 0.9503041f },
};
constexpr float XYZ_TO_RGB[3][3] = {
	{ 3.2404542f, -1.5371385f, -0.4985314f },
	{ -0.9692660f, 1.8760108f, 0.0415560f },
	{ 0.0556434f, -0.2040259f, 1.0572252f },
};
constexpr float WHITE_X = 0.4124564f + 0.3575761f + 0.1804375f;
constexpr float WHITE_Y = 0.2126729f + 0.7151522f + 0.0721750f;
constexpr float WHITE_Z = 0.0193339f + 0.1191920f + 0.9503041f;

// --- Colour pipeline constants (paper, colour pipeline) --------------------------------------------
// Contrast sensitivity functions as sums of two Gaussians in frequency f (cycles/degree):
//   S(f) = a1 exp(-b1 f^2) + a2 exp(-b2 f^2)
// whose spatial counterpart (x in degrees) the paper writes as
//   s(x) = a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2).
// We use that expression with x = radial distance / PPD for the 2D kernel (as the paper does, keeping
// the 1D weight sqrt(pi / b) rather than the exact 2D Fourier pair's pi / b) and normalise each
// channel's kernel to sum 1. Borders replicate the edge pixel.
struct CSFParams {
	float a1, b1, a2, b2;
};
constexpr CSFParams CSF_ACHROMATIC = { 1.0f, 0.0047f, 0.0f, 1e-5f }; // Y channel.
constexpr CSFParams CSF_RED_GREEN = { 1.0f, 0.0053f, 0.0f, 1e-5f }; // Cx channel.
constexpr CSFParams CSF_BLUE_YELLOW = { 34.1f, 0.04f, 13.5f, 0.025f }; // Cz channel.
// Kernel radius (paper): r = ceil(3 * sqrt(b_max / (2 pi^2)) * PPD), b_max = largest b above (0.04),
// i.e. three standard deviations of the widest Gaussian; one radius is used for all three channels.
constexpr float CSF_B_MAX = 0.04f;

// Colour difference (paper, colour metric): HyAB distance |dL| + sqrt(da^2 + db^2) on Hunt-adjusted
// L*a*b* (a and b scaled by 0.01 L), raised to QC = 0.7. The largest difference cmax is that between
// pure green (0, 1, 0) and pure blue (0, 0, 1) linear RGB. Values below PC * cmax are mapped linearly
// to [0, PT]; the rest linearly from [PC * cmax, cmax] to [PT, 1] (PC = 0.4, PT = 0.95).
constexpr float QC = 0.7f;
constexpr float PC = 0.4f;
constexpr float PT = 0.95f;

// --- Feature pipeline constants (paper, feature pipeline) ------------------------------------------
// Edge and point detectors are the first and second derivatives of a 2D Gaussian with
// sigma = 0.5 * W * PPD pixels, W = 0.082 degrees (the paper's feature width), radius ceil(3 sigma).
// Normalisation: the positive weights of each kernel sum to 1 and the negative ones to -1.
// The feature difference is (max(|edge_r - edge_t|, |point_r - point_t|) / sqrt(2))^QF, QF = 0.5.
constexpr float FEATURE_WIDTH_DEGREES = 0.082f;
constexpr float QF = 0.5f;

// HDR-FLIP (Eurographics 2021 short paper): exposures run from the one that maps the reference's
// largest luminance to tonemapped 0.85 up to the one that maps its median luminance (50th
// percentile) to 0.85, with max(2, ceil(stop - start)) evenly spaced exposures; luminance uses the
// Rec. 709 weights. The tonemapper is Narkowicz's ACES fit applied to 0.6 * x (the fit's usual
// pre-exposure, so exposure values match the paper's; Tonemap::aces_fitted itself has no 0.6).
// Our cap on the exposure count (performance guard) and the fallbacks for black references are ours.
constexpr float HDR_TARGET = 0.85f;
constexpr float HDR_ACES_PRE_EXPOSURE = 0.6f;
constexpr int HDR_MAX_EXPOSURES = 32;

inline float _hdr_tonemap(float p_x) {
	return Tonemap::aces_fitted(HDR_ACES_PRE_EXPOSURE * std::max(0.0f, p_x));
}

// 50th percentile with linear interpolation between the two middle values for even counts.
float _median(std::vector<float> &p_values) {
	const size_t n = p_values.size();
	std::nth_element(p_values.begin(), p_values.begin() + n / 2, p_values.end());
	const float upper = p_values[n / 2];
	if (n % 2 == 1) {
		return upper;
	}
	const float lower = *std::max_element(p_values.begin(), p_values.begin() + n / 2);
	return 0.5f * (lower + upper);
}

inline float _lab_f(float p_t) {
	// CIE 1976 L*a*b* companding, linear segment below (6/29)^3.
	const float delta = 6.0f / 29.0f;
	return p_t > delta * delta * delta ? std::cbrt(p_t) : p_t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

// Linear RGB (clamped to [0, 1]) -> Hunt-adjusted L*a*b*.
inline void _rgb_to_hunt_lab(float p_r, float p_g, float p_b, float r_lab[3]) {
	const float r = Math::clamp(p_r, 0.0f, 1.0f);
	const float g = Math::clamp(p_g, 0.0f, 1.0f);
	const float b = Math::clamp(p_b, 0.0f, 1.0f);
	const float x = (RGB_TO_XYZ[0][0] * r + RGB_TO_XYZ[0][1] * g + RGB_TO_XYZ[0][2] * b) / WHITE_X;
	const float y = (RGB_TO_XYZ[1][0] * r + RGB_TO_XYZ[1][1] * g + RGB_TO_XYZ[1][2] * b) / WHITE_Y;
	const float z = (RGB_TO_XYZ[2][0] * r + RGB_TO_XYZ[2][1] * g + RGB_TO_XYZ[2][2] * b) / WHITE_Z;
	const float fx = _lab_f(x);
	const float fy = _lab_f(y);
	const float fz = _lab_f(z);
	const float l = 116.0f * fy - 16.0f;
	// Hunt effect (paper): chroma is scaled with lightness, a' = 0.01 L a, b' = 0.01 L b.
	r_lab[0] = l;
	r_lab[1] = 0.01f * l * 500.0f * (fx - fy);
	r_lab[2] = 0.01f * l * 200.0f * (fy - fz);
}

inline float _hyab(const float p_a[3], const float p_b[3]) {
	const float da = p_a[1] - p_b[1];
	const float db = p_a[2] - p_b[2];
	return std::fabs(p_a[0] - p_b[0]) + std::sqrt(da * da + db * db);
}

float _cmax() {
	float green[3];
	float blue[3];
	_rgb_to_hunt_lab(0.0f, 1.0f, 0.0f, green);
	_rgb_to_hunt_lab(0.0f, 0.0f, 1.0f, blue);
	return std::pow(_hyab(green, blue), QC);
}

// Adds p_weight * (p_src filtered with the separable Gaussian exp(-pi^2 x^2 / b)) to r_acc.
void _accumulate_csf_term(const std::vector<float> &p_src, int p_width, int p_height, const std::vector<float> &p_kernel, float p_weight, std::vector<float> &r_acc) {
	std::vector<float> filtered;
	MetricsFilter::filter_separable(p_src, p_width, p_height, p_kernel, p_kernel, filtered);
	for (size_t i = 0; i < r_acc.size(); i++) {
		r_acc[i] += p_weight * filtered[i];
	}
}

// Filters one YCxCz plane with the channel's CSF kernel (normalised to sum 1, see above).
std::vector<float> _csf_filter(const std::vector<float> &p_src, int p_width, int p_height, const CSFParams &p_csf, float p_ppd, int p_radius) {
	const float pi = float(Math::PI);
	const CSFParams &c = p_csf;
	const float a[2] = { c.a1, c.a2 };
	const float b[2] = { c.b1, c.b2 };
	std::vector<float> kernels[2];
	double weights[2] = { 0.0, 0.0 };
	double total = 0.0;
	for (int k = 0; k < 2; k++) {
		if (a[k] == 0.0f) {
			continue;
		}
		kernels[k].resize((size_t)(2 * p_radius + 1));
		double sum_1d = 0.0;
		for (int i = -p_radius; i <= p_radius; i++) {
			const double x = double(i) / double(p_ppd); // Degrees.
			const double v = std::exp(-double(pi) * pi * x * x / b[k]);
			kernels[k][i + p_radius] = float(v);
			sum_1d += v;
		}
		weights[k] = double(a[k]) * std::sqrt(double(pi) / b[k]);
		total += weights[k] * sum_1d * sum_1d; // Sum of the 2D kernel term.
	}
	std::vector<float> result(p_src.size(), 0.0f);
	for (int k = 0; k < 2; k++) {
		if (!kernels[k].empty()) {
			_accumulate_csf_term(p_src, p_width, p_height, kernels[k], float(weights[k] / total), result);
		}
	}
	return result;
}

struct FeatureKernels {
	std::vector<float> gaussian; // Sums to 1.
	std::vector<float> first; // 1st derivative; positive weights sum to 1 (negative to -1).
	std::vector<float> second; // 2nd derivative; positive weights sum to 1, negative to -1.
};

FeatureKernels _feature_kernels(float p_ppd) {
	const double sigma = 0.5 * FEATURE_WIDTH_DEGREES * p_ppd;
	const int radius = std::max(1, int(std::ceil(3.0 * sigma)));
	FeatureKernels k;
	k.gaussian.resize((size_t)(2 * radius + 1));
	k.first.resize(k.gaussian.size());
	k.second.resize(k.gaussian.size());
	double g_sum = 0.0, first_pos = 0.0, second_pos = 0.0, second_neg = 0.0;
	for (int i = -radius; i <= radius; i++) {
		const double g = std::exp(-double(i) * i / (2.0 * sigma * sigma));
		const double d1 = -double(i) / (sigma * sigma) * g;
		const double d2 = (double(i) * i / (sigma * sigma) - 1.0) / (sigma * sigma) * g;
		k.gaussian[i + radius] = float(g);
		k.first[i + radius] = float(d1);
		k.second[i + radius] = float(d2);
		g_sum += g;
		first_pos += d1 > 0.0 ? d1 : 0.0;
		second_pos += d2 > 0.0 ? d2 : 0.0;
		second_neg += d2 < 0.0 ? -d2 : 0.0;
	}
	// The 2D kernels are products (derivative along one axis) x (Gaussian along the other); the sign of
	// a weight depends only on the derivative factor, so normalising the 1D factors normalises the 2D
	// kernels' positive and negative parts as the paper asks.
	for (size_t i = 0; i < k.gaussian.size(); i++) {
		k.gaussian[i] = float(k.gaussian[i] / g_sum);
		k.first[i] = first_pos > 0.0 ? float(k.first[i] / first_pos) : 0.0f;
		const float d2 = k.second[i];
		k.second[i] = d2 > 0.0f ? (second_pos > 0.0 ? float(d2 / second_pos) : 0.0f) : (second_neg > 0.0 ? float(d2 / second_neg) : 0.0f);
	}
	return k;
}

// Edge and point magnitudes of an achromatic plane.
void _features(const std::vector<float> &p_plane, int p_width, int p_height, const FeatureKernels &p_k, std::vector<float> &r_edge, std::vector<float> &r_point) {
	std::vector<float> ex, ey, px, py;
	MetricsFilter::filter_separable(p_plane, p_width, p_height, p_k.first, p_k.gaussian, ex);
	MetricsFilter::filter_separable(p_plane, p_width, p_height, p_k.gaussian, p_k.first, ey);
	MetricsFilter::filter_separable(p_plane, p_width, p_height, p_k.second, p_k.gaussian, px);
	MetricsFilter::filter_separable(p_plane, p_width, p_height, p_k.gaussian, p_k.second, py);
	r_edge.resize(p_plane.size());
	r_point.resize(p_plane.size());
	for (size_t i = 0; i < p_plane.size(); i++) {
		r_edge[i] = std::sqrt(ex[i] * ex[i] + ey[i] * ey[i]);
		r_point[i] = std::sqrt(px[i] * px[i] + py[i] * py[i]);
	}
}

// Per-image part of the pipeline: Hunt-adjusted L*a*b* of the CSF-filtered image (3 floats per pixel)
// and the edge / point feature magnitudes of the unfiltered achromatic channel.
struct Prepared {
	std::vector<float> lab;
	std::vector<float> edge;
	std::vector<float> point;
};

Prepared _prepare(const std::vector<float> &p_rgb, int p_width, int p_height, float p_ppd, const FeatureKernels &p_features) {
	const size_t count = (size_t)p_width * p_height;
	// Linear RGB -> YCxCz (the paper's opponent space: L*a*b* without the cube root):
	// Y' = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn).
	std::vector<float> ych(count), cx(count), cz(count), achromatic(count);
	for (size_t i = 0; i < count; i++) {
		const float r = p_rgb[i * 3 + 0];
		const float g = p_rgb[i * 3 + 1];
		const float b = p_rgb[i * 3 + 2];
		const float x = (RGB_TO_XYZ[0][0] * r + RGB_TO_XYZ[0][1] * g + RGB_TO_XYZ[0][2] * b) / WHITE_X;
		const float y = (RGB_TO_XYZ[1][0] * r + RGB_TO_XYZ[1][1] * g + RGB_TO_XYZ[1][2] * b) / WHITE_Y;
		const float z = (RGB_TO_XYZ[2][0] * r + RGB_TO_XYZ[2][1] * g + RGB_TO_XYZ[2][2] * b) / WHITE_Z;
		ych[i] = 116.0f * y - 16.0f;
		cx[i] = 500.0f * (x - y);
		cz[i] = 200.0f * (y - z);
		// Feature pipeline input (paper): the achromatic channel normalised to [0, 1], (Y' + 16) / 116.
		achromatic[i] = y;
	}

	const int radius = std::max(1, int(std::ceil(3.0 * std::sqrt(double(CSF_B_MAX) / (2.0 * Math::PI * Math::PI)) * p_ppd)));
	const std::vector<float> fy = _csf_filter(ych, p_width, p_height, CSF_ACHROMATIC, p_ppd, radius);
	const std::vector<float> fcx = _csf_filter(cx, p_width, p_height, CSF_RED_GREEN, p_ppd, radius);
	const std::vector<float> fcz = _csf_filter(cz, p_width, p_height, CSF_BLUE_YELLOW, p_ppd, radius);

	Prepared p;
	p.lab.resize(count * 3);
	for (size_t i = 0; i < count; i++) {
		// YCxCz -> XYZ -> linear RGB; the filtered colour is clamped per channel to [0, 1] (the RGB
		// cube) before L*a*b* (paper).
		const float y = (fy[i] + 16.0f) / 116.0f;
		const float x = (fcx[i] / 500.0f + y) * WHITE_X;
		const float z = (y - fcz[i] / 200.0f) * WHITE_Z;
		const float yy = y * WHITE_Y;
		const float r = XYZ_TO_RGB[0][0] * x + XYZ_TO_RGB[0][1] * yy + XYZ_TO_RGB[0][2] * z;
		const float g = XYZ_TO_RGB[1][0] * x + XYZ_TO_RGB[1][1] * yy + XYZ_TO_RGB[1][2] * z;
		const float b = XYZ_TO_RGB[2][0] * x + XYZ_TO_RGB[2][1] * yy + XYZ_TO_RGB[2][2] * z;
		_rgb_to_hunt_lab(r, g, b, &p.lab[i * 3]);
	}
	_features(achromatic, p_width, p_height, p_features, p.edge, p.point);
	return p;
}

bool _fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

bool _validate(const Image &p_test, const Image &p_reference, float p_ppd, String *r_error) {
	if (p_test.is_empty() || p_reference.is_empty()) {
		return _fail(r_error, vformat("FLIP: the %s image is empty.", p_test.is_empty() ? "test" : "reference"));
	}
	if (p_test.get_width() != p_reference.get_width() || p_test.get_height() != p_reference.get_height()) {
		return _fail(r_error, vformat("FLIP: image sizes differ (test %dx%d, reference %dx%d).", p_test.get_width(), p_test.get_height(), p_reference.get_width(), p_reference.get_height()));
	}
	if (!p_test.is_finite() || !p_reference.is_finite()) {
		return _fail(r_error, vformat("FLIP: the %s image has non-finite (NaN or infinite) pixels.", p_test.is_finite() ? "reference" : "test"));
	}
	if (!(p_ppd > 0.0f) || !std::isfinite(p_ppd)) {
		return _fail(r_error, vformat("FLIP: pixels per degree must be positive and finite (got %g).", double(p_ppd)));
	}
	return true;
}

// RGB planes (3 floats per pixel) of an image after p_map is applied to each colour channel.
template <typename F>
std::vector<float> _rgb(const Image &p_image, F p_map) {
	const size_t count = (size_t)p_image.get_width() * p_image.get_height();
	std::vector<float> rgb(count * 3);
	const float *src = p_image.ptr();
	for (size_t i = 0; i < count; i++) {
		for (int c = 0; c < 3; c++) {
			rgb[i * 3 + c] = p_map(src[i * Image::CHANNELS + c]);
		}
	}
	return rgb;
}

float _mean(const std::vector<float> &p_values) {
	double sum = 0.0;
	for (float v : p_values) {
		sum += v;
	}
	return p_values.empty() ? 0.0f : float(sum / double(p_values.size()));
}

} // namespace

float FLIP::compute_ppd(float p_distance_m, float p_monitor_width_m, float p_monitor_width_px) {
	ERR_FAIL_COND_V_MSG(!(p_monitor_width_m > 0.0f) || !(p_distance_m > 0.0f) || !(p_monitor_width_px > 0.0f), DEFAULT_PPD,
			"FLIP: viewing distance, monitor width and resolution must be positive; using the default PPD.");
	return float(double(p_distance_m) * (double(p_monitor_width_px) / p_monitor_width_m) * (Math::PI / 180.0));
}

void FLIP::compute_ldr_rgb(const std::vector<float> &p_test_rgb, const std::vector<float> &p_reference_rgb, int p_width, int p_height, float p_ppd, std::vector<float> &r_map) {
	r_map.clear();
	const size_t count = (size_t)std::max(0, p_width) * (size_t)std::max(0, p_height);
	ERR_FAIL_COND_MSG(count == 0 || p_test_rgb.size() != count * 3 || p_reference_rgb.size() != count * 3,
			vformat("FLIP: RGB planes of %zu and %zu floats do not match %dx%d.", p_test_rgb.size(), p_reference_rgb.size(), p_width, p_height));

	static const float cmax = _cmax();
	const FeatureKernels kernels = _feature_kernels(p_ppd);
	const Prepared ref = _prepare(p_reference_rgb, p_width, p_height, p_ppd, kernels);
	const Prepared test = _prepare(p_test_rgb, p_width, p_height, p_ppd, kernels);

	r_map.resize(count);
	const float knee = PC * cmax;
	for (size_t i = 0; i < count; i++) {
		// Colour difference, mapped to [0, 1].
		const float de = std::pow(_hyab(&ref.lab[i * 3], &test.lab[i * 3]), QC);
		float dec = de < knee ? (PT / knee) * de : PT + (de - knee) / (cmax - knee) * (1.0f - PT);
		dec = Math::clamp(dec, 0.0f, 1.0f);
		// Feature difference.
		const float edge_diff = std::fabs(ref.edge[i] - test.edge[i]);
		const float point_diff = std::fabs(ref.point[i] - test.point[i]);
		const float def = Math::clamp(std::pow(std::max(edge_diff, point_diff) / std::sqrt(2.0f), QF), 0.0f, 1.0f);
		// Combination (paper): dE = dEc ^ (1 - dEf). dEc = 0 stays 0 (avoids pow(0, 0) = 1).
		r_map[i] = dec > 0.0f ? std::pow(dec, 1.0f - def) : 0.0f;
	}
}

bool FLIP::compute_ldr(const Image &p_test, const Image &p_reference, float p_ppd, std::vector<float> &r_map, float *r_mean, String *r_error) {
	r_map.clear();
	if (!_validate(p_test, p_reference, p_ppd, r_error)) {
		return false;
	}
	auto clamp01 = [](float v) { return Math::clamp(v, 0.0f, 1.0f); };
	compute_ldr_rgb(_rgb(p_test, clamp01), _rgb(p_reference, clamp01), p_test.get_width(), p_test.get_height(), p_ppd, r_map);
	if (r_mean) {
		*r_mean = _mean(r_map);
	}
	return true;
}

bool FLIP::compute_hdr(const Image &p_test, const Image &p_reference, float p_ppd, std::vector<float> &r_map, float *r_mean, HDRExposures *r_exposures, String *r_error) {
	r_map.clear();
	if (!_validate(p_test, p_reference, p_ppd, r_error)) {
		return false;
	}
	const int width = p_reference.get_width();
	const int height = p_reference.get_height();
	const size_t count = (size_t)width * height;

	// Reference luminance (Rec. 709 / sRGB weights, linear values; negatives count as 0).
	std::vector<float> luminance(count);
	const float *ref = p_reference.ptr();
	for (size_t i = 0; i < count; i++) {
		const float *p = ref + i * Image::CHANNELS;
		luminance[i] = std::max(0.0f, 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]);
	}
	const float max_lum = *std::max_element(luminance.begin(), luminance.end());
	std::vector<float> positive;
	positive.reserve(count);
	for (float l : luminance) {
		if (l > 0.0f) {
			positive.push_back(l);
		}
	}
	float median_lum = _median(luminance);
	if (!(median_lum > 0.0f) && !positive.empty()) {
		// Mostly black reference (the paper's stop exposure would be infinite): use the median of the
		// lit pixels instead (our choice).
		median_lum = _median(positive);
	}

	HDRExposures exposures;
	if (max_lum > 0.0f && median_lum > 0.0f) {
		// Inverse of the tonemap curve at HDR_TARGET, by bisection (the curve is increasing on [0, 64]).
		float lo = 0.0f, hi = 64.0f;
		for (int i = 0; i < 60; i++) {
			const float mid = 0.5f * (lo + hi);
			(_hdr_tonemap(mid) < HDR_TARGET ? lo : hi) = mid;
		}
		const float inv_target = 0.5f * (lo + hi);
		exposures.start_exposure = std::log2(inv_target / max_lum);
		exposures.stop_exposure = std::log2(inv_target / median_lum);
		exposures.count = std::max(2, int(std::ceil(exposures.stop_exposure - exposures.start_exposure)));
		if (exposures.count > HDR_MAX_EXPOSURES) {
			WARN_PRINT(vformat("HDR-FLIP: exposure range %.2f..%.2f needs %d exposures; capped at %d.", double(exposures.start_exposure), double(exposures.stop_exposure), exposures.count, HDR_MAX_EXPOSURES));
			exposures.count = HDR_MAX_EXPOSURES;
		}
	} else {
		// Black reference: a single exposure of 0 stops.
		exposures.count = 1;
	}

	r_map.assign(count, 0.0f);
	std::vector<float> map;
	for (int e = 0; e < exposures.count; e++) {
		const float ev = exposures.count > 1 ? exposures.start_exposure + (exposures.stop_exposure - exposures.start_exposure) * float(e) / float(exposures.count - 1) : exposures.start_exposure;
		const float scale = std::exp2(ev);
		auto tonemap = [scale](float v) { return _hdr_tonemap(v * scale); };
		compute_ldr_rgb(_rgb(p_test, tonemap), _rgb(p_reference, tonemap), width, height, p_ppd, map);
		for (size_t i = 0; i < count; i++) {
			r_map[i] = std::max(r_map[i], map[i]);
		}
	}
	if (r_mean) {
		*r_mean = _mean(r_map);
	}
	if (r_exposures) {
		*r_exposures = exposures;
	}
	return true;
}
