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

/* CylinderMesh */

// Appends a fan cap at height p_y of radius p_radius, normal +Y (p_up) or -Y, UVs in a 0.5 x 0.5 cell
// centred at p_uv_center. Tangent +X (u grows with x, v with z); the bitangent sign follows the normal.
static void add_disk_cap(RS::SurfaceData &r_arrays, float p_y, float p_radius, bool p_up, int p_segments, const Vector2 &p_uv_center) {
	const uint32_t center = (uint32_t)r_arrays.vertices.size();
	const Vector3 normal(0, p_up ? 1.0f : -1.0f, 0);
	const float w = p_up ? 1.0f : -1.0f;
	r_arrays.vertices.push_back(Vector3(0, p_y, 0));
	r_arrays.normals.push_back(normal);
	r_arrays.tangents.insert(r_arrays.tangents.end(), { 1.0f, 0.0f, 0.0f, w });
	r_arrays.uvs.push_back(p_uv_center);
	for (int i = 0; i <= p_segments; i++) {
		const float phi = float(Math::TAU) * float(i) / float(p_segments);
		const float sp = std::sin(phi), cp = std::cos(phi);
		r_arrays.vertices.push_back(Vector3(p_radius * sp, p_y, p_radius * cp));
		r_arrays.normals.push_back(normal);
		r_arrays.tangents.insert(r_arrays.tangents.end(), { 1.0f, 0.0f, 0.0f, w });
		r_arrays.uvs.push_back(p_uv_center + Vector2(sp, cp) * 0.25f);
	}
	for (int i = 0; i < p_segments; i++) {
		const uint32_t b = center + 1 + i, c = b + 1;
		// cross(b - centre, c - centre) points to +Y; clockwise seen from outside needs it against the normal.
		if (p_up) {
			r_arrays.indices.insert(r_arrays.indices.end(), { center, c, b });
		} else {
			r_arrays.indices.insert(r_arrays.indices.end(), { center, b, c });
		}
	}
}

// Appends rows of (p_segments + 1) vertices around Y, one row per entry of p_rows as (radius, y,
// normal radial part, normal y part, v), top row first, and the bands between consecutive rows.
// Rows of radius 0 collapse to a point (degenerate triangles kept, as for the sphere's poles).
struct LatheRow {
	float radius, y, normal_radial, normal_y, v;
};

static void add_lathe(RS::SurfaceData &r_arrays, const std::vector<LatheRow> &p_rows, int p_segments) {
	const uint32_t base = (uint32_t)r_arrays.vertices.size();
	const int columns = p_segments + 1;
	for (const LatheRow &row : p_rows) {
		for (int i = 0; i <= p_segments; i++) {
			const float fu = float(i) / float(p_segments);
			const float phi = float(Math::TAU) * fu;
			const float sp = std::sin(phi), cp = std::cos(phi);
			r_arrays.vertices.push_back(Vector3(row.radius * sp, row.y, row.radius * cp));
			r_arrays.normals.push_back(Vector3(row.normal_radial * sp, row.normal_y, row.normal_radial * cp).normalized());
			// dP/du is along (cos φ, 0, -sin φ); v grows downwards, so cross(N, T) (upwards) is -dP/dv: w = +1.
			r_arrays.tangents.insert(r_arrays.tangents.end(), { cp, 0.0f, -sp, 1.0f });
			r_arrays.uvs.push_back(Vector2(fu, row.v));
		}
	}
	for (int j = 1; j < int(p_rows.size()); j++) {
		for (int i = 1; i <= p_segments; i++) {
			const uint32_t a = base + (j - 1) * columns + (i - 1);
			const uint32_t b = base + j * columns + (i - 1);
			const uint32_t c = base + (j - 1) * columns + i;
			const uint32_t d = base + j * columns + i;
			r_arrays.indices.insert(r_arrays.indices.end(), { a, c, b, c, d, b }); // As the sphere.
		}
	}
}

