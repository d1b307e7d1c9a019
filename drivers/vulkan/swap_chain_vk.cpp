/**************************************************************************/
/*  swap_chain_vk.cpp                                                     */
/**************************************************************************/
/* godot-area: see swap_chain_vk.h.                                       */

#include "drivers/vulkan/swap_chain_vk.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cstring>

bool SwapChainVK::create(const RenderingDevice::VulkanHandles &p_handles, VkSurfaceKHR p_surface, int p_width, int p_height, String *r_error) {
	ERR_FAIL_COND_V_MSG(swapchain != VK_NULL_HANDLE, false, "SwapChainVK::create: already created.");
	instance = (VkInstance)p_handles.instance;
	physical_device = (VkPhysicalDevice)p_handles.physical_device;
	device = (VkDevice)p_handles.device;
	queue = (VkQueue)p_handles.queue;
	queue_family = p_handles.queue_family;
	surface = p_surface;
	if (!device || !surface) {
		*r_error = "SwapChainVK: no Vulkan device or no window surface.";
		return false;
	}
	VkBool32 present_ok = VK_FALSE;
	vkGetPhysicalDeviceSurfaceSupportKHR(physical_device, queue_family, surface, &present_ok);
	if (!present_ok) {
		*r_error = "SwapChainVK: the rendering queue cannot present to this window.";
		return false;
	}
	extent.width = (uint32_t)std::max(1, p_width);
	extent.height = (uint32_t)std::max(1, p_height);

	// Render pass: the image arrives in TRANSFER_DST (cleared), the UI loads it.
	VkAttachmentDescription att = {};
	uint32_t format_count = 0;
	vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device, surface, &format_count, nullptr);
	std::vector<VkSurfaceFormatKHR> formats(format_count);
	vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device, surface, &format_count, formats.data());
	format = VK_FORMAT_UNDEFINED;
	for (const VkSurfaceFormatKHR &f : formats) {
		if ((f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
			format = f.format;
			break;
		}
	}
	if (format == VK_FORMAT_UNDEFINED) {
		*r_error = "SwapChainVK: the window offers no B8G8R8A8_UNORM or R8G8B8A8_UNORM format.";
		return false;
	}
	bgra = format == VK_FORMAT_B8G8R8A8_UNORM;
	att.format = format;
	att.samples = VK_SAMPLE_COUNT_1_BIT;
	att.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
	att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
	att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
	att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
	att.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
	att.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
	VkAttachmentReference ref = { 0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL };
	VkSubpassDescription sub = {};
	sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
	sub.colorAttachmentCount = 1;
	sub.pColorAttachments = &ref;
	VkSubpassDependency dep = {};
	dep.srcSubpass = VK_SUBPASS_EXTERNAL;
	dep.dstSubpass = 0;
	dep.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
	dep.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
	dep.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
	dep.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
	VkRenderPassCreateInfo rpci = { VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO };
	rpci.attachmentCount = 1;
	rpci.pAttachments = &att;
	rpci.subpassCount = 1;
	rpci.pSubpasses = &sub;
	rpci.dependencyCount = 1;
	rpci.pDependencies = &dep;
	if (vkCreateRenderPass(device, &rpci, nullptr, &render_pass) != VK_SUCCESS) {
		*r_error = "SwapChainVK: vkCreateRenderPass failed.";
		return false;
	}

	VkCommandPoolCreateInfo pci = { VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO };
	pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
	pci.queueFamilyIndex = queue_family;
	vkCreateCommandPool(device, &pci, nullptr, &command_pool);
	VkCommandBufferAllocateInfo cai = { VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO };
	cai.commandPool = command_pool;
	cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
	cai.commandBufferCount = 1;
	vkAllocateCommandBuffers(device, &cai, &command_buffer);
	VkFenceCreateInfo fci = { VK_STRUCTURE_TYPE_FENCE_CREATE_INFO };
	vkCreateFence(device, &fci, nullptr, &fence);
	return _create_swapchain(r_error);
}

