/**************************************************************************/
/*  test_texture_mipmaps.cpp                                              */
/**************************************************************************/
/* Issue 15: the mip chain of material textures (texture_mipmaps.h):      */
/* Vulkan's level sizes, the box filter keeps the mean (odd sizes too),   */
/* sRGB colour is averaged in linear space, and the level of detail       */
/* follows Vulkan's formula. The reference renderer's trilinear sample is */
/* tested in tests/modules/test_reference_texture.cpp.                    */

#include "core/math/color.h"
#include "servers/rendering/storage/texture_mipmaps.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestTextureMipmaps {

static double mean_red(const Image &p_image) {
	double sum = 0.0;
	for (int y = 0; y < p_image.get_height(); y++) {
		for (int x = 0; x < p_image.get_width(); x++) {
			sum += p_image.get_pixel(x, y).r;
		}
	}
	return sum / (double(p_image.get_width()) * p_image.get_height());
}

TEST_CASE("[TextureMipmaps] level sizes follow Vulkan and every level keeps the mean") {
	CHECK(texture_mipmap_level_count(1, 1) == 1);
	CHECK(texture_mipmap_level_count(16, 16) == 5);
	CHECK(texture_mipmap_level_count(5, 3) == 3);
	CHECK(texture_mipmap_level_count(1024, 4) == 11);
	Image base(5, 3);
	for (int y = 0; y < 3; y++) {
		for (int x = 0; x < 5; x++) {
			base.set_pixel(x, y, Color(float(x * 3 + y * 7 % 5) / 20.0f, 0, 0, 1));
		}
	}
	std::vector<Image> levels;
	texture_mipmaps_generate(base, false, levels);
	REQUIRE(levels.size() == 2);
	CHECK(levels[0].get_width() == 2);
	CHECK(levels[0].get_height() == 1);
	CHECK(levels[1].get_width() == 1);
	CHECK(levels[1].get_height() == 1);
	const double mean = mean_red(base);
	CHECK(mean_red(levels[0]) == doctest::Approx(mean).epsilon(1e-5));
	CHECK(mean_red(levels[1]) == doctest::Approx(mean).epsilon(1e-5));
	CHECK(levels[1].get_pixel(0, 0).a == doctest::Approx(1.0f));
}

TEST_CASE("[TextureMipmaps] sRGB colour is averaged in linear space, data is not") {
	// A black and white checker: its first level is linear 0.5 (sRGB 0.735) for colour, 0.5 for data.
	Image checker(4, 4);
	for (int y = 0; y < 4; y++) {
		for (int x = 0; x < 4; x++) {
			const float v = float((x + y) % 2);
			checker.set_pixel(x, y, Color(v, v, v, 1));
		}
	}
	std::vector<Image> colour, data;
	texture_mipmaps_generate(checker, true, colour);
	texture_mipmaps_generate(checker, false, data);
	REQUIRE(colour.size() == 2);
	REQUIRE(data.size() == 2);
	for (int level = 0; level < 2; level++) {
		const Color c = colour[level].get_pixel(0, 0), d = data[level].get_pixel(0, 0);
		CHECK(Color::srgb_to_linear_channel(c.r) == doctest::Approx(0.5f).epsilon(1e-4));
		CHECK(c.r == doctest::Approx(0.7354f).epsilon(1e-3));
		CHECK(d.r == doctest::Approx(0.5f).epsilon(1e-6));
	}
}

TEST_CASE("[TextureMipmaps] the level of detail follows Vulkan's formula") {
	// One texel per pixel: lambda 0; four texels per pixel along x: lambda 2.
	CHECK(texture_mipmap_lod(Vector2(1.0f / 64, 0), Vector2(0, 1.0f / 64), 64, 64) == doctest::Approx(0.0f));
	CHECK(texture_mipmap_lod(Vector2(4.0f / 64, 0), Vector2(0, 1.0f / 64), 64, 64) == doctest::Approx(2.0f));
	CHECK(std::isinf(texture_mipmap_lod(Vector2(), Vector2(), 64, 64)));
}

} // namespace TestTextureMipmaps
