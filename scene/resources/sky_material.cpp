/**************************************************************************/
/*  sky_material.cpp                                                      */
/**************************************************************************/

#include "scene/resources/sky_material.h"

#include "core/error/error_macros.h"

#include <cmath>

void ProceduralSkyMaterial::_push() {
	RS *rs = RS::get_singleton();
	if (rs && material.is_valid()) {
		rs->sky_material_set_procedural(material, params);
	}
	emit_changed();
}

bool ProceduralSkyMaterial::_check(float p_value, float p_min, float p_max, const char *p_property) {
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_value) || p_value < p_min || p_value > p_max, false,
			vformat("ProceduralSkyMaterial: %s must be finite and in %s..%s; got %s. The old value is kept.", p_property, rtos(p_min).c_str(), rtos(p_max).c_str(), rtos(p_value).c_str()));
	return true;
}

#define SKY_COLOR_SETTER(m_name, m_field, m_property)                                                                            \
	void ProceduralSkyMaterial::m_name(const Color &p_color) {                                                                   \
		ERR_FAIL_COND_MSG(!p_color.is_finite(), "ProceduralSkyMaterial: " m_property " must be finite; the old value is kept."); \
		params.m_field = p_color;                                                                                                \
		_push();                                                                                                                 \
	}

#define SKY_FLOAT_SETTER(m_name, m_field, m_min, m_max, m_property) \
	void ProceduralSkyMaterial::m_name(float p_value) {             \
		if (_check(p_value, m_min, m_max, m_property)) {            \
			params.m_field = p_value;                               \
			_push();                                                \
		}                                                           \
	}

SKY_COLOR_SETTER(set_sky_top_color, sky_top_color, "sky_top_color")
SKY_COLOR_SETTER(set_sky_horizon_color, sky_horizon_color, "sky_horizon_color")
SKY_COLOR_SETTER(set_ground_bottom_color, ground_bottom_color, "ground_bottom_color")
SKY_COLOR_SETTER(set_ground_horizon_color, ground_horizon_color, "ground_horizon_color")
SKY_FLOAT_SETTER(set_sky_curve, sky_curve, 0.0f, 1.0f, "sky_curve")
SKY_FLOAT_SETTER(set_sky_energy_multiplier, sky_energy_multiplier, 0.0f, 1e6f, "sky_energy_multiplier")
SKY_FLOAT_SETTER(set_ground_curve, ground_curve, 0.0f, 1.0f, "ground_curve")
SKY_FLOAT_SETTER(set_ground_energy_multiplier, ground_energy_multiplier, 0.0f, 1e6f, "ground_energy_multiplier")
SKY_FLOAT_SETTER(set_sun_angle_max, sun_angle_max, 0.0f, 360.0f, "sun_angle_max")
SKY_FLOAT_SETTER(set_sun_curve, sun_curve, 0.0f, 1.0f, "sun_curve")
SKY_FLOAT_SETTER(set_energy_multiplier, energy_multiplier, 0.0f, 1e6f, "energy_multiplier")

void ProceduralSkyMaterial::set_sky_cover(const Ref<Texture2D> &p_cover) {
	sky_cover = p_cover;
	if (p_cover.is_valid()) {
		WARN_PRINT("ProceduralSkyMaterial: sky_cover is stored but not drawn (no cloud layer in this renderer).");
	}
	emit_changed();
}

void ProceduralSkyMaterial::set_sky_cover_modulate(const Color &p_color) {
	ERR_FAIL_COND_MSG(!p_color.is_finite(), "ProceduralSkyMaterial: sky_cover_modulate must be finite; the old value is kept.");
	sky_cover_modulate = p_color;
	emit_changed();
}

void ProceduralSkyMaterial::set_use_debanding(bool p_enable) {
	use_debanding = p_enable; // Stored: the HDR target has no 8-bit banding to hide.
	emit_changed();
}

