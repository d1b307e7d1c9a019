/**************************************************************************/
/*  light_3d.cpp                                                          */
/**************************************************************************/

#include "scene/3d/light_3d.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>

// The server to forward to, or null when this light has no RS light (ClassDB's default constructor).
#define LIGHT_RS() (light.is_valid() ? RS::get_singleton() : nullptr)

/* Light3D */

String Light3D::get_param_property_name(Param p_param) const {
	const bool directional = type == RS::LIGHT_DIRECTIONAL;
	const bool spot = type == RS::LIGHT_SPOT;
	const bool area = type == RS::LIGHT_AREA;
	switch (p_param) {
		case PARAM_ENERGY:
			return "light_energy";
		case PARAM_INDIRECT_ENERGY:
			return "light_indirect_energy";
		case PARAM_VOLUMETRIC_FOG_ENERGY:
			return "light_volumetric_fog_energy";
		case PARAM_SPECULAR:
			return "light_specular";
		case PARAM_RANGE:
			return directional ? "range (PARAM_RANGE, unused by DirectionalLight3D)" : (spot ? "spot_range" : (area ? "area_range" : "omni_range"));
		case PARAM_SIZE:
			return directional ? "light_angular_distance" : "light_size";
		case PARAM_ATTENUATION:
			return directional ? "attenuation (PARAM_ATTENUATION, unused by DirectionalLight3D)" : (spot ? "spot_attenuation" : (area ? "area_attenuation" : "omni_attenuation"));
		case PARAM_SPOT_ANGLE:
			return "spot_angle";
		case PARAM_SPOT_ATTENUATION:
			return "spot_angle_attenuation";
		case PARAM_SHADOW_MAX_DISTANCE:
			return "directional_shadow_max_distance";
		case PARAM_SHADOW_SPLIT_1_OFFSET:
			return "directional_shadow_split_1";
		case PARAM_SHADOW_SPLIT_2_OFFSET:
			return "directional_shadow_split_2";
		case PARAM_SHADOW_SPLIT_3_OFFSET:
			return "directional_shadow_split_3";
		case PARAM_SHADOW_FADE_START:
			return "directional_shadow_fade_start";
		case PARAM_SHADOW_NORMAL_BIAS:
			return "shadow_normal_bias";
		case PARAM_SHADOW_BIAS:
			return "shadow_bias";
		case PARAM_SHADOW_PANCAKE_SIZE:
			return "directional_shadow_pancake_size";
		case PARAM_SHADOW_OPACITY:
			return "shadow_opacity";
		case PARAM_SHADOW_BLUR:
			return "shadow_blur";
		case PARAM_TRANSMITTANCE_BIAS:
			return "shadow_transmittance_bias";
		case PARAM_INTENSITY:
			return directional ? "light_intensity_lux" : "light_intensity_lumens";
		case PARAM_MAX:
			break;
	}
	return vformat("param %d", (int)p_param);
}

String Light3D::validate_param(Param p_param, float p_value) const {
	if (!Math::is_finite(p_value)) {
		return "must be finite (not NaN or infinity)";
	}
	switch (p_param) {
		case PARAM_ATTENUATION:
			// The area light raises its range window to this power (0 = no falloff); negative would
			// amplify light towards the range limit. Omni/spot: a signed distance exponent.
			if (type == RS::LIGHT_AREA) {
				return p_value < 0.0f ? "must not be negative" : String();
			}
			return String();
		// Signed by design: easing curves and the transmittance bias.
		case PARAM_SPOT_ATTENUATION:
		case PARAM_TRANSMITTANCE_BIAS:
			return String();
		// Fractions.
		case PARAM_SHADOW_SPLIT_1_OFFSET:
		case PARAM_SHADOW_SPLIT_2_OFFSET:
		case PARAM_SHADOW_SPLIT_3_OFFSET:
		case PARAM_SHADOW_FADE_START:
		case PARAM_SHADOW_OPACITY:
			return (p_value < 0.0f || p_value > 1.0f) ? "must be between 0 and 1" : String();
		case PARAM_SPOT_ANGLE:
			return (p_value < 0.0f || p_value > 180.0f) ? "must be between 0 and 180 degrees" : String();
		case PARAM_SIZE:
			if (type == RS::LIGHT_DIRECTIONAL) {
				return (p_value < 0.0f || p_value > 90.0f) ? "must be between 0 and 90 degrees" : String();
			}
			return p_value < 0.0f ? "must not be negative" : String();
		default:
			// Energies, specular, range, distances, biases, blur, intensity: negative is meaningless
			// (use light_negative to subtract light).
			return p_value < 0.0f ? "must not be negative" : String();
	}
}

void Light3D::set_param(Param p_param, float p_value) {
	ERR_FAIL_INDEX_MSG((int)p_param, (int)PARAM_MAX, vformat("Light3D::set_param(): parameter index %d is out of range (0..%d).", (int)p_param, (int)PARAM_MAX - 1));
	String problem = validate_param(p_param, p_value);
	ERR_FAIL_COND_MSG(!problem.empty(), vformat("%s \"%s\": %s %s (got %s); the old value %s is kept.", get_class().c_str(), get_name().c_str(), get_param_property_name(p_param).c_str(), problem.c_str(), rtos(p_value).c_str(), rtos(param[p_param]).c_str()));
	param[p_param] = p_value;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_param(light, RS::LightParam(p_param), p_value);
	}
}

float Light3D::get_param(Param p_param) const {
	ERR_FAIL_INDEX_V_MSG((int)p_param, (int)PARAM_MAX, 0.0f, vformat("Light3D::get_param(): parameter index %d is out of range (0..%d).", (int)p_param, (int)PARAM_MAX - 1));
	return param[p_param];
}

void Light3D::set_color(const Color &p_color) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_color.r) || !Math::is_finite(p_color.g) || !Math::is_finite(p_color.b) || !Math::is_finite(p_color.a), vformat("%s \"%s\": light_color must be finite (no NaN or infinity); the old value is kept.", get_class().c_str(), get_name().c_str()));
	color = p_color;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_color(light, color);
	}
}

