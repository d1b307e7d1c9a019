/**************************************************************************/
/*  primitive_meshes.h                                                    */
/**************************************************************************/
/* godot-area: PrimitiveMesh (a Mesh generated from a few parameters)     */
/* and PlaneMesh, QuadMesh, BoxMesh, SphereMesh, CylinderMesh,            */
/* CapsuleMesh, TorusMesh, PrismMesh with Godot 4.7 property names and    */
/* defaults. Each generates one indexed triangle surface with             */
/* normals, tangents and UVs; winding and tangent conventions are the     */
/* ones documented in mesh.h (clockwise front seen from outside, Godot).  */
/* Geometry is rebuilt lazily: setters mark it dirty, the next read       */
/* (get_rid, get_aabb, get_mesh_arrays...) regenerates it.                */
/* The create_*_arrays() statics are the plain generators (no RS needed). */

#pragma once

#include "scene/resources/mesh.h"

class PrimitiveMesh : public Mesh {
	GDCLASS(PrimitiveMesh, Mesh);

	RID mesh;
	Ref<Material> material;
	bool flip_faces = false;
	mutable bool dirty = true;
	// Set once the RID was handed out (a MeshInstance3D draws it): later changes rebuild at once,
	// since this engine has no deferred-call queue to rebuild it before the next frame.
	mutable bool rid_in_use = false;
	mutable RS::SurfaceData arrays;

	void _update() const;

protected:
	static void _bind_methods();
	// Subclasses fill r_arrays (vertices, normals, tangents, uvs, indices).
	virtual void _create_mesh_array(RS::SurfaceData &r_arrays) const = 0;
	// Setters call this after a change.
	void _request_update();
	// Setter guard for counts (subdivisions, segments): false with a message when out of range.
	static bool _check_count(const char *p_property, int p_value, int p_min);

public:
	// Upper bound for subdivisions / segments, so one typo cannot ask for gigabytes.
	static constexpr int MAX_SEGMENTS = 4096;

	void set_material(const Ref<Material> &p_material);
	Ref<Material> get_material() const { return material; }
	// Reverses the winding and the normals (for viewing from inside).
	void set_flip_faces(bool p_enable);
	bool get_flip_faces() const { return flip_faces; }

	// The generated surface (after flip_faces).
	RS::SurfaceData get_mesh_arrays() const;

	int get_surface_count() const override { return 1; }
	AABB get_aabb() const override;
	Ref<Material> surface_get_material(int p_surface) const override;
	RS::SurfaceData surface_get_arrays(int p_surface) const override;
	RID get_rid() const override;

	// Appends a (p_segments_u + 1) x (p_segments_v + 1) vertex grid spanning p_corner + [0,1]·p_u
	// + [0,1]·p_v with normal p_normal, UVs mapped to p_uv_pos + [0,1]·p_uv_size, and its
	// triangles wound clockwise seen from the side p_normal points to (front faces, mesh.h).
	static void add_grid(RS::SurfaceData &r_arrays, const Vector3 &p_corner, const Vector3 &p_u, const Vector3 &p_v, const Vector3 &p_normal, int p_segments_u, int p_segments_v, const Vector2 &p_uv_pos, const Vector2 &p_uv_size);

	PrimitiveMesh();
	~PrimitiveMesh() override;
};

class PlaneMesh : public PrimitiveMesh {
	GDCLASS(PlaneMesh, PrimitiveMesh);

public:
	enum Orientation {
		FACE_X,
		FACE_Y,
		FACE_Z,
	};

private:
	Vector2 size = Vector2(2, 2);
	int subdivide_w = 0;
	int subdivide_d = 0;
	Vector3 center_offset;
	Orientation orientation = FACE_Y;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// FACE_Y: normal +Y, size.x along X, size.y along Z (UV v grows towards +Z).
	// FACE_Z: normal +Z, size.x along X, size.y along Y (UV v grows towards -Y).
	// FACE_X: normal +X, size.x along -Z, size.y along Y (UV v grows towards -Y).
	static void create_plane_arrays(RS::SurfaceData &r_arrays, const Vector2 &p_size, int p_subdivide_w, int p_subdivide_d, const Vector3 &p_center_offset, Orientation p_orientation);

