/**************************************************************************/
/*  targets_bench.h                                                       */
/**************************************************************************/
/* godot-area: the cost targets of issue 17 ("Area lights at the cost of  */
/* spot lights"), `godot-area bench --targets`.                           */
/*                                                                        */
/* ONE process, one RenderingServerDefault + RendererCompositorRD with    */
/* the CLI's light capacity (512 per type). Every configuration is a      */
/* scenario with its own viewport; one viewport is active at a time and  */
/* the configurations are interleaved frame by frame: per round, each     */
/* configuration draws one frame that is thrown away (first frame after   */
/* a switch; waited for before the next one, so with frames in flight    */
/* none of its work falls in the measured window) and one that is         */
/* measured. Two clocks per measured frame:                               */
/*   gpu  the sum of the frame's RD timestamp passes (on lavapipe this    */
/*        is wall clock);                                                 */
/*   cpu  process CPU time (CLOCK_PROCESS_CPUTIME_ID) around draw() and   */
/*        the profile read that waits for that frame (frames in flight):  */
/*        records, submits and waits: on a software rasteriser it         */
/*        counts the rasteriser's threads too, so it is load-independent. */
/* A target ratio A / B is the median over rounds of the per-round        */
/* ratios (both frames of a round are seconds apart at most).             */
/*                                                                        */
/* Targets (issue 17's table):                                            */
/*   P1 LTC / footprint-matched spot, 1/16/64/256 lights;                 */
/*   P2 LTC / MRP, 16/64 lights;                                          */
/*   P4 a scene without area lights / the same frame with the renderer's  */
/*      area code switched off (RenderForwardClustered::                  */
/*      set_area_code_disabled: no area steps, omni/spot clusters only);  */
/*   P5 area-light pairs (pixel, light) listed by the clusters / pairs    */
/*      the light lights (debug view, counted on the read-back image);   */
/*   S1 one 25-map (FIXED 5 x 5) shadowed area light / unshadowed;        */
/*   S2 the same light with 4 / 9 / 25 / 81 maps / its PCSS baseline;     */
/*      scored: the default grid (issue #19: <= 1.5);                     */
/*   L2 the two-lobe LTC (LTC_2LOBE) / LTC, 16/64 lights (issue #18:      */
/*      <= 1.7);                                                          */
/*   C1 cluster build / opaque pass GPU time, the embedded demo scene.    */
/* No RenderingServer may exist when run() is called.                     */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class TargetsBench {
public:
	struct Options {
		int width = 192;
		int height = 108;
		int rounds = 5;
		std::vector<int> p1_lights = { 1, 16, 64, 256 };
		std::vector<int> p2_lights = { 16, 64 };
		bool progress = false;
		bool shadows_only = false; // Only the S1 / S2 shadow configurations (--shadows-only).
		// T1: LTC lights with an area_texture (a 256 x 256 pattern) / the same lights untextured.
		std::vector<int> t1_lights = { 16 };
		bool texture_only = false; // Only the T1 configurations (--texture-only).
		bool clusters_only = false; // Only P5, the cluster pair counts (--clusters-only): no timed frames.
		bool two_lobe_only = false; // Only the L2 configurations (--two-lobe-only): LTC_2LOBE and LTC at p2_lights.
	};

	struct Result {
		String id; // "P1", "P2", ...; "ms": a configuration's median ms per frame (label = its name).
		String label; // "LTC / spot, 64 lights".
		double gpu = 0.0; // Median per-round ratio of GPU timestamps.
		double cpu = 0.0; // Median per-round ratio of process CPU time (P5: the pair ratio; C1: same as gpu).
		double goal = 0.0;
		bool scored = true; // False: reported for the record, no goal.
		// The value compared with the goal (the CPU ratio for timings: load-independent on lavapipe).
		double measured() const { return cpu; }
		bool met() const { return measured() <= goal; }
	};

	static bool run(const Options &p_options, std::vector<Result> *r_results, String *r_error);
	// "id label: measured / goal / met|missed (gpu X, cpu Y)" lines.
	static String format(const std::vector<Result> &p_results);
};

int targets_bench_command(const std::vector<String> &p_args);