void Light3D::set_shadow(bool p_enable) {
	shadow = p_enable;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_shadow(light, shadow);
	}
	// shadow_* properties show or hide.
	notify_property_list_changed();
}

void Light3D::set_negative(bool p_enable) {
	negative = p_enable;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_negative(light, negative);
	}
}

void Light3D::set_shadow_reverse_cull_face(bool p_enable) {
	reverse_cull = p_enable;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_reverse_cull_face_mode(light, reverse_cull);
	}
}

void Light3D::set_cull_mask(uint32_t p_mask) {
	cull_mask = p_mask;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_cull_mask(light, cull_mask);
	}
}

void Light3D::set_shadow_caster_mask(uint32_t p_mask) {
	shadow_caster_mask = p_mask;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_shadow_caster_mask(light, shadow_caster_mask);
	}
}

void Light3D::set_bake_mode(BakeMode p_mode) {
	ERR_FAIL_COND_MSG((int)p_mode < 0 || (int)p_mode > BAKE_DYNAMIC, vformat("%s \"%s\": light_bake_mode must be 0..2 (Disabled, Static, Dynamic); got %d. The old value is kept.", get_class().c_str(), get_name().c_str(), (int)p_mode));
	bake_mode = p_mode;
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_bake_mode(light, RS::LightBakeMode(bake_mode));
	}
}

void Light3D::set_projector(const Ref<Texture2D> &p_texture) {
	projector = p_texture;
}

void Light3D::set_temperature(float p_kelvin) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_kelvin) || p_kelvin <= 0.0f, vformat("%s \"%s\": light_temperature must be finite and > 0 Kelvin (got %s); the old value is kept.", get_class().c_str(), get_name().c_str(), rtos(p_kelvin).c_str()));
	temperature = p_kelvin;
}

void Light3D::_push_distance_fade() {
	if (RS *rs = LIGHT_RS()) {
		rs->light_set_distance_fade(light, distance_fade_enabled, distance_fade_begin, distance_fade_shadow, distance_fade_length);
	}
}

void Light3D::set_enable_distance_fade(bool p_enable) {
	distance_fade_enabled = p_enable;
	_push_distance_fade();
	notify_property_list_changed();
}

void Light3D::set_distance_fade_begin(float p_distance) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_distance) || p_distance < 0.0f, vformat("%s \"%s\": distance_fade_begin must be finite and not negative (got %s); the old value is kept.", get_class().c_str(), get_name().c_str(), rtos(p_distance).c_str()));
	distance_fade_begin = p_distance;
	_push_distance_fade();
}

void Light3D::set_distance_fade_shadow(float p_distance) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_distance) || p_distance < 0.0f, vformat("%s \"%s\": distance_fade_shadow must be finite and not negative (got %s); the old value is kept.", get_class().c_str(), get_name().c_str(), rtos(p_distance).c_str()));
	distance_fade_shadow = p_distance;
	_push_distance_fade();
}

void Light3D::set_distance_fade_length(float p_length) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_length) || p_length < 0.0f, vformat("%s \"%s\": distance_fade_length must be finite and not negative (got %s); the old value is kept.", get_class().c_str(), get_name().c_str(), rtos(p_length).c_str()));
	distance_fade_length = p_length;
	_push_distance_fade();
}

void Light3D::set_editor_only(bool p_editor_only) {
	editor_only = p_editor_only;
	_update_instance_visibility();
}

void Light3D::_update_instance_visibility() {
	RS *rs = RS::get_singleton();
	if (rs && get_instance().is_valid() && is_inside_tree()) {
		rs->instance_set_visible(get_instance(), is_visible_in_tree() && !editor_only);
	}
}

AABB Light3D::get_aabb() const {
	switch (type) {
		case RS::LIGHT_DIRECTIONAL:
			return AABB(Vector3(-1, -1, -1), Vector3(2, 2, 2));
		case RS::LIGHT_OMNI: {
			const real_t r = param[PARAM_RANGE];
			return AABB(Vector3(-r, -r, -r), Vector3(r, r, r) * 2);
		}
		case RS::LIGHT_SPOT: {
			// The cone's slant height is the range; its apex is at the origin, opening along -Z.
			const real_t r = param[PARAM_RANGE];
			const real_t angle = Math::deg_to_rad(param[PARAM_SPOT_ANGLE]);
			if (angle > real_t(Math::PI / 2)) {
				// Wider than a hemisphere: bound it like an omni light.
				return AABB(Vector3(-r, -r, -r), Vector3(r, r, r) * 2);
			}
			const real_t radius = std::sin(angle) * r;
			return AABB(Vector3(-radius, -radius, -r), Vector3(radius * 2, radius * 2, r));
		}
		case RS::LIGHT_AREA:
			break; // AreaLight3D::get_aabb (the size lives there).
	}
	return AABB();
}

std::vector<String> Light3D::get_configuration_warnings() const {
	std::vector<String> warnings;
	if (!get_scale().is_equal_approx(Vector3(1, 1, 1))) {
		warnings.push_back("A light's scale does not affect the visual size of the light.");
	}
	if (type == RS::LIGHT_SPOT && shadow && param[PARAM_SPOT_ANGLE] >= 90.0f) {
		warnings.push_back("A SpotLight3D with an angle wider than 90 degrees cannot cast shadows.");
	}
	if (const AreaLight3D *area = Object::cast_to<AreaLight3D>(this)) {
		if (area->get_area_shape() == AreaLight3D::AREA_SHAPE_SPHERE) {
			if (area->get_area_size().x <= 0.0f) {
				warnings.push_back("A sphere AreaLight3D with a zero diameter (area_size.x) emits no light.");
			}
		} else if (area->get_area_shape() == AreaLight3D::AREA_SHAPE_TUBE) {
			if (area->get_area_size().y <= 0.0f) {
				warnings.push_back("A tube AreaLight3D with a zero diameter (area_size.y) emits no light.");
			}
		} else if (area->get_area_size().x <= 0.0f || area->get_area_size().y <= 0.0f) {
			warnings.push_back("An AreaLight3D with a zero area_size component emits no light.");
		}
		if (area->get_area_shape() != AreaLight3D::AREA_SHAPE_RECTANGLE && area->get_area_texture().is_valid()) {
			warnings.push_back("area_texture applies to rectangle AreaLight3Ds only (as upstream's); this disk, sphere or tube is drawn untextured.");
		}
		if (projector.is_valid()) {
			// Upstream Godot 4.7 warns the same way: area lights take their texture from area_texture.
			warnings.push_back("An AreaLight3D does not use light_projector; an area light's texture is area_texture.");
		}
	}
	if (type != RS::LIGHT_DIRECTIONAL && type != RS::LIGHT_AREA && !shadow && projector.is_valid()) {
		warnings.push_back("Projector texture only works with shadows active.");
	}
	return warnings;
}