void CylinderMesh::create_cylinder_arrays(RS::SurfaceData &r_arrays, float p_top_radius, float p_bottom_radius, float p_height, int p_radial_segments, int p_rings, bool p_cap_top, bool p_cap_bottom) {
	const float half_h = p_height * 0.5f;
	// The side line runs from (top_radius, +h/2) to (bottom_radius, -h/2); its outward normal in the
	// (radial, y) plane is (h, bottom_radius - top_radius).
	const float normal_radial = p_height, normal_y = p_bottom_radius - p_top_radius;
	std::vector<LatheRow> rows;
	for (int j = 0; j <= p_rings + 1; j++) {
		const float f = float(j) / float(p_rings + 1);
		rows.push_back({ p_top_radius + (p_bottom_radius - p_top_radius) * f, half_h - p_height * f, normal_radial, normal_y, 0.5f * f });
	}
	add_lathe(r_arrays, rows, p_radial_segments);
	if (p_cap_top && p_top_radius > 0.0f) {
		add_disk_cap(r_arrays, half_h, p_top_radius, true, p_radial_segments, Vector2(0.25f, 0.75f));
	}
	if (p_cap_bottom && p_bottom_radius > 0.0f) {
		add_disk_cap(r_arrays, -half_h, p_bottom_radius, false, p_radial_segments, Vector2(0.75f, 0.75f));
	}
}

void CylinderMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_cylinder_arrays(r_arrays, top_radius, bottom_radius, height, radial_segments, rings, cap_top, cap_bottom);
}

void CylinderMesh::set_top_radius(float p_radius) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_radius) || p_radius < 0.0f, vformat("CylinderMesh top_radius must be finite and >= 0 (got %s); the old value is kept.", rtos(p_radius).c_str()));
	top_radius = p_radius;
	_request_update();
}

void CylinderMesh::set_bottom_radius(float p_radius) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_radius) || p_radius < 0.0f, vformat("CylinderMesh bottom_radius must be finite and >= 0 (got %s); the old value is kept.", rtos(p_radius).c_str()));
	bottom_radius = p_radius;
	_request_update();
}

void CylinderMesh::set_height(float p_height) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_height) || p_height <= 0.0f, vformat("CylinderMesh height must be finite and > 0 (got %s); the old value is kept.", rtos(p_height).c_str()));
	height = p_height;
	_request_update();
}

void CylinderMesh::set_radial_segments(int p_segments) {
	if (_check_count("radial_segments", p_segments, 4)) {
		radial_segments = p_segments;
		_request_update();
	}
}

void CylinderMesh::set_rings(int p_rings) {
	if (_check_count("rings", p_rings, 0)) {
		rings = p_rings;
		_request_update();
	}
}

void CylinderMesh::set_cap_top(bool p_enable) {
	cap_top = p_enable;
	_request_update();
}

void CylinderMesh::set_cap_bottom(bool p_enable) {
	cap_bottom = p_enable;
	_request_update();
}

void CylinderMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_top_radius", "radius"), &CylinderMesh::set_top_radius);
	ClassDB::bind_method(D_METHOD("get_top_radius"), &CylinderMesh::get_top_radius);
	ClassDB::bind_method(D_METHOD("set_bottom_radius", "radius"), &CylinderMesh::set_bottom_radius);
	ClassDB::bind_method(D_METHOD("get_bottom_radius"), &CylinderMesh::get_bottom_radius);
	ClassDB::bind_method(D_METHOD("set_height", "height"), &CylinderMesh::set_height);
	ClassDB::bind_method(D_METHOD("get_height"), &CylinderMesh::get_height);
	ClassDB::bind_method(D_METHOD("set_radial_segments", "segments"), &CylinderMesh::set_radial_segments);
	ClassDB::bind_method(D_METHOD("get_radial_segments"), &CylinderMesh::get_radial_segments);
	ClassDB::bind_method(D_METHOD("set_rings", "rings"), &CylinderMesh::set_rings);
	ClassDB::bind_method(D_METHOD("get_rings"), &CylinderMesh::get_rings);
	ClassDB::bind_method(D_METHOD("set_cap_top", "cap_top"), &CylinderMesh::set_cap_top);
	ClassDB::bind_method(D_METHOD("is_cap_top"), &CylinderMesh::is_cap_top);
	ClassDB::bind_method(D_METHOD("set_cap_bottom", "cap_bottom"), &CylinderMesh::set_cap_bottom);
	ClassDB::bind_method(D_METHOD("is_cap_bottom"), &CylinderMesh::is_cap_bottom);

	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "top_radius", PROPERTY_HINT_RANGE, "0,100,0.001,or_greater,suffix:m"), "set_top_radius", "get_top_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "bottom_radius", PROPERTY_HINT_RANGE, "0,100,0.001,or_greater,suffix:m"), "set_bottom_radius", "get_bottom_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "height", PROPERTY_HINT_RANGE, "0.001,100,0.001,or_greater,suffix:m"), "set_height", "get_height");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "radial_segments", PROPERTY_HINT_RANGE, "1,100,1,or_greater"), "set_radial_segments", "get_radial_segments");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "rings", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_rings", "get_rings");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "cap_top"), "set_cap_top", "is_cap_top");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "cap_bottom"), "set_cap_bottom", "is_cap_bottom");
}

