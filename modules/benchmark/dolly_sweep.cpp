/**************************************************************************/
/*  dolly_sweep.cpp                                                       */
/**************************************************************************/
/* godot-area: the adaptive-shadow dolly benchmark (see the header).      */

#include "modules/benchmark/dolly_sweep.h"
#include "core/io/file_io.h"

#include "core/math/math_funcs.h"
#include "modules/benchmark/penumbra_scene.h"
#include "modules/benchmark/shadows_sweep.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "scene/main/godot_instance.h"
#include "servers/rendering_server.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

namespace {

// Middle of the box's penumbra on the +X side of the floor (box edge at 0.25 m, outer edge ~1.45 m).
const Vector3 TARGET(0.85f, 0.0f, 0.0f);
// From the target towards the camera: above, in front and to the side of the penumbra (the box stays behind).
const Vector3 CAMERA_DIRECTION(0.55f, 0.75f, 0.9f);

struct FrameTimes {
	double shadow_maps = -1.0;
	double reprojection = -1.0;
	double banding = -1.0;
	double total = -1.0;
};

FrameTimes read_profile(const std::vector<std::pair<String, double>> &p_profile) {
	FrameTimes t;
	auto add = [](double &r_value, double p_ms) {
		r_value = r_value < 0.0 ? p_ms : r_value + p_ms;
	};
	for (const std::pair<String, double> &e : p_profile) {
		if (e.first == "area_shadows") {
			add(t.shadow_maps, e.second);
		} else if (e.first.find("reproj") != String::npos) {
			add(t.reprojection, e.second);
		} else if (e.first.find("band") != String::npos) {
			add(t.banding, e.second);
		}
		add(t.total, e.second); // Each pass is timed from the previous timestamp: the sum is the frame.
	}
	return t;
}

// Median of the values >= 0; -1 when there are none.
double median(std::vector<double> p_values) {
	p_values.erase(std::remove_if(p_values.begin(), p_values.end(), [](double v) { return !(v >= 0.0); }), p_values.end());
	if (p_values.empty()) {
		return -1.0;
	}
	std::sort(p_values.begin(), p_values.end());
	size_t n = p_values.size();
	return n % 2 ? p_values[n / 2] : 0.5 * (p_values[n / 2 - 1] + p_values[n / 2]);
}

PenumbraScene::Settings scene_settings(const DollySweep::Options &p_options) {
	PenumbraScene::Settings s;
	s.light_range = p_options.light_range;
	return s;
}

RenderSceneData make_position_view(const DollySweep::Options &p_options, int p_index, int p_width, int p_height) {
	return PenumbraScene::make_view(DollySweep::get_camera_position(p_options, p_index), DollySweep::get_target(), p_width, p_height);
}

// Mean of p_value over p_rows of mode p_mode at positions [p_from, p_to); -1 if any is missing.
double mean_over(const std::vector<DollySweep::Row> &p_rows, const String &p_mode, int p_from, int p_to, double (*p_value)(const DollySweep::Row &)) {
	double sum = 0.0;
	int n = 0;
	for (const DollySweep::Row &r : p_rows) {
		if (r.mode != p_mode || r.position < p_from || r.position >= p_to) {
			continue;
		}
		double v = p_value(r);
		if (!(v >= 0.0)) {
			return -1.0;
		}
		sum += v;
		n++;
	}
	return n > 0 ? sum / n : -1.0;
}

double shadow_work(const DollySweep::Row &p_row) {
	if (p_row.shadow_maps_ms < 0.0) {
		return -1.0;
	}
	return p_row.shadow_maps_ms + std::max(p_row.reprojection_ms, 0.0) + std::max(p_row.banding_ms, 0.0);
}

} // namespace

std::vector<DollySweep::ModeSpec> DollySweep::default_modes() {
	std::vector<ModeSpec> modes(4);
	parse_mode("adaptive", modes[0]);
	parse_mode("heuristic", modes[1]);
	parse_mode("fixed25", modes[2]);
	parse_mode("fixed81", modes[3]);
	return modes;
}