void Light3D::_validate_property(PropertyInfo &p_property) const {
	const String &n = p_property.name;
	if (!shadow && (n == "shadow_bias" || n == "shadow_normal_bias" || n == "shadow_reverse_cull_face" || n == "shadow_transmittance_bias" || n == "shadow_opacity" || n == "shadow_blur" || n == "distance_fade_shadow" || n == "shadow_caster_mask")) {
		// Saved, but not shown while shadows are off.
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// Upstream Godot 4.7: an area light shows light_size (default 0.5, its PCSS size) and hides
	// light_projector (still saved when set, so nothing is lost; a configuration warning says why).
	if (type == RS::LIGHT_AREA && n == "light_projector") {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	if (type != RS::LIGHT_DIRECTIONAL && (n == "light_angular_distance" || n == "light_intensity_lux")) {
		p_property.usage = PROPERTY_USAGE_NONE;
	} else if (type == RS::LIGHT_DIRECTIONAL && n == "light_intensity_lumens") {
		p_property.usage = PROPERTY_USAGE_NONE;
	}
	// Physical light units are off (no project settings): hide their properties, as Godot does.
	if (n == "light_intensity_lumens" || n == "light_intensity_lux" || n == "light_temperature") {
		p_property.usage = PROPERTY_USAGE_NONE;
	}
	if (!distance_fade_enabled && (n == "distance_fade_begin" || n == "distance_fade_shadow" || n == "distance_fade_length")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
}

void Light3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_editor_only", "editor_only"), &Light3D::set_editor_only);
	ClassDB::bind_method(D_METHOD("is_editor_only"), &Light3D::is_editor_only);
	ClassDB::bind_method(D_METHOD("set_param", "param", "value"), &Light3D::set_param);
	ClassDB::bind_method(D_METHOD("get_param", "param"), &Light3D::get_param);
	ClassDB::bind_method(D_METHOD("set_shadow", "enabled"), &Light3D::set_shadow);
	ClassDB::bind_method(D_METHOD("has_shadow"), &Light3D::has_shadow);
	ClassDB::bind_method(D_METHOD("set_negative", "enabled"), &Light3D::set_negative);
	ClassDB::bind_method(D_METHOD("is_negative"), &Light3D::is_negative);
	ClassDB::bind_method(D_METHOD("set_cull_mask", "cull_mask"), &Light3D::set_cull_mask);
	ClassDB::bind_method(D_METHOD("get_cull_mask"), &Light3D::get_cull_mask);
	ClassDB::bind_method(D_METHOD("set_enable_distance_fade", "enable"), &Light3D::set_enable_distance_fade);
	ClassDB::bind_method(D_METHOD("is_distance_fade_enabled"), &Light3D::is_distance_fade_enabled);
	ClassDB::bind_method(D_METHOD("set_distance_fade_begin", "distance"), &Light3D::set_distance_fade_begin);
	ClassDB::bind_method(D_METHOD("get_distance_fade_begin"), &Light3D::get_distance_fade_begin);
	ClassDB::bind_method(D_METHOD("set_distance_fade_shadow", "distance"), &Light3D::set_distance_fade_shadow);
	ClassDB::bind_method(D_METHOD("get_distance_fade_shadow"), &Light3D::get_distance_fade_shadow);
	ClassDB::bind_method(D_METHOD("set_distance_fade_length", "distance"), &Light3D::set_distance_fade_length);
	ClassDB::bind_method(D_METHOD("get_distance_fade_length"), &Light3D::get_distance_fade_length);
	ClassDB::bind_method(D_METHOD("set_color", "color"), &Light3D::set_color);
	ClassDB::bind_method(D_METHOD("get_color"), &Light3D::get_color);
	ClassDB::bind_method(D_METHOD("set_shadow_reverse_cull_face", "enable"), &Light3D::set_shadow_reverse_cull_face);
	ClassDB::bind_method(D_METHOD("get_shadow_reverse_cull_face"), &Light3D::get_shadow_reverse_cull_face);
	ClassDB::bind_method(D_METHOD("set_shadow_caster_mask", "caster_mask"), &Light3D::set_shadow_caster_mask);
	ClassDB::bind_method(D_METHOD("get_shadow_caster_mask"), &Light3D::get_shadow_caster_mask);
	ClassDB::bind_method(D_METHOD("set_bake_mode", "bake_mode"), &Light3D::set_bake_mode);
	ClassDB::bind_method(D_METHOD("get_bake_mode"), &Light3D::get_bake_mode);
	ClassDB::bind_method(D_METHOD("set_projector", "projector"), &Light3D::set_projector);
	ClassDB::bind_method(D_METHOD("get_projector"), &Light3D::get_projector);
	ClassDB::bind_method(D_METHOD("set_temperature", "temperature"), &Light3D::set_temperature);
	ClassDB::bind_method(D_METHOD("get_temperature"), &Light3D::get_temperature);

	// Order, names, hints and groups as Godot 4.7's Light3D.
	ADD_GROUP("Light", "light_");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_intensity_lumens", PROPERTY_HINT_RANGE, "0,100000.0,0.01,or_greater,suffix:lm"), "set_param", "get_param", PARAM_INTENSITY);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_intensity_lux", PROPERTY_HINT_RANGE, "0,150000.0,0.01,or_greater,suffix:lx"), "set_param", "get_param", PARAM_INTENSITY);
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "light_temperature", PROPERTY_HINT_RANGE, "1000,15000.0,1.0,suffix:k"), "set_temperature", "get_temperature");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "light_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_color", "get_color");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_energy", PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"), "set_param", "get_param", PARAM_ENERGY);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_indirect_energy", PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"), "set_param", "get_param", PARAM_INDIRECT_ENERGY);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_volumetric_fog_energy", PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"), "set_param", "get_param", PARAM_VOLUMETRIC_FOG_ENERGY);
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "light_projector", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_projector", "get_projector");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_size", PROPERTY_HINT_RANGE, "0,1,0.001,or_greater,suffix:m"), "set_param", "get_param", PARAM_SIZE);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_angular_distance", PROPERTY_HINT_RANGE, "0,90,0.01,degrees"), "set_param", "get_param", PARAM_SIZE);
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "light_negative"), "set_negative", "is_negative");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "light_specular", PROPERTY_HINT_RANGE, "0,16,0.001,or_greater"), "set_param", "get_param", PARAM_SPECULAR);
	ADD_PROPERTY(PropertyInfo(Variant::INT, "light_bake_mode", PROPERTY_HINT_ENUM, "Disabled,Static,Dynamic"), "set_bake_mode", "get_bake_mode");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "light_cull_mask", PROPERTY_HINT_LAYERS_3D_RENDER), "set_cull_mask", "get_cull_mask");

	ADD_GROUP("Shadow", "shadow_");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "shadow_enabled"), "set_shadow", "has_shadow");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "shadow_bias", PROPERTY_HINT_RANGE, "0,10,0.001"), "set_param", "get_param", PARAM_SHADOW_BIAS);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "shadow_normal_bias", PROPERTY_HINT_RANGE, "0,10,0.001"), "set_param", "get_param", PARAM_SHADOW_NORMAL_BIAS);
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "shadow_reverse_cull_face"), "set_shadow_reverse_cull_face", "get_shadow_reverse_cull_face");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "shadow_transmittance_bias", PROPERTY_HINT_RANGE, "-16,16,0.001"), "set_param", "get_param", PARAM_TRANSMITTANCE_BIAS);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "shadow_opacity", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_param", "get_param", PARAM_SHADOW_OPACITY);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "shadow_blur", PROPERTY_HINT_RANGE, "0,10,0.001"), "set_param", "get_param", PARAM_SHADOW_BLUR);
	ADD_PROPERTY(PropertyInfo(Variant::INT, "shadow_caster_mask", PROPERTY_HINT_LAYERS_3D_RENDER), "set_shadow_caster_mask", "get_shadow_caster_mask");

	ADD_GROUP("Distance Fade", "distance_fade_");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "distance_fade_enabled"), "set_enable_distance_fade", "is_distance_fade_enabled");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "distance_fade_begin", PROPERTY_HINT_RANGE, "0.0,4096.0,0.01,or_greater,suffix:m"), "set_distance_fade_begin", "get_distance_fade_begin");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "distance_fade_shadow", PROPERTY_HINT_RANGE, "0.0,4096.0,0.01,or_greater,suffix:m"), "set_distance_fade_shadow", "get_distance_fade_shadow");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "distance_fade_length", PROPERTY_HINT_RANGE, "0.0,4096.0,0.01,or_greater,suffix:m"), "set_distance_fade_length", "get_distance_fade_length");

	ADD_GROUP("Editor", "");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "editor_only"), "set_editor_only", "is_editor_only");
	ADD_GROUP("", "");

	BIND_ENUM_CONSTANT(PARAM_ENERGY);
	BIND_ENUM_CONSTANT(PARAM_INDIRECT_ENERGY);
	BIND_ENUM_CONSTANT(PARAM_VOLUMETRIC_FOG_ENERGY);
	BIND_ENUM_CONSTANT(PARAM_SPECULAR);
	BIND_ENUM_CONSTANT(PARAM_RANGE);
	BIND_ENUM_CONSTANT(PARAM_SIZE);
	BIND_ENUM_CONSTANT(PARAM_ATTENUATION);
	BIND_ENUM_CONSTANT(PARAM_SPOT_ANGLE);
	BIND_ENUM_CONSTANT(PARAM_SPOT_ATTENUATION);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_MAX_DISTANCE);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_SPLIT_1_OFFSET);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_SPLIT_2_OFFSET);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_SPLIT_3_OFFSET);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_FADE_START);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_NORMAL_BIAS);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_BIAS);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_PANCAKE_SIZE);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_OPACITY);
	BIND_ENUM_CONSTANT(PARAM_SHADOW_BLUR);
	BIND_ENUM_CONSTANT(PARAM_TRANSMITTANCE_BIAS);
	BIND_ENUM_CONSTANT(PARAM_INTENSITY);
	BIND_ENUM_CONSTANT(PARAM_MAX);

	BIND_ENUM_CONSTANT(BAKE_DISABLED);
	BIND_ENUM_CONSTANT(BAKE_STATIC);
	BIND_ENUM_CONSTANT(BAKE_DYNAMIC);
}

