/**************************************************************************/
/*  cluster_build.glsl                                                    */
/**************************************************************************/
/* Builds the cluster masks (layout: cluster_data_inc.glsl). One variant */
/* per element type (CLUSTER_TYPE, so each compiles only its own bound    */
/* test) and one dispatch per type over the words that hold live          */
/* elements: one thread per (cluster, mask word) computes the view-space  */
/* AABB of its cluster's frustum piece, tests the 32 elements of its word */
/* against it and writes the word (0 past the element count: the words    */
/* live in the previous frame are rewritten so, ClusterBuilderRD).        */
/*                                                                        */
/* Godot rasterizes proxy meshes (icosphere, cone) into tiles; we test    */
/* analytic bounding volumes instead, which is exact-conservative on any  */
/* rasterizer (lavapipe included): no coverage rules, no overfit scales.  */
/* Conservative = a cluster may get an element that does not touch it,   */
/* never the reverse; the margins below absorb float rounding.            */
/*                                                                        */
/* C++: ClusterBuilderRD (servers/rendering/renderer_rd/                  */
/* cluster_builder_rd.cpp), push constant mirror ClusterBuilderRD::       */
/* BuildPushConstant.                                                     */

#[compute]

#version 450

#include "cluster_data_inc.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(set = 0, binding = 0, std430) restrict readonly buffer Elements {
	ClusterElementData data[]; // [type * words_per_type * 32 + index]
}
elements;

layout(set = 0, binding = 1, std430) restrict writeonly buffer Clusters {
	uint data[];
}
clusters;

layout(push_constant, std430) uniform Params { // 112 bytes. Mirror: ClusterBuilderRD::BuildPushConstant.
	mat4 view_from_clip; // Inverse of the (Vulkan depth-corrected) projection.
	vec2 screen_size; // Pixels.
	float z_far; // Metres; slices cover view depth 0..z_far.
	uint words_per_type; // Mask words per cluster and type (max elements per type / 32).
	uint tiles_x;
	uint tiles_y;
	uint tile_size; // Pixels (ClusterBuilderRD::tile_size_for()).
	uint pad0;
	uvec4 element_count; // Elements of each type (x = omni, y = spot, z = area).
}
params;

// Relative margins. Cluster boxes grow by CLUSTER_BOX_MARGIN of their size plus an absolute 1e-4 m,
// element volumes by CLUSTER_ELEMENT_MARGIN of their radius: float rounding of the fragment's
// view position and of the depth/tile mapping is orders of magnitude smaller (~1e-6 relative).
#define CLUSTER_BOX_MARGIN 1e-3
#define CLUSTER_ELEMENT_MARGIN 1e-3

// Point of view space on the line through clip-space (ndc.xy, 0) and (ndc.xy, 1) at depth p_depth
// (a positive distance, z_view = -p_depth). Works for perspective and orthogonal projections.
vec3 unproject_at_depth(vec2 p_ndc, float p_depth) {
	vec4 a = params.view_from_clip * vec4(p_ndc, 0.0, 1.0);
	vec4 b = params.view_from_clip * vec4(p_ndc, 1.0, 1.0);
	vec3 pa = a.xyz / a.w;
	vec3 pb = b.xyz / b.w;
	float t = (-p_depth - pa.z) / (pb.z - pa.z);
	return mix(pa, pb, t);
}

bool test_sphere(vec3 p_box_min, vec3 p_box_max, vec3 p_center, float p_radius) {
	vec3 closest = clamp(p_center, p_box_min, p_box_max);
	vec3 d = closest - p_center;
	return dot(d, d) <= p_radius * p_radius;
}

// Cone (apex p_apex, unit axis p_axis, half angle with cosine/sine p_cos/p_sin) against a sphere
// bounding the cluster. In the plane through the axis and the sphere centre, with a = axial and
// b = radial distance of the centre from the apex, b cos - a sin is a lower bound of the distance
// from the centre to the cone for every half angle in (0, pi) (it is the distance to the cone's
// boundary line, and its sign tells the side). Wronski 2017, "Cull that cone!".
bool test_cone(vec3 p_sphere_center, float p_sphere_radius, vec3 p_apex, vec3 p_axis, float p_cos, float p_sin) {
	vec3 v = p_sphere_center - p_apex;
	float a = dot(v, p_axis);
	float b = sqrt(max(dot(v, v) - a * a, 0.0));
	float dist = b * p_cos - a * p_sin;
	return dist <= p_sphere_radius;
}

