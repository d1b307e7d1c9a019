/**************************************************************************/
/*  mesh_instance_3d.h                                                    */
/**************************************************************************/
/* godot-area: draws a Mesh. Properties as Godot 4.7: `mesh`, and the     */
/* dynamic `surface_material_override/<i>` entries (one per surface).     */
/* The RS has only a whole-instance material override, so a surface       */
/* override takes effect when the mesh has exactly one surface (and no    */
/* material_override is set); with more surfaces it is stored only.       */

#pragma once

#include "scene/3d/geometry_instance_3d.h"
#include "scene/resources/mesh.h"

#include <vector>

class MeshInstance3D : public GeometryInstance3D {
	GDCLASS(MeshInstance3D, GeometryInstance3D);

	Ref<Mesh> mesh;
	std::vector<Ref<Material>> surface_override_materials;

protected:
	static void _bind_methods();
	bool _set(const String &p_name, const Variant &p_value) override;
	bool _get(const String &p_name, Variant &r_ret) const override;
	void _get_property_list(std::vector<PropertyInfo> *r_list) const override;
	void _update_material_override() override;

public:
	void set_mesh(const Ref<Mesh> &p_mesh);
	Ref<Mesh> get_mesh() const { return mesh; }

	int get_surface_override_material_count() const { return (int)surface_override_materials.size(); }
	void set_surface_override_material(int p_surface, const Ref<Material> &p_material);
	Ref<Material> get_surface_override_material(int p_surface) const;
	// Override if set, else the mesh's own surface material.
	Ref<Material> get_active_material(int p_surface) const;

	// The mesh's AABB (empty without a mesh).
	AABB get_aabb() const override;

	MeshInstance3D() {}
};
