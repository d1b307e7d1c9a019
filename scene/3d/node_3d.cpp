/**************************************************************************/
/*  node_3d.cpp                                                           */
/**************************************************************************/

#include "scene/3d/node_3d.h"

#include "core/error/error_macros.h"
#include "scene/main/scene_tree.h"

#include <cmath>

// Local scale: the basis is rotation * scale (columns scaled), so scale is along the node's own axes.

Vector3 Node3D::basis_get_euler_yxz(const Basis &p_basis) {
	// R = Ry * Rx * Rz gives m12 = -sin(x), m02 = sin(y)cos(x), m22 = cos(y)cos(x),
	// m10 = cos(x)sin(z), m11 = cos(x)cos(z). At the poles (cos(x) = 0) z is set to 0 and
	// y is read from m00 = cos(y), m20 = -sin(y).
	Basis m = p_basis.orthonormalized();
	real_t sx = -m.rows[1][2];
	if (sx >= real_t(1) - real_t(CMP_EPSILON)) {
		return Vector3(real_t(Math::PI / 2), std::atan2(-m.rows[2][0], m.rows[0][0]), 0);
	}
	if (sx <= real_t(-1) + real_t(CMP_EPSILON)) {
		return Vector3(real_t(-Math::PI / 2), std::atan2(-m.rows[2][0], m.rows[0][0]), 0);
	}
	return Vector3(std::asin(sx), std::atan2(m.rows[0][2], m.rows[2][2]), std::atan2(m.rows[1][0], m.rows[1][1]));
}

Node3D *Node3D::_get_parent_node_3d() const {
	return Object::cast_to<Node3D>(get_parent());
}

void Node3D::_update_rotation_scale() const {
	if (!rotation_scale_dirty) {
		return;
	}
	const Basis &b = local_transform.basis;
	scale = b.get_scale();
	if (b.determinant() < 0) {
		// A mirrored basis: put the reflection in the scale so rotation stays a rotation.
		scale = -scale;
	}
	Basis unscaled = Basis::from_columns(b.get_column(0) / (scale.x == 0 ? 1 : scale.x), b.get_column(1) / (scale.y == 0 ? 1 : scale.y), b.get_column(2) / (scale.z == 0 ? 1 : scale.z));
	rotation = basis_get_euler_yxz(unscaled);
	rotation_scale_dirty = false;
}

void Node3D::_propagate_transform_changed() {
	global_dirty = true;
	for (int i = 0; i < get_child_count(); i++) {
		Node3D *child = Object::cast_to<Node3D>(get_child(i));
		if (child) {
			child->_propagate_transform_changed();
		}
	}
	if (is_inside_tree()) {
		notification(NOTIFICATION_TRANSFORM_CHANGED);
	}
}

void Node3D::_propagate_visibility_changed() {
	if (is_inside_tree()) {
		notification(NOTIFICATION_VISIBILITY_CHANGED);
	}
	for (int i = 0; i < get_child_count(); i++) {
		Node3D *child = Object::cast_to<Node3D>(get_child(i));
		if (child && child->visible) {
			child->_propagate_visibility_changed();
		}
	}
}

void Node3D::set_transform(const Transform3D &p_transform) {
	ERR_FAIL_COND_MSG(!p_transform.is_finite(), vformat("Node3D \"%s\": transform must be finite (no NaN or infinity); the old value is kept.", get_name().c_str()));
	local_transform = p_transform;
	rotation_scale_dirty = true;
	_propagate_transform_changed();
	if (is_inside_tree()) {
		notification(NOTIFICATION_LOCAL_TRANSFORM_CHANGED);
	}
}

void Node3D::set_position(const Vector3 &p_position) {
	ERR_FAIL_COND_MSG(!p_position.is_finite(), vformat("Node3D \"%s\": position must be finite; the old value is kept.", get_name().c_str()));
	Transform3D t = local_transform;
	t.origin = p_position;
	bool keep = !rotation_scale_dirty;
	set_transform(t);
	rotation_scale_dirty = !keep;
}

void Node3D::set_rotation(const Vector3 &p_euler_radians) {
	ERR_FAIL_COND_MSG(!p_euler_radians.is_finite(), vformat("Node3D \"%s\": rotation must be finite; the old value is kept.", get_name().c_str()));
	_update_rotation_scale();
	Vector3 s = scale;
	set_transform(Transform3D(Basis::from_euler(p_euler_radians) * Basis::from_scale(s), local_transform.origin));
	rotation = p_euler_radians;
	scale = s;
	rotation_scale_dirty = false;
}

Vector3 Node3D::get_rotation() const {
	_update_rotation_scale();
	return rotation;
}

void Node3D::set_rotation_degrees(const Vector3 &p_euler_degrees) {
	set_rotation(Vector3(Math::deg_to_rad(p_euler_degrees.x), Math::deg_to_rad(p_euler_degrees.y), Math::deg_to_rad(p_euler_degrees.z)));
}

Vector3 Node3D::get_rotation_degrees() const {
	Vector3 r = get_rotation();
	return Vector3(Math::rad_to_deg(r.x), Math::rad_to_deg(r.y), Math::rad_to_deg(r.z));
}

