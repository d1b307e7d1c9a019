/**************************************************************************/
/*  render_scene_helpers.h                                                */
/**************************************************************************/
/* Shared test helpers that need no GPU: small meshes (quad, plane, box, */
/* sphere)                                                                */
/* and hand-made RenderSceneData views for renderers tested as units (the */
/* Forward+ renderer in tests/servers, the reference in tests/modules).   */

#pragma once

#include "core/math/math_funcs.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering/renderer_scene_render.h"

#include <cmath>
#include <vector>

namespace RenderTest {

// Appends a quad centred at p_center with half axes p_u, p_v; its front (normal p_u x p_v) is
// clockwise as seen from the front (Godot's winding).
inline void add_quad(RS::SurfaceData &r_s, const Vector3 &p_center, const Vector3 &p_u, const Vector3 &p_v) {
	uint32_t base = uint32_t(r_s.vertices.size());
	Vector3 n = p_u.cross(p_v).normalized();
	Vector3 corners[4] = { p_center - p_u - p_v, p_center + p_u - p_v, p_center + p_u + p_v, p_center - p_u + p_v };
	for (int i = 0; i < 4; i++) {
		r_s.vertices.push_back(corners[i]);
		r_s.normals.push_back(n);
	}
	uint32_t idx[6] = { 0, 2, 1, 0, 3, 2 };
	for (int i = 0; i < 6; i++) {
		r_s.indices.push_back(base + idx[i]);
	}
}

// Square y = 0 of half side p_half_size, normal +Y.
inline RS::SurfaceData make_plane(float p_half_size) {
	RS::SurfaceData s;
	add_quad(s, Vector3(), Vector3(0, 0, p_half_size), Vector3(p_half_size, 0, 0));
	return s;
}

// Closed box of half extents p_half around the origin, normals outward (BoxMesh's arrays, without
// tangents and UVs so add_quad() can extend it).
inline RS::SurfaceData make_box(const Vector3 &p_half) {
	RS::SurfaceData s;
	BoxMesh::create_box_arrays(s, p_half * 2, 0, 0, 0);
	s.tangents.clear();
	s.uvs.clear();
	return s;
}

// UV sphere of radius p_radius around the origin with p_rings bands of latitude and p_segments of
// longitude, smooth normals (SphereMesh's arrays, whose `rings` counts the p_rings - 1 inner circles).
inline RS::SurfaceData make_sphere(float p_radius, int p_rings, int p_segments) {
	RS::SurfaceData s;
	SphereMesh::create_sphere_arrays(s, p_radius, 2.0f * p_radius, p_segments, p_rings - 1);
	return s;
}

// A view of p_w x p_h pixels from p_cam (near 0.05 m) on a black background, no ambient light.
inline RenderSceneData make_scene(const Transform3D &p_cam, float p_fovy, int p_w, int p_h, float p_z_far) {
	RenderSceneData d;
	d.cam_transform = p_cam;
	d.z_near = 0.05f;
	d.z_far = p_z_far;
	d.fovy_degrees = p_fovy;
	d.cam_projection = Projection::create_perspective(p_fovy, float(p_w) / float(p_h), d.z_near, d.z_far);
	d.viewport_width = p_w;
	d.viewport_height = p_h;
	d.environment.has_environment = true;
	d.environment.background = RS::ENV_BG_COLOR;
	d.environment.bg_color = Color(0, 0, 0, 1);
	d.environment.bg_energy = 1.0f;
	d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
	d.environment.ambient_color = Color(0, 0, 0, 1);
	d.environment.ambient_energy = 0.0f;
	return d;
}

// Adds one mesh instance (material override, world transform) to a scene.
inline void add_geometry(RenderSceneData &r_d, RID p_mesh, RID p_material, const Transform3D &p_xform = Transform3D()) {
	RenderSceneData::GeometryInstance g;
	g.mesh = p_mesh;
	g.material_override = p_material;
	g.transform = p_xform;
	r_d.geometry.push_back(g);
}

// Adds one visible light instance to a scene.
inline void add_light(RenderSceneData &r_d, RID p_light, RS::LightType p_type, const Transform3D &p_xform) {
	RenderSceneData::LightInstance l;
	l.light = p_light;
	l.type = p_type;
	l.transform = p_xform;
	r_d.lights.push_back(l);
}

// Camera at height p_height looking along -Y with -Z as screen-up.
inline Transform3D camera_looking_down(float p_height) {
	return Transform3D(Basis::looking_at(Vector3(0, -1, 0), Vector3(0, 0, -1)), Vector3(0, p_height, 0));
}

// Light basis whose local -Z (emission) points to world -Y; local X stays world X, local Y becomes world -Z.
inline Basis facing_down() {
	return Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f);
}

// World point on y = 0 seen through the centre of pixel (p_px, p_py) (top row first).
inline Vector3 pixel_on_ground(const RenderSceneData &p_d, int p_px, int p_py) {
	float t = std::tan(Math::deg_to_rad(p_d.fovy_degrees) * 0.5f);
	float aspect = float(p_d.viewport_width) / float(p_d.viewport_height);
	float x_ndc = (p_px + 0.5f) / p_d.viewport_width * 2.0f - 1.0f;
	float y_ndc = 1.0f - (p_py + 0.5f) / p_d.viewport_height * 2.0f;
	Vector3 dir = p_d.cam_transform.basis.xform(Vector3(x_ndc * t * aspect, y_ndc * t, -1.0f));
	Vector3 o = p_d.cam_transform.origin;
	return o + dir * (-o.y / dir.y);
}

} // namespace RenderTest
