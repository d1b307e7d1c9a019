/**************************************************************************/
/*  node_3d.h                                                             */
/**************************************************************************/
/* godot-area: a node with a 3D transform. The local `transform` is the   */
/* saved property (scene files hold `transform = Transform3D(...)`);      */
/* position / rotation (radians, YXZ Euler as Godot) / scale are views of */
/* it. The global transform is the chain of Node3D ancestors' transforms; */
/* a non-Node3D parent breaks the chain (the node acts as top level).     */
/*                                                                        */
/* Changing a transform marks this node and its Node3D descendants dirty  */
/* and, inside the tree, sends them NOTIFICATION_TRANSFORM_CHANGED at     */
/* once (Godot defers this to the end of the frame; we have no frames).   */

#pragma once

#include "core/math/transform_3d.h"
#include "scene/main/node.h"
#include "scene/resources/world_3d.h"

class Node3D : public Node {
	GDCLASS(Node3D, Node);

	Transform3D local_transform;
	// Cached decomposition, so rotation/scale read back exactly what was set.
	mutable Vector3 rotation;
	mutable Vector3 scale = Vector3(1, 1, 1);
	mutable bool rotation_scale_dirty = false;
	mutable Transform3D global_transform;
	mutable bool global_dirty = true;
	bool visible = true;

	Node3D *_get_parent_node_3d() const;
	void _update_rotation_scale() const;
	void _propagate_transform_changed();
	void _propagate_visibility_changed();

protected:
	static void _bind_methods();
	void _notification(int p_what);

public:
	enum {
		// Values follow Godot's Node3D notifications.
		NOTIFICATION_TRANSFORM_CHANGED = 2000,
		NOTIFICATION_ENTER_WORLD = 41,
		NOTIFICATION_EXIT_WORLD = 42,
		NOTIFICATION_VISIBILITY_CHANGED = 43,
		NOTIFICATION_LOCAL_TRANSFORM_CHANGED = 44,
	};

	// Non-finite transforms are rejected with a message (the old value is kept).
	void set_transform(const Transform3D &p_transform);
	Transform3D get_transform() const { return local_transform; }
	void set_position(const Vector3 &p_position);
	Vector3 get_position() const { return local_transform.origin; }
	// Radians, YXZ order (Basis::from_euler).
	void set_rotation(const Vector3 &p_euler_radians);
	Vector3 get_rotation() const;
	void set_rotation_degrees(const Vector3 &p_euler_degrees);
	Vector3 get_rotation_degrees() const;
	void set_scale(const Vector3 &p_scale);
	Vector3 get_scale() const;

	void set_global_transform(const Transform3D &p_transform);
	Transform3D get_global_transform() const;
	void set_global_position(const Vector3 &p_position);
	Vector3 get_global_position() const { return get_global_transform().origin; }

	// Rotates so that local -Z points at p_target (global), +Y towards p_up.
	void look_at(const Vector3 &p_target, const Vector3 &p_up = Vector3(0, 1, 0));

	// Godot's Node3D helpers. Rotations are about the parent's axes (rotate, rotate_x/y/z) or
	// the node's own axes (rotate_object_local); translate moves along the node's own axes,
	// global_translate along the world's. Angles in radians.
	void rotate(const Vector3 &p_axis, real_t p_angle);
	void rotate_x(real_t p_angle) { rotate(Vector3(1, 0, 0), p_angle); }
	void rotate_y(real_t p_angle) { rotate(Vector3(0, 1, 0), p_angle); }
	void rotate_z(real_t p_angle) { rotate(Vector3(0, 0, 1), p_angle); }
	void rotate_object_local(const Vector3 &p_axis, real_t p_angle);
	void scale_object_local(const Vector3 &p_scale);
	void translate(const Vector3 &p_offset);
	void translate_object_local(const Vector3 &p_offset) { translate(p_offset); }
	void global_translate(const Vector3 &p_offset);
	// A point from this node's local space to global space and back.
	Vector3 to_global(const Vector3 &p_local_point) const { return get_global_transform().xform(p_local_point); }
	Vector3 to_local(const Vector3 &p_global_point) const { return get_global_transform().affine_inverse().xform(p_global_point); }

	void set_visible(bool p_visible);
	bool is_visible() const { return visible; }
	// Visible and every Node3D ancestor visible.
	bool is_visible_in_tree() const;
	void show() { set_visible(true); }
	void hide() { set_visible(false); }

	// The World3D of this node's SceneTree (null outside the tree).
	Ref<World3D> get_world_3d() const;

	// YXZ Euler angles (radians) of a rotation basis (scale is removed first).
	static Vector3 basis_get_euler_yxz(const Basis &p_basis);

	Node3D();
};
