/**************************************************************************/
/*  accuracy_scenes.h                                                     */
/**************************************************************************/
/* godot-area: the generated scenes of the area-light accuracy suite      */
/* (thesis 5.5). A scene is one receiver (plane or sphere) with one       */
/* material and one area light, seen by a fixed camera. Scenes are built  */
/* through the RenderingServer API only, so the same description renders  */
/* on the engine (RendererCompositorRD) and on the Embree reference       */
/* (RendererCompositorReference) with identical data.                     */
/*                                                                        */
/* Receiver frame: target point p (plane: origin; sphere of radius 1 at   */
/* the origin: its top (0, 1, 0)), normal n = +Y, tangent t = +X.         */
/* Placements (w = longer light side, h = the side along the light's Y):  */
/*   facing   light parallel to the receiver, 1.5 m above p.             */
/*   grazing  light plane 10 degrees off perpendicular to the receiver,   */
/*            1 m to the side of p, lower edge 5 cm above p's tangent     */
/*            plane: every receiver point is lit at grazing incidence.    */
/*   horizon  light tilted 30 degrees from perpendicular, centre 1.2 m to */
/*            the side IN p's tangent plane: half the rectangle is below  */
/*            the horizon of the points near p (horizon clipping); it    */
/*            does not cut the sphere (it does cut the plane).            */
/*   tilted   light 1 m above p, its normal turned 60 degrees away from p */
/*            (p sees it at 60 degrees off axis; receiver points behind   */
/*            the light plane are unlit: one-sided emission).             */
/*   close    facing at distance 0.1 w (distance << size).               */
/*   far      facing at distance 10 w (distance >> size).                 */
/*   vertical a TV / window over a floor: the light stands upright 1 m    */
/*            behind p (towards -Z, away from the camera), emitting       */
/*            towards the camera (+Z), lower edge 5 cm above p's tangent  */
/*            plane: a floor seen at a low angle mirrors it (the pose     */
/*            where a 3-parameter LTC errs most, issue #18).              */
/* View axis: view_elevation 0 is the suite's standard camera (eye        */
/* (0, 2.5, 3.2) looking at (0, 0.2, 0): about 36 degrees above the       */
/* plane); a positive value puts the eye 3.5 m from p on the +Z side at   */
/* that many degrees above p's tangent plane, looking at p (5 to 20:      */
/* theta_v 70 to 85 degrees at p, the grazing views of issue #18).        */
/* Energy: chosen per scene so that a Lambert surface at p would have     */
/* radiance 0.5 (the irradiance at p integrated by a 64 x 64 midpoint     */
/* rule), so every scene is well exposed for the LDR metrics. Range is    */
/* ten times the lit distance and attenuation 2 (physical): W(d) >= 1 -    */
/* 2e-4, the purely physical integral.                                    */

#pragma once

#include "core/math/transform_3d.h"
#include "core/math/vector2.h"
#include "core/string/ustring.h"
#include "servers/rendering_server.h"

#include <vector>

class AccuracyScenes {
public:
	enum Receiver {
		RECEIVER_PLANE,
		RECEIVER_SPHERE,
	};

	enum Placement {
		PLACEMENT_FACING,
		PLACEMENT_GRAZING,
		PLACEMENT_HORIZON,
		PLACEMENT_TILTED,
		PLACEMENT_CLOSE,
		PLACEMENT_FAR,
		PLACEMENT_VERTICAL,
		PLACEMENT_MAX,
	};

	struct Scene {
		String id; // e.g. "plane_r0.25_m1_1x1_facing".
		Receiver receiver = RECEIVER_PLANE;
		float roughness = 0.5f;
		float metallic = 0.0f;
		Vector2 light_size = Vector2(1, 1);
		Placement placement = PLACEMENT_FACING;
		float view_elevation = 0.0f; // Degrees above the tangent plane at p; 0 = the standard camera.
		// The light's area_shape; light_size keeps its meaning per shape (RS::LightAreaShape).
		RS::LightAreaShape shape = RS::LIGHT_AREA_SHAPE_RECTANGLE;
		// Derived by make_scene():
		Transform3D light_transform;
		float light_energy = 1.0f;
		float light_range = 100.0f;
	};

