/**************************************************************************/
/*  geometry_instance_3d.cpp                                              */
/**************************************************************************/

#include "scene/3d/geometry_instance_3d.h"

#include "core/error/error_macros.h"
#include "servers/rendering_server.h"

void GeometryInstance3D::_update_material_override() {
	RS *rs = RS::get_singleton();
	if (rs && get_instance().is_valid()) {
		rs->instance_geometry_set_material_override(get_instance(), material_override.is_valid() ? material_override->get_rid() : RID());
	}
}

void GeometryInstance3D::set_material_override(const Ref<Material> &p_material) {
	material_override = p_material;
	_update_material_override();
}

void GeometryInstance3D::set_cast_shadows_setting(ShadowCastingSetting p_setting) {
	ERR_FAIL_INDEX_MSG((int)p_setting, 4, vformat("cast_shadow must be 0..3 (Off, On, Double-Sided, Shadows Only); got %d.", (int)p_setting));
	shadow_casting_setting = p_setting;
	RS *rs = RS::get_singleton();
	if (rs && get_instance().is_valid()) {
		rs->instance_geometry_set_cast_shadows_setting(get_instance(), RS::ShadowCastingSetting(p_setting));
	}
}

void GeometryInstance3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_material_override", "material"), &GeometryInstance3D::set_material_override);
	ClassDB::bind_method(D_METHOD("get_material_override"), &GeometryInstance3D::get_material_override);
	ClassDB::bind_method(D_METHOD("set_cast_shadows_setting", "shadow_casting_setting"), &GeometryInstance3D::set_cast_shadows_setting);
	ClassDB::bind_method(D_METHOD("get_cast_shadows_setting"), &GeometryInstance3D::get_cast_shadows_setting);

	ADD_GROUP("Geometry", "");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "material_override", PROPERTY_HINT_RESOURCE_TYPE, "BaseMaterial3D,ShaderMaterial", PROPERTY_USAGE_DEFAULT, "Material"), "set_material_override", "get_material_override");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "cast_shadow", PROPERTY_HINT_ENUM, "Off,On,Double-Sided,Shadows Only"), "set_cast_shadows_setting", "get_cast_shadows_setting");
	ADD_GROUP("", "");

	BIND_ENUM_CONSTANT(SHADOW_CASTING_SETTING_OFF);
	BIND_ENUM_CONSTANT(SHADOW_CASTING_SETTING_ON);
	BIND_ENUM_CONSTANT(SHADOW_CASTING_SETTING_DOUBLE_SIDED);
	BIND_ENUM_CONSTANT(SHADOW_CASTING_SETTING_SHADOWS_ONLY);
}
