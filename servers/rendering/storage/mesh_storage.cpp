/**************************************************************************/
/*  mesh_storage.cpp                                                      */
/**************************************************************************/
/* godot-area: shared helpers of the abstract mesh storage.               */

#include "servers/rendering/storage/mesh_storage.h"

#include "core/error/error_macros.h"

bool RendererMeshStorage::validate_surface(const RS::SurfaceData &p_surface) {
	const size_t count = p_surface.vertices.size();
	ERR_FAIL_COND_V_MSG(count == 0, false, "Surface has no vertices (ARRAY_VERTEX is empty).");
	ERR_FAIL_COND_V_MSG(count > 0xFFFFFFFFu, false, "Surface has too many vertices for 32-bit indices.");
	ERR_FAIL_COND_V_MSG(!p_surface.normals.empty() && p_surface.normals.size() != count, false,
			vformat("ARRAY_NORMAL has %zu entries, expected 0 or %zu (one per vertex).", p_surface.normals.size(), count));
	ERR_FAIL_COND_V_MSG(!p_surface.tangents.empty() && p_surface.tangents.size() != count * 4, false,
			vformat("ARRAY_TANGENT has %zu floats, expected 0 or %zu (four per vertex).", p_surface.tangents.size(), count * 4));
	ERR_FAIL_COND_V_MSG(!p_surface.colors.empty() && p_surface.colors.size() != count, false,
			vformat("ARRAY_COLOR has %zu entries, expected 0 or %zu (one per vertex).", p_surface.colors.size(), count));
	ERR_FAIL_COND_V_MSG(!p_surface.uvs.empty() && p_surface.uvs.size() != count, false,
			vformat("ARRAY_TEX_UV has %zu entries, expected 0 or %zu (one per vertex).", p_surface.uvs.size(), count));
	if (p_surface.indices.empty()) {
		ERR_FAIL_COND_V_MSG(count % 3 != 0, false, vformat("Non-indexed surface has %zu vertices, expected a multiple of 3 (triangle list).", count));
	} else {
		ERR_FAIL_COND_V_MSG(p_surface.indices.size() % 3 != 0, false, vformat("ARRAY_INDEX has %zu entries, expected a multiple of 3 (triangle list).", p_surface.indices.size()));
		for (size_t i = 0; i < p_surface.indices.size(); i++) {
			ERR_FAIL_COND_V_MSG(p_surface.indices[i] >= count, false, vformat("ARRAY_INDEX[%zu] = %u is out of range (vertex count %zu).", i, p_surface.indices[i], count));
		}
	}
	for (size_t i = 0; i < count; i++) {
		ERR_FAIL_COND_V_MSG(!p_surface.vertices[i].is_finite(), false, vformat("ARRAY_VERTEX[%zu] is not finite.", i));
	}
	return true;
}

AABB RendererMeshStorage::compute_surface_aabb(const RS::SurfaceData &p_surface) {
	if (p_surface.vertices.empty()) {
		return AABB();
	}
	AABB aabb(p_surface.vertices[0], Vector3());
	for (size_t i = 1; i < p_surface.vertices.size(); i++) {
		aabb.expand_to(p_surface.vertices[i]);
	}
	return aabb;
}