	// Every RID of a built scene (build() creates them, free_scene() frees them).
	struct Built {
		RID mesh;
		RID material;
		RID light;
		RID environment;
		RID scenario;
		RID mesh_instance;
		RID light_instance;
		RID camera;
		RID viewport;
	};

	static const char *receiver_name(Receiver p_receiver);
	static const char *placement_name(Placement p_placement);

	// Fills the derived fields (transform, energy, range) and the id. p_view_elevation: see the banner
	// (0 = the standard camera; otherwise in [1, 89] degrees). The id gets "_v<degrees>" when not 0.
	// p_shape other than the rectangle appends "_<shape>" to the id; its exposure integral is that of the
	// shape's silhouette from above approximated by rectangles (disk: the rectangle times pi / 4; sphere:
	// the x by x square times pi / 4; tube: the rectangle plus the y by y square times pi / 4), which
	// only sets the brightness of the scene.
	static Scene make_scene(Receiver p_receiver, float p_roughness, float p_metallic, const Vector2 &p_light_size, Placement p_placement, float p_view_elevation = 0.0f, RS::LightAreaShape p_shape = RS::LIGHT_AREA_SHAPE_RECTANGLE);
	// The shape suite (issue 21): the plane x shapes {disk 1 x 1, sphere of diameter 0.5, tube 1 long and
	// 0.2 thick} x roughness {0.25, 0.5, 1} x metallic {0, 1} x placements {facing, grazing, tilted,
	// close, far} (90 scenes), and its CI subset (6 scenes: each shape diffuse facing and a glossy metal
	// tilted).
	static std::vector<Scene> shape_suite();
	static std::vector<Scene> shape_ci_subset();

	// The full suite: receivers {plane, sphere} x roughness {0.05, 0.1, 0.25, 0.5, 0.75, 1} x metallic
	// {0, 1} x light sizes {0.25 x 0.25, 1 x 1, 4 x 4, 2 x 0.5 (thin 4:1)} x the seven placements, seen by
	// the standard camera; then the view axis: the plane x the same roughness and metallic values x
	// light sizes {1 x 1, 2 x 0.5} x placements {vertical, facing, horizon} x view elevations
	// VIEW_ELEVATIONS.
	static std::vector<Scene> full_suite();
	static constexpr float VIEW_ELEVATIONS[3] = { 5.0f, 10.0f, 20.0f };
	// The CI subset (28 scenes): diffuse-only (roughness 1, metallic 0) in every placement, specular
	// (metallic 1) facing/far/close, rough/glossy dielectrics at grazing, horizon and tilted, and the
	// issue #18 poses: vertical lights over a floor seen at 10 and 20 degrees, a light crossing the
	// plane.
	static std::vector<Scene> ci_subset();

	// The standard camera (view_elevation 0); camera_transform(scene) is the one p_scene uses.
	static Transform3D camera_transform();
	static Transform3D camera_transform(const Scene &p_scene);
	static constexpr float CAMERA_FOVY = 55.0f;

	// Builds p_scene in the current RenderingServer as a p_resolution^2 viewport with shading method
	// p_method. Returns false (r_error set) when the server rejects something (e.g. an unknown method).
	static bool build(RenderingServer *p_rs, const Scene &p_scene, int p_resolution, int p_method, Built *r_built, String *r_error);
	static void free_scene(RenderingServer *p_rs, Built &r_built);

	// Lambert irradiance integral I = integral over the rectangle of cos_i cos_l / r^2 dA at p_point
	// with normal p_normal (one-sided, horizon clipped), midpoint rule with p_n x p_n cells.
	static double irradiance_integral(const Transform3D &p_light, const Vector2 &p_size, const Vector3 &p_point, const Vector3 &p_normal, int p_n = 64);
};