void Node3D::set_scale(const Vector3 &p_scale) {
	ERR_FAIL_COND_MSG(!p_scale.is_finite(), vformat("Node3D \"%s\": scale must be finite; the old value is kept.", get_name().c_str()));
	_update_rotation_scale();
	Vector3 r = rotation;
	set_transform(Transform3D(Basis::from_euler(r) * Basis::from_scale(p_scale), local_transform.origin));
	rotation = r;
	scale = p_scale;
	rotation_scale_dirty = false;
}

Vector3 Node3D::get_scale() const {
	_update_rotation_scale();
	return scale;
}

Transform3D Node3D::get_global_transform() const {
	if (global_dirty) {
		const Node3D *p = _get_parent_node_3d();
		global_transform = p ? p->get_global_transform() * local_transform : local_transform;
		global_dirty = false;
	}
	return global_transform;
}

void Node3D::set_global_transform(const Transform3D &p_transform) {
	ERR_FAIL_COND_MSG(!p_transform.is_finite(), vformat("Node3D \"%s\": global_transform must be finite; the old value is kept.", get_name().c_str()));
	const Node3D *p = _get_parent_node_3d();
	set_transform(p ? p->get_global_transform().affine_inverse() * p_transform : p_transform);
}

void Node3D::set_global_position(const Vector3 &p_position) {
	Transform3D t = get_global_transform();
	t.origin = p_position;
	set_global_transform(t);
}

void Node3D::look_at(const Vector3 &p_target, const Vector3 &p_up) {
	Transform3D g = get_global_transform();
	Vector3 dir = p_target - g.origin;
	ERR_FAIL_COND_MSG(dir.length_squared() < real_t(CMP_EPSILON * CMP_EPSILON), vformat("Node3D \"%s\": look_at() target is at the node's own position.", get_name().c_str()));
	ERR_FAIL_COND_MSG(dir.normalized().cross(p_up.normalized()).length_squared() < real_t(CMP_EPSILON), vformat("Node3D \"%s\": look_at() up vector is parallel to the view direction.", get_name().c_str()));
	Vector3 s = g.basis.get_scale();
	set_global_transform(Transform3D(Basis::looking_at(dir, p_up) * Basis::from_scale(s), g.origin));
}

void Node3D::rotate(const Vector3 &p_axis, real_t p_angle) {
	ERR_FAIL_COND_MSG(p_axis.length_squared() < real_t(CMP_EPSILON), vformat("Node3D \"%s\": rotate() needs a non-zero axis.", get_name().c_str()));
	Transform3D t = get_transform();
	t.basis = Basis::from_axis_angle(p_axis.normalized(), p_angle) * t.basis;
	set_transform(t);
}

void Node3D::rotate_object_local(const Vector3 &p_axis, real_t p_angle) {
	ERR_FAIL_COND_MSG(p_axis.length_squared() < real_t(CMP_EPSILON), vformat("Node3D \"%s\": rotate_object_local() needs a non-zero axis.", get_name().c_str()));
	Transform3D t = get_transform();
	t.basis = t.basis * Basis::from_axis_angle(p_axis.normalized(), p_angle);
	set_transform(t);
}

void Node3D::scale_object_local(const Vector3 &p_scale) {
	Transform3D t = get_transform();
	t.basis = t.basis * Basis::from_scale(p_scale);
	set_transform(t);
}

void Node3D::translate(const Vector3 &p_offset) {
	Transform3D t = get_transform();
	t.origin = t.origin + t.basis.xform(p_offset);
	set_transform(t);
}

void Node3D::global_translate(const Vector3 &p_offset) {
	Transform3D g = get_global_transform();
	g.origin = g.origin + p_offset;
	set_global_transform(g);
}

void Node3D::set_visible(bool p_visible) {
	if (visible == p_visible) {
		return;
	}
	visible = p_visible;
	_propagate_visibility_changed();
}

bool Node3D::is_visible_in_tree() const {
	for (const Node3D *n = this; n; n = n->_get_parent_node_3d()) {
		if (!n->visible) {
			return false;
		}
	}
	return true;
}

Ref<World3D> Node3D::get_world_3d() const {
	SceneTree *t = get_tree();
	return t ? t->get_world_3d() : Ref<World3D>();
}

void Node3D::_notification(int p_what) {
	switch (p_what) {
		case NOTIFICATION_ENTER_TREE: {
			// The parent chain may be new: recompute the global transform lazily.
			global_dirty = true;
			notification(NOTIFICATION_ENTER_WORLD);
		} break;
		case NOTIFICATION_EXIT_TREE: {
			notification(NOTIFICATION_EXIT_WORLD, true);
			global_dirty = true;
		} break;
		case NOTIFICATION_PARENTED:
		case NOTIFICATION_UNPARENTED: {
			// The whole subtree's cached global transforms depend on the new parent chain.
			_propagate_transform_changed();
		} break;
	}
}