// Oriented box (centre p_center, orthonormal axes p_u0..2, half sizes p_h) against the axis-aligned
// cluster box: the separating axis theorem (Gottschalk et al. 1996, "OBBTree"). Two convex boxes are
// disjoint iff their projections are disjoint on one of 15 axes: the 3 + 3 face normals and the 9
// cross products of edge directions. Exact; a nearly degenerate cross-product axis (parallel edges) is
// skipped, which can only keep a cluster (conservative), never drop one.
bool test_obb(vec3 p_box_min, vec3 p_box_max, vec3 p_center, vec3 p_u0, vec3 p_u1, vec3 p_u2, vec3 p_h) {
	vec3 box_center = (p_box_min + p_box_max) * 0.5;
	vec3 box_half = (p_box_max - p_box_min) * 0.5;
	vec3 t = p_center - box_center;
	mat3 u = mat3(p_u0, p_u1, p_u2);
	// Cluster box face normals (x, y, z): the OBB's projected radius is sum_j h_j |u_j[i]|.
	for (int i = 0; i < 3; i++) {
		float rb = p_h.x * abs(p_u0[i]) + p_h.y * abs(p_u1[i]) + p_h.z * abs(p_u2[i]);
		if (abs(t[i]) > box_half[i] + rb) {
			return false;
		}
	}
	// OBB face normals.
	for (int j = 0; j < 3; j++) {
		vec3 l = u[j];
		float ra = dot(box_half, abs(l));
		if (abs(dot(t, l)) > ra + p_h[j]) {
			return false;
		}
	}
	// Edge cross products e_i x u_j.
	for (int i = 0; i < 3; i++) {
		vec3 e = vec3(0.0);
		e[i] = 1.0;
		for (int j = 0; j < 3; j++) {
			vec3 l = cross(e, u[j]);
			if (dot(l, l) < 1e-8) {
				continue;
			}
			float ra = dot(box_half, abs(l));
			float rb = p_h.x * abs(dot(p_u0, l)) + p_h.y * abs(dot(p_u1, l)) + p_h.z * abs(dot(p_u2, l));
			if (abs(dot(t, l)) > ra + rb) {
				return false;
			}
		}
	}
	return true;
}

// Support of the cluster's frustum piece (its 8 corners) along p_n: max over the piece of dot(p_n, x).
float frustum_support(vec3 p_corners[8], vec3 p_n) {
	float m = -1e30;
	for (uint i = 0; i < 8; i++) {
		m = max(m, dot(p_n, p_corners[i]));
	}
	return m;
}

vec3 closest_on_rect(vec3 p_point, vec3 p_center, vec3 p_u0, vec3 p_u1, vec2 p_half) {
	vec3 v = p_point - p_center;
	return p_center + p_u0 * clamp(dot(v, p_u0), -p_half.x, p_half.x) + p_u1 * clamp(dot(v, p_u1), -p_half.y, p_half.y);
}

// The influence region of a one-sided rectangle light: the points in front of it (p_n side) within p_range
// of the rectangle (the support of the range window W(d), area_light_common_inc.glsl). The cluster's frustum
// piece misses it if it lies wholly behind the light's plane, or if a separating axis shows it farther than
// p_range from the rectangle. Any axis gives a lower bound of the distance between the two convex sets; the
// one used is the direction between the closest pair found by two rounds of alternating projections
// (rectangle <-> the piece's AABB), which converge to the closest pair, so the bound is nearly the distance.
// Conservative whatever the number of rounds; p_slack (metres) absorbs the rounding of the corners.
bool test_rounded_rect(vec3 p_corners[8], vec3 p_box_min, vec3 p_box_max, vec3 p_center, vec3 p_u0, vec3 p_u1, vec3 p_n, vec2 p_half, float p_range, float p_slack) {
	if (frustum_support(p_corners, p_n) + p_slack < dot(p_n, p_center)) {
		return false; // Wholly behind the emitting side.
	}
	vec3 q = closest_on_rect((p_box_min + p_box_max) * 0.5, p_center, p_u0, p_u1, p_half);
	vec3 b = clamp(q, p_box_min, p_box_max);
	q = closest_on_rect(b, p_center, p_u0, p_u1, p_half);
	b = clamp(q, p_box_min, p_box_max);
	vec3 d = q - b;
	float len = length(d);
	if (len <= p_range) {
		return true; // The pair found is within range: the region is reached (or nearly: keep the cluster).
	}
	vec3 axis = d / len; // From the piece towards the rectangle.
	float rect_min = dot(axis, p_center) - abs(dot(axis, p_u0)) * p_half.x - abs(dot(axis, p_u1)) * p_half.y;
	return rect_min - frustum_support(p_corners, axis) <= p_range + p_slack;
}

