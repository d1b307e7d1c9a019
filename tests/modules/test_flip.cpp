/**************************************************************************/
/*  test_flip.cpp                                                         */
/**************************************************************************/
/* godot-area: tests for LDR-FLIP and HDR-FLIP.                           */

#include "modules/metrics/flip.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

namespace TestFLIP {

static Image make_gradient(int p_size) {
	Image image(p_size, p_size);
	for (int y = 0; y < p_size; y++) {
		for (int x = 0; x < p_size; x++) {
			const float u = float(x) / float(p_size - 1);
			const float v = float(y) / float(p_size - 1);
			image.set_pixel(x, y, Color(0.2f + 0.6f * u, 0.3f + 0.4f * v, 0.5f - 0.3f * u * v, 1.0f));
		}
	}
	return image;
}

static Image add_noise(const Image &p_image, float p_amplitude, unsigned p_seed = 99) {
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

TEST_CASE("[FLIP] default pixels per degree matches 0.7 m from a 0.7 m, 3840 px monitor") {
	CHECK(FLIP::compute_ppd(0.7f, 0.7f, 3840.0f) == doctest::Approx(67.0206f).epsilon(1e-4));
	CHECK(FLIP::DEFAULT_PPD == doctest::Approx(FLIP::compute_ppd(0.7f, 0.7f, 3840.0f)).epsilon(1e-4));
}

TEST_CASE("[FLIP] identical images give zero error everywhere") {
	const Image image = make_gradient(32);
	std::vector<float> map;
	float mean = -1.0f;
	REQUIRE(FLIP::compute_ldr(image, image, FLIP::DEFAULT_PPD, map, &mean));
	CHECK(mean == 0.0f);
	REQUIRE(map.size() == 32u * 32u);
	for (float v : map) {
		CHECK(v == 0.0f);
	}
	REQUIRE(FLIP::compute_hdr(image, image, FLIP::DEFAULT_PPD, map, &mean));
	CHECK(mean == 0.0f);
}

TEST_CASE("[FLIP] black against white is close to 1") {
	const Image black(16, 16, Color(0, 0, 0, 1));
	const Image white(16, 16, Color(1, 1, 1, 1));
	std::vector<float> map;
	float mean = 0.0f;
	REQUIRE(FLIP::compute_ldr(black, white, FLIP::DEFAULT_PPD, map, &mean));
	// HyAB(black, white) = 100 -> 100^0.7 = 25.1 lies above pc * cmax, so dE = 0.95 + a little.
	CHECK(mean > 0.95f);
	CHECK(mean <= 1.0f);
	// Symmetric in its arguments.
	float mean_swapped = 0.0f;
	REQUIRE(FLIP::compute_ldr(white, black, FLIP::DEFAULT_PPD, map, &mean_swapped));
	CHECK(mean_swapped == doctest::Approx(mean));
	// Values above 1 are clamped (LDR input), so 5.0 reads as white.
	const Image bright(16, 16, Color(5, 5, 5, 1));
	REQUIRE(FLIP::compute_ldr(bright, white, FLIP::DEFAULT_PPD, map, &mean));
	CHECK(mean == 0.0f);
}

TEST_CASE("[FLIP] error grows with noise amplitude and stays in [0, 1]") {
	const Image image = make_gradient(48);
	float previous = 0.0f;
	for (float amplitude : { 0.01f, 0.05f, 0.15f, 0.4f }) {
		std::vector<float> map;
		float mean = 0.0f;
		REQUIRE(FLIP::compute_ldr(add_noise(image, amplitude), image, FLIP::DEFAULT_PPD, map, &mean));
		INFO("amplitude ", amplitude, " flip ", mean);
		CHECK(mean > previous);
		for (float v : map) {
			CHECK((v >= 0.0f && v <= 1.0f));
		}
		previous = mean;
	}
}

TEST_CASE("[FLIP] a small sharp edge difference is seen through the feature pipeline") {
	// Same mean colour, but the test has a thin bright line: the colour term alone is reduced by the
	// CSF blur; the edge/point detectors must still flag the line's neighbourhood.
	const Image reference(32, 32, Color(0.2f, 0.2f, 0.2f, 1));
	Image test = reference;
	for (int y = 0; y < 32; y++) {
		test.set_pixel(16, y, Color(0.8f, 0.8f, 0.8f, 1));
	}
	std::vector<float> map;
	float mean = 0.0f;
	REQUIRE(FLIP::compute_ldr(test, reference, FLIP::DEFAULT_PPD, map, &mean));
	CHECK(map[16 * 32 + 16] > 0.3f); // On the line.
	CHECK(map[16 * 32 + 16] > map[16 * 32 + 2]); // Far from the line: less.
	CHECK(map[16 * 32 + 2] < 0.05f);
}

TEST_CASE("[FLIP] HDR-FLIP brackets exposures and sees differences in bright regions") {
	Image reference(24, 24, Color(0.05f, 0.05f, 0.05f, 1));
	for (int y = 8; y < 16; y++) {
		for (int x = 8; x < 16; x++) {
			reference.set_pixel(x, y, Color(20.0f, 20.0f, 20.0f, 1));
		}
	}
	Image test = reference;
	for (int y = 8; y < 16; y++) {
		for (int x = 8; x < 16; x++) {
			test.set_pixel(x, y, Color(10.0f, 20.0f, 20.0f, 1)); // Cyan-ish: invisible to LDR (both clamp to 1).
		}
	}
	std::vector<float> map;
	float ldr = 0.0f;
	REQUIRE(FLIP::compute_ldr(test, reference, FLIP::DEFAULT_PPD, map, &ldr));
	CHECK(ldr == 0.0f);
	float hdr = 0.0f;
	FLIP::HDRExposures exposures;
	REQUIRE(FLIP::compute_hdr(test, reference, FLIP::DEFAULT_PPD, map, &hdr, &exposures));
	CHECK(exposures.count >= 2);
	CHECK(exposures.start_exposure < exposures.stop_exposure);
	CHECK(hdr > 0.01f);
	CHECK(map[12 * 24 + 12] > 0.1f);
}

TEST_CASE("[FLIP] bad inputs fail with a message") {
	const Image a(8, 8);
	const Image b(9, 8);
	std::vector<float> map;
	String error;
	CHECK_FALSE(FLIP::compute_ldr(a, b, FLIP::DEFAULT_PPD, map, nullptr, &error));
	CHECK(error.find("sizes differ") != String::npos);
	CHECK(map.empty());
	CHECK_FALSE(FLIP::compute_ldr(a, a, 0.0f, map, nullptr, &error));
	CHECK(error.find("pixels per degree") != String::npos);
	CHECK_FALSE(FLIP::compute_hdr(Image(), a, FLIP::DEFAULT_PPD, map, nullptr, nullptr, &error));
	CHECK(error.find("empty") != String::npos);
}

} // namespace TestFLIP
