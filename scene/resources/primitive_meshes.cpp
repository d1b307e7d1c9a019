/**************************************************************************/
/*  primitive_meshes.cpp                                                  */
/**************************************************************************/

#include "scene/resources/primitive_meshes.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>

/* PrimitiveMesh */

void PrimitiveMesh::add_grid(RS::SurfaceData &r_arrays, const Vector3 &p_corner, const Vector3 &p_u, const Vector3 &p_v, const Vector3 &p_normal, int p_segments_u, int p_segments_v, const Vector2 &p_uv_pos, const Vector2 &p_uv_size) {
	const uint32_t base = (uint32_t)r_arrays.vertices.size();
	const int columns = p_segments_u + 1;
	const Vector3 normal = p_normal.normalized();
	const Vector3 tangent = p_u.length_squared() > 0 ? p_u.normalized() : Vector3(1, 0, 0);
	// Binormal sign: cross(N, T) * w must point along -V (see mesh.h).
	const float w = normal.cross(tangent).dot(-p_v) < 0 ? -1.0f : 1.0f;

	for (int j = 0; j <= p_segments_v; j++) {
		const real_t fv = real_t(j) / real_t(p_segments_v);
		for (int i = 0; i <= p_segments_u; i++) {
			const real_t fu = real_t(i) / real_t(p_segments_u);
			r_arrays.vertices.push_back(p_corner + p_u * fu + p_v * fv);
			r_arrays.normals.push_back(normal);
			r_arrays.tangents.insert(r_arrays.tangents.end(), { tangent.x, tangent.y, tangent.z, w });
			r_arrays.uvs.push_back(Vector2(p_uv_pos.x + p_uv_size.x * fu, p_uv_pos.y + p_uv_size.y * fv));
		}
	}

	// For a cell with corners a (i, j), b (i+1, j), c (i, j+1), d (i+1, j+1):
	// cross(b - a, c - a) is along cross(U, V). Front faces are clockwise seen from outside
	// (Godot's convention, see mesh.h), so that order is used when cross(U, V) points INWARD.
	const bool uv_agrees = p_u.cross(p_v).dot(normal) < 0;
	for (int j = 0; j < p_segments_v; j++) {
		for (int i = 0; i < p_segments_u; i++) {
			const uint32_t a = base + j * columns + i;
			const uint32_t b = a + 1;
			const uint32_t c = a + columns;
			const uint32_t d = c + 1;
			if (uv_agrees) {
				r_arrays.indices.insert(r_arrays.indices.end(), { a, b, c, b, d, c });
			} else {
				r_arrays.indices.insert(r_arrays.indices.end(), { a, c, b, b, c, d });
			}
		}
	}
}

bool PrimitiveMesh::_check_count(const char *p_property, int p_value, int p_min) {
	ERR_FAIL_COND_V_MSG(p_value < p_min || p_value > MAX_SEGMENTS, false, vformat("%s must be between %d and %d (got %d); the old value is kept.", p_property, p_min, MAX_SEGMENTS, p_value));
	return true;
}

void PrimitiveMesh::_update() const {
	if (!dirty) {
		return;
	}
	dirty = false;
	arrays = RS::SurfaceData();
	_create_mesh_array(arrays);
	if (flip_faces) {
		for (Vector3 &n : arrays.normals) {
			n = -n;
		}
		for (size_t i = 0; i + 2 < arrays.indices.size(); i += 3) {
			std::swap(arrays.indices[i + 1], arrays.indices[i + 2]);
		}
		// The tangent frame stays right-handed with the flipped normal: flip w as well.
		for (size_t i = 3; i < arrays.tangents.size(); i += 4) {
			arrays.tangents[i] = -arrays.tangents[i];
		}
	}
	arrays.aabb = ArrayMesh::compute_aabb(arrays);

	RS *rs = RS::get_singleton();
	if (rs && mesh.is_valid()) {
		rs->mesh_clear(mesh);
		rs->mesh_add_surface(mesh, arrays);
		rs->mesh_surface_set_material(mesh, 0, material.is_valid() ? material->get_rid() : RID());
	}
}

void PrimitiveMesh::_request_update() {
	dirty = true;
	if (rid_in_use) {
		_update();
	}
	emit_changed();
}

