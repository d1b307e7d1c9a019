/**************************************************************************/
/*  visual_instance_3d.cpp                                                */
/**************************************************************************/

#include "scene/3d/visual_instance_3d.h"

#include "core/error/error_macros.h"
#include "servers/rendering_server.h"

void VisualInstance3D::set_base(RID p_base) {
	base = p_base;
	RS *rs = RS::get_singleton();
	if (rs && instance.is_valid()) {
		rs->instance_set_base(instance, base);
	}
}

void VisualInstance3D::set_layer_mask(uint32_t p_mask) {
	layers = p_mask;
	RS *rs = RS::get_singleton();
	if (rs && instance.is_valid()) {
		rs->instance_set_layer_mask(instance, layers);
	}
}

void VisualInstance3D::set_layer_mask_value(int p_layer_number, bool p_value) {
	ERR_FAIL_COND_MSG(p_layer_number < 1 || p_layer_number > 20, vformat("Render layer number must be between 1 and 20 inclusive (got %d).", p_layer_number));
	uint32_t bit = 1u << (p_layer_number - 1);
	set_layer_mask(p_value ? (layers | bit) : (layers & ~bit));
}

bool VisualInstance3D::get_layer_mask_value(int p_layer_number) const {
	ERR_FAIL_COND_V_MSG(p_layer_number < 1 || p_layer_number > 20, false, vformat("Render layer number must be between 1 and 20 inclusive (got %d).", p_layer_number));
	return layers & (1u << (p_layer_number - 1));
}

void VisualInstance3D::_update_instance_visibility() {
	RS *rs = RS::get_singleton();
	if (rs && instance.is_valid() && is_inside_tree()) {
		rs->instance_set_visible(instance, is_visible_in_tree());
	}
}

void VisualInstance3D::_notification(int p_what) {
	RS *rs = RS::get_singleton();
	if (!rs || !instance.is_valid()) {
		return;
	}
	switch (p_what) {
		case NOTIFICATION_ENTER_WORLD: {
			Ref<World3D> world = get_world_3d();
			ERR_FAIL_COND_MSG(world.is_null(), vformat("VisualInstance3D \"%s\" entered the tree without a World3D.", get_name().c_str()));
			rs->instance_set_scenario(instance, world->get_scenario());
			rs->instance_set_transform(instance, get_global_transform());
			_update_instance_visibility();
		} break;
		case NOTIFICATION_TRANSFORM_CHANGED: {
			rs->instance_set_transform(instance, get_global_transform());
		} break;
		case NOTIFICATION_VISIBILITY_CHANGED: {
			_update_instance_visibility();
		} break;
		case NOTIFICATION_EXIT_WORLD: {
			rs->instance_set_scenario(instance, RID());
		} break;
	}
}

void VisualInstance3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_layer_mask", "mask"), &VisualInstance3D::set_layer_mask);
	ClassDB::bind_method(D_METHOD("get_layer_mask"), &VisualInstance3D::get_layer_mask);
	ClassDB::bind_method(D_METHOD("set_layer_mask_value", "layer_number", "value"), &VisualInstance3D::set_layer_mask_value);
	ClassDB::bind_method(D_METHOD("get_layer_mask_value", "layer_number"), &VisualInstance3D::get_layer_mask_value);

	ADD_PROPERTY(PropertyInfo(Variant::INT, "layers", PROPERTY_HINT_LAYERS_3D_RENDER), "set_layer_mask", "get_layer_mask");
}

VisualInstance3D::VisualInstance3D() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "VisualInstance3D needs a RenderingServer; create one before the scene.");
	instance = rs->instance_create();
	rs->instance_set_layer_mask(instance, layers);
}

VisualInstance3D::~VisualInstance3D() {
	RS *rs = RS::get_singleton();
	if (rs && instance.is_valid()) {
		rs->free(instance);
	}
}
