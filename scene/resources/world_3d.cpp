/**************************************************************************/
/*  world_3d.cpp                                                          */
/**************************************************************************/

#include "scene/resources/world_3d.h"

#include "core/error/error_macros.h"
#include "servers/rendering_server.h"

void World3D::set_environment(const Ref<Environment> &p_environment) {
	environment = p_environment;
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "World3D needs a RenderingServer to attach an environment.");
	rs->scenario_set_environment(scenario, environment.is_valid() ? environment->get_rid() : RID());
}

void World3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_environment", "env"), &World3D::set_environment);
	ClassDB::bind_method(D_METHOD("get_environment"), &World3D::get_environment);
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "environment", PROPERTY_HINT_RESOURCE_TYPE, "Environment"), "set_environment", "get_environment");
}

World3D::World3D() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "World3D needs a RenderingServer; create one before the scene.");
	scenario = rs->scenario_create();
}

World3D::~World3D() {
	RS *rs = RS::get_singleton();
	if (rs && scenario.is_valid()) {
		rs->free(scenario);
	}
}
