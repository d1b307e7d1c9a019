/**************************************************************************/
/*  mesh_storage.h                                                        */
/**************************************************************************/
/* godot-area: abstract mesh storage (Godot's RendererMeshStorage).       */
/* Implementations keep the CPU SurfaceData (mesh_get_surface) so the     */
/* dummy backend, tests and the reference renderer can read it back.      */

#pragma once

#include "servers/rendering_server.h"

class RendererMeshStorage {
public:
	// Checks a surface: non-empty vertices, matching per-vertex array sizes, tangents 4 per vertex,
	// indices a multiple of 3 and in range (or a vertex count multiple of 3 when non-indexed), finite
	// positions. Prints an error naming the problem and returns false when invalid.
	static bool validate_surface(const RS::SurfaceData &p_surface);
	// Returns the AABB enclosing all vertices of a surface.
	static AABB compute_surface_aabb(const RS::SurfaceData &p_surface);

	// Creates an empty mesh.
	virtual RID mesh_create() = 0;
	// Frees a mesh; returns false if this storage does not own p_rid.
	virtual bool mesh_free(RID p_rid) = 0;
	// Returns true if p_rid is a mesh of this storage.
	virtual bool owns_mesh(RID p_rid) const = 0;
	// Appends a validated surface (its aabb is computed here).
	virtual void mesh_add_surface(RID p_mesh, const RS::SurfaceData &p_surface) = 0;
	// Returns the surface count (0 for an invalid mesh).
	virtual int mesh_get_surface_count(RID p_mesh) const = 0;
	// Returns the CPU data of a surface, or nullptr. Valid only during the current call.
	virtual const RS::SurfaceData *mesh_get_surface(RID p_mesh, int p_surface) const = 0;
	// Sets a surface material.
	virtual void mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) = 0;
	// Returns a surface material, or RID().
	virtual RID mesh_surface_get_material(RID p_mesh, int p_surface) const = 0;
	// Returns the union of all surface AABBs (object space).
	virtual AABB mesh_get_aabb(RID p_mesh) const = 0;
	// Removes all surfaces.
	virtual void mesh_clear(RID p_mesh) = 0;

	virtual ~RendererMeshStorage() {}
};
