/**************************************************************************/
/*  geometry_instance_3d.h                                                */
/**************************************************************************/
/* godot-area: a VisualInstance3D that draws geometry (Godot's            */
/* GeometryInstance3D, reduced): the material override and the shadow     */
/* casting setting (RS::instance_geometry_set_cast_shadows_setting(): Off */
/* casts nothing, Shadows Only casts but is not drawn).                   */

#pragma once

#include "scene/3d/visual_instance_3d.h"
#include "scene/resources/material.h"

class GeometryInstance3D : public VisualInstance3D {
	GDCLASS(GeometryInstance3D, VisualInstance3D);

public:
	enum ShadowCastingSetting {
		SHADOW_CASTING_SETTING_OFF,
		SHADOW_CASTING_SETTING_ON,
		SHADOW_CASTING_SETTING_DOUBLE_SIDED,
		SHADOW_CASTING_SETTING_SHADOWS_ONLY,
	};

private:
	Ref<Material> material_override;
	ShadowCastingSetting shadow_casting_setting = SHADOW_CASTING_SETTING_ON;

protected:
	static void _bind_methods();
	// Sends the material that applies to every surface (override, or a subclass's choice).
	virtual void _update_material_override();

public:
	void set_material_override(const Ref<Material> &p_material);
	Ref<Material> get_material_override() const { return material_override; }

	void set_cast_shadows_setting(ShadowCastingSetting p_setting);
	ShadowCastingSetting get_cast_shadows_setting() const { return shadow_casting_setting; }

	GeometryInstance3D() {}
};

VARIANT_ENUM_CAST(GeometryInstance3D::ShadowCastingSetting);
