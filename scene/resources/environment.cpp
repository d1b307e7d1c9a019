/**************************************************************************/
/*  environment.cpp                                                       */
/**************************************************************************/

#include "scene/resources/environment.h"

#include "core/error/error_macros.h"

static bool _env_color_is_finite(const Color &p_c) {
	return Math::is_finite(p_c.r) && Math::is_finite(p_c.g) && Math::is_finite(p_c.b) && Math::is_finite(p_c.a);
}

void Environment::_update_ambient_light() {
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_ambient_light(environment, ambient_color, RS::EnvironmentAmbientSource(ambient_source), ambient_energy);
	}
	emit_changed();
}

void Environment::set_background(BGMode p_bg) {
	ERR_FAIL_INDEX_MSG((int)p_bg, BG_MAX, vformat("background_mode must be 0..%d (Clear Color, Custom Color, Sky, Canvas, Keep, Camera Feed); got %d. The old value is kept.", BG_MAX - 1, (int)p_bg));
	bg_mode = p_bg;
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_background(environment, RS::EnvironmentBG(bg_mode));
	}
	notify_property_list_changed();
	emit_changed();
}

void Environment::set_bg_color(const Color &p_color) {
	ERR_FAIL_COND_MSG(!_env_color_is_finite(p_color), "background_color must be finite (no NaN or infinity); the old value is kept.");
	bg_color = p_color;
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_bg_color(environment, bg_color);
	}
	emit_changed();
}

void Environment::set_bg_energy_multiplier(float p_multiplier) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_multiplier) || p_multiplier < 0.0f, vformat("background_energy_multiplier must be finite and >= 0 (got %s); the old value is kept.", rtos(p_multiplier).c_str()));
	bg_energy_multiplier = p_multiplier;
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_bg_energy(environment, bg_energy_multiplier);
	}
	emit_changed();
}

void Environment::set_ambient_source(AmbientSource p_source) {
	ERR_FAIL_INDEX_MSG((int)p_source, AMBIENT_SOURCE_MAX, vformat("ambient_light_source must be 0..%d (Background, Disabled, Color, Sky); got %d. The old value is kept.", AMBIENT_SOURCE_MAX - 1, (int)p_source));
	ambient_source = p_source;
	notify_property_list_changed();
	_update_ambient_light();
}

void Environment::set_ambient_light_color(const Color &p_color) {
	ERR_FAIL_COND_MSG(!_env_color_is_finite(p_color), "ambient_light_color must be finite (no NaN or infinity); the old value is kept.");
	ambient_color = p_color;
	_update_ambient_light();
}

void Environment::set_ambient_light_energy(float p_energy) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_energy) || p_energy < 0.0f, vformat("ambient_light_energy must be finite and >= 0 (got %s); the old value is kept.", rtos(p_energy).c_str()));
	ambient_energy = p_energy;
	_update_ambient_light();
}

void Environment::set_sky(const Ref<Sky> &p_sky) {
	sky = p_sky;
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_sky(environment, p_sky.is_valid() ? p_sky->get_rid() : RID());
	}
	emit_changed();
}

void Environment::set_ambient_light_sky_contribution(float p_contribution) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_contribution), "ambient_light_sky_contribution must be finite; the old value is kept.");
	ambient_sky_contribution = Math::clamp(p_contribution, 0.0f, 1.0f);
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_ambient_sky_contribution(environment, ambient_sky_contribution);
	}
	emit_changed();
}

void Environment::set_reflection_source(ReflectionSource p_source) {
	ERR_FAIL_INDEX_MSG((int)p_source, REFLECTION_SOURCE_MAX, vformat("reflected_light_source must be 0..%d (Background, Disabled, Sky); got %d. The old value is kept.", REFLECTION_SOURCE_MAX - 1, (int)p_source));
	reflection_source = p_source;
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_reflection_source(environment, RS::EnvironmentReflectionSource(reflection_source));
	}
	emit_changed();
}

bool Environment::_check_ss_value(const char *p_property, float p_value, float p_min, float p_max) {
	ERR_FAIL_COND_V_MSG(!Math::is_finite(p_value) || p_value < p_min || p_value > p_max, false,
			vformat("%s must be finite and in %s..%s (got %s); the old value is kept.", p_property, rtos(p_min).c_str(), rtos(p_max).c_str(), rtos(p_value).c_str()));
	return true;
}

void Environment::_update_ssao() {
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_ssao(environment, ssao_enabled, ssao_radius, ssao_intensity, ssao_power, ssao_detail, ssao_horizon, ssao_sharpness, ssao_direct_light_affect, ssao_ao_channel_affect);
	}
	emit_changed();
}

