/**************************************************************************/
/*  swap_chain_vk.h                                                       */
/**************************************************************************/
/* godot-area: a Vulkan swapchain for the editor window, on the           */
/* RenderingDevice's own VkDevice and queue (RD::get_vulkan_handles()).  */
/* Godot keeps this in RenderingContextDriverVulkan/RenderingDeviceDriver */
/* (swap_chain_*); ours is the small part a presenter needs:              */
/*                                                                        */
/*   SwapChainVK sc;                                                      */
/*   sc.create(rd->get_vulkan_handles(), surface, w, h, &err);           */
/*   VkCommandBuffer cb = sc.begin_frame(clear_color);  // image cleared  */
/*   ...barriers for textures the UI samples...                           */
/*   sc.begin_render_pass();               // LOAD: UI drawn on top       */
/*   ...record UI draws into cb...                                        */
/*   sc.end_frame();                       // submit + present            */
/*                                                                        */
/* One frame in flight: begin_frame() waits for the previous frame. The   */
/* image format is 8-bit UNORM (B8G8R8A8 or R8G8B8A8): what is drawn is   */
/* already sRGB-encoded.                                                  */

#pragma once

#include "core/math/color.h"
#include "core/string/ustring.h"
#include "servers/rendering/rendering_device.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

class SwapChainVK {
	VkInstance instance = VK_NULL_HANDLE;
	VkPhysicalDevice physical_device = VK_NULL_HANDLE;
	VkDevice device = VK_NULL_HANDLE;
	VkQueue queue = VK_NULL_HANDLE;
	uint32_t queue_family = 0;
	VkSurfaceKHR surface = VK_NULL_HANDLE;

	VkSwapchainKHR swapchain = VK_NULL_HANDLE;
	VkFormat format = VK_FORMAT_UNDEFINED;
	VkExtent2D extent = {};
	uint32_t min_image_count = 2;
	std::vector<VkImage> images;
	std::vector<VkImageView> views;
	std::vector<VkFramebuffer> framebuffers;
	std::vector<VkSemaphore> render_done; // One per image.
	std::vector<VkSemaphore> acquired; // A ring, one more than images.
	uint32_t acquire_index = 0;
	VkRenderPass render_pass = VK_NULL_HANDLE;
	VkCommandPool command_pool = VK_NULL_HANDLE;
	VkCommandBuffer command_buffer = VK_NULL_HANDLE;
	VkFence fence = VK_NULL_HANDLE;
	bool fence_pending = false;

	// Window capture (capture_next_frame()).
	bool can_capture = false;
	bool capture_requested = false;
	VkBuffer capture_buffer = VK_NULL_HANDLE;
	VkDeviceMemory capture_memory = VK_NULL_HANDLE;
	std::vector<uint8_t> capture_rgba;

	uint32_t image_index = 0;
	bool in_frame = false;
	bool in_pass = false;
	bool bgra = true;

	bool _create_swapchain(String *r_error);
	void _destroy_swapchain();
	bool _create_host_buffer(VkDeviceSize p_size, VkBufferUsageFlags p_usage, VkBuffer &r_buffer, VkDeviceMemory &r_memory);
	void _free_capture();

public:
	// p_surface is owned from now on (destroyed by destroy()). False with r_error on failure.
	bool create(const RenderingDevice::VulkanHandles &p_handles, VkSurfaceKHR p_surface, int p_width, int p_height, String *r_error);
	void destroy();
	bool is_valid() const { return swapchain != VK_NULL_HANDLE; }

	VkRenderPass get_render_pass() const { return render_pass; }
	uint32_t get_image_count() const { return (uint32_t)images.size(); }
	uint32_t get_min_image_count() const { return min_image_count; }
	int get_width() const { return (int)extent.width; }
	int get_height() const { return (int)extent.height; }

	// Acquires the next image and clears it to p_clear (sRGB bytes, as the UI). Returns the frame's
	// command buffer, or VK_NULL_HANDLE when nothing can be drawn this frame (error printed).
	VkCommandBuffer begin_frame(const Color &p_clear);
	// Starts the render pass (load, not clear) over the whole image.
	void begin_render_pass();
	// Ends the pass, submits and presents. False when the image could not be presented.
	bool end_frame();
	// The next end_frame() also reads the presented image back (waits for it); false when the
	// window's images cannot be copied from. The pixels: get_capture(), RGBA8, top row first.
	bool capture_next_frame();
	const std::vector<uint8_t> &get_capture() const { return capture_rgba; }
	// Waits until the last frame finished (before destroying what it uses).
	void wait_idle();
	// Waits for the last submitted frame only (before the RenderingDevice rewrites a texture that
	// frame samples). begin_frame() then has nothing left to wait for.
	void wait_frame();
	// The window was resized: the swapchain is rebuilt at the surface's new size (the next
	// begin_frame() creates it). Waits for the device first.
	void resize(int p_width, int p_height);

	SwapChainVK() {}
	~SwapChainVK() { destroy(); }
	SwapChainVK(const SwapChainVK &) = delete;
	SwapChainVK &operator=(const SwapChainVK &) = delete;
};
