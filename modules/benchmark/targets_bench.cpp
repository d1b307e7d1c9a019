/**************************************************************************/
/*  targets_bench.cpp                                                     */
/**************************************************************************/
/* godot-area: issue 17's cost targets (see targets_bench.h).             */

#include "modules/benchmark/targets_bench.h"

#include "core/error/error_macros.h"
#include "scene/main/godot_instance.h"
#include "scene/main/node.h"
#include "scene/main/scene_tree.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering_server.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>

namespace {

// The CLI's capacity (GodotInstance::start() with the renderer's default): the light loops and
// the cluster build pay for it, so the benchmark must use the same.
constexpr uint32_t CLI_MAX_LIGHTS_PER_TYPE = 512;

// The P1/P2 scene (as `bench --sweep methods`): a 24 x 24 m rough dielectric floor, N lights on a grid
// 1.5 m above it (k x k, k = ceil(sqrt(N)), spread over 16 x 16 m), facing down, range 4 m.
constexpr float LIGHT_HEIGHT = 1.5f;
constexpr float LIGHT_RANGE = 4.0f;
const Vector2 AREA_SIZE(1.0f, 0.5f);

double median(std::vector<double> p_values) {
	if (p_values.empty()) {
		return 0.0;
	}
	std::sort(p_values.begin(), p_values.end());
	const size_t n = p_values.size();
	return (n % 2) ? p_values[n / 2] : 0.5 * (p_values[n / 2 - 1] + p_values[n / 2]);
}

double process_cpu_ms() {
	timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

// The footprint-matched spot of an area light (size AREA_SIZE, range LIGHT_RANGE, LIGHT_HEIGHT above the
// floor, facing it): the area light lights the floor points within its range of the rectangle, the
// rectangle dilated by d = sqrt(r^2 - h^2), area ab + 2(a + b)d + pi d^2. The spot at the same place lights
// a disc of radius R = h tan(angle) out to range sqrt(h^2 + R^2); R is chosen so the disc has that area.
void footprint_matched_spot(float *r_angle_degrees, float *r_range) {
	const float h = LIGHT_HEIGHT, r = LIGHT_RANGE;
	const float d = std::sqrt(r * r - h * h);
	const float area = AREA_SIZE.x * AREA_SIZE.y + 2.0f * (AREA_SIZE.x + AREA_SIZE.y) * d + float(Math::PI) * d * d;
	const float disc = std::sqrt(area / float(Math::PI));
	*r_angle_degrees = std::atan2(disc, h) * 180.0f / float(Math::PI);
	*r_range = std::sqrt(h * h + disc * disc);
}

struct Config {
	String name;
	RID viewport;
	bool area_code_disabled = false;
	bool sample_filter_off = false; // Area shadows through the fixed PCF (AreaShadowRendererRD).
	std::vector<double> gpu, cpu, cluster, opaque; // One entry per round.
};

class Scenes {
	RenderingServer *rs;
	std::vector<RID> owned; // Freed in reverse order.

	RID keep(RID p_rid) {
		owned.push_back(p_rid);
		return p_rid;
	}

public:
	explicit Scenes(RenderingServer *p_rs) :
			rs(p_rs) {}

	~Scenes() {
		for (auto it = owned.rbegin(); it != owned.rend(); ++it) {
			rs->free(*it);
		}
	}

	RID scenario_with_floor() {
		RS::SurfaceData surface;
		PlaneMesh::create_plane_arrays(surface, Vector2(24, 24), 0, 0, Vector3(), PlaneMesh::FACE_Y);
		RID mesh = keep(rs->mesh_create());
		rs->mesh_add_surface(mesh, surface);
		RS::MaterialParams mp;
		mp.albedo = Color(0.8f, 0.8f, 0.8f, 1.0f);
		mp.roughness = 0.4f;
		mp.metallic = 0.0f;
		mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
		RID material = keep(rs->material_create());
		rs->material_set_params(material, mp);
		rs->mesh_surface_set_material(mesh, 0, material);
		RID environment = keep(rs->environment_create());
		rs->environment_set_background(environment, RS::ENV_BG_COLOR);
		rs->environment_set_bg_color(environment, Color(0, 0, 0, 1));
		rs->environment_set_ambient_light(environment, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
		RID scenario = keep(rs->scenario_create());
		rs->scenario_set_environment(scenario, environment);
		RID inst = keep(rs->instance_create());
		rs->instance_set_base(inst, mesh);
		rs->instance_set_scenario(inst, scenario);
		return scenario;
	}

	void add_box(RID p_scenario, const Vector3 &p_size, const Vector3 &p_position) {
		RS::SurfaceData surface;
		BoxMesh::create_box_arrays(surface, p_size, 0, 0, 0);
		RID mesh = keep(rs->mesh_create());
		rs->mesh_add_surface(mesh, surface);
		RS::MaterialParams mp;
		mp.albedo = Color(0.5f, 0.5f, 0.5f, 1.0f);
		mp.roughness = 0.6f;
		RID material = keep(rs->material_create());
		rs->material_set_params(material, mp);
		rs->mesh_surface_set_material(mesh, 0, material);
		RID inst = keep(rs->instance_create());
		rs->instance_set_base(inst, mesh);
		rs->instance_set_scenario(inst, p_scenario);
		rs->instance_set_transform(inst, Transform3D(Basis(), p_position));
	}

	// p_method < 0: footprint-matched spots; else area lights with that RS::LightAreaShadingMethod.
	// p_texture: the area_texture of every area light (RID() for none).
	bool add_light_grid(RID p_scenario, int p_method, int p_lights, RID p_texture = RID()) {
		const int k = int(std::ceil(std::sqrt(double(p_lights))));
		const Basis down = Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
		float spot_angle = 0.0f, spot_range = 0.0f;
		footprint_matched_spot(&spot_angle, &spot_range);
		for (int i = 0; i < p_lights; i++) {
			RID l;
			if (p_method >= 0) {
				l = keep(rs->area_light_create());
				rs->light_area_set_size(l, AREA_SIZE);
				rs->light_area_set_shading_method(l, RS::LightAreaShadingMethod(p_method));
				if (int(rs->light_area_get_shading_method(l)) != p_method) {
					return false;
				}
				rs->light_set_param(l, RS::LIGHT_PARAM_RANGE, LIGHT_RANGE);
				if (p_texture.is_valid()) {
					rs->light_area_set_texture(l, p_texture);
				}
			} else {
				l = keep(rs->spot_light_create());
				rs->light_set_param(l, RS::LIGHT_PARAM_SPOT_ANGLE, spot_angle);
				rs->light_set_param(l, RS::LIGHT_PARAM_RANGE, spot_range);
			}
			rs->light_set_param(l, RS::LIGHT_PARAM_ENERGY, 4.0f / float(p_lights));
			RID inst = keep(rs->instance_create());
			rs->instance_set_base(inst, l);
			rs->instance_set_scenario(inst, p_scenario);
			const float step = k > 1 ? 16.0f / float(k - 1) : 0.0f;
			const Vector3 pos = k > 1 ? Vector3(-8.0f + step * float(i % k), LIGHT_HEIGHT, -8.0f + step * float(i / k)) : Vector3(0, LIGHT_HEIGHT, 0);
			rs->instance_set_transform(inst, Transform3D(down, pos));
		}
		return true;
	}

	RID add_shadow_light(RID p_scenario, bool p_shadow, RS::LightAreaShadowMode p_mode = RS::LIGHT_AREA_SHADOW_FIXED, int p_grid = 5) {
		RID l = keep(rs->area_light_create());
		rs->light_area_set_size(l, Vector2(1.0f, 1.0f));
		rs->light_set_param(l, RS::LIGHT_PARAM_RANGE, 6.0f);
		rs->light_set_param(l, RS::LIGHT_PARAM_ENERGY, 2.0f);
		rs->light_set_shadow(l, p_shadow);
		rs->light_area_set_shadow_mode(l, p_mode);
		rs->light_area_set_shadow_grid(l, p_grid); // 25 maps by default.
		RID inst = keep(rs->instance_create());
		rs->instance_set_base(inst, l);
		rs->instance_set_scenario(inst, p_scenario);
		rs->instance_set_transform(inst, Transform3D(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f), Vector3(0, 2.5f, 0)));
		return l;
	}

	// T1's area_texture: 256 x 256 texels, colour quadrants under a fine checker (every atlas level differs).
	RID pattern_texture() {
		Image image(256, 256);
		for (int y = 0; y < 256; y++) {
			for (int x = 0; x < 256; x++) {
				const float c = ((x / 8 + y / 8) & 1) ? 1.0f : 0.6f;
				image.set_pixel(x, y, Color(x < 128 ? c : 0.2f * c, y < 128 ? c : 0.5f * c, (x >= 128) == (y >= 128) ? c : 0.1f, 1.0f));
			}
		}
		return keep(rs->texture_2d_create(image));
	}

	RID viewport(RID p_scenario, int p_width, int p_height) {
		RID camera = keep(rs->camera_create());
		rs->camera_set_perspective(camera, 60.0f, 0.05f, 100.0f);
		const Vector3 eye(0, 9, 11);
		rs->camera_set_transform(camera, Transform3D(Basis::looking_at(Vector3(0, 0, 0) - eye), eye));
		RID vp = rs->viewport_create();
		owned.insert(owned.begin(), vp); // Viewports go first (before their scenario and camera).
		rs->viewport_set_size(vp, p_width, p_height);
		rs->viewport_attach_camera(vp, camera);
		rs->viewport_set_scenario(vp, p_scenario);
		rs->viewport_set_active(vp, false);
		return vp;
	}
};

// Sum of red (pairs listed by the clusters) and green (pairs lit) of a cluster debug image.
bool count_pairs(const Image &p_image, double *r_listed, double *r_lit) {
	if (p_image.is_empty()) {
		return false;
	}
	double listed = 0.0, lit = 0.0;
	const std::vector<float> &d = p_image.get_data();
	for (size_t i = 0; i + 3 < d.size(); i += 4) {
		listed += d[i];
		lit += d[i + 1];
	}
	*r_listed = listed;
	*r_lit = lit;
	return true;
}

} // namespace

bool TargetsBench::run(const Options &p_options, std::vector<Result> *r_results, String *r_error) {
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	ERR_FAIL_NULL_V(r_results, false);
	r_results->clear();
	if (RenderingServer::get_singleton()) {
		return fail("TargetsBench::run creates its own rendering servers; a RenderingServer already exists.");
	}
	if (p_options.width < 16 || p_options.height < 16 || p_options.width > 4096 || p_options.height > 4096) {
		return fail(vformat("--resolution must be within 16..4096 per side, got %dx%d.", p_options.width, p_options.height));
	}
	if (p_options.rounds < 1) {
		return fail("--rounds must be >= 1.");
	}
	String error;
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, &error, CLI_MAX_LIGHTS_PER_TYPE)) {
		return fail(error);
	}
	RenderingServer *rs = engine.get_rendering_server();
	bool ok = true;
	{
		Scenes scenes(rs);
		const int w = p_options.width, h = p_options.height;
		std::vector<Config> configs;
		auto add = [&](const String &p_name, RID p_viewport, bool p_area_code_disabled = false) {
			Config c;
			c.name = p_name;
			c.viewport = p_viewport;
			c.area_code_disabled = p_area_code_disabled;
			configs.push_back(c);
			return int(configs.size()) - 1;
		};
		auto find = [&](const String &p_name) {
			for (size_t i = 0; i < configs.size(); i++) {
				if (configs[i].name == p_name) {
					return int(i);
				}
			}
			return -1;
		};
		std::vector<int> counts = p_options.p1_lights;
		for (int n : p_options.p2_lights) {
			if (std::find(counts.begin(), counts.end(), n) == counts.end()) {
				counts.push_back(n);
			}
		}
		std::vector<std::pair<int, RID>> ltc_scenarios;
		if (p_options.shadows_only || p_options.texture_only) {
			counts.clear();
		}
		if (p_options.clusters_only || p_options.two_lobe_only) {
			counts = p_options.p2_lights; // P5 counts the pairs of the 16- and 64-light LTC scenes; L2 compares at them.
		}
		// Configurations other than LTC and LTC_2LOBE (none for --two-lobe-only; --clusters-only times nothing).
		const bool others = !p_options.two_lobe_only && !p_options.clusters_only;
		// T1: the same LTC grid with and without an area_texture (in one process, interleaved below).
		if (!p_options.shadows_only && others) {
			RID texture = scenes.pattern_texture();
			for (int n : p_options.t1_lights) {
				if (std::find(counts.begin(), counts.end(), n) == counts.end()) {
					RID ltc = scenes.scenario_with_floor();
					scenes.add_light_grid(ltc, RS::LIGHT_AREA_SHADING_LTC, n);
					add(vformat("LTC_%d", n), scenes.viewport(ltc, w, h));
				}
				RID tex = scenes.scenario_with_floor();
				scenes.add_light_grid(tex, RS::LIGHT_AREA_SHADING_LTC, n, texture);
				add(vformat("LTC_TEX_%d", n), scenes.viewport(tex, w, h));
			}
		}
		for (int n : counts) {
			if (n < 1 || n > int(CLI_MAX_LIGHTS_PER_TYPE)) {
				ok = false;
				error = vformat("light counts must be within 1..%d, got %d.", CLI_MAX_LIGHTS_PER_TYPE, n);
				break;
			}
			RID ltc = scenes.scenario_with_floor();
			ok = ok && scenes.add_light_grid(ltc, RS::LIGHT_AREA_SHADING_LTC, n);
			add(vformat("LTC_%d", n), scenes.viewport(ltc, w, h));
			ltc_scenarios.push_back({ n, ltc });
			if (p_options.clusters_only) {
				continue;
			}
			if (others && std::find(p_options.p1_lights.begin(), p_options.p1_lights.end(), n) != p_options.p1_lights.end()) {
				RID spot = scenes.scenario_with_floor();
				scenes.add_light_grid(spot, -1, n);
				add(vformat("SPOT_%d", n), scenes.viewport(spot, w, h));
			}
			if (std::find(p_options.p2_lights.begin(), p_options.p2_lights.end(), n) != p_options.p2_lights.end()) {
				if (others) {
					RID mrp = scenes.scenario_with_floor();
					ok = ok && scenes.add_light_grid(mrp, RS::LIGHT_AREA_SHADING_MRP, n);
					add(vformat("MRP_%d", n), scenes.viewport(mrp, w, h));
				}
				RID two_lobe = scenes.scenario_with_floor();
				ok = ok && scenes.add_light_grid(two_lobe, RS::LIGHT_AREA_SHADING_LTC_2LOBE, n);
				add(vformat("LTC2_%d", n), scenes.viewport(two_lobe, w, h));
			}
		}
		if (!ok && error.empty()) {
			error = "an area light rejected its shading method.";
		}
		// P4: a scene without area lights (16 spots and a box), with and without the area code.
		if (!p_options.shadows_only && !p_options.texture_only && others) {
			RID no_area = scenes.scenario_with_floor();
			scenes.add_light_grid(no_area, -1, 16);
			scenes.add_box(no_area, Vector3(1, 1, 1), Vector3(0, 0.5f, 0));
			RID no_area_vp = scenes.viewport(no_area, w, h);
			add("NO_AREA", no_area_vp);
			add("NO_AREA_CODE_OFF", no_area_vp, true);
		}
		// S1: one 25-map area light above a box, shadows on / off.
		for (bool shadow : { true, false }) {
			if (p_options.texture_only || !others) {
				break;
			}
			RID s = scenes.scenario_with_floor();
			scenes.add_box(s, Vector3(1, 1, 1), Vector3(0, 0.5f, 0));
			scenes.add_shadow_light(s, shadow);
			add(shadow ? "SHADOW_25" : "SHADOW_OFF", scenes.viewport(s, w, h));
		}
		// S2: the same light with the PCSS baseline, and 4 / 9 maps with and without the per-sample
		// penumbra filter (issue 19's default: frame <= 1.5 x PCSS's).
		if (!p_options.texture_only && others) {
			RID s = scenes.scenario_with_floor();
			scenes.add_box(s, Vector3(1, 1, 1), Vector3(0, 0.5f, 0));
			scenes.add_shadow_light(s, true, RS::LIGHT_AREA_SHADOW_PCSS_BASELINE);
			add("SHADOW_PCSS", scenes.viewport(s, w, h));
			for (int grid : { 2, 3 }) {
				RID g = scenes.scenario_with_floor();
				scenes.add_box(g, Vector3(1, 1, 1), Vector3(0, 0.5f, 0));
				scenes.add_shadow_light(g, true, RS::LIGHT_AREA_SHADOW_FIXED, grid);
				RID vp = scenes.viewport(g, w, h);
				add(vformat("SHADOW_%d", grid * grid), vp);
				configs[add(vformat("SHADOW_%d_PCF", grid * grid), vp)].sample_filter_off = true;
			}
			configs[add("SHADOW_25_PCF", configs[find("SHADOW_25")].viewport)].sample_filter_off = true;
			RID g = scenes.scenario_with_floor();
			scenes.add_box(g, Vector3(1, 1, 1), Vector3(0, 0.5f, 0));
			scenes.add_shadow_light(g, true, RS::LIGHT_AREA_SHADOW_FIXED, 9);
			add("SHADOW_81", scenes.viewport(g, w, h));
		}
		// C1: the embedded demo scene (the CLI's default scene) in a scene tree.
		const bool no_demo = p_options.shadows_only || p_options.texture_only || !others;
		Node *demo = no_demo ? nullptr : GodotInstance::load_scene(String(), &error);
		if (!demo && !no_demo) {
			ok = false;
			error = "cannot load the embedded demo scene: " + error;
		} else if (demo) {
			engine.set_scene(demo);
			SceneTree *tree = engine.get_tree();
			tree->set_size(w, h);
			rs->viewport_set_active(tree->get_viewport_rid(), false);
			add("DEMO", tree->get_viewport_rid());
		}

		// Interleaved rounds: each configuration draws a discarded frame (the first after a switch) and a
		// measured one, then the next configuration.
		const int rounds = p_options.clusters_only ? 0 : p_options.rounds; // P5 counts pairs: nothing to time.
		for (int round = 0; ok && round < rounds; round++) {
			for (Config &c : configs) {
				rs->viewport_set_active(c.viewport, true);
				rs->set_debug_disable_area_lights(c.area_code_disabled);
				// The S2 rows with the fixed PCF switch the per-sample penumbra filter off.
				rs->area_shadow_filter_set_mode(c.sample_filter_off ? RS::AREA_SHADOW_FILTER_PCF : RS::AREA_SHADOW_FILTER_PENUMBRA);
				rs->draw(); // Discarded.
				// Frames in flight: wait for the discarded frame before the window opens, so that the window
				// holds the measured frame alone (it held the rasteriser's work on both, 2 x the GPU time).
				rs->get_frame_profile();
				const double cpu0 = process_cpu_ms();
				rs->draw();
				// Frames in flight: draw() no longer waits for its own frame; reading the profile does, so the
				// frame's whole cost (the rasteriser's threads too) falls inside the measured window.
				const std::vector<std::pair<String, double>> profile = rs->get_frame_profile();
				const double cpu = process_cpu_ms() - cpu0;
				double gpu = 0.0, cluster = 0.0, opaque = 0.0;
				for (const auto &pass : profile) {
					gpu += pass.second;
					cluster += pass.first == "cluster_build" ? pass.second : 0.0;
					opaque += pass.first == "opaque" ? pass.second : 0.0;
				}
				rs->set_debug_disable_area_lights(false);
				rs->area_shadow_filter_set_mode(RS::AREA_SHADOW_FILTER_PENUMBRA);
				rs->viewport_set_active(c.viewport, false);
				c.gpu.push_back(gpu);
				c.cpu.push_back(cpu);
				c.cluster.push_back(cluster);
				c.opaque.push_back(opaque);
			}
			if (p_options.progress) {
				printf("[round %d/%d]", round + 1, p_options.rounds);
				for (const Config &c : configs) {
					printf(" %s %.1f/%.1f", c.name.c_str(), c.gpu.back(), c.cpu.back());
				}
				printf(" (GPU/CPU ms)\n");
				fflush(stdout);
			}
		}

		auto ratio = [&](const String &p_id, const String &p_label, const String &p_a, const String &p_b, double p_goal, bool p_scored) {
			const int a = find(p_a), b = find(p_b);
			if (a < 0 || b < 0 || configs[a].gpu.empty()) {
				return;
			}
			std::vector<double> g, c;
			for (size_t i = 0; i < configs[a].gpu.size(); i++) {
				g.push_back(configs[b].gpu[i] > 0.0 ? configs[a].gpu[i] / configs[b].gpu[i] : 0.0);
				c.push_back(configs[b].cpu[i] > 0.0 ? configs[a].cpu[i] / configs[b].cpu[i] : 0.0);
			}
			Result r;
			r.id = p_id;
			r.label = p_label;
			r.gpu = median(g);
			r.cpu = median(c);
			r.goal = p_goal;
			r.scored = p_scored;
			r_results->push_back(r);
		};
		if (ok) {
			// The absolute medians behind the ratios (ms per frame), for the record.
			for (const Config &c : configs) {
				if (c.gpu.empty()) {
					continue; // --clusters-only: not timed.
				}
				Result r;
				r.id = "ms";
				r.label = c.name;
				r.gpu = median(c.gpu);
				r.cpu = median(c.cpu);
				r.scored = false;
				r_results->push_back(r);
				if (c.name == "DEMO") {
					r.label = "DEMO cluster_build / opaque passes";
					r.gpu = median(c.cluster);
					r.cpu = median(c.opaque);
					r_results->push_back(r);
				}
			}
			for (int n : p_options.p1_lights) {
				ratio("P1", vformat("LTC / footprint-matched spot, %d lights", n), vformat("LTC_%d", n), vformat("SPOT_%d", n), 1.5, n == 64);
			}
			for (int n : p_options.p2_lights) {
				ratio("P2", vformat("LTC / MRP, %d lights", n), vformat("LTC_%d", n), vformat("MRP_%d", n), 1.2, true);
			}
			for (int n : p_options.p2_lights) {
				ratio("L2", vformat("LTC_2LOBE / LTC, %d lights", n), vformat("LTC2_%d", n), vformat("LTC_%d", n), 1.7, true);
			}
			ratio("P4", "no-area scene / same frame with the area code off", "NO_AREA", "NO_AREA_CODE_OFF", 1.01, true);
			for (int n : p_options.t1_lights) {
				ratio("T1", vformat("textured LTC / untextured LTC, %d lights", n), vformat("LTC_TEX_%d", n), vformat("LTC_%d", n), 1.15, true);
			}
			ratio("S1", "one 25-map shadowed area light / unshadowed", "SHADOW_25", "SHADOW_OFF", 1.25, true);
			for (const char *name : { "SHADOW_4", "SHADOW_9", "SHADOW_25", "SHADOW_81", "SHADOW_4_PCF", "SHADOW_9_PCF", "SHADOW_25_PCF" }) {
				// Scored: the default grid (issue 19: the default's frame <= 1.5 x the PCSS baseline's).
				const int default_maps = RS::LIGHT_AREA_SHADOW_GRID_DEFAULT * RS::LIGHT_AREA_SHADOW_GRID_DEFAULT;
				ratio("S2", vformat("%s / the PCSS baseline", name), name, "SHADOW_PCSS", 1.5, String(name) == vformat("SHADOW_%d", default_maps));
			}
			const int demo_index = find("DEMO");
			if (demo_index >= 0) {
				std::vector<double> q;
				for (size_t i = 0; i < configs[demo_index].cluster.size(); i++) {
					q.push_back(configs[demo_index].opaque[i] > 0.0 ? configs[demo_index].cluster[i] / configs[demo_index].opaque[i] : 0.0);
				}
				Result r;
				r.id = "C1";
				r.label = "cluster build / opaque pass GPU time, demo";
				r.gpu = median(q);
				r.cpu = r.gpu; // A split of one frame's GPU time: no CPU counterpart.
				r.goal = 0.02;
				r_results->push_back(r);
			}
			// P5: the cluster debug view of the LTC scenes; red = listed pairs, green = lit pairs.
			for (const auto &s : ltc_scenarios) {
				if (s.first != 16 && s.first != 64) {
					continue;
				}
				RID vp = scenes.viewport(s.second, w, h);
				rs->viewport_set_debug_draw(vp, RS::VIEWPORT_DEBUG_DRAW_CLUSTER_AREA_LIGHTS);
				rs->viewport_set_active(vp, true);
				rs->draw();
				rs->viewport_set_active(vp, false);
				double listed = 0.0, lit = 0.0;
				if (!count_pairs(rs->viewport_get_texture_data(vp), &listed, &lit) || !(lit > 0.0)) {
					ok = false;
					error = "the cluster debug view returned no lit pixels.";
					break;
				}
				Result r;
				r.id = "P5";
				r.label = vformat("area (pixel, light) pairs listed by the clusters / lit, %d lights", s.first);
				r.gpu = listed / lit;
				r.cpu = r.gpu; // A count, not a time.
				r.goal = 1.5;
				r_results->push_back(r);
			}
		}
	}
	engine.stop();
	if (!ok) {
		return fail(error);
	}
	return true;
}

