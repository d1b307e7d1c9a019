/**************************************************************************/
/*  texture.cpp                                                           */
/**************************************************************************/

#include "scene/resources/texture.h"

#include "core/error/error_macros.h"
#include "servers/rendering_server.h"

void Texture2D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("get_width"), &Texture2D::get_width);
	ClassDB::bind_method(D_METHOD("get_height"), &Texture2D::get_height);
}

Ref<ImageTexture> ImageTexture::create_from_image(const Image &p_image) {
	ERR_FAIL_COND_V_MSG(p_image.is_empty(), Ref<ImageTexture>(), "Cannot create an ImageTexture from an empty image.");
	Ref<ImageTexture> tex;
	tex.instantiate();
	tex->set_image(p_image);
	return tex;
}

void ImageTexture::set_image(const Image &p_image) {
	ERR_FAIL_COND_MSG(p_image.is_empty(), "ImageTexture::set_image(): the image is empty; the old texture is kept.");
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "ImageTexture needs a RenderingServer.");
	RID new_texture = rs->texture_2d_create(p_image);
	ERR_FAIL_COND_MSG(!new_texture.is_valid(), "ImageTexture::set_image(): the RenderingServer could not create the texture; the old one is kept.");
	if (texture.is_valid()) {
		rs->free(texture);
	}
	texture = new_texture;
	image = p_image;
	emit_changed();
}

void ImageTexture::_bind_methods() {
}

ImageTexture::~ImageTexture() {
	RS *rs = RS::get_singleton();
	if (rs && texture.is_valid()) {
		rs->free(texture);
	}
}
