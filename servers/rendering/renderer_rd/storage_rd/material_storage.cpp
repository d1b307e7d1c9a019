/**************************************************************************/
/*  material_storage.cpp                                                  */
/**************************************************************************/

#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"

#include "core/error/error_macros.h"
#include "servers/rendering/storage/texture_mipmaps.h"

#include <cstring>

using namespace RendererRD;

static RID _create_solid_texture(RenderingDevice *p_rd, const Color &p_color) {
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	tf.width = 1;
	tf.height = 1;
	tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
	float texel[4] = { p_color.r, p_color.g, p_color.b, p_color.a };
	std::vector<uint8_t> bytes(sizeof(texel));
	memcpy(bytes.data(), texel, sizeof(texel));
	return p_rd->texture_create(tf, { bytes });
}

bool MaterialStorage::initialize_gpu() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !rd->is_initialized(), false, "MaterialStorage::initialize_gpu() needs an initialized RenderingDevice.");
	finalize_gpu();
	white_texture = _create_solid_texture(rd, Color(1, 1, 1, 1));
	normal_texture = _create_solid_texture(rd, Color(0.5f, 0.5f, 1.0f, 1.0f));
	for (int k = 0; k < SAMPLER_MAX; k++) {
		const bool nearest = k == SAMPLER_NEAREST || k == SAMPLER_NEAREST_MIPMAPS;
		const bool mipmaps = k == SAMPLER_NEAREST_MIPMAPS || k == SAMPLER_LINEAR_MIPMAPS;
		RD::SamplerState ss;
		ss.mag_filter = nearest ? RD::SAMPLER_FILTER_NEAREST : RD::SAMPLER_FILTER_LINEAR;
		ss.min_filter = ss.mag_filter;
		ss.mip_filter = RD::SAMPLER_FILTER_LINEAR;
		ss.max_lod = mipmaps ? 1e20f : 0.0f; // Without mipmaps: the base level only.
		ss.repeat_u = RD::SAMPLER_REPEAT_MODE_REPEAT;
		ss.repeat_v = RD::SAMPLER_REPEAT_MODE_REPEAT;
		samplers[k] = rd->sampler_create(ss);
	}
	default_material = material_create();
	// Textures get their GPU copies on first use (material_get_uniform_set).
	bool ok = white_texture.is_valid() && normal_texture.is_valid();
	for (int k = 0; k < SAMPLER_MAX; k++) {
		ok = ok && samplers[k].is_valid();
	}
	return ok;
}

void MaterialStorage::finalize_gpu() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	bool live = rd && rd->is_initialized();
	for (RID rid : material_owner.get_owned_list()) {
		Material *m = material_owner.get_or_null(rid);
		if (!m) {
			continue;
		}
		if (live && m->uniform_buffer.is_valid()) {
			rd->free(m->uniform_buffer); // Also frees its uniform set.
		}
		m->uniform_buffer = RID();
		m->uniform_set = RID();
		m->ubo_dirty = true;
	}
	for (RID rid : texture_owner.get_owned_list()) {
		Texture *t = texture_owner.get_or_null(rid);
		for (int u = 0; t && u < TEXTURE_USE_MAX; u++) {
			if (live && t->rd_texture[u].is_valid()) {
				rd->free(t->rd_texture[u]);
			}
			t->rd_texture[u] = RID();
		}
	}
	if (live) {
		if (white_texture.is_valid()) {
			rd->free(white_texture);
		}
		if (normal_texture.is_valid()) {
			rd->free(normal_texture);
		}
		for (int k = 0; k < SAMPLER_MAX; k++) {
			if (samplers[k].is_valid()) {
				rd->free(samplers[k]);
			}
		}
	}
	white_texture = RID();
	normal_texture = RID();
	for (int k = 0; k < SAMPLER_MAX; k++) {
		samplers[k] = RID();
	}
	if (default_material.is_valid()) {
		material_owner.free(default_material);
		default_material = RID();
	}
}

MaterialStorage::~MaterialStorage() {
	finalize_gpu();
}