Light3D::Light3D(RS::LightType p_type) {
	type = p_type;
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "Light3D needs a RenderingServer; create one before the scene.");
	switch (p_type) {
		case RS::LIGHT_DIRECTIONAL:
			light = rs->directional_light_create();
			break;
		case RS::LIGHT_OMNI:
			light = rs->omni_light_create();
			break;
		case RS::LIGHT_SPOT:
			light = rs->spot_light_create();
			break;
		case RS::LIGHT_AREA:
			light = rs->area_light_create();
			break;
	}
	set_base(light);

	// Godot 4.7's defaults, applied through the setters so node and server agree.
	set_color(Color(1, 1, 1, 1));
	set_shadow(false);
	set_negative(false);
	set_cull_mask(0xFFFFFFFF);
	set_shadow_caster_mask(0xFFFFFFFF);
	set_shadow_reverse_cull_face(false);
	set_bake_mode(BAKE_DYNAMIC);
	set_param(PARAM_ENERGY, 1.0f);
	set_param(PARAM_INDIRECT_ENERGY, 1.0f);
	set_param(PARAM_VOLUMETRIC_FOG_ENERGY, 1.0f);
	set_param(PARAM_SPECULAR, 0.5f);
	set_param(PARAM_RANGE, 5.0f);
	set_param(PARAM_SIZE, 0.0f);
	set_param(PARAM_ATTENUATION, 1.0f);
	set_param(PARAM_SPOT_ANGLE, 45.0f);
	set_param(PARAM_SPOT_ATTENUATION, 1.0f);
	set_param(PARAM_SHADOW_MAX_DISTANCE, 0.0f);
	set_param(PARAM_SHADOW_SPLIT_1_OFFSET, 0.1f);
	set_param(PARAM_SHADOW_SPLIT_2_OFFSET, 0.2f);
	set_param(PARAM_SHADOW_SPLIT_3_OFFSET, 0.5f);
	set_param(PARAM_SHADOW_PANCAKE_SIZE, 20.0f);
	set_param(PARAM_SHADOW_OPACITY, 1.0f);
	set_param(PARAM_SHADOW_BLUR, 1.0f);
	set_param(PARAM_SHADOW_BIAS, 0.1f);
	set_param(PARAM_SHADOW_NORMAL_BIAS, 1.0f);
	set_param(PARAM_TRANSMITTANCE_BIAS, 0.05f);
	set_param(PARAM_SHADOW_FADE_START, 1.0f);
	set_param(PARAM_INTENSITY, 1000.0f); // Lumens for omni and spot lights.
	set_temperature(6500.0f);
	_push_distance_fade();
}

