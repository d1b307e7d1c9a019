/**************************************************************************/
/*  primitive_meshes.h                                                    */
/**************************************************************************/
/* godot-area: PrimitiveMesh (a Mesh generated from a few parameters)     */
/* and PlaneMesh, QuadMesh, BoxMesh, SphereMesh with Godot 4.7 property   */
/* names and defaults. Each generates one indexed triangle surface with   */
/* normals, tangents and UVs; winding and tangent conventions are the     */
/* ones documented in mesh.h (clockwise front seen from outside, Godot). */
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

VARIANT_ENUM_CAST(PlaneMesh::Orientation);
