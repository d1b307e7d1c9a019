/**************************************************************************/
/*  test_image.cpp                                                        */
/**************************************************************************/
/* godot-area: tests for Image, Tonemap, the OpenEXR saver/loader and the */
/* PNG writer/reader.                                                     */

#include "core/io/image.h"
#include "core/io/tonemap.h"
#include "drivers/png/png_reader.h"
#include "drivers/png/png_writer.h"
#include "modules/openexr/image_loader_exr.h"
#include "modules/openexr/image_saver_exr.h"

#include "core/error/error_macros.h"

#include <doctest/doctest.h>

#include <Imath/half.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace TestImage {

// A scratch directory under the system temp dir, removed when the test ends.
struct TempDir {
	std::filesystem::path path;
	explicit TempDir(const char *p_name) {
		path = std::filesystem::temp_directory_path() / (String("godot_area_test_") + p_name);
		std::filesystem::remove_all(path);
		std::filesystem::create_directories(path);
	}
	~TempDir() {
		std::error_code ec;
		std::filesystem::remove_all(path, ec);
	}
	String file(const char *p_name) const { return (path / p_name).string(); }
};

// Runs with error printing silenced (the error handlers still run).
struct SilenceErrors {
	SilenceErrors() { set_error_print_silenced(true); }
	~SilenceErrors() { set_error_print_silenced(false); }
};

// A 7x5 image with distinct, awkward float values (not representable as halves).
static Image make_test_image() {
	Image image(7, 5);
	for (int y = 0; y < image.get_height(); y++) {
		for (int x = 0; x < image.get_width(); x++) {
			const float base = 0.1234567f * float(x + 1) + 3.3333333f * float(y);
			image.set_pixel(x, y, Color(base, base * 0.01f + 1e-5f, -base * 7.0f, 0.25f + 0.1f * float(x)));
		}
	}
	image.set_pixel(0, 0, Color(1000.5f, 0.0f, 123456.78f, 1.0f));
	return image;
}

TEST_CASE("[Image] create, pixel access and checks") {
	Image image;
	CHECK(image.is_empty());
	CHECK(image.is_finite());
	CHECK_FALSE(image.has_non_black());

	REQUIRE(image.create(4, 3));
	CHECK(image.get_width() == 4);
	CHECK(image.get_height() == 3);
	CHECK(image.get_data().size() == 4 * 3 * 4);
	CHECK(image.get_pixel(3, 2) == Color(0, 0, 0, 1));
	CHECK_FALSE(image.has_non_black());

	image.set_pixel(3, 2, Color(0.0f, 0.0f, 0.5f, 1.0f));
	CHECK(image.get_pixel(3, 2) == Color(0.0f, 0.0f, 0.5f, 1.0f));
	CHECK(image.get_data()[(2 * 4 + 3) * 4 + 2] == 0.5f); // Row-major, top row first.
	CHECK(image.has_non_black());
	CHECK_FALSE(image.has_non_black(0.5f));

	SUBCASE("alpha alone is not colour") {
		Image alpha_only(2, 2, Color(0, 0, 0, 0.7f));
		CHECK_FALSE(alpha_only.has_non_black());
	}
	SUBCASE("non-finite values are detected") {
		CHECK(image.is_finite());
		image.set_pixel(1, 1, Color(0, std::numeric_limits<float>::quiet_NaN(), 0, 1));
		CHECK_FALSE(image.is_finite());
		image.set_pixel(1, 1, Color(0, 0, 0, std::numeric_limits<float>::infinity()));
		CHECK_FALSE(image.is_finite());
	}
	SUBCASE("bad sizes and coordinates fail without crashing") {
		SilenceErrors silence;
		CHECK_FALSE(image.create(0, 5));
		CHECK(image.is_empty());
		CHECK_FALSE(image.create(-3, 5));
		CHECK_FALSE(image.create(Image::MAX_SIZE + 1, 1));
		REQUIRE(image.create(2, 2));
		CHECK(image.get_pixel(2, 0) == Color(0, 0, 0, 0));
		CHECK(image.get_pixel(0, -1) == Color(0, 0, 0, 0));
		image.set_pixel(5, 5, Color(1, 1, 1, 1));
		CHECK_FALSE(image.has_non_black());
		CHECK_FALSE(image.set_data(2, 2, std::vector<float>(3)));
	}
	SUBCASE("max difference") {
		Image other = image;
		CHECK(image.get_max_difference(other) == 0.0f);
		other.set_pixel(0, 0, Color(0.25f, 0, 0, 1));
		CHECK(image.get_max_difference(other) == doctest::Approx(0.25f));
		CHECK(image.get_max_difference(Image(1, 1)) == -1.0f);
	}
}

