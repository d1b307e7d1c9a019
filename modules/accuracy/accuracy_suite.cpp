/**************************************************************************/
/*  accuracy_suite.cpp                                                    */
/**************************************************************************/
/* godot-area: the area-light accuracy suite runner (see the header).     */

#include "modules/accuracy/accuracy_suite.h"
#include "core/io/file_io.h"

#include "core/error/error_macros.h"
#include "core/io/tonemap.h"
#include "drivers/png/png_writer.h"
#include "modules/accuracy/accuracy_scenes.h"
#include "modules/metrics/heatmap.h"
#include "modules/metrics/image_metrics.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "scene/main/godot_instance.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/rendering_server_default.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace {

struct Thumb {
	double flip = 0.0;
	size_t scene = 0;
	Image engine;
	std::vector<float> flip_map;
};

// Renders one scene in the current server; returns the image (empty on failure).
Image render_scene(RenderingServer *p_rs, const AccuracyScenes::Scene &p_scene, int p_resolution, int p_method, bool p_warm_up, double *r_wall_ms, double *r_gpu_ms, String *r_error) {
	AccuracyScenes::Built built;
	if (!AccuracyScenes::build(p_rs, p_scene, p_resolution, p_method, &built, r_error)) {
		return Image();
	}
	if (p_warm_up) {
		p_rs->draw(); // Compiles the pipelines of this method outside the timed frame.
	}
	auto begin = std::chrono::steady_clock::now();
	p_rs->draw();
	// Frames in flight: reading the profile waits for this frame, so the wall time is the whole frame's.
	const std::vector<std::pair<String, double>> profile = p_rs->get_frame_profile();
	*r_wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
	double gpu = 0.0;
	for (const auto &pass : profile) {
		gpu += pass.second;
	}
	*r_gpu_ms = gpu;
	Image image = p_rs->viewport_get_texture_data(built.viewport);
	AccuracyScenes::free_scene(p_rs, built);
	if (image.get_width() != p_resolution || image.get_height() != p_resolution) {
		*r_error = vformat("Scene %s: the renderer returned a %dx%d image, expected %dx%d.", p_scene.id.c_str(), image.get_width(), image.get_height(), p_resolution, p_resolution);
		return Image();
	}
	return image;
}

String csv_field(const String &p_text) {
	if (p_text.find_first_of(",\"\n") == String::npos) {
		return p_text;
	}
	String out = "\"";
	for (char c : p_text) {
		out += c == '"' ? String("\"\"") : String(1, c);
	}
	return out + "\"";
}

} // namespace

String AccuracySuite::method_name(int p_method) {
	// RS::LightAreaShadingMethod values as numbers (this file compiles whichever methods exist yet);
	// keep in step as values are appended.
	switch (p_method) {
		case 0:
			return "LTC";
		case 1:
			return "LTC_POLYNOMIAL";
		case 2:
			return "MRP";
		case 3:
			return "STOCHASTIC";
		case 4:
			return "AUTO";
		case 5:
			return "LTC_2LOBE";
		default:
			return "method_" + itos(p_method);
	}
}

