/**************************************************************************/
/*  image_metrics.cpp                                                     */
/**************************************************************************/
/* godot-area: image error metrics, see image_metrics.h.                  */

#include "modules/metrics/image_metrics.h"

#include "core/error/error_macros.h"
#include "core/io/tonemap.h"
#include "drivers/png/png_reader.h"
#include "modules/metrics/heatmap.h"
#include "modules/metrics/ssim.h"
#include "modules/openexr/image_loader_exr.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace {

bool _fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

// JSON number (JSON has no NaN or infinity; those become null).
String _json_number(double p_value) {
	return std::isfinite(p_value) ? vformat("%.9g", p_value) : String("null");
}

String _lower_extension(const String &p_path) {
	const size_t dot = p_path.find_last_of('.');
	const size_t slash = p_path.find_last_of("/\\");
	if (dot == String::npos || (slash != String::npos && dot < slash)) {
		return String();
	}
	String ext = p_path.substr(dot + 1);
	std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	return ext;
}

// Pearson correlation, ISR eq. (20), with population mean and standard deviation.
double _pearson(const std::vector<double> &p_x, const std::vector<double> &p_y) {
	const size_t n = p_x.size();
	double mx = 0.0, my = 0.0;
	for (size_t i = 0; i < n; i++) {
		mx += p_x[i];
		my += p_y[i];
	}
	mx /= double(n);
	my /= double(n);
	double sxx = 0.0, syy = 0.0, sxy = 0.0;
	for (size_t i = 0; i < n; i++) {
		const double dx = p_x[i] - mx;
		const double dy = p_y[i] - my;
		sxx += dx * dx;
		syy += dy * dy;
		sxy += dx * dy;
	}
	if (sxx <= 0.0 || syy <= 0.0) {
		// Undefined by eq. (20); our convention (see image_metrics.h).
		return p_x == p_y ? 1.0 : 0.0;
	}
	// (1/n) sum(z_x z_y) with sigma = sqrt(s/n) equals sxy / sqrt(sxx syy).
	return Math::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
}

} // namespace

bool ImageMetrics::compare(const Image &p_image, const Image &p_reference, Result *r_result, String *r_error, const Options &p_options) {
	if (!r_result) {
		return _fail(r_error, "ImageMetrics: no result object given.");
	}
	*r_result = Result();
	if (p_image.is_empty()) {
		return _fail(r_error, "ImageMetrics: the image is empty.");
	}
	if (p_reference.is_empty()) {
		return _fail(r_error, "ImageMetrics: the reference image is empty.");
	}
	if (p_image.get_width() != p_reference.get_width() || p_image.get_height() != p_reference.get_height()) {
		return _fail(r_error, vformat("ImageMetrics: image sizes differ (image %dx%d, reference %dx%d).", p_image.get_width(), p_image.get_height(), p_reference.get_width(), p_reference.get_height()));
	}
	if (!p_image.is_finite()) {
		return _fail(r_error, "ImageMetrics: the image has non-finite (NaN or infinite) pixels.");
	}
	if (!p_reference.is_finite()) {
		return _fail(r_error, "ImageMetrics: the reference image has non-finite (NaN or infinite) pixels.");
	}
	if (!(p_options.ppd > 0.0f) || !std::isfinite(p_options.ppd)) {
		return _fail(r_error, vformat("ImageMetrics: pixels per degree must be positive and finite (got %g).", double(p_options.ppd)));
	}

	Result &r = *r_result;
	r.width = p_image.get_width();
	r.height = p_image.get_height();
	r.ppd = p_options.ppd;
	const size_t count = (size_t)r.width * r.height;
	const float *a = p_image.ptr();
	const float *b = p_reference.ptr();

	double sum_sq = 0.0, sum_rel = 0.0, sum_abs = 0.0, sum_ref_sq = 0.0, sum_a = 0.0, sum_b = 0.0;
	std::vector<double> lum_a(count), lum_b(count);
	std::vector<float> ssim_a(count), ssim_b(count);
	for (size_t i = 0; i < count; i++) {
		const float *pa = a + i * Image::CHANNELS;
		const float *pb = b + i * Image::CHANNELS;
		float enc_a[3], enc_b[3];
		for (int c = 0; c < 3; c++) {
			const double d = double(pa[c]) - double(pb[c]);
			sum_sq += d * d;
			sum_rel += d * d / (double(pb[c]) * pb[c] + RELATIVE_MSE_EPSILON);
			sum_abs += std::fabs(d);
			sum_ref_sq += double(pb[c]) * pb[c];
			sum_a += pa[c];
			sum_b += pb[c];
			enc_a[c] = Tonemap::linear_to_srgb(Math::clamp(pa[c], 0.0f, 1.0f));
			enc_b[c] = Tonemap::linear_to_srgb(Math::clamp(pb[c], 0.0f, 1.0f));
		}
		lum_a[i] = 0.27 * pa[0] + 0.67 * pa[1] + 0.06 * pa[2];
		lum_b[i] = 0.27 * pb[0] + 0.67 * pb[1] + 0.06 * pb[2];
		ssim_a[i] = luminance(enc_a[0], enc_a[1], enc_a[2]);
		ssim_b[i] = luminance(enc_b[0], enc_b[1], enc_b[2]);
	}
	const double values = 3.0 * double(count);
	r.rmse = std::sqrt(sum_sq / values);
	r.relative_mse = sum_rel / values;
	const double nan = std::numeric_limits<double>::quiet_NaN();
	r.relative_rmse = sum_ref_sq > 0.0 ? std::sqrt(sum_sq / sum_ref_sq) : nan;
	r.brightness_ratio = sum_b > 0.0 ? sum_a / sum_b : nan;
	r.mae = sum_abs / values;
	r.pearson = _pearson(lum_a, lum_b);
	r.ssim = SSIM::compute(ssim_a, ssim_b, r.width, r.height);

	float mean = 0.0f;
	if (!FLIP::compute_ldr(p_image, p_reference, p_options.ppd, r.flip_map, &mean, r_error)) {
		return false;
	}
	r.flip = mean;
	if (p_options.hdr_flip) {
		if (!FLIP::compute_hdr(p_image, p_reference, p_options.ppd, r.hdr_flip_map, &mean, &r.hdr_exposures, r_error)) {
			return false;
		}
		r.hdr_flip = mean;
		r.has_hdr_flip = true;
	}
	return true;
}

