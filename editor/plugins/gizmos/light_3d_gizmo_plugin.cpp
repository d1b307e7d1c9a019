/**************************************************************************/
/*  light_3d_gizmo_plugin.cpp                                             */
/**************************************************************************/
/* godot-area: Light3DGizmoPlugin (see the header).                       */

#include "editor/plugins/gizmos/light_3d_gizmo_plugin.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "scene/3d/camera_3d.h"
#include "scene/3d/light_3d.h"

#include <algorithm>
#include <cmath>

const char *Light3DGizmoPlugin::ICON_DIRECTIONAL = "editor/icons/GizmoDirectionalLight.svg";
const char *Light3DGizmoPlugin::ICON_OMNI = "editor/icons/GizmoLight.svg";
const char *Light3DGizmoPlugin::ICON_SPOT = "editor/icons/GizmoSpotLight.svg";
const char *Light3DGizmoPlugin::ICON_AREA = "editor/icons/GizmoAreaLight.svg";

// Segments of a full circle in the gizmo lines (only affects smoothness).
static const int CIRCLE_SEGMENTS = 64;
// Screen scale of the billboard icons (Godot's light gizmo passes 0.05).
static const real_t ICON_SCALE = 0.05;

Light3DGizmoPlugin::Light3DGizmoPlugin() {
	create_material("lights_material", Color(1, 1, 1, 1));
	create_material("lights_billboard_material", Color(1, 1, 1, 1), true);
	create_icon_material("light_directional_icon", ICON_DIRECTIONAL);
	create_icon_material("light_omni_icon", ICON_OMNI);
	create_icon_material("light_spot_icon", ICON_SPOT);
	create_icon_material("light_area_icon", ICON_AREA);
	create_handle_material("handles");
	create_handle_material("handles_billboard", true);
}

bool Light3DGizmoPlugin::has_gizmo(Node3D *p_node) {
	return Object::cast_to<Light3D>(p_node) != nullptr;
}

Color Light3DGizmoPlugin::get_gizmo_color(const Light3D *p_light) {
	ERR_FAIL_NULL_V_MSG(p_light, Color(1, 1, 1, 1), "Light3DGizmoPlugin::get_gizmo_color(): the light is null.");
	const Color c = p_light->get_color();
	const float v = std::max(c.r, std::max(c.g, c.b));
	if (!(v > 0.0f) || !Math::is_finite(v)) {
		return Color(1, 1, 1, 1);
	}
	// Dividing by the largest channel keeps hue and saturation and sets the HSV value to 1.
	return Color(std::max(c.r, 0.0f) / v, std::max(c.g, 0.0f) / v, std::max(c.b, 0.0f) / v, 1.0f);
}

std::vector<Vector3> Light3DGizmoPlugin::get_area_outline(const Vector2 &p_size) {
	const real_t a = p_size.x * real_t(0.5);
	const real_t b = p_size.y * real_t(0.5);
	const Vector3 corners[4] = { Vector3(-a, b, 0), Vector3(a, b, 0), Vector3(a, -b, 0), Vector3(-a, -b, 0) };
	std::vector<Vector3> points;
	for (int i = 0; i < 4; i++) {
		points.push_back(corners[i]);
		points.push_back(corners[(i + 1) % 4]);
	}
	return points;
}

// Line pairs of the arc p_centre + p_u cos t + p_v sin t for t in [p_t0, p_t1], p_segments segments.
static void _add_arc(std::vector<Vector3> &r_points, const Vector3 &p_centre, const Vector3 &p_u, const Vector3 &p_v, real_t p_t0, real_t p_t1, int p_segments) {
	for (int i = 0; i < p_segments; i++) {
		const real_t a = p_t0 + (p_t1 - p_t0) * real_t(i) / p_segments;
		const real_t b = p_t0 + (p_t1 - p_t0) * real_t(i + 1) / p_segments;
		r_points.push_back(p_centre + p_u * std::cos(a) + p_v * std::sin(a));
		r_points.push_back(p_centre + p_u * std::cos(b) + p_v * std::sin(b));
	}
}

