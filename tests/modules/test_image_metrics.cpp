/**************************************************************************/
/*  test_image_metrics.cpp                                                */
/**************************************************************************/
/* godot-area: tests for ImageMetrics (RMSE, relMSE, MAE, Pearson, SSIM,  */
/* FLIP means, JSON/text output), SSIM and the heatmap writer.            */

#include "modules/metrics/heatmap.h"
#include "modules/metrics/image_metrics.h"
#include "modules/metrics/ssim.h"

#include "drivers/png/png_reader.h"
#include "drivers/png/png_writer.h"
#include "modules/openexr/image_saver_exr.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

namespace TestImageMetrics {

// A deterministic, smoothly varying colour test pattern with some detail.
static Image make_pattern(int p_width, int p_height) {
	Image image(p_width, p_height);
	for (int y = 0; y < p_height; y++) {
		for (int x = 0; x < p_width; x++) {
			const float u = float(x) / float(p_width - 1);
			const float v = float(y) / float(p_height - 1);
			const float checker = ((x / 4 + y / 4) % 2) ? 0.15f : 0.0f;
			image.set_pixel(x, y, Color(0.1f + 0.6f * u + checker, 0.2f + 0.5f * v, 0.3f + 0.3f * u * v + checker, 1.0f));
		}
	}
	return image;
}

// p_image plus uniform noise of the given amplitude in [-amp, amp], per channel, fixed seed.
static Image add_noise(const Image &p_image, float p_amplitude, unsigned p_seed = 1234) {
	Image out = p_image;
	std::mt19937 rng(p_seed);
	std::uniform_real_distribution<float> dist(-1.0f, 1.0f);
	float *d = out.ptrw();
	for (size_t i = 0; i < out.get_data().size(); i++) {
		if (i % 4 != 3) {
			d[i] += p_amplitude * dist(rng);
		}
	}
	return out;
}

static ImageMetrics::Options ldr_only() {
	ImageMetrics::Options options;
	options.hdr_flip = false;
	return options;
}

TEST_CASE("[Metrics] identical images give zero error and perfect similarity") {
	const Image image = make_pattern(32, 32);
	ImageMetrics::Result r;
	String error;
	REQUIRE(ImageMetrics::compare(image, image, &r, &error));
	CHECK(error.empty());
	CHECK(r.width == 32);
	CHECK(r.height == 32);
	CHECK(r.rmse == 0.0);
	CHECK(r.relative_mse == 0.0);
	CHECK(r.relative_rmse == 0.0);
	CHECK(r.brightness_ratio == 1.0);
	CHECK(r.mae == 0.0);
	CHECK(r.pearson == doctest::Approx(1.0).epsilon(1e-9));
	CHECK(r.ssim == doctest::Approx(1.0).epsilon(1e-9));
	CHECK(r.flip == 0.0);
	REQUIRE(r.has_hdr_flip);
	CHECK(r.hdr_flip == 0.0);
	CHECK(r.flip_map.size() == 32u * 32u);
	CHECK(r.hdr_flip_map.size() == 32u * 32u);
}

TEST_CASE("[Metrics] a constant offset gives the analytic RMSE, MAE and relative MSE") {
	const Image reference(16, 8, Color(0.5f, 0.25f, 1.0f, 1.0f));
	const Image image(16, 8, Color(0.6f, 0.35f, 1.1f, 1.0f)); // +0.1 on every colour channel.
	ImageMetrics::Result r;
	REQUIRE(ImageMetrics::compare(image, reference, &r, nullptr, ldr_only()));
	CHECK(r.rmse == doctest::Approx(0.1).epsilon(1e-5));
	CHECK(r.mae == doctest::Approx(0.1).epsilon(1e-5));
	const double eps = ImageMetrics::RELATIVE_MSE_EPSILON;
	const double expected_rel = (0.01 / (0.25 + eps) + 0.01 / (0.0625 + eps) + 0.01 / (1.0 + eps)) / 3.0;
	CHECK(r.relative_mse == doctest::Approx(expected_rel).epsilon(1e-4));
	// Radiance errors: sum d^2 = 3 n 0.01 over sum b^2 = n (0.25 + 0.0625 + 1); sum a / sum b.
	CHECK(r.relative_rmse == doctest::Approx(std::sqrt(0.03 / 1.3125)).epsilon(1e-4));
	CHECK(r.brightness_ratio == doctest::Approx(2.05 / 1.75).epsilon(1e-5));
	// Alpha is ignored.
	Image alpha_changed = reference;
	alpha_changed.fill(Color(0.5f, 0.25f, 1.0f, 0.0f));
	REQUIRE(ImageMetrics::compare(alpha_changed, reference, &r, nullptr, ldr_only()));
	CHECK(r.rmse == 0.0);
}

TEST_CASE("[Metrics] MAE follows ISR eq. 19 for mixed per-channel differences") {
	Image reference(2, 1, Color(0, 0, 0, 1));
	Image image(2, 1, Color(0, 0, 0, 1));
	image.set_pixel(0, 0, Color(0.3f, -0.6f, 0.0f, 1.0f));
	image.set_pixel(1, 0, Color(0.0f, 0.0f, 0.9f, 1.0f));
	ImageMetrics::Result r;
	REQUIRE(ImageMetrics::compare(image, reference, &r, nullptr, ldr_only()));
	CHECK(r.mae == doctest::Approx((0.3 + 0.6 + 0.9) / 6.0).epsilon(1e-5));
	CHECK(r.rmse == doctest::Approx(std::sqrt((0.09 + 0.36 + 0.81) / 6.0)).epsilon(1e-5));
	// A black reference has no relative error: NaN, and null in JSON (never a made-up number).
	CHECK(std::isnan(r.relative_rmse));
	CHECK(std::isnan(r.brightness_ratio));
	CHECK(r.to_json().find("\"relative_rmse\":null") != String::npos);
}

TEST_CASE("[Metrics] Pearson is 1 for an affine transform and -1 for a negated image") {
	const Image image = make_pattern(24, 20);
	Image affine = image;
	Image negated = image;
	for (int y = 0; y < image.get_height(); y++) {
		for (int x = 0; x < image.get_width(); x++) {
			const Color c = image.get_pixel(x, y);
			affine.set_pixel(x, y, Color(2.5f * c.r + 0.3f, 2.5f * c.g + 0.3f, 2.5f * c.b + 0.3f, 1.0f));
			negated.set_pixel(x, y, Color(-c.r, -c.g, -c.b, 1.0f));
		}
	}
	ImageMetrics::Result r;
	REQUIRE(ImageMetrics::compare(affine, image, &r, nullptr, ldr_only()));
	CHECK(r.pearson == doctest::Approx(1.0).epsilon(1e-6));
	CHECK(r.rmse > 0.1);
	REQUIRE(ImageMetrics::compare(negated, image, &r, nullptr, ldr_only()));
	CHECK(r.pearson == doctest::Approx(-1.0).epsilon(1e-6));
	// A noisy copy correlates positively but not perfectly.
	REQUIRE(ImageMetrics::compare(add_noise(image, 0.2f), image, &r, nullptr, ldr_only()));
	CHECK(r.pearson > 0.5);
	CHECK(r.pearson < 0.999);
}

TEST_CASE("[Metrics] SSIM decreases monotonically with noise amplitude") {
	const Image image = make_pattern(48, 48);
	double previous = 1.0;
	for (float amplitude : { 0.01f, 0.03f, 0.1f, 0.3f }) {
		ImageMetrics::Result r;
		REQUIRE(ImageMetrics::compare(add_noise(image, amplitude), image, &r, nullptr, ldr_only()));
		INFO("amplitude ", amplitude, " ssim ", r.ssim);
		CHECK(r.ssim < previous);
		CHECK(r.ssim > -1.0);
		previous = r.ssim;
	}
	CHECK(previous < 0.5);
}

TEST_CASE("[Metrics] SSIM of planes: identical gives 1, wrong sizes give NaN") {
	std::vector<float> plane(7 * 5);
	for (size_t i = 0; i < plane.size(); i++) {
		plane[i] = float(i % 7) / 7.0f;
	}
	std::vector<float> map;
	CHECK(SSIM::compute(plane, plane, 7, 5, &map) == doctest::Approx(1.0f));
	CHECK(map.size() == plane.size());
	std::vector<float> inverted = plane;
	for (float &v : inverted) {
		v = 1.0f - v;
	}
	CHECK(SSIM::compute(plane, inverted, 7, 5) < 0.0f);
	CHECK(std::isnan(SSIM::compute(plane, plane, 8, 5)));
}

TEST_CASE("[Metrics] bad inputs fail with a message naming the problem") {
	const Image a(8, 8);
	const Image b(8, 9);
	ImageMetrics::Result r;
	String error;
	CHECK_FALSE(ImageMetrics::compare(a, b, &r, &error));
	CHECK(error.find("sizes differ") != String::npos);
	CHECK(error.find("8x9") != String::npos);

	error.clear();
	const Image empty;
	CHECK_FALSE(ImageMetrics::compare(empty, a, &r, &error));
	CHECK(error.find("empty") != String::npos);

	error.clear();
	Image nan_image(8, 8);
	nan_image.set_pixel(3, 4, Color(std::numeric_limits<float>::quiet_NaN(), 0, 0, 1));
	CHECK_FALSE(ImageMetrics::compare(a, nan_image, &r, &error));
	CHECK(error.find("reference") != String::npos);
	CHECK(error.find("non-finite") != String::npos);

	error.clear();
	Image inf_image(8, 8);
	inf_image.set_pixel(0, 0, Color(0, std::numeric_limits<float>::infinity(), 0, 1));
	CHECK_FALSE(ImageMetrics::compare(inf_image, a, &r, &error));
	CHECK(error.find("non-finite") != String::npos);

	error.clear();
	CHECK_FALSE(ImageMetrics::load_image("/nonexistent/file.tga", nan_image, &error));
	CHECK(error.find("unsupported file type") != String::npos);
}

TEST_CASE("[Metrics] JSON and text output carry every metric") {
	const Image image = make_pattern(16, 16);
	ImageMetrics::Result r;
	REQUIRE(ImageMetrics::compare(add_noise(image, 0.05f), image, &r));
	const String json = r.to_json();
	CHECK(json.front() == '{');
	CHECK(json.back() == '}');
	for (const char *key : { "\"width\":16", "\"height\":16", "\"rmse\":", "\"relative_mse\":", "\"relative_rmse\":", "\"brightness_ratio\":", "\"mae\":", "\"pearson\":", "\"ssim\":", "\"flip\":", "\"ppd\":", "\"hdr_flip\":", "\"hdr_flip_exposures\":" }) {
		INFO(key);
		CHECK(json.find(key) != String::npos);
	}
	CHECK(json.find("nan") == String::npos);
	const String text = r.to_text();
	CHECK(text.find("RMSE") != String::npos);
	CHECK(text.find("SSIM") != String::npos);
	CHECK(text.find("relRMSE") != String::npos);
	CHECK(text.find("ratio") != String::npos);
	CHECK(text.find("LDR-FLIP") != String::npos);
	CHECK(text.find("HDR-FLIP") != String::npos);
	CHECK(r.hdr_exposures.count >= 2);
	CHECK(r.hdr_flip > 0.0);
}

TEST_CASE("[Metrics] heatmap colour map and PNG writer") {
	const Color lo = Heatmap::map(0.0f);
	const Color hi = Heatmap::map(1.0f);
	CHECK(lo.r + lo.g + lo.b < 0.1f);
	CHECK(hi.r > 0.9f);
	CHECK(hi.g > 0.9f);
	// Lightness grows along the map.
	float previous = -1.0f;
	for (int i = 0; i <= 20; i++) {
		const Color c = Heatmap::map(float(i) / 20.0f);
		const float lum = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
		CHECK(lum > previous);
		previous = lum;
	}
	CHECK(Heatmap::map(5.0f).is_equal_approx(hi));
	CHECK(Heatmap::map(std::numeric_limits<float>::quiet_NaN()).is_equal_approx(lo));

	const std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_metrics_heatmap";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const String path = (dir / "heat.png").string();
	std::vector<float> errors(4 * 2);
	for (size_t i = 0; i < errors.size(); i++) {
		errors[i] = float(i) / 7.0f * 2.0f; // 0..2, shown with max 2.
	}
	String error;
	REQUIRE(Heatmap::write_png(errors, 4, 2, 2.0f, path, &error));
	std::vector<uint8_t> rgba;
	int w = 0, h = 0;
	REQUIRE(PNGReader::load(path, rgba, w, h));
	CHECK(w == 4);
	CHECK(h == 2);
	CHECK(rgba[0] + rgba[1] + rgba[2] < 20); // First pixel: error 0, dark.
	CHECK(rgba[7 * 4 + 1] > 200); // Last pixel: error = max, pale yellow.
	CHECK(rgba[7 * 4 + 3] == 255);

	CHECK_FALSE(Heatmap::write_png(errors, 3, 2, 1.0f, path, &error));
	CHECK(error.find("do not match") != String::npos);
	CHECK_FALSE(Heatmap::write_png(errors, 4, 2, 0.0f, path, &error));
	CHECK(error.find("max value") != String::npos);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[Metrics] compare_files reads EXR and PNG and writes the FLIP heatmap") {
	const std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_metrics_files";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const Image reference = make_pattern(16, 16);
	const Image image = add_noise(reference, 0.1f);
	const String ref_exr = (dir / "ref.exr").string();
	const String img_exr = (dir / "img.EXR").string();
	const String ref_png = (dir / "ref.png").string();
	const String heat_png = (dir / "heat.png").string();
	REQUIRE(ImageSaverEXR::save(reference, ref_exr));
	REQUIRE(ImageSaverEXR::save(image, img_exr));
	REQUIRE(PNGWriter::save(reference, ref_png));

	ImageMetrics::Result from_files;
	ImageMetrics::Result direct;
	String error;
	REQUIRE(ImageMetrics::compare_files(img_exr, ref_exr, &from_files, &error, ImageMetrics::Options(), heat_png));
	REQUIRE(ImageMetrics::compare(image, reference, &direct, &error));
	CHECK(from_files.rmse == doctest::Approx(direct.rmse).epsilon(1e-6));
	CHECK(from_files.flip == doctest::Approx(direct.flip).epsilon(1e-6));
	std::vector<uint8_t> rgba;
	int w = 0, h = 0;
	REQUIRE(PNGReader::load(heat_png, rgba, w, h));
	CHECK(w == 16);
	CHECK(h == 16);

	// The 8-bit PNG of the reference decodes back to nearly the same linear values.
	REQUIRE(ImageMetrics::compare_files(ref_png, ref_exr, &from_files, &error, ImageMetrics::Options()));
	CHECK(from_files.rmse < 0.005);
	CHECK(from_files.pearson > 0.999);

	CHECK_FALSE(ImageMetrics::compare_files((dir / "missing.exr").string(), ref_exr, &from_files, &error, ImageMetrics::Options()));
	CHECK(error.find("missing.exr") != String::npos);
	std::filesystem::remove_all(dir);
}

} // namespace TestImageMetrics
