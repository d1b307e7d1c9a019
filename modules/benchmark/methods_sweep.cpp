/**************************************************************************/
/*  methods_sweep.cpp                                                     */
/**************************************************************************/
/* godot-area: the shading-method sweep (see methods_sweep.h).            */

#include "modules/benchmark/methods_sweep.h"
#include "core/io/file_io.h"

#include "core/error/error_macros.h"
#include "modules/accuracy/accuracy_scenes.h"
#include "modules/accuracy/accuracy_suite.h"
#include "modules/metrics/image_metrics.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "scene/main/godot_instance.h"
#include "scene/resources/primitive_meshes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

double median(std::vector<double> p_values) {
	if (p_values.empty()) {
		return 0.0;
	}
	std::sort(p_values.begin(), p_values.end());
	const size_t n = p_values.size();
	return (n % 2) ? p_values[n / 2] : 0.5 * (p_values[n / 2 - 1] + p_values[n / 2]);
}

// The timing scene: a 24 x 24 m rough dielectric floor, N lights on a grid 1.5 m above it
// (k x k, k = ceil(sqrt(N)), spread over 16 x 16 m), each 1 x 0.5 m (area) with range 4 m, facing down.
struct TimingScene {
	RID mesh, material, environment, scenario, camera, viewport, mesh_instance;
	std::vector<RID> lights, light_instances;

