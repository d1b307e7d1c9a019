/**************************************************************************/
/*  dolly_sweep_command.cpp                                               */
/**************************************************************************/
/* godot-area: the `bench --sweep dolly` command (see the header).        */

#include "modules/benchmark/dolly_sweep_command.h"

#include "core/error/error_macros.h"
#include "modules/benchmark/bench_charts.h"
#include "modules/benchmark/dolly_sweep.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

int dolly_usage_error(const String &p_message) {
	fprintf(stderr, "godot-area bench --sweep dolly: %s\n", p_message.c_str());
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

bool parse_int(const String &p_text, int p_min, int p_max, int &r_value) {
	double v = 0.0;
	if (!parse_number(p_text, p_min, p_max, v) || v != std::floor(v)) {
		return false;
	}
	r_value = int(v);
	return true;
}

} // namespace

int dolly_sweep_command(const std::vector<String> &p_args) {
	DollySweep::Options options;
	String csv = "doc/results/dolly.csv";
	bool charts = true;
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		double v = 0.0;
		if (a == "bench") {
			continue;
		} else if (a == "--sweep") {
			if (!has_value || p_args[i + 1] != "dolly") {
				return dolly_usage_error("--sweep expects 'dolly'.");
			}
			i++;
		} else if (a == "--progress") {
			options.progress = true;
		} else if (a == "--no-errors") {
			options.errors = false;
		} else if (a == "--no-charts") {
			charts = false;
		} else if (!has_value) {
			return dolly_usage_error(vformat("unknown option '%s' or missing value.", a.c_str()));
		} else if (a == "--csv") {
			csv = p_args[++i];
		} else if (a == "--positions") {
			if (!parse_int(p_args[++i], 1, 100, options.positions)) {
				return dolly_usage_error("--positions expects an integer 1..100.");
			}
		} else if (a == "--far") {
			if (!parse_number(p_args[++i], 0.1, 18.0, v)) {
				return dolly_usage_error("--far expects a distance 0.1..18 (metres).");
			}
			options.far_distance = float(v);
		} else if (a == "--near") {
			if (!parse_number(p_args[++i], 0.1, 18.0, v)) {
				return dolly_usage_error("--near expects a distance 0.1..18 (metres).");
			}
			options.near_distance = float(v);
		} else if (a == "--resolution") {
			std::vector<String> wh = string_split(p_args[++i], 'x');
			if (wh.size() != 2 || !parse_int(wh[0], 4, 1024, options.ref_width) || !parse_int(wh[1], 4, 1024, options.ref_height)) {
				return dolly_usage_error("--resolution expects WxH of the reference image, 4..1024 each (e.g. 128x72).");
			}
		} else if (a == "--supersample") {
			if (!parse_int(p_args[++i], 1, 9, options.supersample) || options.supersample % 2 == 0) {
				return dolly_usage_error("--supersample expects an odd integer 1..9.");
			}
		} else if (a == "--modes") {
			options.modes.clear();
			for (const String &name : string_split(p_args[++i], ',')) {
				DollySweep::ModeSpec mode;
				if (!DollySweep::parse_mode(name, mode)) {
					return dolly_usage_error(vformat("--modes: unknown mode '%s' (adaptive, heuristic, pcss, fixed4..fixed81).", name.c_str()));
				}
				options.modes.push_back(mode);
			}
			if (options.modes.empty()) {
				return dolly_usage_error("--modes expects at least one mode.");
			}
		} else if (a == "--atlas") {
			if (!parse_int(p_args[++i], 256, 16384, options.atlas) || (options.atlas & (options.atlas - 1)) != 0) {
				return dolly_usage_error("--atlas expects a power of two 256..16384.");
			}
		} else if (a == "--subdivision") {
			if (!parse_int(p_args[++i], 1, 64, options.subdivision) || (options.subdivision & (options.subdivision - 1)) != 0) {
				return dolly_usage_error("--subdivision expects a power of two 1..64 (tiles per side).");
			}
		} else if (a == "--frames") {
			if (!parse_int(p_args[++i], 1, 1000, options.frames)) {
				return dolly_usage_error("--frames expects an integer 1..1000.");
			}
		} else if (a == "--converge-max") {
			if (!parse_int(p_args[++i], 1, 10000, options.converge_max)) {
				return dolly_usage_error("--converge-max expects an integer 1..10000.");
			}
		} else if (a == "--converge-stable") {
			if (!parse_int(p_args[++i], 1, 1000, options.converge_stable)) {
				return dolly_usage_error("--converge-stable expects an integer 1..1000.");
			}
		} else if (a == "--blur") {
			if (!parse_number(p_args[++i], 0.0, 4.0, v)) {
				return dolly_usage_error("--blur expects a shadow_blur 0..4.");
			}
			options.blur = float(v);
		} else if (a == "--reference-error") {
			if (!parse_number(p_args[++i], 0.0005, 0.5, v)) {
				return dolly_usage_error("--reference-error expects 0.0005..0.5.");
			}
			options.reference_error = float(v);
		} else {
			return dolly_usage_error(vformat("unknown option '%s'.", a.c_str()));
		}
	}
	if (options.near_distance >= options.far_distance) {
		return dolly_usage_error("--near must be smaller than --far.");
	}
	std::vector<DollySweep::Row> rows;
	String error;
	if (!DollySweep::run(options, rows, &error)) {
		fprintf(stderr, "godot-area bench --sweep dolly: %s\n", error.c_str());
		return 1;
	}
	if (!DollySweep::write_csv(csv, rows, &error)) {
		fprintf(stderr, "godot-area bench --sweep dolly: %s\n", error.c_str());
		return 1;
	}
	printf("dolly sweep: %zu rows written to %s\n", rows.size(), csv.c_str());
	if (charts && !BenchCharts::draw("plot_dolly.py", csv, {}, &error)) {
		WARN_PRINT("godot-area bench --sweep dolly: " + error);
	}
	printf("%s", DollySweep::format_targets(DollySweep::compute_targets(rows)).c_str());
	return 0;
}