bool DollySweep::parse_mode(const String &p_name, ModeSpec &r_mode) {
	String name = p_name;
	std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	if (name == "adaptive") {
		r_mode = { "ADAPTIVE", RS::LIGHT_AREA_SHADOW_ADAPTIVE, 0 };
		return true;
	}
	if (name == "heuristic") {
		r_mode = { "HEURISTIC", RS::LIGHT_AREA_SHADOW_HEURISTIC, 0 };
		return true;
	}
	if (name == "pcss") {
		r_mode = { "PCSS", RS::LIGHT_AREA_SHADOW_PCSS_BASELINE, 1 };
		return true;
	}
	if (name.compare(0, 5, "fixed") == 0) {
		String digits = name.substr(5);
		if (!digits.empty() && digits[0] == '_') {
			digits = digits.substr(1);
		}
		if (digits.empty() || digits.size() > 2 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
			return false;
		}
		int maps = std::stoi(digits);
		for (int g = RS::LIGHT_AREA_SHADOW_GRID_MIN; g <= RS::LIGHT_AREA_SHADOW_GRID_MAX; g++) {
			if (g * g == maps) {
				r_mode = { vformat("FIXED_%d", maps), RS::LIGHT_AREA_SHADOW_FIXED, g };
				return true;
			}
		}
	}
	return false;
}

Vector3 DollySweep::get_target() {
	return TARGET;
}

Vector3 DollySweep::get_camera_position(const Options &p_options, int p_index) {
	const int n = std::max(p_options.positions, 1);
	float t = n > 1 ? float(p_index) / float(n - 1) : 0.0f;
	float far_d = std::max(p_options.far_distance, 0.01f);
	float near_d = std::max(p_options.near_distance, 0.01f);
	float d = far_d * std::pow(near_d / far_d, t); // Geometric: equal steps in log distance (screen size).
	return TARGET + CAMERA_DIRECTION.normalized() * d;
}