	// p_shape / p_size: the area lights' shape and size (the default sweep: rectangles of 1 x 0.5).
	bool build(RenderingServer *p_rs, const MethodsSweep::Config &p_config, int p_lights, int p_width, int p_height, int p_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE, const Vector2 &p_size = Vector2(1.0f, 0.5f)) {
		RS::SurfaceData surface;
		PlaneMesh::create_plane_arrays(surface, Vector2(24, 24), 0, 0, Vector3(), PlaneMesh::FACE_Y);
		mesh = p_rs->mesh_create();
		p_rs->mesh_add_surface(mesh, surface);
		RS::MaterialParams mp;
		mp.albedo = Color(0.8f, 0.8f, 0.8f, 1.0f);
		mp.roughness = 0.4f;
		mp.metallic = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		material = p_rs->material_create();
		p_rs->material_set_params(material, mp);
		p_rs->mesh_surface_set_material(mesh, 0, material);

		environment = p_rs->environment_create();
		p_rs->environment_set_background(environment, RS::ENV_BG_COLOR);
		p_rs->environment_set_bg_color(environment, Color(0, 0, 0, 1));
		p_rs->environment_set_ambient_light(environment, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
		scenario = p_rs->scenario_create();
		p_rs->scenario_set_environment(scenario, environment);
		mesh_instance = p_rs->instance_create();
		p_rs->instance_set_base(mesh_instance, mesh);
		p_rs->instance_set_scenario(mesh_instance, scenario);

		const int k = int(std::ceil(std::sqrt(double(p_lights))));
		const Basis down = Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
		for (int i = 0; i < p_lights; i++) {
			RID l;
			if (p_config.kind == MethodsSweep::KIND_AREA) {
				l = p_rs->area_light_create();
				if (p_shape != RS::LIGHT_AREA_SHAPE_RECTANGLE) {
					p_rs->light_area_set_shape(l, RS::LightAreaShape(p_shape));
				}
				p_rs->light_area_set_size(l, p_size);
				p_rs->light_area_set_shading_method(l, RS::LightAreaShadingMethod(p_config.method));
				p_rs->light_area_set_stochastic_samples(l, p_config.samples);
				if (int(p_rs->light_area_get_shading_method(l)) != p_config.method) {
					p_rs->free(l);
					return false;
				}
			} else if (p_config.kind == MethodsSweep::KIND_SPOT) {
				l = p_rs->spot_light_create();
				p_rs->light_set_param(l, RS::LIGHT_PARAM_SPOT_ANGLE, 60.0f);
			} else {
				l = p_rs->omni_light_create();
			}
			p_rs->light_set_param(l, RS::LIGHT_PARAM_ENERGY, 4.0f / float(p_lights));
			p_rs->light_set_param(l, RS::LIGHT_PARAM_RANGE, 4.0f);
			lights.push_back(l);
			RID inst = p_rs->instance_create();
			p_rs->instance_set_base(inst, l);
			p_rs->instance_set_scenario(inst, scenario);
			const float step = k > 1 ? 16.0f / float(k - 1) : 0.0f;
			const Vector3 pos = k > 1 ? Vector3(-8.0f + step * float(i % k), 1.5f, -8.0f + step * float(i / k)) : Vector3(0, 1.5f, 0);
			p_rs->instance_set_transform(inst, Transform3D(down, pos));
			light_instances.push_back(inst);
		}
		camera = p_rs->camera_create();
		p_rs->camera_set_perspective(camera, 60.0f, 0.05f, 100.0f);
		const Vector3 eye(0, 9, 11);
		p_rs->camera_set_transform(camera, Transform3D(Basis::looking_at(Vector3(0, 0, 0) - eye), eye));
		viewport = p_rs->viewport_create();
		p_rs->viewport_set_size(viewport, p_width, p_height);
		p_rs->viewport_attach_camera(viewport, camera);
		p_rs->viewport_set_scenario(viewport, scenario);
		return true;
	}

	void free(RenderingServer *p_rs) {
		for (RID r : { viewport, camera }) {
			if (r.is_valid()) {
				p_rs->free(r);
			}
		}
		for (RID r : light_instances) {
			p_rs->free(r);
		}
		if (mesh_instance.is_valid()) {
			p_rs->free(mesh_instance);
		}
		for (RID r : { scenario, environment }) {
			if (r.is_valid()) {
				p_rs->free(r);
			}
		}
		for (RID r : lights) {
			p_rs->free(r);
		}
		for (RID r : { material, mesh }) {
			if (r.is_valid()) {
				p_rs->free(r);
			}
		}
	}
};

std::vector<AccuracyScenes::Scene> failure_scenes() {
	typedef AccuracyScenes S;
	return {
		S::make_scene(S::RECEIVER_PLANE, 0.25f, 0.0f, Vector2(1, 1), S::PLACEMENT_GRAZING),
		S::make_scene(S::RECEIVER_PLANE, 0.25f, 0.0f, Vector2(4, 4), S::PLACEMENT_HORIZON),
		S::make_scene(S::RECEIVER_PLANE, 0.05f, 1.0f, Vector2(1, 1), S::PLACEMENT_FACING),
		S::make_scene(S::RECEIVER_PLANE, 0.5f, 1.0f, Vector2(4, 4), S::PLACEMENT_CLOSE),
		S::make_scene(S::RECEIVER_PLANE, 0.25f, 1.0f, Vector2(2, 0.5f), S::PLACEMENT_FACING),
	};
}

Image render_accuracy_scene(RenderingServer *p_rs, const AccuracyScenes::Scene &p_scene, int p_res, int p_method, int p_samples, String *r_error) {
	AccuracyScenes::Built built;
	if (!AccuracyScenes::build(p_rs, p_scene, p_res, p_method, &built, r_error)) {
		return Image();
	}
	p_rs->light_area_set_stochastic_samples(built.light, p_samples);
	p_rs->draw();
	Image image = p_rs->viewport_get_texture_data(built.viewport);
	AccuracyScenes::free_scene(p_rs, built);
	return image;
}

// One draw: GPU ms of the opaque pass and of all passes (RD timestamps), wall ms of draw().
struct FrameTime {
	double opaque = 0.0, total = 0.0, wall = 0.0;
};

FrameTime time_frame(RenderingServer *p_rs) {
	FrameTime t;
	auto begin = std::chrono::steady_clock::now();
	p_rs->draw();
	// Frames in flight: draw() does not wait for its frame; reading its profile does, so the wall time
	// covers the whole frame, as before.
	const std::vector<std::pair<String, double>> profile = p_rs->get_frame_profile();
	t.wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
	for (const auto &pass : profile) {
		t.total += pass.second;
		if (pass.first == "opaque") {
			t.opaque = pass.second;
		}
	}
	return t;
}

// Draws the built scene warmup_frames + frames times; a timing row of the medians.
MethodsSweep::Row time_scene(RenderingServer *p_rs, const MethodsSweep::Options &p_options, const MethodsSweep::Config &p_config, int p_lights) {
	std::vector<double> opaque, total, wall;
	for (int f = 0; f < p_options.warmup_frames + p_options.frames; f++) {
		const FrameTime t = time_frame(p_rs);
		if (f >= p_options.warmup_frames) {
			opaque.push_back(t.opaque);
			total.push_back(t.total);
			wall.push_back(t.wall);
		}
	}
	MethodsSweep::Row row;
	row.section = "timing";
	row.config = p_config.name;
	row.method = p_config.method;
	row.samples = p_config.samples;
	row.lights = p_lights;
	row.width = p_options.width;
	row.height = p_options.height;
	row.gpu_ms_opaque = median(opaque);
	row.gpu_ms_total = median(total);
	row.wall_ms = median(wall);
	return row;
}

// The Embree reference images of p_scenes (shadows off, seed 0), from a server of their own.
bool render_references(const std::vector<AccuracyScenes::Scene> &p_scenes, int p_resolution, bool p_progress, std::vector<Image> *r_images, String *r_error) {
	if (p_scenes.empty()) {
		return true;
	}
	ReferenceRenderOptions options;
	options.shadows = false;
	options.seed = 0;
	GodotInstance reference;
	if (!reference.start_with_compositor(new RendererCompositorReference(options), r_error)) {
		return false;
	}
	for (size_t i = 0; i < p_scenes.size(); i++) {
		Image img = render_accuracy_scene(reference.get_rendering_server(), p_scenes[i], p_resolution, RS::LIGHT_AREA_SHADING_LTC, 1, r_error);
		if (img.is_empty()) {
			*r_error = "Reference: " + *r_error;
			return false;
		}
		r_images->push_back(img);
		if (p_progress) {
			printf("[reference %zu/%zu] %s\n", i + 1, p_scenes.size(), p_scenes[i].id.c_str());
			fflush(stdout);
		}
	}
	return true;
}

// The engine for timing and errors, with room for the largest light count (at least 64).
bool start_engine(const MethodsSweep::Options &p_options, GodotInstance &r_engine, String *r_error) {
	int max_lights = 64;
	for (int n : p_options.light_counts) {
		max_lights = std::max(max_lights, n);
	}
	return r_engine.start(GodotInstance::BACKEND_RD, r_error, uint32_t(max_lights));
}

// An error row of p_config on scene p_scene (p_resolution squared) with metrics p_m.
MethodsSweep::Row error_row(const MethodsSweep::Config &p_config, int p_resolution, const String &p_scene, const ImageMetrics::Result &p_m) {
	MethodsSweep::Row row;
	row.section = "error";
	row.config = p_config.name;
	row.method = p_config.method;
	row.samples = p_config.samples;
	row.lights = 1;
	row.width = p_resolution;
	row.height = p_resolution;
	row.scene = p_scene;
	row.flip = p_m.flip;
	row.rmse = p_m.rmse;
	row.ssim = p_m.ssim;
	row.hdr_flip = p_m.has_hdr_flip ? p_m.hdr_flip : 0.0;
	return row;
}

bool wanted(const MethodsSweep::Options &p_options, const MethodsSweep::Config &p_config) {
	return p_options.only_configs.empty() || std::find(p_options.only_configs.begin(), p_options.only_configs.end(), p_config.name) != p_options.only_configs.end();
}

// The shape axis (issue 21; see the header): one server for the reference images, then the engine for
// the timing (per light count, all shape x method scenes interleaved frame by frame) and the errors.
std::vector<AccuracyScenes::Scene> shape_error_scenes() {
	typedef AccuracyScenes S;
	std::vector<S::Scene> scenes;
	scenes.push_back(S::make_scene(S::RECEIVER_PLANE, 1.0f, 0.0f, Vector2(1, 1), S::PLACEMENT_FACING));
	scenes.push_back(S::make_scene(S::RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 1), S::PLACEMENT_TILTED));
	for (const S::Scene &s : S::shape_ci_subset()) {
		scenes.push_back(s);
	}
	return scenes;
}