/* CapsuleMesh */

void CapsuleMesh::create_capsule_arrays(RS::SurfaceData &r_arrays, float p_radius, float p_height, int p_radial_segments, int p_rings) {
	const float half_cylinder = std::max(p_height * 0.5f - p_radius, 0.0f);
	// V by arc length: a quarter circle, the straight part, a quarter circle.
	const float quarter = float(Math::PI) * 0.5f * p_radius;
	const float length = 2.0f * quarter + 2.0f * half_cylinder;
	const float inv_length = length > 0.0f ? 1.0f / length : 0.0f;
	std::vector<LatheRow> rows;
	const int steps = p_rings + 1;
	for (int j = 0; j <= steps; j++) { // Top pole to the upper equator.
		const float theta = float(Math::PI) * 0.5f * float(j) / float(steps);
		const float st = std::sin(theta), ct = std::cos(theta);
		rows.push_back({ p_radius * st, half_cylinder + p_radius * ct, st, ct, quarter * float(j) / float(steps) * inv_length });
	}
	for (int j = 0; j <= steps; j++) { // Lower equator to the bottom pole.
		const float theta = float(Math::PI) * 0.5f * (1.0f + float(j) / float(steps));
		const float st = std::sin(theta), ct = std::cos(theta);
		rows.push_back({ p_radius * st, -half_cylinder + p_radius * ct, st, ct, (quarter * (1.0f + float(j) / float(steps)) + 2.0f * half_cylinder) * inv_length });
	}
	add_lathe(r_arrays, rows, p_radial_segments);
}

void CapsuleMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_capsule_arrays(r_arrays, radius, height, radial_segments, rings);
}

void CapsuleMesh::set_radius(float p_radius) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_radius) || p_radius <= 0.0f, vformat("CapsuleMesh radius must be finite and > 0 (got %s); the old value is kept.", rtos(p_radius).c_str()));
	radius = p_radius;
	if (height < 2.0f * radius) {
		height = 2.0f * radius;
	}
	_request_update();
}

void CapsuleMesh::set_height(float p_height) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_height) || p_height <= 0.0f, vformat("CapsuleMesh height must be finite and > 0 (got %s); the old value is kept.", rtos(p_height).c_str()));
	height = p_height;
	if (radius > height * 0.5f) {
		radius = height * 0.5f;
	}
	_request_update();
}

void CapsuleMesh::set_radial_segments(int p_segments) {
	if (_check_count("radial_segments", p_segments, 4)) {
		radial_segments = p_segments;
		_request_update();
	}
}

void CapsuleMesh::set_rings(int p_rings) {
	if (_check_count("rings", p_rings, 0)) {
		rings = p_rings;
		_request_update();
	}
}

void CapsuleMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_radius", "radius"), &CapsuleMesh::set_radius);
	ClassDB::bind_method(D_METHOD("get_radius"), &CapsuleMesh::get_radius);
	ClassDB::bind_method(D_METHOD("set_height", "height"), &CapsuleMesh::set_height);
	ClassDB::bind_method(D_METHOD("get_height"), &CapsuleMesh::get_height);
	ClassDB::bind_method(D_METHOD("set_radial_segments", "segments"), &CapsuleMesh::set_radial_segments);
	ClassDB::bind_method(D_METHOD("get_radial_segments"), &CapsuleMesh::get_radial_segments);
	ClassDB::bind_method(D_METHOD("set_rings", "rings"), &CapsuleMesh::set_rings);
	ClassDB::bind_method(D_METHOD("get_rings"), &CapsuleMesh::get_rings);

	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "radius", PROPERTY_HINT_RANGE, "0.001,100.0,0.001,or_greater,suffix:m"), "set_radius", "get_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "height", PROPERTY_HINT_RANGE, "0.001,100.0,0.001,or_greater,suffix:m"), "set_height", "get_height");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "radial_segments", PROPERTY_HINT_RANGE, "1,100,1,or_greater"), "set_radial_segments", "get_radial_segments");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "rings", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_rings", "get_rings");
}

