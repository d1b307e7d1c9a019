/**************************************************************************/
/*  mesh_storage.h                                                        */
/**************************************************************************/
/* godot-area: mesh storage on the RenderingDevice (Godot's               */
/* RendererRD::MeshStorage, reduced). Every surface keeps its CPU         */
/* SurfaceData and, when a RenderingDevice is up, GPU vertex buffers in   */
/* the scene shader's vertex format: location 0 position (vec3),          */
/* 1 normal (vec3), 2 tangent (vec4), 3 uv (vec2), one buffer each.       */
/* Missing normals are computed from the triangles (area weighted),       */
/* missing tangents are built perpendicular to the normal, missing UVs    */
/* are zero. Winding as Godot: front faces are clockwise (seen from the  */
/* front); RenderForwardClustered culls with that convention.             */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/storage/mesh_storage.h"

namespace RendererRD {

class MeshStorage : public RendererMeshStorage {
public:
	// GPU handles of one surface (valid during the current call only).
	struct SurfaceGPU {
		RID vertex_array;
		RID index_array; // Invalid for non-indexed surfaces.
		uint32_t vertex_count = 0;
		uint32_t index_count = 0;
		bool has_colors = false; // ARRAY_COLOR given; without it the colour stream is a stand-in (unread).
	};

private:
	struct Surface {
		RS::SurfaceData data;
		RID material;
		RID buffers[5]; // position, normal, tangent, uv, colour (invalid without ARRAY_COLOR)
		RID index_buffer;
		SurfaceGPU gpu;
	};
	struct Mesh {
		std::vector<Surface> surfaces;
		AABB aabb;
	};

	mutable RID_Owner<Mesh, true> mesh_owner{ "RendererRD::Mesh" };
	RD::VertexFormatID vertex_format = RD::INVALID_FORMAT_ID;

	void _create_surface_gpu(Surface &r_surface);
	void _free_surface_gpu(Surface &r_surface);

public:
	// The scene shader's vertex format (created on first use; needs a RenderingDevice).
	RD::VertexFormatID get_vertex_format();
	// GPU data of a surface, or nullptr (no RenderingDevice, invalid mesh or index).
	const SurfaceGPU *mesh_surface_get_gpu(RID p_mesh, int p_surface) const;

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

	MeshStorage() {}
	~MeshStorage();
};

} // namespace RendererRD