Light3D::Light3D() {
	ERR_PRINT("Light3D should not be instantiated directly; use the DirectionalLight3D, OmniLight3D, SpotLight3D or AreaLight3D subtypes instead.");
}

Light3D::~Light3D() {
	RS *rs = RS::get_singleton();
	if (rs && light.is_valid()) {
		set_base(RID());
		rs->free(light);
	}
}

/* DirectionalLight3D */

void DirectionalLight3D::set_shadow_mode(ShadowMode p_mode) {
	ERR_FAIL_COND_MSG((int)p_mode < 0 || (int)p_mode > SHADOW_PARALLEL_4_SPLITS, vformat("DirectionalLight3D \"%s\": directional_shadow_mode must be 0..2; got %d. The old value is kept.", get_name().c_str(), (int)p_mode));
	shadow_mode = p_mode;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_directional_set_shadow_mode(get_light(), RS::LightDirectionalShadowMode(p_mode));
	}
	notify_property_list_changed();
}

void DirectionalLight3D::set_blend_splits(bool p_enable) {
	blend_splits = p_enable;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_directional_set_blend_splits(get_light(), p_enable);
	}
}

void DirectionalLight3D::set_sky_mode(SkyMode p_mode) {
	ERR_FAIL_COND_MSG((int)p_mode < 0 || (int)p_mode > SKY_MODE_SKY_ONLY, vformat("DirectionalLight3D \"%s\": sky_mode must be 0..2; got %d. The old value is kept.", get_name().c_str(), (int)p_mode));
	sky_mode = p_mode;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_directional_set_sky_mode(get_light(), RS::LightDirectionalSkyMode(p_mode));
	}
}

void DirectionalLight3D::_validate_property(PropertyInfo &p_property) const {
	const String &n = p_property.name;
	if (shadow_mode == SHADOW_ORTHOGONAL && (n == "directional_shadow_split_1" || n == "directional_shadow_blend_splits")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	if ((shadow_mode == SHADOW_ORTHOGONAL || shadow_mode == SHADOW_PARALLEL_2_SPLITS) && (n == "directional_shadow_split_2" || n == "directional_shadow_split_3")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// Not used by directional lights in Godot 4.7 (light_size is replaced by light_angular_distance).
	if (n == "light_size" || n == "light_projector" || n == "light_specular") {
		p_property.usage = PROPERTY_USAGE_NONE;
	}
	if (n == "distance_fade_enabled" || n == "distance_fade_begin" || n == "distance_fade_shadow" || n == "distance_fade_length") {
		p_property.usage = PROPERTY_USAGE_NONE;
	}
}

void DirectionalLight3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_shadow_mode", "mode"), &DirectionalLight3D::set_shadow_mode);
	ClassDB::bind_method(D_METHOD("get_shadow_mode"), &DirectionalLight3D::get_shadow_mode);
	ClassDB::bind_method(D_METHOD("set_blend_splits", "enabled"), &DirectionalLight3D::set_blend_splits);
	ClassDB::bind_method(D_METHOD("is_blend_splits_enabled"), &DirectionalLight3D::is_blend_splits_enabled);
	ClassDB::bind_method(D_METHOD("set_sky_mode", "mode"), &DirectionalLight3D::set_sky_mode);
	ClassDB::bind_method(D_METHOD("get_sky_mode"), &DirectionalLight3D::get_sky_mode);

	ADD_GROUP("Directional Shadow", "directional_shadow_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "directional_shadow_mode", PROPERTY_HINT_ENUM, "Orthogonal (Fast),PSSM 2 Splits (Average),PSSM 4 Splits (Slow)"), "set_shadow_mode", "get_shadow_mode");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "directional_shadow_split_1", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_param", "get_param", PARAM_SHADOW_SPLIT_1_OFFSET);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "directional_shadow_split_2", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_param", "get_param", PARAM_SHADOW_SPLIT_2_OFFSET);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "directional_shadow_split_3", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_param", "get_param", PARAM_SHADOW_SPLIT_3_OFFSET);
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "directional_shadow_blend_splits"), "set_blend_splits", "is_blend_splits_enabled");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "directional_shadow_fade_start", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_param", "get_param", PARAM_SHADOW_FADE_START);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "directional_shadow_max_distance", PROPERTY_HINT_RANGE, "0,8192,0.1,or_greater,exp"), "set_param", "get_param", PARAM_SHADOW_MAX_DISTANCE);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "directional_shadow_pancake_size", PROPERTY_HINT_RANGE, "0,1024,0.1,or_greater,exp"), "set_param", "get_param", PARAM_SHADOW_PANCAKE_SIZE);
	ADD_GROUP("", "");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "sky_mode", PROPERTY_HINT_ENUM, "Light and Sky,Light Only,Sky Only"), "set_sky_mode", "get_sky_mode");

	BIND_ENUM_CONSTANT(SHADOW_ORTHOGONAL);
	BIND_ENUM_CONSTANT(SHADOW_PARALLEL_2_SPLITS);
	BIND_ENUM_CONSTANT(SHADOW_PARALLEL_4_SPLITS);
	BIND_ENUM_CONSTANT(SKY_MODE_LIGHT_AND_SKY);
	BIND_ENUM_CONSTANT(SKY_MODE_LIGHT_ONLY);
	BIND_ENUM_CONSTANT(SKY_MODE_SKY_ONLY);
}