std::vector<Vector3> Light3DGizmoPlugin::get_area_shape_outline(int p_shape, const Vector2 &p_size) {
	const real_t tau = real_t(Math::PI) * 2;
	std::vector<Vector3> points;
	switch (p_shape) {
		case RS::LIGHT_AREA_SHAPE_DISK:
			_add_arc(points, Vector3(), Vector3(p_size.x * real_t(0.5), 0, 0), Vector3(0, p_size.y * real_t(0.5), 0), 0, tau, 32);
			break;
		case RS::LIGHT_AREA_SHAPE_SPHERE: {
			const real_t r = p_size.x * real_t(0.5);
			_add_arc(points, Vector3(), Vector3(r, 0, 0), Vector3(0, r, 0), 0, tau, 32);
			_add_arc(points, Vector3(), Vector3(r, 0, 0), Vector3(0, 0, r), 0, tau, 32);
			_add_arc(points, Vector3(), Vector3(0, r, 0), Vector3(0, 0, r), 0, tau, 32);
		} break;
		case RS::LIGHT_AREA_SHAPE_TUBE: {
			const real_t h = p_size.x * real_t(0.5);
			const real_t r = p_size.y * real_t(0.5);
			const Vector3 ends[2] = { Vector3(-h, 0, 0), Vector3(h, 0, 0) };
			for (int e = 0; e < 2; e++) {
				_add_arc(points, ends[e], Vector3(0, r, 0), Vector3(0, 0, r), 0, tau, 24);
				// The cap: half circles in the XY and XZ planes, bulging outwards.
				const Vector3 out(e == 0 ? -r : r, 0, 0);
				_add_arc(points, ends[e], Vector3(0, r, 0), out, 0, real_t(Math::PI), 12);
				_add_arc(points, ends[e], Vector3(0, 0, r), out, 0, real_t(Math::PI), 12);
			}
			const Vector3 sides[4] = { Vector3(0, r, 0), Vector3(0, -r, 0), Vector3(0, 0, r), Vector3(0, 0, -r) };
			for (const Vector3 &s : sides) {
				points.push_back(ends[0] + s);
				points.push_back(ends[1] + s);
			}
		} break;
		default:
			return get_area_outline(p_size);
	}
	return points;
}

std::vector<Vector3> Light3DGizmoPlugin::get_area_range_box(const Vector2 &p_size, real_t p_range) {
	// The cluster volume of the thesis (§5.1.1): the rectangle grown by r on each side, r deep in front.
	const real_t hx = p_size.x * real_t(0.5) + p_range;
	const real_t hy = p_size.y * real_t(0.5) + p_range;
	const real_t z[2] = { 0, -p_range };
	std::vector<Vector3> points;
	for (int k = 0; k < 2; k++) {
		const Vector3 c[4] = { Vector3(-hx, hy, z[k]), Vector3(hx, hy, z[k]), Vector3(hx, -hy, z[k]), Vector3(-hx, -hy, z[k]) };
		for (int i = 0; i < 4; i++) {
			points.push_back(c[i]);
			points.push_back(c[(i + 1) % 4]);
		}
	}
	const real_t sx[4] = { -hx, hx, hx, -hx };
	const real_t sy[4] = { hy, hy, -hy, -hy };
	for (int i = 0; i < 4; i++) {
		points.push_back(Vector3(sx[i], sy[i], z[0]));
		points.push_back(Vector3(sx[i], sy[i], z[1]));
	}
	return points;
}

Vector2 Light3DGizmoPlugin::get_area_size_for_drag(const Vector2 &p_old_size, int p_id, const Vector3 &p_local) const {
	Vector2 size = p_old_size;
	const real_t half = p_id == HANDLE_AREA_WIDTH ? p_local.x : p_local.y;
	if (!Math::is_finite(half)) {
		return size;
	}
	// A drag past the centre clamps to a zero extent (the light then emits nothing).
	real_t extent = std::max(real_t(2) * half, real_t(0));
	if (is_snap_enabled()) {
		extent = std::max(snapped(extent, get_translate_snap()), real_t(0));
	}
	if (p_id == HANDLE_AREA_WIDTH) {
		size.x = extent;
	} else {
		size.y = extent;
	}
	return size;
}

