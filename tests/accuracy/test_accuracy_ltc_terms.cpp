/**************************************************************************/
/*  test_accuracy_ltc_terms.cpp                                           */
/**************************************************************************/
/* godot-area: the LTC error decomposition of an accuracy scene           */
/* (modules/accuracy/accuracy_ltc_terms.h): a diffuse scene has no error  */
/* in any term; under a TV seen at a grazing angle the error of a         */
/* dielectric is its Fresnel term (thesis eq. 5.10), which the shader's   */
/* polygon Fresnel removes most of; bad input is refused.                 */

#include "modules/accuracy/accuracy_ltc_terms.h"

#include <doctest/doctest.h>

namespace TestAccuracyLTCTerms {

TEST_CASE("[Accuracy][LTC] the error terms of a diffuse scene are all small") {
	const AccuracyScenes::Scene scene = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 1.0f, 0.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_FACING);
	AccuracyLTCTerms::Result r;
	String error;
	REQUIRE(AccuracyLTCTerms::evaluate(scene, 16, 32, &r, &error));
	MESSAGE(AccuracyLTCTerms::format(r));
	CHECK(r.pixels > 100);
	CHECK(r.total < 0.01);
	CHECK(r.eq510 < 0.01);
	CHECK(r.fresnel < 0.01);
	CHECK(r.norm < 0.01);
	CHECK(r.lobe < 0.01);
	CHECK(r.total_ratio == doctest::Approx(1.0).epsilon(0.01));
	CHECK(r.truth_convergence < 0.01);
}

TEST_CASE("[Accuracy][LTC] under a TV seen at 20 degrees a dielectric's error is Fresnel, and the polygon Fresnel removes most of it") {
	// Measured here (16 x 16, 48^2 light samples): eq. 5.10 0.118 (ratio 0.89), of which Fresnel 0.117 and
	// lobe shape 0.007; with the polygon Fresnel 0.026 (1.031). At 40 x 40 (bench --accuracy --ltc-terms
	// --ci): 0.073 (0.92), Fresnel 0.073, lobe 0.006; 0.015 (1.021).
	const AccuracyScenes::Scene scene = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 0.0f, Vector2(2, 0.5f), AccuracyScenes::PLACEMENT_VERTICAL, 20.0f);
	AccuracyLTCTerms::Result r;
	String error;
	REQUIRE(AccuracyLTCTerms::evaluate(scene, 16, 48, &r, &error));
	MESSAGE(AccuracyLTCTerms::format(r));
	CHECK(r.truth_convergence < 0.02);
	CHECK(r.fresnel > 0.04);
	CHECK(r.fresnel > 4.0 * r.lobe);
	CHECK(r.fresnel_ratio < 0.95);
	CHECK(r.eq510 > 0.04);
	CHECK(r.total < 0.35 * r.eq510);
	CHECK(r.total_ratio > 0.97);
	CHECK(r.total_ratio < 1.05);
	CHECK(r.angle_index_max >= 50); // Grazing rows of the LUT.
	REQUIRE(!r.worst_cells.empty());
	CHECK(r.worst_cells[0].share > 0.0);
}

TEST_CASE("[Accuracy][LTC] the decomposition refuses spheres, bad sizes and a wrong table") {
	AccuracyLTCTerms::Result r;
	String error;
	const AccuracyScenes::Scene sphere = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_SPHERE, 0.5f, 1.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_FACING);
	CHECK_FALSE(AccuracyLTCTerms::evaluate(sphere, 8, 16, &r, &error));
	CHECK(error.find("plane") != String::npos);
	const AccuracyScenes::Scene plane = AccuracyScenes::make_scene(AccuracyScenes::RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 1), AccuracyScenes::PLACEMENT_FACING);
	error.clear();
	CHECK_FALSE(AccuracyLTCTerms::evaluate(plane, 0, 16, &r, &error));
	CHECK(!error.empty());
	error.clear();
	CHECK_FALSE(AccuracyLTCTerms::evaluate(plane, 8, 2, &r, &error));
	CHECK(!error.empty());
	const std::vector<float> short_table(10, 1.0f);
	error.clear();
	CHECK_FALSE(AccuracyLTCTerms::evaluate(plane, 8, 16, &r, &error, &short_table));
	CHECK(error.find("floats") != String::npos);
}

} // namespace TestAccuracyLTCTerms