TEST_CASE("[Image][Tonemap] preview tonemap") {
	SUBCASE("zero maps to zero in every mode") {
		CHECK(Tonemap::map_channel(0.0f, 0.0f, Tonemap::MODE_ACES_FITTED) == 0);
		CHECK(Tonemap::map_channel(0.0f, 5.0f, Tonemap::MODE_LINEAR) == 0);
		CHECK(Tonemap::aces_fitted(0.0f) == 0.0f);
	}
	SUBCASE("ACES fitted curve is monotonic and saturates") {
		float previous = 0.0f;
		int previous_byte = 0;
		int decreases = 0;
		for (int i = 1; i <= 4000; i++) {
			const float x = float(i) * 0.005f;
			const float y = Tonemap::aces_fitted(x);
			const int byte = Tonemap::map_channel(x, 0.0f, Tonemap::MODE_ACES_FITTED);
			if (y < previous || byte < previous_byte) {
				decreases++;
			}
			previous = y;
			previous_byte = byte;
		}
		CHECK_MESSAGE(decreases == 0, "curve and 8-bit output must never decrease");
		CHECK(previous == 1.0f);
		CHECK(previous_byte == 255);
		CHECK(Tonemap::aces_fitted(0.18f) < 0.18f * 1.5f);
	}
	SUBCASE("linear mode is the plain sRGB encoding") {
		CHECK(Tonemap::map_channel(0.5f, 0.0f, Tonemap::MODE_LINEAR) == 188);
		CHECK(Tonemap::map_channel(1.0f, 0.0f, Tonemap::MODE_LINEAR) == 255);
		CHECK(Tonemap::map_channel(0.216f, 0.0f, Tonemap::MODE_LINEAR) == 128);
		CHECK(Tonemap::map_channel(0.25f, 1.0f, Tonemap::MODE_LINEAR) == 188); // +1 EV doubles.
		CHECK(Tonemap::map_channel(0.001f, 0.0f, Tonemap::MODE_LINEAR) == 3); // Linear toe: 12.92 * 0.001 * 255.
	}
	SUBCASE("bad values do not propagate") {
		CHECK(Tonemap::map_channel(-2.0f, 0.0f) == 0);
		CHECK(Tonemap::map_channel(std::numeric_limits<float>::quiet_NaN(), 0.0f) == 0);
		CHECK(Tonemap::map_channel(std::numeric_limits<float>::infinity(), 0.0f) == 255);
		CHECK(Tonemap::map_alpha(0.5f) == 128);
		CHECK(Tonemap::map_alpha(2.0f) == 255);
	}
	SUBCASE("apply covers every pixel") {
		Image image(3, 2, Color(0.5f, 0.0f, 1.0f, 1.0f));
		const std::vector<uint8_t> bytes = Tonemap::apply(image, 0.0f, Tonemap::MODE_LINEAR);
		REQUIRE(bytes.size() == 3 * 2 * 4);
		CHECK(bytes[20] == 188);
		CHECK(bytes[21] == 0);
		CHECK(bytes[22] == 255);
		CHECK(bytes[23] == 255);
		SilenceErrors silence;
		CHECK(Tonemap::apply(Image(), 0.0f).empty());
	}
}

