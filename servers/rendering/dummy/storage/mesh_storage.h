/**************************************************************************/
/*  mesh_storage.h                                                        */
/**************************************************************************/
/* godot-area: CPU-only mesh storage (dummy backend).                     */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/storage/mesh_storage.h"

namespace RendererDummy {

class MeshStorage : public RendererMeshStorage {
	struct Surface {
		RS::SurfaceData data;
		RID material;
	};
	struct Mesh {
		std::vector<Surface> surfaces;
		AABB aabb;
	};

	mutable RID_Owner<Mesh, true> mesh_owner{ "Mesh" };

public:
	RID mesh_create() override;
	bool mesh_free(RID p_rid) override;
	bool owns_mesh(RID p_rid) const override { return mesh_owner.owns(p_rid); }
	void mesh_add_surface(RID p_mesh, const RS::SurfaceData &p_surface) override;
	int mesh_get_surface_count(RID p_mesh) const override;
	const RS::SurfaceData *mesh_get_surface(RID p_mesh, int p_surface) const override;
	void mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) override;
	RID mesh_surface_get_material(RID p_mesh, int p_surface) const override;
	AABB mesh_get_aabb(RID p_mesh) const override;
	void mesh_clear(RID p_mesh) override;
};

} // namespace RendererDummy
