/**************************************************************************/
/*  main.cpp                                                              */
/**************************************************************************/
/* godot-area render [SCENE.tscn] -o OUT.exr [--width W] [--height H]     */
/*                   [--png P] [--half] [--exposure EV] [--gizmos]        */
/*                   [--gizmos-selected] [--debug-area-clusters]          */
/*                   [--compare-punctual] [--frames N [--path SPEC]       */
/*                   [--apng A.png] [--frame-ms MS]]  (main/demo_renders.h) */
/* godot-area bench [SCENE.tscn] [--frames N] [--warmup N] [--csv F]      */
/* godot-area bench --accuracy [--ci] [--csv F] [--methods 0,1,..] ...    */
/*                   [--width W] [--height H]                             */
/* godot-area compare A.exr B.exr [--heatmap H.png] [--json] [--no-hdr-flip] */
/*                   (B is the reference)                                 */
/* godot-area reference [SCENE.tscn] -o REF.exr [--width W] [--height H]  */
/*                   [--spp N] [--error E] [--shadows on|off] [--bounces 0|1] [--bounce-samples N] [--seed S]  */
/* godot-area ltc-fit [--size N] [--brdf engine|smith|both] [-o PATH]     */
/* godot-area info                                                        */
/* godot-area editor [SCENE.tscn] [options]   (editor/editor_node.h)       */
/* Without SCENE the embedded demo scene (demo/demo.tscn) is used.        */
/* Exit codes: 0 success, 1 runtime failure, 2 bad arguments or files.    */

#include "main/main.h"
#include "main/demo_renders.h"

#include "core/config/project_settings.h"
#include "core/error/error_macros.h"
#include "core/io/image.h"
#include "core/io/tonemap.h"
#include "drivers/png/apng_writer.h"
#include "drivers/png/png_writer.h"
#include "editor/editor_node.h"
#include "editor/gizmo_overlay.h"
#include "modules/accuracy/accuracy_command.h"
#include "modules/benchmark/dolly_sweep_command.h"
#include "modules/benchmark/frame_queue_bench.h"
#include "modules/benchmark/isr_sweep_command.h"
#include "modules/benchmark/methods_sweep_command.h"
#include "modules/benchmark/shadows_sweep_command.h"
#include "modules/benchmark/targets_bench.h"
#include "modules/ltc_fit/ltc_fit_command.h"
#include "modules/metrics/image_metrics.h"
#include "modules/openexr/image_saver_exr.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "modules/register_module_types.h"
#include "scene/3d/camera_3d.h"
#include "scene/main/godot_instance.h"
#include "scene/main/node.h"
#include "scene/main/scene_tree.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/renderer_rd/area_lights/area_method_selector.h"
#include "servers/rendering/renderer_rd/area_lights/area_shadow_atlas.h"
#include "servers/rendering/renderer_rd/directional_shadow_rd.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_adaptive.h"
#include "servers/rendering/renderer_rd/effects/area_shadow_renderer.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/rendering_profiler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace {
GodotInstance engine;
} // namespace

bool Main::setup(Backend p_backend, String *r_error, const void *p_reference_options) {
	bool ok = false;
	if (p_backend == BACKEND_REFERENCE) {
		ReferenceRenderOptions options;
		if (p_reference_options) {
			options = *static_cast<const ReferenceRenderOptions *>(p_reference_options);
		}
		ok = engine.start_with_compositor(new RendererCompositorReference(options), r_error);
	} else {
		// RD: the light capacity per type is rendering/limits/cluster_builder/max_clustered_elements.
		ok = engine.start(p_backend == BACKEND_RD ? GodotInstance::BACKEND_RD : GodotInstance::BACKEND_DUMMY, r_error,
				p_backend == BACKEND_RD ? RendererRD::LightStorage::get_project_max_lights() : 0);
	}
	if (ok) {
		initialize_modules();
	}
	return ok;
}

int Main::get_validation_error_count() {
	return engine.get_validation_error_count();
}

void Main::cleanup() {
	uninitialize_modules();
	engine.stop();
}

Node *Main::load_scene(const String &p_path, String *r_error) {
	return GodotInstance::load_scene(p_path, r_error);
}