bool run_shape_axis(const MethodsSweep::Options &p_options, std::vector<MethodsSweep::Row> *r_rows, String *r_error) {
	typedef MethodsSweep MS;
	std::vector<MS::Config> configs;
	for (const MS::Config &c : MS::shape_configs()) {
		if (wanted(p_options, c)) {
			configs.push_back(c);
		}
	}
	if (configs.empty()) {
		*r_error = "None of the requested configurations is on the shape axis (LTC, MRP, MC8).";
		return false;
	}
	const std::vector<AccuracyScenes::Scene> scenes = p_options.errors ? shape_error_scenes() : std::vector<AccuracyScenes::Scene>();
	const int res = p_options.error_resolution;
	std::vector<Image> references;
	if (!render_references(scenes, res, p_options.progress, &references, r_error)) {
		return false;
	}
	GodotInstance engine;
	if (!start_engine(p_options, engine, r_error)) {
		return false;
	}
	RenderingServer *rs = engine.get_rendering_server();
	// Per light count, every shape x method scene is built (each its own viewport, inactive) and the
	// frames are interleaved: round k draws each scene once, so the load of a shared machine falls on
	// all configurations alike.
	for (int n : p_options.timing ? p_options.light_counts : std::vector<int>()) {
		std::vector<TimingScene> built;
		std::vector<std::pair<int, MS::Config>> what;
		bool ok = true;
		for (int shape = 0; shape < RS::LIGHT_AREA_SHAPE_MAX && ok; shape++) {
			for (const MS::Config &config : configs) {
				built.emplace_back();
				what.emplace_back(shape, config);
				if (!built.back().build(rs, config, n, p_options.width, p_options.height, shape, MS::shape_size(shape))) {
					*r_error = vformat("Could not build the timing scene for %s lights of shape %s.", config.name.c_str(), MS::shape_name(shape));
					ok = false;
					break;
				}
				rs->viewport_set_active(built.back().viewport, false);
			}
		}
		std::vector<std::vector<double>> opaque(built.size()), total(built.size()), wall(built.size());
		for (int f = 0; ok && f < p_options.warmup_frames + p_options.frames; f++) {
			for (size_t c = 0; c < built.size(); c++) {
				rs->viewport_set_active(built[c].viewport, true);
				const FrameTime t = time_frame(rs);
				rs->viewport_set_active(built[c].viewport, false);
				if (f >= p_options.warmup_frames) {
					opaque[c].push_back(t.opaque);
					total[c].push_back(t.total);
					wall[c].push_back(t.wall);
				}
			}
		}
		for (TimingScene &scene : built) {
			scene.free(rs);
		}
		if (!ok) {
			return false;
		}
		for (size_t c = 0; c < built.size(); c++) {
			MS::Row row;
			row.section = "shape_timing";
			row.config = what[c].second.name;
			row.method = what[c].second.method;
			row.samples = what[c].second.samples;
			row.lights = n;
			row.width = p_options.width;
			row.height = p_options.height;
			row.gpu_ms_opaque = median(opaque[c]);
			row.gpu_ms_total = median(total[c]);
			row.wall_ms = median(wall[c]);
			row.shape = MS::shape_name(what[c].first);
			r_rows->push_back(row);
			if (p_options.progress) {
				printf("[shape timing %s %s] %d lights: opaque %.3f ms, wall %.1f ms\n", row.shape.c_str(), row.config.c_str(), n, row.gpu_ms_opaque, row.wall_ms);
				fflush(stdout);
			}
		}
	}
	for (size_t i = 0; i < scenes.size(); i++) {
		for (const MS::Config &config : configs) {
			Image image = render_accuracy_scene(rs, scenes[i], res, config.method, config.samples, r_error);
			ImageMetrics::Result m;
			if (image.is_empty() || !ImageMetrics::compare(image, references[i], &m, r_error)) {
				*r_error = config.name + " on " + scenes[i].id + ": " + *r_error;
				return false;
			}
			MS::Row row = error_row(config, res, scenes[i].id, m);
			row.section = "shape_error";
			row.shape = MS::shape_name(scenes[i].shape);
			row.relative_rmse = m.relative_rmse;
			row.brightness_ratio = m.brightness_ratio;
			r_rows->push_back(row);
			if (p_options.progress) {
				printf("[shape error %s] %s: rel-RMSE %.4f, FLIP %.4f\n", config.name.c_str(), scenes[i].id.c_str(), m.relative_rmse, m.flip);
				fflush(stdout);
			}
		}
	}
	engine.stop();
	return true;
}

} // namespace

