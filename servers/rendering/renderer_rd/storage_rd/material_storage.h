/**************************************************************************/
/*  material_storage.h                                                    */
/**************************************************************************/
/* godot-area: materials and textures on the RenderingDevice (Godot's     */
/* RendererRD::MaterialStorage + TextureStorage, reduced to the built-in  */
/* StandardMaterial3D subset). A material owns a uniform buffer           */
/* (MaterialUBO) and, created on first use by the renderer, the uniform   */
/* set 1 of the scene shader. Textures are RGBA32F copies of the Image    */
/* with their full mip chain (texture_mipmaps.h), uploaded on first use:  */
/* one copy for colour (albedo, mips averaged in linear space) and one    */
/* for data (normal, roughness, metallic), each only when used so.        */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/rendering_device.h"
#include "servers/rendering/storage/material_storage.h"

namespace RendererRD {

class MaterialStorage : public RendererMaterialStorage {
public:
	// Must match MATERIAL_FLAG_* (shaders/material_block_inc.glsl).
	enum MaterialFlags {
		MATERIAL_FLAG_ALBEDO_TEXTURE = 1,
		MATERIAL_FLAG_NORMAL_MAP = 2,
		MATERIAL_FLAG_UNSHADED = 4,
		MATERIAL_FLAG_SPECULAR_DISABLED = 8,
		MATERIAL_FLAG_ROUGHNESS_TEXTURE = 16,
		MATERIAL_FLAG_METALLIC_TEXTURE = 32,
		MATERIAL_FLAG_ALPHA_SCISSOR = 64,
		MATERIAL_FLAG_VERTEX_COLOR = 128,
		MATERIAL_FLAG_VERTEX_COLOR_SRGB = 256,
	};

	// Mirror of MaterialBlock (set 1, binding 0, std140) in
	// shaders/material_block_inc.glsl. 112 bytes.
	struct MaterialUBO {
		float albedo[4]; // Linear rgb, alpha.
		float emission[4]; // Linear rgb * emission_energy, a unused.
		float roughness;
		float metallic;
		float specular;
		float normal_scale;
		uint32_t flags; // MaterialFlags.
		uint32_t diffuse_mode; // BRDF_DIFFUSE_* (brdf_inc.glsl): 0 Burley, 1 Lambert.
		float alpha_scissor_threshold; // MATERIAL_FLAG_ALPHA_SCISSOR only.
		uint32_t pad1;
		float uv1[4]; // uv1_scale.xy, uv1_offset.xy.
		float roughness_channel[4]; // Weights of the roughness texture's channels (roughness_texture_channel).
		float metallic_channel[4];
	};
	static_assert(sizeof(MaterialUBO) == 112, "MaterialUBO must match scene_forward_clustered_inc.glsl.");
	static_assert(sizeof(MaterialUBO) % 16 == 0, "MaterialUBO must stay a multiple of 16 bytes.");

private:
	struct Material {
		RS::MaterialParams params;
		RID uniform_buffer;
		RID uniform_set;
		RID uniform_set_shader; // Shader the set was made for.
		// RD textures bound in uniform_set (to notice freed textures): albedo, normal, roughness, metallic.
		RID set_textures[4];
		int set_sampler = -1; // The SamplerKind bound in uniform_set.
		bool ubo_dirty = true;
	};
	// A texture's two uses: sRGB-encoded colour (albedo) and linear data (normal, roughness, metallic).
	enum TextureUse {
		TEXTURE_USE_DATA,
		TEXTURE_USE_COLOR,
		TEXTURE_USE_MAX
	};
	struct Texture {
		Image image;
		RID rd_texture[TEXTURE_USE_MAX]; // Made on first use (material_get_uniform_set), every mip level.
		mutable std::vector<Image> mipmaps[TEXTURE_USE_MAX]; // Levels 1..n, made on first use.
		mutable bool mipmaps_made[TEXTURE_USE_MAX] = { false, false };
	};
	// The material sampler per texture_filter (Godot's: the *_WITH_MIPMAPS filters blend two levels,
	// rendering/textures/default_filters/use_nearest_mipmap_filter = false); all repeat.
	enum SamplerKind {
		SAMPLER_NEAREST,
		SAMPLER_LINEAR,
		SAMPLER_NEAREST_MIPMAPS,
		SAMPLER_LINEAR_MIPMAPS,
		SAMPLER_MAX
	};

	mutable RID_Owner<Material, true> material_owner{ "RendererRD::Material" };
	mutable RID_Owner<Texture, true> texture_owner{ "RendererRD::Texture" };

	RID default_material;
	RID white_texture; // RD texture (1, 1, 1, 1).
	RID normal_texture; // RD texture (0.5, 0.5, 1, 1): flat normal.
	RID samplers[SAMPLER_MAX];

	static MaterialUBO _make_ubo(const RS::MaterialParams &p_params, bool p_has_albedo, bool p_has_normal, bool p_has_roughness = false, bool p_has_metallic = false);
	static SamplerKind _sampler_kind(RS::MaterialTextureFilter p_filter);
	const std::vector<Image> &_mipmaps(const Texture &p_texture, TextureUse p_use) const;
	// The RD texture of p_texture for p_use (uploaded with its mip chain on first use), or RID().
	RID _rd_texture_for(RID p_texture, TextureUse p_use);

public:
	// Creates default textures, the sampler and the default material (needs a RenderingDevice).
	bool initialize_gpu();
	// Frees every GPU object (before RenderingDevice::finalize()).
	void finalize_gpu();

	// The uniform set 1 of p_shader for a material (an invalid or RID() material uses the default one).
	// Created on first use and when bound textures changed.
	RID material_get_uniform_set(RID p_material, RID p_shader);
	// True when the material draws with back faces culled (MaterialParams::cull_back).
	bool material_is_cull_back(RID p_material) const;
	// The material's transparency (MaterialParams::transparency; the default material's for an invalid RID).
	RS::MaterialTransparency material_get_transparency(RID p_material) const;
	RID get_default_material() const { return default_material; }
	RID get_sampler() const { return samplers[SAMPLER_LINEAR]; }
	// Converts the parameters as the shader reads them (tests).
	static MaterialUBO make_material_ubo(const RS::MaterialParams &p_params) {
		return _make_ubo(p_params, p_params.albedo_texture.is_valid(), p_params.normal_texture.is_valid(), p_params.roughness_texture.is_valid(), p_params.metallic_texture.is_valid());
	}

	RID material_create() override;
	bool material_free(RID p_rid) override;
	bool owns_material(RID p_rid) const override { return material_owner.owns(p_rid); }
	void material_set_params(RID p_material, const RS::MaterialParams &p_params) override;
	RS::MaterialParams material_get_params(RID p_material) const override;

	RID texture_2d_create(const Image &p_image) override;
	bool texture_free(RID p_rid) override;
	bool owns_texture(RID p_rid) const override { return texture_owner.owns(p_rid); }
	int texture_get_width(RID p_texture) const override;
	int texture_get_height(RID p_texture) const override;
	const Image *texture_get_image(RID p_texture) const override;
	const std::vector<Image> *texture_get_mipmaps(RID p_texture, bool p_srgb) const override;

	MaterialStorage() {}
	~MaterialStorage();
};

} // namespace RendererRD
