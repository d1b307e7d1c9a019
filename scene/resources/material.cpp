/**************************************************************************/
/*  material.cpp                                                          */
/**************************************************************************/

#include "scene/resources/material.h"

#include "core/error/error_macros.h"

static bool _color_is_finite(const Color &p_c) {
	return Math::is_finite(p_c.r) && Math::is_finite(p_c.g) && Math::is_finite(p_c.b) && Math::is_finite(p_c.a);
}

/* Material */

void Material::_bind_methods() {
}

Material::Material() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "Material needs a RenderingServer; create one first.");
	material = rs->material_create();
}

Material::~Material() {
	RS *rs = RS::get_singleton();
	if (rs && material.is_valid()) {
		rs->free(material);
	}
}

/* BaseMaterial3D */

RS::MaterialParams BaseMaterial3D::get_params() const {
	RS::MaterialParams p;
	p.albedo = albedo;
	p.albedo_texture = albedo_texture.is_valid() ? albedo_texture->get_rid() : RID();
	p.roughness = roughness;
	p.metallic = metallic;
	if (orm) {
		const RID orm_rid = orm_texture.is_valid() ? orm_texture->get_rid() : RID();
		p.roughness_texture = orm_rid;
		p.roughness_texture_channel = RS::MATERIAL_TEXTURE_CHANNEL_GREEN;
		p.metallic_texture = orm_rid;
		p.metallic_texture_channel = RS::MATERIAL_TEXTURE_CHANNEL_BLUE;
	} else {
		p.roughness_texture = roughness_texture.is_valid() ? roughness_texture->get_rid() : RID();
		p.roughness_texture_channel = RS::MaterialTextureChannel(roughness_texture_channel);
		p.metallic_texture = metallic_texture.is_valid() ? metallic_texture->get_rid() : RID();
		p.metallic_texture_channel = RS::MaterialTextureChannel(metallic_texture_channel);
	}
	p.uv1_scale = uv1_scale;
	p.uv1_offset = uv1_offset;
	p.texture_filter = RS::MaterialTextureFilter(texture_filter);
	p.specular = specular;
	p.normal_texture = (normal_enabled && normal_texture.is_valid()) ? normal_texture->get_rid() : RID();
	p.normal_scale = normal_scale;
	p.emission = emission_enabled ? emission : Color(0, 0, 0, 1);
	p.emission_energy = emission_energy;
	p.diffuse_mode = RS::MaterialDiffuseMode(diffuse_mode);
	p.specular_mode = RS::MaterialSpecularMode(specular_mode);
	p.unshaded = shading_mode == SHADING_MODE_UNSHADED;
	p.cull_back = cull_mode == CULL_BACK;
	static const RS::MaterialTransparency transparencies[TRANSPARENCY_MAX] = { RS::MATERIAL_TRANSPARENCY_DISABLED, RS::MATERIAL_TRANSPARENCY_ALPHA,
		RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR, RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR, RS::MATERIAL_TRANSPARENCY_ALPHA };
	p.transparency = transparencies[transparency];
	p.alpha_scissor_threshold = alpha_scissor_threshold;
	p.vertex_color_use_as_albedo = vertex_color_use_as_albedo;
	p.vertex_color_is_srgb = vertex_color_is_srgb;
	return p;
}

void BaseMaterial3D::_update_params() {
	RS *rs = RS::get_singleton();
	if (rs && get_rid().is_valid()) {
		rs->material_set_params(get_rid(), get_params());
	}
	emit_changed();
}

void BaseMaterial3D::set_shading_mode(ShadingMode p_mode) {
	ERR_FAIL_INDEX_MSG((int)p_mode, SHADING_MODE_MAX, vformat("shading_mode must be 0..%d (Unshaded, Per-Pixel, Per-Vertex); got %d. The old value is kept.", SHADING_MODE_MAX - 1, (int)p_mode));
	if (p_mode == SHADING_MODE_PER_VERTEX) {
		WARN_PRINT_ONCE("shading_mode Per-Vertex is not supported by this renderer; it is shaded per pixel.");
	}
	shading_mode = p_mode;
	_update_params();
}