void PrimitiveMesh::set_material(const Ref<Material> &p_material) {
	material = p_material;
	RS *rs = RS::get_singleton();
	if (!dirty && rs && mesh.is_valid()) {
		rs->mesh_surface_set_material(mesh, 0, material.is_valid() ? material->get_rid() : RID());
	}
	emit_changed();
}

void PrimitiveMesh::set_flip_faces(bool p_enable) {
	flip_faces = p_enable;
	_request_update();
}

RS::SurfaceData PrimitiveMesh::get_mesh_arrays() const {
	_update();
	return arrays;
}

AABB PrimitiveMesh::get_aabb() const {
	_update();
	return arrays.aabb;
}

Ref<Material> PrimitiveMesh::surface_get_material(int p_surface) const {
	ERR_FAIL_INDEX_V_MSG(p_surface, 1, Ref<Material>(), vformat("Surface index %d is out of range (a PrimitiveMesh has 1 surface).", p_surface));
	return material;
}

RS::SurfaceData PrimitiveMesh::surface_get_arrays(int p_surface) const {
	ERR_FAIL_INDEX_V_MSG(p_surface, 1, RS::SurfaceData(), vformat("Surface index %d is out of range (a PrimitiveMesh has 1 surface).", p_surface));
	return get_mesh_arrays();
}

RID PrimitiveMesh::get_rid() const {
	rid_in_use = true;
	_update();
	return mesh;
}

void PrimitiveMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_material", "material"), &PrimitiveMesh::set_material);
	ClassDB::bind_method(D_METHOD("get_material"), &PrimitiveMesh::get_material);
	ClassDB::bind_method(D_METHOD("set_flip_faces", "flip_faces"), &PrimitiveMesh::set_flip_faces);
	ClassDB::bind_method(D_METHOD("get_flip_faces"), &PrimitiveMesh::get_flip_faces);

	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "material", PROPERTY_HINT_RESOURCE_TYPE, "BaseMaterial3D,ShaderMaterial", PROPERTY_USAGE_DEFAULT, "Material"), "set_material", "get_material");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "flip_faces"), "set_flip_faces", "get_flip_faces");
}

PrimitiveMesh::PrimitiveMesh() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "PrimitiveMesh needs a RenderingServer; create one first.");
	mesh = rs->mesh_create();
}

PrimitiveMesh::~PrimitiveMesh() {
	RS *rs = RS::get_singleton();
	if (rs && mesh.is_valid()) {
		rs->free(mesh);
	}
}

/* PlaneMesh */

void PlaneMesh::create_plane_arrays(RS::SurfaceData &r_arrays, const Vector2 &p_size, int p_subdivide_w, int p_subdivide_d, const Vector3 &p_center_offset, Orientation p_orientation) {
	const real_t hw = p_size.x * real_t(0.5);
	const real_t hd = p_size.y * real_t(0.5);
	Vector3 corner, u, v, n;
	switch (p_orientation) {
		case FACE_X: {
			corner = Vector3(0, hd, hw);
			u = Vector3(0, 0, -p_size.x);
			v = Vector3(0, -p_size.y, 0);
			n = Vector3(1, 0, 0);
		} break;
		case FACE_Z: {
			corner = Vector3(-hw, hd, 0);
			u = Vector3(p_size.x, 0, 0);
			v = Vector3(0, -p_size.y, 0);
			n = Vector3(0, 0, 1);
		} break;
		case FACE_Y:
		default: {
			corner = Vector3(-hw, 0, -hd);
			u = Vector3(p_size.x, 0, 0);
			v = Vector3(0, 0, p_size.y);
			n = Vector3(0, 1, 0);
		} break;
	}
	add_grid(r_arrays, corner + p_center_offset, u, v, n, p_subdivide_w + 1, p_subdivide_d + 1, Vector2(0, 0), Vector2(1, 1));
}

void PlaneMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_plane_arrays(r_arrays, size, subdivide_w, subdivide_d, center_offset, orientation);
}

