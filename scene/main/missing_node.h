/**************************************************************************/
/*  missing_node.h                                                        */
/**************************************************************************/
/* godot-area: a placeholder for a scene node whose type this engine does */
/* not run (StaticBody3D, RigidBody3D, AnimationPlayer...), in the spirit */
/* of Godot's MissingNode. It acts as a Node3D (its `transform` and       */
/* `visible` apply, so children stay where they were), keeps its children */
/* and remembers the original type; the text scene loader keeps every    */
/* other property as written and the saver writes them back.             */
/* An empty original class marks an override section ([node name= parent=*/
/* ] without type) whose target was not found.                            */

#pragma once

#include "scene/3d/node_3d.h"

class MissingNode : public Node3D {
	GDCLASS(MissingNode, Node3D);

	String original_class;

protected:
	static void _bind_methods();

public:
	void set_original_class(const String &p_class) { original_class = p_class; }
	String get_original_class() const { return original_class; }

	MissingNode() {}
};
