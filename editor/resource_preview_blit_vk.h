/**************************************************************************/
/*  resource_preview_blit_vk.h                                            */
/**************************************************************************/
/* godot-area: the inspector's texture preview on screen (Godot's         */
/* EditorResourcePicker shows the thumbnail of its texture). The          */
/* thumbnail (EditorResourcePreview::make_texture_thumbnail, linear RGB)  */
/* goes into a RenderingDevice texture, which a ViewportBlitVK draws at   */
/* the row's place in the Inspector dock, one texel per pixel, with the   */
/* Linear tonemap at exposure 1 (so the texture shows its own colours).   */
/* Frame order, as the viewport's blit: draw() while ImGui builds the     */
/* frame, update() once the previous frame finished, then begin_frame(). */
/* Only built with the editor window (GODOT_AREA_EDITOR_WINDOW).          */

#pragma once

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "core/io/image.h"
#include "core/templates/rid.h"
#include "editor/viewport_blit_vk.h"

class Texture2D;

class ResourcePreviewBlitVK {
	ViewportBlitVK blit;
	RID texture; // The thumbnail.
	RID overlay; // 1 x 1 transparent: nothing drawn over the thumbnail.
	// What the thumbnail was made from; a new image (set_image) makes a new thumbnail.
	const Texture2D *source = nullptr;
	const float *source_data = nullptr;
	int source_width = 0;
	int source_height = 0;
	Image pending; // A thumbnail to upload at update().
	bool upload = false;
	bool drawn_this_frame = false;
	bool fully_visible = false; // The whole thumbnail inside the dock's clip rectangle.
	float rect[4] = {}; // Where draw() placed it (window pixels).

public:
	static constexpr int MAX_SIZE = 64; // Pixels a side.

	bool create(RenderingDevice *p_rd, VkRenderPass p_render_pass, String *r_error);
	void destroy(RenderingDevice *p_rd);

	// While ImGui builds the frame, at the cursor: reserves the thumbnail's space and queues its
	// draw (the dock's clip rectangle applies). A texture without an image reserves nothing.
	void draw(const Texture2D *p_texture);
	// After the previous frame finished (it sampled the old thumbnail): uploads a new one.
	void update(RenderingDevice *p_rd);
	// Before the render pass; false when nothing is drawn this frame.
	bool begin_frame(VkCommandBuffer p_command_buffer, int p_fb_width, int p_fb_height, RenderingDevice *p_rd);
	// Draws that reached the framebuffer (ViewportBlitVK's count), and where the last was queued.
	uint64_t get_draw_count() const { return blit.get_draw_count(); }
	const float *get_rect() const { return rect; }
	bool is_fully_visible() const { return fully_visible; }
	int get_width() const { return pending.get_width(); }
	int get_height() const { return pending.get_height(); }

	ResourcePreviewBlitVK() {}
	~ResourcePreviewBlitVK() {}
	ResourcePreviewBlitVK(const ResourcePreviewBlitVK &) = delete;
	ResourcePreviewBlitVK &operator=(const ResourcePreviewBlitVK &) = delete;
};

#endif // GODOT_AREA_EDITOR_WINDOW
