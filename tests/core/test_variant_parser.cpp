/**************************************************************************/
/*  test_variant_parser.cpp                                               */
/**************************************************************************/

#include "core/variant/variant_parser.h"
#include "scene/main/node.h"
#include "scene/resources/resource_format_text.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <ctime>
#include <filesystem>

namespace TestVariantParser {

TEST_CASE("[VariantParser] hexadecimal and exponent literals still lex as before") {
	Variant v;
	String error;
	REQUIRE_MESSAGE(VariantParser::parse_string("0x1e", v, &error), error);
	CHECK(v == Variant(int64_t(0x1e)));
	REQUIRE_MESSAGE(VariantParser::parse_string("1e-05", v, &error), error);
	CHECK(double(v) == doctest::Approx(1e-05));
	REQUIRE_MESSAGE(VariantParser::parse_string("-2.5E+3", v, &error), error);
	CHECK(double(v) == doctest::Approx(-2500.0));
	// In a hex literal '-' after 'e' ends the number, so "0xe-1" is not one literal.
	CHECK_FALSE(VariantParser::parse_string("0xe-1", v, &error));
}

// A scene of p_lights OmniLight3D nodes, each with a transform and four numeric properties.
static String _light_scene(int p_lights) {
	String text = "[gd_scene format=3]\n\n[node name=\"Root\" type=\"Node3D\"]\n";
	for (int i = 0; i < p_lights; i++) {
		text += vformat("\n[node name=\"Light%d\" type=\"OmniLight3D\" parent=\".\"]\n"
						"transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, %d.25, 1.5, -%d.125)\n"
						"light_energy = 1.25e-01\nomni_range = 12.5\nomni_attenuation = 0.75\nlight_specular = 0.5\n",
				i, i % 97, i % 89);
	}
	return text;
}

// Process CPU time (the machine is shared: wall time would measure the neighbours).
static double _cpu_seconds() {
	return double(clock()) / CLOCKS_PER_SEC;
}

// Best of p_tries: CPU seconds to load p_text p_reps times.
static double _load_seconds(const String &p_text, int p_reps, int p_tries) {
	// Only the load is timed; freeing the nodes is not (RendererSceneCull::notify_base_freed scans every
	// instance per freed base, a separate quadratic noted in doc/reliability.md).
	double best = 1e30;
	for (int t = 0; t < p_tries; t++) {
		double total = 0.0;
		for (int r = 0; r < p_reps; r++) {
			String error;
			double start = _cpu_seconds();
			Node *root = ResourceFormatText::load_scene_from_string(p_text, "res://lights.tscn", &error);
			total += _cpu_seconds() - start;
			REQUIRE_MESSAGE(root != nullptr, error);
			delete root;
		}
		best = std::min(best, total);
	}
	return best;
}

TEST_CASE("[VariantParser][SceneTree] scene loading is linear: 4,096 lights cost < 2x per node of 64 lights") {
	// Issue 20: _lex_number searched the rest of the file for an 'x' per character, so 1,024 lights took
	// 15.9 s and 4,096 took 260 s. The same number of nodes is loaded both ways (64 x 64 and 1 x 4,096).
	SceneTest::DummyServer server;
	const String small = _light_scene(64), large = _light_scene(4096);
	_load_seconds(small, 4, 1); // Warm up allocators and class lookups.
	const double t_small = _load_seconds(small, 64, 3);
	const double t_large = _load_seconds(large, 1, 3);
	const double ratio = t_large / std::max(t_small, 1e-6);
	MESSAGE("64 x 64 lights: ", t_small, " s CPU; 1 x 4096 lights: ", t_large, " s CPU; ratio ", ratio);
	CHECK_MESSAGE(ratio < 2.0, "per-node load time grows with the scene: ratio ", ratio);
}

TEST_CASE("[VariantParser][SceneTree] an endless or oversized scene file stops with an error naming it") {
	if (!std::filesystem::exists("/dev/zero")) {
		MESSAGE("skipped: /dev/zero is not available");
		return;
	}
	SceneTest::DummyServer server;
	SceneTest::ErrorCatcher catcher;
	String error;
	Node *root = ResourceFormatText::load_scene("/dev/zero", &error);
	CHECK(root == nullptr);
	CHECK_MESSAGE(error.find("/dev/zero:0: Cannot open the scene file: /dev/zero: larger than the 268435456-byte limit") != String::npos, error);
	delete root;
}

} // namespace TestVariantParser
