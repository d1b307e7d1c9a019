/**************************************************************************/
/*  missing_resource.h                                                    */
/**************************************************************************/
/* godot-area: a placeholder for a resource whose type (or file format)   */
/* this engine cannot load (BoxShape3D, a GDScript, an .ogg...), in the   */
/* spirit of Godot's MissingResource. It remembers the original type; the */
/* text scene loader keeps its properties as written and the saver writes */
/* them back. A placeholder with a path stands for an ext_resource.       */

#pragma once

#include "core/io/resource.h"

class MissingResource : public Resource {
	GDCLASS(MissingResource, Resource);

	String original_class;

protected:
	static void _bind_methods();

public:
	void set_original_class(const String &p_class) { original_class = p_class; }
	String get_original_class() const { return original_class; }

	MissingResource() {}
};