String TargetsBench::format(const std::vector<Result> &p_results) {
	String out;
	for (const Result &r : p_results) {
		char line[512];
		if (r.id == "ms" && r.label == "DEMO cluster_build / opaque passes") {
			snprintf(line, sizeof(line), "  median GPU ms, DEMO: cluster_build %.3f, opaque %.3f\n", r.gpu, r.cpu);
			out += line;
			continue;
		}
		if (r.id == "ms") {
			snprintf(line, sizeof(line), "  median ms per frame, %s: gpu %.2f, cpu %.2f\n", r.label.c_str(), r.gpu, r.cpu);
			out += line;
			continue;
		}
		snprintf(line, sizeof(line), "%s %s: %.3f / %s%.3f / %s (gpu %.3f, cpu %.3f)\n", r.id.c_str(), r.label.c_str(), r.measured(), r.scored ? "" : "(", r.goal,
				r.scored ? (r.met() ? "met" : "missed") : "not scored)", r.gpu, r.cpu);
		out += line;
	}
	return out;
}

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

} // namespace

int targets_bench_command(const std::vector<String> &p_args) {
	TargetsBench::Options options;
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		if (a == "--targets") {
			continue;
		} else if (a == "--progress") {
			options.progress = true;
		} else if (a == "--shadows-only") {
			options.shadows_only = true;
		} else if (a == "--texture-only") {
			options.texture_only = true;
		} else if (a == "--clusters-only") {
			options.clusters_only = true;
		} else if (a == "--two-lobe-only") {
			options.two_lobe_only = true;
		} else if (a == "--rounds" && has_value) {
			if (!parse_int(p_args[++i], 1, 1000, options.rounds)) {
				fprintf(stderr, "godot-area bench --targets: --rounds must be an integer in 1..1000, got '%s'\n", p_args[i].c_str());
				return 2;
			}
		} else if (a == "--resolution" && has_value) {
			const String v = p_args[++i];
			const size_t x = v.find('x');
			if (x == String::npos || !parse_int(v.substr(0, x), 16, 4096, options.width) || !parse_int(v.substr(x + 1), 16, 4096, options.height)) {
				fprintf(stderr, "godot-area bench --targets: --resolution must be WxH with 16..4096 per side, got '%s'\n", v.c_str());
				return 2;
			}
		} else {
			fprintf(stderr, "godot-area bench --targets: unknown or incomplete option '%s' (options: --rounds N, --resolution WxH, --progress, --shadows-only, --texture-only, --clusters-only, --two-lobe-only)\n", a.c_str());
			return 2;
		}
	}
	std::vector<TargetsBench::Result> results;
	String error;
	if (!TargetsBench::run(options, &results, &error)) {
		fprintf(stderr, "godot-area bench --targets: %s\n", error.c_str());
		return 1;
	}
	printf("bench --targets: %dx%d, %d rounds, %u lights per type capacity; target: measured / goal / met|missed (measured = median per-round ratio of process CPU time; P5 a pair count, C1 a GPU split)\n",
			options.width, options.height, options.rounds, CLI_MAX_LIGHTS_PER_TYPE);
	printf("%s", TargetsBench::format(results).c_str());
	return 0;
}
