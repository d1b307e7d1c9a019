/**************************************************************************/
/*  world_environment.cpp                                                 */
/**************************************************************************/

#include "scene/3d/world_environment.h"

#include "scene/main/scene_tree.h"

void WorldEnvironment::_apply() {
	SceneTree *t = get_tree();
	if (t && t->get_world_3d().is_valid()) {
		t->get_world_3d()->set_environment(environment);
	}
}

void WorldEnvironment::_remove() {
	SceneTree *t = get_tree();
	if (t && t->get_world_3d().is_valid() && environment.is_valid() && t->get_world_3d()->get_environment() == environment) {
		t->get_world_3d()->set_environment(Ref<Environment>());
	}
}

void WorldEnvironment::set_environment(const Ref<Environment> &p_environment) {
	if (is_inside_tree()) {
		_remove();
	}
	environment = p_environment;
	if (is_inside_tree() && environment.is_valid()) {
		_apply();
	}
}

void WorldEnvironment::_notification(int p_what) {
	switch (p_what) {
		case NOTIFICATION_ENTER_TREE: {
			if (environment.is_valid()) {
				_apply();
			}
		} break;
		case NOTIFICATION_EXIT_TREE: {
			_remove();
		} break;
	}
}

void WorldEnvironment::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_environment", "env"), &WorldEnvironment::set_environment);
	ClassDB::bind_method(D_METHOD("get_environment"), &WorldEnvironment::get_environment);
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "environment", PROPERTY_HINT_RESOURCE_TYPE, "Environment"), "set_environment", "get_environment");
}

WorldEnvironment::~WorldEnvironment() {
	// Deleted while inside the tree (without remove_child): still detach the environment.
	_remove();
}