MaterialStorage::MaterialUBO MaterialStorage::_make_ubo(const RS::MaterialParams &p_params, bool p_has_albedo, bool p_has_normal, bool p_has_roughness, bool p_has_metallic) {
	MaterialUBO ubo;
	memset(&ubo, 0, sizeof(ubo));
	// Unit conversion: node colours are sRGB.
	Color albedo = p_params.albedo.srgb_to_linear();
	ubo.albedo[0] = albedo.r;
	ubo.albedo[1] = albedo.g;
	ubo.albedo[2] = albedo.b;
	ubo.albedo[3] = albedo.a;
	Color emission = p_params.emission.srgb_to_linear();
	ubo.emission[0] = emission.r * p_params.emission_energy;
	ubo.emission[1] = emission.g * p_params.emission_energy;
	ubo.emission[2] = emission.b * p_params.emission_energy;
	ubo.roughness = p_params.roughness;
	ubo.metallic = p_params.metallic;
	ubo.specular = p_params.specular;
	ubo.normal_scale = p_params.normal_scale;
	ubo.flags = 0;
	if (p_has_albedo) {
		ubo.flags |= MATERIAL_FLAG_ALBEDO_TEXTURE;
	}
	if (p_has_normal) {
		ubo.flags |= MATERIAL_FLAG_NORMAL_MAP;
	}
	if (p_params.unshaded) {
		ubo.flags |= MATERIAL_FLAG_UNSHADED;
	}
	if (p_params.specular_mode == RS::MATERIAL_SPECULAR_DISABLED) {
		ubo.flags |= MATERIAL_FLAG_SPECULAR_DISABLED;
	}
	if (p_has_roughness) {
		ubo.flags |= MATERIAL_FLAG_ROUGHNESS_TEXTURE;
	}
	if (p_has_metallic) {
		ubo.flags |= MATERIAL_FLAG_METALLIC_TEXTURE;
	}
	if (p_params.vertex_color_use_as_albedo) {
		ubo.flags |= MATERIAL_FLAG_VERTEX_COLOR | (p_params.vertex_color_is_srgb ? uint32_t(MATERIAL_FLAG_VERTEX_COLOR_SRGB) : 0u);
	}
	if (p_params.transparency == RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR) {
		ubo.flags |= MATERIAL_FLAG_ALPHA_SCISSOR;
		ubo.alpha_scissor_threshold = p_params.alpha_scissor_threshold;
	}
	ubo.uv1[0] = p_params.uv1_scale.x;
	ubo.uv1[1] = p_params.uv1_scale.y;
	ubo.uv1[2] = p_params.uv1_offset.x;
	ubo.uv1[3] = p_params.uv1_offset.y;
	RS::material_texture_channel_weights(p_params.roughness_texture_channel, ubo.roughness_channel);
	RS::material_texture_channel_weights(p_params.metallic_texture_channel, ubo.metallic_channel);
	// Lambert wrap and toon are not implemented: they fall back to Lambert (the closest model).
	ubo.diffuse_mode = p_params.diffuse_mode == RS::MATERIAL_DIFFUSE_BURLEY ? 0u : 1u;
	return ubo;
}

MaterialStorage::SamplerKind MaterialStorage::_sampler_kind(RS::MaterialTextureFilter p_filter) {
	// The anisotropic filters sample like their isotropic mipmap filters (the sampler has no anisotropy);
	// BaseMaterial3D warns about them.
	switch (p_filter) {
		case RS::MATERIAL_TEXTURE_FILTER_NEAREST:
			return SAMPLER_NEAREST;
		case RS::MATERIAL_TEXTURE_FILTER_LINEAR:
			return SAMPLER_LINEAR;
		case RS::MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS:
		case RS::MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC:
			return SAMPLER_NEAREST_MIPMAPS;
		default:
			return SAMPLER_LINEAR_MIPMAPS;
	}
}

const std::vector<Image> &MaterialStorage::_mipmaps(const Texture &p_texture, TextureUse p_use) const {
	if (!p_texture.mipmaps_made[p_use]) {
		texture_mipmaps_generate(p_texture.image, p_use == TEXTURE_USE_COLOR, p_texture.mipmaps[p_use]);
		p_texture.mipmaps_made[p_use] = true;
	}
	return p_texture.mipmaps[p_use];
}