bool SwapChainVK::_create_swapchain(String *r_error) {
	VkSurfaceCapabilitiesKHR caps;
	vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_device, surface, &caps);
	if (caps.currentExtent.width != 0xFFFFFFFFu) {
		extent = caps.currentExtent;
	} else {
		extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
		extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
	}
	if (extent.width == 0 || extent.height == 0) {
		return true; // Minimized: no images until the window has a size again.
	}
	VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
	if ((caps.supportedUsageFlags & usage) != usage) {
		*r_error = "SwapChainVK: the window's images cannot be transfer destinations.";
		return false;
	}
	can_capture = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
	if (can_capture) {
		usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
	}
	min_image_count = std::max(2u, caps.minImageCount);
	uint32_t count = min_image_count + 1;
	if (caps.maxImageCount > 0) {
		count = std::min(count, caps.maxImageCount);
	}
	VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
	if (!(caps.supportedCompositeAlpha & alpha)) {
		for (uint32_t bit = 1; bit <= VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR; bit <<= 1) {
			if (caps.supportedCompositeAlpha & bit) {
				alpha = (VkCompositeAlphaFlagBitsKHR)bit;
				break;
			}
		}
	}
	VkSwapchainCreateInfoKHR sci = { VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR };
	sci.surface = surface;
	sci.minImageCount = count;
	sci.imageFormat = format;
	sci.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
	sci.imageExtent = extent;
	sci.imageArrayLayers = 1;
	sci.imageUsage = usage;
	sci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
	sci.preTransform = caps.currentTransform;
	sci.compositeAlpha = alpha;
	sci.presentMode = VK_PRESENT_MODE_FIFO_KHR; // Always supported.
	sci.clipped = VK_TRUE;
	VkResult res = vkCreateSwapchainKHR(device, &sci, nullptr, &swapchain);
	if (res != VK_SUCCESS) {
		*r_error = vformat("SwapChainVK: vkCreateSwapchainKHR failed (VkResult %d).", res);
		swapchain = VK_NULL_HANDLE;
		return false;
	}
	uint32_t n = 0;
	vkGetSwapchainImagesKHR(device, swapchain, &n, nullptr);
	images.resize(n);
	vkGetSwapchainImagesKHR(device, swapchain, &n, images.data());
	views.resize(n);
	framebuffers.resize(n);
	render_done.resize(n);
	acquired.resize(n + 1);
	VkSemaphoreCreateInfo semci = { VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO };
	for (uint32_t i = 0; i < n; i++) {
		VkImageViewCreateInfo vci = { VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO };
		vci.image = images[i];
		vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
		vci.format = format;
		vci.subresourceRange = { VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1 };
		vkCreateImageView(device, &vci, nullptr, &views[i]);
		VkFramebufferCreateInfo fbci = { VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO };
		fbci.renderPass = render_pass;
		fbci.attachmentCount = 1;
		fbci.pAttachments = &views[i];
		fbci.width = extent.width;
		fbci.height = extent.height;
		fbci.layers = 1;
		vkCreateFramebuffer(device, &fbci, nullptr, &framebuffers[i]);
		vkCreateSemaphore(device, &semci, nullptr, &render_done[i]);
	}
	for (VkSemaphore &s : acquired) {
		vkCreateSemaphore(device, &semci, nullptr, &s);
	}
	acquire_index = 0;
	return true;
}

void SwapChainVK::_destroy_swapchain() {
	if (!device) {
		return;
	}
	vkDeviceWaitIdle(device);
	for (VkFramebuffer fb : framebuffers) {
		vkDestroyFramebuffer(device, fb, nullptr);
	}
	for (VkImageView v : views) {
		vkDestroyImageView(device, v, nullptr);
	}
	for (VkSemaphore s : render_done) {
		vkDestroySemaphore(device, s, nullptr);
	}
	for (VkSemaphore s : acquired) {
		vkDestroySemaphore(device, s, nullptr);
	}
	framebuffers.clear();
	views.clear();
	render_done.clear();
	acquired.clear();
	images.clear();
	if (swapchain) {
		vkDestroySwapchainKHR(device, swapchain, nullptr);
		swapchain = VK_NULL_HANDLE;
	}
}

void SwapChainVK::wait_frame() {
	if (fence_pending) {
		vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
		vkResetFences(device, 1, &fence);
		fence_pending = false;
	}
}

void SwapChainVK::resize(int p_width, int p_height) {
	ERR_FAIL_COND_MSG(in_frame, "SwapChainVK::resize: not inside a frame.");
	wait_frame();
	_destroy_swapchain();
	extent.width = (uint32_t)std::max(0, p_width);
	extent.height = (uint32_t)std::max(0, p_height);
}

void SwapChainVK::wait_idle() {
	if (device) {
		vkDeviceWaitIdle(device);
	}
}

