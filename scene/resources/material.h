/**************************************************************************/
/*  material.h                                                            */
/**************************************************************************/
/* godot-area: Material (abstract; owns one RS material RID) and the      */
/* BaseMaterial3D / StandardMaterial3D subset the renderer supports.      */
/* Property names, groups, enum orders and defaults follow Godot 4.7.     */
/* Every setter validates, stores locally, then pushes the whole          */
/* RS::MaterialParams block (colours stay sRGB; the renderer linearizes). */

#pragma once

#include "core/io/resource.h"
#include "scene/resources/texture.h"
#include "servers/rendering_server.h"

class Material : public Resource {
	GDCLASS(Material, Resource);

	RID material;

protected:
	static void _bind_methods();

public:
	RID get_rid() const override { return material; }

	Material();
	~Material() override;
};

class BaseMaterial3D : public Material {
	GDCLASS(BaseMaterial3D, Material);

public:
	// Enum values equal Godot's (they are saved in scene files).
	enum ShadingMode {
		SHADING_MODE_UNSHADED,
		SHADING_MODE_PER_PIXEL,
		SHADING_MODE_PER_VERTEX,
		SHADING_MODE_MAX
	};
	enum DiffuseMode {
		DIFFUSE_BURLEY = RS::MATERIAL_DIFFUSE_BURLEY,
		DIFFUSE_LAMBERT = RS::MATERIAL_DIFFUSE_LAMBERT,
		DIFFUSE_LAMBERT_WRAP = RS::MATERIAL_DIFFUSE_LAMBERT_WRAP,
		DIFFUSE_TOON = RS::MATERIAL_DIFFUSE_TOON,
		DIFFUSE_MAX
	};
	enum SpecularMode {
		SPECULAR_SCHLICK_GGX = RS::MATERIAL_SPECULAR_SCHLICK_GGX,
		SPECULAR_TOON = RS::MATERIAL_SPECULAR_TOON,
		SPECULAR_DISABLED = RS::MATERIAL_SPECULAR_DISABLED,
		SPECULAR_MAX
	};
	// Godot's values. ALPHA_HASH is drawn as ALPHA_SCISSOR (no dithered hash) and ALPHA_DEPTH_PRE_PASS as
	// ALPHA (no opaque pre-pass part), each with a warning.
	enum Transparency {
		TRANSPARENCY_DISABLED,
		TRANSPARENCY_ALPHA,
		TRANSPARENCY_ALPHA_SCISSOR,
		TRANSPARENCY_ALPHA_HASH,
		TRANSPARENCY_ALPHA_DEPTH_PRE_PASS,
		TRANSPARENCY_MAX
	};
	enum CullMode {
		CULL_BACK,
		CULL_FRONT, // Not supported by the renderer: drawn like CULL_DISABLED (with a warning).
		CULL_DISABLED,
		CULL_MAX
	};
	enum TextureChannel {
		TEXTURE_CHANNEL_RED = RS::MATERIAL_TEXTURE_CHANNEL_RED,
		TEXTURE_CHANNEL_GREEN = RS::MATERIAL_TEXTURE_CHANNEL_GREEN,
		TEXTURE_CHANNEL_BLUE = RS::MATERIAL_TEXTURE_CHANNEL_BLUE,
		TEXTURE_CHANNEL_ALPHA = RS::MATERIAL_TEXTURE_CHANNEL_ALPHA,
		TEXTURE_CHANNEL_GRAYSCALE = RS::MATERIAL_TEXTURE_CHANNEL_GRAYSCALE,
		TEXTURE_CHANNEL_MAX
	};
	// The *_WITH_MIPMAPS filters read the texture's mip chain; the anisotropic ones sample without
	// anisotropy (warned once; RS::MaterialTextureFilter).
	enum TextureFilter {
		TEXTURE_FILTER_NEAREST = RS::MATERIAL_TEXTURE_FILTER_NEAREST,
		TEXTURE_FILTER_LINEAR = RS::MATERIAL_TEXTURE_FILTER_LINEAR,
		TEXTURE_FILTER_NEAREST_WITH_MIPMAPS = RS::MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS,
		TEXTURE_FILTER_LINEAR_WITH_MIPMAPS = RS::MATERIAL_TEXTURE_FILTER_LINEAR_WITH_MIPMAPS,
		TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC = RS::MATERIAL_TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC,
		TEXTURE_FILTER_LINEAR_WITH_MIPMAPS_ANISOTROPIC = RS::MATERIAL_TEXTURE_FILTER_LINEAR_WITH_MIPMAPS_ANISOTROPIC,
		TEXTURE_FILTER_MAX
	};

private:
	ShadingMode shading_mode = SHADING_MODE_PER_PIXEL;
	DiffuseMode diffuse_mode = DIFFUSE_BURLEY;
	SpecularMode specular_mode = SPECULAR_SCHLICK_GGX;
	CullMode cull_mode = CULL_BACK;
	Transparency transparency = TRANSPARENCY_DISABLED;
	float alpha_scissor_threshold = 0.5f;
	bool vertex_color_use_as_albedo = false;
	bool vertex_color_is_srgb = false;
	Color albedo = Color(1, 1, 1, 1);
	Ref<Texture2D> albedo_texture;
	float metallic = 0.0f;
	Ref<Texture2D> metallic_texture;
	TextureChannel metallic_texture_channel = TEXTURE_CHANNEL_RED;
	float specular = 0.5f;
	float roughness = 1.0f;
	Ref<Texture2D> roughness_texture;
	TextureChannel roughness_texture_channel = TEXTURE_CHANNEL_RED;
	Ref<Texture2D> orm_texture; // ORMMaterial3D: ambient occlusion (r, not used), roughness (g), metallic (b).
	bool orm = false;
	Vector3 uv1_scale = Vector3(1, 1, 1);
	Vector3 uv1_offset;
	TextureFilter texture_filter = TEXTURE_FILTER_LINEAR_WITH_MIPMAPS;
	bool emission_enabled = false;
	Color emission = Color(0, 0, 0, 1);
	float emission_energy = 1.0f;
	bool normal_enabled = false;
	float normal_scale = 1.0f;
	Ref<Texture2D> normal_texture;