namespace {

struct Args {
	String command;
	String scene;
	std::map<String, String> options;
	std::vector<String> flags;
	std::vector<String> positional; // compare: the two images.
};

void _print_usage() {
	fprintf(stderr,
			"usage:\n"
			"  godot-area render [SCENE.tscn] -o OUT.exr [--width W] [--height H] [--png P] [--half] [--exposure EV]\n"
			"                    [--gizmos] [--gizmos-selected] [--debug-area-clusters] [--settle-frames N] [--verbose]\n"
			"                    [--compare-punctual]   (also OUT_punctual.exr: each AreaLight3D replaced by a SpotLight3D of equal power;\n"
			"                                            with --png, P_punctual.png and P_side_by_side.png)\n"
			"                    [--frames N [--path orbit:DEG@X,Y,Z|dolly:DX,DY,DZ] [--apng A.png] [--frame-ms MS]]\n"
			"                                           (one draw per frame, numbered OUT00000000.exr ... as Godot's Movie Maker)\n"
			"  godot-area bench [SCENE.tscn] [--frames N] [--warmup N] [--csv F] [--width W] [--height H]\n"
			"  godot-area bench --sweep methods|shadows|dolly|isr [--csv F] ...   (speed vs accuracy sweeps, charts in doc/results/)\n"
			"  godot-area bench --targets [--rounds N] [--resolution WxH] [--progress]   (issue 17's cost targets)\n"
			"  godot-area bench --frame-queue [--rounds N] [--frames N] [--width W] [--height H]   (frames in flight: queue size 1 vs 2)\n"
			"  godot-area bench --accuracy [--ci] [--shapes] [--resolution N] [--csv F] [--thumbnails DIR] [--methods 0,1,..] [--filter S] [--progress]\n"
			"  godot-area compare A.exr B.exr [--heatmap H.png] [--json] [--no-hdr-flip]   (B is the reference)\n"
			"  godot-area reference [SCENE.tscn] -o REF.exr [--width W] [--height H] [--spp N] [--error E] [--shadows on|off]\n"
			"                       [--seed S] [--png P] [--progress]\n"
			"  godot-area ltc-fit [--size N] [--brdf engine|smith|both] [-o PATH] [--cells r0:r1,t0:t1] [--threads N] [--polynomial [--glsl PATH]]\n"
			"  godot-area info\n"
			"  godot-area editor [SCENE.tscn] [--select NODE_PATH] [--save-as PATH] [--test-log FILE] [--screenshot PREFIX]\n"
			"SCENE may be a .tscn or a .glb/.gltf. Without SCENE the embedded demo scene is used. GODOT_AREA_DEVICE=<name|index> picks a Vulkan device,\n"
			"GODOT_AREA_VALIDATION=1 enables the validation layer. --setting name=value overrides a project setting\n"
			"(e.g. rendering/lights_and_shadows/area_light_error_budget=0.02; unknown names are rejected). --strict makes\n"
			"any warning or error (a scene property that does not apply, lights over capacity) exit with 1.\n");
}

// Options that take a value, per command; anything else starting with "-" is an error.
bool _parse_args(int p_argc, char **p_argv, Args &r_args, String *r_error) {
	static const std::map<String, std::vector<String>> value_options = {
		{ "render", { "-o", "--width", "--height", "--png", "--exposure", "--settle-frames", "--frames", "--path", "--apng", "--frame-ms" } },
		{ "bench", { "--frames", "--warmup", "--csv", "--width", "--height" } },
		{ "compare", { "--heatmap" } },
		{ "reference", { "-o", "--width", "--height", "--spp", "--error", "--shadows", "--seed", "--png", "--exposure", "--bounces", "--bounce-samples" } },
		{ "info", {} },
	};
	static const std::map<String, std::vector<String>> flag_options = {
		{ "compare", { "--json", "--no-hdr-flip" } },
		{ "reference", { "--progress" } },
		{ "render", { "--half", "--gizmos", "--gizmos-selected", "--debug-area-clusters", "--verbose", "--compare-punctual" } },
		{ "bench", {} },
		{ "info", {} },
	};
	if (p_argc < 2) {
		*r_error = "missing command";
		return false;
	}
	r_args.command = p_argv[1];
	if (!value_options.count(r_args.command)) {
		*r_error = vformat("unknown command '%s'", r_args.command.c_str());
		return false;
	}
	const std::vector<String> &values = value_options.at(r_args.command);
	const std::vector<String> &flags = flag_options.at(r_args.command);
	for (int i = 2; i < p_argc; i++) {
		String a = p_argv[i];
		if (std::find(values.begin(), values.end(), a) != values.end()) {
			if (i + 1 >= p_argc) {
				*r_error = vformat("option '%s' needs a value", a.c_str());
				return false;
			}
			r_args.options[a] = p_argv[++i];
		} else if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
			r_args.flags.push_back(a);
		} else if (!a.empty() && a[0] == '-') {
			*r_error = vformat("unknown option '%s' for '%s'", a.c_str(), r_args.command.c_str());
			return false;
		} else if (r_args.command == "compare" && r_args.positional.size() < 2) {
			r_args.positional.push_back(a);
		} else if (r_args.scene.empty() && r_args.command != "info" && r_args.command != "compare") {
			r_args.scene = a;
		} else {
			*r_error = vformat("unexpected argument '%s'", a.c_str());
			return false;
		}
	}
	return true;
}