bool AccuracySuite::run(const Options &p_options, std::vector<Row> *r_rows, String *r_error) {
	String error;
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	if (!r_rows) {
		return fail("AccuracySuite::run needs an output vector.");
	}
	r_rows->clear();
	if (p_options.resolution < 1 || p_options.resolution > 1024) {
		return fail(vformat("The accuracy suite resolution must be in [1, 1024], got %d.", p_options.resolution));
	}
	if (RenderingServer::get_singleton()) {
		return fail("AccuracySuite::run creates its own rendering servers; a RenderingServer already exists (stop the running GodotInstance first).");
	}
	std::vector<int> methods = p_options.methods.empty() ? std::vector<int>{ RS::LIGHT_AREA_SHADING_LTC } : p_options.methods;
	std::vector<AccuracyScenes::Scene> all = p_options.shapes ? (p_options.ci_subset ? AccuracyScenes::shape_ci_subset() : AccuracyScenes::shape_suite())
															  : (p_options.ci_subset ? AccuracyScenes::ci_subset() : AccuracyScenes::full_suite());
	std::vector<AccuracyScenes::Scene> scenes;
	for (const AccuracyScenes::Scene &s : all) {
		if (p_options.filter.empty() || s.id.find(p_options.filter) != String::npos) {
			scenes.push_back(s);
		}
	}
	if (scenes.empty()) {
		return fail("No accuracy scene matches the filter '" + p_options.filter + "'.");
	}
	const int res = p_options.resolution;

	// 1. The reference, once per scene (the method does not apply to it).
	std::vector<Image> references(scenes.size());
	std::vector<double> reference_ms(scenes.size()), reference_spp(scenes.size());
	{
		ReferenceRenderOptions options;
		options.shadows = false;
		options.seed = 0;
		options.threads = p_options.reference_threads;
		RendererCompositorReference *compositor = new RendererCompositorReference(options);
		GodotInstance reference;
		if (!reference.start_with_compositor(compositor, &error)) {
			return fail(error);
		}
		RenderingServer *rs = reference.get_rendering_server();
		for (size_t i = 0; i < scenes.size(); i++) {
			double wall = 0.0, gpu = 0.0;
			references[i] = render_scene(rs, scenes[i], res, RS::LIGHT_AREA_SHADING_LTC, false, &wall, &gpu, &error);
			if (references[i].is_empty()) {
				return fail("Reference: " + error);
			}
			const ReferenceRenderStats &stats = compositor->get_reference_renderer()->get_last_stats();
			reference_ms[i] = stats.seconds * 1000.0;
			reference_spp[i] = double(stats.area_light_samples) / (double(res) * res);
			if (p_options.progress) {
				printf("[reference %zu/%zu] %s: %.0f ms, %.0f samples/pixel\n", i + 1, scenes.size(), scenes[i].id.c_str(), reference_ms[i], reference_spp[i]);
				fflush(stdout);
			}
		}
	}

	// 2. The engine, per method, compared at once; the worst scenes are kept for thumbnails.
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, &error, 64)) {
		return fail(error);
	}
	RenderingServer *rs = engine.get_rendering_server();
	bool ok = true;
	std::map<int, std::vector<Thumb>> worst;
	const int keep = std::max(0, p_options.thumbnails_per_method);
	for (int method : methods) {
		for (size_t i = 0; i < scenes.size() && ok; i++) {
			double wall = 0.0, gpu = 0.0;
			Image engine = render_scene(rs, scenes[i], res, method, i == 0, &wall, &gpu, &error);
			if (engine.is_empty()) {
				error = "Engine (" + method_name(method) + "): " + error;
				ok = false;
				break;
			}
			ImageMetrics::Result m;
			if (!ImageMetrics::compare(engine, references[i], &m, &error)) {
				error = "Scene " + scenes[i].id + ": " + error;
				ok = false;
				break;
			}
			const AccuracyScenes::Scene &s = scenes[i];
			Row row;
			row.scene_id = s.id;
			row.receiver = AccuracyScenes::receiver_name(s.receiver);
			row.roughness = s.roughness;
			row.metallic = s.metallic;
			row.light_width = s.light_size.x;
			row.light_height = s.light_size.y;
			row.placement = AccuracyScenes::placement_name(s.placement);
			row.view_elevation = s.view_elevation;
			row.method = method;
			row.method_name = method_name(method);
			row.resolution = res;
			row.rmse = m.rmse;
			row.relative_mse = m.relative_mse;
			row.relative_rmse = m.relative_rmse;
			row.brightness_ratio = m.brightness_ratio;
			row.mae = m.mae;
			row.pearson = m.pearson;
			row.ssim = m.ssim;
			row.flip = m.flip;
			row.hdr_flip = m.has_hdr_flip ? m.hdr_flip : 0.0;
			row.engine_ms = wall;
			row.engine_gpu_ms = gpu;
			row.reference_ms = reference_ms[i];
			row.reference_samples_per_pixel = reference_spp[i];
			r_rows->push_back(row);
			if (p_options.progress) {
				printf("[%s %zu/%zu] %s: relRMSE %.4f ratio %.3f FLIP %.4f RMSE %.4f SSIM %.4f\n", row.method_name.c_str(), i + 1, scenes.size(), s.id.c_str(), m.relative_rmse, m.brightness_ratio, m.flip, m.rmse, m.ssim);
				fflush(stdout);
			}
			if (!p_options.thumbnails_dir.empty() && keep > 0) {
				std::vector<Thumb> &list = worst[method];
				if (int(list.size()) < keep || m.flip > list.back().flip) {
					Thumb t;
					t.flip = m.flip;
					t.scene = i;
					t.engine = engine;
					t.flip_map = m.flip_map;
					if (int(list.size()) >= keep) {
						list.pop_back();
					}
					list.push_back(std::move(t));
					std::sort(list.begin(), list.end(), [](const Thumb &a, const Thumb &b) { return a.flip > b.flip; });
				}
			}
		}
		if (!ok) {
			break;
		}
	}
	engine.stop();
	if (!ok) {
		return fail(error);
	}

	if (!p_options.thumbnails_dir.empty()) {
		std::error_code ec;
		std::filesystem::create_directories(p_options.thumbnails_dir, ec);
		for (const auto &entry : worst) {
			for (const Thumb &t : entry.second) {
				String path = p_options.thumbnails_dir + "/" + method_name(entry.first) + "_" + scenes[t.scene].id + ".png";
				if (!write_thumbnail(t.engine, references[t.scene], t.flip_map, path, &error)) {
					return fail(error);
				}
			}
		}
	}
	if (!p_options.csv_path.empty() && !write_csv(p_options.csv_path, *r_rows, &error)) {
		return fail(error);
	}
	return true;
}