bool DollySweep::run(const Options &p_options, std::vector<Row> &r_rows, String *r_error) {
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	const int rw = p_options.ref_width, rh = p_options.ref_height, ss = p_options.supersample;
	if (rw < 4 || rh < 4 || rw > 1024 || rh > 1024) {
		return fail(vformat("reference size %dx%d is out of range (4..1024).", rw, rh));
	}
	if (ss < 1 || ss % 2 == 0 || rw * ss > 4096 || rh * ss > 4096) {
		return fail(vformat("supersample %d must be odd and keep the image within 4096 px.", ss));
	}
	if (p_options.positions < 1 || p_options.positions > 100 || p_options.frames < 1 || p_options.converge_max < 1 || p_options.converge_stable < 1) {
		return fail("positions (1..100), frames, converge_max and converge_stable must be positive.");
	}
	if (p_options.modes.empty()) {
		return fail("no shadow modes to run.");
	}
	const int w = rw * ss, h = rh * ss;
	const int positions = p_options.positions;
	const PenumbraScene::Settings settings = scene_settings(p_options);

	// 1. The reference at every position, open and with shadow rays: the same scene through the server,
	// drawn by the Embree reference compositor.
	std::vector<std::vector<float>> ref_open(positions), ref_shadowed(positions);
	if (p_options.errors) {
		ReferenceRenderOptions options;
		options.threads = 0;
		options.target_relative_error = p_options.reference_error;
		options.max_samples = 4096;
		RendererCompositorReference *compositor = new RendererCompositorReference(options);
		GodotInstance reference;
		String error;
		if (!reference.start_with_compositor(compositor, &error)) {
			return fail(error);
		}
		PenumbraScene objects;
		if (!objects.create_in_server(reference.get_rendering_server(), rw, rh, settings)) {
			return fail("the reference scene could not be created.");
		}
		for (int i = 0; i < positions; i++) {
			objects.set_view(make_position_view(p_options, i, rw, rh));
			options.shadows = false;
			compositor->get_reference_renderer()->set_options(options);
			ref_open[i] = objects.render();
			options.shadows = true;
			compositor->get_reference_renderer()->set_options(options);
			ref_shadowed[i] = objects.render();
			if (p_options.progress) {
				printf("[reference] position %d/%d (%.2f m) %dx%d done\n", i + 1, positions, double((get_camera_position(p_options, i) - TARGET).length()), rw, rh);
				fflush(stdout);
			}
		}
		objects.free();
	}

	// 2. The engine: one scene (scenario, viewport, atlas, light) per mode, only the drawn one active, so the
	// modes' timed frames interleave frame by frame (load changes on a shared machine hit them alike).
	String error;
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, &error, 8)) {
		return fail(error);
	}
	RenderingServer *rs = engine.get_rendering_server();
	bool ok = true;
	{
		const size_t mode_count = p_options.modes.size();
		std::vector<std::unique_ptr<PenumbraScene>> scenes;
		std::vector<int> subdivisions(mode_count, p_options.subdivision);
		std::vector<uint64_t> frames(mode_count, 0);
		const Transform3D rest = PenumbraScene::light_transform(settings);
		for (size_t m = 0; ok && m < mode_count; m++) {
			scenes.push_back(std::make_unique<PenumbraScene>());
			ok = scenes[m]->create_in_server(rs, w, h, settings);
			error = ok ? String() : String("The scene could not be created.");
			if (ok) {
				rs->viewport_set_active(scenes[m]->get_viewport(), false);
			}
		}
		auto activate = [&](size_t p_mode) {
			for (size_t m = 0; m < mode_count; m++) {
				rs->viewport_set_active(scenes[m]->get_viewport(), m == p_mode);
			}
		};
		auto set_position = [&](size_t p_mode, int p_index) {
			scenes[p_mode]->set_view(make_position_view(p_options, p_index, w, h));
		};
		auto map_count = [&]() -> int {
			return int(rs->get_rendering_info(RS::RENDERING_INFO_AREA_SHADOW_MAPS_IN_FRAME));
		};

		// Unshadowed images (the same for every mode), from the first mode's scene before its shadows go on.
		std::vector<std::vector<float>> open(positions);
		if (ok && p_options.errors) {
			activate(0);
			rs->light_set_shadow(scenes[0]->get_light(), false);
			scenes[0]->set_light_transform(rest);
			for (int i = 0; i < positions; i++) {
				set_position(0, i);
				open[i] = scenes[0]->render();
			}
		}

		for (size_t m = 0; ok && m < mode_count; m++) {
			const ModeSpec &mode = p_options.modes[m];
			const RID light = scenes[m]->get_light();
			const RID viewport = scenes[m]->get_viewport();
			if (mode.mode == RS::LIGHT_AREA_SHADOW_FIXED) {
				subdivisions[m] = std::max(subdivisions[m], ShadowsSweep::subdivision_for_grid(mode.grid));
			}
			rs->area_shadow_atlas_set_size(viewport, p_options.atlas, subdivisions[m]);
			if (rs->area_shadow_atlas_get_size(viewport) != p_options.atlas || rs->area_shadow_atlas_get_subdivision(viewport) != subdivisions[m]) {
				ok = false;
				error = vformat("atlas %d px with %d x %d tiles was rejected.", p_options.atlas, subdivisions[m], subdivisions[m]);
				break;
			}
			rs->light_area_set_shadow_mode(light, mode.mode);
			if (mode.mode == RS::LIGHT_AREA_SHADOW_FIXED) {
				rs->light_area_set_shadow_grid(light, mode.grid);
			}
			rs->light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, p_options.blur);
			rs->light_set_shadow(light, true);
		}
		// One frame of mode p_mode (the only active viewport).
		auto render_frame = [&](size_t p_mode, bool p_moving) {
			Transform3D xform = rest;
			if (p_moving && (frames[p_mode] % 2)) {
				xform.origin.x += 0.01f; // Every map redraws.
			}
			scenes[p_mode]->set_light_transform(xform);
			frames[p_mode]++;
			rs->draw();
		};

		for (int i = 0; ok && i < positions; i++) {
			std::vector<Row> rows(mode_count);
			std::vector<std::vector<double>> maps_ms(mode_count), reproj_ms(mode_count), banding_ms(mode_count), total_ms(mode_count), cpu_ms(mode_count);
			std::vector<uint64_t> draws(mode_count, 0);
			for (size_t m = 0; m < mode_count; m++) {
				Row &row = rows[m];
				row.mode = p_options.modes[m].name;
				row.position = i;
				row.distance = (get_camera_position(p_options, i) - TARGET).length();
				row.width = w;
				row.height = h;
				row.atlas = p_options.atlas;
				row.subdivision = subdivisions[m];
				row.tile = p_options.atlas / subdivisions[m];
				set_position(m, i);
				// Converge with the light at rest (a static view): the map count unchanged for converge_stable
				// frames in a row. The 1 cm light jitter of the timed frames would move the shadow edge between
				// two positions and make ADAPTIVE's banding answers alternate.
				activate(m);
				int last = -1, stable = 0;
				while (row.converge_frames < p_options.converge_max) {
					render_frame(m, false);
					row.converge_frames++;
					int maps = map_count();
					stable = maps == last ? stable + 1 : 1;
					last = maps;
					if (stable >= p_options.converge_stable) {
						break;
					}
				}
			}

			// Timing, interleaved: frame f of every mode, then frame f + 1.
			for (int f = 0; f < p_options.frames; f++) {
				for (size_t m = 0; m < mode_count; m++) {
					activate(m);
					auto t0 = std::chrono::steady_clock::now();
					render_frame(m, true);
					// Frames in flight: the profile read waits for this frame, so t1 - t0 is the whole frame.
					const std::vector<std::pair<String, double>> profile = rs->get_frame_profile();
					auto t1 = std::chrono::steady_clock::now();
					FrameTimes t = read_profile(profile);
					maps_ms[m].push_back(t.shadow_maps);
					reproj_ms[m].push_back(t.reprojection);
					banding_ms[m].push_back(t.banding);
					total_ms[m].push_back(t.total);
					cpu_ms[m].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
					draws[m] += rs->get_rendering_info(RS::RENDERING_INFO_AREA_SHADOW_DRAW_CALLS_IN_FRAME);
				}
			}

			for (size_t m = 0; m < mode_count; m++) {
				Row &row = rows[m];
				row.shadow_maps_ms = median(maps_ms[m]);
				row.reprojection_ms = median(reproj_ms[m]);
				row.banding_ms = median(banding_ms[m]);
				row.total_ms = median(total_ms[m]);
				row.cpu_ms = median(cpu_ms[m]);
				row.draws = double(draws[m]) / double(p_options.frames);

				// Error: the light at rest.
				activate(m);
				render_frame(m, false);
				row.maps = map_count();
				if (p_options.errors) {
					const std::vector<float> shadowed = rs->viewport_get_texture_data(scenes[m]->get_viewport()).get_data();
					PenumbraScene::visibility_error(open[i], shadowed, w, ref_open[i], ref_shadowed[i], rw, rh, ss, row.visibility_rmse, &row.penumbra_rmse);
				}
				if (p_options.progress) {
					printf("[%s] position %d/%d (%.2f m): %d maps (%d frames to converge), maps %.2f ms, reprojection %.2f ms, banding %.2f ms, total %.2f ms, visibility RMSE %.4f (penumbra %.4f)\n",
							row.mode.c_str(), i + 1, positions, double(row.distance), row.maps, row.converge_frames, row.shadow_maps_ms, row.reprojection_ms, row.banding_ms, row.total_ms, row.visibility_rmse, row.penumbra_rmse);
					fflush(stdout);
				}
			}
			r_rows.insert(r_rows.end(), rows.begin(), rows.end());
		}
		for (std::unique_ptr<PenumbraScene> &scene : scenes) {
			scene->free();
		}
		// Mode by mode, as the CSV has always listed them.
		std::stable_sort(r_rows.begin(), r_rows.end(), [&](const Row &p_a, const Row &p_b) {
			auto index = [&](const String &p_name) {
				for (size_t m = 0; m < p_options.modes.size(); m++) {
					if (p_options.modes[m].name == p_name) {
						return m;
					}
				}
				return p_options.modes.size();
			};
			return index(p_a.mode) < index(p_b.mode);
		});
	}
	engine.stop();
	return ok ? true : fail(error);
}