bool _get_int(const Args &p_args, const String &p_name, int p_default, int p_min, int p_max, int &r_value, String *r_error) {
	auto it = p_args.options.find(p_name);
	if (it == p_args.options.end()) {
		r_value = p_default;
		return true;
	}
	char *end = nullptr;
	long v = strtol(it->second.c_str(), &end, 10);
	if (it->second.empty() || *end != '\0' || v < p_min || v > p_max) {
		*r_error = vformat("%s must be an integer in [%d, %d], got '%s'", p_name.c_str(), p_min, p_max, it->second.c_str());
		return false;
	}
	r_value = int(v);
	return true;
}

bool _get_float(const Args &p_args, const String &p_name, float p_default, float &r_value, String *r_error) {
	auto it = p_args.options.find(p_name);
	if (it == p_args.options.end()) {
		r_value = p_default;
		return true;
	}
	char *end = nullptr;
	double v = strtod(it->second.c_str(), &end);
	if (it->second.empty() || *end != '\0' || !std::isfinite(v)) {
		*r_error = vformat("%s must be a finite number, got '%s'", p_name.c_str(), it->second.c_str());
		return false;
	}
	r_value = float(v);
	return true;
}

bool _has_flag(const Args &p_args, const String &p_flag) {
	return std::find(p_args.flags.begin(), p_args.flags.end(), p_flag) != p_args.flags.end();
}

void _print_profile(const std::vector<std::pair<String, double>> &p_profile, const char *p_total_label = "GPU total") {
	double total = 0;
	for (const auto &p : p_profile) {
		printf("  %-16s %9.3f ms\n", p.first.c_str(), p.second);
		total += p.second;
	}
	printf("  %-16s %9.3f ms\n", p_total_label, total);
}

// Loads the scene into a tree of the given size. Returns false with r_error on failure.
bool _prepare_tree(SceneTree &r_tree, const Args &p_args, int p_width, int p_height, String *r_error) {
	String error;
	ResourceFormatText::set_verbose(_has_flag(p_args, "--verbose")); // Every load problem, not one line per kind.
	Node *scene = Main::load_scene(p_args.scene, &error);
	if (!scene) {
		*r_error = vformat("cannot load scene '%s': %s", p_args.scene.empty() ? "<embedded demo>" : p_args.scene.c_str(), error.c_str());
		return false;
	}
	r_tree.get_root()->add_child(scene);
	if (!r_tree.get_camera_3d()) {
		*r_error = vformat("scene '%s' has no Camera3D to render from", p_args.scene.empty() ? "<embedded demo>" : p_args.scene.c_str());
		return false;
	}
	r_tree.set_size(p_width, p_height);
	return true;
}

int _command_info() {
	String error;
	if (!Main::setup(Main::BACKEND_RD, &error)) {
		fprintf(stderr, "godot-area: %s\n", error.c_str());
		return 1;
	}
	printf("%s\n", RenderingDevice::get_singleton()->get_device_info_string().c_str());
	Main::cleanup();
	return 0;
}

// The Environment's tonemap (tonemap_mode/_exposure/_white) of the tree's camera or world, as Godot shows it.
Tonemap::Settings _tree_tonemap(SceneTree &p_tree) {
	return Environment::get_preview_tonemap(p_tree.get_camera_3d()->get_environment(), p_tree.get_world_3d()->get_environment());
}

// Writes p_image to p_exr (scene-linear) and, unless p_png is empty, a tonemapped PNG preview. Returns 0 or 1
// (with the reason printed); a failed write leaves no file (the writers are atomic).
int _write_image(const Image &p_image, SceneTree &p_tree, const Args &p_args, const String &p_exr, const String &p_png, float p_exposure, const char *p_cmd, bool p_quiet = false) {
	String error;
	if (p_image.is_empty()) {
		fprintf(stderr, "godot-area %s: the renderer returned no image\n", p_cmd);
		return 1;
	}
	if (!p_image.is_finite()) {
		fprintf(stderr, "godot-area %s: the image has NaN or infinite pixels\n", p_cmd);
		return 1;
	}
	if (!ImageSaverEXR::save(p_image, p_exr, _has_flag(p_args, "--half"), &error)) {
		fprintf(stderr, "godot-area %s: %s\n", p_cmd, error.c_str());
		return 1;
	}
	if (!p_quiet) {
		printf("wrote %s (%dx%d, scene-linear %s)\n", p_exr.c_str(), p_image.get_width(), p_image.get_height(), _has_flag(p_args, "--half") ? "half" : "float");
	}
	if (p_png.empty()) {
		return 0;
	}
	const Tonemap::Settings tonemap = _tree_tonemap(p_tree);
	static const char *tonemap_names[Tonemap::MODE_MAX] = { "Linear", "ACES-fitted", "Reinhard", "Filmic", "ACES", "AgX" };
	if (!PNGWriter::save(p_image, p_png, &error, p_exposure, tonemap)) {
		fprintf(stderr, "godot-area %s: %s\n", p_cmd, error.c_str());
		return 1;
	}
	if (!p_quiet) {
		printf("wrote %s (%s preview, tonemap exposure %.2f, white %.2f, %+.2f EV)\n", p_png.c_str(), tonemap_names[tonemap.mode], tonemap.exposure, tonemap.white, p_exposure);
	}
	return 0;
}