std::vector<MethodsSweep::Config> MethodsSweep::default_configs() {
	std::vector<Config> c;
	c.push_back({ "LTC", KIND_AREA, int(RS::LIGHT_AREA_SHADING_LTC), 1 });
	c.push_back({ "LTC_POLYNOMIAL", KIND_AREA, int(RS::LIGHT_AREA_SHADING_LTC_POLYNOMIAL), 1 });
	c.push_back({ "LTC_2LOBE", KIND_AREA, int(RS::LIGHT_AREA_SHADING_LTC_2LOBE), 1 });
	c.push_back({ "MRP", KIND_AREA, int(RS::LIGHT_AREA_SHADING_MRP), 1 });
	for (int n : { 1, 4, 16 }) {
		c.push_back({ "MC" + itos(n), KIND_AREA, int(RS::LIGHT_AREA_SHADING_STOCHASTIC), n });
	}
	c.push_back({ "SPOT", KIND_SPOT, -1, 1 });
	c.push_back({ "OMNI", KIND_OMNI, -1, 1 });
	return c;
}

std::vector<MethodsSweep::Config> MethodsSweep::shape_configs() {
	return {
		{ "LTC", KIND_AREA, int(RS::LIGHT_AREA_SHADING_LTC), 1 },
		{ "MRP", KIND_AREA, int(RS::LIGHT_AREA_SHADING_MRP), 1 },
		{ "MC8", KIND_AREA, int(RS::LIGHT_AREA_SHADING_STOCHASTIC), 8 },
	};
}