// Points of a circle of radius p_r around the origin in the plane of axes p_u and p_v (line pairs).
static void _add_circle(std::vector<Vector3> &r_points, real_t p_r, int p_u, int p_v, real_t p_offset_axis_value = 0, int p_offset_axis = -1) {
	for (int i = 0; i < CIRCLE_SEGMENTS; i++) {
		for (int k = 0; k < 2; k++) {
			const real_t a = real_t(Math::TAU) * real_t(i + k) / real_t(CIRCLE_SEGMENTS);
			Vector3 p;
			p[p_u] = std::cos(a) * p_r;
			p[p_v] = std::sin(a) * p_r;
			if (p_offset_axis >= 0) {
				p[p_offset_axis] = p_offset_axis_value;
			}
			r_points.push_back(p);
		}
	}
}

void Light3DGizmoPlugin::redraw(EditorNode3DGizmo *p_gizmo) {
	ERR_FAIL_NULL_MSG(p_gizmo, "Light3DGizmoPlugin::redraw(): the gizmo is null.");
	Light3D *light = Object::cast_to<Light3D>(p_gizmo->get_node_3d());
	ERR_FAIL_NULL_MSG(light, "Light3DGizmoPlugin::redraw(): the gizmo's node is not a Light3D.");
	p_gizmo->clear();

	const Color color = get_gizmo_color(light);
	const bool selected = p_gizmo->is_selected();
	const Ref<EditorGizmoMaterial> lines = get_material("lights_material", p_gizmo);

	switch (light->get_light_type()) {
		case RS::LIGHT_DIRECTIONAL: {
			if (selected) {
				// An arrow along -Z (the light direction), 1 m long, with a four-sided head.
				const real_t len = 1.0, head = 0.2;
				std::vector<Vector3> points = { Vector3(0, 0, 0), Vector3(0, 0, -len) };
				const Vector3 tip(0, 0, -len);
				const Vector3 sides[4] = { Vector3(head, 0, 0), Vector3(-head, 0, 0), Vector3(0, head, 0), Vector3(0, -head, 0) };
				for (const Vector3 &s : sides) {
					points.push_back(tip);
					points.push_back(tip + s + Vector3(0, 0, head * 1.5f));
				}
				p_gizmo->add_lines(points, lines, false, color);
			}
			p_gizmo->add_unscaled_billboard(get_material("light_directional_icon", p_gizmo), ICON_SCALE, color);
		} break;
		case RS::LIGHT_OMNI: {
			if (selected) {
				const real_t r = light->get_param(Light3D::PARAM_RANGE);
				// The range circle facing the camera, plus the three axis circles for depth.
				std::vector<Vector3> billboard;
				_add_circle(billboard, r, 0, 1);
				p_gizmo->add_lines(billboard, get_material("lights_billboard_material", p_gizmo), true, color);
				std::vector<Vector3> axes;
				_add_circle(axes, r, 0, 1);
				_add_circle(axes, r, 0, 2);
				_add_circle(axes, r, 1, 2);
				p_gizmo->add_lines(axes, lines, false, Color(color.r, color.g, color.b, 0.5f));
				p_gizmo->add_handles({ Vector3(r, 0, 0) }, get_material("handles_billboard"), { HANDLE_RANGE }, true);
			}
			p_gizmo->add_unscaled_billboard(get_material("light_omni_icon", p_gizmo), ICON_SCALE, color);
		} break;
		case RS::LIGHT_SPOT: {
			if (selected) {
				const real_t r = light->get_param(Light3D::PARAM_RANGE);
				const real_t angle = Math::deg_to_rad(light->get_param(Light3D::PARAM_SPOT_ANGLE));
				const real_t w = r * std::sin(angle); // Rim radius.
				const real_t d = r * std::cos(angle); // Rim distance along -Z.
				std::vector<Vector3> points;
				_add_circle(points, w, 0, 1, -d, 2);
				const Vector3 rim[4] = { Vector3(w, 0, -d), Vector3(-w, 0, -d), Vector3(0, w, -d), Vector3(0, -w, -d) };
				for (const Vector3 &p : rim) {
					points.push_back(Vector3());
					points.push_back(p);
				}
				p_gizmo->add_lines(points, lines, false, color);
				p_gizmo->add_handles({ Vector3(0, 0, -r), Vector3(w, 0, -d) }, get_material("handles"), { HANDLE_RANGE, HANDLE_SPOT_ANGLE });
			}
			p_gizmo->add_unscaled_billboard(get_material("light_spot_icon", p_gizmo), ICON_SCALE, color);
		} break;
		case RS::LIGHT_AREA: {
			const AreaLight3D *area = Object::cast_to<AreaLight3D>(light);
			ERR_FAIL_NULL_MSG(area, "Light3DGizmoPlugin::redraw(): a LIGHT_AREA light that is not an AreaLight3D.");
			const Vector2 size = area->get_area_size();
			// Thesis Listing A.4, except that the outline is always shown, so the light's extent is
			// visible without selecting it.
			p_gizmo->add_lines(get_area_shape_outline(int(area->get_area_shape()), size), lines, false, color);
			if (selected) {
				const real_t r = light->get_param(Light3D::PARAM_RANGE);
				std::vector<Vector3> box = get_area_range_box(size, r);
				if (area->get_area_shape() == AreaLight3D::AREA_SHAPE_SPHERE || area->get_area_shape() == AreaLight3D::AREA_SHAPE_TUBE) {
					// Lit all around: the node's bound (the range around the whole shape), its 12 edges.
					const AABB bound = area->get_aabb();
					box.clear();
					for (int i = 0; i < 8; i++) {
						for (int axis = 0; axis < 3; axis++) {
							if (!(i & (1 << axis))) { // Corner i and its neighbour along one axis.
								box.push_back(bound.get_endpoint(i));
								box.push_back(bound.get_endpoint(i | (1 << axis)));
							}
						}
					}
				}
				p_gizmo->add_lines(box, lines, false, Color(color.r, color.g, color.b, 0.35f));
				if (area->get_area_shape() == AreaLight3D::AREA_SHAPE_SPHERE) {
					p_gizmo->add_handles({ Vector3(size.x * real_t(0.5), 0, 0) }, get_material("handles"), { HANDLE_AREA_WIDTH }); // Its diameter only.
				} else {
					p_gizmo->add_handles({ Vector3(size.x * real_t(0.5), 0, 0), Vector3(0, size.y * real_t(0.5), 0) }, get_material("handles"), { HANDLE_AREA_WIDTH, HANDLE_AREA_HEIGHT });
				}
			}
			p_gizmo->add_unscaled_billboard(get_material("light_area_icon", p_gizmo), ICON_SCALE, color);
		} break;
		default:
			break;
	}
}