void _print_frame_profile(Main::Backend p_backend, const char *p_what = "one frame") {
	if (p_backend == Main::BACKEND_RD) {
		printf("device: %s\nGPU time per pass (%s):\n", RenderingDevice::get_singleton()->get_device_info().name.c_str(), p_what);
	} else {
		printf("CPU reference renderer (Embree), time per pass:\n");
	}
	_print_profile(RenderingServer::get_singleton()->get_frame_profile(), p_backend == Main::BACKEND_RD ? "GPU total" : "total");
}

// A still image: draws until ADAPTIVE area shadows settle (at most p_settle_frames draws).
Image _render_still(SceneTree &p_tree, int p_settle_frames) {
	int frames = 0;
	Image image = p_tree.render_settled(p_settle_frames, &frames);
	if (RenderingServer::get_singleton()->get_frame_area_shadow_tests() > 0) {
		printf("ADAPTIVE area shadows were still refining after %d frames (--settle-frames)\n", frames);
	} else if (frames > 1) {
		printf("ADAPTIVE area shadows settled after %d frames\n", frames);
	}
	return image;
}

// --compare-punctual: the same scene with each AreaLight3D replaced by a SpotLight3D of equal power
// (main/demo_renders.h), written beside OUT as OUT_punctual.exr; with --png also P_punctual.png and
// P_side_by_side.png (area lights left, punctual right, same tonemap).
int _render_punctual(SceneTree &p_tree, const Args &p_args, const Image &p_area_image, const String &p_out, const String &p_png, float p_exposure, int p_settle_frames, Main::Backend p_backend) {
	std::vector<String> report;
	const int replaced = DemoRenders::replace_area_lights_with_spots(p_tree.get_root(), &report);
	printf("--compare-punctual: %d AreaLight3D replaced by SpotLight3D of equal power:\n", replaced);
	for (const String &line : report) {
		printf("  %s\n", line.c_str());
	}
	if (replaced == 0) {
		fprintf(stderr, "godot-area render: --compare-punctual: the scene has no AreaLight3D to replace\n");
		return 1;
	}
	const Image image = _render_still(p_tree, p_settle_frames);
	const String png = p_png.empty() ? String() : DemoRenders::suffixed_path(p_png, "_punctual");
	int code = _write_image(image, p_tree, p_args, DemoRenders::suffixed_path(p_out, "_punctual"), png, p_exposure, "render");
	if (code == 0 && !png.empty()) {
		// Side by side, 8 black pixels apart.
		const Tonemap::Settings tonemap = _tree_tonemap(p_tree);
		const std::vector<uint8_t> left = Tonemap::apply(p_area_image, tonemap, p_exposure), right = Tonemap::apply(image, tonemap, p_exposure);
		const int w = image.get_width(), h = image.get_height(), gap = 8, row = 2 * w + gap;
		std::vector<uint8_t> both(size_t(row) * size_t(h) * 4, 0);
		for (int y = 0; y < h; y++) {
			std::copy_n(&left[size_t(y) * w * 4], size_t(w) * 4, &both[size_t(y) * row * 4]);
			std::copy_n(&right[size_t(y) * w * 4], size_t(w) * 4, &both[(size_t(y) * row + w + gap) * 4]);
		}
		for (size_t i = 3; i < both.size(); i += 4) {
			both[i] = 255;
		}
		String error;
		const String side = DemoRenders::suffixed_path(p_png, "_side_by_side");
		if (!PNGWriter::save_rgba8(both, row, h, side, &error)) {
			fprintf(stderr, "godot-area render: %s\n", error.c_str());
			code = 1;
		} else {
			printf("wrote %s (area lights | punctual stand-ins, %dx%d)\n", side.c_str(), row, h);
		}
	}
	_print_frame_profile(p_backend, "one frame, punctual stand-ins");
	return code;
}

