/**************************************************************************/
/*  shadow_casters_rd.cpp                                                 */
/**************************************************************************/
/* See shadow_casters_rd.h: Godot's casting rules per material.           */

#include "servers/rendering/renderer_rd/effects/shadow_casters_rd.h"

#include "core/error/error_macros.h"

static void _hash_bytes(uint64_t &r_hash, const void *p_data, size_t p_size) {
	const uint8_t *b = static_cast<const uint8_t *>(p_data);
	for (size_t i = 0; i < p_size; i++) {
		r_hash ^= b[i];
		r_hash *= 1099511628211ull; // FNV-1a.
	}
}

static RID _surface_material(const RenderSceneData::GeometryInstance &p_instance, const RendererRD::MeshStorage *p_mesh_storage, int p_surface) {
	return p_instance.material_override.is_valid() ? p_instance.material_override : p_mesh_storage->mesh_surface_get_material(p_instance.mesh, p_surface);
}

bool ShadowCastersRD::material_casts(const RendererRD::MaterialStorage *p_material_storage, RID p_material, bool &r_alpha_test) {
	const RS::MaterialTransparency transparency = p_material_storage->material_get_transparency(p_material);
	r_alpha_test = transparency == RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR;
	return transparency != RS::MATERIAL_TRANSPARENCY_ALPHA;
}

uint32_t ShadowCastersRD::collect(const RenderSceneData::GeometryInstance &p_instance, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage, RID p_material_shader, std::vector<Surface> &r_surfaces) {
	const bool casts = p_instance.cast_shadows != RS::SHADOW_CASTING_SETTING_OFF; // GeometryInstance3D::cast_shadow.
	const int count = casts && p_mesh_storage->owns_mesh(p_instance.mesh) ? p_mesh_storage->mesh_get_surface_count(p_instance.mesh) : 0;
	uint32_t added = 0;
	for (int s = 0; s < count; s++) {
		Surface surface;
		surface.gpu = p_mesh_storage->mesh_surface_get_gpu(p_instance.mesh, s);
		if (!surface.gpu) {
			continue;
		}
		const RID material = _surface_material(p_instance, p_mesh_storage, s);
		if (!material_casts(p_material_storage, material, surface.alpha_test)) {
			continue;
		}
		if (surface.alpha_test) {
			surface.material_set = p_material_storage->material_get_uniform_set(material, p_material_shader);
			ERR_CONTINUE_MSG(!surface.material_set.is_valid(), "Shadow casters: an alpha-scissor material's uniform set could not be created; the surface casts no shadow.");
		}
		r_surfaces.push_back(surface);
		added++;
	}
	return added;
}

void ShadowCastersRD::hash_materials(uint64_t &r_hash, const RenderSceneData::GeometryInstance &p_instance, const RendererRD::MeshStorage *p_mesh_storage, const RendererRD::MaterialStorage *p_material_storage) {
	_hash_bytes(r_hash, &p_instance.cast_shadows, sizeof(p_instance.cast_shadows)); // Off casts nothing.
	const int count = p_mesh_storage->owns_mesh(p_instance.mesh) ? p_mesh_storage->mesh_get_surface_count(p_instance.mesh) : 0;
	for (int s = 0; s < count; s++) {
		const RID material = _surface_material(p_instance, p_mesh_storage, s);
		const RS::MaterialTransparency transparency = p_material_storage->material_get_transparency(material);
		_hash_bytes(r_hash, &transparency, sizeof(transparency));
		if (transparency != RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR || !p_material_storage->owns_material(material)) {
			continue;
		}
		const RS::MaterialParams p = p_material_storage->material_get_params(material);
		const uint64_t texture = p.albedo_texture.get_id();
		const float values[6] = { p.alpha_scissor_threshold, p.albedo.a, p.uv1_scale.x, p.uv1_scale.y, p.uv1_offset.x, p.uv1_offset.y };
		const uint32_t modes[2] = { uint32_t(p.texture_filter), p.vertex_color_use_as_albedo ? 1u : 0u };
		_hash_bytes(r_hash, &texture, sizeof(texture));
		_hash_bytes(r_hash, values, sizeof(values));
		_hash_bytes(r_hash, modes, sizeof(modes));
	}
}

void ShadowCastersRD::FrameSurfaces::add(const RenderSceneData::GeometryInstance *p_instance, RendererRD::MeshStorage *p_mesh_storage, RendererRD::MaterialStorage *p_material_storage, RID p_material_shader) {
	if (ranges.count(p_instance)) {
		return;
	}
	const uint32_t begin = uint32_t(surfaces.size());
	collect(*p_instance, p_mesh_storage, p_material_storage, p_material_shader, surfaces);
	ranges[p_instance] = { begin, uint32_t(surfaces.size()) };
	for (uint32_t i = begin; i < surfaces.size(); i++) {
		any_alpha_test = any_alpha_test || surfaces[i].alpha_test;
	}
}

std::pair<uint32_t, uint32_t> ShadowCastersRD::FrameSurfaces::get_range(const RenderSceneData::GeometryInstance *p_instance) const {
	auto it = ranges.find(p_instance);
	return it != ranges.end() ? it->second : std::pair<uint32_t, uint32_t>(0, 0);
}

void ShadowCastersRD::bind_surface(RD::DrawListID p_list, const Surface &p_surface, RID p_pipeline, RID p_alpha_pipeline, bool &r_alpha_bound) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (p_surface.alpha_test != r_alpha_bound) {
		r_alpha_bound = p_surface.alpha_test;
		rd->draw_list_bind_render_pipeline(p_list, r_alpha_bound ? p_alpha_pipeline : p_pipeline);
	}
	if (p_surface.alpha_test) {
		rd->draw_list_bind_uniform_set(p_list, p_surface.material_set, 1);
	}
}

void ShadowCastersRD::draw_surface(RD::DrawListID p_list, const Surface &p_surface, const void *p_push, uint32_t p_push_size) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	rd->draw_list_bind_vertex_array(p_list, p_surface.gpu->vertex_array);
	rd->draw_list_set_push_constant(p_list, p_push, p_push_size);
	if (p_surface.gpu->index_array.is_valid()) {
		rd->draw_list_bind_index_array(p_list, p_surface.gpu->index_array);
		rd->draw_list_draw(p_list, true);
	} else {
		rd->draw_list_draw(p_list, false);
	}
}
