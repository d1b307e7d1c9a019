/**************************************************************************/
/*  isr_sweep_command.cpp                                                 */
/**************************************************************************/
/* godot-area: the `bench --sweep isr` command (see the header).          */

#include "modules/benchmark/isr_sweep_command.h"

#include "core/error/error_macros.h"
#include "core/io/file_io.h"
#include "modules/benchmark/bench_charts.h"
#include "modules/benchmark/isr_sweep.h"
#include "scene/main/godot_instance.h"
#include "servers/rendering_server.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>

namespace {

int isr_usage_error(const String &p_message) {
	fprintf(stderr, "godot-area bench --sweep isr: %s\n", p_message.c_str());
	return 2;
}

bool parse_int(const String &p_text, int p_min, int p_max, int &r_value) {
	char *end = nullptr;
	const long v = strtol(p_text.c_str(), &end, 10);
	if (p_text.empty() || *end != '\0' || v < p_min || v > p_max) {
		return false;
	}
	r_value = int(v);
	return true;
}

struct QualityRow {
	String scene;
	int frame = 0;
	IsrQuality q;
};

struct TimingRow {
	int width = 0;
	int height = 0;
	int samples = 0; // 0 = SSIL off.
	double opaque_ms = 0.0; // Medians over the rounds.
	double isr_ms = 0.0;
	double cpu_ms = 0.0; // Process CPU time per frame (mean).
	double ratio = 0.0; // isr_ms / opaque_ms.
};

double median(std::vector<double> p_v) {
	if (p_v.empty()) {
		return 0.0;
	}
	std::sort(p_v.begin(), p_v.end());
	return p_v[p_v.size() / 2];
}

double profile_ms(const RenderingServer *p_rs, const char *p_name) {
	for (const auto &kv : p_rs->get_frame_profile()) {
		if (kv.first == p_name) {
			return kv.second;
		}
	}
	return 0.0;
}

// The timing part: one engine, every configuration a viewport of its own (the room in a scenario of
// its own, as its SSIL settings live in the scenario's environment), one frame per round each.
bool run_timing(int p_rounds, bool p_progress, std::vector<TimingRow> &r_rows, String *r_error) {
	const int sizes[3][2] = { { 160, 120 }, { 320, 240 }, { 640, 480 } };
	const int samples[4] = { 0, 24, 48, 80 };
	const IsrScene room = IsrScene::make_room(IsrScene::ROOM_CORNELL);
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, r_error, 64)) {
		return false;
	}
	RenderingServer *rs = engine.get_rendering_server();
	struct Config {
		IsrServerScene view;
		ScreenSpaceLightingSettings settings;
		std::vector<double> opaque, isr;
		double cpu = 0.0;
		TimingRow row;
	};
	std::vector<std::unique_ptr<Config>> configs;
	bool ok = true;
	for (const auto &s : sizes) {
		for (int n : samples) {
			std::unique_ptr<Config> c(new Config);
			ok = ok && c->view.create(rs, room, s[0], s[1]);
			c->view.set_active(false);
			if (n > 0) {
				c->settings = IsrSweep::default_settings();
				c->settings.ssil_quality = n == 24 ? RS::ENV_SSIL_QUALITY_LOW : (n == 48 ? RS::ENV_SSIL_QUALITY_MEDIUM : RS::ENV_SSIL_QUALITY_HIGH);
			}
			c->view.set_screen_space_lighting(c->settings);
			c->row.width = s[0];
			c->row.height = s[1];
			c->row.samples = n;
			configs.push_back(std::move(c));
		}
	}
	for (int round = -1; ok && round < p_rounds; round++) { // Round -1 warms up (shader compiles, first uploads).
		for (std::unique_ptr<Config> &c : configs) {
			c->view.set_active(true);
			c->view.set_screen_space_lighting(c->settings); // The quality is global: set it per draw.
			const clock_t t0 = clock();
			rs->draw();
			rs->get_frame_profile(); // Frames in flight: waits for this frame, so t1 - t0 covers all of it.
			const clock_t t1 = clock();
			c->view.set_active(false);
			if (round >= 0) {
				c->cpu += double(t1 - t0) * 1000.0 / CLOCKS_PER_SEC;
				c->opaque.push_back(profile_ms(rs, "opaque"));
				c->isr.push_back(profile_ms(rs, "ss_radiosity"));
			}
		}
		if (p_progress) {
			printf("[timing] round %d/%d\n", round + 1, p_rounds);
			fflush(stdout);
		}
	}
	for (std::unique_ptr<Config> &c : configs) {
		if (ok) {
			c->row.opaque_ms = median(c->opaque);
			c->row.isr_ms = median(c->isr);
			c->row.cpu_ms = c->cpu / std::max(p_rounds, 1);
			c->row.ratio = c->row.opaque_ms > 0.0 ? c->row.isr_ms / c->row.opaque_ms : 0.0;
			r_rows.push_back(c->row);
		}
		c->view.free();
	}
	if (!ok && r_error) {
		*r_error = "the timing scenes could not be created.";
	}
	return ok;
}