void Node3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_transform", "local"), &Node3D::set_transform);
	ClassDB::bind_method(D_METHOD("get_transform"), &Node3D::get_transform);
	ClassDB::bind_method(D_METHOD("set_position", "position"), &Node3D::set_position);
	ClassDB::bind_method(D_METHOD("get_position"), &Node3D::get_position);
	ClassDB::bind_method(D_METHOD("set_rotation", "euler_radians"), &Node3D::set_rotation);
	ClassDB::bind_method(D_METHOD("get_rotation"), &Node3D::get_rotation);
	ClassDB::bind_method(D_METHOD("set_rotation_degrees", "euler_degrees"), &Node3D::set_rotation_degrees);
	ClassDB::bind_method(D_METHOD("get_rotation_degrees"), &Node3D::get_rotation_degrees);
	ClassDB::bind_method(D_METHOD("set_scale", "scale"), &Node3D::set_scale);
	ClassDB::bind_method(D_METHOD("get_scale"), &Node3D::get_scale);
	ClassDB::bind_method(D_METHOD("set_global_transform", "global"), &Node3D::set_global_transform);
	ClassDB::bind_method(D_METHOD("get_global_transform"), &Node3D::get_global_transform);
	ClassDB::bind_method(D_METHOD("set_global_position", "position"), &Node3D::set_global_position);
	ClassDB::bind_method(D_METHOD("get_global_position"), &Node3D::get_global_position);
	ClassDB::bind_method(D_METHOD("set_visible", "visible"), &Node3D::set_visible);
	ClassDB::bind_method(D_METHOD("is_visible"), &Node3D::is_visible);
	ClassDB::bind_method(D_METHOD("is_visible_in_tree"), &Node3D::is_visible_in_tree);
	ClassDB::bind_method(D_METHOD("look_at", "target", "up"), &Node3D::look_at, DEFVAL(Vector3(0, 1, 0)));
	ClassDB::bind_method(D_METHOD("rotate", "axis", "angle"), &Node3D::rotate);
	ClassDB::bind_method(D_METHOD("rotate_x", "angle"), &Node3D::rotate_x);
	ClassDB::bind_method(D_METHOD("rotate_y", "angle"), &Node3D::rotate_y);
	ClassDB::bind_method(D_METHOD("rotate_z", "angle"), &Node3D::rotate_z);
	ClassDB::bind_method(D_METHOD("rotate_object_local", "axis", "angle"), &Node3D::rotate_object_local);
	ClassDB::bind_method(D_METHOD("scale_object_local", "scale"), &Node3D::scale_object_local);
	ClassDB::bind_method(D_METHOD("translate", "offset"), &Node3D::translate);
	ClassDB::bind_method(D_METHOD("translate_object_local", "offset"), &Node3D::translate_object_local);
	ClassDB::bind_method(D_METHOD("global_translate", "offset"), &Node3D::global_translate);
	ClassDB::bind_method(D_METHOD("to_global", "local_point"), &Node3D::to_global);
	ClassDB::bind_method(D_METHOD("to_local", "global_point"), &Node3D::to_local);
	ClassDB::bind_method(D_METHOD("show"), &Node3D::show);
	ClassDB::bind_method(D_METHOD("hide"), &Node3D::hide);

	// Godot 4 order and usages: only `transform` is saved; the editor edits the views.
	ADD_GROUP("Transform", "");
	ADD_PROPERTY(PropertyInfo(Variant::TRANSFORM3D, "transform", PROPERTY_HINT_NONE, "suffix:m", PROPERTY_USAGE_NO_EDITOR), "set_transform", "get_transform");
	ADD_PROPERTY(PropertyInfo(Variant::TRANSFORM3D, "global_transform", PROPERTY_HINT_NONE, "suffix:m", PROPERTY_USAGE_NONE), "set_global_transform", "get_global_transform");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "position", PROPERTY_HINT_RANGE, "-99999,99999,0.001,or_greater,or_less,hide_slider,suffix:m", PROPERTY_USAGE_EDITOR), "set_position", "get_position");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "rotation", PROPERTY_HINT_RANGE, "-360,360,0.1,or_less,or_greater,radians_as_degrees", PROPERTY_USAGE_EDITOR), "set_rotation", "get_rotation");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "rotation_degrees", PROPERTY_HINT_NONE, "", PROPERTY_USAGE_NONE), "set_rotation_degrees", "get_rotation_degrees");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "scale", PROPERTY_HINT_LINK, "", PROPERTY_USAGE_EDITOR), "set_scale", "get_scale");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "global_position", PROPERTY_HINT_NONE, "suffix:m", PROPERTY_USAGE_NONE), "set_global_position", "get_global_position");
	ADD_GROUP("Visibility", "");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "visible"), "set_visible", "is_visible");
	ADD_GROUP("", "");

	BIND_CONSTANT(NOTIFICATION_TRANSFORM_CHANGED);
	BIND_CONSTANT(NOTIFICATION_ENTER_WORLD);
	BIND_CONSTANT(NOTIFICATION_EXIT_WORLD);
	BIND_CONSTANT(NOTIFICATION_VISIBILITY_CHANGED);
	BIND_CONSTANT(NOTIFICATION_LOCAL_TRANSFORM_CHANGED);
}

Node3D::Node3D() {}