	void set_size(const Vector2 &p_size);
	Vector2 get_size() const { return size; }
	void set_subdivide_width(int p_divisions);
	int get_subdivide_width() const { return subdivide_w; }
	void set_subdivide_depth(int p_divisions);
	int get_subdivide_depth() const { return subdivide_d; }
	void set_center_offset(const Vector3 &p_offset);
	Vector3 get_center_offset() const { return center_offset; }
	void set_orientation(Orientation p_orientation);
	Orientation get_orientation() const { return orientation; }

	PlaneMesh() {}
};

// Godot 4's QuadMesh: a PlaneMesh facing +Z with size (1, 1).
class QuadMesh : public PlaneMesh {
	GDCLASS(QuadMesh, PlaneMesh);

protected:
	static void _bind_methods() {}

public:
	QuadMesh();
};

class BoxMesh : public PrimitiveMesh {
	GDCLASS(BoxMesh, PrimitiveMesh);

	Vector3 size = Vector3(1, 1, 1);
	int subdivide_w = 0;
	int subdivide_h = 0;
	int subdivide_d = 0;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// Six faces, each its own grid (hard edges). UV atlas of 3 x 2 cells: top row +Z, +X, -Z;
	// bottom row -X, +Y, -Y.
	static void create_box_arrays(RS::SurfaceData &r_arrays, const Vector3 &p_size, int p_subdivide_w, int p_subdivide_h, int p_subdivide_d);

	void set_size(const Vector3 &p_size);
	Vector3 get_size() const { return size; }
	void set_subdivide_width(int p_divisions);
	int get_subdivide_width() const { return subdivide_w; }
	void set_subdivide_height(int p_divisions);
	int get_subdivide_height() const { return subdivide_h; }
	void set_subdivide_depth(int p_divisions);
	int get_subdivide_depth() const { return subdivide_d; }

	BoxMesh() {}
};

class SphereMesh : public PrimitiveMesh {
	GDCLASS(SphereMesh, PrimitiveMesh);

	float radius = 0.5f;
	float height = 1.0f;
	int radial_segments = 64;
	int rings = 32;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// An ellipsoid of p_radius around Y and half-height p_height / 2: (p_rings + 2) rows of
	// (p_radial_segments + 1) vertices (the seam column is duplicated for UVs), pole to pole.
	// U goes around (+Z towards +X), V from the top pole (0) to the bottom pole (1).
	static void create_sphere_arrays(RS::SurfaceData &r_arrays, float p_radius, float p_height, int p_radial_segments, int p_rings);

	// Radius and height must be finite and > 0; radial_segments >= 4; rings >= 1.
	void set_radius(float p_radius);
	float get_radius() const { return radius; }
	void set_height(float p_height);
	float get_height() const { return height; }
	void set_radial_segments(int p_segments);
	int get_radial_segments() const { return radial_segments; }
	void set_rings(int p_rings);
	int get_rings() const { return rings; }

	SphereMesh() {}
};

class CylinderMesh : public PrimitiveMesh {
	GDCLASS(CylinderMesh, PrimitiveMesh);

	float top_radius = 0.5f;
	float bottom_radius = 0.5f;
	float height = 2.0f;
	int radial_segments = 64;
	int rings = 4;
	bool cap_top = true;
	bool cap_bottom = true;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// A cylinder (or cone, or truncated cone) around Y from -p_height / 2 to +p_height / 2: the side is
	// (p_rings + 2) rows of (p_radial_segments + 1) vertices from the top edge down (normals tilted by
	// the slope), then the top and bottom caps (fans around a centre vertex; none for a cap of radius 0
	// or switched off). UVs: side in v 0..0.5 (u around, +Z towards +X), top cap centred at (0.25, 0.75),
	// bottom cap at (0.75, 0.75).
	static void create_cylinder_arrays(RS::SurfaceData &r_arrays, float p_top_radius, float p_bottom_radius, float p_height, int p_radial_segments, int p_rings, bool p_cap_top, bool p_cap_bottom);

	// Radii finite and >= 0, height finite and > 0; radial_segments >= 4; rings >= 0.
	void set_top_radius(float p_radius);
	float get_top_radius() const { return top_radius; }
	void set_bottom_radius(float p_radius);
	float get_bottom_radius() const { return bottom_radius; }
	void set_height(float p_height);
	float get_height() const { return height; }
	void set_radial_segments(int p_segments);
	int get_radial_segments() const { return radial_segments; }
	void set_rings(int p_rings);
	int get_rings() const { return rings; }
	void set_cap_top(bool p_enable);
	bool is_cap_top() const { return cap_top; }
	void set_cap_bottom(bool p_enable);
	bool is_cap_bottom() const { return cap_bottom; }

