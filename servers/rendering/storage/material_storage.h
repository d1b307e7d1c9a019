/**************************************************************************/
/*  material_storage.h                                                    */
/**************************************************************************/
/* godot-area: abstract material and texture storage (Godot splits these  */
/* into RendererMaterialStorage and RendererTextureStorage; we keep one). */
/* Implementations keep a CPU copy of texture texels (texture_get_image). */

#pragma once

#include "servers/rendering_server.h"

class RendererMaterialStorage {
public:
	// Checks material parameters (finite values, roughness/metallic/specular in 0..1, enum ranges);
	// prints an error naming the field and returns false when invalid.
	static bool validate_params(const RS::MaterialParams &p_params);

	// Creates a material with default parameters.
	virtual RID material_create() = 0;
	// Frees a material; returns false if this storage does not own p_rid.
	virtual bool material_free(RID p_rid) = 0;
	// Returns true if p_rid is a material of this storage.
	virtual bool owns_material(RID p_rid) const = 0;
	// Replaces all parameters (validated; invalid input keeps the old ones).
	virtual void material_set_params(RID p_material, const RS::MaterialParams &p_params) = 0;
	// Returns the parameters (defaults for an invalid RID).
	virtual RS::MaterialParams material_get_params(RID p_material) const = 0;

	// Creates a 2D texture from float RGBA texels; RID() for an empty image.
	virtual RID texture_2d_create(const Image &p_image) = 0;
	// Frees a texture; returns false if this storage does not own p_rid.
	virtual bool texture_free(RID p_rid) = 0;
	// Returns true if p_rid is a texture of this storage.
	virtual bool owns_texture(RID p_rid) const = 0;
	// Returns the texture width (0 for an invalid RID).
	virtual int texture_get_width(RID p_texture) const = 0;
	// Returns the texture height (0 for an invalid RID).
	virtual int texture_get_height(RID p_texture) const = 0;
	// Returns the CPU copy of the texels, or nullptr. Valid only during the current call.
	virtual const Image *texture_get_image(RID p_texture) const = 0;
	// Levels 1..n of the texture's mip chain (texture_mipmaps_generate; level 0 is texture_get_image),
	// made on first call and kept with the texture; p_srgb: the chain of the sRGB-encoded colour use
	// (albedo), averaged in linear space. nullptr for an invalid RID. Not thread-safe on first call.
	virtual const std::vector<Image> *texture_get_mipmaps(RID p_texture, bool p_srgb) const = 0;

	virtual ~RendererMaterialStorage() {}
};