bool write_quality_csv(const String &p_path, const std::vector<QualityRow> &p_rows, String *r_error) {
	FileWriteBuffer out; // Atomic: no partial CSV.
	FILE *f = out.file();
	if (!f) {
		if (r_error) {
			*r_error = "cannot write " + p_path + ": out of memory";
		}
		return false;
	}
	fprintf(f, "scene,frame,indirect_pixels,improved_pixels,improved_share,mean_error_dl,mean_error_isr,mean_error_gain,pearson_dl,pearson_isr,quality\n");
	for (const QualityRow &r : p_rows) {
		fprintf(f, "%s,%d,%d,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%d\n", r.scene.c_str(), r.frame, r.q.indirect_pixels, r.q.improved_pixels, r.q.improved_share,
				r.q.mean_error_dl, r.q.mean_error_isr, r.q.mean_error_gain, r.q.pearson_dl, r.q.pearson_isr, r.q.quality);
	}
	return out.commit(p_path, r_error);
}

bool write_timing_csv(const String &p_path, const std::vector<TimingRow> &p_rows, String *r_error) {
	FileWriteBuffer out;
	FILE *f = out.file();
	if (!f) {
		if (r_error) {
			*r_error = "cannot write " + p_path + ": out of memory";
		}
		return false;
	}
	fprintf(f, "width,height,samples,opaque_ms,isr_ms,isr_over_opaque,cpu_ms_per_frame\n");
	for (const TimingRow &r : p_rows) {
		fprintf(f, "%d,%d,%d,%.4f,%.4f,%.4f,%.4f\n", r.width, r.height, r.samples, r.opaque_ms, r.isr_ms, r.ratio, r.cpu_ms);
	}
	return out.commit(p_path, r_error);
}

} // namespace

