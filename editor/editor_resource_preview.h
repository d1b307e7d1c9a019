/**************************************************************************/
/*  editor_resource_preview.h                                             */
/**************************************************************************/
/* godot-area: what the inspector shows of a resource-valued property     */
/* (Godot: EditorResourcePreview and its texture preview plugin, drawn by */
/* EditorResourcePicker). Headless: the thumbnail is an Image, which the  */
/* editor window uploads and draws (editor_node_window.cpp), so tests     */
/* check it without a window.                                             */
/*                                                                        */
/*   Image thumb = EditorResourcePreview::make_texture_thumbnail(         */
/*           texture->get_image(), 64);                                   */
/*   String text = EditorResourcePreview::describe(value);                */
/*   // "ImageTexture 256x128 res://textures/tv.png"                      */

#pragma once

#include "core/io/image.h"
#include "core/string/ustring.h"
#include "core/variant/variant.h"

class EditorResourcePreview {
public:
	// Cell size and the two greys (sRGB-encoded) of the transparency checkerboard under a
	// thumbnail, as Godot's editor draws it behind translucent textures.
	static constexpr int CHECKER_CELL = 8;
	static constexpr float CHECKER_DARK = 0.4f;
	static constexpr float CHECKER_LIGHT = 0.6f;

	// A texture's thumbnail: p_image (sRGB-encoded colour texels, as ImageLoader stores them)
	// fitted into p_max_size x p_max_size with its aspect ratio kept (at least one pixel a side;
	// a small image is enlarged). Each thumbnail pixel is the box-filtered average of the texels
	// it covers, taken in linear light with alpha weighting, then laid over the checkerboard by
	// its alpha. The result is linear RGB with alpha 1 (the window's blit encodes it to sRGB).
	// Empty for an empty image or p_max_size < 1.
	static Image make_texture_thumbnail(const Image &p_image, int p_max_size);

	// One line for a resource-valued property: "<empty>" for null; otherwise the class, the
	// size of a texture ("256x128"), and the file it came from, or "(built-in)" when it is
	// embedded in the scene.
	static String describe(const Variant &p_value);

	// A file typed into a resource row (Godot's EditorResourcePicker "Load"): p_path resolved as
	// the ext_resources of the scene at p_scene_path are (res:// against the project root,
	// relative paths against the scene's folder) and loaded. The resource must be a p_type (or
	// inherit it); a res:// path becomes its path, so a save writes it as typed. Null, with
	// r_error naming the file and the problem, when the file is missing, unreadable, has no
	// loader or holds another type.
	static Variant load_for_property(const String &p_path, const String &p_scene_path, const String &p_type, String *r_error);
};