DirectionalLight3D::DirectionalLight3D() :
		Light3D(RS::LIGHT_DIRECTIONAL) {
	set_param(PARAM_SHADOW_MAX_DISTANCE, 100.0f);
	set_param(PARAM_SHADOW_FADE_START, 0.8f);
	// Godot raises the normal bias for directional lights.
	set_param(PARAM_SHADOW_NORMAL_BIAS, 2.0f);
	set_param(PARAM_INTENSITY, 100000.0f); // Lux, roughly mid-day sun.
	set_shadow_mode(SHADOW_PARALLEL_4_SPLITS);
	set_blend_splits(false);
	set_sky_mode(SKY_MODE_LIGHT_AND_SKY);
}

/* OmniLight3D */

void OmniLight3D::set_shadow_mode(ShadowMode p_mode) {
	ERR_FAIL_COND_MSG((int)p_mode < 0 || (int)p_mode > SHADOW_CUBE, vformat("OmniLight3D \"%s\": omni_shadow_mode must be 0 (Dual Paraboloid) or 1 (Cube); got %d. The old value is kept.", get_name().c_str(), (int)p_mode));
	shadow_mode = p_mode;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_omni_set_shadow_mode(get_light(), RS::LightOmniShadowMode(p_mode));
	}
}

void OmniLight3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_shadow_mode", "mode"), &OmniLight3D::set_shadow_mode);
	ClassDB::bind_method(D_METHOD("get_shadow_mode"), &OmniLight3D::get_shadow_mode);

	ADD_GROUP("Omni", "omni_");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "omni_range", PROPERTY_HINT_RANGE, "0,4096,0.001,or_greater,exp,suffix:m"), "set_param", "get_param", PARAM_RANGE);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "omni_attenuation", PROPERTY_HINT_RANGE, "-10,10,0.001,or_greater,or_less"), "set_param", "get_param", PARAM_ATTENUATION);
	ADD_PROPERTY(PropertyInfo(Variant::INT, "omni_shadow_mode", PROPERTY_HINT_ENUM, "Dual Paraboloid,Cube"), "set_shadow_mode", "get_shadow_mode");
	ADD_GROUP("", "");

	BIND_ENUM_CONSTANT(SHADOW_DUAL_PARABOLOID);
	BIND_ENUM_CONSTANT(SHADOW_CUBE);
}

OmniLight3D::OmniLight3D() :
		Light3D(RS::LIGHT_OMNI) {
	set_shadow_mode(SHADOW_CUBE);
}

/* SpotLight3D */

void SpotLight3D::_bind_methods() {
	ADD_GROUP("Spot", "spot_");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "spot_range", PROPERTY_HINT_RANGE, "0,4096,0.001,or_greater,exp,suffix:m"), "set_param", "get_param", PARAM_RANGE);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "spot_attenuation", PROPERTY_HINT_RANGE, "-10,10,0.01,or_greater,or_less"), "set_param", "get_param", PARAM_ATTENUATION);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "spot_angle", PROPERTY_HINT_RANGE, "0,180,0.01,degrees"), "set_param", "get_param", PARAM_SPOT_ANGLE);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "spot_angle_attenuation", PROPERTY_HINT_EXP_EASING, "attenuation"), "set_param", "get_param", PARAM_SPOT_ATTENUATION);
	ADD_GROUP("", "");
}

SpotLight3D::SpotLight3D() :
		Light3D(RS::LIGHT_SPOT) {
	// Godot lowers the default shadow bias for spot lights.
	set_param(PARAM_SHADOW_BIAS, 0.03f);
}

/* AreaLight3D */

void AreaLight3D::set_area_shape(AreaShape p_shape) {
	ERR_FAIL_COND_MSG((int)p_shape < 0 || (int)p_shape >= (int)RS::LIGHT_AREA_SHAPE_MAX, vformat("AreaLight3D \"%s\": area_shape must be 0..%d (Rectangle, Disk, Sphere, Tube); got %d. The old value is kept.", get_name().c_str(), (int)RS::LIGHT_AREA_SHAPE_MAX - 1, (int)p_shape));
	area_shape = p_shape;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_shape(get_light(), RS::LightAreaShape(p_shape));
	}
	notify_property_list_changed(); // The editor redraws the gizmo and the Area group.
}

