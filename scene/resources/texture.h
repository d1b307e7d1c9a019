/**************************************************************************/
/*  texture.h                                                             */
/**************************************************************************/
/* godot-area: Texture2D (abstract: size + RS texture RID) and            */
/* ImageTexture (a Texture2D made from an Image). The RS has no texture   */
/* update call, so set_image() frees the old RID and creates a new one;   */
/* users that cached the RID re-read it when get_version() changes.       */

#pragma once

#include "core/io/image.h"
#include "core/io/resource.h"

class Texture2D : public Resource {
	GDCLASS(Texture2D, Resource);

protected:
	static void _bind_methods();

public:
	virtual int get_width() const = 0;
	virtual int get_height() const = 0;

	Texture2D() {}
};

class ImageTexture : public Texture2D {
	GDCLASS(ImageTexture, Texture2D);

	RID texture;
	Image image;

protected:
	static void _bind_methods();

public:
	// Returns a texture holding a copy of p_image, or a null Ref (with an error) for an empty image.
	static Ref<ImageTexture> create_from_image(const Image &p_image);

	// Replaces the texels; an empty image prints an error and keeps the old texture.
	void set_image(const Image &p_image);
	const Image &get_image() const { return image; }

	int get_width() const override { return image.get_width(); }
	int get_height() const override { return image.get_height(); }
	RID get_rid() const override { return texture; }

	ImageTexture() {}
	~ImageTexture() override;
};