Vector2 MethodsSweep::shape_size(int p_shape) {
	static const Vector2 sizes[RS::LIGHT_AREA_SHAPE_MAX] = { Vector2(1.0f, 0.5f), Vector2(1.0f, 0.5f), Vector2(0.5f, 0.5f), Vector2(1.0f, 0.15f) };
	ERR_FAIL_INDEX_V(p_shape, int(RS::LIGHT_AREA_SHAPE_MAX), Vector2());
	return sizes[p_shape];
}

const char *MethodsSweep::shape_name(int p_shape) {
	static const char *names[RS::LIGHT_AREA_SHAPE_MAX] = { "rectangle", "disk", "sphere", "tube" };
	ERR_FAIL_INDEX_V(p_shape, int(RS::LIGHT_AREA_SHAPE_MAX), "");
	return names[p_shape];
}

std::vector<String> MethodsSweep::shape_error_scene_ids() {
	std::vector<String> ids;
	for (const AccuracyScenes::Scene &s : shape_error_scenes()) {
		ids.push_back(s.id);
	}
	return ids;
}

std::vector<String> MethodsSweep::failure_scene_ids() {
	std::vector<String> ids;
	for (const AccuracyScenes::Scene &s : failure_scenes()) {
		ids.push_back(s.id);
	}
	return ids;
}