void PlaneMesh::set_size(const Vector2 &p_size) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_size.x) || !Math::is_finite(p_size.y) || p_size.x < 0 || p_size.y < 0, vformat("PlaneMesh size must be finite and not negative (got (%s, %s)); the old value is kept.", rtos(p_size.x).c_str(), rtos(p_size.y).c_str()));
	size = p_size;
	_request_update();
}

void PlaneMesh::set_subdivide_width(int p_divisions) {
	if (_check_count("subdivide_width", p_divisions, 0)) {
		subdivide_w = p_divisions;
		_request_update();
	}
}

void PlaneMesh::set_subdivide_depth(int p_divisions) {
	if (_check_count("subdivide_depth", p_divisions, 0)) {
		subdivide_d = p_divisions;
		_request_update();
	}
}

void PlaneMesh::set_center_offset(const Vector3 &p_offset) {
	ERR_FAIL_COND_MSG(!p_offset.is_finite(), "PlaneMesh center_offset must be finite; the old value is kept.");
	center_offset = p_offset;
	_request_update();
}

void PlaneMesh::set_orientation(Orientation p_orientation) {
	ERR_FAIL_INDEX_MSG((int)p_orientation, 3, vformat("PlaneMesh orientation must be 0..2 (Face X, Face Y, Face Z); got %d. The old value is kept.", (int)p_orientation));
	orientation = p_orientation;
	_request_update();
}

void PlaneMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_size", "size"), &PlaneMesh::set_size);
	ClassDB::bind_method(D_METHOD("get_size"), &PlaneMesh::get_size);
	ClassDB::bind_method(D_METHOD("set_subdivide_width", "subdivide"), &PlaneMesh::set_subdivide_width);
	ClassDB::bind_method(D_METHOD("get_subdivide_width"), &PlaneMesh::get_subdivide_width);
	ClassDB::bind_method(D_METHOD("set_subdivide_depth", "subdivide"), &PlaneMesh::set_subdivide_depth);
	ClassDB::bind_method(D_METHOD("get_subdivide_depth"), &PlaneMesh::get_subdivide_depth);
	ClassDB::bind_method(D_METHOD("set_center_offset", "offset"), &PlaneMesh::set_center_offset);
	ClassDB::bind_method(D_METHOD("get_center_offset"), &PlaneMesh::get_center_offset);
	ClassDB::bind_method(D_METHOD("set_orientation", "orientation"), &PlaneMesh::set_orientation);
	ClassDB::bind_method(D_METHOD("get_orientation"), &PlaneMesh::get_orientation);

	ADD_PROPERTY(PropertyInfo(Variant::VECTOR2, "size", PROPERTY_HINT_NONE, "suffix:m"), "set_size", "get_size");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_width", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_width", "get_subdivide_width");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_depth", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_depth", "get_subdivide_depth");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "center_offset", PROPERTY_HINT_NONE, "suffix:m"), "set_center_offset", "get_center_offset");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "orientation", PROPERTY_HINT_ENUM, "Face X,Face Y,Face Z"), "set_orientation", "get_orientation");

	BIND_ENUM_CONSTANT(FACE_X);
	BIND_ENUM_CONSTANT(FACE_Y);
	BIND_ENUM_CONSTANT(FACE_Z);
}

/* QuadMesh */

QuadMesh::QuadMesh() {
	set_orientation(FACE_Z);
	set_size(Vector2(1, 1));
}

/* BoxMesh */

