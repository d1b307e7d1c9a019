/**************************************************************************/
/*  world_3d.h                                                            */
/**************************************************************************/
/* godot-area: the 3D world a node tree renders into: one RS scenario and */
/* the environment a WorldEnvironment node puts there. A SceneTree owns   */
/* one (Godot's Viewport does); Node3D::get_world_3d() returns it.        */

#pragma once

#include "core/io/resource.h"
#include "scene/resources/environment.h"

class World3D : public Resource {
	GDCLASS(World3D, Resource);

	RID scenario;
	Ref<Environment> environment;

protected:
	static void _bind_methods();

public:
	RID get_scenario() const { return scenario; }

	// Attaches the environment to the scenario (null removes it).
	void set_environment(const Ref<Environment> &p_environment);
	Ref<Environment> get_environment() const { return environment; }

	World3D();
	~World3D() override;
};