// --frames N [--path SPEC]: one draw per frame (ADAPTIVE shadows refine across frames as in a game),
// the camera moved along the path, numbered EXR (and PNG) files, optionally one APNG of all frames.
int _render_frames(SceneTree &p_tree, const Args &p_args, int p_frames, const DemoRenders::CameraPath *p_path, const String &p_out, const String &p_png, float p_exposure, Main::Backend p_backend) {
	Camera3D *camera = p_tree.get_camera_3d();
	const Transform3D start = camera->get_global_transform();
	const auto apng_it = p_args.options.find("--apng");
	int frame_ms = 0;
	String error;
	if (!_get_int(p_args, "--frame-ms", 83, 1, 65535, frame_ms, &error)) {
		fprintf(stderr, "godot-area render: %s\n", error.c_str());
		return 2;
	}
	const Tonemap::Settings tonemap = _tree_tonemap(p_tree);
	std::vector<std::vector<uint8_t>> apng_frames;
	for (int i = 0; i < p_frames; i++) {
		if (p_path) {
			camera->set_global_transform(p_path->sample(start, p_frames > 1 ? float(i) / float(p_frames - 1) : 0.0f));
		}
		const Image image = p_tree.render();
		const String png = p_png.empty() ? String() : DemoRenders::numbered_path(p_png, i);
		if (_write_image(image, p_tree, p_args, DemoRenders::numbered_path(p_out, i), png, p_exposure, "render", true) != 0) {
			return 1;
		}
		if (apng_it != p_args.options.end()) {
			apng_frames.push_back(Tonemap::apply(image, tonemap, p_exposure));
		}
		double total = 0;
		for (const auto &pass : RenderingServer::get_singleton()->get_frame_profile()) {
			total += pass.second;
		}
		printf("frame %d: %s, GPU total %.3f ms, ADAPTIVE shadow tests %d\n", i, DemoRenders::numbered_path(p_out, i).c_str(), total, RenderingServer::get_singleton()->get_frame_area_shadow_tests());
	}
	printf("wrote %d frames %s ... %s%s\n", p_frames, DemoRenders::numbered_path(p_out, 0).c_str(), DemoRenders::numbered_path(p_out, p_frames - 1).c_str(), p_png.empty() ? "" : " (and PNG previews)");
	if (apng_it != p_args.options.end()) {
		if (!APNGWriter::save_rgba8(apng_frames, p_tree.get_width(), p_tree.get_height(), frame_ms, apng_it->second, &error)) {
			fprintf(stderr, "godot-area render: %s\n", error.c_str());
			return 1;
		}
		printf("wrote %s (APNG, %d frames, %d ms each, looping)\n", apng_it->second.c_str(), p_frames, frame_ms);
	}
	_print_frame_profile(p_backend, "last frame");
	return 0;
}

int _command_render(const Args &p_args, Main::Backend p_backend = Main::BACKEND_RD, const void *p_backend_options = nullptr) {
	const char *cmd = p_backend == Main::BACKEND_REFERENCE ? "reference" : "render";
	String error;
	int width = 0, height = 0, frames = 0;
	float exposure = 0;
	// ADAPTIVE area shadows refine over frames: a still render draws until they settle, at most this many frames.
	int settle_frames = SceneTree::DEFAULT_SETTLE_FRAMES;
	if (!_get_int(p_args, "--width", 640, 1, 16384, width, &error) || !_get_int(p_args, "--height", 360, 1, 16384, height, &error) || !_get_float(p_args, "--exposure", 0.0f, exposure, &error) ||
			!_get_int(p_args, "--settle-frames", SceneTree::DEFAULT_SETTLE_FRAMES, 1, 1000, settle_frames, &error) || !_get_int(p_args, "--frames", 0, 1, 100000, frames, &error)) {
		fprintf(stderr, "godot-area %s: %s\n", cmd, error.c_str());
		return 2;
	}
	auto out_it = p_args.options.find("-o");
	if (out_it == p_args.options.end() || out_it->second.empty()) {
		fprintf(stderr, "godot-area %s: missing -o OUT.exr\n", cmd);
		return 2;
	}
	const bool compare_punctual = _has_flag(p_args, "--compare-punctual");
	const bool have_frames = p_args.options.count("--frames") > 0;
	for (const char *needs_frames : { "--path", "--apng", "--frame-ms" }) {
		if (!have_frames && p_args.options.count(needs_frames)) {
			fprintf(stderr, "godot-area %s: %s needs --frames N\n", cmd, needs_frames);
			return 2;
		}
	}
	if (have_frames && (compare_punctual || _has_flag(p_args, "--gizmos") || _has_flag(p_args, "--gizmos-selected"))) {
		fprintf(stderr, "godot-area %s: --frames cannot be combined with --compare-punctual or --gizmos\n", cmd);
		return 2;
	}
	DemoRenders::CameraPath path;
	const bool have_path = p_args.options.count("--path") > 0;
	if (have_path && !DemoRenders::parse_camera_path(p_args.options.at("--path"), path, &error)) {
		fprintf(stderr, "godot-area %s: %s\n", cmd, error.c_str());
		return 2;
	}
	const String out_path = out_it->second;
	const auto png_it = p_args.options.find("--png");
	const String png_path = png_it == p_args.options.end() ? String() : png_it->second;
	if (!Main::setup(p_backend, &error, p_backend_options)) {
		fprintf(stderr, "godot-area %s: %s\n", cmd, error.c_str());
		return 1;
	}
	int code = 0;
	{
		SceneTree tree;
		if (!_prepare_tree(tree, p_args, width, height, &error)) {
			fprintf(stderr, "godot-area %s: %s\n", cmd, error.c_str());
			code = 2;
		} else if (have_frames) {
			code = _render_frames(tree, p_args, frames, have_path ? &path : nullptr, out_path, png_path, exposure, p_backend);
		} else {
			if (_has_flag(p_args, "--debug-area-clusters")) {
				// Writes the per-pixel number of area lights in each pixel's cluster instead of shading.
				RenderingServer::get_singleton()->viewport_set_debug_draw(tree.get_viewport_rid(), RS::VIEWPORT_DEBUG_DRAW_CLUSTER_AREA_LIGHTS);
			}
			Image image = _render_still(tree, settle_frames);
			if (!image.is_empty() && (_has_flag(p_args, "--gizmos") || _has_flag(p_args, "--gizmos-selected"))) {
				// Editor gizmos (outlines, handles, icons) as an overlay; --gizmos-selected draws every light as selected.
				if (GizmoOverlay::draw(image, tree, _has_flag(p_args, "--gizmos-selected")) < 0) {
					fprintf(stderr, "godot-area %s: the gizmo overlay failed (see above)\n", cmd);
				}
			}
			code = _write_image(image, tree, p_args, out_path, png_path, exposure, cmd);
			if (code == 0) {
				_print_frame_profile(p_backend);
				if (compare_punctual) {
					code = _render_punctual(tree, p_args, image, out_path, png_path, exposure, settle_frames, p_backend);
				}
			}
		}
	}
	if (Main::get_validation_error_count() > 0) {
		fprintf(stderr, "godot-area: the Vulkan validation layer reported %d error(s) (see above)\n", Main::get_validation_error_count());
		code = code ? code : 1;
	}
	Main::cleanup();
	return code;
}

