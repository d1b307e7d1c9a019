/**************************************************************************/
/*  cluster_builder_rd.h                                                  */
/**************************************************************************/
/* godot-area: the Forward+ cluster builder (Godot's ClusterBuilderRD).   */
/* Square screen tiles (8-128 px) x 32 linear depth slices; per type and  */
/* cluster one bit per element. Layout and bounding-volume tests:         */
/* shaders/cluster_data_inc.glsl and shaders/cluster_build.glsl.          */
/*                                                                        */
/* Per frame: begin() -> add_light() per light, in GPU index order ->     */
/* bake_cluster() (uploads elements and records one compute dispatch).   */
/* Unlike Godot (proxy meshes rasterized into tiles) a compute shader     */
/* tests each element's analytic bounding volume against each cluster's  */
/* view-space AABB: exact-conservative on every rasterizer.               */
/*                                                                        */
/* Adding an element type: a value in ElementType (and the matching       */
/* define), a bound kind in cluster_get_bound_type() and, for a new kind, */
/* its test in cluster_build.glsl. Area lights did exactly that: type     */
/* AREA, bound kind BOX (oriented box, separating-axis test).             */

#pragma once

#include "core/math/projection.h"
#include "core/math/vector3.h"
#include "servers/rendering/renderer_rd/shader_rd.h"

#include <vector>

class ClusterBuilderRD {
public:
	/* Definition */

	// Tiles are the smallest power of two from 8 px whose grid has at most MAX_TILES tiles (a budget, as
	// Doom 2016's fixed cluster grid, not a fixed size): 8 px up to 960x540 (at 192x108 a 16 px tile is a
	// twelfth of the view: bench --targets P5), 16 px (Godot's size) from 1280x720 to 1920x1080, 32 px at 4K,
	// so the cluster buffer stays within ~50 MB at 512 lights per type whatever the resolution.
	static constexpr uint32_t MIN_TILE_SIZE = 8;
	static constexpr uint32_t MAX_TILES = 8192;
	static uint32_t tile_size_for(uint32_t p_width, uint32_t p_height);
	static constexpr uint32_t Z_SLICES = 32; // Must match CLUSTER_Z_SLICES.

	// Must match CLUSTER_ELEMENT_TYPE_* (shaders/cluster_data_inc.glsl).
	enum ElementType {
		ELEMENT_TYPE_OMNI_LIGHT,
		ELEMENT_TYPE_SPOT_LIGHT,
		ELEMENT_TYPE_AREA_LIGHT,
		ELEMENT_TYPE_MAX,
	};

	// Mirror of ClusterElementData (shaders/cluster_data_inc.glsl), 64 bytes std430.
	struct ElementData {
		float position[3]; // View space centre (sphere, box) / cone apex.
		float radius; // Sphere radius; box: eq. 5.1 radius (range + the shape's reach) around position - direction * sphere_offset.
		float direction[3]; // View space unit cone axis; box: unit axis z (the area light's normal).
		float cone_cos; // cos(half angle).
		float extents[3]; // Box half sizes along axis_x, axis_y (= direction x axis_x) and direction.
		float cone_sin; // sin(half angle).
		float axis_x[3]; // Box: unit axis x (view space).
		float sphere_offset; // Box: from the box centre back to the light centre along -direction (one-sided: extents.z; all around: 0).
	};
	static_assert(sizeof(ElementData) == 64, "ElementData must match shaders/cluster_data_inc.glsl.");
	static_assert(sizeof(ElementData) % 16 == 0, "ElementData must stay a multiple of 16 bytes.");

	// Mirror of the push constant in shaders/cluster_build.glsl, 112 bytes.
	struct BuildPushConstant {
		float view_from_clip[16];
		float screen_size[2];
		float z_far;
		uint32_t words_per_type;
		uint32_t tiles_x;
		uint32_t tiles_y;
		uint32_t tile_size; // Pixels.
		uint32_t pad0;
		uint32_t element_count[4];
	};
	static_assert(sizeof(BuildPushConstant) == 112, "BuildPushConstant must match shaders/cluster_build.glsl.");
	static_assert(sizeof(BuildPushConstant) % 16 == 0, "BuildPushConstant must stay a multiple of 16 bytes.");

private:
	/* Private Members */

	ShaderRD shader; // One variant per ElementType (CLUSTER_TYPE).
	RID pipelines[ELEMENT_TYPE_MAX];
	uint32_t written_words[ELEMENT_TYPE_MAX] = {}; // Mask words per cluster the last bake wrote, per type.
	uint32_t max_elements = 0; // Per type, multiple of 32.
	RID element_buffer; // ElementData[ELEMENT_TYPE_MAX * max_elements]
	std::vector<ElementData> elements; // Same layout, CPU side.
	uint32_t element_count[ELEMENT_TYPE_MAX] = {};

