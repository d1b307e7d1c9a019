/**************************************************************************/
/*  shadows_sweep.h                                                       */
/**************************************************************************/
/* godot-area: the area soft-shadow sweep (thesis section 6.2 on our      */
/* engine; `godot-area bench --sweep shadows`). Scene: a 1.6 x 1.6 m     */
/* area light 1.5 m above a Lambert floor and a 0.5 m box centred 0.55 m */
/* above it (penumbra_scene.h, shared with the dolly sweep), seen from  */
/* above.                                                                 */
/*                                                                        */
/*  error   For each atlas size and number of maps (grid^2), the atlas is */
/*          split into the smallest power-of-two subdivision that holds   */
/*          the maps (as the thesis: more maps, each map half as wide),   */
/*          and the visibility (shadowed / unshadowed image, so LTC's own */
/*          error cancels) is compared with the Embree reference with     */
/*          shadow rays: RMSE over the lit pixels, per PCF radius         */
/*          (shadow_blur). The one-map PCSS baseline is a row of its own. */
/*  timing  GPU ms of the "area_shadows" profiler pass with every map     */
/*          redrawn each frame (the light moves), median over `frames`:   */
/*          with the sweep's tiles ("timing") and with a fixed tile size  */
/*          ("timing_fixed_tile", timing_subdivision tiles per side),     */
/*          whose slope over the number of maps is the cost per map.      */
/*                                                                        */
/* RenderForwardClustered is driven directly (no RenderingServer); a      */
/* RenderingDevice is created when none exists.                           */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class GodotInstance;
class PenumbraScene;
class RenderingServer;

class ShadowsSweep {
public:
	struct Options {
		std::vector<int> atlas_sizes = { 2048, 8192 };
		std::vector<int> grids = { 2, 3, 5, 7, 9 }; // 4, 9, 25, 49, 81 maps.
		std::vector<float> blurs = { 0.0f, 1.0f, 2.0f }; // shadow_blur: PCF radius 2 x blur texels.
		int resolution = 96; // Square image.
		int frames = 9; // Timed frames per configuration (after one warm-up).
		int timing_subdivision = 16; // Fixed-tile timing: tiles per side for every map count.
		int pcss_subdivision = 16; // PCSS baseline row: its one map in a tile of atlas / this.
		float reference_error = 0.01f; // Target relative std error of the reference.
		bool errors = true;
		bool timing = true;
		bool progress = false;
		// Not empty: only render the doc's images (the reference, PCSS, 3 x 3 and 5 x 5 with the fixed PCF and
		// the per-sample penumbra filter, default atlas) as visibility PNGs into this folder, and print their
		// errors and banding; no CSV rows.
		String images_dir;
	};

	struct Row {
		String section; // "error", "timing" or "timing_fixed_tile".
		String mode; // "FIXED" or "PCSS".
		int atlas = 0;
		int subdivision = 0;
		int tile = 0; // Pixels per tile (a map: four octant views of tile / 2).
		int maps = 0;
		float blur = 0.0f;
		double visibility_rmse = -1.0; // error rows.
		double shadow_ms = -1.0; // timing rows: median GPU ms of the shadow pass.
	};

private:
	static bool _write_images(const Options &p_options, RenderingServer *p_rs, PenumbraScene &p_objects, GodotInstance &p_engine, const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, String &r_error);

public:
	// Smallest power of two >= p_grid (tiles per side for p_grid^2 maps).
	static int subdivision_for_grid(int p_grid);

	// Runs the sweep; false with r_error on failure.
	static bool run(const Options &p_options, std::vector<Row> &r_rows, String *r_error);
	// CSV with a header line.
	static bool write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error);
};