/* TorusMesh */

void TorusMesh::create_torus_arrays(RS::SurfaceData &r_arrays, float p_inner_radius, float p_outer_radius, int p_rings, int p_ring_segments) {
	const float r_min = std::min(p_inner_radius, p_outer_radius), r_max = std::max(p_inner_radius, p_outer_radius);
	const float center = (r_min + r_max) * 0.5f, tube = (r_max - r_min) * 0.5f;
	const uint32_t base = (uint32_t)r_arrays.vertices.size();
	const int columns = p_ring_segments + 1;
	for (int i = 0; i <= p_rings; i++) {
		const float fu = float(i) / float(p_rings);
		const float phi = float(Math::TAU) * fu;
		const Vector3 d(std::sin(phi), 0, std::cos(phi));
		const Vector3 t(std::cos(phi), 0, -std::sin(phi)); // dP/du.
		for (int j = 0; j <= p_ring_segments; j++) {
			const float fv = float(j) / float(p_ring_segments);
			const float psi = float(Math::TAU) * fv;
			const float cs = std::cos(psi), sn = std::sin(psi);
			r_arrays.vertices.push_back(d * (center + tube * cs) + Vector3(0, tube * sn, 0));
			r_arrays.normals.push_back(d * cs + Vector3(0, sn, 0));
			// cross(N, T) = Y cos ψ - d sin ψ = -(dP/dv) / r: the bitangent sign is -1 everywhere.
			r_arrays.tangents.insert(r_arrays.tangents.end(), { t.x, t.y, t.z, -1.0f });
			r_arrays.uvs.push_back(Vector2(fu, fv));
		}
	}
	for (int i = 0; i < p_rings; i++) {
		for (int j = 0; j < p_ring_segments; j++) {
			const uint32_t a = base + i * columns + j;
			const uint32_t b = a + columns; // Next slice.
			const uint32_t c = a + 1; // Next segment around the tube.
			const uint32_t d = b + 1;
			// cross(dP/du, dP/dv) points outwards: (a, c, b) and (b, c, d) are clockwise seen from outside.
			r_arrays.indices.insert(r_arrays.indices.end(), { a, c, b, b, c, d });
		}
	}
}

void TorusMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_torus_arrays(r_arrays, inner_radius, outer_radius, rings, ring_segments);
}

void TorusMesh::set_inner_radius(float p_radius) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_radius) || p_radius < 0.0f, vformat("TorusMesh inner_radius must be finite and >= 0 (got %s); the old value is kept.", rtos(p_radius).c_str()));
	inner_radius = p_radius;
	_request_update();
}

void TorusMesh::set_outer_radius(float p_radius) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_radius) || p_radius < 0.0f, vformat("TorusMesh outer_radius must be finite and >= 0 (got %s); the old value is kept.", rtos(p_radius).c_str()));
	outer_radius = p_radius;
	_request_update();
}

void TorusMesh::set_rings(int p_rings) {
	if (_check_count("rings", p_rings, 3)) {
		rings = p_rings;
		_request_update();
	}
}

void TorusMesh::set_ring_segments(int p_segments) {
	if (_check_count("ring_segments", p_segments, 3)) {
		ring_segments = p_segments;
		_request_update();
	}
}

void TorusMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_inner_radius", "radius"), &TorusMesh::set_inner_radius);
	ClassDB::bind_method(D_METHOD("get_inner_radius"), &TorusMesh::get_inner_radius);
	ClassDB::bind_method(D_METHOD("set_outer_radius", "radius"), &TorusMesh::set_outer_radius);
	ClassDB::bind_method(D_METHOD("get_outer_radius"), &TorusMesh::get_outer_radius);
	ClassDB::bind_method(D_METHOD("set_rings", "rings"), &TorusMesh::set_rings);
	ClassDB::bind_method(D_METHOD("get_rings"), &TorusMesh::get_rings);
	ClassDB::bind_method(D_METHOD("set_ring_segments", "rings"), &TorusMesh::set_ring_segments);
	ClassDB::bind_method(D_METHOD("get_ring_segments"), &TorusMesh::get_ring_segments);

	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "inner_radius", PROPERTY_HINT_RANGE, "0.001,1000.0,0.001,or_greater,suffix:m"), "set_inner_radius", "get_inner_radius");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "outer_radius", PROPERTY_HINT_RANGE, "0.001,1000.0,0.001,or_greater,suffix:m"), "set_outer_radius", "get_outer_radius");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "rings", PROPERTY_HINT_RANGE, "3,128,1,or_greater"), "set_rings", "get_rings");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "ring_segments", PROPERTY_HINT_RANGE, "3,64,1,or_greater"), "set_ring_segments", "get_ring_segments");
}

/* PrismMesh */

// Appends one triangular end of the prism at z = p_z: rows from the base (y = -h/2) up to the apex,
// p_columns + 1 vertices per row (the top row collapses to the apex). p_front: normal +Z, u along +X;
// else normal -Z, u along -X (both read left to right from outside). V grows downwards.
static void add_prism_end(RS::SurfaceData &r_arrays, const Vector3 &p_size, float p_apex_x, float p_z, bool p_front, int p_columns, int p_rows, const Vector2 &p_uv_pos, const Vector2 &p_uv_size) {
	const uint32_t base = (uint32_t)r_arrays.vertices.size();
	const float hw = p_size.x * 0.5f, hh = p_size.y * 0.5f;
	const Vector3 normal(0, 0, p_front ? 1.0f : -1.0f);
	const float tx = p_front ? 1.0f : -1.0f;
	for (int k = 0; k <= p_rows; k++) {
		const float fk = float(k) / float(p_rows);
		const float y = -hh + p_size.y * fk;
		const float left = -hw + (p_apex_x + hw) * fk, right = hw + (p_apex_x - hw) * fk;
		for (int i = 0; i <= p_columns; i++) {
			const float x = left + (right - left) * float(i) / float(p_columns);
			r_arrays.vertices.push_back(Vector3(x, y, p_z));
			r_arrays.normals.push_back(normal);
			// cross(N, T) is +Y for both ends, against dP/dv (downwards): w = +1.
			r_arrays.tangents.insert(r_arrays.tangents.end(), { tx, 0.0f, 0.0f, 1.0f });
			const float fu = p_size.x > 0.0f ? (p_front ? x + hw : hw - x) / p_size.x : 0.0f;
			r_arrays.uvs.push_back(Vector2(p_uv_pos.x + p_uv_size.x * fu, p_uv_pos.y + p_uv_size.y * (1.0f - fk)));
		}
	}
	const int columns = p_columns + 1;
	for (int k = 0; k < p_rows; k++) {
		for (int i = 0; i < p_columns; i++) {
			const uint32_t a = base + k * columns + i, b = a + 1, c = a + columns, d = c + 1;
			// cross(b - a, c - a) is +Z: against the normal for the back end, along it for the front.
			if (p_front) {
				r_arrays.indices.insert(r_arrays.indices.end(), { a, c, b, b, c, d });
			} else {
				r_arrays.indices.insert(r_arrays.indices.end(), { a, b, c, b, d, c });
			}
		}
	}
}