String Light3DGizmoPlugin::get_handle_name(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary) const {
	const Light3D *light = p_gizmo ? Object::cast_to<Light3D>(p_gizmo->get_node_3d()) : nullptr;
	ERR_FAIL_NULL_V_MSG(light, String(), "Light3DGizmoPlugin::get_handle_name(): the gizmo's node is not a Light3D.");
	switch (light->get_light_type()) {
		case RS::LIGHT_OMNI:
			return p_id == HANDLE_RANGE ? "Radius" : String();
		case RS::LIGHT_SPOT:
			return p_id == HANDLE_RANGE ? "Radius" : (p_id == HANDLE_SPOT_ANGLE ? "Aperture" : String());
		case RS::LIGHT_AREA: {
			const AreaLight3D *area = Object::cast_to<AreaLight3D>(light);
			const AreaLight3D::AreaShape shape = area ? area->get_area_shape() : AreaLight3D::AREA_SHAPE_RECTANGLE;
			if (shape == AreaLight3D::AREA_SHAPE_SPHERE) {
				return p_id == HANDLE_AREA_WIDTH ? "Diameter" : String();
			}
			if (shape == AreaLight3D::AREA_SHAPE_TUBE) {
				return p_id == HANDLE_AREA_WIDTH ? "Length" : (p_id == HANDLE_AREA_HEIGHT ? "Diameter" : String());
			}
			return p_id == HANDLE_AREA_WIDTH ? "Width" : (p_id == HANDLE_AREA_HEIGHT ? "Height" : String());
		}
		default:
			return String();
	}
}

Variant Light3DGizmoPlugin::get_handle_value(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary) const {
	const Light3D *light = p_gizmo ? Object::cast_to<Light3D>(p_gizmo->get_node_3d()) : nullptr;
	ERR_FAIL_NULL_V_MSG(light, Variant(), "Light3DGizmoPlugin::get_handle_value(): the gizmo's node is not a Light3D.");
	switch (light->get_light_type()) {
		case RS::LIGHT_OMNI:
		case RS::LIGHT_SPOT:
			if (p_id == HANDLE_RANGE) {
				return light->get_param(Light3D::PARAM_RANGE);
			}
			if (p_id == HANDLE_SPOT_ANGLE && light->get_light_type() == RS::LIGHT_SPOT) {
				return light->get_param(Light3D::PARAM_SPOT_ANGLE);
			}
			break;
		case RS::LIGHT_AREA:
			if (p_id == HANDLE_AREA_WIDTH || p_id == HANDLE_AREA_HEIGHT) {
				// The whole size, so one restore value serves both handles.
				return Object::cast_to<AreaLight3D>(light)->get_area_size();
			}
			break;
		default:
			break;
	}
	ERR_FAIL_V_MSG(Variant(), vformat("Light3DGizmoPlugin::get_handle_value(): %s \"%s\" has no handle %d.", light->get_class().c_str(), light->get_name().c_str(), p_id));
}