void SwapChainVK::destroy() {
	if (!device) {
		return;
	}
	_destroy_swapchain();
	_free_capture();
	if (fence) {
		vkDestroyFence(device, fence, nullptr);
		fence = VK_NULL_HANDLE;
	}
	if (command_pool) {
		vkDestroyCommandPool(device, command_pool, nullptr);
		command_pool = VK_NULL_HANDLE;
		command_buffer = VK_NULL_HANDLE;
	}
	if (render_pass) {
		vkDestroyRenderPass(device, render_pass, nullptr);
		render_pass = VK_NULL_HANDLE;
	}
	if (surface) {
		vkDestroySurfaceKHR(instance, surface, nullptr);
		surface = VK_NULL_HANDLE;
	}
	device = VK_NULL_HANDLE;
}

void SwapChainVK::_free_capture() {
	if (capture_buffer) {
		vkDestroyBuffer(device, capture_buffer, nullptr);
		vkFreeMemory(device, capture_memory, nullptr);
		capture_buffer = VK_NULL_HANDLE;
		capture_memory = VK_NULL_HANDLE;
	}
}

bool SwapChainVK::_create_host_buffer(VkDeviceSize p_size, VkBufferUsageFlags p_usage, VkBuffer &r_buffer, VkDeviceMemory &r_memory) {
	VkBufferCreateInfo bci = { VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO };
	bci.size = p_size;
	bci.usage = p_usage;
	bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
	ERR_FAIL_COND_V_MSG(vkCreateBuffer(device, &bci, nullptr, &r_buffer) != VK_SUCCESS, false, "SwapChainVK: cannot create a host buffer.");
	VkMemoryRequirements req;
	vkGetBufferMemoryRequirements(device, r_buffer, &req);
	VkPhysicalDeviceMemoryProperties mp;
	vkGetPhysicalDeviceMemoryProperties(physical_device, &mp);
	const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
	uint32_t type = UINT32_MAX;
	for (uint32_t i = 0; i < mp.memoryTypeCount; i++) {
		if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) {
			type = i;
			break;
		}
	}
	if (type == UINT32_MAX) {
		vkDestroyBuffer(device, r_buffer, nullptr);
		r_buffer = VK_NULL_HANDLE;
		ERR_FAIL_V_MSG(false, "SwapChainVK: no host-visible coherent memory for a host buffer.");
	}
	VkMemoryAllocateInfo mai = { VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO };
	mai.allocationSize = req.size;
	mai.memoryTypeIndex = type;
	vkAllocateMemory(device, &mai, nullptr, &r_memory);
	vkBindBufferMemory(device, r_buffer, r_memory, 0);
	return true;
}

bool SwapChainVK::capture_next_frame() {
	ERR_FAIL_COND_V_MSG(!can_capture, false, "SwapChainVK: this window's images cannot be read back.");
	capture_requested = true;
	return true;
}

VkCommandBuffer SwapChainVK::begin_frame(const Color &p_clear) {
	ERR_FAIL_COND_V_MSG(in_frame, VK_NULL_HANDLE, "SwapChainVK: begin_frame() called twice.");
	wait_frame();
	if (!swapchain) {
		String error;
		if (!_create_swapchain(&error) || !swapchain) {
			return VK_NULL_HANDLE;
		}
	}
	VkSemaphore sem = acquired[acquire_index];
	VkResult res = vkAcquireNextImageKHR(device, swapchain, UINT64_MAX, sem, VK_NULL_HANDLE, &image_index);
	if (res == VK_ERROR_OUT_OF_DATE_KHR) {
		_destroy_swapchain();
		return VK_NULL_HANDLE; // Recreated next frame.
	}
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS && res != VK_SUBOPTIMAL_KHR, VK_NULL_HANDLE, vformat("SwapChainVK: vkAcquireNextImageKHR failed (VkResult %d).", res));

	vkResetCommandBuffer(command_buffer, 0);
	VkCommandBufferBeginInfo bi = { VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO };
	bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
	vkBeginCommandBuffer(command_buffer, &bi);
	VkImageMemoryBarrier b = { VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER };
	b.srcAccessMask = 0;
	b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
	b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
	b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
	b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
	b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
	b.image = images[image_index];
	b.subresourceRange = { VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1 };
	vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
	VkClearColorValue clear = {};
	clear.float32[0] = p_clear.r;
	clear.float32[1] = p_clear.g;
	clear.float32[2] = p_clear.b;
	clear.float32[3] = p_clear.a;
	vkCmdClearColorImage(command_buffer, images[image_index], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &b.subresourceRange);
	// The clear before anything recorded next that writes the image.
	VkMemoryBarrier mb = { VK_STRUCTURE_TYPE_MEMORY_BARRIER };
	mb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
	mb.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
	vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &mb, 0, nullptr, 0, nullptr);
	in_frame = true;
	return command_buffer;
}

