/**************************************************************************/
/*  resource.h                                                            */
/**************************************************************************/
/* Base class of shareable data (textures, materials, meshes, scenes).    */
/* A resource with a path is external (ext_resource in scene files); one  */
/* without is embedded (sub_resource) and keeps a scene-unique id.        */

#pragma once

#include "core/object/ref_counted.h"
#include "core/templates/rid.h"

#include <cstdint>

class Resource : public RefCounted {
	GDCLASS(Resource, RefCounted);

	String path;
	String name;
	String scene_unique_id;
	uint64_t version = 0;

protected:
	static void _bind_methods();

public:
	// Bound as "resource_path" (editor only, not saved).
	void set_path(const String &p_path);
	String get_path() const { return path; }
	// Bound as "resource_name" (saved).
	void set_name(const String &p_name);
	String get_name() const { return name; }
	// The id used for this resource in [sub_resource ... id="..."].
	void set_scene_unique_id(const String &p_id) { scene_unique_id = p_id; }
	String get_scene_unique_id() const { return scene_unique_id; }

	// Server-side handle (texture, mesh...). Invalid by default.
	virtual RID get_rid() const { return RID(); }

	// Call when the data changed; bumps a counter users can poll.
	void emit_changed() { version++; }
	uint64_t get_version() const { return version; }

	Resource() {}
};
