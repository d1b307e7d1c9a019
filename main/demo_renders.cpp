/**************************************************************************/
/*  demo_renders.cpp                                                      */
/**************************************************************************/
/* godot-area: punctual stand-ins for area lights and camera paths (see   */
/* demo_renders.h for the power conversion).                              */

#include "main/demo_renders.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "scene/3d/light_3d.h"
#include "scene/main/node.h"

#include <cmath>
#include <cstdlib>

namespace DemoRenders {

float spot_energy_for_area_light(float p_area_energy, float p_area_width, float p_area_height, bool p_normalize_energy, float p_spot_angle_degrees, float p_spot_angle_attenuation) {
	// Area power / (c pi^2) = E (normalized) or E * A; spot power / (c pi^2) = E' * 2 (1 - cos a) k / (k + 1).
	const float area_power = p_normalize_energy ? p_area_energy : p_area_energy * p_area_width * p_area_height;
	const float cos_a = std::cos(Math::deg_to_rad(p_spot_angle_degrees));
	const float k = p_spot_angle_attenuation;
	const float spot_power_per_energy = 2.0f * (1.0f - cos_a) * k / (k + 1.0f);
	return spot_power_per_energy > 0.0f ? area_power / spot_power_per_energy : 0.0f;
}

static void _collect_area_lights(Node *p_node, std::vector<AreaLight3D *> &r_lights) {
	if (AreaLight3D *area = Object::cast_to<AreaLight3D>(p_node)) {
		r_lights.push_back(area);
	}
	for (int i = 0; i < p_node->get_child_count(); i++) {
		_collect_area_lights(p_node->get_child(i), r_lights);
	}
}

int replace_area_lights_with_spots(Node *p_root, std::vector<String> *r_report) {
	ERR_FAIL_NULL_V(p_root, 0);
	std::vector<AreaLight3D *> lights;
	_collect_area_lights(p_root, lights);
	for (AreaLight3D *area : lights) {
		Node *parent = area->get_parent();
		ERR_CONTINUE_MSG(!parent, "an AreaLight3D without a parent (the scene root) cannot be replaced");
		const Vector2 size = area->get_area_size();
		SpotLight3D *spot = new SpotLight3D;
		spot->set_transform(area->get_transform()); // Both emit along local -Z.
		spot->set_color(area->get_color());
		spot->set_negative(area->is_negative());
		spot->set_cull_mask(area->get_cull_mask());
		spot->set_param(Light3D::PARAM_SPECULAR, area->get_param(Light3D::PARAM_SPECULAR));
		spot->set_param(Light3D::PARAM_INDIRECT_ENERGY, area->get_param(Light3D::PARAM_INDIRECT_ENERGY));
		spot->set_param(Light3D::PARAM_RANGE, area->get_param(Light3D::PARAM_RANGE));
		spot->set_param(Light3D::PARAM_ATTENUATION, area->get_param(Light3D::PARAM_ATTENUATION));
		spot->set_param(Light3D::PARAM_SPOT_ANGLE, 90.0f);
		spot->set_param(Light3D::PARAM_SPOT_ATTENUATION, 1.0f);
		const float energy = spot_energy_for_area_light(area->get_param(Light3D::PARAM_ENERGY), size.x, size.y, area->is_area_normalizing_energy());
		spot->set_param(Light3D::PARAM_ENERGY, energy);
		if (r_report) {
			r_report->push_back(vformat("%s: AreaLight3D %gx%g m, light_energy %g -> SpotLight3D light_energy %g (spot_angle 90, equal power)",
					area->get_name().c_str(), size.x, size.y, area->get_param(Light3D::PARAM_ENERGY), energy));
		}
		const String name = area->get_name();
		const int index = area->get_index();
		parent->remove_child(area);
		delete area;
		spot->set_name(name);
		parent->add_child(spot);
		parent->move_child(spot, index);
	}
	return int(lights.size());
}

static bool _parse_floats(const String &p_text, int p_count, float *r_values) {
	const std::vector<String> parts = string_split(p_text, ',');
	if (int(parts.size()) != p_count) {
		return false;
	}
	for (int i = 0; i < p_count; i++) {
		const String part = string_strip_edges(parts[i]);
		char *end = nullptr;
		const double v = std::strtod(part.c_str(), &end);
		if (part.empty() || *end != '\0' || !std::isfinite(v)) {
			return false;
		}
		r_values[i] = float(v);
	}
	return true;
}

bool parse_camera_path(const String &p_spec, CameraPath &r_path, String *r_error) {
	if (string_begins_with(p_spec, "orbit:")) {
		const String rest = p_spec.substr(6);
		const size_t at = rest.find('@');
		float degrees = 0.0f, pivot[3] = { 0, 0, 0 };
		if (at == String::npos || !_parse_floats(rest.substr(0, at), 1, &degrees) || !_parse_floats(rest.substr(at + 1), 3, pivot)) {
			*r_error = vformat("--path '%s': orbit needs 'orbit:DEGREES@X,Y,Z' (finite numbers)", p_spec.c_str());
			return false;
		}
		r_path.kind = CameraPath::ORBIT;
		r_path.degrees = degrees;
		r_path.pivot = Vector3(pivot[0], pivot[1], pivot[2]);
		return true;
	}
	if (string_begins_with(p_spec, "dolly:")) {
		float offset[3] = { 0, 0, 0 };
		if (!_parse_floats(p_spec.substr(6), 3, offset)) {
			*r_error = vformat("--path '%s': dolly needs 'dolly:DX,DY,DZ' (finite numbers, metres)", p_spec.c_str());
			return false;
		}
		r_path.kind = CameraPath::DOLLY;
		r_path.offset = Vector3(offset[0], offset[1], offset[2]);
		return true;
	}
	*r_error = vformat("--path '%s': expected 'orbit:DEGREES@X,Y,Z' or 'dolly:DX,DY,DZ'", p_spec.c_str());
	return false;
}

Transform3D CameraPath::sample(const Transform3D &p_start, float p_t) const {
	if (kind == DOLLY) {
		Transform3D t = p_start;
		t.origin += offset * p_t;
		return t;
	}
	const float angle = Math::deg_to_rad(degrees * (p_t - 0.5f));
	const Basis turn = Basis::from_axis_angle(Vector3(0, 1, 0), angle);
	return Transform3D(turn * p_start.basis, pivot + turn.xform(p_start.origin - pivot));
}

String numbered_path(const String &p_path, int p_frame) {
	const size_t slash = p_path.find_last_of('/');
	const size_t dot = p_path.find_last_of('.');
	const bool has_ext = dot != String::npos && (slash == String::npos || dot > slash);
	const String base = has_ext ? p_path.substr(0, dot) : p_path;
	const String ext = has_ext ? p_path.substr(dot) : String();
	return base + vformat("%08d", p_frame) + ext;
}

String suffixed_path(const String &p_path, const String &p_suffix) {
	const size_t slash = p_path.find_last_of('/');
	const size_t dot = p_path.find_last_of('.');
	if (dot == String::npos || (slash != String::npos && dot < slash)) {
		return p_path + p_suffix;
	}
	return p_path.substr(0, dot) + p_suffix + p_path.substr(dot);
}

} // namespace DemoRenders