void ProceduralSkyMaterial::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_sky_top_color", "color"), &ProceduralSkyMaterial::set_sky_top_color);
	ClassDB::bind_method(D_METHOD("get_sky_top_color"), &ProceduralSkyMaterial::get_sky_top_color);
	ClassDB::bind_method(D_METHOD("set_sky_horizon_color", "color"), &ProceduralSkyMaterial::set_sky_horizon_color);
	ClassDB::bind_method(D_METHOD("get_sky_horizon_color"), &ProceduralSkyMaterial::get_sky_horizon_color);
	ClassDB::bind_method(D_METHOD("set_sky_curve", "curve"), &ProceduralSkyMaterial::set_sky_curve);
	ClassDB::bind_method(D_METHOD("get_sky_curve"), &ProceduralSkyMaterial::get_sky_curve);
	ClassDB::bind_method(D_METHOD("set_sky_energy_multiplier", "multiplier"), &ProceduralSkyMaterial::set_sky_energy_multiplier);
	ClassDB::bind_method(D_METHOD("get_sky_energy_multiplier"), &ProceduralSkyMaterial::get_sky_energy_multiplier);
	ClassDB::bind_method(D_METHOD("set_sky_cover", "sky_cover"), &ProceduralSkyMaterial::set_sky_cover);
	ClassDB::bind_method(D_METHOD("get_sky_cover"), &ProceduralSkyMaterial::get_sky_cover);
	ClassDB::bind_method(D_METHOD("set_sky_cover_modulate", "color"), &ProceduralSkyMaterial::set_sky_cover_modulate);
	ClassDB::bind_method(D_METHOD("get_sky_cover_modulate"), &ProceduralSkyMaterial::get_sky_cover_modulate);
	ClassDB::bind_method(D_METHOD("set_ground_bottom_color", "color"), &ProceduralSkyMaterial::set_ground_bottom_color);
	ClassDB::bind_method(D_METHOD("get_ground_bottom_color"), &ProceduralSkyMaterial::get_ground_bottom_color);
	ClassDB::bind_method(D_METHOD("set_ground_horizon_color", "color"), &ProceduralSkyMaterial::set_ground_horizon_color);
	ClassDB::bind_method(D_METHOD("get_ground_horizon_color"), &ProceduralSkyMaterial::get_ground_horizon_color);
	ClassDB::bind_method(D_METHOD("set_ground_curve", "curve"), &ProceduralSkyMaterial::set_ground_curve);
	ClassDB::bind_method(D_METHOD("get_ground_curve"), &ProceduralSkyMaterial::get_ground_curve);
	ClassDB::bind_method(D_METHOD("set_ground_energy_multiplier", "energy"), &ProceduralSkyMaterial::set_ground_energy_multiplier);
	ClassDB::bind_method(D_METHOD("get_ground_energy_multiplier"), &ProceduralSkyMaterial::get_ground_energy_multiplier);
	ClassDB::bind_method(D_METHOD("set_sun_angle_max", "degrees"), &ProceduralSkyMaterial::set_sun_angle_max);
	ClassDB::bind_method(D_METHOD("get_sun_angle_max"), &ProceduralSkyMaterial::get_sun_angle_max);
	ClassDB::bind_method(D_METHOD("set_sun_curve", "curve"), &ProceduralSkyMaterial::set_sun_curve);
	ClassDB::bind_method(D_METHOD("get_sun_curve"), &ProceduralSkyMaterial::get_sun_curve);
	ClassDB::bind_method(D_METHOD("set_use_debanding", "use_debanding"), &ProceduralSkyMaterial::set_use_debanding);
	ClassDB::bind_method(D_METHOD("get_use_debanding"), &ProceduralSkyMaterial::get_use_debanding);
	ClassDB::bind_method(D_METHOD("set_energy_multiplier", "multiplier"), &ProceduralSkyMaterial::set_energy_multiplier);
	ClassDB::bind_method(D_METHOD("get_energy_multiplier"), &ProceduralSkyMaterial::get_energy_multiplier);

	ADD_GROUP("Sky", "sky_");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "sky_top_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_sky_top_color", "get_sky_top_color");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "sky_horizon_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_sky_horizon_color", "get_sky_horizon_color");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "sky_curve", PROPERTY_HINT_EXP_EASING), "set_sky_curve", "get_sky_curve");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "sky_energy_multiplier", PROPERTY_HINT_RANGE, "0,64,0.01"), "set_sky_energy_multiplier", "get_sky_energy_multiplier");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "sky_cover", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_sky_cover", "get_sky_cover");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "sky_cover_modulate"), "set_sky_cover_modulate", "get_sky_cover_modulate");
	ADD_GROUP("Ground", "ground_");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "ground_bottom_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_ground_bottom_color", "get_ground_bottom_color");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "ground_horizon_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_ground_horizon_color", "get_ground_horizon_color");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ground_curve", PROPERTY_HINT_EXP_EASING), "set_ground_curve", "get_ground_curve");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ground_energy_multiplier", PROPERTY_HINT_RANGE, "0,64,0.01"), "set_ground_energy_multiplier", "get_ground_energy_multiplier");
	ADD_GROUP("Sun", "sun_");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "sun_angle_max", PROPERTY_HINT_RANGE, "0,360,0.01,degrees"), "set_sun_angle_max", "get_sun_angle_max");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "sun_curve", PROPERTY_HINT_EXP_EASING), "set_sun_curve", "get_sun_curve");
	ADD_GROUP("", "");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "use_debanding"), "set_use_debanding", "get_use_debanding");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "energy_multiplier", PROPERTY_HINT_RANGE, "0,128,0.01"), "set_energy_multiplier", "get_energy_multiplier");
}