void SwapChainVK::begin_render_pass() {
	ERR_FAIL_COND_MSG(!in_frame || in_pass, "SwapChainVK::begin_render_pass: no frame, or already in the pass.");
	VkRenderPassBeginInfo rbi = { VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO };
	rbi.renderPass = render_pass;
	rbi.framebuffer = framebuffers[image_index];
	rbi.renderArea.extent = extent;
	vkCmdBeginRenderPass(command_buffer, &rbi, VK_SUBPASS_CONTENTS_INLINE);
	in_pass = true;
}

bool SwapChainVK::end_frame() {
	ERR_FAIL_COND_V_MSG(!in_frame, false, "SwapChainVK::end_frame: no frame.");
	if (!in_pass) {
		begin_render_pass();
	}
	vkCmdEndRenderPass(command_buffer);
	bool capturing = capture_requested && can_capture;
	capture_requested = false;
	if (capturing) {
		_free_capture();
		capturing = _create_host_buffer(VkDeviceSize(extent.width) * extent.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, capture_buffer, capture_memory);
	}
	if (capturing) {
		VkImageMemoryBarrier b = { VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER };
		b.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
		b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
		b.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
		b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
		b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
		b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
		b.image = images[image_index];
		b.subresourceRange = { VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1 };
		vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
		VkBufferImageCopy region = {};
		region.imageSubresource = { VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1 };
		region.imageExtent = { extent.width, extent.height, 1 };
		vkCmdCopyImageToBuffer(command_buffer, images[image_index], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, capture_buffer, 1, &region);
		b.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
		b.dstAccessMask = 0;
		b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
		b.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
		vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
		VkMemoryBarrier hb = { VK_STRUCTURE_TYPE_MEMORY_BARRIER };
		hb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
		hb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
		vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &hb, 0, nullptr, 0, nullptr);
	}
	vkEndCommandBuffer(command_buffer);
	in_pass = false;
	in_frame = false;
	VkSemaphore wait = acquired[acquire_index];
	acquire_index = (acquire_index + 1) % (uint32_t)acquired.size();
	VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
	VkSubmitInfo si = { VK_STRUCTURE_TYPE_SUBMIT_INFO };
	si.waitSemaphoreCount = 1;
	si.pWaitSemaphores = &wait;
	si.pWaitDstStageMask = &wait_stage;
	si.commandBufferCount = 1;
	si.pCommandBuffers = &command_buffer;
	si.signalSemaphoreCount = 1;
	si.pSignalSemaphores = &render_done[image_index];
	VkResult res = vkQueueSubmit(queue, 1, &si, fence);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("SwapChainVK: vkQueueSubmit failed (VkResult %d).", res));
	fence_pending = true;
	if (capturing) {
		vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
		void *map = nullptr;
		vkMapMemory(device, capture_memory, 0, VK_WHOLE_SIZE, 0, &map);
		const uint8_t *src = (const uint8_t *)map;
		capture_rgba.resize(size_t(extent.width) * extent.height * 4);
		for (size_t i = 0; i < capture_rgba.size(); i += 4) {
			capture_rgba[i + 0] = src[i + (bgra ? 2 : 0)];
			capture_rgba[i + 1] = src[i + 1];
			capture_rgba[i + 2] = src[i + (bgra ? 0 : 2)];
			capture_rgba[i + 3] = 255;
		}
		vkUnmapMemory(device, capture_memory);
	}
	VkPresentInfoKHR pi = { VK_STRUCTURE_TYPE_PRESENT_INFO_KHR };
	pi.waitSemaphoreCount = 1;
	pi.pWaitSemaphores = &render_done[image_index];
	pi.swapchainCount = 1;
	pi.pSwapchains = &swapchain;
	pi.pImageIndices = &image_index;
	res = vkQueuePresentKHR(queue, &pi);
	if (res == VK_ERROR_OUT_OF_DATE_KHR || res == VK_SUBOPTIMAL_KHR) {
		_destroy_swapchain();
		return res == VK_SUBOPTIMAL_KHR;
	}
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("SwapChainVK: vkQueuePresentKHR failed (VkResult %d).", res));
	return true;
}