	CylinderMesh() {}
};

class CapsuleMesh : public PrimitiveMesh {
	GDCLASS(CapsuleMesh, PrimitiveMesh);

	float radius = 0.5f;
	float height = 2.0f;
	int radial_segments = 64;
	int rings = 8;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// A cylinder of p_radius with hemispherical ends around Y, p_height tall in all (>= 2 p_radius):
	// each hemisphere is (p_rings + 2) rows of (p_radial_segments + 1) vertices from its pole to the
	// equator, the two equators joined by the straight band. V follows the arc length pole to pole.
	static void create_capsule_arrays(RS::SurfaceData &r_arrays, float p_radius, float p_height, int p_radial_segments, int p_rings);

	// As in Godot, a capsule is never shorter than its two hemispheres: a radius above height / 2
	// raises the height to 2 radius, a height below 2 radius lowers the radius to height / 2.
	void set_radius(float p_radius);
	float get_radius() const { return radius; }
	void set_height(float p_height);
	float get_height() const { return height; }
	void set_radial_segments(int p_segments);
	int get_radial_segments() const { return radial_segments; }
	void set_rings(int p_rings);
	int get_rings() const { return rings; }

	CapsuleMesh() {}
};

class TorusMesh : public PrimitiveMesh {
	GDCLASS(TorusMesh, PrimitiveMesh);

	float inner_radius = 0.5f;
	float outer_radius = 1.0f;
	int rings = 64;
	int ring_segments = 32;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// A torus around Y between radii p_inner and p_outer (swapped when given the other way round, as
	// Godot does): p_rings + 1 slices around Y (u, +Z towards +X) of p_ring_segments + 1 vertices
	// around the tube (v, from the outer equator upwards).
	static void create_torus_arrays(RS::SurfaceData &r_arrays, float p_inner_radius, float p_outer_radius, int p_rings, int p_ring_segments);

	// Radii finite and >= 0; rings and ring_segments >= 3.
	void set_inner_radius(float p_radius);
	float get_inner_radius() const { return inner_radius; }
	void set_outer_radius(float p_radius);
	float get_outer_radius() const { return outer_radius; }
	void set_rings(int p_rings);
	int get_rings() const { return rings; }
	void set_ring_segments(int p_segments);
	int get_ring_segments() const { return ring_segments; }

	TorusMesh() {}
};

class PrismMesh : public PrimitiveMesh {
	GDCLASS(PrismMesh, PrimitiveMesh);

	float left_to_right = 0.5f;
	Vector3 size = Vector3(1, 1, 1);
	int subdivide_w = 0;
	int subdivide_h = 0;
	int subdivide_d = 0;

protected:
	static void _bind_methods();
	void _create_mesh_array(RS::SurfaceData &r_arrays) const override;

public:
	// A triangular prism in a box of p_size around the origin: the triangle in XY (base at -Y, apex at
	// +Y, p_left_to_right 0 over the left edge, 1 over the right), extruded along Z. Faces: front (+Z)
	// and back triangles (rows up to the apex), the left and right slopes and the base. UV atlas of
	// 3 x 2 cells: top row front, right, back; bottom row left, base.
	static void create_prism_arrays(RS::SurfaceData &r_arrays, float p_left_to_right, const Vector3 &p_size, int p_subdivide_w, int p_subdivide_h, int p_subdivide_d);

	// left_to_right in [0, 1]; size finite and >= 0.
	void set_left_to_right(float p_value);
	float get_left_to_right() const { return left_to_right; }
	void set_size(const Vector3 &p_size);
	Vector3 get_size() const { return size; }
	void set_subdivide_width(int p_divisions);
	int get_subdivide_width() const { return subdivide_w; }
	void set_subdivide_height(int p_divisions);
	int get_subdivide_height() const { return subdivide_h; }
	void set_subdivide_depth(int p_divisions);
	int get_subdivide_depth() const { return subdivide_d; }

	PrismMesh() {}
};

VARIANT_ENUM_CAST(PlaneMesh::Orientation);