static std::vector<uint8_t> _image_bytes(const Image &p_image) {
	std::vector<uint8_t> bytes(p_image.get_data().size() * sizeof(float));
	memcpy(bytes.data(), p_image.ptr(), bytes.size());
	return bytes;
}

RID MaterialStorage::_rd_texture_for(RID p_texture, TextureUse p_use) {
	Texture *t = p_texture.is_valid() ? texture_owner.get_or_null(p_texture) : nullptr;
	if (!t) {
		return RID();
	}
	if (t->rd_texture[p_use].is_valid()) {
		return t->rd_texture[p_use];
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	const std::vector<Image> &levels = _mipmaps(*t, p_use);
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	tf.width = t->image.get_width();
	tf.height = t->image.get_height();
	tf.mipmaps = uint32_t(levels.size() + 1);
	tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
	RID texture = rd->texture_create(tf, { _image_bytes(t->image) });
	ERR_FAIL_COND_V_MSG(!texture.is_valid(), RID(), vformat("MaterialStorage: a %dx%d texture could not be created; the material reads its default.", t->image.get_width(), t->image.get_height()));
	// Levels 1..n through one-level views (texture_update writes the view's level).
	for (uint32_t level = 1; level < tf.mipmaps; level++) {
		RID view = rd->texture_create_shared_from_slice(texture, 0, level);
		const bool uploaded = view.is_valid() && rd->texture_update(view, 0, _image_bytes(levels[level - 1]));
		if (!uploaded) {
			rd->free(texture); // Also frees the view.
		} else {
			rd->free(view);
		}
		ERR_FAIL_COND_V_MSG(!uploaded, RID(), "MaterialStorage: a mipmap level could not be uploaded; the material reads its default texture.");
	}
	t->rd_texture[p_use] = texture;
	return texture;
}

RID MaterialStorage::material_get_uniform_set(RID p_material, RID p_shader) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!white_texture.is_valid(), RID(), "material_get_uniform_set() called before initialize_gpu().");
	Material *m = material_owner.get_or_null(p_material);
	if (!m) {
		m = material_owner.get_or_null(default_material);
		ERR_FAIL_NULL_V_MSG(m, RID(), "material_get_uniform_set: the default material is missing.");
	}
	const RID textures[4] = { _rd_texture_for(m->params.albedo_texture, TEXTURE_USE_COLOR), _rd_texture_for(m->params.normal_texture, TEXTURE_USE_DATA),
		_rd_texture_for(m->params.roughness_texture, TEXTURE_USE_DATA), _rd_texture_for(m->params.metallic_texture, TEXTURE_USE_DATA) };
	const SamplerKind sampler_kind = _sampler_kind(m->params.texture_filter);
	bool same_textures = sampler_kind == m->set_sampler;
	for (int i = 0; i < 4; i++) {
		same_textures = same_textures && textures[i] == m->set_textures[i];
	}
	if (!m->uniform_buffer.is_valid()) {
		m->uniform_buffer = rd->uniform_buffer_create(sizeof(MaterialUBO));
		m->ubo_dirty = true;
	}
	if (m->ubo_dirty || !same_textures) {
		MaterialUBO ubo = _make_ubo(m->params, textures[0].is_valid(), textures[1].is_valid(), textures[2].is_valid(), textures[3].is_valid());
		rd->buffer_update(m->uniform_buffer, 0, sizeof(ubo), &ubo);
		m->ubo_dirty = false;
	}
	bool set_ok = m->uniform_set.is_valid() && rd->uniform_set_is_valid(m->uniform_set) && m->uniform_set_shader == p_shader && same_textures;
	if (!set_ok) {
		if (m->uniform_set.is_valid() && rd->uniform_set_is_valid(m->uniform_set)) {
			rd->free(m->uniform_set);
		}
		std::vector<RD::Uniform> uniforms;
		uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, m->uniform_buffer));
		uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 1, textures[0].is_valid() ? textures[0] : white_texture));
		uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 2, textures[1].is_valid() ? textures[1] : normal_texture));
		uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 3, textures[2].is_valid() ? textures[2] : white_texture));
		uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_TEXTURE, 4, textures[3].is_valid() ? textures[3] : white_texture));
		uniforms.push_back(RD::Uniform(RD::UNIFORM_TYPE_SAMPLER, 5, samplers[sampler_kind]));
		m->uniform_set = rd->uniform_set_create(uniforms, p_shader, 1);
		m->uniform_set_shader = p_shader;
		for (int i = 0; i < 4; i++) {
			m->set_textures[i] = textures[i];
		}
		m->set_sampler = sampler_kind;
	}
	return m->uniform_set;
}