void Environment::_update_ssil() {
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->environment_set_ssil(environment, ssil_enabled, ssil_radius, ssil_intensity, ssil_sharpness, ssil_normal_rejection);
	}
	emit_changed();
}

void Environment::set_ssao_enabled(bool p_enabled) {
	ssao_enabled = p_enabled;
	notify_property_list_changed();
	_update_ssao();
}

void Environment::set_ssil_enabled(bool p_enabled) {
	ssil_enabled = p_enabled;
	notify_property_list_changed();
	_update_ssil();
}

void Environment::set_ssao_radius(float p_value) {
	if (_check_ss_value("ssao_radius", p_value, 0.01f, 1e4f)) {
		ssao_radius = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_intensity(float p_value) {
	if (_check_ss_value("ssao_intensity", p_value, 0.0f, 1e4f)) {
		ssao_intensity = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_power(float p_value) {
	if (_check_ss_value("ssao_power", p_value, 0.01f, 1e4f)) {
		ssao_power = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_detail(float p_value) {
	if (_check_ss_value("ssao_detail", p_value, 0.0f, 5.0f)) {
		ssao_detail = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_horizon(float p_value) {
	if (_check_ss_value("ssao_horizon", p_value, 0.0f, 1.0f)) {
		ssao_horizon = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_sharpness(float p_value) {
	if (_check_ss_value("ssao_sharpness", p_value, 0.0f, 1.0f)) {
		ssao_sharpness = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_direct_light_affect(float p_value) {
	if (_check_ss_value("ssao_light_affect", p_value, 0.0f, 1.0f)) {
		ssao_direct_light_affect = p_value;
		_update_ssao();
	}
}

void Environment::set_ssao_ao_channel_affect(float p_value) {
	if (_check_ss_value("ssao_ao_channel_affect", p_value, 0.0f, 1.0f)) {
		ssao_ao_channel_affect = p_value;
		_update_ssao();
	}
}

void Environment::set_ssil_radius(float p_value) {
	if (_check_ss_value("ssil_radius", p_value, 0.01f, 1e4f)) {
		ssil_radius = p_value;
		_update_ssil();
	}
}

void Environment::set_ssil_intensity(float p_value) {
	if (_check_ss_value("ssil_intensity", p_value, 0.0f, 1e4f)) {
		ssil_intensity = p_value;
		_update_ssil();
	}
}

void Environment::set_ssil_sharpness(float p_value) {
	if (_check_ss_value("ssil_sharpness", p_value, 0.0f, 1.0f)) {
		ssil_sharpness = p_value;
		_update_ssil();
	}
}

void Environment::set_ssil_normal_rejection(float p_value) {
	if (_check_ss_value("ssil_normal_rejection", p_value, 0.0f, 1.0f)) {
		ssil_normal_rejection = p_value;
		_update_ssil();
	}
}

void Environment::set_tonemapper(ToneMapper p_mode) {
	ERR_FAIL_INDEX_MSG((int)p_mode, TONE_MAPPER_MAX, vformat("tonemap_mode must be 0..%d (Linear, Reinhard, Filmic, ACES, AgX); got %d. The old value is kept.", TONE_MAPPER_MAX - 1, (int)p_mode));
	tonemap_mode = p_mode;
	notify_property_list_changed();
	emit_changed();
}

void Environment::set_tonemap_exposure(float p_exposure) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_exposure) || p_exposure <= 0.0f, vformat("tonemap_exposure must be finite and > 0 (got %s); the old value is kept.", rtos(p_exposure).c_str()));
	tonemap_exposure = p_exposure;
	emit_changed();
}

void Environment::set_tonemap_white(float p_white) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_white) || p_white <= 0.0f, vformat("tonemap_white must be finite and > 0 (got %s); the old value is kept.", rtos(p_white).c_str()));
	tonemap_white = p_white;
	emit_changed();
}

Tonemap::Settings Environment::get_tonemap_settings() const {
	Tonemap::Settings settings;
	Tonemap::mode_from_godot(int(tonemap_mode), settings.mode);
	settings.exposure = tonemap_exposure;
	settings.white = tonemap_white;
	return settings;
}

Tonemap::Settings Environment::get_preview_tonemap(const Ref<Environment> &p_camera_environment, const Ref<Environment> &p_world_environment) {
	if (p_camera_environment.is_valid()) {
		return p_camera_environment->get_tonemap_settings();
	}
	if (p_world_environment.is_valid()) {
		return p_world_environment->get_tonemap_settings();
	}
	Tonemap::Settings preview;
	preview.mode = Tonemap::MODE_ACES_FITTED;
	return preview;
}

void Environment::_validate_property(PropertyInfo &p_property) const {
	// As Godot: background_color only matters for Custom Color; ambient colour/energy not when disabled.
	if (p_property.name == "background_color" && bg_mode != BG_COLOR) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	if (p_property.name == "tonemap_white" && (tonemap_mode == TONE_MAPPER_LINEAR || tonemap_mode == TONE_MAPPER_AGX)) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR; // As Godot: no white point for these two.
	}
	// As Godot: the SSAO/SSIL parameters show only while their effect is enabled (still saved).
	if (p_property.name != "ssao_enabled" && string_begins_with(p_property.name, "ssao_") && !ssao_enabled) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	if (p_property.name != "ssil_enabled" && string_begins_with(p_property.name, "ssil_") && !ssil_enabled) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	if ((p_property.name == "ambient_light_color" || p_property.name == "ambient_light_energy") && ambient_source == AMBIENT_SOURCE_DISABLED) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
}

void Environment::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_background", "mode"), &Environment::set_background);
	ClassDB::bind_method(D_METHOD("get_background"), &Environment::get_background);
	ClassDB::bind_method(D_METHOD("set_bg_color", "color"), &Environment::set_bg_color);
	ClassDB::bind_method(D_METHOD("get_bg_color"), &Environment::get_bg_color);
	ClassDB::bind_method(D_METHOD("set_bg_energy_multiplier", "energy"), &Environment::set_bg_energy_multiplier);
	ClassDB::bind_method(D_METHOD("get_bg_energy_multiplier"), &Environment::get_bg_energy_multiplier);
	ClassDB::bind_method(D_METHOD("set_ambient_source", "source"), &Environment::set_ambient_source);
	ClassDB::bind_method(D_METHOD("get_ambient_source"), &Environment::get_ambient_source);
	ClassDB::bind_method(D_METHOD("set_ambient_light_color", "color"), &Environment::set_ambient_light_color);
	ClassDB::bind_method(D_METHOD("get_ambient_light_color"), &Environment::get_ambient_light_color);
	ClassDB::bind_method(D_METHOD("set_ambient_light_energy", "energy"), &Environment::set_ambient_light_energy);
	ClassDB::bind_method(D_METHOD("get_ambient_light_energy"), &Environment::get_ambient_light_energy);

	ADD_GROUP("Background", "background_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "background_mode", PROPERTY_HINT_ENUM, "Clear Color,Custom Color,Sky,Canvas,Keep,Camera Feed"), "set_background", "get_background");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "background_color"), "set_bg_color", "get_bg_color");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "background_energy_multiplier", PROPERTY_HINT_RANGE, "0,16,0.01"), "set_bg_energy_multiplier", "get_bg_energy_multiplier");

	ClassDB::bind_method(D_METHOD("set_sky", "sky"), &Environment::set_sky);
	ClassDB::bind_method(D_METHOD("get_sky"), &Environment::get_sky);
	ClassDB::bind_method(D_METHOD("set_ambient_light_sky_contribution", "ratio"), &Environment::set_ambient_light_sky_contribution);
	ClassDB::bind_method(D_METHOD("get_ambient_light_sky_contribution"), &Environment::get_ambient_light_sky_contribution);
	ADD_GROUP("Sky", "sky_");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "sky", PROPERTY_HINT_RESOURCE_TYPE, "Sky"), "set_sky", "get_sky");
	ADD_GROUP("Ambient Light", "ambient_light_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "ambient_light_source", PROPERTY_HINT_ENUM, "Background,Disabled,Color,Sky"), "set_ambient_source", "get_ambient_source");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "ambient_light_color", PROPERTY_HINT_COLOR_NO_ALPHA), "set_ambient_light_color", "get_ambient_light_color");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ambient_light_sky_contribution", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_ambient_light_sky_contribution", "get_ambient_light_sky_contribution");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ambient_light_energy", PROPERTY_HINT_RANGE, "0,16,0.01"), "set_ambient_light_energy", "get_ambient_light_energy");
	ClassDB::bind_method(D_METHOD("set_reflection_source", "source"), &Environment::set_reflection_source);
	ClassDB::bind_method(D_METHOD("get_reflection_source"), &Environment::get_reflection_source);
	ADD_GROUP("Reflected Light", "reflected_light_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "reflected_light_source", PROPERTY_HINT_ENUM, "Background,Disabled,Sky"), "set_reflection_source", "get_reflection_source");
	ClassDB::bind_method(D_METHOD("set_tonemapper", "mode"), &Environment::set_tonemapper);
	ClassDB::bind_method(D_METHOD("get_tonemapper"), &Environment::get_tonemapper);
	ClassDB::bind_method(D_METHOD("set_tonemap_exposure", "exposure"), &Environment::set_tonemap_exposure);
	ClassDB::bind_method(D_METHOD("get_tonemap_exposure"), &Environment::get_tonemap_exposure);
	ClassDB::bind_method(D_METHOD("set_tonemap_white", "white"), &Environment::set_tonemap_white);
	ClassDB::bind_method(D_METHOD("get_tonemap_white"), &Environment::get_tonemap_white);
	ADD_GROUP("Tonemap", "tonemap_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "tonemap_mode", PROPERTY_HINT_ENUM, "Linear,Reinhard,Filmic,ACES,AgX"), "set_tonemapper", "get_tonemapper");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "tonemap_exposure", PROPERTY_HINT_RANGE, "0,16,0.01"), "set_tonemap_exposure", "get_tonemap_exposure");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "tonemap_white", PROPERTY_HINT_RANGE, "0,16,0.01"), "set_tonemap_white", "get_tonemap_white");
	ClassDB::bind_method(D_METHOD("set_ssao_enabled", "enabled"), &Environment::set_ssao_enabled);
	ClassDB::bind_method(D_METHOD("is_ssao_enabled"), &Environment::is_ssao_enabled);
	ClassDB::bind_method(D_METHOD("set_ssao_radius", "amount"), &Environment::set_ssao_radius);
	ClassDB::bind_method(D_METHOD("get_ssao_radius"), &Environment::get_ssao_radius);
	ClassDB::bind_method(D_METHOD("set_ssao_intensity", "amount"), &Environment::set_ssao_intensity);
	ClassDB::bind_method(D_METHOD("get_ssao_intensity"), &Environment::get_ssao_intensity);
	ClassDB::bind_method(D_METHOD("set_ssao_power", "amount"), &Environment::set_ssao_power);
	ClassDB::bind_method(D_METHOD("get_ssao_power"), &Environment::get_ssao_power);
	ClassDB::bind_method(D_METHOD("set_ssao_detail", "amount"), &Environment::set_ssao_detail);
	ClassDB::bind_method(D_METHOD("get_ssao_detail"), &Environment::get_ssao_detail);
	ClassDB::bind_method(D_METHOD("set_ssao_horizon", "amount"), &Environment::set_ssao_horizon);
	ClassDB::bind_method(D_METHOD("get_ssao_horizon"), &Environment::get_ssao_horizon);
	ClassDB::bind_method(D_METHOD("set_ssao_sharpness", "amount"), &Environment::set_ssao_sharpness);
	ClassDB::bind_method(D_METHOD("get_ssao_sharpness"), &Environment::get_ssao_sharpness);
	ClassDB::bind_method(D_METHOD("set_ssao_direct_light_affect", "amount"), &Environment::set_ssao_direct_light_affect);
	ClassDB::bind_method(D_METHOD("get_ssao_direct_light_affect"), &Environment::get_ssao_direct_light_affect);
	ClassDB::bind_method(D_METHOD("set_ssao_ao_channel_affect", "amount"), &Environment::set_ssao_ao_channel_affect);
	ClassDB::bind_method(D_METHOD("get_ssao_ao_channel_affect"), &Environment::get_ssao_ao_channel_affect);
	ClassDB::bind_method(D_METHOD("set_ssil_enabled", "enabled"), &Environment::set_ssil_enabled);
	ClassDB::bind_method(D_METHOD("is_ssil_enabled"), &Environment::is_ssil_enabled);
	ClassDB::bind_method(D_METHOD("set_ssil_radius", "amount"), &Environment::set_ssil_radius);
	ClassDB::bind_method(D_METHOD("get_ssil_radius"), &Environment::get_ssil_radius);
	ClassDB::bind_method(D_METHOD("set_ssil_intensity", "amount"), &Environment::set_ssil_intensity);
	ClassDB::bind_method(D_METHOD("get_ssil_intensity"), &Environment::get_ssil_intensity);
	ClassDB::bind_method(D_METHOD("set_ssil_sharpness", "amount"), &Environment::set_ssil_sharpness);
	ClassDB::bind_method(D_METHOD("get_ssil_sharpness"), &Environment::get_ssil_sharpness);
	ClassDB::bind_method(D_METHOD("set_ssil_normal_rejection", "amount"), &Environment::set_ssil_normal_rejection);
	ClassDB::bind_method(D_METHOD("get_ssil_normal_rejection"), &Environment::get_ssil_normal_rejection);
	ADD_GROUP("SSAO", "ssao_");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "ssao_enabled"), "set_ssao_enabled", "is_ssao_enabled");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_radius", PROPERTY_HINT_RANGE, "0.01,16,0.01,or_greater,suffix:m"), "set_ssao_radius", "get_ssao_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_intensity", PROPERTY_HINT_RANGE, "0,16,0.01,or_greater"), "set_ssao_intensity", "get_ssao_intensity");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_power", PROPERTY_HINT_RANGE, "0.01,16,0.01,or_greater"), "set_ssao_power", "get_ssao_power");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_detail", PROPERTY_HINT_RANGE, "0,5,0.01"), "set_ssao_detail", "get_ssao_detail");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_horizon", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_ssao_horizon", "get_ssao_horizon");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_sharpness", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_ssao_sharpness", "get_ssao_sharpness");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_light_affect", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_ssao_direct_light_affect", "get_ssao_direct_light_affect");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssao_ao_channel_affect", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_ssao_ao_channel_affect", "get_ssao_ao_channel_affect");
	ADD_GROUP("SSIL", "ssil_");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "ssil_enabled"), "set_ssil_enabled", "is_ssil_enabled");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssil_radius", PROPERTY_HINT_RANGE, "0.01,16,0.01,or_greater,suffix:m"), "set_ssil_radius", "get_ssil_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssil_intensity", PROPERTY_HINT_RANGE, "0,16,0.01,or_greater"), "set_ssil_intensity", "get_ssil_intensity");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssil_sharpness", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_ssil_sharpness", "get_ssil_sharpness");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "ssil_normal_rejection", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_ssil_normal_rejection", "get_ssil_normal_rejection");
	ADD_GROUP("", "");

	BIND_ENUM_CONSTANT(BG_CLEAR_COLOR);
	BIND_ENUM_CONSTANT(BG_COLOR);
	BIND_ENUM_CONSTANT(BG_SKY);
	BIND_ENUM_CONSTANT(BG_CANVAS);
	BIND_ENUM_CONSTANT(BG_KEEP);
	BIND_ENUM_CONSTANT(BG_CAMERA_FEED);
	BIND_ENUM_CONSTANT(BG_MAX);
	BIND_ENUM_CONSTANT(REFLECTION_SOURCE_BG);
	BIND_ENUM_CONSTANT(REFLECTION_SOURCE_DISABLED);
	BIND_ENUM_CONSTANT(REFLECTION_SOURCE_SKY);
	BIND_ENUM_CONSTANT(AMBIENT_SOURCE_BG);
	BIND_ENUM_CONSTANT(AMBIENT_SOURCE_DISABLED);
	BIND_ENUM_CONSTANT(AMBIENT_SOURCE_COLOR);
	BIND_ENUM_CONSTANT(AMBIENT_SOURCE_SKY);
	BIND_ENUM_CONSTANT(TONE_MAPPER_LINEAR);
	BIND_ENUM_CONSTANT(TONE_MAPPER_REINHARDT);
	BIND_ENUM_CONSTANT(TONE_MAPPER_FILMIC);
	BIND_ENUM_CONSTANT(TONE_MAPPER_ACES);
	BIND_ENUM_CONSTANT(TONE_MAPPER_AGX);
}

Environment::Environment() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "Environment needs a RenderingServer; create one first.");
	environment = rs->environment_create();
	// Push the node-side defaults so resource and server agree.
	rs->environment_set_background(environment, RS::EnvironmentBG(bg_mode));
	rs->environment_set_bg_color(environment, bg_color);
	rs->environment_set_bg_energy(environment, bg_energy_multiplier);
	rs->environment_set_ambient_light(environment, ambient_color, RS::EnvironmentAmbientSource(ambient_source), ambient_energy);
	rs->environment_set_reflection_source(environment, RS::EnvironmentReflectionSource(reflection_source));
	rs->environment_set_ssao(environment, ssao_enabled, ssao_radius, ssao_intensity, ssao_power, ssao_detail, ssao_horizon, ssao_sharpness, ssao_direct_light_affect, ssao_ao_channel_affect);
	rs->environment_set_ssil(environment, ssil_enabled, ssil_radius, ssil_intensity, ssil_sharpness, ssil_normal_rejection);
}

Environment::~Environment() {
	RS *rs = RS::get_singleton();
	if (rs && environment.is_valid()) {
		rs->free(environment);
	}
}