bool DollySweep::write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error) {
	FileWriteBuffer out; // Written atomically by commit(): no partial CSV on a full disk.
	FILE *f = out.file();
	if (!f) {
		if (r_error) {
			*r_error = "cannot write " + p_path + ": out of memory";
		}
		return false;
	}
	fprintf(f, "mode,position,distance,width,height,atlas,subdivision,tile,maps,draws,converge_frames,shadow_maps_ms,reprojection_ms,banding_ms,total_ms,cpu_ms,visibility_rmse,penumbra_rmse\n");
	for (const Row &r : p_rows) {
		fprintf(f, "%s,%d,%.4f,%d,%d,%d,%d,%d,%d,%.2f,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.6f,%.6f\n", r.mode.c_str(), r.position, double(r.distance), r.width, r.height,
				r.atlas, r.subdivision, r.tile, r.maps, r.draws, r.converge_frames, r.shadow_maps_ms, r.reprojection_ms, r.banding_ms, r.total_ms, r.cpu_ms,
				r.visibility_rmse, r.penumbra_rmse);
	}
	return out.commit(p_path, r_error);
}

DollySweep::Targets DollySweep::compute_targets(const std::vector<Row> &p_rows) {
	Targets t;
	int positions = 0;
	for (const Row &r : p_rows) {
		positions = std::max(positions, r.position + 1);
		if (r.mode == "ADAPTIVE" && (r.reprojection_ms >= 0.0 || r.banding_ms >= 0.0)) {
			t.has_adaptive_passes = true;
		}
	}
	if (positions == 0) {
		return t;
	}
	const int k = std::max(1, (positions + 3) / 4); // A quarter of the path at each end.
	t.far_count = k;
	auto total = [](const Row &r) { return r.total_ms; };
	auto rmse = [](const Row &r) { return r.visibility_rmse; };
	auto penumbra = [](const Row &r) { return r.penumbra_rmse; };
	double a = mean_over(p_rows, "ADAPTIVE", 0, k, total), b = mean_over(p_rows, "FIXED_25", 0, k, total);
	t.far_total_ratio = a > 0.0 && b > 0.0 ? a / b : -1.0;
	a = mean_over(p_rows, "ADAPTIVE", 0, k, rmse);
	b = mean_over(p_rows, "FIXED_25", 0, k, rmse);
	t.far_error_ratio = a >= 0.0 && b > 0.0 ? a / b : -1.0;
	a = mean_over(p_rows, "ADAPTIVE", 0, k, shadow_work);
	b = mean_over(p_rows, "FIXED_25", 0, k, shadow_work);
	t.far_shadow_ratio = a > 0.0 && b > 0.0 ? a / b : -1.0;
	a = mean_over(p_rows, "ADAPTIVE", positions - k, positions, rmse);
	b = mean_over(p_rows, "FIXED_81", positions - k, positions, rmse);
	t.near_error_ratio = a >= 0.0 && b > 0.0 ? a / b : -1.0;
	a = mean_over(p_rows, "ADAPTIVE", positions - k, positions, penumbra);
	b = mean_over(p_rows, "FIXED_81", positions - k, positions, penumbra);
	t.near_penumbra_ratio = a >= 0.0 && b > 0.0 ? a / b : -1.0;
	if (t.has_adaptive_passes) {
		double overhead = 0.0, maps = 0.0;
		for (const Row &r : p_rows) {
			if (r.mode == "ADAPTIVE") {
				overhead += std::max(r.reprojection_ms, 0.0) + std::max(r.banding_ms, 0.0);
				maps += std::max(r.shadow_maps_ms, 0.0);
			}
		}
		t.overhead_ratio = maps > 0.0 ? overhead / maps : -1.0;
	}
	return t;
}