TEST_CASE("[OpenEXR] float round-trip is exact") {
	TempDir dir("exr_float");
	const Image image = make_test_image();
	const String path = dir.file("float.exr");
	String error;
	REQUIRE_MESSAGE(ImageSaverEXR::save(image, path, false, &error), error);
	Image loaded;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(path, loaded, &error), error);
	REQUIRE(loaded.get_width() == 7);
	REQUIRE(loaded.get_height() == 5);
	CHECK(loaded.get_data() == image.get_data());
	CHECK(loaded.get_pixel(0, 0) == Color(1000.5f, 0.0f, 123456.78f, 1.0f));
}

TEST_CASE("[OpenEXR] half round-trip is within half precision") {
	TempDir dir("exr_half");
	const Image image = make_test_image();
	const String path = dir.file("half.exr");
	String error;
	REQUIRE_MESSAGE(ImageSaverEXR::save(image, path, true, &error), error);
	Image loaded;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(path, loaded, &error), error);
	REQUIRE(loaded.get_width() == image.get_width());
	REQUIRE(loaded.get_height() == image.get_height());
	bool any_rounded = false;
	for (size_t i = 0; i < image.get_data().size(); i++) {
		const float original = image.get_data()[i];
		const float read = loaded.get_data()[i];
		CHECK(read == float(Imath::half(original))); // Exactly the half rounding, nothing else.
		if (std::fabs(original) >= 6.2e-5f && std::fabs(original) <= 65504.0f) {
			// Normal halves: 11 significant bits, so relative error <= 2^-11.
			CHECK(std::fabs(read - original) <= std::fabs(original) * (1.0f / 2048.0f));
		}
		any_rounded = any_rounded || read != original;
	}
	CHECK_MESSAGE(any_rounded, "test data must exercise half rounding");
	CHECK(std::isinf(loaded.get_pixel(0, 0).b)); // 123456.78 is beyond the half range.
}

TEST_CASE("[OpenEXR] errors name the file and never crash") {
	TempDir dir("exr_errors");
	SilenceErrors silence;
	Image loaded;
	String error;

	SUBCASE("missing file") {
		const String path = dir.file("does_not_exist.exr");
		CHECK_FALSE(ImageLoaderEXR::load(path, loaded, &error));
		CHECK(error.find(path) != String::npos);
		CHECK(error.find("not found") != String::npos);
		CHECK(loaded.is_empty());
	}
	SUBCASE("garbage file") {
		const String path = dir.file("garbage.exr");
		std::ofstream(path) << "this is not an OpenEXR file at all";
		CHECK_FALSE(ImageLoaderEXR::load(path, loaded, &error));
		CHECK(error.find(path) != String::npos);
		CHECK(loaded.is_empty());
	}
	SUBCASE("truncated file") {
		const String path = dir.file("truncated.exr");
		REQUIRE(ImageSaverEXR::save(Image(64, 64, Color(0.3f, 0.6f, 0.9f, 1.0f)), path, false, &error));
		const uintmax_t size = std::filesystem::file_size(path);
		std::filesystem::resize_file(path, size / 2);
		CHECK_FALSE(ImageLoaderEXR::load(path, loaded, &error));
		CHECK(error.find(path) != String::npos);
		CHECK(loaded.is_empty());
	}
	SUBCASE("unwritable path and empty image") {
		const String bad_path = dir.file("no_such_dir/out.exr");
		CHECK_FALSE(ImageSaverEXR::save(Image(2, 2), bad_path, false, &error));
		CHECK(error.find(bad_path) != String::npos);
		const String empty_path = dir.file("empty.exr");
		CHECK_FALSE(ImageSaverEXR::save(Image(), empty_path, true, &error));
		CHECK(error.find(empty_path) != String::npos);
		CHECK_FALSE(std::filesystem::exists(empty_path));
	}
}

