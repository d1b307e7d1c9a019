/**************************************************************************/
/*  mesh_storage.cpp                                                      */
/**************************************************************************/

#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include "core/error/error_macros.h"

#include <cmath>

using namespace RendererRD;

RD::VertexFormatID MeshStorage::get_vertex_format() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (vertex_format == RD::INVALID_FORMAT_ID && rd && rd->is_initialized()) {
		std::vector<RD::VertexAttribute> attribs(5);
		attribs[0].location = 0;
		attribs[0].format = RD::DATA_FORMAT_R32G32B32_SFLOAT;
		attribs[0].stride = 12;
		attribs[1].location = 1;
		attribs[1].format = RD::DATA_FORMAT_R32G32B32_SFLOAT;
		attribs[1].stride = 12;
		attribs[2].location = 2;
		attribs[2].format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
		attribs[2].stride = 16;
		attribs[3].location = 3;
		attribs[3].format = RD::DATA_FORMAT_R32G32_SFLOAT;
		attribs[3].stride = 8;
		attribs[4].location = 4; // ARRAY_COLOR.
		attribs[4].format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
		attribs[4].stride = 16;
		vertex_format = rd->vertex_format_create(attribs);
	}
	return vertex_format;
}

void MeshStorage::_create_surface_gpu(Surface &r_surface) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (!rd || !rd->is_initialized()) {
		return; // CPU-only use (tests without a device); the renderer needs GPU data.
	}
	const RS::SurfaceData &d = r_surface.data;
	const uint32_t count = uint32_t(d.vertices.size());

	std::vector<float> positions(count * 3);
	std::vector<float> normals(count * 3, 0.0f);
	std::vector<float> tangents(count * 4);
	std::vector<float> uvs(count * 2, 0.0f);
	for (uint32_t i = 0; i < count; i++) {
		positions[i * 3 + 0] = d.vertices[i].x;
		positions[i * 3 + 1] = d.vertices[i].y;
		positions[i * 3 + 2] = d.vertices[i].z;
	}
	if (!d.normals.empty()) {
		for (uint32_t i = 0; i < count; i++) {
			normals[i * 3 + 0] = d.normals[i].x;
			normals[i * 3 + 1] = d.normals[i].y;
			normals[i * 3 + 2] = d.normals[i].z;
		}
	} else {
		// Area-weighted face normals. Godot's winding: front faces are CLOCKWISE as seen by their viewer,
		// so the outward normal is (c - a) x (b - a).
		std::vector<Vector3> acc(count);
		uint32_t tri_count = d.indices.empty() ? count / 3 : uint32_t(d.indices.size() / 3);
		for (uint32_t t = 0; t < tri_count; t++) {
			uint32_t a = d.indices.empty() ? t * 3 : d.indices[t * 3];
			uint32_t b = d.indices.empty() ? t * 3 + 1 : d.indices[t * 3 + 1];
			uint32_t c = d.indices.empty() ? t * 3 + 2 : d.indices[t * 3 + 2];
			Vector3 n = (d.vertices[c] - d.vertices[a]).cross(d.vertices[b] - d.vertices[a]);
			acc[a] += n;
			acc[b] += n;
			acc[c] += n;
		}
		for (uint32_t i = 0; i < count; i++) {
			Vector3 n = acc[i].normalized();
			if (n == Vector3()) {
				n = Vector3(0, 1, 0);
			}
			normals[i * 3 + 0] = n.x;
			normals[i * 3 + 1] = n.y;
			normals[i * 3 + 2] = n.z;
		}
	}
	if (!d.tangents.empty()) {
		tangents = d.tangents;
	} else {
		for (uint32_t i = 0; i < count; i++) {
			Vector3 n(normals[i * 3 + 0], normals[i * 3 + 1], normals[i * 3 + 2]);
			Vector3 helper = std::fabs(n.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
			Vector3 t = (helper - n * n.dot(helper)).normalized();
			tangents[i * 4 + 0] = t.x;
			tangents[i * 4 + 1] = t.y;
			tangents[i * 4 + 2] = t.z;
			tangents[i * 4 + 3] = 1.0f;
		}
	}
	if (!d.uvs.empty()) {
		for (uint32_t i = 0; i < count; i++) {
			uvs[i * 2 + 0] = d.uvs[i].x;
			uvs[i * 2 + 1] = d.uvs[i].y;
		}
	}

	r_surface.buffers[0] = rd->vertex_buffer_create(uint32_t(positions.size() * sizeof(float)), positions.data());
	r_surface.buffers[1] = rd->vertex_buffer_create(uint32_t(normals.size() * sizeof(float)), normals.data());
	r_surface.buffers[2] = rd->vertex_buffer_create(uint32_t(tangents.size() * sizeof(float)), tangents.data());
	r_surface.buffers[3] = rd->vertex_buffer_create(uint32_t(uvs.size() * sizeof(float)), uvs.data());
	// Vertex colours only when the surface has them; otherwise the tangent stream (the same size and
	// format) stands in and the shader reads white (DRAW_FLAG_HAS_COLOR unset): no memory for a feature
	// the surface does not use.
	r_surface.gpu.has_colors = d.colors.size() == count;
	if (r_surface.gpu.has_colors) {
		std::vector<float> colors(count * 4);
		for (uint32_t i = 0; i < count; i++) {
			colors[i * 4 + 0] = d.colors[i].r;
			colors[i * 4 + 1] = d.colors[i].g;
			colors[i * 4 + 2] = d.colors[i].b;
			colors[i * 4 + 3] = d.colors[i].a;
		}
		r_surface.buffers[4] = rd->vertex_buffer_create(uint32_t(colors.size() * sizeof(float)), colors.data());
	}
	r_surface.gpu.vertex_count = count;
	r_surface.gpu.vertex_array = rd->vertex_array_create(count, get_vertex_format(), { r_surface.buffers[0], r_surface.buffers[1], r_surface.buffers[2], r_surface.buffers[3], r_surface.gpu.has_colors ? r_surface.buffers[4] : r_surface.buffers[2] });
	if (!d.indices.empty()) {
		r_surface.index_buffer = rd->index_buffer_create(uint32_t(d.indices.size()), RD::INDEX_BUFFER_FORMAT_UINT32, d.indices.data());
		r_surface.gpu.index_array = rd->index_array_create(r_surface.index_buffer, 0, uint32_t(d.indices.size()));
		r_surface.gpu.index_count = uint32_t(d.indices.size());
	}
}