void AreaLight3D::set_area_size(const Vector2 &p_size) {
	ERR_FAIL_COND_MSG(!p_size.is_finite(), vformat("AreaLight3D \"%s\": area_size must be finite in both components (got (%s, %s)); the old value (%s, %s) is kept.", get_name().c_str(), rtos(p_size.x).c_str(), rtos(p_size.y).c_str(), rtos(area_size.x).c_str(), rtos(area_size.y).c_str()));
	// Upstream Godot 4.7 clamps negative components to 0; we do too, and say so.
	const Vector2 clamped(std::max(p_size.x, real_t(0)), std::max(p_size.y, real_t(0)));
	if (clamped != p_size) {
		WARN_PRINT(vformat("AreaLight3D \"%s\": area_size (%s, %s) has a negative component; clamped to (%s, %s).", get_name().c_str(), rtos(p_size.x).c_str(), rtos(p_size.y).c_str(), rtos(clamped.x).c_str(), rtos(clamped.y).c_str()));
	}
	area_size = clamped;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_size(get_light(), area_size);
	}
}

void AreaLight3D::set_area_normalize_energy(bool p_enable) {
	area_normalize_energy = p_enable;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_normalize_energy(get_light(), area_normalize_energy);
	}
}

void AreaLight3D::set_area_shading_method(AreaShadingMethod p_method) {
	ERR_FAIL_COND_MSG((int)p_method < 0 || (int)p_method >= (int)RS::LIGHT_AREA_SHADING_MAX, vformat("AreaLight3D \"%s\": area_shading_method must be 0..%d (LTC, LTC Polynomial, MRP, Stochastic, Auto, LTC 2-Lobe); got %d. The old value is kept.", get_name().c_str(), (int)RS::LIGHT_AREA_SHADING_MAX - 1, (int)p_method));
	area_shading_method = p_method;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_shading_method(get_light(), RS::LightAreaShadingMethod(p_method));
	}
	notify_property_list_changed(); // area_stochastic_samples shows or hides.
}

void AreaLight3D::set_area_stochastic_samples(int p_samples) {
	ERR_FAIL_COND_MSG(p_samples < RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN || p_samples > RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MAX,
			vformat("AreaLight3D \"%s\": area_stochastic_samples must be %d..%d; got %d. The old value is kept.", get_name().c_str(), RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MIN, RS::LIGHT_AREA_STOCHASTIC_SAMPLES_MAX, p_samples));
	area_stochastic_samples = p_samples;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_stochastic_samples(get_light(), area_stochastic_samples);
	}
}

void AreaLight3D::set_area_shadow_mode(AreaShadowMode p_mode) {
	ERR_FAIL_COND_MSG((int)p_mode < 0 || (int)p_mode >= (int)RS::LIGHT_AREA_SHADOW_MAX, vformat("AreaLight3D \"%s\": area_shadow_mode must be 0..%d (Fixed, PCSS Baseline, Adaptive, Heuristic); got %d. The old value is kept.", get_name().c_str(), (int)RS::LIGHT_AREA_SHADOW_MAX - 1, (int)p_mode));
	area_shadow_mode = p_mode;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_shadow_mode(get_light(), RS::LightAreaShadowMode(p_mode));
	}
	notify_property_list_changed(); // area_shadow_grid shows or hides.
}

void AreaLight3D::set_area_shadow_grid(int p_grid) {
	ERR_FAIL_COND_MSG(p_grid < RS::LIGHT_AREA_SHADOW_GRID_MIN || p_grid > RS::LIGHT_AREA_SHADOW_GRID_MAX,
			vformat("AreaLight3D \"%s\": area_shadow_grid must be %d..%d; got %d. The old value is kept.", get_name().c_str(), RS::LIGHT_AREA_SHADOW_GRID_MIN, RS::LIGHT_AREA_SHADOW_GRID_MAX, p_grid));
	area_shadow_grid = p_grid;
	if (get_light().is_valid() && RS::get_singleton()) {
		RS::get_singleton()->light_area_set_shadow_grid(get_light(), area_shadow_grid);
	}
}

void AreaLight3D::set_area_texture(const Ref<Texture2D> &p_texture) {
	area_texture = p_texture;
	// A texture without texels (an empty ImageTexture) has no RID: the light is drawn untextured, as upstream.
	RID rid = area_texture.is_valid() ? area_texture->get_rid() : RID();
	if (get_light().is_valid()) {
		RS::get_singleton()->light_area_set_texture(get_light(), rid);
	}
	notify_property_list_changed(); // A non-rectangle shows the row only while it holds a texture.
}

