/**************************************************************************/
/*  cluster_builder_rd.cpp                                                */
/**************************************************************************/

#include "servers/rendering/renderer_rd/cluster_builder_rd.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>
#include <cstring>

bool ClusterBuilderRD::initialize(uint32_t p_max_elements) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL_V_MSG(rd, false, "ClusterBuilderRD needs an initialized RenderingDevice.");
	ERR_FAIL_COND_V_MSG(p_max_elements == 0, false, "ClusterBuilderRD: the maximum element count per type must be at least 1.");
	finalize();

	// One variant per element type (CLUSTER_TYPE): each compiles only its own bound test.
	std::vector<String> variants;
	for (uint32_t t = 0; t < ELEMENT_TYPE_MAX; t++) {
		variants.push_back(vformat("#define CLUSTER_TYPE %u\n", t));
	}
	if (!shader.initialize("cluster_build.glsl", variants)) {
		ERR_FAIL_V_MSG(false, "ClusterBuilderRD: cannot load shaders/cluster_build.glsl.");
	}
	for (uint32_t t = 0; t < ELEMENT_TYPE_MAX; t++) {
		RID shader_rid = shader.version_get_shader(int(t));
		ERR_FAIL_COND_V_MSG(!shader_rid.is_valid(), false, "ClusterBuilderRD: cluster_build.glsl failed to compile: " + shader.get_last_error());
		pipelines[t] = rd->compute_pipeline_create(shader_rid);
		ERR_FAIL_COND_V_MSG(!pipelines[t].is_valid(), false, "ClusterBuilderRD: cannot create the cluster build pipeline.");
	}

	max_elements = (p_max_elements + 31) / 32 * 32;
	elements.assign(ELEMENT_TYPE_MAX * max_elements, ElementData());
	element_buffer = rd->storage_buffer_create(uint32_t(elements.size() * sizeof(ElementData)), elements.data());
	rd->set_resource_name(element_buffer, "ClusterBuilderRD elements");
	for (uint32_t i = 0; i < ELEMENT_TYPE_MAX; i++) {
		element_count[i] = 0;
	}
	return true;
}

void ClusterBuilderRD::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd) {
		// Freeing a buffer frees the uniform sets that use it.
		if (cluster_buffer.is_valid()) {
			rd->free(cluster_buffer);
		}
		if (element_buffer.is_valid()) {
			rd->free(element_buffer);
		}
		for (RID &p : pipelines) {
			if (p.is_valid()) {
				rd->free(p);
			}
		}
	}
	cluster_buffer = RID();
	element_buffer = RID();
	uniform_set = RID();
	for (RID &p : pipelines) {
		p = RID();
	}
	shader.clear();
	width = height = tiles_x = tiles_y = 0;
	max_elements = 0;
	elements.clear();
}

ClusterBuilderRD::~ClusterBuilderRD() {
	finalize();
}

uint32_t ClusterBuilderRD::tile_size_for(uint32_t p_width, uint32_t p_height) {
	uint32_t size = MIN_TILE_SIZE;
	while (size < 128 && uint64_t((p_width + size - 1) / size) * ((p_height + size - 1) / size) > MAX_TILES) {
		size *= 2;
	}
	return size;
}

bool ClusterBuilderRD::setup(uint32_t p_width, uint32_t p_height) {
	ERR_FAIL_COND_V_MSG(!is_initialized(), false, "ClusterBuilderRD::setup() called before initialize().");
	ERR_FAIL_COND_V_MSG(p_width == 0 || p_height == 0, false, vformat("ClusterBuilderRD: render size must be positive, got %ux%u.", p_width, p_height));
	if (p_width == width && p_height == height && cluster_buffer.is_valid()) {
		return true;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (cluster_buffer.is_valid()) {
		rd->free(cluster_buffer);
		cluster_buffer = RID();
		uniform_set = RID();
	}
	width = p_width;
	height = p_height;
	tile_size = tile_size_for(width, height);
	tiles_x = (width + tile_size - 1) / tile_size;
	tiles_y = (height + tile_size - 1) / tile_size;
	// The first bake writes every word of the new buffer (written_words), later ones only the live ones.
	for (uint32_t t = 0; t < ELEMENT_TYPE_MAX; t++) {
		written_words[t] = get_words_per_type();
	}
	uint64_t words = uint64_t(ELEMENT_TYPE_MAX) * tiles_x * tiles_y * Z_SLICES * get_words_per_type();
	ERR_FAIL_COND_V_MSG(words * 4 > 0x7FFFFFFF, false, "ClusterBuilderRD: the cluster buffer would exceed 2 GiB; lower the element count or the resolution.");
	cluster_buffer = rd->storage_buffer_create(uint32_t(words * 4));
	rd->set_resource_name(cluster_buffer, "ClusterBuilderRD clusters");

	std::vector<RD::Uniform> uniforms;
	uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, element_buffer));
	uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, cluster_buffer));
	uniform_set = rd->uniform_set_create(uniforms, shader.version_get_shader(0), 0);
	ERR_FAIL_COND_V_MSG(!uniform_set.is_valid(), false, "ClusterBuilderRD: cannot create the build uniform set.");
	return true;
}

