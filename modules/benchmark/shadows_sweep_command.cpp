/**************************************************************************/
/*  shadows_sweep_command.cpp                                             */
/**************************************************************************/
/* godot-area: the `bench --sweep shadows` command (see the header).      */

#include "modules/benchmark/shadows_sweep_command.h"

#include "modules/benchmark/shadows_sweep.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

int shadows_usage_error(const String &p_message) {
	fprintf(stderr, "godot-area bench --sweep shadows: %s\n", p_message.c_str());
	return 2;
}

bool parse_number(const String &p_text, double p_min, double p_max, double &r_value) {
	char *end = nullptr;
	double v = strtod(p_text.c_str(), &end);
	if (p_text.empty() || *end != '\0' || !std::isfinite(v) || v < p_min || v > p_max) {
		return false;
	}
	r_value = v;
	return true;
}

bool parse_list(const String &p_text, double p_min, double p_max, std::vector<double> &r_values) {
	r_values.clear();
	for (const String &item : string_split(p_text, ',')) {
		double v = 0.0;
		if (!parse_number(item, p_min, p_max, v)) {
			return false;
		}
		r_values.push_back(v);
	}
	return !r_values.empty();
}

} // namespace

int shadows_sweep_command(const std::vector<String> &p_args) {
	ShadowsSweep::Options options;
	String csv = "doc/results/shadows_sweep.csv";
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		std::vector<double> list;
		double v = 0.0;
		if (a == "bench") {
			continue;
		} else if (a == "--sweep") {
			if (!has_value || p_args[i + 1] != "shadows") {
				return shadows_usage_error("--sweep expects 'shadows'.");
			}
			i++;
		} else if (a == "--progress") {
			options.progress = true;
		} else if (a == "--no-errors") {
			options.errors = false;
		} else if (a == "--no-timing") {
			options.timing = false;
		} else if (!has_value) {
			return shadows_usage_error(vformat("unknown option '%s' or missing value.", a.c_str()));
		} else if (a == "--csv") {
			csv = p_args[++i];
		} else if (a == "--resolution") {
			if (!parse_number(p_args[++i], 8, 1024, v) || v != std::floor(v)) {
				return shadows_usage_error("--resolution expects an integer 8..1024.");
			}
			options.resolution = int(v);
		} else if (a == "--frames") {
			if (!parse_number(p_args[++i], 1, 1000, v) || v != std::floor(v)) {
				return shadows_usage_error("--frames expects an integer 1..1000.");
			}
			options.frames = int(v);
		} else if (a == "--reference-error") {
			if (!parse_number(p_args[++i], 0.0005, 0.5, v)) {
				return shadows_usage_error("--reference-error expects 0.0005..0.5.");
			}
			options.reference_error = float(v);
		} else if (a == "--atlas") {
			if (!parse_list(p_args[++i], 256, 16384, list)) {
				return shadows_usage_error("--atlas expects powers of two 256..16384, comma separated.");
			}
			options.atlas_sizes.clear();
			for (double s : list) {
				int n = int(s);
				if (double(n) != s || (n & (n - 1)) != 0) {
					return shadows_usage_error(vformat("--atlas: %g is not a power of two.", s));
				}
				options.atlas_sizes.push_back(n);
			}
		} else if (a == "--maps") {
			if (!parse_list(p_args[++i], 4, 81, list)) {
				return shadows_usage_error("--maps expects squares 4..81 (4,9,16,..,81), comma separated.");
			}
			options.grids.clear();
			for (double m : list) {
				int g = int(std::lround(std::sqrt(m)));
				if (double(g * g) != m) {
					return shadows_usage_error(vformat("--maps: %g is not a square of 2..9.", m));
				}
				options.grids.push_back(g);
			}
		} else if (a == "--blur") {
			if (!parse_list(p_args[++i], 0, 4, list)) {
				return shadows_usage_error("--blur expects shadow_blur values 0..4, comma separated.");
			}
			options.blurs.clear();
			for (double b : list) {
				options.blurs.push_back(float(b));
			}
		} else if (a == "--images") {
			if (i + 1 >= p_args.size()) {
				return shadows_usage_error("--images expects a folder.");
			}
			options.images_dir = p_args[++i];
		} else {
			return shadows_usage_error(vformat("unknown option '%s'.", a.c_str()));
		}
	}
	std::vector<ShadowsSweep::Row> rows;
	String error;
	if (!ShadowsSweep::run(options, rows, &error)) {
		fprintf(stderr, "godot-area bench --sweep shadows: %s\n", error.c_str());
		return 1;
	}
	if (!options.images_dir.empty()) {
		printf("shadows sweep: images written to %s\n", options.images_dir.c_str());
		return 0;
	}
	if (!ShadowsSweep::write_csv(csv, rows, &error)) {
		fprintf(stderr, "godot-area bench --sweep shadows: %s\n", error.c_str());
		return 1;
	}
	printf("shadows sweep: %zu rows written to %s\n", rows.size(), csv.c_str());
	return 0;
}