bool AccuracySuite::write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error) {
	FileWriteBuffer out; // Written atomically by commit(): no partial CSV on a full disk.
	FILE *f = out.file();
	if (!f) {
		if (r_error) {
			*r_error = "Cannot write the accuracy CSV '" + p_path + "': out of memory.";
		}
		return false;
	}
	fprintf(f, "scene_id,receiver,roughness,metallic,light_width,light_height,placement,method,method_name,resolution,rmse,relative_mse,mae,pearson,ssim,flip,hdr_flip,engine_ms,engine_gpu_ms,reference_ms,reference_samples_per_pixel,relative_rmse,brightness_ratio,view_elevation\n");
	for (const Row &r : p_rows) {
		fprintf(f, "%s,%s,%g,%g,%g,%g,%s,%d,%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.3f,%.3f,%.1f,%.1f,%.6g,%.6g,%g\n", csv_field(r.scene_id).c_str(), csv_field(r.receiver).c_str(), r.roughness, r.metallic, r.light_width, r.light_height,
				csv_field(r.placement).c_str(), r.method, csv_field(r.method_name).c_str(), r.resolution, r.rmse, r.relative_mse, r.mae, r.pearson, r.ssim, r.flip, r.hdr_flip, r.engine_ms, r.engine_gpu_ms,
				r.reference_ms, r.reference_samples_per_pixel, r.relative_rmse, r.brightness_ratio, r.view_elevation);
	}
	return out.commit(p_path, r_error);
}

AccuracySuite::SceneClass AccuracySuite::scene_class(const Row &p_row) {
	if (p_row.placement == "horizon" && p_row.receiver == "plane") {
		return CLASS_CROSSING;
	}
	if (p_row.view_elevation > 0.0f && p_row.view_elevation <= 25.0f) {
		return CLASS_GRAZING_VIEW;
	}
	if (p_row.view_elevation == 0.0f && (p_row.placement == "facing" || p_row.placement == "close" || p_row.placement == "far")) {
		return CLASS_FACING;
	}
	return CLASS_OBLIQUE;
}