void ClusterBuilderRD::begin(const Projection &p_clip_from_view, float p_z_far) {
	clip_from_view = p_clip_from_view;
	z_far = p_z_far > 0.0f && std::isfinite(p_z_far) ? p_z_far : 1.0f;
	element_depth_max = 0.0f;
	for (uint32_t i = 0; i < ELEMENT_TYPE_MAX; i++) {
		element_count[i] = 0;
	}
}

bool ClusterBuilderRD::add_light(ElementType p_type, const Vector3 &p_position, float p_radius, const Vector3 &p_direction, float p_spot_half_angle) {
	ERR_FAIL_INDEX_V_MSG((int)p_type, (int)ELEMENT_TYPE_MAX, false, "ClusterBuilderRD::add_light: type is not an ElementType value.");
	ERR_FAIL_COND_V_MSG(p_type == ELEMENT_TYPE_AREA_LIGHT, false, "ClusterBuilderRD::add_light: area lights need their rectangle; use add_area_light().");
	if (element_count[p_type] >= max_elements) {
		return false;
	}
	ElementData &e = elements[p_type * max_elements + element_count[p_type]];
	e = ElementData();
	e.position[0] = p_position.x;
	e.position[1] = p_position.y;
	e.position[2] = p_position.z;
	e.radius = std::fmax(p_radius, 0.0f);
	Vector3 dir = p_direction.normalized();
	e.direction[0] = dir.x;
	e.direction[1] = dir.y;
	e.direction[2] = dir.z;
	float half_angle = std::fmin(std::fmax(p_spot_half_angle, 0.0f), float(Math::PI));
	e.cone_cos = std::cos(half_angle);
	e.cone_sin = std::sin(half_angle);
	element_depth_max = std::fmax(element_depth_max, -p_position.z + e.radius);
	element_count[p_type]++;
	return true;
}