void BoxMesh::create_box_arrays(RS::SurfaceData &r_arrays, const Vector3 &p_size, int p_subdivide_w, int p_subdivide_h, int p_subdivide_d) {
	const Vector3 h = p_size * real_t(0.5);
	const int sw = p_subdivide_w + 1, sh = p_subdivide_h + 1, sd = p_subdivide_d + 1;
	const Vector2 cell(real_t(1.0 / 3.0), real_t(0.5));
	// Each face seen from outside: U to the right, V downwards.
	add_grid(r_arrays, Vector3(-h.x, h.y, h.z), Vector3(p_size.x, 0, 0), Vector3(0, -p_size.y, 0), Vector3(0, 0, 1), sw, sh, Vector2(0, 0), cell); // +Z
	add_grid(r_arrays, Vector3(h.x, h.y, h.z), Vector3(0, 0, -p_size.z), Vector3(0, -p_size.y, 0), Vector3(1, 0, 0), sd, sh, Vector2(cell.x, 0), cell); // +X
	add_grid(r_arrays, Vector3(h.x, h.y, -h.z), Vector3(-p_size.x, 0, 0), Vector3(0, -p_size.y, 0), Vector3(0, 0, -1), sw, sh, Vector2(cell.x * 2, 0), cell); // -Z
	add_grid(r_arrays, Vector3(-h.x, h.y, -h.z), Vector3(0, 0, p_size.z), Vector3(0, -p_size.y, 0), Vector3(-1, 0, 0), sd, sh, Vector2(0, cell.y), cell); // -X
	add_grid(r_arrays, Vector3(-h.x, h.y, -h.z), Vector3(p_size.x, 0, 0), Vector3(0, 0, p_size.z), Vector3(0, 1, 0), sw, sd, Vector2(cell.x, cell.y), cell); // +Y
	add_grid(r_arrays, Vector3(-h.x, -h.y, h.z), Vector3(p_size.x, 0, 0), Vector3(0, 0, -p_size.z), Vector3(0, -1, 0), sw, sd, Vector2(cell.x * 2, cell.y), cell); // -Y
}

void BoxMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_box_arrays(r_arrays, size, subdivide_w, subdivide_h, subdivide_d);
}

void BoxMesh::set_size(const Vector3 &p_size) {
	ERR_FAIL_COND_MSG(!p_size.is_finite() || p_size.x < 0 || p_size.y < 0 || p_size.z < 0, vformat("BoxMesh size must be finite and not negative (got (%s, %s, %s)); the old value is kept.", rtos(p_size.x).c_str(), rtos(p_size.y).c_str(), rtos(p_size.z).c_str()));
	size = p_size;
	_request_update();
}

void BoxMesh::set_subdivide_width(int p_divisions) {
	if (_check_count("subdivide_width", p_divisions, 0)) {
		subdivide_w = p_divisions;
		_request_update();
	}
}

void BoxMesh::set_subdivide_height(int p_divisions) {
	if (_check_count("subdivide_height", p_divisions, 0)) {
		subdivide_h = p_divisions;
		_request_update();
	}
}

void BoxMesh::set_subdivide_depth(int p_divisions) {
	if (_check_count("subdivide_depth", p_divisions, 0)) {
		subdivide_d = p_divisions;
		_request_update();
	}
}

void BoxMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_size", "size"), &BoxMesh::set_size);
	ClassDB::bind_method(D_METHOD("get_size"), &BoxMesh::get_size);
	ClassDB::bind_method(D_METHOD("set_subdivide_width", "subdivide"), &BoxMesh::set_subdivide_width);
	ClassDB::bind_method(D_METHOD("get_subdivide_width"), &BoxMesh::get_subdivide_width);
	ClassDB::bind_method(D_METHOD("set_subdivide_height", "divisions"), &BoxMesh::set_subdivide_height);
	ClassDB::bind_method(D_METHOD("get_subdivide_height"), &BoxMesh::get_subdivide_height);
	ClassDB::bind_method(D_METHOD("set_subdivide_depth", "subdivide"), &BoxMesh::set_subdivide_depth);
	ClassDB::bind_method(D_METHOD("get_subdivide_depth"), &BoxMesh::get_subdivide_depth);

	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "size", PROPERTY_HINT_NONE, "suffix:m"), "set_size", "get_size");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_width", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_width", "get_subdivide_width");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_height", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_height", "get_subdivide_height");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_depth", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_depth", "get_subdivide_depth");
}

/* SphereMesh */

