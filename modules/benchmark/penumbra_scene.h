/**************************************************************************/
/*  penumbra_scene.h                                                      */
/**************************************************************************/
/* godot-area: the penumbra scene of the shadow benchmarks (thesis        */
/* chapter 6), shared by `bench --sweep shadows` (shadows_sweep.h) and    */
/* `bench --sweep dolly` (dolly_sweep.h): a square area light facing down */
/* above a Lambert floor, and a box between them that casts a wide        */
/* penumbra. The sweeps build it through the public RenderingServer (a   */
/* scenario, instances, a camera and a viewport), so the Forward+ image   */
/* and the Embree reference (RendererCompositorReference) see one scene   */
/* through the scene cull, the path users take. (The renderer's own unit */
/* tests build the same objects in bare storages themselves, from the    */
/* static builders below.)                                                */
/*                                                                        */
/* Also the visibility error of the sweeps: visibility = shadowed /       */
/* unshadowed image (the shading method's own error cancels), compared    */
/* with the reference's over the lit pixels.                              */
/* tests/servers/test_area_shadows_render.cpp renders it too.             */

#pragma once

#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"
#include "servers/rendering/renderer_scene_render.h"

#include <cstdint>
#include <vector>

class RenderingServer;

class PenumbraScene {
public:
	struct Settings {
		Vector2 light_size = Vector2(1.6f, 1.6f);
		float light_height = 1.5f; // Light centre above the floor (y = 0).
		float light_energy = 2.0f;
		float light_range = 20.0f;
		float box_half = 0.25f;
		float box_half_height = -1.0f; // Vertical half extent; < 0: box_half (a cube). Small: a plate.
		float box_half_depth = -1.0f; // Half extent along Z; < 0: box_half. Long and thin: a bar.
		Vector3 box_center = Vector3(0.0f, 0.55f, 0.0f);
		float floor_half = 4.0f;
	};

private:
	RenderingServer *rs = nullptr;
	RID floor_mesh, box_mesh, material, light;
	RID scenario, environment, camera, viewport, floor_instance, box_instance, light_instance;
	int view_width = 0;
	int view_height = 0;

public:
	static RS::SurfaceData make_plane(float p_half);
	// Axis-aligned box, 24 vertices with outward normals (half extents p_half, or p_half on every axis).
	static RS::SurfaceData make_box(const Vector3 &p_center, const Vector3 &p_half);
	static RS::SurfaceData make_box(const Vector3 &p_center, float p_half) { return make_box(p_center, Vector3(p_half, p_half, p_half)); }
	// The box's half extents (box_half, or box_half_height / box_half_depth where set).
	static Vector3 box_half_extents(const Settings &p_settings);
	static RS::MaterialParams lambert();
	// world_from_light: the light faces down (-Z local = -Y world).
	static Transform3D light_transform(const Settings &p_settings);
	// A camera at p_position looking at p_target (up +Y, or -Z when looking straight down), black
	// background, p_width x p_height, vertical field of view p_fovy.
	static RenderSceneData make_view(const Vector3 &p_position, const Vector3 &p_target, int p_width, int p_height, float p_fovy = 60.0f);
	// The shadows sweep's view: from 3.2 m above, slightly off centre, square.
	static RenderSceneData make_top_view(int p_resolution);

	// Creates the scene in p_rs with a p_width x p_height viewport (black background, no ambient) that
	// looks from the top view. False (and nothing left behind) if the server refused.
	bool create_in_server(RenderingServer *p_rs, int p_width, int p_height, const Settings &p_settings);
	bool create_in_server(RenderingServer *p_rs, int p_width, int p_height) { return create_in_server(p_rs, p_width, p_height, Settings()); }
	// Server scene: the camera (transform and field of view of p_view) and the light's transform.
	void set_view(const RenderSceneData &p_view);
	void set_light_transform(const Transform3D &p_transform);
	// Server scene: draws one frame and reads the viewport back (RGBA floats, row-major).
	std::vector<float> render();
	RID get_viewport() const { return viewport; }
	void free();
	RID get_light() const { return light; }
	bool is_created() const { return light.is_valid(); }

	// Visibility error of an engine image against the reference (RGBA float images, row-major). Reference
	// pixel (x, y) is compared with engine pixel (x * p_step + p_step / 2, y * p_step + p_step / 2): with an odd
	// p_step and an engine image p_step times larger, the two pixel centres coincide. Visibility is clamped to
	// [0, 1.5]; pixels unlit in either unshadowed image are skipped. r_rmse: over the lit pixels (1 when
	// none); r_penumbra_rmse (optional): over the reference's penumbra (0.02 < v < 0.98; -1 when none).
	static void visibility_error(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, int p_width,
			const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int p_ref_width, int p_ref_height,
			int p_step, double &r_rmse, double *r_penumbra_rmse = nullptr);

	// Visibility image (shadowed / open, clamped to [0, 1.5]; -1 where the light does not reach).
	static std::vector<float> visibility_image(const std::vector<float> &p_open, const std::vector<float> &p_shadowed);

	// Banding (what the ADAPTIVE pass' detector looks for, thesis 6.3, on a whole image): a penumbra pixel
	// (0.02 < v < 0.98) is banded when it sits on a plateau of a row or column: its central step is at most
	// a third of the steepest step within 6 pixels on either side, those two steps go the same way and are
	// each at least p_step per pixel. N hard shadows make N - 1 plateaus between their edges; a continuous
	// penumbra has one steep part per edge (and Monte Carlo noise goes up and down). Returns the banded
	// pixels; r_penumbra: the penumbra pixels (optional). Unlit pixels (v < 0) end the search.
	// r_mask (optional): 1 per banded pixel.
	static int count_banded_pixels(const std::vector<float> &p_visibility, int p_width, int p_height, int *r_penumbra = nullptr, float p_step = 0.003f, std::vector<uint8_t> *r_mask = nullptr);

	// Error of the visibility against the reference over the shadow region (pixels where either
	// visibility is below 0.98; same sampling as visibility_error(); silhouette pixels, where the open
	// reference differs from a 4-neighbour by over 10 %, left out): rel_rmse = RMSE / mean reference
	// visibility there, p99 = the 99th percentile of |v - v_ref| / max(v_ref, 0.05).
	struct ShadowError {
		double rmse = 1.0; // Over every lit pixel (as visibility_error()).
		double rel_rmse = 1.0;
		double p99 = 1.0;
		int pixels = 0; // In the shadow region.
	};
	static ShadowError shadow_error(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, int p_width,
			const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int p_ref_width, int p_ref_height, int p_step);

	~PenumbraScene() { free(); }
};