bool ClusterBuilderRD::add_area_light(const Vector3 &p_center, const Vector3 &p_half_axis_x, const Vector3 &p_half_axis_y, const Vector3 &p_normal, float p_range) {
	if (element_count[ELEMENT_TYPE_AREA_LIGHT] >= max_elements) {
		return false;
	}
	float r = std::fmax(p_range, 0.0f);
	Vector3 n = p_normal.normalized();
	Vector3 ax = p_half_axis_x - n * n.dot(p_half_axis_x); // Orthogonalised against the normal.
	float half_a = p_half_axis_x.length();
	float half_b = p_half_axis_y.length();
	if (ax.length_squared() < 1e-20f) {
		// Zero width: any axis perpendicular to n will do.
		ax = std::fabs(n.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
		ax = ax - n * n.dot(ax);
	}
	ax = ax.normalized();
	ElementData &e = elements[ELEMENT_TYPE_AREA_LIGHT * max_elements + element_count[ELEMENT_TYPE_AREA_LIGHT]];
	e = ElementData();
	// Box centre: r / 2 in front of the rectangle.
	Vector3 c = p_center + n * (r * 0.5f);
	Vector3 ext(half_a + r, half_b + r, r * 0.5f);
	for (int i = 0; i < 3; i++) {
		e.position[i] = c[i];
		e.direction[i] = n[i];
		e.axis_x[i] = ax[i];
		e.extents[i] = ext[i];
	}
	e.radius = r + std::sqrt(half_a * half_a + half_b * half_b); // Thesis eq. 5.1.
	e.cone_cos = 1.0f;
	e.cone_sin = 0.0f;
	e.sphere_offset = ext.z;
	// The eq. 5.1 sphere is centred on the rectangle (the box centre minus direction * extents.z).
	element_depth_max = std::fmax(element_depth_max, -p_center.z + e.radius);
	element_count[ELEMENT_TYPE_AREA_LIGHT]++;
	return true;
}

bool ClusterBuilderRD::add_area_light_box(const Vector3 &p_center, const Vector3 &p_axis_x, const Vector3 &p_axis_z, const Vector3 &p_extents, float p_radius) {
	if (element_count[ELEMENT_TYPE_AREA_LIGHT] >= max_elements) {
		return false;
	}
	ElementData &e = elements[ELEMENT_TYPE_AREA_LIGHT * max_elements + element_count[ELEMENT_TYPE_AREA_LIGHT]];
	e = ElementData();
	for (int i = 0; i < 3; i++) {
		e.position[i] = p_center[i];
		e.direction[i] = p_axis_z[i];
		e.axis_x[i] = p_axis_x[i];
		e.extents[i] = std::fmax(p_extents[i], 0.0f);
	}
	e.radius = std::fmax(p_radius, 0.0f);
	e.cone_cos = 1.0f;
	e.cone_sin = 0.0f;
	e.sphere_offset = 0.0f; // The box is centred on the light.
	element_depth_max = std::fmax(element_depth_max, -p_center.z + e.radius);
	element_count[ELEMENT_TYPE_AREA_LIGHT]++;
	return true;
}

float ClusterBuilderRD::get_slice_depth() const {
	uint32_t elements_total = 0;
	for (uint32_t t = 0; t < ELEMENT_TYPE_MAX; t++) {
		elements_total += element_count[t];
	}
	if (elements_total == 0 || !std::isfinite(element_depth_max)) {
		return z_far;
	}
	return std::fmin(z_far, std::fmax(element_depth_max * 1.001f + 1e-4f, 1e-3f));
}

void ClusterBuilderRD::bake_cluster(uint32_t p_type_count) {
	ERR_FAIL_COND_MSG(!cluster_buffer.is_valid(), "ClusterBuilderRD::bake_cluster() called before setup().");
	RenderingDevice *rd = RenderingDevice::get_singleton();

	// Upload only the used part of each type's range.
	for (uint32_t t = 0; t < ELEMENT_TYPE_MAX; t++) {
		if (element_count[t] > 0) {
			rd->buffer_update(element_buffer, t * max_elements * sizeof(ElementData), element_count[t] * sizeof(ElementData), &elements[t * max_elements]);
		}
	}

	BuildPushConstant pc;
	memset(&pc, 0, sizeof(pc));
	clip_from_view.inverse().to_floats(pc.view_from_clip);
	pc.screen_size[0] = float(width);
	pc.screen_size[1] = float(height);
	pc.z_far = get_slice_depth();
	pc.words_per_type = get_words_per_type();
	pc.tiles_x = tiles_x;
	pc.tiles_y = tiles_y;
	pc.tile_size = tile_size;
	for (uint32_t t = 0; t < ELEMENT_TYPE_MAX; t++) {
		pc.element_count[t] = element_count[t];
	}

	// One dispatch per type over the words that hold its live elements, plus the words that were live in
	// the previous bake (rewritten as 0): words past both are 0 already, so the buffer stays exact while a
	// type without elements dispatches nothing. The scene shader reads only the live words.
	RD::ComputeListID list = rd->compute_list_begin();
	for (uint32_t t = 0; t < std::min(p_type_count, uint32_t(ELEMENT_TYPE_MAX)); t++) {
		const uint32_t live = (element_count[t] + 31) / 32;
		const uint32_t dispatch_words = std::max(live, written_words[t]);
		written_words[t] = live;
		if (dispatch_words == 0) {
			continue;
		}
		rd->compute_list_bind_compute_pipeline(list, pipelines[t]);
		rd->compute_list_bind_uniform_set(list, uniform_set, 0);
		rd->compute_list_set_push_constant(list, &pc, sizeof(pc));
		rd->compute_list_dispatch_threads(list, tiles_x * tiles_y * Z_SLICES, dispatch_words, 1);
	}
	rd->compute_list_end();
}

uint32_t ClusterBuilderRD::get_element_count(ElementType p_type) const {
	ERR_FAIL_INDEX_V_MSG((int)p_type, (int)ELEMENT_TYPE_MAX, 0, "ClusterBuilderRD::get_element_count: type is not an ElementType value.");
	return element_count[p_type];
}

uint32_t ClusterBuilderRD::get_cluster_offset(ElementType p_type, uint32_t p_tile_x, uint32_t p_tile_y, uint32_t p_slice) const {
	uint32_t tile_index = p_tile_y * tiles_x + p_tile_x;
	return ((uint32_t(p_type) * tiles_x * tiles_y + tile_index) * Z_SLICES + p_slice) * get_words_per_type();
}