void AreaLight3D::_validate_property(PropertyInfo &p_property) const {
	const String &n = p_property.name;
	// Godot style: shadow settings are saved but not shown while shadows are off (Light3D hides shadow_*).
	if (!has_shadow() && (n == "area_shadow_mode" || n == "area_shadow_grid")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// The PCSS baseline draws one map from the centre; ADAPTIVE and HEURISTIC choose their own samples
	// (up to the project's rendering/lights_and_shadows/area_shadow_adaptive_max_depth): the grid does not apply.
	if (area_shadow_mode != AREA_SHADOW_FIXED && n == "area_shadow_grid") {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// Only the stochastic method takes samples (AUTO may pick it per light and frame).
	if (area_shading_method != AREA_SHADING_STOCHASTIC && area_shading_method != AREA_SHADING_AUTO && n == "area_stochastic_samples") {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// area_texture textures rectangles only (upstream's only shape): another shape shows the row only
	// while it holds a texture (so it can be seen and cleared; a configuration warning says it is unused).
	if (area_shape != AREA_SHAPE_RECTANGLE && area_texture.is_null() && n == "area_texture") {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// Area lights do not sample a projector texture (the shading of the rectangle has no projection);
	// a value from a scene file is still kept and saved.
	if (n == "light_projector") {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
}

AABB AreaLight3D::get_aabb() const {
	// Same box as RendererLightStorage::compute_area_light_aabb() (the server's bound).
	const real_t r = get_param(PARAM_RANGE);
	if (area_shape == AREA_SHAPE_SPHERE) {
		const real_t h = area_size.x * 0.5f + r;
		return AABB(-Vector3(h, h, h), Vector3(h, h, h) * 2);
	}
	if (area_shape == AREA_SHAPE_TUBE) {
		const real_t radius = area_size.y * 0.5f;
		const Vector3 h(area_size.x * 0.5f + radius + r, radius + r, radius + r);
		return AABB(-h, h * 2);
	}
	const real_t half_a = area_size.x * 0.5f + r;
	const real_t half_b = area_size.y * 0.5f + r;
	return AABB(-Vector3(half_a, half_b, r), Vector3(half_a * 2, half_b * 2, r));
}

void AreaLight3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_area_shape", "shape"), &AreaLight3D::set_area_shape);
	ClassDB::bind_method(D_METHOD("get_area_shape"), &AreaLight3D::get_area_shape);
	ClassDB::bind_method(D_METHOD("set_area_size", "size"), &AreaLight3D::set_area_size);
	ClassDB::bind_method(D_METHOD("get_area_size"), &AreaLight3D::get_area_size);
	ClassDB::bind_method(D_METHOD("set_area_normalize_energy", "enabled"), &AreaLight3D::set_area_normalize_energy);
	ClassDB::bind_method(D_METHOD("is_area_normalizing_energy"), &AreaLight3D::is_area_normalizing_energy);
	ClassDB::bind_method(D_METHOD("set_area_shading_method", "method"), &AreaLight3D::set_area_shading_method);
	ClassDB::bind_method(D_METHOD("get_area_shading_method"), &AreaLight3D::get_area_shading_method);
	ClassDB::bind_method(D_METHOD("set_area_stochastic_samples", "samples"), &AreaLight3D::set_area_stochastic_samples);
	ClassDB::bind_method(D_METHOD("get_area_stochastic_samples"), &AreaLight3D::get_area_stochastic_samples);
	ClassDB::bind_method(D_METHOD("set_area_shadow_mode", "mode"), &AreaLight3D::set_area_shadow_mode);
	ClassDB::bind_method(D_METHOD("get_area_shadow_mode"), &AreaLight3D::get_area_shadow_mode);
	ClassDB::bind_method(D_METHOD("set_area_shadow_grid", "grid"), &AreaLight3D::set_area_shadow_grid);
	ClassDB::bind_method(D_METHOD("get_area_shadow_grid"), &AreaLight3D::get_area_shadow_grid);
	ClassDB::bind_method(D_METHOD("set_area_texture", "texture"), &AreaLight3D::set_area_texture);
	ClassDB::bind_method(D_METHOD("get_area_texture"), &AreaLight3D::get_area_texture);

	ADD_GROUP("Area", "area_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "area_shape", PROPERTY_HINT_ENUM, "Rectangle,Disk,Sphere,Tube"), "set_area_shape", "get_area_shape");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR2, "area_size", PROPERTY_HINT_RANGE, "0,4096,0.001,or_greater,suffix:m"), "set_area_size", "get_area_size");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "area_texture", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_area_texture", "get_area_texture");
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "area_range", PROPERTY_HINT_RANGE, "0,4096,0.001,or_greater,exp,suffix:m"), "set_param", "get_param", PARAM_RANGE);
	ADD_PROPERTYI(PropertyInfo(Variant::FLOAT, "area_attenuation", PROPERTY_HINT_RANGE, "0,10,0.001,or_greater"), "set_param", "get_param", PARAM_ATTENUATION);
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "area_normalize_energy"), "set_area_normalize_energy", "is_area_normalizing_energy");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "area_shading_method", PROPERTY_HINT_ENUM, "LTC,LTC Polynomial,MRP,Stochastic,Auto,LTC 2-Lobe"), "set_area_shading_method", "get_area_shading_method");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "area_stochastic_samples", PROPERTY_HINT_RANGE, "1,256"), "set_area_stochastic_samples", "get_area_stochastic_samples");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "area_shadow_mode", PROPERTY_HINT_ENUM, "Fixed,PCSS Baseline,Adaptive,Heuristic"), "set_area_shadow_mode", "get_area_shadow_mode");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "area_shadow_grid", PROPERTY_HINT_RANGE, "2,9"), "set_area_shadow_grid", "get_area_shadow_grid");
	ADD_GROUP("", "");

	BIND_ENUM_CONSTANT(AREA_SHAPE_RECTANGLE);
	BIND_ENUM_CONSTANT(AREA_SHAPE_DISK);
	BIND_ENUM_CONSTANT(AREA_SHAPE_SPHERE);
	BIND_ENUM_CONSTANT(AREA_SHAPE_TUBE);
	BIND_ENUM_CONSTANT(AREA_SHADING_LTC);
	BIND_ENUM_CONSTANT(AREA_SHADING_LTC_POLYNOMIAL);
	BIND_ENUM_CONSTANT(AREA_SHADING_MRP);
	BIND_ENUM_CONSTANT(AREA_SHADING_STOCHASTIC);
	BIND_ENUM_CONSTANT(AREA_SHADING_AUTO);
	BIND_ENUM_CONSTANT(AREA_SHADING_LTC_2LOBE);
	BIND_ENUM_CONSTANT(AREA_SHADOW_FIXED);
	BIND_ENUM_CONSTANT(AREA_SHADOW_PCSS_BASELINE);
	BIND_ENUM_CONSTANT(AREA_SHADOW_ADAPTIVE);
	BIND_ENUM_CONSTANT(AREA_SHADOW_HEURISTIC);
}

AreaLight3D::AreaLight3D() :
		Light3D(RS::LIGHT_AREA) {
	// Upstream Godot 4.7's AreaLight3D defaults (range 5, attenuation 1, shadow_bias 0.1 and
	// shadow_normal_bias 1 come from Light3D), pushed to the server.
	set_param(PARAM_SPECULAR, 1.0f);
	set_param(PARAM_SIZE, 0.5f);
	set_area_shape(AREA_SHAPE_RECTANGLE);
	set_area_size(Vector2(1, 1));
	set_area_normalize_energy(true);
	set_area_shading_method(AREA_SHADING_LTC);
	set_area_stochastic_samples(RS::LIGHT_AREA_STOCHASTIC_SAMPLES_DEFAULT);
	set_area_shadow_mode(AREA_SHADOW_FIXED);
	set_area_shadow_grid(RS::LIGHT_AREA_SHADOW_GRID_DEFAULT);
}