bool ImageMetrics::compare(const Image &p_image, const Image &p_reference, Result *r_result, String *r_error) {
	return compare(p_image, p_reference, r_result, r_error, Options());
}

bool ImageMetrics::load_image(const String &p_path, Image &r_image, String *r_error) {
	const String ext = _lower_extension(p_path);
	if (ext == "exr") {
		return ImageLoaderEXR::load(p_path, r_image, r_error);
	}
	if (ext == "png") {
		std::vector<uint8_t> rgba;
		int w = 0, h = 0;
		if (!PNGReader::load(p_path, rgba, w, h, r_error)) {
			return false;
		}
		if (!r_image.create(w, h)) {
			return _fail(r_error, vformat("Cannot use PNG \"%s\": unsupported size %dx%d.", p_path.c_str(), w, h));
		}
		float *dst = r_image.ptrw();
		for (size_t i = 0; i < (size_t)w * h * 4; i++) {
			const float v = rgba[i] / 255.0f;
			dst[i] = (i % 4 == 3) ? v : Color::srgb_to_linear_channel(v);
		}
		return true;
	}
	return _fail(r_error, vformat("Cannot load \"%s\": unsupported file type (expected .exr or .png).", p_path.c_str()));
}

bool ImageMetrics::compare_files(const String &p_image_path, const String &p_reference_path, Result *r_result, String *r_error, const Options &p_options, const String &p_heatmap_path) {
	Image image;
	Image reference;
	if (!load_image(p_image_path, image, r_error) || !load_image(p_reference_path, reference, r_error)) {
		return false;
	}
	if (!compare(image, reference, r_result, r_error, p_options)) {
		return false;
	}
	if (!p_heatmap_path.empty()) {
		return Heatmap::write_png(r_result->flip_map, r_result->width, r_result->height, 1.0f, p_heatmap_path, r_error);
	}
	return true;
}

String ImageMetrics::Result::to_json() const {
	String s = "{";
	s += vformat("\"width\":%d,\"height\":%d", width, height);
	s += ",\"rmse\":" + _json_number(rmse);
	s += ",\"relative_mse\":" + _json_number(relative_mse);
	s += ",\"relative_rmse\":" + _json_number(relative_rmse);
	s += ",\"brightness_ratio\":" + _json_number(brightness_ratio);
	s += ",\"mae\":" + _json_number(mae);
	s += ",\"pearson\":" + _json_number(pearson);
	s += ",\"ssim\":" + _json_number(ssim);
	s += ",\"flip\":" + _json_number(flip);
	s += ",\"ppd\":" + _json_number(ppd);
	if (has_hdr_flip) {
		s += ",\"hdr_flip\":" + _json_number(hdr_flip);
		s += ",\"hdr_flip_exposures\":{\"start\":" + _json_number(hdr_exposures.start_exposure) + ",\"stop\":" + _json_number(hdr_exposures.stop_exposure) + vformat(",\"count\":%d}", hdr_exposures.count);
	}
	s += "}";
	return s;
}

String ImageMetrics::Result::to_text() const {
	String s;
	s += vformat("size:         %dx%d\n", width, height);
	s += vformat("RMSE:         %.6g\n", rmse);
	s += vformat("relMSE:       %.6g\n", relative_mse);
	s += vformat("relRMSE:      %.6g (radiance)\n", relative_rmse);
	s += vformat("ratio:        %.6g (mean brightness, image / reference)\n", brightness_ratio);
	s += vformat("MAE:          %.6g\n", mae);
	s += vformat("Pearson:      %.6f\n", pearson);
	s += vformat("SSIM:         %.6f\n", ssim);
	s += vformat("LDR-FLIP:     %.6f (%.1f PPD)\n", flip, double(ppd));
	if (has_hdr_flip) {
		s += vformat("HDR-FLIP:     %.6f (exposures %.2f..%.2f, %d)\n", hdr_flip, double(hdr_exposures.start_exposure), double(hdr_exposures.stop_exposure), hdr_exposures.count);
	}
	return s;
}
