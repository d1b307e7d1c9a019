/**************************************************************************/
/*  area_shadow_adaptive_inc.glsl                                         */
/**************************************************************************/
/* Shared structures of the adaptive area-shadow passes                   */
/* (area_shadow_reprojection.glsl, area_shadow_banding.glsl). C++         */
/* mirrors: AreaShadowAdaptiveRD::GridData / AdaptiveLightData /          */
/* PointData / QueryData (renderer_rd/effects/area_shadow_adaptive.h).    */

#define AREA_SHADOW_ADAPTIVE_MAX_WORDS 3 // 95 points per light: a 9 x 9 tree has 81.

struct GridData { // std430, 32 bytes: one light's cells over the depth buffer.
	uvec2 origin; // Depth pixels.
	uvec2 size; // Cells.
	uint step; // Depth pixels per cell.
	uint offset; // First visibility word of the light.
	uvec2 extent; // Depth pixels covered.
};

struct AdaptiveLightData { // std430, 144 bytes.
	mat4 light_from_view; // View space -> light space (emission along -Z).
	vec2 half_size; // Rectangle half extents (m).
	float depth_scale; // Stored depth = distance * depth_scale.
	float bias; // Constant bias in receiver texels (shadow_bias).
	uint atlas_subdivision;
	uint quadrant_size;
	uint tile_size;
	uint point_offset; // First PointData of the light.
	uint point_count;
	uint words; // Visibility words per cell: (point_count + 1 + 31) / 32 (at most MAX_WORDS).
	uint query_offset; // First QueryData of the light.
	uint query_count;
	GridData grid;
};

struct PointData { // std430, 16 bytes: a sample point and its map.
	vec2 uv; // On the light's canonical square.
	uint tile; // Atlas tile.
	uint pad;
};

struct QueryData { // std430, 32 bytes: one tested quad.
	uvec4 corners; // Its four corners: indices into the light's points.
	uint light; // Index into Lights.
	uint pad0;
	uint pad1;
	uint pad2;
};