void Light3DGizmoPlugin::set_handle(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary, Camera3D *p_camera, const Vector2 &p_point) {
	Light3D *light = p_gizmo ? Object::cast_to<Light3D>(p_gizmo->get_node_3d()) : nullptr;
	ERR_FAIL_NULL_MSG(light, "Light3DGizmoPlugin::set_handle(): the gizmo's node is not a Light3D.");
	ERR_FAIL_NULL_MSG(p_camera, "Light3DGizmoPlugin::set_handle(): the camera is null.");
	Vector3 ray_from, ray_dir;
	if (!get_camera_ray(p_camera, p_point, ray_from, ray_dir)) {
		return;
	}
	const Transform3D gt = light->get_global_transform();
	// Light space from world space (affine, so scaled lights work too).
	const Transform3D gi = gt.affine_inverse();
	const Vector3 local_from = gi.xform(ray_from);
	const Vector3 local_dir = gi.basis.xform(ray_dir);

	switch (light->get_light_type()) {
		case RS::LIGHT_OMNI: {
			if (p_id != HANDLE_RANGE) {
				break;
			}
			// The plane through the light facing the camera (the billboard circle's plane).
			const Vector3 n = -p_camera->get_camera_transform().basis.get_column(2).normalized();
			const real_t den = n.dot(ray_dir);
			if (std::fabs(den) < real_t(1e-6)) {
				return;
			}
			const real_t t = n.dot(gt.origin - ray_from) / den;
			if (t < 0) {
				return;
			}
			real_t r = (ray_from + ray_dir * t - gt.origin).length();
			if (is_snap_enabled()) {
				r = snapped(r, get_translate_snap());
			}
			light->set_param(Light3D::PARAM_RANGE, std::max(r, real_t(0)));
		} break;
		case RS::LIGHT_SPOT: {
			if (p_id == HANDLE_RANGE) {
				// Closest point of the ray to the light axis (local -Z): range = its distance along -Z.
				const Vector3 u(0, 0, -1);
				const Vector3 w0 = -local_from;
				const real_t b = u.dot(local_dir), c = local_dir.dot(local_dir), d = u.dot(w0), e = local_dir.dot(w0);
				const real_t den = c - b * b;
				if (std::fabs(den) < real_t(1e-8)) {
					return; // Looking along the axis.
				}
				real_t r = (b * e - c * d) / den;
				if (is_snap_enabled()) {
					r = snapped(r, get_translate_snap());
				}
				light->set_param(Light3D::PARAM_RANGE, std::max(r, real_t(0)));
			} else if (p_id == HANDLE_SPOT_ANGLE) {
				// The handle moves on the arc of radius `range` in the light's XZ plane, from -Z
				// (0 degrees) through +X (90) to +Z (180): pick the arc point closest to the ray.
				const real_t r = std::max(light->get_param(Light3D::PARAM_RANGE), real_t(1e-4));
				const Vector3 dir = local_dir.normalized();
				auto ray_distance = [&](real_t p_deg) {
					const real_t a = Math::deg_to_rad(p_deg);
					const Vector3 p(r * std::sin(a), 0, -r * std::cos(a));
					const Vector3 rel = p - local_from;
					return (rel - dir * std::max(rel.dot(dir), real_t(0))).length();
				};
				// Coarse 1-degree scan, then a 0.001-degree refinement around the best sample.
				real_t best = 0, best_d = ray_distance(0);
				for (int i = 1; i <= 180; i++) {
					const real_t d = ray_distance(real_t(i));
					if (d < best_d) {
						best_d = d;
						best = real_t(i);
					}
				}
				const real_t lo = std::max(best - 1, real_t(0));
				for (int i = 0; i <= 2000; i++) {
					const real_t deg = std::min(lo + real_t(i) * real_t(0.001), real_t(180));
					const real_t d = ray_distance(deg);
					if (d < best_d) {
						best_d = d;
						best = deg;
					}
				}
				real_t deg = best;
				if (is_snap_enabled()) {
					deg = snapped(deg, get_rotate_snap());
				}
				light->set_param(Light3D::PARAM_SPOT_ANGLE, Math::clamp(deg, real_t(0), real_t(180)));
			}
		} break;
		case RS::LIGHT_AREA: {
			if (p_id != HANDLE_AREA_WIDTH && p_id != HANDLE_AREA_HEIGHT) {
				break;
			}
			AreaLight3D *area = Object::cast_to<AreaLight3D>(light);
			ERR_FAIL_NULL(area);
			// Intersect the ray with the light's local XY plane (z = 0).
			if (std::fabs(local_dir.z) < real_t(1e-8)) {
				return; // The ray runs parallel to the light's plane.
			}
			const real_t t = -local_from.z / local_dir.z;
			if (!(t >= 0)) {
				return; // The plane is behind the camera along this ray.
			}
			const Vector3 hit = local_from + local_dir * t;
			const Vector2 size = get_area_size_for_drag(area->get_area_size(), p_id, hit);
			if (size != area->get_area_size()) {
				area->set_area_size(size);
			}
		} break;
		default:
			break;
	}
}