	// Per screen size.
	uint32_t width = 0;
	uint32_t height = 0;
	uint32_t tile_size = 16;
	uint32_t tiles_x = 0;
	uint32_t tiles_y = 0;
	RID cluster_buffer;
	RID uniform_set;

	Projection clip_from_view; // Vulkan-corrected.
	float z_far = 1.0f;
	float element_depth_max = 0.0f; // Furthest view depth any element's bound reaches (metres), this frame.

public:
	/* Public Methods */

	// Compiles the build shader and allocates the element buffer. p_max_elements (per type) is rounded
	// up to a multiple of 32. Returns false (with an error) when the shader does not compile.
	bool initialize(uint32_t p_max_elements);
	// Frees every GPU object (before RenderingDevice::finalize()).
	void finalize();
	bool is_initialized() const { return pipelines[0].is_valid(); }

	// (Re)allocates the cluster buffer for a render size. Returns false for zero sizes.
	bool setup(uint32_t p_width, uint32_t p_height);

	// Starts a frame: p_clip_from_view is the projection used for rendering (with Vulkan depth
	// correction), p_z_far the depth the 32 slices cover. Clears the element lists.
	void begin(const Projection &p_clip_from_view, float p_z_far);
	// Adds a light in view space. Omni: bound sphere (p_position, p_radius). Spot: range sphere cut by the
	// cone of half angle p_spot_half_angle (radians) around p_direction. Returns false when full.
	bool add_light(ElementType p_type, const Vector3 &p_position, float p_radius, const Vector3 &p_direction = Vector3(0, 0, -1), float p_spot_half_angle = 0.0f);
	// Adds an area light (type AREA) in view space: rectangle centre p_center, half axes p_half_axis_x/y
	// (size / 2 along the light's local X and Y), unit emission normal p_normal, range p_range. Bound:
	// the oriented box (a + 2r) x (b + 2r) x r in front of the rectangle (thesis section 5.1.1), which
	// contains every point in front within distance r of the rectangle, intersected with the thesis'
	// eq. 5.1 sphere (radius r + sqrt(a^2 + b^2) / 2 around the centre). Returns false when full.
	bool add_area_light(const Vector3 &p_center, const Vector3 &p_half_axis_x, const Vector3 &p_half_axis_y, const Vector3 &p_normal, float p_range);
	// The view depth the 32 slices cover: p_z_far of begin(), or less where every element's bound ends
	// nearer (the furthest depth any bound sphere reaches, + 0.1 %). Fragments past it hold no light at
	// all, so the slices are spent where lights are (a floor lit from 8-30 m of a 100 m camera range
	// gets slices 4x thinner). Call after the last add_*(); the scene shader slices with the same value.
	float get_slice_depth() const;
	// Adds an area light that emits all around (sphere, tube shapes) in view space: the oriented box of
	// half extents p_extents centred on the light centre p_center (axes p_axis_x, cross(p_axis_z, p_axis_x),
	// p_axis_z; unit, orthogonal), intersected with the sphere of radius p_radius around p_center.
	bool add_area_light_box(const Vector3 &p_center, const Vector3 &p_axis_x, const Vector3 &p_axis_z, const Vector3 &p_extents, float p_radius);
	// Uploads the elements and records the build dispatch (outside any list). p_type_count < ELEMENT_TYPE_MAX
	// builds only the first types (the benchmark's "no area code" baseline; the other masks are stale).
	void bake_cluster(uint32_t p_type_count = ELEMENT_TYPE_MAX);

	RID get_cluster_buffer() const { return cluster_buffer; }
	uint32_t get_tile_size() const { return tile_size; } // Pixels, set by set_size() (tile_size_for()).
	uint32_t get_tiles_x() const { return tiles_x; }
	uint32_t get_tiles_y() const { return tiles_y; }
	uint32_t get_words_per_type() const { return max_elements / 32; }
	uint32_t get_max_elements() const { return max_elements; }
	uint32_t get_element_count(ElementType p_type) const;
	// Index of the first mask word of a cluster (shaders/cluster_data_inc.glsl: cluster_get_offset).
	uint32_t get_cluster_offset(ElementType p_type, uint32_t p_tile_x, uint32_t p_tile_y, uint32_t p_slice) const;

	ClusterBuilderRD() {}
	~ClusterBuilderRD();
};