TEST_CASE("[PNG] written bytes read back as the expected sRGB values") {
	TempDir dir("png");
	Image image(3, 2, Color(0, 0, 0, 1));
	image.set_pixel(0, 0, Color(0.5f, 0.0f, 1.0f, 1.0f));
	image.set_pixel(1, 0, Color(0.216f, 2.0f, -1.0f, 0.5f));
	image.set_pixel(2, 1, Color(0.001f, 0.0031308f, 0.04f, 0.0f));
	const String path = dir.file("preview.png");
	String error;
	REQUIRE_MESSAGE(PNGWriter::save(image, path, &error), error);

	std::vector<uint8_t> bytes;
	int width = 0;
	int height = 0;
	REQUIRE_MESSAGE(PNGReader::load(path, bytes, width, height, &error), error);
	REQUIRE(width == 3);
	REQUIRE(height == 2);
	REQUIRE(bytes.size() == 3 * 2 * 4);
	const std::vector<uint8_t> expected = {
		188, 0, 255, 255, /**/ 128, 255, 0, 128, /**/ 0, 0, 0, 255, // Row 0.
		0, 0, 0, 255, /**/ 0, 0, 0, 255, /**/ 3, 10, 56, 0, // Row 1.
	};
	CHECK(bytes == expected);

	SUBCASE("raw RGBA8 bytes round-trip unchanged") {
		std::vector<uint8_t> raw(5 * 4 * 4);
		for (size_t i = 0; i < raw.size(); i++) {
			raw[i] = uint8_t((i * 37 + 11) & 0xff);
		}
		const String raw_path = dir.file("raw.png");
		REQUIRE_MESSAGE(PNGWriter::save_rgba8(raw, 5, 4, raw_path, &error), error);
		std::vector<uint8_t> read;
		REQUIRE_MESSAGE(PNGReader::load(raw_path, read, width, height, &error), error);
		CHECK(width == 5);
		CHECK(height == 4);
		CHECK(read == raw);
	}
	SUBCASE("tonemapped preview is brighter with more exposure") {
		Image grey(1, 1, Color(0.18f, 0.18f, 0.18f, 1.0f));
		const String dark = dir.file("dark.png");
		const String bright = dir.file("bright.png");
		REQUIRE(PNGWriter::save(grey, dark, &error, 0.0f, Tonemap::MODE_ACES_FITTED));
		REQUIRE(PNGWriter::save(grey, bright, &error, 2.0f, Tonemap::MODE_ACES_FITTED));
		std::vector<uint8_t> d, b;
		REQUIRE(PNGReader::load(dark, d, width, height, &error));
		REQUIRE(PNGReader::load(bright, b, width, height, &error));
		CHECK(b[0] > d[0]);
		CHECK(d[0] > 0);
	}
	SUBCASE("errors name the file") {
		SilenceErrors silence;
		const String missing = dir.file("missing.png");
		CHECK_FALSE(PNGReader::load(missing, bytes, width, height, &error));
		CHECK(error.find(missing) != String::npos);
		CHECK(bytes.empty());

		const String garbage = dir.file("garbage.png");
		std::ofstream(garbage) << "not a png";
		CHECK_FALSE(PNGReader::load(garbage, bytes, width, height, &error));
		CHECK(error.find(garbage) != String::npos);

		const String truncated = dir.file("truncated.png");
		std::filesystem::copy_file(path, truncated);
		std::filesystem::resize_file(truncated, std::filesystem::file_size(path) / 2);
		CHECK_FALSE(PNGReader::load(truncated, bytes, width, height, &error));
		CHECK(error.find(truncated) != String::npos);

		const String bad_path = dir.file("no_such_dir/out.png");
		CHECK_FALSE(PNGWriter::save(image, bad_path, &error));
		CHECK(error.find(bad_path) != String::npos);
		CHECK_FALSE(PNGWriter::save(Image(), dir.file("empty.png"), &error));
		CHECK(error.find("empty.png") != String::npos);
		CHECK_FALSE(PNGWriter::save_rgba8(std::vector<uint8_t>(7), 2, 2, dir.file("short.png"), &error));
		CHECK(error.find("short.png") != String::npos);
	}
}

} // namespace TestImage
