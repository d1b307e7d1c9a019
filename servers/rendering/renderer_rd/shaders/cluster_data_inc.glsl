/**************************************************************************/
/*  cluster_data_inc.glsl                                                 */
/**************************************************************************/
/* Clustered-shading constants, the per-element bounding volume and the   */
/* cluster buffer layout, shared by cluster_build.glsl (writer) and the   */
/* scene shader (reader). Mirror of the constants and of                  */
/* ClusterBuilderRD::ElementData in                                       */
/* servers/rendering/renderer_rd/cluster_builder_rd.h.                    */
/*                                                                        */
/* Clusters: the screen is cut into square tiles of tile_size pixels (8 */
/* to 128, ClusterBuilderRD::tile_size_for(); tile = gl_FragCoord.xy /    */
/* tile_size, from the scene data) and the view depth 0..z_far into       */
/* CLUSTER_Z_SLICES linear slices (slice = -z_view / z_far * 32, clamped  */
/* to 0..31, as Godot). For every element type, every cluster stores one  */
/* bit per element: words_per_type 32-bit words, bit (i & 31) of word     */
/* (i >> 5) set when element i of that type may touch the cluster.        */
/*                                                                        */
/* Buffer layout (uint data[]), word w of type t in tile (x, y), slice z: */
/*   ((t * tile_count + y * tiles_x + x) * CLUSTER_Z_SLICES + z)          */
/*       * words_per_type + w                                             */
/* i.e. per type, per tile, 32 consecutive slice masks. A "per tile mask  */
/* + depth range" (Godot's packing) saves memory but loses exactness per  */
/* slice; at our sizes per-cluster masks are small and simplest.          */
/*                                                                        */
/* Element i of type t is ALWAYS the light at index i of that type's      */
/* light array (LightStorage fills both in the same loop).                */

#ifndef CLUSTER_DATA_INC_GLSL
#define CLUSTER_DATA_INC_GLSL

#define CLUSTER_Z_SLICES 32 // Must match ClusterBuilderRD::Z_SLICES.

// Element types. Must match ClusterBuilderRD::ElementType.
#define CLUSTER_ELEMENT_TYPE_OMNI 0
#define CLUSTER_ELEMENT_TYPE_SPOT 1
#define CLUSTER_ELEMENT_TYPE_AREA 2
#define CLUSTER_ELEMENT_TYPE_MAX 3

// Bounding volume kinds. Must match ClusterBuilderRD::BoundType. A new element type picks one of these
// (or adds one, with its test in cluster_build.glsl).
#define CLUSTER_BOUND_SPHERE 0 // Sphere (position, radius).
#define CLUSTER_BOUND_CONE 1 // Sphere (position, radius) intersected with the cone (apex position, axis direction, cone_cos/cone_sin).
#define CLUSTER_BOUND_BOX 2 // Oriented box (centre position, unit axes axis_x, cross(direction, axis_x), direction, half sizes extents) intersected with the sphere of radius `radius` centred at position - direction * extents.z.

// Bounding volume of each element type. Adding a type = a define above, a line here, and (for a new
// bound kind) its test in cluster_build.glsl.
uint cluster_get_bound_type(uint p_type) {
	if (p_type == CLUSTER_ELEMENT_TYPE_SPOT) {
		return CLUSTER_BOUND_CONE;
	}
	if (p_type == CLUSTER_ELEMENT_TYPE_AREA) {
		return CLUSTER_BOUND_BOX; // (a + 2r) x (b + 2r) x r in front of the light (thesis section 5.1.1).
	}
	return CLUSTER_BOUND_SPHERE;
}

struct ClusterElementData { // 64 bytes, std430. Mirror: ClusterBuilderRD::ElementData.
	vec3 position; // 0: view space centre (sphere, box) / apex (cone), metres.
	float radius; // 12: metres; box: radius of the thesis' eq. 5.1 sphere r + |(a, b)| / 2 around the light centre.
	vec3 direction; // 16: unit axis of the cone / box axis z (area light normal), view space.
	float cone_cos; // 28: cosine of the cone half angle.
	vec3 extents; // 32: box half sizes along axis_x, cross(direction, axis_x), direction (metres).
	float cone_sin; // 44: sine of the cone half angle.
	vec3 axis_x; // 48: box unit axis x, view space.
	float sphere_offset; // 60: box: from position back to the light centre along -direction (one-sided lights: extents.z; all around: 0).
};

// Index of the first mask word of cluster (p_tile, p_slice) for element type p_type.
uint cluster_get_offset(uint p_type, uvec2 p_tile, uint p_slice, uint p_tiles_x, uint p_tile_count, uint p_words_per_type) {
	uint tile_index = p_tile.y * p_tiles_x + p_tile.x;
	return ((p_type * p_tile_count + tile_index) * CLUSTER_Z_SLICES + p_slice) * p_words_per_type;
}

// Slice of a view-space depth (positive distance in front of the camera).
uint cluster_get_slice(float p_depth, float p_z_far) {
	return uint(clamp(floor(p_depth / p_z_far * float(CLUSTER_Z_SLICES)), 0.0, float(CLUSTER_Z_SLICES - 1)));
}

#endif // CLUSTER_DATA_INC_GLSL
