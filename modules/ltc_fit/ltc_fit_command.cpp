/**************************************************************************/
/*  ltc_fit_command.cpp                                                   */
/**************************************************************************/
/* godot-area: `godot-area ltc-fit` (see ltc_fit_command.h).              */

#include "modules/ltc_fit/ltc_fit_command.h"

#include "core/error/error_macros.h"
#include "modules/ltc_fit/ltc_fitter.h"
#include "modules/ltc_fit/ltc_polynomial.h"
#include "modules/ltc_fit/ltc_table_io.h"
#include "modules/ltc_fit/ltc_two_lobe.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <unistd.h>

namespace {

void _print_usage() {
	fprintf(stderr, "Usage: godot-area ltc-fit [--size N] [--brdf engine|smith|both] [-o PATH] [--cells r0:r1,t0:t1] [--threads N] [--free-axis] [--norm 1|2|3 | --polygons] [--smoothness S]\n");
	fprintf(stderr, "       godot-area ltc-fit --polynomial [-o PATH] [--glsl PATH]\n");
	fprintf(stderr, "       godot-area ltc-fit --two-lobe [-o PATH] [--cells r0:r1,t0:t1] [--threads N] [--smoothness S]\n");
}

// `ltc-fit --polynomial`: fits the degree-5 polynomials to the built-in LTC_LUT_ENGINE_GGX with its
// free-axis block refitted as the 3-parameter fit (LTCFitter::get_three_parameter_engine_table; thesis
// section 5.4.3) and writes the C++ include (-o) and the GLSL include (--glsl).
int _polynomial_command(const std::vector<String> &p_args, size_t p_first) {
	String out_path;
	String glsl_path;
	String command = "godot-area ltc-fit --polynomial";
	for (size_t i = p_first; i < p_args.size(); i++) {
		const String &a = p_args[i];
		if (a == "--polynomial") {
			continue;
		}
		if (a != "-o" && a != "--glsl") {
			ERR_PRINT(vformat("ltc-fit --polynomial: unknown or unsupported argument '%s' (only -o and --glsl).", a.c_str()));
			_print_usage();
			return 2;
		}
		if (i + 1 >= p_args.size() || p_args[i + 1].empty()) {
			ERR_PRINT(vformat("ltc-fit --polynomial: %s needs a non-empty path.", a.c_str()));
			return 2;
		}
		(a == "-o" ? out_path : glsl_path) = p_args[++i];
		command += " " + a + " " + p_args[i];
	}
	if (out_path.empty()) {
		out_path = String(LTCPolynomial::DEFAULT_INC_PATH);
	}
	if (glsl_path.empty()) {
		glsl_path = String(LTCPolynomial::DEFAULT_GLSL_PATH);
	}
	LTCPolynomial::Fit fit;
	std::vector<float> table;
	if (!LTCFitter::get_three_parameter_engine_table(table)) {
		ERR_PRINT("ltc-fit --polynomial: could not rebuild the 3-parameter table.");
		return 1;
	}
	if (!LTCPolynomial::fit_table(table.data(), LTCTableIO::get_builtin_size(), fit)) {
		ERR_PRINT("ltc-fit --polynomial: the fit failed.");
		return 1;
	}
	for (int k = 0; k < LTCPolynomial::COMPONENTS; k++) {
		printf("%-2s RMSE %.6f (%.6f up to theta_v 80 deg) max |error| %.6f at (ri %d, ti %d)\n", LTCPolynomial::COMPONENT_NAMES[k], fit.rmse[k], fit.rmse_80[k], fit.max_error[k],
				fit.max_error_r[k], fit.max_error_t[k]);
	}
	if (!LTCPolynomial::save_text(out_path, LTCPolynomial::format_inc(fit, command)) || !LTCPolynomial::save_text(glsl_path, LTCPolynomial::format_glsl(fit, command))) {
		return 1;
	}
	printf("Wrote %s and %s\n", out_path.c_str(), glsl_path.c_str());
	return 0;
}

bool _parse_int(const String &p_text, int *r_value) {
	if (p_text.empty()) {
		return false;
	}
	char *end = nullptr;
	long v = std::strtol(p_text.c_str(), &end, 10);
	if (*end != '\0' || v < -1000000 || v > 1000000) {
		return false;
	}
	*r_value = (int)v;
	return true;
}

bool _parse_range(const String &p_text, int *r_lo, int *r_hi) {
	std::vector<String> parts = string_split(p_text, ':');
	if (parts.size() == 1) {
		return _parse_int(parts[0], r_lo) && _parse_int(parts[0], r_hi);
	}
	return parts.size() == 2 && _parse_int(parts[0], r_lo) && _parse_int(parts[1], r_hi);
}

// `ltc-fit --two-lobe`: fits the two-lobe table (ltc_two_lobe.h) from the built-in 1-lobe engine table and
// writes ltc_lut_2lobe_data.inc (-o), or with --cells and no -o prints the fitted cells.
int _two_lobe_command(const std::vector<String> &p_args, size_t p_first) {
	const int size = LTCTableIO::get_builtin_size();
	int r0 = 0, r1 = size - 1, t0 = 0, t1 = size - 1, threads = 0;
	double smoothness = LTCTwoLobe::DEFAULT_SMOOTHNESS;
	String out_path;
	bool partial = false;
	String command = "godot-area ltc-fit --two-lobe";
	for (size_t i = p_first; i < p_args.size(); i++) {
		const String &a = p_args[i];
		if (a == "--two-lobe") {
			continue;
		}
		if (a != "-o" && a != "--cells" && a != "--threads" && a != "--smoothness") {
			ERR_PRINT(vformat("ltc-fit --two-lobe: unknown or unsupported argument '%s'.", a.c_str()));
			_print_usage();
			return 2;
		}
		if (i + 1 >= p_args.size() || p_args[i + 1].empty()) {
			ERR_PRINT(vformat("ltc-fit --two-lobe: %s needs a value.", a.c_str()));
			return 2;
		}
		const String &value = p_args[++i];
		command += " " + a + " " + value;
		if (a == "-o") {
			out_path = value;
		} else if (a == "--threads") {
			if (!_parse_int(value, &threads) || threads < 0 || threads > 1024) {
				ERR_PRINT(vformat("ltc-fit --two-lobe: --threads must be an integer in [0, 1024], got '%s'.", value.c_str()));
				return 2;
			}
		} else if (a == "--smoothness") {
			char *end = nullptr;
			smoothness = std::strtod(value.c_str(), &end);
			if (*end != '\0' || !(smoothness >= 0.0) || smoothness > 1e6) {
				ERR_PRINT(vformat("ltc-fit --two-lobe: --smoothness must be a number in [0, 1e6], got '%s'.", value.c_str()));
				return 2;
			}
		} else {
			std::vector<String> parts = string_split(value, ',');
			if (parts.size() != 2 || !_parse_range(parts[0], &r0, &r1) || !_parse_range(parts[1], &t0, &t1) || r0 < 0 || r1 >= size || r0 > r1 || t0 < 0 || t1 >= size || t0 > t1) {
				ERR_PRINT(vformat("ltc-fit --two-lobe: --cells must be r0:r1,t0:t1 inside the %dx%d table, got '%s'.", size, size, value.c_str()));
				return 2;
			}
			partial = true;
		}
	}
	const float *src = LTCTableIO::get_builtin_table(LTC_BRDF_ENGINE_GGX);
	const std::vector<float> one_lobe(src, src + size_t(size) * size * LTCFitter::FLOATS_PER_CELL);
	std::vector<float> table;
	std::vector<LTCTwoLobeCell> cells;
	std::atomic<int> done(0);
	const auto start = std::chrono::steady_clock::now();
	if (!LTCTwoLobe::fit_table(size, r0, r1, t0, t1, threads, smoothness, one_lobe, table, &cells, &done)) {
		ERR_PRINT("ltc-fit --two-lobe: the fit failed.");
		return 1;
	}
	const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	// Statistics: the polygon objective (relative squared error of the test lights' integrals) of the
	// 1-lobe and the two-lobe cells, over the block and over its grazing rows (theta_v >= 65 degrees).
	double sum1 = 0.0, sum2 = 0.0, g1 = 0.0, g2 = 0.0, worst2 = 0.0;
	int count = 0, grazing = 0, worst_r = 0, worst_t = 0;
	bool finite = true;
	for (int t = t0; t <= t1; t++) {
		for (int r = r0; r <= r1; r++) {
			const LTCTwoLobeCell &c = cells[size_t(t) * size + r];
			sum1 += c.error_one_lobe;
			sum2 += c.error;
			count++;
			if (LTCFitter::get_theta(size, t) >= 65.0 * LTCBRDF::BRDF_PI / 180.0) {
				g1 += c.error_one_lobe;
				g2 += c.error;
				grazing++;
			}
			if (c.error > worst2) {
				worst2 = c.error;
				worst_r = r;
				worst_t = t;
			}
			finite = finite && std::isfinite(c.error) && c.weights[0] >= 0.0f && c.weights[1] >= 0.0f;
			if (partial && out_path.empty()) {
				printf("ri %d ti %d: lobe 1 (%.6g %.6g %.6g %.6g %.6g) w %.6g | lobe 2 (%.6g %.6g %.6g %.6g %.6g) w %.6g | E 1-lobe %.6g 2-lobe %.6g | it %d\n", r, t,
						c.lobes[0][0], c.lobes[0][1], c.lobes[0][2], c.lobes[0][3], c.lobes[0][4], c.weights[0], c.lobes[1][0], c.lobes[1][1], c.lobes[1][2], c.lobes[1][3],
						c.lobes[1][4], c.weights[1], c.error_one_lobe, c.error, c.iterations);
			}
		}
	}
	const String stats = vformat("engine 2-lobe: %d cells (ri %d-%d, ti %d-%d), smoothness %g. Polygon objective (relative squared error of 180 test lights): mean 1-lobe %.5f -> 2-lobe %.5f; "
								 "rows theta_v >= 65 deg (%d cells) %.5f -> %.5f; worst 2-lobe %.5f at (ri %d, ti %d).",
			count, r0, r1, t0, t1, smoothness, sum1 / std::max(1, count), sum2 / std::max(1, count), grazing, g1 / std::max(1, grazing), g2 / std::max(1, grazing), worst2, worst_r, worst_t);
	printf("%s Wall time %.1f s.\n", stats.c_str(), seconds);
	if (!finite) {
		ERR_PRINT("ltc-fit --two-lobe: a cell has a non-finite objective or a negative weight.");
		return 1;
	}
	if (partial && out_path.empty()) {
		return 0;
	}
	if (out_path.empty()) {
		out_path = String(LTCTwoLobe::DEFAULT_INC_PATH);
	}
	if (!LTCTableIO::save_inc(out_path, LTCTwoLobe::format_inc(size, table, command, stats))) {
		return 1;
	}
	printf("Wrote %s\n", out_path.c_str());
	return 0;
}

struct VariantStats {
	double max_l1 = 0.0, mean_l1 = 0.0, max_l3 = 0.0, mean_l3 = 0.0, mean_iterations = 0.0, max_fn = 0.0;
	int max_l1_r = 0, max_l1_t = 0;
	int cells = 0;
	int below_01 = 0, below_025 = 0; // Cells with L1 < 0.1 and < 0.25.
	double mean_l1_60 = 0.0; // Mean L1 over the rows with theta_v <= 60 degrees.
	int cells_60 = 0;
	bool finite = true;
	bool positive_det = true;
};

VariantStats _compute_stats(int p_size, int p_r0, int p_r1, int p_t0, int p_t1, const std::vector<LTCCell> &p_cells) {
	VariantStats s;
	for (int t = p_t0; t <= p_t1; t++) {
		for (int r = p_r0; r <= p_r1; r++) {
			const LTCCell &c = p_cells[(size_t)t * p_size + r];
			s.cells++;
			s.mean_l1 += c.error_l1;
			s.below_01 += c.error_l1 < 0.1 ? 1 : 0;
			s.below_025 += c.error_l1 < 0.25 ? 1 : 0;
			if (LTCFitter::get_theta(p_size, t) <= 60.0 * LTCBRDF::BRDF_PI / 180.0) {
				s.mean_l1_60 += c.error_l1;
				s.cells_60++;
			}
			s.mean_l3 += c.error_l3;
			s.mean_iterations += c.iterations;
			s.max_l3 = std::max(s.max_l3, c.error_l3);
			s.max_fn = std::max(s.max_fn, (double)c.fn);
			if (c.error_l1 > s.max_l1) {
				s.max_l1 = c.error_l1;
				s.max_l1_r = r;
				s.max_l1_t = t;
			}
			const float v[7] = { c.a, c.b, c.c, c.d, c.e, c.fn, c.fg };
			for (float x : v) {
				s.finite = s.finite && std::isfinite(x);
			}
			const double det = (double)c.c * ((double)c.a * c.e - (double)c.b * c.d);
			s.positive_det = s.positive_det && det > 0.0;
		}
	}
	if (s.cells > 0) {
		s.mean_l1 /= s.cells;
		s.mean_l3 /= s.cells;
		s.mean_iterations /= s.cells;
	}
	if (s.cells_60 > 0) {
		s.mean_l1_60 /= s.cells_60;
	}
	return s;
}

String _format_stats(const char *p_name, const VariantStats &p_s) {
	const double pct = p_s.cells > 0 ? 100.0 / p_s.cells : 0.0;
	return vformat("%s: %d cells. L1 distance integral |rho - D| dl (0 = exact, 2 = disjoint): mean %.4f (%.4f over theta_v <= 60 deg), "
				   "max %.4f at (ri %d, ti %d); %.1f %% of cells below 0.1, %.1f %% below 0.25.\n"
				   "%s: L3 objective: mean %.4g, max %.4g (dominated by grazing near-mirror cells); mean Nelder-Mead iterations %.1f; max fn %.6f",
			p_name, p_s.cells, p_s.mean_l1, p_s.mean_l1_60, p_s.max_l1, p_s.max_l1_r, p_s.max_l1_t, p_s.below_01 * pct, p_s.below_025 * pct,
			p_name, p_s.mean_l3, p_s.max_l3, p_s.mean_iterations, p_s.max_fn);
}

// Fits one variant with a progress bar on stderr.
bool _fit_with_progress(LTCBRDFVariant p_variant, int p_size, int p_r0, int p_r1, int p_t0, int p_t1, int p_threads, const LTCFitOptions &p_options, std::vector<float> &r_table, std::vector<LTCCell> &r_cells, double *r_seconds) {
	std::atomic<int> done(0);
	std::atomic<bool> finished(false);
	bool ok = false;
	const int total = (p_r1 - p_r0 + 1) * (p_t1 - p_t0 + 1);
	const auto start = std::chrono::steady_clock::now();
	std::thread fitter([&]() {
		ok = LTCFitter::fit_table(p_variant, p_size, p_r0, p_r1, p_t0, p_t1, p_threads, r_table, &r_cells, &done, p_options);
		finished.store(true);
	});
	const bool tty = isatty(2);
	int last_printed = -1;
	while (!finished.load()) {
		std::this_thread::sleep_for(std::chrono::milliseconds(250));
		const int d = done.load();
		if (!tty && d * 10 / std::max(1, total) == last_printed) {
			continue; // Logs get a line per 10 %, terminals a live bar.
		}
		last_printed = d * 10 / std::max(1, total);
		const int width = 40;
		const int filled = total > 0 ? d * width / total : width;
		const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
		fprintf(stderr, "%s[ltc-fit %s] [%s%s] %d/%d cells, %.1f s%s", tty ? "\r" : "", LTCBRDF::get_variant_name(p_variant),
				String(filled, '#').c_str(), String(width - filled, '.').c_str(), d, total, secs, tty ? "" : "\n");
		fflush(stderr);
	}
	fitter.join();
	*r_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	fprintf(stderr, "%s[ltc-fit %s] %d/%d cells in %.1f s\n", tty ? "\r" : "", LTCBRDF::get_variant_name(p_variant), done.load(), total, *r_seconds);
	return ok;
}

} // namespace