void SphereMesh::create_sphere_arrays(RS::SurfaceData &r_arrays, float p_radius, float p_height, int p_radial_segments, int p_rings) {
	const uint32_t base = (uint32_t)r_arrays.vertices.size();
	const int columns = p_radial_segments + 1;
	const float half_h = p_height * 0.5f;
	for (int j = 0; j <= p_rings + 1; j++) {
		const float fv = float(j) / float(p_rings + 1);
		const float theta = float(Math::PI) * fv; // 0 at the top pole.
		const float st = std::sin(theta), ct = std::cos(theta);
		for (int i = 0; i <= p_radial_segments; i++) {
			const float fu = float(i) / float(p_radial_segments);
			const float phi = float(Math::TAU) * fu;
			const float sp = std::sin(phi), cp = std::cos(phi);
			r_arrays.vertices.push_back(Vector3(p_radius * st * sp, half_h * ct, p_radius * st * cp));
			// Gradient of x²/r² + y²/h² + z²/r² (exact for an ellipsoid, unit sphere when h = r).
			r_arrays.normals.push_back(Vector3(st * sp / p_radius, ct / half_h, st * cp / p_radius).normalized());
			// dP/du is along (cos φ, 0, -sin φ); dP/dv is along (cos θ sin φ, -sin θ, cos θ cos φ)
			// scaled; cross(N, T) points up (-V) everywhere, so w = +1.
			r_arrays.tangents.insert(r_arrays.tangents.end(), { cp, 0.0f, -sp, 1.0f });
			r_arrays.uvs.push_back(Vector2(fu, fv));
		}
	}
	// Rows j-1 and j, columns i-1 and i. With a = (j-1, i-1), b = (j, i-1), c = (j-1, i),
	// d = (j, i): cross(b - a, c - a) = cross(dV, dU) points outwards, so (a, b, c), (c, b, d).
	// The first and last rows collapse to the poles; their degenerate triangles are kept (as
	// Godot does) so every row has the same layout.
	for (int j = 1; j <= p_rings + 1; j++) {
		for (int i = 1; i <= p_radial_segments; i++) {
			const uint32_t a = base + (j - 1) * columns + (i - 1);
			const uint32_t b = base + j * columns + (i - 1);
			const uint32_t c = base + (j - 1) * columns + i;
			const uint32_t d = base + j * columns + i;
			// Clockwise seen from outside (mesh.h).
			r_arrays.indices.insert(r_arrays.indices.end(), { a, c, b, c, d, b });
		}
	}
}

void SphereMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_sphere_arrays(r_arrays, radius, height, radial_segments, rings);
}

void SphereMesh::set_radius(float p_radius) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_radius) || p_radius <= 0.0f, vformat("SphereMesh radius must be finite and > 0 (got %s); the old value is kept.", rtos(p_radius).c_str()));
	radius = p_radius;
	_request_update();
}

void SphereMesh::set_height(float p_height) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_height) || p_height <= 0.0f, vformat("SphereMesh height must be finite and > 0 (got %s); the old value is kept.", rtos(p_height).c_str()));
	height = p_height;
	_request_update();
}

void SphereMesh::set_radial_segments(int p_segments) {
	if (_check_count("radial_segments", p_segments, 4)) {
		radial_segments = p_segments;
		_request_update();
	}
}

void SphereMesh::set_rings(int p_rings) {
	if (_check_count("rings", p_rings, 1)) {
		rings = p_rings;
		_request_update();
	}
}

void SphereMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_radius", "radius"), &SphereMesh::set_radius);
	ClassDB::bind_method(D_METHOD("get_radius"), &SphereMesh::get_radius);
	ClassDB::bind_method(D_METHOD("set_height", "height"), &SphereMesh::set_height);
	ClassDB::bind_method(D_METHOD("get_height"), &SphereMesh::get_height);
	ClassDB::bind_method(D_METHOD("set_radial_segments", "radial_segments"), &SphereMesh::set_radial_segments);
	ClassDB::bind_method(D_METHOD("get_radial_segments"), &SphereMesh::get_radial_segments);
	ClassDB::bind_method(D_METHOD("set_rings", "rings"), &SphereMesh::set_rings);
	ClassDB::bind_method(D_METHOD("get_rings"), &SphereMesh::get_rings);

	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "radius", PROPERTY_HINT_RANGE, "0.001,100.0,0.001,or_greater,suffix:m"), "set_radius", "get_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "height", PROPERTY_HINT_RANGE, "0.001,100.0,0.001,or_greater,suffix:m"), "set_height", "get_height");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "radial_segments", PROPERTY_HINT_RANGE, "1,100,1,or_greater"), "set_radial_segments", "get_radial_segments");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "rings", PROPERTY_HINT_RANGE, "1,100,1,or_greater"), "set_rings", "get_rings");
}
