/**************************************************************************/
/*  frame_queue_bench.h                                                   */
/**************************************************************************/
/* godot-area: the cost of frames in flight (issue 17 item 6),            */
/* `godot-area bench --frame-queue`. ONE process draws the embedded demo  */
/* scene (the CLI's default) with RenderingDevice frame queue size 1 and  */
/* 2 (rendering/rendering_device/vsync/frame_queue_size) alternately, in  */
/* blocks: per round and size, set_frame_queue_size() (a flush), two      */
/* discarded frames and a sync(), then N draws and a final sync() (each   */
/* block pays for exactly its N frames). Two clocks per block, divided    */
/* by N: wall (steady clock) and process CPU time (CLOCK_PROCESS_CPUTIME_ */
/* ID: on a software rasteriser it counts its threads too). The result    */
/* is the median over rounds of the per-round ratio size 2 / size 1. No   */
/* pass profile is read while measuring (reading one waits for its        */
/* frame). No RenderingServer may exist when run() is called.             */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class FrameQueueBench {
public:
	struct Options {
		int width = 1280;
		int height = 720;
		int rounds = 5;
		int frames = 10; // Measured draws per block.
	};

	struct Result {
		double wall_ms[2] = { 0.0, 0.0 }; // Median per-frame wall time, queue size 1 and 2.
		double cpu_ms[2] = { 0.0, 0.0 }; // Median per-frame process CPU time.
		double wall_ratio = 0.0; // Median per-round ratio, size 2 / size 1.
		double cpu_ratio = 0.0;
		double waits_per_frame[2] = { 0.0, 0.0 }; // Fence waits per measured draw (sync() excluded).
		double lag[2] = { 0.0, 0.0 }; // Mean frames submitted but not waited for, right after a draw.
		double blocked_ms[2] = { 0.0, 0.0 }; // Mean wall time per draw blocked on fences (sync() excluded).
	};

	static bool run(const Options &p_options, Result *r_result, String *r_error);
	static String format(const Options &p_options, const Result &p_result);
};

int frame_queue_bench_command(const std::vector<String> &p_args);
