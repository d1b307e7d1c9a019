/**************************************************************************/
/*  test_tonemap.cpp                                                      */
/**************************************************************************/
/* godot-area: Godot 4's tonemappers (Environment.tonemap_mode) against  */
/* their published formulas at sample points, written out here from the */
/* papers independently of core/io/tonemap.cpp, plus the properties each */
/* curve must have (white maps to 1, monotonic, 0 stays 0) and the        */
/* Environment wiring (defaults, validation, preview selection).          */

#include "core/io/tonemap.h"

#include "scene/resources/environment.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestTonemap {

// Reinhard et al. 2002, eq. 4: L_d = L (1 + L / L_white^2) / (1 + L).
static double reinhard_paper(double p_l, double p_white) {
	return p_l * (1.0 + p_l / (p_white * p_white)) / (1.0 + p_l);
}

// Hable 2010 (GDC "Uncharted 2: HDR Lighting"), slide constants; Godot biases input and white by 2.
static double hable_paper(double p_x) {
	const double A = 0.22, B = 0.30, C = 0.10, D = 0.20, E = 0.01, F = 0.30;
	return ((p_x * (A * p_x + C * B) + D * E) / (p_x * (A * p_x + B) + D * F)) - E / F;
}

// Hill's RRT+ODT fit (BakingLab ACES.hlsl, RRTAndODTFit).
static double aces_rrt_odt_paper(double p_v) {
	return (p_v * (p_v + 0.0245786) - 0.000090537) / (p_v * (0.983729 * p_v + 0.432951) + 0.238081);
}

TEST_CASE("[Tonemap] Reinhard, Filmic, ACES and AgX match their published formulas at sample points") {
	const double xs[7] = { 0.0, 0.01, 0.18, 0.5, 1.0, 2.5, 8.0 };
	SUBCASE("Reinhard (white 1 is the identity below 1; the white point maps to 1)") {
		for (double w : { 1.0, 4.0, 11.2 }) {
			for (double x : xs) {
				INFO("x ", x, " white ", w);
				CHECK(Tonemap::reinhard(float(x), float(w)) == doctest::Approx(reinhard_paper(x, w)).epsilon(1e-6));
			}
			CHECK(Tonemap::reinhard(float(w), float(w)) == doctest::Approx(1.0).epsilon(1e-6));
		}
		CHECK(Tonemap::reinhard(0.5f, 1.0f) == doctest::Approx(0.5));
	}
	SUBCASE("Filmic (Hable with Godot's bias 2)") {
		for (double w : { 1.0, 6.0 }) {
			for (double x : xs) {
				INFO("x ", x, " white ", w);
				CHECK(Tonemap::filmic(float(x), float(w)) == doctest::Approx(hable_paper(2.0 * x) / hable_paper(2.0 * w)).epsilon(1e-5));
			}
			CHECK(Tonemap::filmic(float(w), float(w)) == doctest::Approx(1.0).epsilon(1e-6));
		}
		CHECK(std::fabs(Tonemap::filmic(0.0f, 1.0f)) < 1e-6f); // h(0) = DE/DF - E/F = 0.
	}
	SUBCASE("ACES (Hill's fit with Godot's bias 1.8): grey stays grey, the white point maps to 1") {
		for (double w : { 1.0, 6.0 }) {
			for (double x : xs) {
				float rgb[3] = { float(x), float(x), float(x) };
				Tonemap::aces(rgb, float(w));
				// Both matrices have rows summing to 1 (to 1e-5), so grey passes through the curve alone.
				const double expected = aces_rrt_odt_paper(1.8 * x) / aces_rrt_odt_paper(1.8 * w);
				INFO("x ", x, " white ", w, " got ", rgb[0], " ", rgb[1], " ", rgb[2]);
				for (int c = 0; c < 3; c++) {
					CHECK(rgb[c] == doctest::Approx(expected).epsilon(2e-4));
				}
			}
		}
		// A saturated red: the input matrix row 0 (0.59719, 0.35458, 0.04823) spreads it into every channel.
		float red[3] = { 1.0f, 0.0f, 0.0f };
		Tonemap::aces(red, 1.0f);
		const double w = aces_rrt_odt_paper(1.8);
		const double r = aces_rrt_odt_paper(1.8 * 0.59719), g = aces_rrt_odt_paper(1.8 * 0.07600), b = aces_rrt_odt_paper(1.8 * 0.02840);
		CHECK(red[0] == doctest::Approx((1.60475 * r - 0.53108 * g - 0.07367 * b) / w).epsilon(1e-5));
		CHECK(red[1] == doctest::Approx((-0.10208 * r + 1.10813 * g - 0.00605 * b) / w).epsilon(1e-4));
	}
	SUBCASE("AgX (Wrensch's minimal AgX): log2 encoding, polynomial, gamma 2.2") {
		// Grey: the inset rows sum to 1.000136, the outset rows to 0.99983 (published matrices).
		for (double x : { 0.01, 0.18, 1.0, 8.0 }) {
			float rgb[3] = { float(x), float(x), float(x) };
			Tonemap::agx(rgb);
			const double inset = x * (0.842479062253094 + 0.0784335999999992 + 0.0792237451477643);
			const double t = (std::log2(inset) + 12.47393) / (4.026069 + 12.47393);
			const double poly = 15.5 * std::pow(t, 6) - 40.14 * std::pow(t, 5) + 31.96 * std::pow(t, 4) - 6.868 * std::pow(t, 3) + 0.4298 * t * t + 0.1191 * t - 0.00232;
			const double expected = std::pow(poly * (1.19687900512017 - 0.0980208811401368 - 0.0990297440797205), 2.2);
			INFO("x ", x, " got ", rgb[0]);
			CHECK(rgb[0] == doctest::Approx(expected).epsilon(1e-5));
		}
		float black[3] = { 0, 0, 0 };
		Tonemap::agx(black);
		CHECK(black[0] <= 1e-6f); // The polynomial's -0.00232 at the floor clamps to 0.
	}
	SUBCASE("every curve is monotonic on a grey ramp and reaches at most 1") {
		for (int m = 0; m < Tonemap::MODE_MAX; m++) {
			Tonemap::Settings s;
			s.mode = Tonemap::Mode(m);
			s.white = 4.0f;
			float previous = -1.0f;
			int decreases = 0;
			for (int i = 0; i <= 2000; i++) {
				float rgb[3] = { i * 0.01f, i * 0.01f, i * 0.01f };
				Tonemap::map_linear(rgb, s);
				decreases += rgb[1] < previous - 1e-6f ? 1 : 0;
				previous = rgb[1];
				CHECK(rgb[1] <= 1.0f);
			}
			INFO("mode ", m);
			CHECK(decreases == 0);
		}
	}
	SUBCASE("exposure multiplies before the curve; bad settings are refused") {
		Tonemap::Settings s;
		s.mode = Tonemap::MODE_REINHARD;
		s.white = 3.0f;
		s.exposure = 2.0f;
		float rgb[3] = { 0.25f, 0.25f, 0.25f };
		Tonemap::map_linear(rgb, s);
		CHECK(rgb[0] == doctest::Approx(reinhard_paper(0.5, 3.0)).epsilon(1e-6));
		Image image(2, 2, Color(0.5f, 0.5f, 0.5f, 1));
		s.exposure = 0.0f;
		SceneTest::ErrorCatcher silence;
		CHECK(Tonemap::apply(image, s).empty());
		s.exposure = 1.0f;
		s.white = -1.0f;
		CHECK(Tonemap::apply(image, s).empty());
	}
}

