/**************************************************************************/
/*  accuracy_command.cpp                                                  */
/**************************************************************************/
/* godot-area: argument parsing and output of `bench --accuracy`.         */

#include "modules/accuracy/accuracy_command.h"

#include "modules/accuracy/accuracy_ltc_terms.h"
#include "modules/accuracy/accuracy_suite.h"
#include "modules/ltc_fit/ltc_table_io.h"

#include <cstdio>
#include <cstdlib>

namespace {

bool parse_int(const String &p_text, int p_min, int p_max, int &r_value) {
	char *end = nullptr;
	long v = strtol(p_text.c_str(), &end, 10);
	if (p_text.empty() || *end != '\0' || v < p_min || v > p_max) {
		return false;
	}
	r_value = int(v);
	return true;
}

// `bench --accuracy --ltc-terms`: the LTC error decomposition (accuracy_ltc_terms.h) of the selected plane
// scenes, one line each; other scenes are counted and skipped.
int ltc_terms_command(const AccuracySuite::Options &p_options, int p_light_samples, const String &p_lut) {
	std::vector<float> table;
	if (!p_lut.empty()) {
		int size = 0;
		std::vector<float> smith;
		String error;
		if (!LTCTableIO::load_inc(p_lut, &size, &table, &smith, &error)) {
			fprintf(stderr, "godot-area bench --accuracy --ltc-terms: %s\n", error.c_str());
			return 1;
		}
	}
	std::vector<AccuracyScenes::Scene> scenes = p_options.ci_subset ? AccuracyScenes::ci_subset() : AccuracyScenes::full_suite();
	int skipped = 0, done = 0;
	for (const AccuracyScenes::Scene &scene : scenes) {
		if (!p_options.filter.empty() && scene.id.find(p_options.filter) == String::npos) {
			continue;
		}
		if (scene.receiver != AccuracyScenes::RECEIVER_PLANE || scene.shape != RS::LIGHT_AREA_SHAPE_RECTANGLE) {
			skipped++;
			continue;
		}
		AccuracyLTCTerms::Result result;
		String error;
		if (!AccuracyLTCTerms::evaluate(scene, p_options.resolution, p_light_samples, &result, &error, p_lut.empty() ? nullptr : &table)) {
			fprintf(stderr, "godot-area bench --accuracy --ltc-terms: %s\n", error.c_str());
			return 1;
		}
		printf("%s", AccuracyLTCTerms::format(result).c_str());
		fflush(stdout);
		done++;
	}
	printf("%d scenes decomposed (relRMSE (brightness ratio)); %d skipped (not a plane lit by a rectangle)\n", done, skipped);
	return done > 0 ? 0 : 1;
}

} // namespace

int accuracy_command(const std::vector<String> &p_args) {
	AccuracySuite::Options options;
	bool ltc_terms = false;
	int light_samples = 128;
	String lut;
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		if (a == "--accuracy" || a == "bench") {
			continue;
		} else if (a == "--ci") {
			options.ci_subset = true;
		} else if (a == "--shapes") {
			options.shapes = true;
		} else if (a == "--ltc-terms") {
			ltc_terms = true;
		} else if (a == "--lut") {
			if (!has_value) {
				fprintf(stderr, "godot-area bench --accuracy: --lut needs a path (an ltc_lut_data.inc written by ltc-fit)\n");
				return 2;
			}
			lut = p_args[++i];
		} else if (a == "--light-samples") {
			if (!has_value || !parse_int(p_args[++i], 4, 4096, light_samples)) {
				fprintf(stderr, "godot-area bench --accuracy: --light-samples must be an integer in [4, 4096]\n");
				return 2;
			}
		} else if (a == "--progress") {
			options.progress = true;
		} else if ((a == "--csv" || a == "--thumbnails" || a == "--filter" || a == "--resolution" || a == "--methods") && !has_value) {
			fprintf(stderr, "godot-area bench --accuracy: %s needs a value\n", a.c_str());
			return 2;
		} else if (a == "--csv") {
			options.csv_path = p_args[++i];
		} else if (a == "--thumbnails") {
			options.thumbnails_dir = p_args[++i];
		} else if (a == "--filter") {
			options.filter = p_args[++i];
		} else if (a == "--resolution") {
			if (!parse_int(p_args[++i], 1, 1024, options.resolution)) {
				fprintf(stderr, "godot-area bench --accuracy: --resolution must be an integer in [1, 1024], got '%s'\n", p_args[i].c_str());
				return 2;
			}
		} else if (a == "--methods") {
			for (const String &m : string_split(p_args[++i], ',')) {
				int value = 0;
				if (!parse_int(m, 0, 1000, value)) {
					fprintf(stderr, "godot-area bench --accuracy: --methods takes shading method numbers separated by commas (0 = LTC), got '%s'\n", p_args[i].c_str());
					return 2;
				}
				options.methods.push_back(value);
			}
		} else {
			fprintf(stderr, "godot-area bench --accuracy: unknown argument '%s'\n", a.c_str());
			return 2;
		}
	}
	if (ltc_terms) {
		return ltc_terms_command(options, light_samples, lut);
	}
	std::vector<AccuracySuite::Row> rows;
	String error;
	if (!AccuracySuite::run(options, &rows, &error)) {
		fprintf(stderr, "godot-area bench --accuracy: %s\n", error.c_str());
		return 1;
	}
	printf("%s", AccuracySuite::summary_table(rows).c_str());
	double reference_ms = 0.0, engine_ms = 0.0;
	int references = 0;
	for (const AccuracySuite::Row &r : rows) {
		if (r.method == rows.front().method) {
			reference_ms += r.reference_ms;
			references++;
		}
		engine_ms += r.engine_ms;
	}
	printf("%zu comparisons at %dx%d; reference %.1f ms per image (mean of %d), engine %.1f ms per frame (mean wall time of draw())\n", rows.size(), options.resolution, options.resolution,
			references ? reference_ms / references : 0.0, references, rows.empty() ? 0.0 : engine_ms / rows.size());
	if (!options.csv_path.empty()) {
		printf("wrote %s\n", options.csv_path.c_str());
	}
	return 0;
}
