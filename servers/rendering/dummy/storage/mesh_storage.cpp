/**************************************************************************/
/*  mesh_storage.cpp                                                      */
/**************************************************************************/

#include "servers/rendering/dummy/storage/mesh_storage.h"

#include "core/error/error_macros.h"

using namespace RendererDummy;

RID MeshStorage::mesh_create() {
	return mesh_owner.make_rid();
}

bool MeshStorage::mesh_free(RID p_rid) {
	if (!mesh_owner.owns(p_rid)) {
		return false;
	}
	mesh_owner.free(p_rid);
	return true;
}

void MeshStorage::mesh_add_surface(RID p_mesh, const RS::SurfaceData &p_surface) {
	Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_MSG(mesh, "Invalid mesh RID.");
	if (!validate_surface(p_surface)) {
		return;
	}
	Surface surface;
	surface.data = p_surface;
	surface.data.aabb = compute_surface_aabb(p_surface);
	mesh->aabb = mesh->surfaces.empty() ? surface.data.aabb : mesh->aabb.merge(surface.data.aabb);
	mesh->surfaces.push_back(std::move(surface));
}

int MeshStorage::mesh_get_surface_count(RID p_mesh) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, 0, "Invalid mesh RID.");
	return (int)mesh->surfaces.size();
}

const RS::SurfaceData *MeshStorage::mesh_get_surface(RID p_mesh, int p_surface) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, nullptr, "Invalid mesh RID.");
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)mesh->surfaces.size(), nullptr, "Surface index out of range.");
	return &mesh->surfaces[p_surface].data;
}

void MeshStorage::mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) {
	Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_MSG(mesh, "Invalid mesh RID.");
	ERR_FAIL_INDEX_MSG(p_surface, (int)mesh->surfaces.size(), "Surface index out of range.");
	mesh->surfaces[p_surface].material = p_material;
}

RID MeshStorage::mesh_surface_get_material(RID p_mesh, int p_surface) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, RID(), "Invalid mesh RID.");
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)mesh->surfaces.size(), RID(), "Surface index out of range.");
	return mesh->surfaces[p_surface].material;
}

AABB MeshStorage::mesh_get_aabb(RID p_mesh) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, AABB(), "Invalid mesh RID.");
	return mesh->aabb;
}

void MeshStorage::mesh_clear(RID p_mesh) {
	Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_MSG(mesh, "Invalid mesh RID.");
	mesh->surfaces.clear();
	mesh->aabb = AABB();
}