int _command_reference(const Args &p_args) {
	ReferenceRenderOptions options;
	String error;
	int spp = 0, seed = 0, bounces = 0, bounce_samples = 0;
	float target = 0;
	if (!_get_int(p_args, "--spp", options.max_samples, 1, 1 << 24, spp, &error) || !_get_int(p_args, "--seed", 0, 0, 2147483647, seed, &error) ||
			!_get_int(p_args, "--bounces", 0, 0, 1, bounces, &error) || !_get_int(p_args, "--bounce-samples", options.bounce_samples, 1, 1 << 16, bounce_samples, &error) ||
			!_get_float(p_args, "--error", options.target_relative_error, target, &error)) {
		fprintf(stderr, "godot-area reference: %s\n", error.c_str());
		return 2;
	}
	if (!(target > 0)) {
		fprintf(stderr, "godot-area reference: --error must be a positive relative standard error (e.g. 0.002)\n");
		return 2;
	}
	auto shadows_it = p_args.options.find("--shadows");
	if (shadows_it != p_args.options.end() && shadows_it->second != "on" && shadows_it->second != "off") {
		fprintf(stderr, "godot-area reference: --shadows must be 'on' or 'off', got '%s'\n", shadows_it->second.c_str());
		return 2;
	}
	options.max_samples = spp;
	options.bounces = bounces; // 1: one diffuse bounce (the image-space radiosity ground truth).
	options.bounce_samples = bounce_samples;
	options.seed = uint64_t(seed);
	options.target_relative_error = target;
	options.shadows = shadows_it == p_args.options.end() || shadows_it->second == "on";
	options.progress = _has_flag(p_args, "--progress");
	return _command_render(p_args, Main::BACKEND_REFERENCE, &options);
}

int _command_bench(const Args &p_args) {
	String error;
	int width = 0, height = 0, frames = 0, warmup = 0;
	if (!_get_int(p_args, "--width", 1280, 1, 16384, width, &error) || !_get_int(p_args, "--height", 720, 1, 16384, height, &error) ||
			!_get_int(p_args, "--frames", 100, 1, 1000000, frames, &error) || !_get_int(p_args, "--warmup", RenderingProfiler::DEFAULT_WARMUP_FRAMES, 0, 1000000, warmup, &error)) {
		fprintf(stderr, "godot-area bench: %s\n", error.c_str());
		return 2;
	}
	if (!Main::setup(Main::BACKEND_RD, &error)) {
		fprintf(stderr, "godot-area bench: %s\n", error.c_str());
		return 1;
	}
	int code = 0;
	{
		SceneTree tree;
		if (!_prepare_tree(tree, p_args, width, height, &error)) {
			fprintf(stderr, "godot-area bench: %s\n", error.c_str());
			code = 2;
		} else {
			RenderingProfiler profiler;
			profiler.set_warmup_frames(warmup);
			RenderingServer *rs = RenderingServer::get_singleton();
			for (int i = 0; i < warmup + frames; i++) {
				auto begin = std::chrono::steady_clock::now();
				rs->draw();
				// Frames in flight: the profile read waits for this frame, so the time is the whole frame's.
				const std::vector<std::pair<String, double>> profile = rs->get_frame_profile();
				double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
				profiler.record_frame(cpu_ms, profile);
			}
			printf("device: %s, %dx%d, %d frames after %d warm-up frames (discarded)\n", RenderingDevice::get_singleton()->get_device_info().name.c_str(), width, height, frames, warmup);
			printf("%s", profiler.summary_table().c_str());
			auto csv_it = p_args.options.find("--csv");
			if (csv_it != p_args.options.end()) {
				if (!profiler.write_csv(csv_it->second, &error)) {
					fprintf(stderr, "godot-area bench: %s\n", error.c_str());
					code = 1;
				} else {
					printf("wrote %s\n", csv_it->second.c_str());
				}
			}
		}
	}
	if (Main::get_validation_error_count() > 0) {
		fprintf(stderr, "godot-area: the Vulkan validation layer reported %d error(s) (see above)\n", Main::get_validation_error_count());
		code = code ? code : 1;
	}
	Main::cleanup();
	return code;
}