ProceduralSkyMaterial::ProceduralSkyMaterial() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "ProceduralSkyMaterial needs a RenderingServer; create one first.");
	material = rs->sky_material_create();
	rs->sky_material_set_procedural(material, params);
}

ProceduralSkyMaterial::~ProceduralSkyMaterial() {
	RS *rs = RS::get_singleton();
	if (rs && material.is_valid()) {
		rs->free(material);
	}
}

/* PhysicalSkyMaterial */

void PhysicalSkyMaterial::_push() {
	RS *rs = RS::get_singleton();
	if (rs && material.is_valid()) {
		rs->sky_material_set_physical(material, params);
	}
	emit_changed();
}

bool PhysicalSkyMaterial::_check(float p_value, float p_min, float p_max, const char *p_property) {
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_value) || p_value < p_min || p_value > p_max, false,
			vformat("PhysicalSkyMaterial: %s must be finite and in %s..%s; got %s. The old value is kept.", p_property, rtos(p_min).c_str(), rtos(p_max).c_str(), rtos(p_value).c_str()));
	return true;
}

#define PHYSICAL_COLOR_SETTER(m_name, m_field, m_property)                                                                     \
	void PhysicalSkyMaterial::m_name(const Color &p_color) {                                                                   \
		ERR_FAIL_COND_MSG(!p_color.is_finite(), "PhysicalSkyMaterial: " m_property " must be finite; the old value is kept."); \
		params.m_field = p_color;                                                                                              \
		_push();                                                                                                               \
	}

#define PHYSICAL_FLOAT_SETTER(m_name, m_field, m_min, m_max, m_property) \
	void PhysicalSkyMaterial::m_name(float p_value) {                    \
		if (_check(p_value, m_min, m_max, m_property)) {                 \
			params.m_field = p_value;                                    \
			_push();                                                     \
		}                                                                \
	}

// Ranges: Godot's inspector hints (values outside them are refused with an error, as above).
PHYSICAL_FLOAT_SETTER(set_rayleigh_coefficient, rayleigh_coefficient, 0.0f, 64.0f, "rayleigh_coefficient")
PHYSICAL_COLOR_SETTER(set_rayleigh_color, rayleigh_color, "rayleigh_color")
PHYSICAL_FLOAT_SETTER(set_mie_coefficient, mie_coefficient, 0.0f, 1.0f, "mie_coefficient")
PHYSICAL_FLOAT_SETTER(set_mie_eccentricity, mie_eccentricity, -1.0f, 1.0f, "mie_eccentricity")
PHYSICAL_COLOR_SETTER(set_mie_color, mie_color, "mie_color")
PHYSICAL_FLOAT_SETTER(set_turbidity, turbidity, 0.0f, 1000.0f, "turbidity")
PHYSICAL_FLOAT_SETTER(set_sun_disk_scale, sun_disk_scale, 0.0f, 360.0f, "sun_disk_scale")
PHYSICAL_COLOR_SETTER(set_ground_color, ground_color, "ground_color")
PHYSICAL_FLOAT_SETTER(set_energy_multiplier, energy_multiplier, 0.0f, 128.0f, "energy_multiplier")

void PhysicalSkyMaterial::set_use_debanding(bool p_enable) {
	params.use_debanding = p_enable;
	_push();
}

void PhysicalSkyMaterial::set_night_sky(const Ref<Texture2D> &p_night_sky) {
	night_sky = p_night_sky;
	params.has_night_sky = p_night_sky.is_valid();
	if (p_night_sky.is_valid()) {
		WARN_PRINT("PhysicalSkyMaterial: night_sky is stored but not drawn (no sky textures in this renderer).");
	}
	_push();
}