TEST_CASE("[Environment] tonemap_mode, tonemap_exposure and tonemap_white: Godot's defaults, validation and the preview choice") {
	SceneTest::DummyServer server;
	Ref<Environment> env;
	env.instantiate();
	CHECK(env->get_tonemapper() == Environment::TONE_MAPPER_LINEAR);
	CHECK(env->get_tonemap_exposure() == 1.0f);
	CHECK(env->get_tonemap_white() == 1.0f);
	env->set("tonemap_mode", 3);
	CHECK(env->get_tonemapper() == Environment::TONE_MAPPER_ACES);
	CHECK(env->get_tonemap_settings().mode == Tonemap::MODE_ACES);
	{
		SceneTest::ErrorCatcher silence;
		env->set_tonemap_exposure(-1.0f);
		env->set_tonemapper(Environment::ToneMapper(7));
	}
	CHECK(env->get_tonemap_exposure() == 1.0f);
	CHECK(env->get_tonemapper() == Environment::TONE_MAPPER_ACES);
	Tonemap::Mode mode;
	CHECK(Tonemap::mode_from_godot(4, mode));
	CHECK(mode == Tonemap::MODE_AGX);
	CHECK_FALSE(Tonemap::mode_from_godot(5, mode));
	// Camera environment first, then the world's, else the ACES-fitted preview.
	Ref<Environment> world;
	world.instantiate();
	world->set_tonemapper(Environment::TONE_MAPPER_FILMIC);
	CHECK(Environment::get_preview_tonemap(env, world).mode == Tonemap::MODE_ACES);
	CHECK(Environment::get_preview_tonemap(Ref<Environment>(), world).mode == Tonemap::MODE_FILMIC);
	CHECK(Environment::get_preview_tonemap(Ref<Environment>(), Ref<Environment>()).mode == Tonemap::MODE_ACES_FITTED);
}

} // namespace TestTonemap