bool MaterialStorage::material_is_cull_back(RID p_material) const {
	const Material *m = material_owner.get_or_null(p_material);
	if (!m) {
		m = material_owner.get_or_null(default_material);
	}
	return m ? m->params.cull_back : true;
}

RS::MaterialTransparency MaterialStorage::material_get_transparency(RID p_material) const {
	const Material *m = material_owner.get_or_null(p_material);
	if (!m) {
		m = material_owner.get_or_null(default_material);
	}
	return m ? m->params.transparency : RS::MATERIAL_TRANSPARENCY_DISABLED;
}

RID MaterialStorage::material_create() {
	return material_owner.make_rid();
}

bool MaterialStorage::material_free(RID p_rid) {
	Material *m = material_owner.get_or_null(p_rid);
	if (!m) {
		return false;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized() && m->uniform_buffer.is_valid()) {
		rd->free(m->uniform_buffer); // Also frees the uniform set.
	}
	material_owner.free(p_rid);
	return true;
}

void MaterialStorage::material_set_params(RID p_material, const RS::MaterialParams &p_params) {
	Material *m = material_owner.get_or_null(p_material);
	ERR_FAIL_NULL_MSG(m, "material_set_params: invalid material RID.");
	if (!validate_params(p_params)) {
		return;
	}
	m->params = p_params;
	m->ubo_dirty = true;
}

RS::MaterialParams MaterialStorage::material_get_params(RID p_material) const {
	const Material *m = material_owner.get_or_null(p_material);
	ERR_FAIL_NULL_V_MSG(m, RS::MaterialParams(), "material_get_params: invalid material RID.");
	return m->params;
}

RID MaterialStorage::texture_2d_create(const Image &p_image) {
	ERR_FAIL_COND_V_MSG(p_image.is_empty(), RID(), "texture_2d_create: the image is empty.");
	Texture t;
	t.image = p_image;
	return texture_owner.make_rid(t);
}

bool MaterialStorage::texture_free(RID p_rid) {
	Texture *t = texture_owner.get_or_null(p_rid);
	if (!t) {
		return false;
	}
	RenderingDevice *rd = RenderingDevice::get_singleton();
	for (int u = 0; u < TEXTURE_USE_MAX; u++) {
		if (rd && rd->is_initialized() && t->rd_texture[u].is_valid()) {
			rd->free(t->rd_texture[u]); // Uniform sets using it are freed too; materials rebuild theirs.
		}
	}
	texture_owner.free(p_rid);
	return true;
}

int MaterialStorage::texture_get_width(RID p_texture) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, 0, "texture_get_width: invalid texture RID.");
	return t->image.get_width();
}

int MaterialStorage::texture_get_height(RID p_texture) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, 0, "texture_get_height: invalid texture RID.");
	return t->image.get_height();
}

const Image *MaterialStorage::texture_get_image(RID p_texture) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, nullptr, "texture_get_image: invalid texture RID.");
	return &t->image;
}

const std::vector<Image> *MaterialStorage::texture_get_mipmaps(RID p_texture, bool p_srgb) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, nullptr, "texture_get_mipmaps: invalid texture RID.");
	return &_mipmaps(*t, p_srgb ? TEXTURE_USE_COLOR : TEXTURE_USE_DATA);
}
