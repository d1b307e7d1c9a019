/**************************************************************************/
/*  mesh.cpp                                                              */
/**************************************************************************/

#include "scene/resources/mesh.h"

#include "core/error/error_macros.h"

/* Mesh */

void Mesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("get_surface_count"), &Mesh::get_surface_count);
	ClassDB::bind_method(D_METHOD("surface_get_material", "surf_idx"), &Mesh::surface_get_material);

	BIND_ENUM_CONSTANT(PRIMITIVE_POINTS);
	BIND_ENUM_CONSTANT(PRIMITIVE_LINES);
	BIND_ENUM_CONSTANT(PRIMITIVE_LINE_STRIP);
	BIND_ENUM_CONSTANT(PRIMITIVE_TRIANGLES);
	BIND_ENUM_CONSTANT(PRIMITIVE_TRIANGLE_STRIP);
}

/* ArrayMesh */

String ArrayMesh::validate_surface(const RS::SurfaceData &p_arrays) {
	size_t n = p_arrays.vertices.size();
	if (n == 0) {
		return "the surface has no vertices";
	}
	for (const Vector3 &v : p_arrays.vertices) {
		if (!v.is_finite()) {
			return "a vertex position is not finite (NaN or infinity)";
		}
	}
	if (!p_arrays.normals.empty() && p_arrays.normals.size() != n) {
		return vformat("normals has %d entries but there are %d vertices", (int)p_arrays.normals.size(), (int)n);
	}
	if (!p_arrays.tangents.empty() && p_arrays.tangents.size() != n * 4) {
		return vformat("tangents has %d floats but 4 per vertex (%d) are needed", (int)p_arrays.tangents.size(), (int)(n * 4));
	}
	if (!p_arrays.colors.empty() && p_arrays.colors.size() != n) {
		return vformat("colors has %d entries but there are %d vertices", (int)p_arrays.colors.size(), (int)n);
	}
	if (!p_arrays.uvs.empty() && p_arrays.uvs.size() != n) {
		return vformat("uvs has %d entries but there are %d vertices", (int)p_arrays.uvs.size(), (int)n);
	}
	if (p_arrays.indices.empty()) {
		if (n % 3 != 0) {
			return vformat("a non-indexed triangle list needs a multiple of 3 vertices (got %d)", (int)n);
		}
	} else {
		if (p_arrays.indices.size() % 3 != 0) {
			return vformat("the index count must be a multiple of 3 (got %d)", (int)p_arrays.indices.size());
		}
		for (uint32_t idx : p_arrays.indices) {
			if (idx >= n) {
				return vformat("index %u is out of range (%d vertices)", idx, (int)n);
			}
		}
	}
	return String();
}

AABB ArrayMesh::compute_aabb(const RS::SurfaceData &p_arrays) {
	if (p_arrays.vertices.empty()) {
		return AABB();
	}
	AABB box(p_arrays.vertices[0], Vector3());
	for (const Vector3 &v : p_arrays.vertices) {
		box.expand_to(v);
	}
	return box;
}

bool ArrayMesh::add_surface_from_arrays(PrimitiveType p_primitive, const RS::SurfaceData &p_arrays) {
	ERR_FAIL_COND_V_MSG(p_primitive != PRIMITIVE_TRIANGLES, false, vformat("ArrayMesh only supports PRIMITIVE_TRIANGLES (got primitive %d); the surface was not added.", (int)p_primitive));
	String problem = validate_surface(p_arrays);
	ERR_FAIL_COND_V_MSG(!problem.empty(), false, "ArrayMesh::add_surface_from_arrays(): " + problem + "; the surface was not added.");

	Surface s;
	s.data = p_arrays;
	s.data.aabb = compute_aabb(p_arrays);
	aabb = surfaces.empty() ? s.data.aabb : aabb.merge(s.data.aabb);
	surfaces.push_back(s);

	RS *rs = RS::get_singleton();
	if (rs && mesh.is_valid()) {
		rs->mesh_add_surface(mesh, s.data);
	}
	emit_changed();
	return true;
}

void ArrayMesh::surface_set_material(int p_surface, const Ref<Material> &p_material) {
	ERR_FAIL_INDEX_MSG(p_surface, (int)surfaces.size(), vformat("Surface index %d is out of range (%d surfaces).", p_surface, (int)surfaces.size()));
	surfaces[p_surface].material = p_material;
	RS *rs = RS::get_singleton();
	if (rs && mesh.is_valid()) {
		rs->mesh_surface_set_material(mesh, p_surface, p_material.is_valid() ? p_material->get_rid() : RID());
	}
	emit_changed();
}

Ref<Material> ArrayMesh::surface_get_material(int p_surface) const {
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)surfaces.size(), Ref<Material>(), vformat("Surface index %d is out of range (%d surfaces).", p_surface, (int)surfaces.size()));
	return surfaces[p_surface].material;
}

RS::SurfaceData ArrayMesh::surface_get_arrays(int p_surface) const {
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)surfaces.size(), RS::SurfaceData(), vformat("Surface index %d is out of range (%d surfaces).", p_surface, (int)surfaces.size()));
	return surfaces[p_surface].data;
}

void ArrayMesh::clear_surfaces() {
	surfaces.clear();
	aabb = AABB();
	RS *rs = RS::get_singleton();
	if (rs && mesh.is_valid()) {
		rs->mesh_clear(mesh);
	}
	emit_changed();
}

void ArrayMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("surface_set_material", "surf_idx", "material"), &ArrayMesh::surface_set_material);
	ClassDB::bind_method(D_METHOD("clear_surfaces"), &ArrayMesh::clear_surfaces);
}

ArrayMesh::ArrayMesh() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "ArrayMesh needs a RenderingServer; create one first.");
	mesh = rs->mesh_create();
}

ArrayMesh::~ArrayMesh() {
	RS *rs = RS::get_singleton();
	if (rs && mesh.is_valid()) {
		rs->free(mesh);
	}
}