void PhysicalSkyMaterial::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_rayleigh_coefficient", "rayleigh"), &PhysicalSkyMaterial::set_rayleigh_coefficient);
	ClassDB::bind_method(D_METHOD("get_rayleigh_coefficient"), &PhysicalSkyMaterial::get_rayleigh_coefficient);
	ClassDB::bind_method(D_METHOD("set_rayleigh_color", "color"), &PhysicalSkyMaterial::set_rayleigh_color);
	ClassDB::bind_method(D_METHOD("get_rayleigh_color"), &PhysicalSkyMaterial::get_rayleigh_color);
	ClassDB::bind_method(D_METHOD("set_mie_coefficient", "mie"), &PhysicalSkyMaterial::set_mie_coefficient);
	ClassDB::bind_method(D_METHOD("get_mie_coefficient"), &PhysicalSkyMaterial::get_mie_coefficient);
	ClassDB::bind_method(D_METHOD("set_mie_eccentricity", "eccentricity"), &PhysicalSkyMaterial::set_mie_eccentricity);
	ClassDB::bind_method(D_METHOD("get_mie_eccentricity"), &PhysicalSkyMaterial::get_mie_eccentricity);
	ClassDB::bind_method(D_METHOD("set_mie_color", "color"), &PhysicalSkyMaterial::set_mie_color);
	ClassDB::bind_method(D_METHOD("get_mie_color"), &PhysicalSkyMaterial::get_mie_color);
	ClassDB::bind_method(D_METHOD("set_turbidity", "turbidity"), &PhysicalSkyMaterial::set_turbidity);
	ClassDB::bind_method(D_METHOD("get_turbidity"), &PhysicalSkyMaterial::get_turbidity);
	ClassDB::bind_method(D_METHOD("set_sun_disk_scale", "scale"), &PhysicalSkyMaterial::set_sun_disk_scale);
	ClassDB::bind_method(D_METHOD("get_sun_disk_scale"), &PhysicalSkyMaterial::get_sun_disk_scale);
	ClassDB::bind_method(D_METHOD("set_ground_color", "color"), &PhysicalSkyMaterial::set_ground_color);
	ClassDB::bind_method(D_METHOD("get_ground_color"), &PhysicalSkyMaterial::get_ground_color);
	ClassDB::bind_method(D_METHOD("set_energy_multiplier", "multiplier"), &PhysicalSkyMaterial::set_energy_multiplier);
	ClassDB::bind_method(D_METHOD("get_energy_multiplier"), &PhysicalSkyMaterial::get_energy_multiplier);
	ClassDB::bind_method(D_METHOD("set_use_debanding", "use_debanding"), &PhysicalSkyMaterial::set_use_debanding);
	ClassDB::bind_method(D_METHOD("get_use_debanding"), &PhysicalSkyMaterial::get_use_debanding);
	ClassDB::bind_method(D_METHOD("set_night_sky", "night_sky"), &PhysicalSkyMaterial::set_night_sky);
	ClassDB::bind_method(D_METHOD("get_night_sky"), &PhysicalSkyMaterial::get_night_sky);

	ADD_GROUP("Rayleigh", "rayleigh_");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "rayleigh_coefficient", PROPERTY_HINT_RANGE, "0,64,0.01"), "set_rayleigh_coefficient", "get_rayleigh_coefficient");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "rayleigh_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_rayleigh_color", "get_rayleigh_color");
	ADD_GROUP("Mie", "mie_");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "mie_coefficient", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_mie_coefficient", "get_mie_coefficient");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "mie_eccentricity", PROPERTY_HINT_RANGE, "-1,1,0.01"), "set_mie_eccentricity", "get_mie_eccentricity");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "mie_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_mie_color", "get_mie_color");
	ADD_GROUP("", "");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "turbidity", PROPERTY_HINT_RANGE, "0,1000,0.01"), "set_turbidity", "get_turbidity");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "sun_disk_scale", PROPERTY_HINT_RANGE, "0,360,0.01"), "set_sun_disk_scale", "get_sun_disk_scale");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "ground_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_ground_color", "get_ground_color");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "energy_multiplier", PROPERTY_HINT_RANGE, "0,128,0.01"), "set_energy_multiplier", "get_energy_multiplier");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "use_debanding"), "set_use_debanding", "get_use_debanding");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "night_sky", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_night_sky", "get_night_sky");
}

PhysicalSkyMaterial::PhysicalSkyMaterial() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "PhysicalSkyMaterial needs a RenderingServer; create one first.");
	material = rs->sky_material_create();
	rs->sky_material_set_physical(material, params);
}

PhysicalSkyMaterial::~PhysicalSkyMaterial() {
	RS *rs = RS::get_singleton();
	if (rs && material.is_valid()) {
		rs->free(material);
	}
}