const char *AccuracySuite::scene_class_name(SceneClass p_class) {
	switch (p_class) {
		case CLASS_FACING:
			return "facing";
		case CLASS_OBLIQUE:
			return "oblique";
		case CLASS_GRAZING_VIEW:
			return "grazing view";
		case CLASS_CROSSING:
			return "crossing";
		default:
			return "unknown";
	}
}

namespace {

// Error statistics of a group of rows. Relative RMSE and brightness ratio skip rows whose reference is
// black (NaN there); `black` counts them so nothing is dropped silently.
struct GroupStats {
	int count = 0;
	int black = 0;
	double flip_sum = 0.0, flip_max = -1.0, rmse_sum = 0.0, rmse_max = 0.0, ssim_sum = 0.0, ssim_min = 2.0;
	double rel_sum = 0.0, rel_max = -1.0, ratio_min = 1e300, ratio_max = -1e300;
	String worst; // By relative RMSE (by FLIP when every reference is black).
	String worst_flip;

	void add(const AccuracySuite::Row &p_row) {
		count++;
		flip_sum += p_row.flip;
		rmse_sum += p_row.rmse;
		ssim_sum += p_row.ssim;
		rmse_max = std::max(rmse_max, p_row.rmse);
		ssim_min = std::min(ssim_min, p_row.ssim);
		if (p_row.flip > flip_max) {
			flip_max = p_row.flip;
			worst_flip = p_row.scene_id;
		}
		if (!std::isfinite(p_row.relative_rmse) || !std::isfinite(p_row.brightness_ratio)) {
			black++;
			return;
		}
		rel_sum += p_row.relative_rmse;
		ratio_min = std::min(ratio_min, p_row.brightness_ratio);
		ratio_max = std::max(ratio_max, p_row.brightness_ratio);
		if (p_row.relative_rmse > rel_max) {
			rel_max = p_row.relative_rmse;
			worst = p_row.scene_id;
		}
	}
	int lit() const { return count - black; }
	double rel_mean() const { return lit() > 0 ? rel_sum / lit() : 0.0; }
	String worst_scene() const { return worst.empty() ? worst_flip : worst; }
	String black_note() const { return black ? vformat(" (%d black references skipped)", black) : String(); }
};

} // namespace

String AccuracySuite::summary_table(const std::vector<Row> &p_rows) {
	// Methods in order of first appearance, roughness ascending.
	std::vector<String> methods;
	std::map<String, std::map<float, GroupStats>> table;
	std::map<String, std::map<int, GroupStats>> classes;
	std::map<String, GroupStats> targets[3];
	for (const Row &r : p_rows) {
		if (std::find(methods.begin(), methods.end(), r.method_name) == methods.end()) {
			methods.push_back(r.method_name);
		}
		table[r.method_name][r.roughness].add(r);
		const SceneClass c = scene_class(r);
		classes[r.method_name][c].add(r);
		if (c == CLASS_GRAZING_VIEW && r.roughness >= 0.25f && r.roughness <= 0.6f) {
			targets[0][r.method_name].add(r);
		} else if (c == CLASS_FACING && r.roughness >= 0.1f) {
			targets[1][r.method_name].add(r);
		} else if (c == CLASS_CROSSING) {
			targets[2][r.method_name].add(r);
		}
	}
	String out = "| method | roughness | scenes | FLIP mean | FLIP worst | RMSE mean | RMSE worst | relRMSE mean | relRMSE worst | SSIM mean | SSIM worst | worst scene (relRMSE) |\n";
	out += "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
	for (const String &m : methods) {
		for (const auto &entry : table[m]) {
			const GroupStats &s = entry.second;
			out += vformat("| %s | %g | %d | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %s%s |\n", m.c_str(), entry.first, s.count, s.flip_sum / s.count, s.flip_max, s.rmse_sum / s.count, s.rmse_max, s.rel_mean(),
					std::max(0.0, s.rel_max), s.ssim_sum / s.count, s.ssim_min, s.worst_scene().c_str(), s.black_note().c_str());
		}
	}
	auto class_row = [](const String &p_method, const char *p_name, const GroupStats &p_s) {
		if (p_s.lit() == 0) {
			return vformat("| %s | %s | %d | - | - | - | %.4f | %s%s |\n", p_method.c_str(), p_name, p_s.count, p_s.flip_sum / p_s.count, p_s.worst_scene().c_str(), p_s.black_note().c_str());
		}
		return vformat("| %s | %s | %d | %.4f | %.4f | %.3f..%.3f | %.4f | %s%s |\n", p_method.c_str(), p_name, p_s.count, p_s.rel_mean(), p_s.rel_max, p_s.ratio_min, p_s.ratio_max, p_s.flip_sum / p_s.count, p_s.worst_scene().c_str(),
				p_s.black_note().c_str());
	};
	out += "\n| method | class | scenes | relRMSE mean | relRMSE worst | brightness ratio | FLIP mean | worst scene (relRMSE) |\n";
	out += "|---|---|---|---|---|---|---|---|\n";
	for (const String &m : methods) {
		for (const auto &entry : classes[m]) {
			out += class_row(m, scene_class_name(SceneClass(entry.first)), entry.second);
		}
	}
	const char *target_names[3] = { "grazing view, roughness 0.25-0.6", "facing, roughness >= 0.1", "crossing" };
	out += "\n| method | issue #18 target class | scenes | relRMSE mean | relRMSE worst | brightness ratio | FLIP mean | worst scene (relRMSE) |\n";
	out += "|---|---|---|---|---|---|---|---|\n";
	for (const String &m : methods) {
		for (int t = 0; t < 3; t++) {
			if (targets[t].count(m)) {
				out += class_row(m, target_names[t], targets[t][m]);
			}
		}
	}
	return out;
}