int _command_compare(const Args &p_args) {
	if (p_args.positional.size() != 2) {
		fprintf(stderr, "godot-area compare: needs two images, A (tested) and B (reference)\n");
		return 2;
	}
	ImageMetrics::Options options;
	options.hdr_flip = !_has_flag(p_args, "--no-hdr-flip");
	auto heatmap_it = p_args.options.find("--heatmap");
	String heatmap = heatmap_it == p_args.options.end() ? String() : heatmap_it->second;
	ImageMetrics::Result result;
	String error;
	if (!ImageMetrics::compare_files(p_args.positional[0], p_args.positional[1], &result, &error, options, heatmap)) {
		fprintf(stderr, "godot-area compare: %s\n", error.c_str());
		return 2;
	}
	printf("%s\n", _has_flag(p_args, "--json") ? result.to_json().c_str() : result.to_text().c_str());
	return 0;
}

} // namespace

namespace {

/* --setting names, --strict (issue 20) */

// Registers every project setting the engine reads, so that --setting can reject a name nobody reads. A
// new GLOBAL_DEF must be added here (its getter registers it with its default).
void _register_project_settings() {
	set_error_print_silenced(true); // Getters complain about invalid values; there are none yet.
	AreaMethodSelector::get_error_budget();
	AreaMethodSelector::get_default_roughness();
	AreaShadowAdaptiveRD::get_project_reprojection_divisor();
	AreaShadowAdaptiveRD::get_project_max_depth();
	AreaShadowAdaptiveRD::get_project_heuristic_occluder_fraction();
	RendererRD::LightStorage::get_project_max_lights();
	DirectionalShadowRD::get_project_atlas_size();
	AreaShadowRendererRD::get_project_filter();
	RenderingDevice::get_project_frame_queue_size();
	GLOBAL_DEF("rendering/lights_and_shadows/area_shadow_atlas_size", int(AreaShadowAtlas::DEFAULT_SIZE));
	GLOBAL_DEF("rendering/lights_and_shadows/area_shadow_atlas_subdivision", int(AreaShadowAtlas::DEFAULT_SUBDIVISION));
	set_error_print_silenced(false);
}

// Levenshtein distance, for the did-you-mean of an unknown setting.
size_t _edit_distance(const String &p_a, const String &p_b) {
	std::vector<size_t> row(p_b.size() + 1);
	for (size_t j = 0; j <= p_b.size(); j++) {
		row[j] = j;
	}
	for (size_t i = 1; i <= p_a.size(); i++) {
		size_t diag = row[0];
		row[0] = i;
		for (size_t j = 1; j <= p_b.size(); j++) {
			size_t up = row[j];
			row[j] = std::min({ row[j] + 1, row[j - 1] + 1, diag + (p_a[i - 1] == p_b[j - 1] ? 0 : 1) });
			diag = up;
		}
	}
	return row[p_b.size()];
}

// False with r_error ("... did you mean ...?") when p_assignment names no registered setting.
bool _check_setting_name(const String &p_assignment, String *r_error) {
	const String name = string_strip_edges(p_assignment.substr(0, p_assignment.find('=')));
	ProjectSettings *ps = ProjectSettings::get_singleton();
	if (ps->is_registered(name)) {
		return true;
	}
	String best;
	size_t best_distance = String::npos;
	for (const String &n : ps->get_setting_names()) {
		size_t d = ps->is_registered(n) ? _edit_distance(name, n) : String::npos;
		if (d < best_distance) {
			best_distance = d;
			best = n;
		}
	}
	*r_error = vformat("unknown project setting \"%s\"", name.c_str());
	if (!best.empty() && best_distance <= std::max<size_t>(3, name.size() / 4)) {
		*r_error += vformat("; did you mean \"%s\"?", best.c_str());
	}
	return false;
}

int _run_command(int p_argc, char **p_argv);

} // namespace