String DollySweep::format_targets(const Targets &p_targets) {
	auto value = [](double v, double p_target) {
		if (v < 0.0) {
			return String("n/a");
		}
		return vformat("%.4f (target <= %.2f: %s)", v, p_target, v <= p_target ? "met" : "missed");
	};
	String s = vformat("dolly targets (far = the %d farthest positions, near = the %d nearest, means):\n", p_targets.far_count, p_targets.far_count);
	s += "  ADAPTIVE / FIXED_25 total GPU ms, far:               " + value(p_targets.far_total_ratio, 0.6) + "\n";
	s += "    (shadow work only: maps + reprojection + banding:   " + (p_targets.far_shadow_ratio < 0.0 ? String("n/a") : vformat("%.4f", p_targets.far_shadow_ratio)) + ")\n";
	s += "  ADAPTIVE / FIXED_25 visibility RMSE, far:            " + value(p_targets.far_error_ratio, 1.2) + "\n";
	s += "  ADAPTIVE / FIXED_81 visibility RMSE, near:            " + value(p_targets.near_error_ratio, 1.0) + "\n";
	s += "    (penumbra pixels only:                              " + (p_targets.near_penumbra_ratio < 0.0 ? String("n/a") : vformat("%.4f", p_targets.near_penumbra_ratio)) + ")\n";
	s += "  ADAPTIVE (reprojection + banding) / shadow-map ms:    " + (p_targets.has_adaptive_passes ? value(p_targets.overhead_ratio, 0.15) : String("n/a (no reprojection/banding passes in the profile)")) + "\n";
	return s;
}
