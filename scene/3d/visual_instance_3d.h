/**************************************************************************/
/*  visual_instance_3d.h                                                  */
/**************************************************************************/
/* godot-area: a Node3D that the RenderingServer draws. It owns one RS    */
/* instance RID (created in the constructor, freed in the destructor);    */
/* subclasses attach their resource as its base with set_base(). Inside  */
/* the tree the instance lives in the World3D scenario, follows the       */
/* global transform and is visible when is_visible_in_tree().             */

#pragma once

#include "core/math/aabb.h"
#include "scene/3d/node_3d.h"

class VisualInstance3D : public Node3D {
	GDCLASS(VisualInstance3D, Node3D);

	RID instance;
	RID base;
	uint32_t layers = 1;

protected:
	static void _bind_methods();
	void _notification(int p_what);

	// Sends the visibility to the server; Light3D adds its editor_only rule.
	virtual void _update_instance_visibility();

public:
	RID get_instance() const { return instance; }
	// Attaches the resource RID (mesh, light) the instance draws; RID() detaches.
	void set_base(RID p_base);
	RID get_base() const { return base; }

	// Render layers (bit i = layer i + 1), matched against light and camera cull masks.
	void set_layer_mask(uint32_t p_mask);
	uint32_t get_layer_mask() const { return layers; }
	void set_layer_mask_value(int p_layer_number, bool p_value);
	bool get_layer_mask_value(int p_layer_number) const;

	// Local-space bounds of what is drawn.
	virtual AABB get_aabb() const { return AABB(); }

	VisualInstance3D();
	~VisualInstance3D() override;
};
