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
	enum CullMode {
		CULL_BACK,
		CULL_FRONT, // Not supported by the renderer: drawn like CULL_DISABLED (with a warning).
		CULL_DISABLED,
		CULL_MAX
	};

private:
	ShadingMode shading_mode = SHADING_MODE_PER_PIXEL;
	DiffuseMode diffuse_mode = DIFFUSE_BURLEY;
	SpecularMode specular_mode = SPECULAR_SCHLICK_GGX;
	CullMode cull_mode = CULL_BACK;
	Color albedo = Color(1, 1, 1, 1);
	Ref<Texture2D> albedo_texture;
	float metallic = 0.0f;
	float specular = 0.5f;
	float roughness = 1.0f;
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

	BaseMaterial3D();
};

// The concrete material scene files name ("StandardMaterial3D").
class StandardMaterial3D : public BaseMaterial3D {
	GDCLASS(StandardMaterial3D, BaseMaterial3D);

public:
	StandardMaterial3D() {}
};

VARIANT_ENUM_CAST(BaseMaterial3D::ShadingMode);
VARIANT_ENUM_CAST(BaseMaterial3D::DiffuseMode);
VARIANT_ENUM_CAST(BaseMaterial3D::SpecularMode);
VARIANT_ENUM_CAST(BaseMaterial3D::CullMode);