int ltc_fit_command(const std::vector<String> &p_args) {
	int size = 64;
	int threads = 0;
	String brdf = "both";
	String out_path;
	String cells_arg;
	LTCFitOptions fit_options;
	size_t i = 0;
	if (!p_args.empty() && p_args[0] == "ltc-fit") {
		i = 1;
	}
	for (size_t j = i; j < p_args.size(); j++) {
		if (p_args[j] == "--polynomial") {
			return _polynomial_command(p_args, i);
		}
		if (p_args[j] == "--two-lobe") {
			return _two_lobe_command(p_args, i);
		}
	}
	String command = "godot-area ltc-fit";
	for (; i < p_args.size(); i++) {
		const String &a = p_args[i];
		if (a == "-h" || a == "--help") {
			_print_usage();
			return 0;
		}
		if (a == "--free-axis") {
			fit_options.free_axis = true;
			command += " --free-axis";
			continue;
		}
		if (a == "--polygons") {
			fit_options.polygons = true;
			command += " --polygons";
			continue;
		}
		const bool takes_value = a == "--size" || a == "--brdf" || a == "-o" || a == "--cells" || a == "--threads" || a == "--norm" || a == "--smoothness";
		if (!takes_value) {
			ERR_PRINT(vformat("ltc-fit: unknown argument '%s'.", a.c_str()));
			_print_usage();
			return 2;
		}
		if (i + 1 >= p_args.size()) {
			ERR_PRINT(vformat("ltc-fit: %s needs a value.", a.c_str()));
			_print_usage();
			return 2;
		}
		const String &value = p_args[++i];
		command += " " + a + " " + value;
		if (a == "--size") {
			if (!_parse_int(value, &size) || size < 2 || size > 256) {
				ERR_PRINT(vformat("ltc-fit: --size must be an integer in [2, 256], got '%s'.", value.c_str()));
				return 2;
			}
		} else if (a == "--threads") {
			if (!_parse_int(value, &threads) || threads < 0 || threads > 1024) {
				ERR_PRINT(vformat("ltc-fit: --threads must be an integer in [0, 1024], got '%s'.", value.c_str()));
				return 2;
			}
		} else if (a == "--smoothness") {
			char *end = nullptr;
			fit_options.smoothness = std::strtod(value.c_str(), &end);
			if (value.empty() || *end != '\0' || !(fit_options.smoothness >= 0.0) || fit_options.smoothness > 1e6) {
				ERR_PRINT(vformat("ltc-fit: --smoothness must be a number in [0, 1e6], got '%s'.", value.c_str()));
				return 2;
			}
		} else if (a == "--norm") {
			if (!_parse_int(value, &fit_options.norm) || fit_options.norm < 1 || fit_options.norm > 3) {
				ERR_PRINT(vformat("ltc-fit: --norm must be 1, 2 or 3, got '%s'.", value.c_str()));
				return 2;
			}
		} else if (a == "--brdf") {
			if (value != "engine" && value != "smith" && value != "both") {
				ERR_PRINT(vformat("ltc-fit: --brdf must be engine, smith or both, got '%s'.", value.c_str()));
				return 2;
			}
			brdf = value;
		} else if (a == "-o") {
			if (value.empty()) {
				ERR_PRINT("ltc-fit: -o needs a non-empty path.");
				return 2;
			}
			out_path = value;
		} else {
			cells_arg = value;
		}
	}

	int r0 = 0, r1 = size - 1, t0 = 0, t1 = size - 1;
	if (!cells_arg.empty()) {
		std::vector<String> parts = string_split(cells_arg, ',');
		if (parts.size() != 2 || !_parse_range(parts[0], &r0, &r1) || !_parse_range(parts[1], &t0, &t1)) {
			ERR_PRINT(vformat("ltc-fit: --cells must look like r0:r1,t0:t1, got '%s'.", cells_arg.c_str()));
			return 2;
		}
		if (r0 < 0 || r1 >= size || r0 > r1 || t0 < 0 || t1 >= size || t0 > t1) {
			ERR_PRINT(vformat("ltc-fit: --cells %s is outside the %dx%d table (indices 0..%d, lo <= hi).", cells_arg.c_str(), size, size, size - 1));
			return 2;
		}
	}
	const bool partial = !cells_arg.empty();
	const bool fit_engine = brdf != "smith";
	const bool fit_smith = brdf != "engine";
	const int builtin_size = LTCTableIO::get_builtin_size();
	const bool needs_builtin = (partial && r1 < size - 1) || !fit_engine || !fit_smith;
	if (needs_builtin && size != builtin_size) {
		ERR_PRINT(vformat("ltc-fit: the built-in table is %dx%d; with --size %d fit both variants and the whole table.", builtin_size, builtin_size, size));
		return 2;
	}

	const size_t n = (size_t)size * size * LTCFitter::FLOATS_PER_CELL;
	std::vector<float> tables[LTC_BRDF_MAX];
	for (int v = 0; v < LTC_BRDF_MAX; v++) {
		if (size == builtin_size) {
			const float *src = LTCTableIO::get_builtin_table((LTCBRDFVariant)v);
			tables[v].assign(src, src + n);
		} else {
			tables[v].assign(n, 0.0f);
		}
	}

	String stats_text;
	for (int v = 0; v < LTC_BRDF_MAX; v++) {
		if ((v == LTC_BRDF_ENGINE_GGX && !fit_engine) || (v == LTC_BRDF_SMITH_GGX && !fit_smith)) {
			stats_text += vformat("%s: kept from the previous table (not refitted).\n", LTCBRDF::get_variant_name((LTCBRDFVariant)v));
			continue;
		}
		std::vector<LTCCell> cells;
		double seconds = 0.0;
		if (!_fit_with_progress((LTCBRDFVariant)v, size, r0, r1, t0, t1, threads, fit_options, tables[v], cells, &seconds)) {
			ERR_PRINT("ltc-fit: the fit failed.");
			return 1;
		}
		VariantStats s = _compute_stats(size, r0, r1, t0, t1, cells);
		const String line = _format_stats(LTCBRDF::get_variant_name((LTCBRDFVariant)v), s);
		printf("%s; wall time %.1f s\n", line.c_str(), seconds);
		stats_text += line + "\n";
		if (!s.finite || !s.positive_det) {
			ERR_PRINT(vformat("ltc-fit: the %s table has non-finite values or a matrix with det <= 0.", LTCBRDF::get_variant_name((LTCBRDFVariant)v)));
			return 1;
		}
		if (partial && (r1 - r0 + 1) * (t1 - t0 + 1) <= 64) {
			const float *builtin = size == builtin_size ? LTCTableIO::get_builtin_table((LTCBRDFVariant)v) : nullptr;
			for (int t = t0; t <= t1; t++) {
				for (int r = r0; r <= r1; r++) {
					const size_t at = ((size_t)t * size + r) * LTCFitter::FLOATS_PER_CELL;
					const LTCCell &c = cells[(size_t)t * size + r];
					double diff = 0.0;
					if (builtin) {
						for (int k = 0; k < 7; k++) {
							diff = std::max(diff, (double)std::fabs(tables[v][at + k] - builtin[at + k]));
						}
					}
					printf("%s ri %d ti %d: a %.9g b %.9g c %.9g d %.9g e %.9g fn %.9g fg %.9g | L1 %.5f L3 %.5g it %d | max |diff| to built-in %s\n",
							LTCBRDF::get_variant_name((LTCBRDFVariant)v), r, t, c.a, c.b, c.c, c.d, c.e, c.fn, c.fg, c.error_l1, c.error_l3, c.iterations,
							builtin ? vformat("%.3g", diff).c_str() : "n/a");
				}
			}
		}
	}

	if (partial && out_path.empty()) {
		return 0;
	}
	if (out_path.empty()) {
		out_path = String(LTCTableIO::DEFAULT_INC_PATH);
	}
	const String text = LTCTableIO::format_inc(size, tables[LTC_BRDF_ENGINE_GGX], tables[LTC_BRDF_SMITH_GGX], command, stats_text);
	if (!LTCTableIO::save_inc(out_path, text)) {
		return 1;
	}
	printf("Wrote %s\n", out_path.c_str());
	return 0;
}
