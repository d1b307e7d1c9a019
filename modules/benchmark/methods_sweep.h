/**************************************************************************/
/*  methods_sweep.h                                                       */
/**************************************************************************/
/* godot-area: the shading-method sweep (issue "All shading methods",     */
/* item 6; `godot-area bench --sweep methods`). Two parts, one CSV:       */
/*                                                                        */
/*  timing  For each configuration (LTC, LTC polynomial, MRP, MC with     */
/*          1/4/16 samples, spot, omni) and light count (1 -> 256), a     */
/*          floor lit by a grid of lights, drawn through                  */
/*          RenderingServerDefault + RendererCompositorRD at a modest     */
/*          resolution; GPU ms per pass = median over `frames` frames     */
/*          after `warmup_frames` (RD timestamps, as the profiler).       */
/*  error   Each area configuration on the accuracy suite's CI subset     */
/*          (modules/accuracy/accuracy_scenes.h) vs the Embree reference  */
/*          (shadows off, seed 0): LDR-FLIP, RMSE, SSIM per scene.        */
/*                                                                        */
/* Optionally writes engine | reference | FLIP strips of the failure      */
/* scenes per method (maps_dir), which misc/scripts/plot_methods.py puts  */
/* into grids. No RenderingServer may exist when run() is called.         */
/*                                                                        */
/* Shape axis (Options::shapes, `--shapes`; issue 21): instead of the     */
/* above, shape_configs() (LTC, MRP, MC 8) x the four area_shapes         */
/* (rectangle, disk, sphere, tube): timing rows "shape_timing" in the     */
/* same scene with lights of that shape (shape_size()), the twelve        */
/* configurations interleaved frame by frame per light count, and error   */
/* rows "shape_error" on shape_error_scenes() (relative RMSE, brightness  */
/* ratio and LDR-FLIP vs the Embree reference). The CSV then has three    */
/* more columns: shape, rel_rmse, brightness_ratio.                       */

#pragma once

#include "core/math/vector2.h"
#include "core/string/ustring.h"

#include <vector>

class MethodsSweep {
public:
	enum Kind {
		KIND_AREA,
		KIND_SPOT,
		KIND_OMNI,
	};

	struct Config {
		String name; // "LTC", "LTC_POLYNOMIAL", "LTC_2LOBE", "MRP", "MC1", "MC4", "MC16", "SPOT", "OMNI".
		Kind kind = KIND_AREA;
		int method = 0; // RS::LightAreaShadingMethod (area only).
		int samples = 1; // Stochastic samples (MC only; 1 otherwise).
	};

	struct Options {
		int width = 256;
		int height = 144;
		std::vector<int> light_counts = { 1, 4, 16, 64, 256 };
		int warmup_frames = 2;
		int frames = 7;
		bool timing = true;
		bool errors = true;
		int error_resolution = 64; // Square images for the error part.
		String csv_path;
		String maps_dir; // When not empty: failure-scene strips, <config>_<scene>.png.
		bool progress = false;
		std::vector<String> only_configs; // Empty: all.
		// A configuration whose median frame (wall) exceeds this at one light count is not timed at
		// larger counts (0 = no cap), so a slow path cannot stall the sweep on a software rasteriser.
		double frame_cap_ms = 2500.0;
		// The shape axis instead of the default sweep (see the banner); maps_dir is not used.
		bool shapes = false;
	};

	struct Row {
		String section; // "timing" or "error".
		String config;
		int method = -1; // -1 for spot/omni.
		int samples = 1;
		int lights = 1;
		int width = 0;
		int height = 0;
		double gpu_ms_opaque = 0.0; // Median GPU ms of the opaque (shading) pass.
		double gpu_ms_total = 0.0; // Median GPU ms of all timed passes.
		double wall_ms = 0.0; // Median wall ms of draw().
		String scene; // Error rows: the accuracy scene id.
		double flip = 0.0;
		double rmse = 0.0;
		double ssim = 1.0;
		double hdr_flip = 0.0;
		String shape; // Shape rows only: "rectangle", "disk", "sphere", "tube".
		double relative_rmse = 0.0; // Shape error rows: sqrt(sum (a - b)^2 / sum b^2).
		double brightness_ratio = 1.0; // Shape error rows: sum a / sum b.
	};

	static std::vector<Config> default_configs();
	// The methods of the shape axis: "LTC", "MRP", "MC8" (8 samples, as doc/methods.md §11).
	static std::vector<Config> shape_configs();
	// Light sizes of the shape axis' timing scene, indexed by RS::LightAreaShape (RS::light_area_set_size
	// meaning per shape): rectangle and disk 1 x 0.5, sphere of diameter 0.5, tube 1 long, 0.15 thick.
	static Vector2 shape_size(int p_shape);
	static const char *shape_name(int p_shape);
	// The error scenes of the shape axis: per shape a diffuse plane facing the light and a glossy metal
	// (roughness 0.5) under the tilted light; the disk, sphere and tube ones are
	// AccuracyScenes::shape_ci_subset(), the rectangle's the same two with a 1 x 1 rectangle.
	static std::vector<String> shape_error_scene_ids();
	// The failure scenes whose maps are written (accuracy scene ids).
	static std::vector<String> failure_scene_ids();

	static bool run(const Options &p_options, std::vector<Row> *r_rows, String *r_error);
	// Writes the fully preprocessed fragment sources the renderer compiles: area_<CONFIG>.frag (the
	// area-light colour variant with exactly one method) and base.frag (the colour variant without
	// area lights, for the omni/spot loops). misc/scripts/spirv_method_counts.py counts their SPIR-V.
	static bool write_shader_sources(const String &p_dir, String *r_error = nullptr);
	static bool write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error = nullptr);
};
