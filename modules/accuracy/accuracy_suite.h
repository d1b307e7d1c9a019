/**************************************************************************/
/*  accuracy_suite.h                                                      */
/**************************************************************************/
/* godot-area: the area-light accuracy suite (thesis 5.5). Every          */
/* generated scene (accuracy_scenes.h) is rendered by the engine          */
/* (RenderingServerDefault + RendererCompositorRD, once per shading       */
/* method) and by the reference (RendererCompositorReference, shadows     */
/* off, adaptive to 0.2 % relative standard error, seed 0), and compared  */
/* with ImageMetrics. The shading method is a column: the caller lists    */
/* the RS::LightAreaShadingMethod values to measure (default {LTC}).      */
/*                                                                        */
/* run() creates its own rendering servers one after the other (first    */
/* the reference, then the engine) and a RenderingDevice if none exists;  */
/* no RenderingServer may exist when it is called.                        */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"

#include <vector>

class AccuracySuite {
public:
	struct Options {
		bool ci_subset = false; // The CI subset (22 scenes) instead of the full suite.
		bool shapes = false; // The disk / sphere / tube scenes (AccuracyScenes::shape_suite(), with ci_subset its CI subset).
		int resolution = 96; // Square images, 1..1024 pixels.
		std::vector<int> methods; // RS::LightAreaShadingMethod values; empty = {LTC}.
		String csv_path; // Written by run() when not empty.
		String thumbnails_dir; // When not empty: PNGs engine | reference | FLIP of the worst scenes.
		bool progress = false; // One line per scene on stdout.
		String filter; // Only scenes whose id contains this (empty = all).
		int thumbnails_per_method = 8; // Worst scenes by LDR-FLIP, per method.
		int reference_threads = 0; // 0 = hardware concurrency.
	};

	struct Row {
		String scene_id;
		String receiver; // "plane" or "sphere".
		float roughness = 0.0f;
		float metallic = 0.0f;
		float light_width = 0.0f;
		float light_height = 0.0f;
		String placement; // facing, grazing, horizon, tilted, close, far, vertical.
		float view_elevation = 0.0f; // Degrees; 0 = the standard camera (accuracy_scenes.h).
		int method = 0; // RS::LightAreaShadingMethod.
		String method_name;
		int resolution = 0;
		double rmse = 0.0;
		double relative_mse = 0.0;
		double relative_rmse = 0.0; // Radiance: sqrt(sum (a - b)^2 / sum b^2) (image_metrics.h).
		double brightness_ratio = 1.0; // Mean brightness engine / reference.
		double mae = 0.0;
		double pearson = 1.0;
		double ssim = 1.0;
		double flip = 0.0; // Mean LDR-FLIP.
		double hdr_flip = 0.0;
		double engine_ms = 0.0; // Wall time of RenderingServer::draw() (submit + wait).
		double engine_gpu_ms = 0.0; // Sum of the GPU pass timestamps (0 if unsupported).
		double reference_ms = 0.0; // Wall time of the reference render.
		double reference_samples_per_pixel = 0.0; // Mean area-light integrand evaluations per pixel.
	};

	// Renders and compares every scene for every method. Fills r_rows (scene-major within each
	// method) and writes the CSV / thumbnails if asked. False (r_error set) on any failure.
	static bool run(const Options &p_options, std::vector<Row> *r_rows, String *r_error);

	// The CSV: one header line, then one line per row (the columns of the first version, then
	// relative_rmse, brightness_ratio, view_elevation appended so older readers keep working).
	static bool write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error = nullptr);

	// Scene classes of the radiance-error report and of the CI bounds (doc/accuracy.md):
	//   CLASS_CROSSING      the light crosses the receiver's plane (horizon placement on the plane).
	//   CLASS_GRAZING_VIEW  seen from view_elevation <= 25 degrees (theta_v >= 65 at p), not crossing.
	//   CLASS_FACING        facing / close / far with the standard camera (top-down views).
	//   CLASS_OBLIQUE       the rest (grazing / tilted / vertical lights, sphere horizon).
	enum SceneClass {
		CLASS_FACING,
		CLASS_OBLIQUE,
		CLASS_GRAZING_VIEW,
		CLASS_CROSSING,
		CLASS_MAX,
	};
	static SceneClass scene_class(const Row &p_row);
	static const char *scene_class_name(SceneClass p_class);

	// Markdown tables: (1) per method and roughness, the number of scenes, mean and worst LDR-FLIP,
	// RMSE, relative RMSE and SSIM, and the worst scene (by relative RMSE); (2) per method and scene
	// class, mean and worst relative RMSE, the range of the brightness ratio, mean FLIP; (3) the
	// issue #18 target classes: grazing views at roughness 0.25 to 0.6, facing views at roughness >=
	// 0.1, crossing lights.
	static String summary_table(const std::vector<Row> &p_rows);

	// Display name of a shading method value ("LTC", ...; unknown values: "method_<n>").
	static String method_name(int p_method);

	// engine | reference | FLIP heatmap side by side, linear values clamped to [0, 1] then
	// sRGB-encoded (what LDR-FLIP sees), upscaled by an integer factor to at least 96 pixels high.
	static bool write_thumbnail(const Image &p_engine, const Image &p_reference, const std::vector<float> &p_flip_map, const String &p_path, String *r_error = nullptr);
};
