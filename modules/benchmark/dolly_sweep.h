/**************************************************************************/
/*  dolly_sweep.h                                                         */
/**************************************************************************/
/* godot-area: the adaptive-shadow dolly benchmark (thesis section 6.4 on */
/* our engine; `godot-area bench --sweep dolly`). The penumbra scene of   */
/* penumbra_scene.h (light range 3 m, so the HEURISTIC's distance term    */
/* works); the camera looks at the middle of the box's penumbra on the    */
/* floor from N positions on a straight line, far to near (distances      */
/* spaced geometrically). Each shadow mode (ADAPTIVE, HEURISTIC, FIXED    */
/* 5 x 5, FIXED 9 x 9 by default) has its own scene and viewport (only    */
/* the drawn one active); the cameras dolly in together, and at each      */
/* position every mode converges, then the modes' timed frames are        */
/* interleaved frame by frame (f of each mode, then f + 1):               */
/*                                                                        */
/*  converge  at each position, frames until the light's map count is     */
/*            unchanged for `converge_stable` frames (cap                 */
/*            `converge_max`; ADAPTIVE's tree changes over frames and     */
/*            carries over from the previous position, as in a dolly);    */
/*  timing    `frames` frames with the light moving by 1 cm every other   */
/*            frame, so every map is redrawn each frame (the thesis'      */
/*            animated light): median GPU ms per profiler pass            */
/*            ("area_shadows" = shadow maps; passes whose name contains   */
/*            "reproj" / "band" = the adaptive reprojection / banding     */
/*            passes; total = every pass of the frame);                   */
/*  error     one frame with the light at rest: visibility (shadowed /    */
/*            unshadowed) RMSE against the Embree reference with shadow   */
/*            rays at ref_width x ref_height, the engine rendering at     */
/*            supersample times that (odd: pixel centres coincide).       */
/*                                                                        */
/* Atlas: `atlas` px split in `subdivision` tiles per side (default       */
/* 4096 / 16: 256 tiles of 256 px), so every mode, FIXED 9 x 9 and a      */
/* fully refined ADAPTIVE tree included, draws maps of one resolution     */
/* and no mode is limited by the tile count (the thesis gave its 81-map   */
/* grid smaller tiles; that mixes tile size into the comparison). A       */
/* fixed grid that does not fit gets the next power-of-two subdivision.   */
/* RenderForwardClustered is driven directly (no RenderingServer); a      */
/* RenderingDevice is created when none exists.                           */

#pragma once

#include "core/math/vector3.h"
#include "core/string/ustring.h"
#include "servers/rendering_server.h"

#include <vector>

class DollySweep {
public:
	struct ModeSpec {
		String name; // "ADAPTIVE", "HEURISTIC", "FIXED_25", ...
		RS::LightAreaShadowMode mode = RS::LIGHT_AREA_SHADOW_FIXED;
		int grid = 5; // FIXED only.
	};

	struct Options {
		std::vector<ModeSpec> modes = default_modes();
		int positions = 8;
		float far_distance = 10.0f; // Camera distance to the penumbra target, metres.
		float near_distance = 0.5f;
		int ref_width = 96; // Reference (error) image.
		int ref_height = 54;
		int supersample = 3; // Engine image = reference x this (odd).
		int atlas = 4096;
		int subdivision = 16;
		int frames = 7; // Timed frames per position.
		int converge_max = 40;
		int converge_stable = 4;
		float blur = 1.0f; // shadow_blur (PCF radius 2 texels).
		float light_range = 3.0f;
		float reference_error = 0.01f;
		bool errors = true;
		bool progress = false;
	};

	struct Row {
		String mode;
		int position = 0; // 0 = farthest.
		float distance = 0.0f; // Camera to penumbra target, metres.
		int width = 0; // Engine image.
		int height = 0;
		int atlas = 0;
		int subdivision = 0;
		int tile = 0;
		int maps = 0; // Maps the light shades with in the error frame.
		double draws = 0.0; // Mean maps drawn per timed frame.
		int converge_frames = 0;
		double shadow_maps_ms = -1.0; // Medians over the timed frames; -1 = pass not in the profile.
		double reprojection_ms = -1.0;
		double banding_ms = -1.0;
		double total_ms = -1.0;
		double cpu_ms = -1.0; // Wall time of render_scene() (lavapipe: includes the GPU work).
		double visibility_rmse = -1.0; // -1 without errors.
		double penumbra_rmse = -1.0;
	};

	struct Targets {
		int far_count = 0; // Positions averaged at each end.
		double far_total_ratio = -1.0; // ADAPTIVE / FIXED_25 total GPU ms, far (issue 19: <= 0.6).
		double far_error_ratio = -1.0; // ADAPTIVE / FIXED_25 visibility RMSE, far (issue 19: <= 1.2).
		double far_shadow_ratio = -1.0; // Same, shadow work only (maps + reprojection + banding).
		double near_error_ratio = -1.0; // ADAPTIVE / FIXED_81 visibility RMSE, near (target <= 1).
		double near_penumbra_ratio = -1.0;
		double overhead_ratio = -1.0; // ADAPTIVE (reprojection + banding) / shadow maps, all positions (target <= 0.15).
		bool has_adaptive_passes = false; // Reprojection or banding timestamps were found.
	};

	static std::vector<ModeSpec> default_modes();
	// "adaptive", "heuristic", "pcss", "fixedN" (N = g^2, g in 2..9); false on an unknown name.
	static bool parse_mode(const String &p_name, ModeSpec &r_mode);
	// Camera position p_index of p_count (0 = far) and the point it looks at.
	static Vector3 get_camera_position(const Options &p_options, int p_index);
	static Vector3 get_target();

	static bool run(const Options &p_options, std::vector<Row> &r_rows, String *r_error);
	static bool write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error);
	static Targets compute_targets(const std::vector<Row> &p_rows);
	// Human-readable lines of the targets.
	static String format_targets(const Targets &p_targets);
};
