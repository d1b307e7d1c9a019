/**************************************************************************/
/*  frame_queue_bench.cpp                                                 */
/**************************************************************************/
/* godot-area: frame queue size 1 vs 2 on the demo scene (see             */
/* frame_queue_bench.h).                                                  */

#include "modules/benchmark/frame_queue_bench.h"

#include "core/error/error_macros.h"
#include "scene/main/godot_instance.h"
#include "scene/main/node.h"
#include "scene/main/scene_tree.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/rendering_profiler.h"
#include "servers/rendering_server.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace {

double cpu_time_ms() {
	timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

double wall_time_ms() {
	return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double middle(const std::vector<double> &p_values) {
	return RenderingProfiler::compute_stats(p_values).median; // NumPy's median; 0 without samples.
}

} // namespace

bool FrameQueueBench::run(const Options &p_options, Result *r_result, String *r_error) {
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	ERR_FAIL_NULL_V(r_result, false);
	if (RenderingServer::get_singleton()) {
		return fail("FrameQueueBench::run creates its own rendering servers; a RenderingServer already exists.");
	}
	if (p_options.rounds < 1 || p_options.frames < 1) {
		return fail("--rounds and --frames must be >= 1.");
	}
	String error;
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, &error)) {
		return fail(error);
	}
	RenderingServer *rs = engine.get_rendering_server();
	RenderingDevice *rd = RenderingDevice::get_singleton();
	Node *demo = GodotInstance::load_scene(String(), &error);
	if (!demo) {
		return fail("cannot load the embedded demo scene: " + error);
	}
	engine.set_scene(demo);
	engine.get_tree()->set_size(p_options.width, p_options.height);
	const uint32_t original = rd->get_frame_queue_size();
	std::vector<double> wall[2], cpu[2], wall_ratio, cpu_ratio;
	double waits[2] = { 0.0, 0.0 }, lag[2] = { 0.0, 0.0 }, blocked[2] = { 0.0, 0.0 };
	for (int round = 0; round < p_options.rounds; round++) {
		for (int q = 0; q < 2; q++) {
			if (!rd->set_frame_queue_size(uint32_t(q + 1))) {
				return fail("set_frame_queue_size failed.");
			}
			rs->draw(); // Discarded: the first frames after a switch.
			rs->draw();
			rd->sync(); // Nothing in flight when the block starts: it pays for its own frames only.
			const uint64_t waits0 = rd->get_fence_wait_count();
			const uint64_t blocked0 = rd->get_fence_wait_time_usec();
			const double wall0 = wall_time_ms();
			const double cpu0 = cpu_time_ms();
			double block_lag = 0.0;
			for (int f = 0; f < p_options.frames; f++) {
				rs->draw();
				block_lag += double(rd->get_frames_submitted() - rd->get_frames_completed());
			}
			const uint64_t block_waits = rd->get_fence_wait_count() - waits0;
			const uint64_t block_blocked = rd->get_fence_wait_time_usec() - blocked0;
			rd->sync(); // The frames still in flight belong to this block.
			wall[q].push_back((wall_time_ms() - wall0) / p_options.frames);
			cpu[q].push_back((cpu_time_ms() - cpu0) / p_options.frames);
			waits[q] += double(block_waits) / (double(p_options.frames) * p_options.rounds);
			lag[q] += block_lag / (double(p_options.frames) * p_options.rounds);
			blocked[q] += double(block_blocked) * 1e-3 / (double(p_options.frames) * p_options.rounds);
		}
		wall_ratio.push_back(wall[1].back() / wall[0].back());
		cpu_ratio.push_back(cpu[1].back() / cpu[0].back());
	}
	rd->set_frame_queue_size(original);
	for (int q = 0; q < 2; q++) {
		r_result->wall_ms[q] = middle(wall[q]);
		r_result->cpu_ms[q] = middle(cpu[q]);
		r_result->waits_per_frame[q] = waits[q];
		r_result->lag[q] = lag[q];
		r_result->blocked_ms[q] = blocked[q];
	}
	r_result->wall_ratio = middle(wall_ratio);
	r_result->cpu_ratio = middle(cpu_ratio);
	return true;
}

String FrameQueueBench::format(const Options &p_options, const Result &p_result) {
	String s = vformat("bench --frame-queue: demo scene %dx%d, %d rounds x %d frames per queue size (median per-frame ms; ratio = median per-round 2 / 1)\n",
			p_options.width, p_options.height, p_options.rounds, p_options.frames);
	for (int q = 0; q < 2; q++) {
		s += vformat("frame_queue_size %d: wall %.2f ms, process CPU %.2f ms, blocked on fences %.2f ms (%.2f waits) per draw, frames in flight after a draw %.2f\n",
				q + 1, p_result.wall_ms[q], p_result.cpu_ms[q], p_result.blocked_ms[q], p_result.waits_per_frame[q], p_result.lag[q]);
	}
	s += vformat("ratio 2 / 1: wall %.3f, process CPU %.3f\n", p_result.wall_ratio, p_result.cpu_ratio);
	return s;
}

int frame_queue_bench_command(const std::vector<String> &p_args) {
	FrameQueueBench::Options options;
	for (size_t i = 0; i < p_args.size(); i++) {
		const String &a = p_args[i];
		const bool has_value = i + 1 < p_args.size();
		int *target = nullptr;
		if (a == "--frame-queue") {
			continue;
		} else if (a == "--rounds" && has_value) {
			target = &options.rounds;
		} else if (a == "--frames" && has_value) {
			target = &options.frames;
		} else if ((a == "--width" || a == "--height") && has_value) {
			target = a == "--width" ? &options.width : &options.height;
		} else {
			fprintf(stderr, "godot-area bench --frame-queue: unknown or incomplete option '%s' (options: --rounds N, --frames N, --width W, --height H)\n", a.c_str());
			return 2;
		}
		const String v = p_args[++i];
		char *end = nullptr;
		const long n = std::strtol(v.c_str(), &end, 10);
		if (v.empty() || *end != '\0' || n < 1 || n > 4096) {
			fprintf(stderr, "godot-area bench --frame-queue: %s must be an integer in 1..4096, got '%s'\n", a.c_str(), v.c_str());
			return 2;
		}
		*target = int(n);
	}
	FrameQueueBench::Result result;
	String error;
	if (!FrameQueueBench::run(options, &result, &error)) {
		fprintf(stderr, "godot-area bench --frame-queue: %s\n", error.c_str());
		return 1;
	}
	printf("%s", FrameQueueBench::format(options, result).c_str());
	return 0;
}