bool AccuracySuite::write_thumbnail(const Image &p_engine, const Image &p_reference, const std::vector<float> &p_flip_map, const String &p_path, String *r_error) {
	const int w = p_engine.get_width(), h = p_engine.get_height();
	if (w <= 0 || h <= 0 || p_reference.get_width() != w || p_reference.get_height() != h || p_flip_map.size() != size_t(w) * h) {
		if (r_error) {
			*r_error = "Thumbnail '" + p_path + "': the engine image, reference image and FLIP map must have the same non-zero size.";
		}
		return false;
	}
	const int scale = std::max(1, (96 + h - 1) / h);
	const int gap = 2 * scale;
	const int tw = 3 * w * scale + 2 * gap, th = h * scale;
	std::vector<uint8_t> rgba(size_t(tw) * th * 4, 255);
	auto put = [&](int p_x, int p_y, uint8_t p_r, uint8_t p_g, uint8_t p_b) {
		uint8_t *p = &rgba[(size_t(p_y) * tw + p_x) * 4];
		p[0] = p_r;
		p[1] = p_g;
		p[2] = p_b;
		p[3] = 255;
	};
	for (int y = 0; y < th; y++) {
		for (int x = 0; x < w * scale; x++) {
			const int sx = x / scale, sy = y / scale;
			Color e = p_engine.get_pixel(sx, sy), r = p_reference.get_pixel(sx, sy);
			put(x, y, Tonemap::map_channel(e.r, 0.0f, Tonemap::MODE_LINEAR), Tonemap::map_channel(e.g, 0.0f, Tonemap::MODE_LINEAR), Tonemap::map_channel(e.b, 0.0f, Tonemap::MODE_LINEAR));
			put(x + w * scale + gap, y, Tonemap::map_channel(r.r, 0.0f, Tonemap::MODE_LINEAR), Tonemap::map_channel(r.g, 0.0f, Tonemap::MODE_LINEAR), Tonemap::map_channel(r.b, 0.0f, Tonemap::MODE_LINEAR));
			Color c = Heatmap::map(p_flip_map[size_t(sy) * w + sx]);
			auto to8 = [](float p_v) { return uint8_t(std::min(255.0f, std::max(0.0f, p_v * 255.0f + 0.5f))); };
			put(x + 2 * (w * scale + gap), y, to8(c.r), to8(c.g), to8(c.b));
		}
	}
	return PNGWriter::save_rgba8(rgba, tw, th, p_path, r_error);
}