void BaseMaterial3D::set_diffuse_mode(DiffuseMode p_mode) {
	ERR_FAIL_INDEX_MSG((int)p_mode, DIFFUSE_MAX, vformat("diffuse_mode must be 0..%d (Burley, Lambert, Lambert Wrap, Toon); got %d. The old value is kept.", DIFFUSE_MAX - 1, (int)p_mode));
	diffuse_mode = p_mode;
	_update_params();
}

void BaseMaterial3D::set_specular_mode(SpecularMode p_mode) {
	ERR_FAIL_INDEX_MSG((int)p_mode, SPECULAR_MAX, vformat("specular_mode must be 0..%d (SchlickGGX, Toon, Disabled); got %d. The old value is kept.", SPECULAR_MAX - 1, (int)p_mode));
	specular_mode = p_mode;
	_update_params();
}

void BaseMaterial3D::set_cull_mode(CullMode p_mode) {
	ERR_FAIL_INDEX_MSG((int)p_mode, CULL_MAX, vformat("cull_mode must be 0..%d (Back, Front, Disabled); got %d. The old value is kept.", CULL_MAX - 1, (int)p_mode));
	if (p_mode == CULL_FRONT) {
		WARN_PRINT_ONCE("cull_mode Front is not supported by this renderer; faces are drawn two-sided.");
	}
	cull_mode = p_mode;
	_update_params();
}

void BaseMaterial3D::set_transparency(Transparency p_transparency) {
	ERR_FAIL_INDEX_MSG((int)p_transparency, TRANSPARENCY_MAX, vformat("transparency must be 0..%d (Disabled, Alpha, Alpha Scissor, Alpha Hash, Depth Pre-Pass); got %d. The old value is kept.", TRANSPARENCY_MAX - 1, (int)p_transparency));
	if (p_transparency == TRANSPARENCY_ALPHA_HASH) {
		WARN_PRINT_ONCE("transparency Alpha Hash is not supported by this renderer; it is drawn as Alpha Scissor (alpha_scissor_threshold).");
	} else if (p_transparency == TRANSPARENCY_ALPHA_DEPTH_PRE_PASS) {
		WARN_PRINT_ONCE("transparency Depth Pre-Pass is not supported by this renderer; it is drawn as Alpha (blended, no depth write).");
	}
	transparency = p_transparency;
	_update_params();
}

void BaseMaterial3D::set_alpha_scissor_threshold(float p_threshold) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_threshold) || p_threshold < 0.0f || p_threshold > 1.0f, vformat("alpha_scissor_threshold must be between 0 and 1; got %s. The old value is kept.", rtos(p_threshold).c_str()));
	alpha_scissor_threshold = p_threshold;
	_update_params();
}

void BaseMaterial3D::set_flag_vertex_color_use_as_albedo(bool p_enabled) {
	vertex_color_use_as_albedo = p_enabled;
	_update_params();
}

void BaseMaterial3D::set_flag_vertex_color_is_srgb(bool p_enabled) {
	vertex_color_is_srgb = p_enabled;
	_update_params();
}

void BaseMaterial3D::set_albedo(const Color &p_albedo) {
	ERR_FAIL_COND_MSG(!_color_is_finite(p_albedo), "albedo_color must be finite (no NaN or infinity); the old value is kept.");
	albedo = p_albedo;
	_update_params();
}

void BaseMaterial3D::set_albedo_texture(const Ref<Texture2D> &p_texture) {
	albedo_texture = p_texture;
	_update_params();
}

void BaseMaterial3D::set_metallic(float p_metallic) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_metallic) || p_metallic < 0.0f || p_metallic > 1.0f, vformat("metallic must be between 0 and 1 (got %s); the old value is kept.", rtos(p_metallic).c_str()));
	metallic = p_metallic;
	_update_params();
}

