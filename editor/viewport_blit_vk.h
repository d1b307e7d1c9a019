/**************************************************************************/
/*  viewport_blit_vk.h                                                    */
/**************************************************************************/
/* godot-area: draws the editor's 3D viewport into the window straight    */
/* from the GPU (Godot's editor shows its SubViewport's texture the same  */
/* way): a full-rect draw inside Dear ImGui's render pass that samples    */
/*   - the RenderingServer viewport's own scene-linear texture,           */
/*   - the gizmo overlay texture (premultiplied linear RGBA),             */
/* composites the overlay in linear light, applies the Environment's      */
/* tonemap (core/io/tonemap.h: exposure, curve, clamp, sRGB OETF; the     */
/* same formulas as Tonemap::apply, in GLSL) and writes the window's      */
/* UNORM image. Nothing is read back to the CPU.                          */
/*                                                                        */
/* Dear ImGui 1.86's Vulkan backend draws only its font texture, so the   */
/* draw goes in as an ImDrawList callback: add_to_draw_list() queues it    */
/* where the viewport panel is drawn (window order and clipping kept),    */
/* followed by ImDrawCallback_ResetRenderState so the backend rebinds its  */
/* own pipeline afterwards. The textures live in VK_IMAGE_LAYOUT_GENERAL  */
/* (RenderingDevice keeps every image there); record_barrier() makes the  */
/* RenderingDevice's finished writes visible to the fragment shader.       */

#pragma once

#include "core/io/tonemap.h"
#include "core/string/ustring.h"
#include "servers/rendering/rendering_device.h"

#include <vulkan/vulkan.h>

struct ImDrawCmd;
struct ImDrawList;

class ViewportBlitVK {
	VkDevice device = VK_NULL_HANDLE;
	VkSampler sampler = VK_NULL_HANDLE;
	VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
	VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
	VkPipeline pipeline = VK_NULL_HANDLE;
	VkDescriptorPool pool = VK_NULL_HANDLE;
	VkDescriptorSet set = VK_NULL_HANDLE;
	VkImageView bound_scene = VK_NULL_HANDLE;
	VkImageView bound_overlay = VK_NULL_HANDLE;

	// The draw queued for this frame.
	VkCommandBuffer command_buffer = VK_NULL_HANDLE;
	int fb_width = 0;
	int fb_height = 0;
	float rect[4] = {}; // x, y, w, h in framebuffer pixels.
	Tonemap::Settings tonemap;
	bool ready = false; // Textures bound this frame.
	uint64_t draws = 0;

	static void _callback(const ImDrawList *p_list, const ImDrawCmd *p_cmd);

public:
	// Builds the pipeline for p_render_pass (subpass 0, one colour attachment) on p_rd's device;
	// the shaders are compiled with p_rd's glslang. False with r_error on failure.
	bool create(RenderingDevice *p_rd, VkRenderPass p_render_pass, String *r_error);
	void destroy();

	// Once per frame, after the previous frame finished (SwapChainVK::begin_frame) and before
	// the render pass: binds the textures (RenderingDevice RIDs) and records the barrier.
	// False (nothing will be drawn) when a texture is missing.
	bool begin_frame(VkCommandBuffer p_command_buffer, int p_fb_width, int p_fb_height, RenderingDevice *p_rd, RID p_scene, RID p_overlay, const Tonemap::Settings &p_tonemap);
	// A bound texture was freed: the next begin_frame() writes the descriptors again even when a
	// new texture's view got the old handle value.
	void forget_bindings() { bound_scene = bound_overlay = VK_NULL_HANDLE; }
	// Queues the draw into p_list at (p_x, p_y) with size p_w x p_h framebuffer pixels.
	void add_to_draw_list(ImDrawList *p_list, float p_x, float p_y, float p_w, float p_h);
	uint64_t get_draw_count() const { return draws; }

	ViewportBlitVK() {}
	~ViewportBlitVK() { destroy(); }
	ViewportBlitVK(const ViewportBlitVK &) = delete;
	ViewportBlitVK &operator=(const ViewportBlitVK &) = delete;
};
