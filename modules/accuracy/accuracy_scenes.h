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
		PLACEMENT_MAX,
	};

	struct Scene {
		String id; // e.g. "plane_r0.25_m1_1x1_facing".
		Receiver receiver = RECEIVER_PLANE;
		float roughness = 0.5f;
		float metallic = 0.0f;
		Vector2 light_size = Vector2(1, 1);
		Placement placement = PLACEMENT_FACING;
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

	// Fills the derived fields (transform, energy, range) and the id.
	static Scene make_scene(Receiver p_receiver, float p_roughness, float p_metallic, const Vector2 &p_light_size, Placement p_placement);

	// The full suite: receivers {plane, sphere} x roughness {0.05, 0.1, 0.25, 0.5, 0.75, 1} x metallic
	// {0, 1} x light sizes {0.25 x 0.25, 1 x 1, 4 x 4, 2 x 0.5 (thin 4:1)} x the six placements.
	static std::vector<Scene> full_suite();
	// The CI subset (22 scenes): diffuse-only (roughness 1, metallic 0) in every placement, specular
	// (metallic 1) facing/far/close, and rough/glossy dielectrics at grazing, horizon and tilted.
	static std::vector<Scene> ci_subset();

	// The camera every scene uses (pixel centres identical for both backends).
	static Transform3D camera_transform();
	static constexpr float CAMERA_FOVY = 55.0f;

	// Builds p_scene in the current RenderingServer as a p_resolution^2 viewport with shading method
	// p_method. Returns false (r_error set) when the server rejects something (e.g. an unknown method).
	static bool build(RenderingServer *p_rs, const Scene &p_scene, int p_resolution, int p_method, Built *r_built, String *r_error);
	static void free_scene(RenderingServer *p_rs, Built &r_built);

	// Lambert irradiance integral I = integral over the rectangle of cos_i cos_l / r^2 dA at p_point
	// with normal p_normal (one-sided, horizon clipped), midpoint rule with p_n x p_n cells.
	static double irradiance_integral(const Transform3D &p_light, const Vector2 &p_size, const Vector3 &p_point, const Vector3 &p_normal, int p_n = 64);
};
