/**************************************************************************/
/*  resource_preview_blit_vk.cpp                                          */
/**************************************************************************/
/* godot-area: see resource_preview_blit_vk.h.                            */

#include "editor/resource_preview_blit_vk.h"

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "editor/editor_resource_preview.h"
#include "scene/resources/texture.h"

#include <imgui.h>

static RID _float_texture(RenderingDevice *p_rd, const Image &p_image, const char *p_name) {
	const std::vector<float> &floats = p_image.get_data();
	std::vector<uint8_t> bytes((const uint8_t *)floats.data(), (const uint8_t *)(floats.data() + floats.size()));
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	tf.width = p_image.get_width();
	tf.height = p_image.get_height();
	tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
	RID rid = p_rd->texture_create(tf, { bytes });
	if (rid.is_valid()) {
		p_rd->set_resource_name(rid, p_name);
	}
	return rid;
}

bool ResourcePreviewBlitVK::create(RenderingDevice *p_rd, VkRenderPass p_render_pass, String *r_error) {
	if (!blit.create(p_rd, p_render_pass, r_error)) {
		return false;
	}
	overlay = _float_texture(p_rd, Image(1, 1, Color(0, 0, 0, 0)), "Editor inspector preview overlay");
	return overlay.is_valid();
}

void ResourcePreviewBlitVK::destroy(RenderingDevice *p_rd) {
	blit.destroy();
	if (p_rd && p_rd->is_initialized()) {
		if (texture.is_valid()) {
			p_rd->free(texture);
		}
		if (overlay.is_valid()) {
			p_rd->free(overlay);
		}
	}
	texture = overlay = RID();
}

void ResourcePreviewBlitVK::draw(const Texture2D *p_texture) {
	const ImageTexture *image_texture = Object::cast_to<ImageTexture>(p_texture);
	if (!image_texture || image_texture->get_image().is_empty()) {
		return;
	}
	const Image &image = image_texture->get_image();
	if (p_texture != source || image.ptr() != source_data || image.get_width() != source_width || image.get_height() != source_height) {
		source = p_texture;
		source_data = image.ptr();
		source_width = image.get_width();
		source_height = image.get_height();
		pending = EditorResourcePreview::make_texture_thumbnail(image, MAX_SIZE);
		upload = true;
	}
	const ImVec2 at = ImGui::GetCursorScreenPos();
	rect[0] = at.x;
	rect[1] = at.y;
	rect[2] = (float)pending.get_width();
	rect[3] = (float)pending.get_height();
	ImDrawList *list = ImGui::GetWindowDrawList();
	const ImVec2 clip_min = list->GetClipRectMin();
	const ImVec2 clip_max = list->GetClipRectMax();
	fully_visible = rect[0] >= clip_min.x && rect[1] >= clip_min.y && rect[0] + rect[2] <= clip_max.x && rect[1] + rect[3] <= clip_max.y;
	blit.add_to_draw_list(list, rect[0], rect[1], rect[2], rect[3]);
	ImGui::Dummy(ImVec2(rect[2], rect[3]));
	drawn_this_frame = true;
}

void ResourcePreviewBlitVK::update(RenderingDevice *p_rd) {
	if (!upload || !p_rd) {
		return;
	}
	upload = false;
	if (texture.is_valid() && (int)p_rd->texture_get_format(texture).width == pending.get_width() && (int)p_rd->texture_get_format(texture).height == pending.get_height()) {
		const std::vector<float> &floats = pending.get_data();
		p_rd->texture_update(texture, 0, std::vector<uint8_t>((const uint8_t *)floats.data(), (const uint8_t *)(floats.data() + floats.size())));
	} else {
		if (texture.is_valid()) {
			p_rd->free(texture);
			blit.forget_bindings();
		}
		texture = _float_texture(p_rd, pending, "Editor inspector texture preview");
	}
	p_rd->submit_and_sync();
}

bool ResourcePreviewBlitVK::begin_frame(VkCommandBuffer p_command_buffer, int p_fb_width, int p_fb_height, RenderingDevice *p_rd) {
	const bool wanted = drawn_this_frame;
	drawn_this_frame = false;
	Tonemap::Settings linear; // MODE_LINEAR, exposure 1: the thumbnail's own colours.
	return wanted && texture.is_valid() && blit.begin_frame(p_command_buffer, p_fb_width, p_fb_height, p_rd, texture, overlay, linear);
}

#endif // GODOT_AREA_EDITOR_WINDOW