void MeshStorage::_free_surface_gpu(Surface &r_surface) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized()) {
		// Arrays first, then the buffers behind them.
		if (r_surface.gpu.vertex_array.is_valid()) {
			rd->free(r_surface.gpu.vertex_array);
		}
		if (r_surface.gpu.index_array.is_valid()) {
			rd->free(r_surface.gpu.index_array);
		}
		for (int i = 0; i < 5; i++) {
			if (r_surface.buffers[i].is_valid()) {
				rd->free(r_surface.buffers[i]);
			}
		}
		if (r_surface.index_buffer.is_valid()) {
			rd->free(r_surface.index_buffer);
		}
	}
	r_surface.gpu = SurfaceGPU();
	for (int i = 0; i < 5; i++) {
		r_surface.buffers[i] = RID();
	}
	r_surface.index_buffer = RID();
}

const MeshStorage::SurfaceGPU *MeshStorage::mesh_surface_get_gpu(RID p_mesh, int p_surface) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, nullptr, "mesh_surface_get_gpu: invalid mesh RID.");
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)mesh->surfaces.size(), nullptr, "mesh_surface_get_gpu: surface index out of range.");
	const Surface &s = mesh->surfaces[p_surface];
	return s.gpu.vertex_array.is_valid() ? &s.gpu : nullptr;
}

RID MeshStorage::mesh_create() {
	return mesh_owner.make_rid();
}

bool MeshStorage::mesh_free(RID p_rid) {
	Mesh *mesh = mesh_owner.get_or_null(p_rid);
	if (!mesh) {
		return false;
	}
	for (Surface &s : mesh->surfaces) {
		_free_surface_gpu(s);
	}
	mesh_owner.free(p_rid);
	return true;
}

void MeshStorage::mesh_add_surface(RID p_mesh, const RS::SurfaceData &p_surface) {
	Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_MSG(mesh, "mesh_add_surface: invalid mesh RID.");
	if (!validate_surface(p_surface)) {
		return;
	}
	Surface surface;
	surface.data = p_surface;
	surface.data.aabb = compute_surface_aabb(p_surface);
	_create_surface_gpu(surface);
	mesh->aabb = mesh->surfaces.empty() ? surface.data.aabb : mesh->aabb.merge(surface.data.aabb);
	mesh->surfaces.push_back(std::move(surface));
}

int MeshStorage::mesh_get_surface_count(RID p_mesh) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, 0, "mesh_get_surface_count: invalid mesh RID.");
	return (int)mesh->surfaces.size();
}

const RS::SurfaceData *MeshStorage::mesh_get_surface(RID p_mesh, int p_surface) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, nullptr, "mesh_get_surface: invalid mesh RID.");
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)mesh->surfaces.size(), nullptr, "mesh_get_surface: surface index out of range.");
	return &mesh->surfaces[p_surface].data;
}

void MeshStorage::mesh_surface_set_material(RID p_mesh, int p_surface, RID p_material) {
	Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_MSG(mesh, "mesh_surface_set_material: invalid mesh RID.");
	ERR_FAIL_INDEX_MSG(p_surface, (int)mesh->surfaces.size(), "mesh_surface_set_material: surface index out of range.");
	mesh->surfaces[p_surface].material = p_material;
}

RID MeshStorage::mesh_surface_get_material(RID p_mesh, int p_surface) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, RID(), "mesh_surface_get_material: invalid mesh RID.");
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)mesh->surfaces.size(), RID(), "mesh_surface_get_material: surface index out of range.");
	return mesh->surfaces[p_surface].material;
}

AABB MeshStorage::mesh_get_aabb(RID p_mesh) const {
	const Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_V_MSG(mesh, AABB(), "mesh_get_aabb: invalid mesh RID.");
	return mesh->aabb;
}

void MeshStorage::mesh_clear(RID p_mesh) {
	Mesh *mesh = mesh_owner.get_or_null(p_mesh);
	ERR_FAIL_NULL_MSG(mesh, "mesh_clear: invalid mesh RID.");
	for (Surface &s : mesh->surfaces) {
		_free_surface_gpu(s);
	}
	mesh->surfaces.clear();
	mesh->aabb = AABB();
}

MeshStorage::~MeshStorage() {
	for (RID rid : mesh_owner.get_owned_list()) {
		mesh_free(rid);
	}
}
