/**************************************************************************/
/*  camera_3d.h                                                           */
/**************************************************************************/
/* godot-area: a perspective camera (Godot 4.7 names and defaults: fov 75 */
/* degrees, near 0.05, far 4000, keep_aspect KEEP_HEIGHT). It owns one RS */
/* camera RID. Inside a SceneTree the first camera to enter, or the one   */
/* with `current = true`, is attached to the tree's viewport. The camera  */
/* looks down its local -Z with +Y up; scale is ignored.                  */
/* The RS only has perspective cameras: PROJECTION_ORTHOGONAL/FRUSTUM are */
/* stored and used by get_camera_projection(), but render perspective.    */

#pragma once

#include "core/math/projection.h"
#include "scene/3d/node_3d.h"
#include "scene/resources/environment.h"

class Camera3D : public Node3D {
	GDCLASS(Camera3D, Node3D);

public:
	enum ProjectionType {
		PROJECTION_PERSPECTIVE,
		PROJECTION_ORTHOGONAL,
		PROJECTION_FRUSTUM,
	};
	enum KeepAspect {
		KEEP_WIDTH, // fov is horizontal.
		KEEP_HEIGHT, // fov is vertical (Godot's default).
	};

private:
	RID camera;
	ProjectionType projection = PROJECTION_PERSPECTIVE;
	KeepAspect keep_aspect = KEEP_HEIGHT;
	float fov = 75.0f;
	float size = 1.0f;
	float near = 0.05f;
	float far = 4000.0f;
	uint32_t cull_mask = 0xFFFFF; // Layers 1..20, as Godot.
	bool current = false;
	Ref<Environment> environment;

	void _update_camera_projection();
	void _update_camera_transform();

protected:
	static void _bind_methods();
	void _notification(int p_what);

public:
	RID get_camera() const { return camera; }

	void set_projection(ProjectionType p_projection);
	ProjectionType get_projection() const { return projection; }
	void set_keep_aspect_mode(KeepAspect p_aspect);
	KeepAspect get_keep_aspect_mode() const { return keep_aspect; }
	// Degrees, 0 < fov < 180.
	void set_fov(float p_fov_degrees);
	float get_fov() const { return fov; }
	// Orthogonal height in metres, > 0.
	void set_size(float p_size);
	float get_size() const { return size; }
	// Both > 0 and finite. (near < far is not checked here, since scene files set them one by one.)
	void set_near(float p_near);
	float get_near() const { return near; }
	void set_far(float p_far);
	float get_far() const { return far; }
	void set_cull_mask(uint32_t p_layers);
	uint32_t get_cull_mask() const { return cull_mask; }
	void set_environment(const Ref<Environment> &p_environment);
	Ref<Environment> get_environment() const { return environment; }

	// Inside the tree: makes this the viewport's camera (true) or detaches it (false).
	// Outside: remembered and applied on entering.
	void set_current(bool p_current);
	bool is_current() const;
	void make_current() { set_current(true); }
	void clear_current() { set_current(false); }

	// World transform without scale.
	Transform3D get_camera_transform() const;
	// OpenGL-convention projection (depth -1..1) for a viewport of width / height = p_aspect.
	Projection get_camera_projection(real_t p_aspect) const;
	// Vertical field of view in degrees for the given aspect (applies keep_aspect).
	float get_vertical_fov(real_t p_aspect) const;
	// World-space unit direction through pixel p_pos of a p_viewport_size viewport
	// (top-left origin). Perspective only.
	Vector3 project_ray_normal(const Vector2 &p_pos, const Vector2 &p_viewport_size) const;

	// Called by SceneTree when its size changes (KEEP_WIDTH depends on the aspect).
	void _viewport_size_changed() { _update_camera_projection(); }

	Camera3D();
	~Camera3D() override;
};

VARIANT_ENUM_CAST(Camera3D::ProjectionType);
VARIANT_ENUM_CAST(Camera3D::KeepAspect);
