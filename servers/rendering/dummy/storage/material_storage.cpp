/**************************************************************************/
/*  material_storage.cpp                                                  */
/**************************************************************************/

#include "servers/rendering/dummy/storage/material_storage.h"

#include "core/error/error_macros.h"
#include "servers/rendering/storage/texture_mipmaps.h"

using namespace RendererDummy;

RID MaterialStorage::material_create() {
	return material_owner.make_rid();
}

bool MaterialStorage::material_free(RID p_rid) {
	if (!material_owner.owns(p_rid)) {
		return false;
	}
	material_owner.free(p_rid);
	return true;
}

void MaterialStorage::material_set_params(RID p_material, const RS::MaterialParams &p_params) {
	RS::MaterialParams *params = material_owner.get_or_null(p_material);
	ERR_FAIL_NULL_MSG(params, "Invalid material RID.");
	if (!validate_params(p_params)) {
		return;
	}
	*params = p_params;
}

RS::MaterialParams MaterialStorage::material_get_params(RID p_material) const {
	const RS::MaterialParams *params = material_owner.get_or_null(p_material);
	ERR_FAIL_NULL_V_MSG(params, RS::MaterialParams(), "Invalid material RID.");
	return *params;
}

RID MaterialStorage::texture_2d_create(const Image &p_image) {
	ERR_FAIL_COND_V_MSG(p_image.is_empty(), RID(), "Cannot create a texture from an empty image.");
	Texture t;
	t.image = p_image;
	return texture_owner.make_rid(t);
}

bool MaterialStorage::texture_free(RID p_rid) {
	if (!texture_owner.owns(p_rid)) {
		return false;
	}
	texture_owner.free(p_rid);
	return true;
}

int MaterialStorage::texture_get_width(RID p_texture) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, 0, "Invalid texture RID.");
	return t->image.get_width();
}

int MaterialStorage::texture_get_height(RID p_texture) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, 0, "Invalid texture RID.");
	return t->image.get_height();
}

const Image *MaterialStorage::texture_get_image(RID p_texture) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, nullptr, "Invalid texture RID.");
	return &t->image;
}

const std::vector<Image> *MaterialStorage::texture_get_mipmaps(RID p_texture, bool p_srgb) const {
	const Texture *t = texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, nullptr, "Invalid texture RID.");
	if (!t->mipmaps_made[p_srgb]) {
		texture_mipmaps_generate(t->image, p_srgb, t->mipmaps[p_srgb]);
		t->mipmaps_made[p_srgb] = true;
	}
	return &t->mipmaps[p_srgb];
}