void BaseMaterial3D::set_specular(float p_specular) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_specular) || p_specular < 0.0f || p_specular > 1.0f, vformat("metallic_specular must be between 0 and 1 (got %s); the old value is kept.", rtos(p_specular).c_str()));
	specular = p_specular;
	_update_params();
}

void BaseMaterial3D::set_roughness(float p_roughness) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_roughness) || p_roughness < 0.0f || p_roughness > 1.0f, vformat("roughness must be between 0 and 1 (got %s); the old value is kept.", rtos(p_roughness).c_str()));
	roughness = p_roughness;
	_update_params();
}

void BaseMaterial3D::set_emission_enabled(bool p_enabled) {
	emission_enabled = p_enabled;
	_update_params();
	notify_property_list_changed();
}

void BaseMaterial3D::set_emission(const Color &p_emission) {
	ERR_FAIL_COND_MSG(!_color_is_finite(p_emission), "emission must be finite (no NaN or infinity); the old value is kept.");
	emission = p_emission;
	_update_params();
}

void BaseMaterial3D::set_emission_energy_multiplier(float p_energy) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_energy) || p_energy < 0.0f, vformat("emission_energy_multiplier must be finite and >= 0 (got %s); the old value is kept.", rtos(p_energy).c_str()));
	emission_energy = p_energy;
	_update_params();
}

void BaseMaterial3D::set_normal_enabled(bool p_enabled) {
	normal_enabled = p_enabled;
	_update_params();
	notify_property_list_changed();
}

void BaseMaterial3D::set_normal_scale(float p_scale) {
	ERR_FAIL_COND_MSG(!Math::is_finite(p_scale), vformat("normal_scale must be finite (got %s); the old value is kept.", rtos(p_scale).c_str()));
	normal_scale = p_scale;
	_update_params();
}

void BaseMaterial3D::set_normal_texture(const Ref<Texture2D> &p_texture) {
	normal_texture = p_texture;
	_update_params();
}

void BaseMaterial3D::set_metallic_texture(const Ref<Texture2D> &p_texture) {
	metallic_texture = p_texture;
	_update_params();
}

void BaseMaterial3D::set_metallic_texture_channel(TextureChannel p_channel) {
	ERR_FAIL_INDEX_MSG((int)p_channel, TEXTURE_CHANNEL_MAX, vformat("metallic_texture_channel must be 0..%d (Red, Green, Blue, Alpha, Gray); got %d. The old value is kept.", TEXTURE_CHANNEL_MAX - 1, (int)p_channel));
	metallic_texture_channel = p_channel;
	_update_params();
}

void BaseMaterial3D::set_roughness_texture(const Ref<Texture2D> &p_texture) {
	roughness_texture = p_texture;
	_update_params();
}

void BaseMaterial3D::set_roughness_texture_channel(TextureChannel p_channel) {
	ERR_FAIL_INDEX_MSG((int)p_channel, TEXTURE_CHANNEL_MAX, vformat("roughness_texture_channel must be 0..%d (Red, Green, Blue, Alpha, Gray); got %d. The old value is kept.", TEXTURE_CHANNEL_MAX - 1, (int)p_channel));
	roughness_texture_channel = p_channel;
	_update_params();
}

void BaseMaterial3D::set_orm_texture(const Ref<Texture2D> &p_texture) {
	orm_texture = p_texture;
	_update_params();
}

void BaseMaterial3D::set_uv1_scale(const Vector3 &p_scale) {
	ERR_FAIL_COND_MSG(!p_scale.is_finite(), "uv1_scale must be finite; the old value is kept.");
	uv1_scale = p_scale;
	_update_params();
}

void BaseMaterial3D::set_uv1_offset(const Vector3 &p_offset) {
	ERR_FAIL_COND_MSG(!p_offset.is_finite(), "uv1_offset must be finite; the old value is kept.");
	uv1_offset = p_offset;
	_update_params();
}