bool MethodsSweep::run(const Options &p_options, std::vector<Row> *r_rows, String *r_error) {
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	if (!r_rows) {
		return fail("MethodsSweep::run needs an output vector.");
	}
	r_rows->clear();
	if (RenderingServer::get_singleton()) {
		return fail("MethodsSweep::run creates its own rendering servers; a RenderingServer already exists.");
	}
	if (p_options.width < 1 || p_options.height < 1 || p_options.width > 4096 || p_options.height > 4096) {
		return fail(vformat("Sweep resolution must be within 1..4096, got %dx%d.", p_options.width, p_options.height));
	}
	if (p_options.frames < 1 || p_options.warmup_frames < 0) {
		return fail("Sweep needs frames >= 1 and warmup_frames >= 0.");
	}
	for (int n : p_options.light_counts) {
		if (n < 1 || n > 512) {
			return fail(vformat("Light counts must be in 1..512, got %d.", n));
		}
	}
	String error;
	if (p_options.shapes) {
		if (!run_shape_axis(p_options, r_rows, &error)) {
			return fail(error);
		}
		if (!p_options.csv_path.empty() && !write_csv(p_options.csv_path, *r_rows, &error)) {
			return fail(error);
		}
		return true;
	}
	const std::vector<Config> configs = default_configs();

	// Error part, reference first (its own server), then the engine.
	std::vector<AccuracyScenes::Scene> scenes;
	std::vector<Image> references;
	const int res = p_options.error_resolution;
	if (p_options.errors) {
		scenes = AccuracyScenes::ci_subset();
		for (const AccuracyScenes::Scene &f : failure_scenes()) {
			bool have = false;
			for (const AccuracyScenes::Scene &s : scenes) {
				have = have || s.id == f.id;
			}
			if (!have) {
				scenes.push_back(f);
			}
		}
		if (!render_references(scenes, res, p_options.progress, &references, &error)) {
			return fail(error);
		}
	}

	GodotInstance engine;
	if (!start_engine(p_options, engine, &error)) {
		return fail(error);
	}
	RenderingServer *rs = engine.get_rendering_server();
	bool ok = true;
	const std::vector<String> failure_ids = failure_scene_ids();
	if (!p_options.maps_dir.empty()) {
		std::error_code ec;
		std::filesystem::create_directories(p_options.maps_dir, ec);
	}

	// Timing: light count outer, configuration inner, so slow drift of a shared machine spreads
	// over all configurations alike (ratios are taken at equal light counts).
	std::vector<String> capped;
	for (int n : p_options.timing ? p_options.light_counts : std::vector<int>()) {
		for (const Config &config : configs) {
			if (!ok || !wanted(p_options, config) || std::find(capped.begin(), capped.end(), config.name) != capped.end()) {
				continue;
			}
			TimingScene scene;
			if (!scene.build(rs, config, n, p_options.width, p_options.height)) {
				scene.free(rs);
				error = "Could not build the timing scene for " + config.name + ".";
				ok = false;
				break;
			}
			Row row = time_scene(rs, p_options, config, n);
			scene.free(rs);
			r_rows->push_back(row);
			if (p_options.progress) {
				printf("[timing %s] %d lights: opaque %.3f ms, GPU %.3f ms, wall %.1f ms\n", config.name.c_str(), n, row.gpu_ms_opaque, row.gpu_ms_total, row.wall_ms);
				fflush(stdout);
			}
			if (p_options.frame_cap_ms > 0.0 && row.wall_ms > p_options.frame_cap_ms) {
				capped.push_back(config.name);
				if (p_options.progress) {
					printf("[timing %s] %.0f ms per frame is over the %.0f ms cap: larger light counts skipped\n", config.name.c_str(), row.wall_ms, p_options.frame_cap_ms);
				}
			}
		}
	}
	for (const Config &config : configs) {
		if (!ok || !wanted(p_options, config)) {
			continue;
		}
		if (!ok || !p_options.errors || config.kind != KIND_AREA) {
			continue;
		}
		for (size_t i = 0; i < scenes.size(); i++) {
			Image engine = render_accuracy_scene(rs, scenes[i], res, config.method, config.samples, &error);
			ImageMetrics::Result m;
			if (engine.is_empty() || !ImageMetrics::compare(engine, references[i], &m, &error)) {
				error = config.name + " on " + scenes[i].id + ": " + error;
				ok = false;
				break;
			}
			r_rows->push_back(error_row(config, res, scenes[i].id, m));
			if (p_options.progress) {
				printf("[error %s] %s: FLIP %.4f\n", config.name.c_str(), scenes[i].id.c_str(), m.flip);
				fflush(stdout);
			}
			if (!p_options.maps_dir.empty() && std::find(failure_ids.begin(), failure_ids.end(), scenes[i].id) != failure_ids.end()) {
				const String path = p_options.maps_dir + "/" + config.name + "_" + scenes[i].id + ".png";
				if (!AccuracySuite::write_thumbnail(engine, references[i], m.flip_map, path, &error)) {
					ok = false;
					break;
				}
			}
		}
	}
	engine.stop();
	if (!ok) {
		return fail(error);
	}
	if (!p_options.csv_path.empty() && !write_csv(p_options.csv_path, *r_rows, &error)) {
		return fail(error);
	}
	return true;
}