void main() {
	uint cluster_count = params.tiles_x * params.tiles_y * CLUSTER_Z_SLICES;
	uint index = gl_GlobalInvocationID.x;
	const uint type = CLUSTER_TYPE;
	uint word = gl_GlobalInvocationID.y;
	if (index >= cluster_count || word >= params.words_per_type) {
		return;
	}
	uint slice = index % CLUSTER_Z_SLICES;
	uint tile_index = index / CLUSTER_Z_SLICES;
	uvec2 tile = uvec2(tile_index % params.tiles_x, tile_index / params.tiles_x);

	uint out_index = ((type * params.tiles_x * params.tiles_y + tile_index) * CLUSTER_Z_SLICES + slice) * params.words_per_type + word;

	uint count = params.element_count[type];
	uint first = word * 32;
	if (first >= count) {
		clusters.data[out_index] = 0;
		return;
	}

	// View-space AABB of the cluster: the 8 corners of its frustum piece.
	vec2 px_min = vec2(tile) * float(params.tile_size);
	vec2 px_max = px_min + vec2(float(params.tile_size));
	vec2 ndc_min = px_min / params.screen_size * 2.0 - 1.0;
	vec2 ndc_max = px_max / params.screen_size * 2.0 - 1.0;
	float slice_size = params.z_far / float(CLUSTER_Z_SLICES);
	float depth_near = float(slice) * slice_size;
	float depth_far = float(slice + 1) * slice_size;
	if (slice == CLUSTER_Z_SLICES - 1) {
		depth_far = params.z_far * 2.0; // Fragments past z_far (clipped anyway) clamp into the last slice.
	}

	vec3 box_min = vec3(1e30);
	vec3 box_max = vec3(-1e30);
	vec3 corners[8];
	for (uint i = 0; i < 8; i++) {
		vec2 ndc = vec2((i & 1) != 0 ? ndc_max.x : ndc_min.x, (i & 2) != 0 ? ndc_max.y : ndc_min.y);
		vec3 p = unproject_at_depth(ndc, (i & 4) != 0 ? depth_far : depth_near);
		corners[i] = p;
		box_min = min(box_min, p);
		box_max = max(box_max, p);
	}
	vec3 margin = (box_max - box_min) * CLUSTER_BOX_MARGIN + vec3(1e-4);
	box_min -= margin;
	box_max += margin;
	vec3 box_center = (box_min + box_max) * 0.5;
	float box_radius = length(box_max - box_center);

	uint mask = 0;
	uint last = min(first + 32, count);
	uint base = type * params.words_per_type * 32;
	for (uint i = first; i < last; i++) {
		ClusterElementData e = elements.data[base + i];
		float radius = e.radius * (1.0 + CLUSTER_ELEMENT_MARGIN);
		vec3 sphere_center = e.position;
		if (cluster_get_bound_type(type) == CLUSTER_BOUND_BOX) {
			// Area light: a one-sided light's box centre sits r / 2 in front of it (sphere_offset = extents.z), a
			// sphere or tube light's box is centred on it (0); the sphere (eq. 5.1) is centred on the light.
			sphere_center -= e.direction * e.sphere_offset;
		}
		bool hit = test_sphere(box_min, box_max, sphere_center, radius);
		if (hit && cluster_get_bound_type(type) == CLUSTER_BOUND_CONE) {
			// The range sphere, further cut by the cone.
			hit = test_cone(box_center, box_radius + e.radius * CLUSTER_ELEMENT_MARGIN, e.position, e.direction, e.cone_cos, e.cone_sin);
		}
		if (hit && cluster_get_bound_type(type) == CLUSTER_BOUND_BOX) {
			// Box AND the thesis' eq. 5.1 sphere (tested above): both contain the influence region (points in
			// front within r of the rectangle), so their intersection does too. The box is not inside the
			// sphere (its corners stick out for small lights), so testing both guarantees the area light
			// never takes more clusters than the sphere alone, and usually far fewer.
			vec3 u2 = e.direction;
			vec3 u0 = e.axis_x;
			vec3 u1 = cross(u2, u0);
			hit = test_obb(box_min, box_max, e.position, u0, u1, u2, e.extents * (1.0 + CLUSTER_ELEMENT_MARGIN) + vec3(1e-5));
			if (hit && e.sphere_offset > 0.0) {
				// A rectangle (or disk) light: the region itself, both bounds above being boxes or spheres around it.
				hit = test_rounded_rect(corners, box_min, box_max, e.position - u2 * e.sphere_offset, u0, u1, u2, e.extents.xy - vec2(2.0 * e.extents.z), 2.0 * e.extents.z * (1.0 + CLUSTER_ELEMENT_MARGIN), length(margin));
			}
		}
		if (hit) {
			mask |= 1u << (i - first);
		}
	}
	clusters.data[out_index] = mask;
}
