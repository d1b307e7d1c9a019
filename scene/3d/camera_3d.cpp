/**************************************************************************/
/*  camera_3d.cpp                                                         */
/**************************************************************************/

#include "scene/3d/camera_3d.h"

#include "core/error/error_macros.h"
#include "scene/main/scene_tree.h"
#include "servers/rendering_server.h"

#include <cmath>

float Camera3D::get_vertical_fov(real_t p_aspect) const {
	if (keep_aspect == KEEP_HEIGHT || !(p_aspect > 0)) {
		return fov;
	}
	// fov is horizontal: tan(fovy / 2) = tan(fovx / 2) / aspect.
	float half = std::atan(std::tan(Math::deg_to_rad(fov) * 0.5f) / p_aspect);
	return Math::rad_to_deg(half * 2.0f);
}

void Camera3D::_update_camera_projection() {
	RS *rs = RS::get_singleton();
	if (!rs || !camera.is_valid()) {
		return;
	}
	if (!(near < far)) {
		WARN_PRINT(vformat("Camera3D \"%s\": near (%s) must be smaller than far (%s); the projection is not updated.", get_name().c_str(), rtos(near).c_str(), rtos(far).c_str()));
		return;
	}
	float aspect = 0.0f;
	SceneTree *t = get_tree();
	if (t && t->get_height() > 0) {
		aspect = float(t->get_width()) / float(t->get_height());
	}
	rs->camera_set_perspective(camera, get_vertical_fov(aspect), near, far);
}

void Camera3D::_update_camera_transform() {
	RS *rs = RS::get_singleton();
	if (rs && camera.is_valid()) {
		rs->camera_set_transform(camera, get_camera_transform());
	}
}

void Camera3D::set_projection(ProjectionType p_projection) {
	ERR_FAIL_INDEX_MSG((int)p_projection, 3, vformat("Camera3D projection must be 0..2 (Perspective, Orthogonal, Frustum); got %d. The old value is kept.", (int)p_projection));
	if (p_projection != PROJECTION_PERSPECTIVE) {
		WARN_PRINT_ONCE("Camera3D: only PROJECTION_PERSPECTIVE is rendered; other projections are stored but drawn in perspective.");
	}
	projection = p_projection;
	notify_property_list_changed();
}

void Camera3D::set_keep_aspect_mode(KeepAspect p_aspect) {
	ERR_FAIL_INDEX_MSG((int)p_aspect, 2, vformat("Camera3D keep_aspect must be 0 (Keep Width) or 1 (Keep Height); got %d. The old value is kept.", (int)p_aspect));
	keep_aspect = p_aspect;
	_update_camera_projection();
}

void Camera3D::set_fov(float p_fov_degrees) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_fov_degrees) || p_fov_degrees <= 0.0f || p_fov_degrees >= 180.0f, vformat("Camera3D fov must be between 0 and 180 degrees, exclusive (got %s); the old value is kept.", rtos(p_fov_degrees).c_str()));
	fov = p_fov_degrees;
	_update_camera_projection();
}

void Camera3D::set_size(float p_size) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_size) || p_size <= 0.0f, vformat("Camera3D size must be finite and > 0 (got %s); the old value is kept.", rtos(p_size).c_str()));
	size = p_size;
}

void Camera3D::set_near(float p_near) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_near) || p_near <= 0.0f, vformat("Camera3D near must be finite and > 0 (got %s); the old value is kept.", rtos(p_near).c_str()));
	near = p_near;
	_update_camera_projection();
}

void Camera3D::set_far(float p_far) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_far) || p_far <= 0.0f, vformat("Camera3D far must be finite and > 0 (got %s); the old value is kept.", rtos(p_far).c_str()));
	far = p_far;
	_update_camera_projection();
}

void Camera3D::set_cull_mask(uint32_t p_layers) {
	cull_mask = p_layers;
	RS *rs = RS::get_singleton();
	if (rs && camera.is_valid()) {
		rs->camera_set_cull_mask(camera, cull_mask);
	}
}

void Camera3D::set_environment(const Ref<Environment> &p_environment) {
	environment = p_environment;
	RS *rs = RS::get_singleton();
	if (rs && camera.is_valid()) {
		rs->camera_set_environment(camera, environment.is_valid() ? environment->get_rid() : RID());
	}
}

void Camera3D::set_current(bool p_current) {
	current = p_current;
	SceneTree *t = get_tree();
	if (!t) {
		return;
	}
	if (p_current) {
		Camera3D *old = t->get_camera_3d();
		if (old && old != this) {
			old->current = false;
		}
		t->_camera_set(this);
	} else if (t->get_camera_3d() == this) {
		t->_camera_set(nullptr);
	}
}

bool Camera3D::is_current() const {
	SceneTree *t = get_tree();
	return t ? t->get_camera_3d() == this : current;
}

Transform3D Camera3D::get_camera_transform() const {
	return get_global_transform().orthonormalized();
}

Projection Camera3D::get_camera_projection(real_t p_aspect) const {
	ERR_FAIL_COND_V_MSG(!(p_aspect > 0) || !Math::is_finite(p_aspect), Projection(), vformat("Camera3D::get_camera_projection(): aspect must be finite and > 0 (got %s).", rtos(p_aspect).c_str()));
	if (projection == PROJECTION_ORTHOGONAL) {
		real_t half_h = keep_aspect == KEEP_HEIGHT ? size * 0.5f : size * 0.5f / p_aspect;
		real_t half_w = half_h * p_aspect;
		return Projection::create_orthogonal(-half_w, half_w, -half_h, half_h, near, far);
	}
	return Projection::create_perspective(get_vertical_fov(p_aspect), p_aspect, near, far);
}

