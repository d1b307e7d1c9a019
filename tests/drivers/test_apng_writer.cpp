/**************************************************************************/
/*  test_apng_writer.cpp                                                  */
/**************************************************************************/

#include "core/error/error_macros.h"
#include "drivers/png/apng_writer.h"
#include "drivers/png/png_reader.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

namespace TestAPNGWriter {

std::vector<uint8_t> _frame(int p_w, int p_h, uint8_t p_seed) {
	std::vector<uint8_t> rgba(size_t(p_w) * p_h * 4);
	for (size_t i = 0; i < rgba.size(); i++) {
		rgba[i] = (i % 4 == 3) ? 255 : uint8_t(p_seed + i * 7);
	}
	return rgba;
}

TEST_CASE("[APNGWriter] frame 0 is the PNG's default image; bad input fails with a message and no file") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_apng";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const String path = (dir / "a.png").string();
	const std::vector<std::vector<uint8_t>> frames = { _frame(5, 3, 1), _frame(5, 3, 90) };
	String error;
	REQUIRE_MESSAGE(APNGWriter::save_rgba8(frames, 5, 3, 40, path, &error), error);
	std::vector<uint8_t> read;
	int w = 0, h = 0;
	REQUIRE_MESSAGE(PNGReader::load(path, read, w, h, &error), error);
	CHECK(w == 5);
	CHECK(h == 3);
	CHECK(read == frames[0]);
	std::ifstream f(path, std::ios::binary);
	const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	CHECK(bytes.find("acTL") < bytes.find("IDAT"));
	CHECK(bytes.find("fdAT") != std::string::npos);

	set_error_print_silenced(true);
	const String bad = (dir / "bad.png").string();
	CHECK_FALSE(APNGWriter::save_rgba8({}, 5, 3, 40, bad, &error));
	CHECK_MESSAGE(error.find("no frames") != String::npos, error);
	CHECK_FALSE(APNGWriter::save_rgba8(frames, 5, 3, 0, bad, &error));
	CHECK_MESSAGE(error.find("delay") != String::npos, error);
	CHECK_FALSE(APNGWriter::save_rgba8({ _frame(5, 3, 1), _frame(4, 3, 1) }, 5, 3, 40, bad, &error)); // Wrong size.
	CHECK_MESSAGE(error.find("frame 1") != String::npos, error);
	CHECK_FALSE(std::filesystem::exists(bad));
	CHECK_FALSE(APNGWriter::save_rgba8(frames, 5, 3, 40, (dir / "no_such_dir" / "x.png").string(), &error));
	set_error_print_silenced(false);
	std::filesystem::remove_all(dir);
}

} // namespace TestAPNGWriter