void PrismMesh::create_prism_arrays(RS::SurfaceData &r_arrays, float p_left_to_right, const Vector3 &p_size, int p_subdivide_w, int p_subdivide_h, int p_subdivide_d) {
	const float hw = p_size.x * 0.5f, hh = p_size.y * 0.5f, hd = p_size.z * 0.5f;
	const float apex_x = -hw + p_size.x * p_left_to_right;
	const Vector2 cell(1.0f / 3.0f, 0.5f);
	add_prism_end(r_arrays, p_size, apex_x, hd, true, p_subdivide_w + 1, p_subdivide_h + 1, Vector2(0, 0), cell);
	add_prism_end(r_arrays, p_size, apex_x, -hd, false, p_subdivide_w + 1, p_subdivide_h + 1, Vector2(2.0f / 3.0f, 0), cell);
	// Slopes: from the apex ridge down to the base edges; normals perpendicular to the slope in XY.
	const Vector3 left_down(-hw - apex_x, -p_size.y, 0), right_down(hw - apex_x, -p_size.y, 0);
	add_grid(r_arrays, Vector3(apex_x, hh, -hd), Vector3(0, 0, p_size.z), left_down, Vector3(-p_size.y, apex_x + hw, 0), p_subdivide_d + 1, p_subdivide_h + 1, Vector2(0, 0.5f), cell);
	add_grid(r_arrays, Vector3(apex_x, hh, hd), Vector3(0, 0, -p_size.z), right_down, Vector3(p_size.y, hw - apex_x, 0), p_subdivide_d + 1, p_subdivide_h + 1, Vector2(1.0f / 3.0f, 0), cell);
	add_grid(r_arrays, Vector3(-hw, -hh, hd), Vector3(p_size.x, 0, 0), Vector3(0, 0, -p_size.z), Vector3(0, -1, 0), p_subdivide_w + 1, p_subdivide_d + 1, Vector2(1.0f / 3.0f, 0.5f), cell);
}

void PrismMesh::_create_mesh_array(RS::SurfaceData &r_arrays) const {
	create_prism_arrays(r_arrays, left_to_right, size, subdivide_w, subdivide_h, subdivide_d);
}

void PrismMesh::set_left_to_right(float p_value) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_value) || p_value < 0.0f || p_value > 1.0f, vformat("PrismMesh left_to_right must be within [0, 1] (got %s); the old value is kept.", rtos(p_value).c_str()));
	left_to_right = p_value;
	_request_update();
}

void PrismMesh::set_size(const Vector3 &p_size) {
	ERR_FAIL_COND_MSG(!p_size.is_finite() || p_size.x < 0 || p_size.y < 0 || p_size.z < 0, vformat("PrismMesh size must be finite and not negative (got (%s, %s, %s)); the old value is kept.", rtos(p_size.x).c_str(), rtos(p_size.y).c_str(), rtos(p_size.z).c_str()));
	size = p_size;
	_request_update();
}

void PrismMesh::set_subdivide_width(int p_divisions) {
	if (_check_count("subdivide_width", p_divisions, 0)) {
		subdivide_w = p_divisions;
		_request_update();
	}
}

void PrismMesh::set_subdivide_height(int p_divisions) {
	if (_check_count("subdivide_height", p_divisions, 0)) {
		subdivide_h = p_divisions;
		_request_update();
	}
}

void PrismMesh::set_subdivide_depth(int p_divisions) {
	if (_check_count("subdivide_depth", p_divisions, 0)) {
		subdivide_d = p_divisions;
		_request_update();
	}
}

void PrismMesh::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_left_to_right", "left_to_right"), &PrismMesh::set_left_to_right);
	ClassDB::bind_method(D_METHOD("get_left_to_right"), &PrismMesh::get_left_to_right);
	ClassDB::bind_method(D_METHOD("set_size", "size"), &PrismMesh::set_size);
	ClassDB::bind_method(D_METHOD("get_size"), &PrismMesh::get_size);
	ClassDB::bind_method(D_METHOD("set_subdivide_width", "segments"), &PrismMesh::set_subdivide_width);
	ClassDB::bind_method(D_METHOD("get_subdivide_width"), &PrismMesh::get_subdivide_width);
	ClassDB::bind_method(D_METHOD("set_subdivide_height", "segments"), &PrismMesh::set_subdivide_height);
	ClassDB::bind_method(D_METHOD("get_subdivide_height"), &PrismMesh::get_subdivide_height);
	ClassDB::bind_method(D_METHOD("set_subdivide_depth", "segments"), &PrismMesh::set_subdivide_depth);
	ClassDB::bind_method(D_METHOD("get_subdivide_depth"), &PrismMesh::get_subdivide_depth);

	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "left_to_right", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_left_to_right", "get_left_to_right");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "size", PROPERTY_HINT_NONE, "suffix:m"), "set_size", "get_size");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_width", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_width", "get_subdivide_width");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_height", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_height", "get_subdivide_height");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "subdivide_depth", PROPERTY_HINT_RANGE, "0,100,1,or_greater"), "set_subdivide_depth", "get_subdivide_depth");
}
