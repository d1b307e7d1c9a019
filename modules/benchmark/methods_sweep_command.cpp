/**************************************************************************/
/*  methods_sweep_command.cpp                                             */
/**************************************************************************/
/* godot-area: the `bench --sweep methods` command (see the header).      */

#include "modules/benchmark/methods_sweep_command.h"

#include "modules/benchmark/bench_charts.h"
#include "modules/benchmark/methods_sweep.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace {

const char *DEFAULT_CSV = "doc/results/methods_sweep.csv";
const char *DEFAULT_SHAPES_CSV = "doc/results/methods_shapes.csv"; // --shapes without --csv.
const char *CHART_SCRIPT = "plot_methods.py"; // misc/scripts/, run by BenchCharts.

bool parse_int(const String &p_text, int p_min, int p_max, int &r_value) {
	char *end = nullptr;
	long v = strtol(p_text.c_str(), &end, 10);
	if (p_text.empty() || *end != '\0' || v < p_min || v > p_max) {
		return false;
	}
	r_value = int(v);
	return true;
}

int usage_error(const String &p_message) {
	fprintf(stderr, "godot-area bench --sweep methods: %s\n", p_message.c_str());
	return 2;
}

} // namespace

int methods_sweep_command(const std::vector<String> &p_args) {
	MethodsSweep::Options options;
	options.csv_path = DEFAULT_CSV;
	bool charts = true;
	bool maps_given = false;
	bool csv_given = false;
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		if (a == "bench") {
			continue;
		} else if (a == "--sweep") {
			// Main strips "--sweep methods"; accepted here too for direct callers.
			if (!has_value || p_args[i + 1] != "methods") {
				return usage_error("--sweep expects 'methods'.");
			}
			i++;
		} else if (a == "--progress") {
			options.progress = true;
		} else if (a == "--no-charts") {
			charts = false;
		} else if (a == "--shapes") {
			options.shapes = true;
		} else if (a == "--no-errors") {
			options.errors = false;
		} else if (a == "--no-timing") {
			options.timing = false;
		} else if (a == "--spirv-sources") {
			if (!has_value) {
				return usage_error("--spirv-sources needs a directory.");
			}
			String error;
			if (!MethodsSweep::write_shader_sources(p_args[i + 1], &error)) {
				fprintf(stderr, "godot-area bench --sweep methods: %s\n", error.c_str());
				return 1;
			}
			printf("Wrote the per-method fragment sources to %s\n", p_args[i + 1].c_str());
			return 0;
		} else if (a == "--csv" || a == "--maps" || a == "--resolution" || a == "--lights" || a == "--frames" || a == "--warmup" || a == "--error-resolution" || a == "--configs" || a == "--frame-cap-ms") {
			if (!has_value) {
				return usage_error(a + " needs a value.");
			}
			const String v = p_args[++i];
			if (a == "--csv") {
				if (v.empty()) {
					return usage_error("--csv needs a non-empty path.");
				}
				options.csv_path = v;
				csv_given = true;
			} else if (a == "--maps") {
				options.maps_dir = v;
				maps_given = true;
			} else if (a == "--resolution") {
				std::vector<String> wh = string_split(v, 'x');
				if (wh.size() != 2 || !parse_int(wh[0], 1, 4096, options.width) || !parse_int(wh[1], 1, 4096, options.height)) {
					return usage_error("--resolution expects WxH (1..4096), got '" + v + "'.");
				}
			} else if (a == "--lights") {
				options.light_counts.clear();
				for (const String &n : string_split(v, ',', false)) {
					int count = 0;
					if (!parse_int(n, 1, 512, count)) {
						return usage_error("--lights expects counts in 1..512, got '" + n + "'.");
					}
					options.light_counts.push_back(count);
				}
				if (options.light_counts.empty()) {
					return usage_error("--lights needs at least one count.");
				}
			} else if (a == "--frames") {
				if (!parse_int(v, 1, 1000, options.frames)) {
					return usage_error("--frames expects 1..1000, got '" + v + "'.");
				}
			} else if (a == "--warmup") {
				if (!parse_int(v, 0, 1000, options.warmup_frames)) {
					return usage_error("--warmup expects 0..1000, got '" + v + "'.");
				}
			} else if (a == "--frame-cap-ms") {
				int cap = 0;
				if (!parse_int(v, 0, 10000000, cap)) {
					return usage_error("--frame-cap-ms expects a number of milliseconds (0 = no cap), got '" + v + "'.");
				}
				options.frame_cap_ms = double(cap);
			} else if (a == "--error-resolution") {
				if (!parse_int(v, 8, 1024, options.error_resolution)) {
					return usage_error("--error-resolution expects 8..1024, got '" + v + "'.");
				}
			} else {
				for (const String &c : string_split(v, ',', false)) {
					options.only_configs.push_back(c); // Checked below, once --shapes is known.
				}
			}
		} else {
			return usage_error("unknown argument '" + a + "'.");
		}
	}
	const std::vector<MethodsSweep::Config> known_configs = options.shapes ? MethodsSweep::shape_configs() : MethodsSweep::default_configs();
	for (const String &c : options.only_configs) {
		bool known = false;
		String names;
		for (const MethodsSweep::Config &config : known_configs) {
			known = known || config.name == c;
			names += (names.empty() ? "" : ", ") + config.name;
		}
		if (!known) {
			return usage_error("unknown configuration '" + c + "'" + (options.shapes ? " on the shape axis" : "") + " (" + names + ").");
		}
	}
	if (options.shapes) {
		if (!csv_given) {
			options.csv_path = DEFAULT_SHAPES_CSV;
		}
		if (maps_given) {
			return usage_error("--maps has no failure strips to write with --shapes.");
		}
	}
	if (charts) {
		String tools_error;
		if (!BenchCharts::check(CHART_SCRIPT, &tools_error)) {
			fprintf(stderr, "godot-area bench --sweep methods: %s Nothing was run.\n", tools_error.c_str());
			return 1;
		}
	}
	// Charts need the failure-scene strips: without --maps they go to a temporary directory.
	if (charts && !maps_given && options.errors && !options.shapes) {
		std::error_code ec;
		const std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
		options.maps_dir = (ec ? String("/tmp") : String(tmp.string())) + "/godot_area_methods_maps_" + itos((int64_t)getpid());
	}
	const String csv_dir = BenchCharts::directory_of(options.csv_path);
	std::error_code exists_ec;
	if (!std::filesystem::exists(csv_dir, exists_ec)) {
		std::error_code ec;
		std::filesystem::create_directories(csv_dir, ec);
		if (ec) {
			fprintf(stderr, "godot-area bench --sweep methods: cannot create the CSV's directory '%s': %s\n", csv_dir.c_str(), ec.message().c_str());
			return 1;
		}
	}
	std::vector<MethodsSweep::Row> rows;
	String error;
	if (!MethodsSweep::run(options, &rows, &error)) {
		fprintf(stderr, "godot-area bench --sweep methods: %s\n", error.c_str());
		if (charts && !maps_given && !options.maps_dir.empty()) {
			std::error_code ec;
			std::filesystem::remove_all(options.maps_dir, ec);
		}
		return 1;
	}
	// Summary: GPU ms of the opaque pass per configuration and light count, mean FLIP per configuration.
	// Shape rows: keyed "shape config", mean relative RMSE beside the FLIP.
	std::map<String, std::pair<double, int>> flip, rel_rmse;
	for (const MethodsSweep::Row &r : rows) {
		const String key = r.shape.empty() ? r.config : r.shape + " " + r.config;
		if (r.section == "timing" || r.section == "shape_timing") {
			printf("%-16s %4d lights  opaque %9.3f ms  GPU %9.3f ms\n", key.c_str(), r.lights, r.gpu_ms_opaque, r.gpu_ms_total);
		} else {
			flip[key].first += r.flip;
			flip[key].second++;
			rel_rmse[key].first += r.relative_rmse;
		}
	}
	for (const auto &kv : flip) {
		printf("%-16s mean LDR-FLIP %.4f over %d scenes", kv.first.c_str(), kv.second.first / kv.second.second, kv.second.second);
		if (options.shapes) {
			printf(", mean relative RMSE %.4f", rel_rmse[kv.first].first / kv.second.second);
		}
		printf("\n");
	}
	printf("Wrote %s\n", options.csv_path.c_str());
	if (charts) {
		String chart_error;
		std::vector<String> extra_args;
		if (!options.maps_dir.empty()) {
			extra_args = { "--maps", options.maps_dir };
		}
		const bool drawn = BenchCharts::draw(CHART_SCRIPT, options.csv_path, extra_args, &chart_error);
		if (!maps_given && !options.maps_dir.empty()) {
			std::error_code ec;
			std::filesystem::remove_all(options.maps_dir, ec);
		}
		if (!drawn) {
			fprintf(stderr, "godot-area bench --sweep methods: %s The CSV %s was written.\n", chart_error.c_str(), options.csv_path.c_str());
			return 1;
		}
		printf("Charts written to %s\n", csv_dir.c_str());
	}
	return 0;
}