int isr_sweep_command(const std::vector<String> &p_args) {
	String csv = "doc/results/isr_quality.csv";
	int width = 64, height = 48, bounce_samples = 32, rounds = 6;
	bool quality = true, timing = true, charts = true, progress = false;
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		if (a == "bench") {
			continue;
		} else if (a == "--sweep") {
			if (!has_value || p_args[i + 1] != "isr") {
				return isr_usage_error("--sweep expects 'isr'.");
			}
			i++;
		} else if (a == "--no-quality") {
			quality = false;
		} else if (a == "--no-timing") {
			timing = false;
		} else if (a == "--no-charts") {
			charts = false;
		} else if (a == "--progress") {
			progress = true;
		} else if (!has_value) {
			return isr_usage_error(vformat("unknown option '%s' or missing value.", a.c_str()));
		} else if (a == "--csv") {
			csv = p_args[++i];
		} else if (a == "--resolution") {
			std::vector<String> wh = string_split(p_args[++i], 'x');
			if (wh.size() != 2 || !parse_int(wh[0], 8, 1024, width) || !parse_int(wh[1], 8, 1024, height)) {
				return isr_usage_error("--resolution expects WxH, 8..1024 each (e.g. 96x72).");
			}
		} else if (a == "--bounce-samples") {
			if (!parse_int(p_args[++i], 1, 4096, bounce_samples)) {
				return isr_usage_error("--bounce-samples expects an integer 1..4096.");
			}
		} else if (a == "--frames") {
			if (!parse_int(p_args[++i], 1, 1000, rounds)) {
				return isr_usage_error("--frames expects an integer 1..1000.");
			}
		} else {
			return isr_usage_error(vformat("unknown option '%s'.", a.c_str()));
		}
	}
	String error;
	if (charts && !BenchCharts::check("plot_isr.py", &error)) {
		WARN_PRINT("godot-area bench --sweep isr: no charts: " + error);
		charts = false;
	}
	const String timing_csv = BenchCharts::directory_of(csv) + "/isr_timing.csv";
	if (quality) {
		std::vector<QualityRow> rows;
		const struct {
			const char *name;
			IsrScene scene;
		} scenes[2] = { { "room", IsrScene::make_room(IsrScene::ROOM_CORNELL) }, { "open", IsrScene::make_open() } };
		const ReferenceRenderOptions ro = IsrSweep::truth_options(bounce_samples);
		for (const auto &s : scenes) {
			for (int frame = 0; frame < int(s.scene.camera_path.size()); frame++) {
				IsrImages images;
				QualityRow row;
				row.scene = s.name;
				row.frame = frame;
				if (!IsrSweep::render_gpu(s.scene, frame, width, height, IsrSweep::default_settings(), images, &error) || !IsrSweep::render_truth(s.scene, frame, width, height, ro, images, &error) ||
						!IsrSweep::evaluate(images, row.q, &error)) {
					fprintf(stderr, "godot-area bench --sweep isr: %s frame %d: %s\n", s.name, frame, error.c_str());
					return 1;
				}
				rows.push_back(row);
				printf("%s frame %d: indirect pixels %d, ISR closer on %.2f %%, mean error DL %.5f ISR %.5f (gain %.2f %%), Pearson DL %.4f ISR %.4f, f_q %d\n", s.name, frame,
						row.q.indirect_pixels, 100.0 * row.q.improved_share, row.q.mean_error_dl, row.q.mean_error_isr, 100.0 * row.q.mean_error_gain, row.q.pearson_dl, row.q.pearson_isr, row.q.quality);
				fflush(stdout);
			}
		}
		if (!write_quality_csv(csv, rows, &error)) {
			fprintf(stderr, "godot-area bench --sweep isr: %s\n", error.c_str());
			return 1;
		}
		printf("isr sweep: %zu quality rows written to %s\n", rows.size(), csv.c_str());
	}
	if (timing) {
		std::vector<TimingRow> rows;
		if (!run_timing(rounds, progress, rows, &error)) {
			fprintf(stderr, "godot-area bench --sweep isr: %s\n", error.c_str());
			return 1;
		}
		for (const TimingRow &r : rows) {
			printf("%dx%d samples %d: opaque %.3f ms, ISR %.3f ms (%.1f %% of opaque), CPU %.2f ms/frame\n", r.width, r.height, r.samples, r.opaque_ms, r.isr_ms, 100.0 * r.ratio, r.cpu_ms);
		}
		if (!write_timing_csv(timing_csv, rows, &error)) {
			fprintf(stderr, "godot-area bench --sweep isr: %s\n", error.c_str());
			return 1;
		}
		printf("isr sweep: %zu timing rows written to %s\n", rows.size(), timing_csv.c_str());
	}
	if (charts && quality && timing && !BenchCharts::draw("plot_isr.py", csv, { "--timing", timing_csv }, &error)) {
		WARN_PRINT("godot-area bench --sweep isr: " + error);
	}
	return 0;
}