Vector3 Camera3D::project_ray_normal(const Vector2 &p_pos, const Vector2 &p_viewport_size) const {
	ERR_FAIL_COND_V_MSG(!(p_viewport_size.x > 0) || !(p_viewport_size.y > 0), Vector3(0, 0, -1), "Camera3D::project_ray_normal(): the viewport size must be positive.");
	real_t aspect = p_viewport_size.x / p_viewport_size.y;
	real_t tan_y = std::tan(Math::deg_to_rad(get_vertical_fov(aspect)) * 0.5f);
	real_t ndc_x = 2.0f * p_pos.x / p_viewport_size.x - 1.0f;
	real_t ndc_y = 1.0f - 2.0f * p_pos.y / p_viewport_size.y;
	Vector3 local(ndc_x * tan_y * aspect, ndc_y * tan_y, -1.0f);
	return get_camera_transform().basis.xform(local).normalized();
}

void Camera3D::_notification(int p_what) {
	switch (p_what) {
		case NOTIFICATION_ENTER_WORLD: {
			_update_camera_transform();
			_update_camera_projection();
			SceneTree *t = get_tree();
			// As Godot's Viewport: the first camera becomes current, and `current = true` wins.
			if (t && (current || t->get_camera_3d() == nullptr)) {
				set_current(true);
			}
		} break;
		case NOTIFICATION_TRANSFORM_CHANGED: {
			_update_camera_transform();
		} break;
		case NOTIFICATION_EXIT_WORLD: {
			SceneTree *t = get_tree();
			if (t && t->get_camera_3d() == this) {
				bool keep = current;
				t->_camera_set(nullptr);
				current = keep;
			}
		} break;
	}
}

void Camera3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_projection", "mode"), &Camera3D::set_projection);
	ClassDB::bind_method(D_METHOD("get_projection"), &Camera3D::get_projection);
	ClassDB::bind_method(D_METHOD("set_keep_aspect_mode", "mode"), &Camera3D::set_keep_aspect_mode);
	ClassDB::bind_method(D_METHOD("get_keep_aspect_mode"), &Camera3D::get_keep_aspect_mode);
	ClassDB::bind_method(D_METHOD("set_fov", "fov"), &Camera3D::set_fov);
	ClassDB::bind_method(D_METHOD("get_fov"), &Camera3D::get_fov);
	ClassDB::bind_method(D_METHOD("set_size", "size"), &Camera3D::set_size);
	ClassDB::bind_method(D_METHOD("get_size"), &Camera3D::get_size);
	ClassDB::bind_method(D_METHOD("set_near", "near"), &Camera3D::set_near);
	ClassDB::bind_method(D_METHOD("get_near"), &Camera3D::get_near);
	ClassDB::bind_method(D_METHOD("set_far", "far"), &Camera3D::set_far);
	ClassDB::bind_method(D_METHOD("get_far"), &Camera3D::get_far);
	ClassDB::bind_method(D_METHOD("set_cull_mask", "mask"), &Camera3D::set_cull_mask);
	ClassDB::bind_method(D_METHOD("get_cull_mask"), &Camera3D::get_cull_mask);
	ClassDB::bind_method(D_METHOD("set_environment", "env"), &Camera3D::set_environment);
	ClassDB::bind_method(D_METHOD("get_environment"), &Camera3D::get_environment);
	ClassDB::bind_method(D_METHOD("set_current", "enabled"), &Camera3D::set_current);
	ClassDB::bind_method(D_METHOD("is_current"), &Camera3D::is_current);
	ClassDB::bind_method(D_METHOD("make_current"), &Camera3D::make_current);
	ClassDB::bind_method(D_METHOD("clear_current"), &Camera3D::clear_current);

	ADD_PROPERTY(PropertyInfo(Variant::INT, "keep_aspect", PROPERTY_HINT_ENUM, "Keep Width,Keep Height"), "set_keep_aspect_mode", "get_keep_aspect_mode");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "cull_mask", PROPERTY_HINT_LAYERS_3D_RENDER), "set_cull_mask", "get_cull_mask");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "environment", PROPERTY_HINT_RESOURCE_TYPE, "Environment"), "set_environment", "get_environment");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "projection", PROPERTY_HINT_ENUM, "Perspective,Orthogonal,Frustum"), "set_projection", "get_projection");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "current"), "set_current", "is_current");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "fov", PROPERTY_HINT_RANGE, "1,179,0.1,degrees"), "set_fov", "get_fov");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "size", PROPERTY_HINT_RANGE, "0.001,100,0.001,or_greater,suffix:m"), "set_size", "get_size");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "near", PROPERTY_HINT_RANGE, "0.001,10,0.001,or_greater,exp,suffix:m"), "set_near", "get_near");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "far", PROPERTY_HINT_RANGE, "0.01,4000,0.01,or_greater,exp,suffix:m"), "set_far", "get_far");

	BIND_ENUM_CONSTANT(PROJECTION_PERSPECTIVE);
	BIND_ENUM_CONSTANT(PROJECTION_ORTHOGONAL);
	BIND_ENUM_CONSTANT(PROJECTION_FRUSTUM);
	BIND_ENUM_CONSTANT(KEEP_WIDTH);
	BIND_ENUM_CONSTANT(KEEP_HEIGHT);
}

Camera3D::Camera3D() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "Camera3D needs a RenderingServer; create one before the scene.");
	camera = rs->camera_create();
	rs->camera_set_perspective(camera, fov, near, far);
	rs->camera_set_cull_mask(camera, cull_mask);
}

Camera3D::~Camera3D() {
	SceneTree *t = get_tree();
	if (t && t->get_camera_3d() == this) {
		t->_camera_set(nullptr);
	}
	RS *rs = RS::get_singleton();
	if (rs && camera.is_valid()) {
		rs->free(camera);
	}
}