bool MethodsSweep::write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error) {
	FileWriteBuffer out; // Written atomically by commit(): no partial CSV on a full disk.
	FILE *f = out.file();
	if (!f) {
		if (r_error) {
			*r_error = "Cannot write the sweep CSV '" + p_path + "': out of memory.";
		}
		return false;
	}
	// The shape columns only when there are shape rows: the default sweep's CSV is as before.
	bool shapes = false;
	for (const Row &r : p_rows) {
		shapes = shapes || !r.shape.empty();
	}
	fprintf(f, "section,config,method,samples,lights,width,height,gpu_ms_opaque,gpu_ms_total,wall_ms,scene,flip,rmse,ssim,hdr_flip%s\n", shapes ? ",shape,rel_rmse,brightness_ratio" : "");
	for (const Row &r : p_rows) {
		fprintf(f, "%s,%s,%d,%d,%d,%d,%d,%.4f,%.4f,%.3f,%s,%.6g,%.6g,%.6g,%.6g", r.section.c_str(), r.config.c_str(), r.method, r.samples, r.lights, r.width, r.height,
				r.gpu_ms_opaque, r.gpu_ms_total, r.wall_ms, r.scene.c_str(), r.flip, r.rmse, r.ssim, r.hdr_flip);
		if (shapes) {
			fprintf(f, ",%s,%.6g,%.6g", r.shape.c_str(), r.relative_rmse, r.brightness_ratio);
		}
		fprintf(f, "\n");
	}
	return out.commit(p_path, r_error);
}

bool MethodsSweep::write_shader_sources(const String &p_dir, String *r_error) {
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	// The sources come from the renderer itself (the variants and defines it compiles), through the
	// RenderingServer; no frame is drawn.
	GodotInstance engine;
	String error;
	if (!engine.start(GodotInstance::BACKEND_RD, &error)) {
		return fail(error);
	}
	const std::vector<std::pair<String, String>> sources = engine.get_rendering_server()->get_debug_scene_shader_sources();
	if (sources.empty()) {
		return fail("The renderer returned no scene shader sources.");
	}
	std::error_code ec;
	std::filesystem::create_directories(p_dir, ec);
	for (const std::pair<String, String> &source : sources) {
		if (!file_write_atomic(p_dir + "/" + source.first, source.second, &error)) {
			return fail("Cannot write shader sources under '" + p_dir + "': " + error);
		}
	}
	return true;
}