void Light3DGizmoPlugin::commit_handle(const EditorNode3DGizmo *p_gizmo, int p_id, bool p_secondary, const Variant &p_restore, bool p_cancel) {
	Light3D *light = p_gizmo ? Object::cast_to<Light3D>(p_gizmo->get_node_3d()) : nullptr;
	ERR_FAIL_NULL_MSG(light, "Light3DGizmoPlugin::commit_handle(): the gizmo's node is not a Light3D.");
	UndoRedo *ur = get_undo_redo();

	if (light->get_light_type() == RS::LIGHT_AREA) {
		AreaLight3D *area = Object::cast_to<AreaLight3D>(light);
		ERR_FAIL_NULL(area);
		ERR_FAIL_COND_MSG(p_id != HANDLE_AREA_WIDTH && p_id != HANDLE_AREA_HEIGHT, vformat("Light3DGizmoPlugin::commit_handle(): AreaLight3D has no handle %d.", p_id));
		ERR_FAIL_COND_MSG(p_restore.get_type() != Variant::VECTOR2, vformat("Light3DGizmoPlugin::commit_handle(): the restore value of an area light handle must be a Vector2 (got %s).", Variant::get_type_name(p_restore.get_type()).c_str()));
		const Vector2 restore = p_restore;
		if (p_cancel) {
			area->set_area_size(restore);
			return;
		}
		ur->create_action("Change Area Light Size");
		ur->add_do_method(area, "set_area_size", { area->get_area_size() });
		ur->add_undo_method(area, "set_area_size", { restore });
		ur->commit_action();
		return;
	}

	Light3D::Param param;
	String action;
	if (p_id == HANDLE_RANGE && (light->get_light_type() == RS::LIGHT_OMNI || light->get_light_type() == RS::LIGHT_SPOT)) {
		param = Light3D::PARAM_RANGE;
		action = "Change Light Radius";
	} else if (p_id == HANDLE_SPOT_ANGLE && light->get_light_type() == RS::LIGHT_SPOT) {
		param = Light3D::PARAM_SPOT_ANGLE;
		action = "Change Spot Light Angle";
	} else {
		ERR_FAIL_MSG(vformat("Light3DGizmoPlugin::commit_handle(): %s has no handle %d.", light->get_class().c_str(), p_id));
	}
	ERR_FAIL_COND_MSG(p_restore.get_type() != Variant::FLOAT && p_restore.get_type() != Variant::INT, vformat("Light3DGizmoPlugin::commit_handle(): the restore value must be a number (got %s).", Variant::get_type_name(p_restore.get_type()).c_str()));
	const float restore = p_restore;
	if (p_cancel) {
		light->set_param(param, restore);
		return;
	}
	ur->create_action(action);
	ur->add_do_method(light, "set_param", { (int)param, light->get_param(param) });
	ur->add_undo_method(light, "set_param", { (int)param, restore });
	ur->commit_action();
}