// --strict: any warning or error printed while the command runs (a scene's unknown property, a value out of
// range, lights over capacity) makes an otherwise successful run exit 1.
int Main::run(int p_argc, char **p_argv) {
	std::vector<char *> argv_rest;
	bool strict = false;
	for (int i = 0; i < p_argc; i++) {
		if (String(p_argv[i]) == "--strict") {
			strict = true;
		} else {
			argv_rest.push_back(p_argv[i]);
		}
	}
	int reports = 0;
	ErrorHandlerList counter;
	counter.callback = [&reports](ErrorHandlerType, const String &) { reports++; };
	add_error_handler(&counter);
	int code = _run_command(int(argv_rest.size()), argv_rest.data());
	remove_error_handler(&counter);
	if (strict && code == 0 && reports > 0) {
		fprintf(stderr, "godot-area: --strict: %d warning(s) or error(s) were reported (see above); exiting with 1\n", reports);
		code = 1;
	}
	return code;
}

namespace {

int _run_command(int p_argc, char **p_argv) {
	// Project settings given as --setting name=value (anywhere on the line) apply to every command.
	_register_project_settings();
	std::vector<char *> argv_rest;
	for (int i = 0; i < p_argc; i++) {
		if (String(p_argv[i]) == "--setting") {
			String error;
			if (i + 1 >= p_argc || !_check_setting_name(p_argv[i + 1], &error) || !ProjectSettings::get_singleton()->parse_override(p_argv[i + 1], &error)) {
				fprintf(stderr, "godot-area: --setting needs name=value with a registered setting: %s\n", error.c_str());
				return 2;
			}
			i++;
			continue;
		}
		argv_rest.push_back(p_argv[i]);
	}
	p_argc = int(argv_rest.size());
	p_argv = argv_rest.data();
	if (p_argc >= 2 && String(p_argv[1]) == "editor") {
		// The editor window (editor/editor_node.h) has its own options and sets up its own servers.
		return EditorNode::command(std::vector<String>(p_argv + 2, p_argv + p_argc));
	}
	if (p_argc >= 2 && String(p_argv[1]) == "ltc-fit") {
		// The LTC LUT fitter has its own options (modules/ltc_fit/ltc_fit_command.h).
		return ltc_fit_command(std::vector<String>(p_argv + 2, p_argv + p_argc));
	}
	if (p_argc >= 2 && String(p_argv[1]) == "bench") {
		std::vector<String> rest(p_argv + 2, p_argv + p_argc);
		if (std::find(rest.begin(), rest.end(), String("--accuracy")) != rest.end()) {
			// The accuracy suite (modules/accuracy) makes its own servers, so it runs before Main::setup().
			return accuracy_command(rest);
		}
		if (std::find(rest.begin(), rest.end(), String("--targets")) != rest.end()) {
			// bench --targets: issue 17's cost targets, one process, interleaved (modules/benchmark/targets_bench.h).
			return targets_bench_command(rest);
		}
		if (std::find(rest.begin(), rest.end(), String("--frame-queue")) != rest.end()) {
			// bench --frame-queue: frames in flight, queue size 1 vs 2 in one process (modules/benchmark/frame_queue_bench.h).
			return frame_queue_bench_command(rest);
		}
		auto sweep = std::find(rest.begin(), rest.end(), String("--sweep"));
		if (sweep != rest.end()) {
			// bench --sweep methods|shadows|dolly: benchmark sweeps with their own servers (modules/benchmark).
			String what = (sweep + 1) != rest.end() ? *(sweep + 1) : String();
			std::vector<String> sweep_args;
			for (auto it = rest.begin(); it != rest.end(); ++it) {
				if (it == sweep || it == sweep + 1) {
					continue;
				}
				sweep_args.push_back(*it);
			}
			if (what == "methods") {
				return methods_sweep_command(sweep_args);
			}
			if (what == "shadows") {
				return shadows_sweep_command(sweep_args);
			}
			if (what == "dolly") {
				return dolly_sweep_command(sweep_args);
			}
			if (what == "isr") {
				return isr_sweep_command(sweep_args);
			}
			fprintf(stderr, "godot-area bench: --sweep needs 'methods', 'shadows', 'dolly' or 'isr', got '%s'\n", what.c_str());
			return 2;
		}
	}
	Args args;
	String error;
	if (!_parse_args(p_argc, p_argv, args, &error)) {
		fprintf(stderr, "godot-area: %s\n", error.c_str());
		_print_usage();
		return 2;
	}
	if (args.command == "info") {
		return _command_info();
	}
	if (args.command == "compare") {
		return _command_compare(args);
	}
	if (args.command == "reference") {
		return _command_reference(args);
	}
	if (args.command == "render") {
		return _command_render(args);
	}
	return _command_bench(args);
}

} // namespace