	void _update_params();

protected:
	static void _bind_methods();
	void _validate_property(PropertyInfo &p_property) const;

public:
	void set_shading_mode(ShadingMode p_mode);
	ShadingMode get_shading_mode() const { return shading_mode; }
	void set_diffuse_mode(DiffuseMode p_mode);
	DiffuseMode get_diffuse_mode() const { return diffuse_mode; }
	void set_specular_mode(SpecularMode p_mode);
	SpecularMode get_specular_mode() const { return specular_mode; }
	void set_cull_mode(CullMode p_mode);
	CullMode get_cull_mode() const { return cull_mode; }
	void set_transparency(Transparency p_transparency);
	Transparency get_transparency() const { return transparency; }
	// 0..1: ALPHA_SCISSOR (and ALPHA_HASH) keep the pixels whose alpha is at least this.
	void set_alpha_scissor_threshold(float p_threshold);
	float get_alpha_scissor_threshold() const { return alpha_scissor_threshold; }
	// Godot's "Vertex Color" group: the mesh's vertex colours multiply the albedo (and its alpha).
	void set_flag_vertex_color_use_as_albedo(bool p_enabled);
	bool get_flag_vertex_color_use_as_albedo() const { return vertex_color_use_as_albedo; }
	void set_flag_vertex_color_is_srgb(bool p_enabled);
	bool get_flag_vertex_color_is_srgb() const { return vertex_color_is_srgb; }

	void set_albedo(const Color &p_albedo);
	Color get_albedo() const { return albedo; }
	void set_albedo_texture(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_albedo_texture() const { return albedo_texture; }

	// 0..1; anything else (or NaN) is rejected with a message.
	void set_metallic(float p_metallic);
	float get_metallic() const { return metallic; }
	void set_specular(float p_specular);
	float get_specular() const { return specular; }
	void set_roughness(float p_roughness);
	float get_roughness() const { return roughness; }
	void set_metallic_texture(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_metallic_texture() const { return metallic_texture; }
	void set_metallic_texture_channel(TextureChannel p_channel);
	TextureChannel get_metallic_texture_channel() const { return metallic_texture_channel; }
	void set_roughness_texture(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_roughness_texture() const { return roughness_texture; }
	void set_roughness_texture_channel(TextureChannel p_channel);
	TextureChannel get_roughness_texture_channel() const { return roughness_texture_channel; }
	// ORMMaterial3D only (saved and loaded on every BaseMaterial3D, shown on ORM materials, as Godot).
	void set_orm_texture(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_orm_texture() const { return orm_texture; }

	// UV = UV * uv1_scale.xy + uv1_offset.xy (finite values; z is for triplanar mapping, not supported).
	void set_uv1_scale(const Vector3 &p_scale);
	Vector3 get_uv1_scale() const { return uv1_scale; }
	void set_uv1_offset(const Vector3 &p_offset);
	Vector3 get_uv1_offset() const { return uv1_offset; }
	void set_texture_filter(TextureFilter p_filter);
	TextureFilter get_texture_filter() const { return texture_filter; }

	void set_emission_enabled(bool p_enabled);
	bool is_emission_enabled() const { return emission_enabled; }
	void set_emission(const Color &p_emission);
	Color get_emission() const { return emission; }
	void set_emission_energy_multiplier(float p_energy);
	float get_emission_energy_multiplier() const { return emission_energy; }

	void set_normal_enabled(bool p_enabled);
	bool is_normal_enabled() const { return normal_enabled; }
	void set_normal_scale(float p_scale);
	float get_normal_scale() const { return normal_scale; }
	void set_normal_texture(const Ref<Texture2D> &p_texture);
	Ref<Texture2D> get_normal_texture() const { return normal_texture; }

	// The parameter block as sent to the server.
	RS::MaterialParams get_params() const;

	explicit BaseMaterial3D(bool p_orm = false);
};

// The concrete material scene files name ("StandardMaterial3D").
class StandardMaterial3D : public BaseMaterial3D {
	GDCLASS(StandardMaterial3D, BaseMaterial3D);

public:
	StandardMaterial3D() {}
};

// Godot's ORMMaterial3D: one texture holds occlusion, roughness and metallic (r, g, b).
class ORMMaterial3D : public BaseMaterial3D {
	GDCLASS(ORMMaterial3D, BaseMaterial3D);

public:
	ORMMaterial3D() :
			BaseMaterial3D(true) {}
};

VARIANT_ENUM_CAST(BaseMaterial3D::ShadingMode);
VARIANT_ENUM_CAST(BaseMaterial3D::DiffuseMode);
VARIANT_ENUM_CAST(BaseMaterial3D::SpecularMode);
VARIANT_ENUM_CAST(BaseMaterial3D::CullMode);
VARIANT_ENUM_CAST(BaseMaterial3D::Transparency);
VARIANT_ENUM_CAST(BaseMaterial3D::TextureChannel);
VARIANT_ENUM_CAST(BaseMaterial3D::TextureFilter);