void BaseMaterial3D::set_texture_filter(TextureFilter p_filter) {
	ERR_FAIL_INDEX_MSG((int)p_filter, TEXTURE_FILTER_MAX, vformat("texture_filter must be 0..%d (Nearest, Linear, Nearest Mipmap, Linear Mipmap, Nearest Mipmap Anisotropic, Linear Mipmap Anisotropic); got %d. The old value is kept.", TEXTURE_FILTER_MAX - 1, (int)p_filter));
	if (p_filter == TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC || p_filter == TEXTURE_FILTER_LINEAR_WITH_MIPMAPS_ANISOTROPIC) {
		WARN_PRINT_ONCE("texture_filter Anisotropic is not supported by this renderer; textures are filtered with mipmaps, without anisotropy.");
	}
	texture_filter = p_filter;
	_update_params();
}

void BaseMaterial3D::_validate_property(PropertyInfo &p_property) const {
	// As Godot: an ORM material shows orm_texture instead of the separate roughness and metallic maps.
	const bool separate_maps = p_property.name == "roughness_texture" || p_property.name == "roughness_texture_channel" || p_property.name == "metallic_texture" ||
			p_property.name == "metallic_texture_channel";
	if ((orm && separate_maps) || (!orm && p_property.name == "orm_texture")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	// As Godot: a feature's properties are saved but not shown while the feature is off.
	if (!emission_enabled && (p_property.name == "emission" || p_property.name == "emission_energy_multiplier")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
	if (!normal_enabled && (p_property.name == "normal_scale" || p_property.name == "normal_texture")) {
		p_property.usage = PROPERTY_USAGE_NO_EDITOR;
	}
}

void BaseMaterial3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_shading_mode", "shading_mode"), &BaseMaterial3D::set_shading_mode);
	ClassDB::bind_method(D_METHOD("get_shading_mode"), &BaseMaterial3D::get_shading_mode);
	ClassDB::bind_method(D_METHOD("set_diffuse_mode", "diffuse_mode"), &BaseMaterial3D::set_diffuse_mode);
	ClassDB::bind_method(D_METHOD("get_diffuse_mode"), &BaseMaterial3D::get_diffuse_mode);
	ClassDB::bind_method(D_METHOD("set_specular_mode", "specular_mode"), &BaseMaterial3D::set_specular_mode);
	ClassDB::bind_method(D_METHOD("get_specular_mode"), &BaseMaterial3D::get_specular_mode);
	ClassDB::bind_method(D_METHOD("set_cull_mode", "cull_mode"), &BaseMaterial3D::set_cull_mode);
	ClassDB::bind_method(D_METHOD("get_cull_mode"), &BaseMaterial3D::get_cull_mode);
	ClassDB::bind_method(D_METHOD("set_albedo", "albedo"), &BaseMaterial3D::set_albedo);
	ClassDB::bind_method(D_METHOD("get_albedo"), &BaseMaterial3D::get_albedo);
	ClassDB::bind_method(D_METHOD("set_albedo_texture", "texture"), &BaseMaterial3D::set_albedo_texture);
	ClassDB::bind_method(D_METHOD("get_albedo_texture"), &BaseMaterial3D::get_albedo_texture);
	ClassDB::bind_method(D_METHOD("set_metallic", "metallic"), &BaseMaterial3D::set_metallic);
	ClassDB::bind_method(D_METHOD("get_metallic"), &BaseMaterial3D::get_metallic);
	ClassDB::bind_method(D_METHOD("set_specular", "specular"), &BaseMaterial3D::set_specular);
	ClassDB::bind_method(D_METHOD("get_specular"), &BaseMaterial3D::get_specular);
	ClassDB::bind_method(D_METHOD("set_roughness", "roughness"), &BaseMaterial3D::set_roughness);
	ClassDB::bind_method(D_METHOD("get_roughness"), &BaseMaterial3D::get_roughness);
	ClassDB::bind_method(D_METHOD("set_emission_enabled", "enabled"), &BaseMaterial3D::set_emission_enabled);
	ClassDB::bind_method(D_METHOD("is_emission_enabled"), &BaseMaterial3D::is_emission_enabled);
	ClassDB::bind_method(D_METHOD("set_emission", "emission"), &BaseMaterial3D::set_emission);
	ClassDB::bind_method(D_METHOD("get_emission"), &BaseMaterial3D::get_emission);
	ClassDB::bind_method(D_METHOD("set_emission_energy_multiplier", "emission_energy_multiplier"), &BaseMaterial3D::set_emission_energy_multiplier);
	ClassDB::bind_method(D_METHOD("get_emission_energy_multiplier"), &BaseMaterial3D::get_emission_energy_multiplier);
	ClassDB::bind_method(D_METHOD("set_normal_enabled", "enabled"), &BaseMaterial3D::set_normal_enabled);
	ClassDB::bind_method(D_METHOD("is_normal_enabled"), &BaseMaterial3D::is_normal_enabled);
	ClassDB::bind_method(D_METHOD("set_normal_scale", "normal_scale"), &BaseMaterial3D::set_normal_scale);
	ClassDB::bind_method(D_METHOD("get_normal_scale"), &BaseMaterial3D::get_normal_scale);
	ClassDB::bind_method(D_METHOD("set_normal_texture", "texture"), &BaseMaterial3D::set_normal_texture);
	ClassDB::bind_method(D_METHOD("get_normal_texture"), &BaseMaterial3D::get_normal_texture);
	ClassDB::bind_method(D_METHOD("set_metallic_texture", "texture"), &BaseMaterial3D::set_metallic_texture);
	ClassDB::bind_method(D_METHOD("get_metallic_texture"), &BaseMaterial3D::get_metallic_texture);
	ClassDB::bind_method(D_METHOD("set_metallic_texture_channel", "channel"), &BaseMaterial3D::set_metallic_texture_channel);
	ClassDB::bind_method(D_METHOD("get_metallic_texture_channel"), &BaseMaterial3D::get_metallic_texture_channel);
	ClassDB::bind_method(D_METHOD("set_roughness_texture", "texture"), &BaseMaterial3D::set_roughness_texture);
	ClassDB::bind_method(D_METHOD("get_roughness_texture"), &BaseMaterial3D::get_roughness_texture);
	ClassDB::bind_method(D_METHOD("set_roughness_texture_channel", "channel"), &BaseMaterial3D::set_roughness_texture_channel);
	ClassDB::bind_method(D_METHOD("get_roughness_texture_channel"), &BaseMaterial3D::get_roughness_texture_channel);
	ClassDB::bind_method(D_METHOD("set_orm_texture", "texture"), &BaseMaterial3D::set_orm_texture);
	ClassDB::bind_method(D_METHOD("get_orm_texture"), &BaseMaterial3D::get_orm_texture);
	ClassDB::bind_method(D_METHOD("set_uv1_scale", "scale"), &BaseMaterial3D::set_uv1_scale);
	ClassDB::bind_method(D_METHOD("get_uv1_scale"), &BaseMaterial3D::get_uv1_scale);
	ClassDB::bind_method(D_METHOD("set_uv1_offset", "offset"), &BaseMaterial3D::set_uv1_offset);
	ClassDB::bind_method(D_METHOD("get_uv1_offset"), &BaseMaterial3D::get_uv1_offset);
	ClassDB::bind_method(D_METHOD("set_transparency", "transparency"), &BaseMaterial3D::set_transparency);
	ClassDB::bind_method(D_METHOD("get_transparency"), &BaseMaterial3D::get_transparency);
	ClassDB::bind_method(D_METHOD("set_alpha_scissor_threshold", "threshold"), &BaseMaterial3D::set_alpha_scissor_threshold);
	ClassDB::bind_method(D_METHOD("get_alpha_scissor_threshold"), &BaseMaterial3D::get_alpha_scissor_threshold);
	ClassDB::bind_method(D_METHOD("set_flag_vertex_color_use_as_albedo", "enable"), &BaseMaterial3D::set_flag_vertex_color_use_as_albedo);
	ClassDB::bind_method(D_METHOD("get_flag_vertex_color_use_as_albedo"), &BaseMaterial3D::get_flag_vertex_color_use_as_albedo);
	ClassDB::bind_method(D_METHOD("set_flag_vertex_color_is_srgb", "enable"), &BaseMaterial3D::set_flag_vertex_color_is_srgb);
	ClassDB::bind_method(D_METHOD("get_flag_vertex_color_is_srgb"), &BaseMaterial3D::get_flag_vertex_color_is_srgb);
	ClassDB::bind_method(D_METHOD("set_texture_filter", "mode"), &BaseMaterial3D::set_texture_filter);
	ClassDB::bind_method(D_METHOD("get_texture_filter"), &BaseMaterial3D::get_texture_filter);

	ADD_GROUP("Transparency", "");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "transparency", PROPERTY_HINT_ENUM, "Disabled,Alpha,Alpha Scissor,Alpha Hash,Depth Pre-Pass"), "set_transparency", "get_transparency");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "alpha_scissor_threshold", PROPERTY_HINT_RANGE, "0,1,0.001"), "set_alpha_scissor_threshold", "get_alpha_scissor_threshold");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "cull_mode", PROPERTY_HINT_ENUM, "Back,Front,Disabled"), "set_cull_mode", "get_cull_mode");

	ADD_GROUP("Shading", "");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "shading_mode", PROPERTY_HINT_ENUM, "Unshaded,Per-Pixel,Per-Vertex"), "set_shading_mode", "get_shading_mode");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "diffuse_mode", PROPERTY_HINT_ENUM, "Burley,Lambert,Lambert Wrap,Toon"), "set_diffuse_mode", "get_diffuse_mode");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "specular_mode", PROPERTY_HINT_ENUM, "SchlickGGX,Toon,Disabled"), "set_specular_mode", "get_specular_mode");

	ADD_GROUP("Vertex Color", "vertex_color");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "vertex_color_use_as_albedo"), "set_flag_vertex_color_use_as_albedo", "get_flag_vertex_color_use_as_albedo");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "vertex_color_is_srgb"), "set_flag_vertex_color_is_srgb", "get_flag_vertex_color_is_srgb");

	ADD_GROUP("Albedo", "albedo_");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "albedo_color"), "set_albedo", "get_albedo");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "albedo_texture", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_albedo_texture", "get_albedo_texture");

	ADD_GROUP("ORM", "orm_");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "orm_texture", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_orm_texture", "get_orm_texture");

	ADD_GROUP("Metallic", "metallic_");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "metallic", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_metallic", "get_metallic");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "metallic_specular", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_specular", "get_specular");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "metallic_texture", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_metallic_texture", "get_metallic_texture");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "metallic_texture_channel", PROPERTY_HINT_ENUM, "Red,Green,Blue,Alpha,Gray"), "set_metallic_texture_channel", "get_metallic_texture_channel");

	ADD_GROUP("Roughness", "roughness_");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "roughness", PROPERTY_HINT_RANGE, "0,1,0.01"), "set_roughness", "get_roughness");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "roughness_texture", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_roughness_texture", "get_roughness_texture");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "roughness_texture_channel", PROPERTY_HINT_ENUM, "Red,Green,Blue,Alpha,Gray"), "set_roughness_texture_channel", "get_roughness_texture_channel");

	ADD_GROUP("Emission", "emission_");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "emission_enabled"), "set_emission_enabled", "is_emission_enabled");
	ADD_PROPERTY(PropertyInfo(Variant::COLOR, "emission", PROPERTY_HINT_COLOR_NO_ALPHA), "set_emission", "get_emission");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "emission_energy_multiplier", PROPERTY_HINT_RANGE, "0,16,0.01,or_greater"), "set_emission_energy_multiplier", "get_emission_energy_multiplier");

	ADD_GROUP("Normal Map", "normal_");
	ADD_PROPERTY(PropertyInfo(Variant::BOOL, "normal_enabled"), "set_normal_enabled", "is_normal_enabled");
	ADD_PROPERTY(PropertyInfo(Variant::FLOAT, "normal_scale", PROPERTY_HINT_RANGE, "-16,16,0.01"), "set_normal_scale", "get_normal_scale");
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "normal_texture", PROPERTY_HINT_RESOURCE_TYPE, "Texture2D"), "set_normal_texture", "get_normal_texture");

	ADD_GROUP("UV1", "uv1_");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "uv1_scale", PROPERTY_HINT_LINK), "set_uv1_scale", "get_uv1_scale");
	ADD_PROPERTY(PropertyInfo(Variant::VECTOR3, "uv1_offset"), "set_uv1_offset", "get_uv1_offset");

	ADD_GROUP("Sampling", "texture_");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "texture_filter", PROPERTY_HINT_ENUM, "Nearest,Linear,Nearest Mipmap,Linear Mipmap,Nearest Mipmap Anisotropic,Linear Mipmap Anisotropic"), "set_texture_filter", "get_texture_filter");
	ADD_GROUP("", "");

	BIND_ENUM_CONSTANT(SHADING_MODE_UNSHADED);
	BIND_ENUM_CONSTANT(SHADING_MODE_PER_PIXEL);
	BIND_ENUM_CONSTANT(SHADING_MODE_PER_VERTEX);
	BIND_ENUM_CONSTANT(SHADING_MODE_MAX);
	BIND_ENUM_CONSTANT(DIFFUSE_BURLEY);
	BIND_ENUM_CONSTANT(DIFFUSE_LAMBERT);
	BIND_ENUM_CONSTANT(DIFFUSE_LAMBERT_WRAP);
	BIND_ENUM_CONSTANT(DIFFUSE_TOON);
	BIND_ENUM_CONSTANT(SPECULAR_SCHLICK_GGX);
	BIND_ENUM_CONSTANT(SPECULAR_TOON);
	BIND_ENUM_CONSTANT(SPECULAR_DISABLED);
	BIND_ENUM_CONSTANT(TRANSPARENCY_DISABLED);
	BIND_ENUM_CONSTANT(TRANSPARENCY_ALPHA);
	BIND_ENUM_CONSTANT(TRANSPARENCY_ALPHA_SCISSOR);
	BIND_ENUM_CONSTANT(TRANSPARENCY_ALPHA_HASH);
	BIND_ENUM_CONSTANT(TRANSPARENCY_ALPHA_DEPTH_PRE_PASS);
	BIND_ENUM_CONSTANT(CULL_BACK);
	BIND_ENUM_CONSTANT(CULL_FRONT);
	BIND_ENUM_CONSTANT(CULL_DISABLED);
	BIND_ENUM_CONSTANT(TEXTURE_CHANNEL_RED);
	BIND_ENUM_CONSTANT(TEXTURE_CHANNEL_GREEN);
	BIND_ENUM_CONSTANT(TEXTURE_CHANNEL_BLUE);
	BIND_ENUM_CONSTANT(TEXTURE_CHANNEL_ALPHA);
	BIND_ENUM_CONSTANT(TEXTURE_CHANNEL_GRAYSCALE);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_NEAREST);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_LINEAR);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_NEAREST_WITH_MIPMAPS);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_LINEAR_WITH_MIPMAPS);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_NEAREST_WITH_MIPMAPS_ANISOTROPIC);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_LINEAR_WITH_MIPMAPS_ANISOTROPIC);
	BIND_ENUM_CONSTANT(TEXTURE_FILTER_MAX);
}

BaseMaterial3D::BaseMaterial3D(bool p_orm) :
		orm(p_orm) {
	_update_params();
}
