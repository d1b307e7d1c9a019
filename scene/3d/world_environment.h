/**************************************************************************/
/*  world_environment.h                                                   */
/**************************************************************************/
/* godot-area: puts an Environment into the World3D of its SceneTree      */
/* while it is inside the tree (Godot's WorldEnvironment, environment     */
/* only). With several, the last to enter wins.                           */

#pragma once

#include "scene/main/node.h"
#include "scene/resources/environment.h"

class WorldEnvironment : public Node {
	GDCLASS(WorldEnvironment, Node);

	Ref<Environment> environment;

	void _apply();
	void _remove();

protected:
	static void _bind_methods();
	void _notification(int p_what);

public:
	void set_environment(const Ref<Environment> &p_environment);
	Ref<Environment> get_environment() const { return environment; }

	WorldEnvironment() {}
	~WorldEnvironment() override;
};
