/**************************************************************************/
/*  material_storage.h                                                    */
/**************************************************************************/
/* godot-area: CPU-only material and texture storage (dummy backend).     */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/storage/material_storage.h"

namespace RendererDummy {

class MaterialStorage : public RendererMaterialStorage {
	mutable RID_Owner<RS::MaterialParams, true> material_owner{ "Material" };
	struct Texture {
		Image image;
		mutable std::vector<Image> mipmaps[2]; // Data, sRGB colour: levels 1..n, made on first use.
		mutable bool mipmaps_made[2] = { false, false };
	};
	mutable RID_Owner<Texture, true> texture_owner{ "Texture" };

public:
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
};

} // namespace RendererDummy
