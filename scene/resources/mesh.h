/**************************************************************************/
/*  mesh.h                                                                */
/**************************************************************************/
/* godot-area: Mesh (abstract: surfaces, AABB, RS mesh RID) and ArrayMesh */
/* (surfaces added from RS::SurfaceData triangle lists).                  */
/*                                                                        */
/* Winding convention (all meshes made here, and what the renderer treats */
/* as front): Godot's. A triangle (a, b, c) is FRONT-facing when it is    */
/* clockwise seen from outside, i.e. cross(b - a, c - a) points INTO the  */
/* surface, against the outward normal. glTF files are counter-clockwise; */
/* the glTF importer reverses them. Tangents are 4 floats: xyz            */
/* along +U, w = +1 or -1 so that cross(normal, tangent.xyz) * w points   */
/* along -V (towards the top of the texture; OpenGL-style normal maps).   */

#pragma once

#include "core/io/resource.h"
#include "core/math/aabb.h"
#include "scene/resources/material.h"
#include "servers/rendering_server.h"

#include <vector>

class Mesh : public Resource {
	GDCLASS(Mesh, Resource);

protected:
	static void _bind_methods();

public:
	enum PrimitiveType {
		PRIMITIVE_POINTS,
		PRIMITIVE_LINES,
		PRIMITIVE_LINE_STRIP,
		PRIMITIVE_TRIANGLES,
		PRIMITIVE_TRIANGLE_STRIP,
		PRIMITIVE_MAX,
	};

	virtual int get_surface_count() const = 0;
	// Union of the surface bounds, in mesh space.
	virtual AABB get_aabb() const = 0;
	virtual Ref<Material> surface_get_material(int p_surface) const = 0;
	// The CPU copy of one surface (empty SurfaceData for a bad index, with an error).
	virtual RS::SurfaceData surface_get_arrays(int p_surface) const = 0;

	Mesh() {}
};

class ArrayMesh : public Mesh {
	GDCLASS(ArrayMesh, Mesh);

	struct Surface {
		RS::SurfaceData data;
		Ref<Material> material;
	};

	RID mesh;
	std::vector<Surface> surfaces;
	AABB aabb;

protected:
	static void _bind_methods();

public:
	// Validates and appends a surface: only PRIMITIVE_TRIANGLES; non-empty finite vertices;
	// every optional array empty or one entry per vertex (tangents 4 per vertex); indices a
	// multiple of 3 and in range (or, without indices, a vertex count that is a multiple of 3).
	// Returns false with a message naming the problem and adds nothing on bad input.
	bool add_surface_from_arrays(PrimitiveType p_primitive, const RS::SurfaceData &p_arrays);
	// Same as add_surface_from_arrays(PRIMITIVE_TRIANGLES, ...).
	bool add_surface(const RS::SurfaceData &p_arrays) { return add_surface_from_arrays(PRIMITIVE_TRIANGLES, p_arrays); }
	void surface_set_material(int p_surface, const Ref<Material> &p_material);
	Ref<Material> surface_get_material(int p_surface) const override;
	RS::SurfaceData surface_get_arrays(int p_surface) const override;
	void clear_surfaces();

	int get_surface_count() const override { return (int)surfaces.size(); }
	AABB get_aabb() const override { return aabb; }
	RID get_rid() const override { return mesh; }

	// Shared by ArrayMesh and PrimitiveMesh: returns an empty string when p_arrays is a valid
	// triangle list, else the reason.
	static String validate_surface(const RS::SurfaceData &p_arrays);
	// Bounds of p_arrays' vertices (empty AABB when there are none).
	static AABB compute_aabb(const RS::SurfaceData &p_arrays);

	ArrayMesh();
	~ArrayMesh() override;
};

VARIANT_ENUM_CAST(Mesh::PrimitiveType);
