/**************************************************************************/
/*  rendering_device_resources.cpp                                        */
/**************************************************************************/
/* RenderingDevice buffers, textures and samplers (creation, updates,     */
/* readback). Split from rendering_device.cpp; device setup, frames and   */
/* freeing stay there.                                                    */

#include "servers/rendering/rendering_device.h"

#include "servers/rendering/rendering_device_impl.h"

#include <algorithm>
#include <cstring>

typedef RenderingDevice::Impl RDImpl;
/*****************/
/**** BUFFERS ****/
/*****************/

RID RDImpl::buffer_create(Buffer::Kind p_kind, uint32_t p_size, VkBufferUsageFlags p_usage, const void *p_data) {
	ERR_FAIL_COND_V_MSG(!initialized, RID(), "RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(p_size == 0, RID(), "Buffer size must be greater than zero.");
	ERR_FAIL_COND_V_MSG(list.active, RID(), "Buffers with contents cannot be created while a draw or compute list is open.");
	Buffer b;
	b.kind = p_kind;
	b.size = p_size;
	if (!create_buffer(p_size, p_usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, b.buffer, b.memory)) {
		return RID();
	}
	if (p_data) {
		upload_to_buffer(b.buffer, 0, p_size, p_data);
	} else {
		full_barrier();
		vkCmdFillBuffer(command_buffer, b.buffer, 0, VK_WHOLE_SIZE, 0);
		full_barrier();
	}
	return buffer_owner.make_rid(b);
}

RID RenderingDevice::storage_buffer_create(uint32_t p_size, const void *p_data, uint32_t p_usage) {
	return impl->buffer_create(Impl::Buffer::KIND_STORAGE, p_size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, p_data);
}

RID RenderingDevice::uniform_buffer_create(uint32_t p_size, const void *p_data) {
	ERR_FAIL_COND_V_MSG(impl->initialized && p_size > impl->properties.limits.maxUniformBufferRange, RID(), vformat("Uniform buffer size %u exceeds the device limit %u.", p_size, impl->properties.limits.maxUniformBufferRange));
	return impl->buffer_create(Impl::Buffer::KIND_UNIFORM, p_size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, p_data);
}

RID RenderingDevice::vertex_buffer_create(uint32_t p_size, const void *p_data) {
	return impl->buffer_create(Impl::Buffer::KIND_VERTEX, p_size, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, p_data);
}

RID RenderingDevice::index_buffer_create(uint32_t p_index_count, IndexBufferFormat p_format, const void *p_data) {
	ERR_FAIL_COND_V_MSG(p_format != INDEX_BUFFER_FORMAT_UINT16 && p_format != INDEX_BUFFER_FORMAT_UINT32, RID(), "Invalid index buffer format.");
	uint32_t size = p_index_count * (p_format == INDEX_BUFFER_FORMAT_UINT16 ? 2 : 4);
	// Keep the size a multiple of 4 (fills and copies want it).
	uint32_t alloc = (size + 3) & ~3u;
	std::vector<uint8_t> padded;
	const void *data = p_data;
	if (p_data && alloc != size) {
		padded.assign(alloc, 0);
		memcpy(padded.data(), p_data, size);
		data = padded.data();
	}
	RID rid = impl->buffer_create(Impl::Buffer::KIND_INDEX, alloc, VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, data);
	Impl::Buffer *b = impl->buffer_owner.get_or_null(rid);
	if (b) {
		b->index_format = p_format;
		b->index_count = p_index_count;
	}
	return rid;
}

bool RenderingDevice::buffer_update(RID p_buffer, uint32_t p_offset, uint32_t p_size, const void *p_data) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, false, "buffer_update is not allowed while a draw or compute list is open.");
	Impl::Buffer *b = s->buffer_owner.get_or_null(p_buffer);
	ERR_FAIL_NULL_V_MSG(b, false, "buffer_update: invalid buffer RID.");
	ERR_FAIL_NULL_V_MSG(p_data, false, "buffer_update: data is null.");
	ERR_FAIL_COND_V_MSG(p_size == 0, false, "buffer_update: size is zero.");
	ERR_FAIL_COND_V_MSG((uint64_t)p_offset + p_size > b->size, false, vformat("buffer_update: range [%u, %u) exceeds the buffer size %u.", p_offset, p_offset + p_size, b->size));
	s->upload_to_buffer(b->buffer, p_offset, p_size, p_data);
	return true;
}

bool RenderingDevice::buffer_clear(RID p_buffer, uint32_t p_offset, uint32_t p_size) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, false, "buffer_clear is not allowed while a draw or compute list is open.");
	Impl::Buffer *b = s->buffer_owner.get_or_null(p_buffer);
	ERR_FAIL_NULL_V_MSG(b, false, "buffer_clear: invalid buffer RID.");
	ERR_FAIL_COND_V_MSG((p_offset % 4) != 0 || (p_size % 4) != 0, false, "buffer_clear: offset and size must be multiples of 4.");
	ERR_FAIL_COND_V_MSG(p_size == 0 || (uint64_t)p_offset + p_size > b->size, false, "buffer_clear: range is empty or out of bounds.");
	s->full_barrier();
	vkCmdFillBuffer(s->command_buffer, b->buffer, p_offset, p_size, 0);
	s->full_barrier();
	return true;
}

bool RenderingDevice::buffer_copy(RID p_src, RID p_dst, uint32_t p_src_offset, uint32_t p_dst_offset, uint32_t p_size) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, false, "buffer_copy is not allowed while a draw or compute list is open.");
	Impl::Buffer *src = s->buffer_owner.get_or_null(p_src);
	Impl::Buffer *dst = s->buffer_owner.get_or_null(p_dst);
	ERR_FAIL_NULL_V_MSG(src, false, "buffer_copy: invalid source buffer.");
	ERR_FAIL_NULL_V_MSG(dst, false, "buffer_copy: invalid destination buffer.");
	ERR_FAIL_COND_V_MSG(p_size == 0 || (uint64_t)p_src_offset + p_size > src->size || (uint64_t)p_dst_offset + p_size > dst->size, false, "buffer_copy: range is empty or out of bounds.");
	ERR_FAIL_COND_V_MSG(p_src == p_dst, false, "buffer_copy: source and destination must differ.");
	s->full_barrier();
	VkBufferCopy region = { p_src_offset, p_dst_offset, p_size };
	vkCmdCopyBuffer(s->command_buffer, src->buffer, dst->buffer, 1, &region);
	s->full_barrier();
	return true;
}

std::vector<uint8_t> RenderingDevice::buffer_get_data(RID p_buffer, uint32_t p_offset, uint32_t p_size) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, std::vector<uint8_t>(), "buffer_get_data is not allowed while a draw or compute list is open.");
	Impl::Buffer *b = s->buffer_owner.get_or_null(p_buffer);
	ERR_FAIL_NULL_V_MSG(b, std::vector<uint8_t>(), "buffer_get_data: invalid buffer RID.");
	ERR_FAIL_COND_V_MSG(p_offset >= b->size, std::vector<uint8_t>(), "buffer_get_data: offset out of bounds.");
	uint32_t size = p_size == 0 ? b->size - p_offset : p_size;
	ERR_FAIL_COND_V_MSG((uint64_t)p_offset + size > b->size, std::vector<uint8_t>(), "buffer_get_data: range out of bounds.");
	s->ensure_recording();
	Impl::Staging st = s->create_staging(size);
	ERR_FAIL_COND_V(!st.buffer, std::vector<uint8_t>());
	s->full_barrier();
	VkBufferCopy region = { p_offset, 0, size };
	vkCmdCopyBuffer(s->command_buffer, b->buffer, st.buffer, 1, &region);
	host_read_barrier(s->command_buffer);
	submit();
	sync();
	std::vector<uint8_t> out(size);
	memcpy(out.data(), st.mapped, size);
	destroy_staging(s->device, st);
	return out;
}

bool RenderingDevice::buffer_get_data_async(RID p_buffer, const std::function<void(const std::vector<uint8_t> &)> &p_callback, uint32_t p_offset, uint32_t p_size) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!p_callback, false, "buffer_get_data_async: no callback.");
	ERR_FAIL_COND_V_MSG(s->list.active, false, "buffer_get_data_async is not allowed while a draw or compute list is open.");
	Impl::Buffer *b = s->buffer_owner.get_or_null(p_buffer);
	ERR_FAIL_NULL_V_MSG(b, false, "buffer_get_data_async: invalid buffer RID.");
	ERR_FAIL_COND_V_MSG(p_offset >= b->size, false, "buffer_get_data_async: offset out of bounds.");
	uint32_t size = p_size == 0 ? b->size - p_offset : p_size;
	ERR_FAIL_COND_V_MSG((uint64_t)p_offset + size > b->size, false, "buffer_get_data_async: range out of bounds.");
	s->ensure_recording();
	Impl::Readback r;
	r.staging = s->acquire_readback_staging(size);
	ERR_FAIL_COND_V(!r.staging.buffer, false);
	r.size = size;
	r.callback = p_callback;
	s->full_barrier();
	VkBufferCopy region = { p_offset, 0, size };
	vkCmdCopyBuffer(s->command_buffer, b->buffer, r.staging.buffer, 1, &region);
	host_read_barrier(s->command_buffer);
	s->current_frame().readbacks.push_back(std::move(r));
	return true;
}

uint32_t RenderingDevice::buffer_get_size(RID p_buffer) const {
	Impl::Buffer *b = impl->buffer_owner.get_or_null(p_buffer);
	ERR_FAIL_NULL_V_MSG(b, 0, "buffer_get_size: invalid buffer RID.");
	return b->size;
}

/******************/
/**** TEXTURES ****/
/******************/

static VkImageUsageFlags texture_usage_to_vk(uint32_t p_bits) {
	VkImageUsageFlags u = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
	if (p_bits & RenderingDevice::TEXTURE_USAGE_SAMPLING_BIT) {
		u |= VK_IMAGE_USAGE_SAMPLED_BIT;
	}
	if (p_bits & RenderingDevice::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT) {
		u |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
	}
	if (p_bits & RenderingDevice::TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) {
		u |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
	}
	if (p_bits & RenderingDevice::TEXTURE_USAGE_STORAGE_BIT) {
		u |= VK_IMAGE_USAGE_STORAGE_BIT;
	}
	return u;
}

static void copy_texture_layer(RDImpl *s, RDImpl::Texture *t, uint32_t p_layer, VkBuffer p_buffer, VkDeviceSize p_buffer_offset, bool p_to_texture) {
	VkBufferImageCopy region = {};
	region.bufferOffset = p_buffer_offset;
	region.imageSubresource.aspectMask = t->aspect;
	region.imageSubresource.mipLevel = t->base_mip;
	region.imageSubresource.baseArrayLayer = t->base_layer + p_layer;
	region.imageSubresource.layerCount = 1;
	region.imageExtent = { t->format.width, t->format.height, t->format.depth };
	s->full_barrier();
	if (p_to_texture) {
		vkCmdCopyBufferToImage(s->command_buffer, p_buffer, t->image, VK_IMAGE_LAYOUT_GENERAL, 1, &region);
		s->full_barrier();
	} else {
		vkCmdCopyImageToBuffer(s->command_buffer, t->image, VK_IMAGE_LAYOUT_GENERAL, p_buffer, 1, &region);
		host_read_barrier(s->command_buffer);
	}
}

RID RenderingDevice::texture_create(const TextureFormat &p_format, const std::vector<std::vector<uint8_t>> &p_data) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, RID(), "RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(s->list.active, RID(), "Textures cannot be created while a draw or compute list is open.");
	ERR_FAIL_COND_V_MSG(p_format.format < 0 || p_format.format >= DATA_FORMAT_MAX, RID(), "texture_create: invalid data format.");
	ERR_FAIL_COND_V_MSG(p_format.format == DATA_FORMAT_R32G32B32_SFLOAT, RID(), "texture_create: R32G32B32_SFLOAT is a vertex-only format.");
	ERR_FAIL_COND_V_MSG(p_format.width == 0 || p_format.height == 0 || p_format.depth == 0 || p_format.array_layers == 0 || p_format.mipmaps == 0, RID(), "texture_create: width, height, depth, layers and mipmaps must be at least 1.");
	const VkPhysicalDeviceLimits &lim = s->properties.limits;
	ERR_FAIL_COND_V_MSG(p_format.width > lim.maxImageDimension2D || p_format.height > lim.maxImageDimension2D, RID(), vformat("texture_create: %ux%u exceeds the device limit %u.", p_format.width, p_format.height, lim.maxImageDimension2D));
	ERR_FAIL_COND_V_MSG(p_format.array_layers > lim.maxImageArrayLayers, RID(), "texture_create: too many array layers.");
	TextureType tt = p_format.texture_type;
	ERR_FAIL_COND_V_MSG(tt < TEXTURE_TYPE_2D || tt > TEXTURE_TYPE_3D, RID(), "texture_create: invalid texture type.");
	ERR_FAIL_COND_V_MSG(tt == TEXTURE_TYPE_2D && p_format.array_layers != 1, RID(), "texture_create: TEXTURE_TYPE_2D needs array_layers == 1 (use TEXTURE_TYPE_2D_ARRAY).");
	ERR_FAIL_COND_V_MSG(tt == TEXTURE_TYPE_CUBE && p_format.array_layers != 6, RID(), "texture_create: cube textures need 6 layers.");
	ERR_FAIL_COND_V_MSG(tt == TEXTURE_TYPE_CUBE_ARRAY && (p_format.array_layers % 6) != 0, RID(), "texture_create: cube array layers must be a multiple of 6.");
	ERR_FAIL_COND_V_MSG((tt == TEXTURE_TYPE_CUBE || tt == TEXTURE_TYPE_CUBE_ARRAY) && p_format.width != p_format.height, RID(), "texture_create: cube textures must be square.");
	ERR_FAIL_COND_V_MSG(tt == TEXTURE_TYPE_CUBE_ARRAY && !s->enabled_features.imageCubeArray, RID(), "texture_create: cube arrays are not supported by this device.");
	ERR_FAIL_COND_V_MSG(tt == TEXTURE_TYPE_3D && p_format.array_layers != 1, RID(), "texture_create: 3D textures have one layer.");
	ERR_FAIL_COND_V_MSG(tt != TEXTURE_TYPE_3D && p_format.depth != 1, RID(), "texture_create: depth must be 1 unless TEXTURE_TYPE_3D.");
	bool depth = is_depth_format(p_format.format);
	ERR_FAIL_COND_V_MSG(depth && (p_format.usage_bits & (TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | TEXTURE_USAGE_STORAGE_BIT)), RID(), "texture_create: depth formats cannot be colour attachments or storage images.");
	ERR_FAIL_COND_V_MSG(!depth && (p_format.usage_bits & TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT), RID(), "texture_create: depth attachment usage needs a depth format.");
	uint32_t max_mips = 1;
	for (uint32_t d = std::max(p_format.width, p_format.height); d > 1; d >>= 1) {
		max_mips++;
	}
	ERR_FAIL_COND_V_MSG(p_format.mipmaps > max_mips, RID(), vformat("texture_create: %u mipmaps requested, at most %u possible.", p_format.mipmaps, max_mips));

	VkFormat vkf = Impl::to_vk_format(p_format.format);
	VkImageUsageFlags usage = texture_usage_to_vk(p_format.usage_bits);
	VkImageType image_type = tt == TEXTURE_TYPE_3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
	VkImageCreateFlags flags = (tt == TEXTURE_TYPE_CUBE || tt == TEXTURE_TYPE_CUBE_ARRAY) ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
	VkImageFormatProperties ifp;
	VkResult res = vkGetPhysicalDeviceImageFormatProperties(s->physical_device, vkf, image_type, VK_IMAGE_TILING_OPTIMAL, usage, flags, &ifp);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("texture_create: format %s is not supported with the requested usage (0x%x) on this device.", get_format_name(p_format.format), p_format.usage_bits));

	uint32_t layer_size = p_format.width * p_format.height * p_format.depth * get_format_size(p_format.format);
	ERR_FAIL_COND_V_MSG(!p_data.empty() && p_data.size() != p_format.array_layers, RID(), vformat("texture_create: %zu data layers given, texture has %u.", p_data.size(), p_format.array_layers));
	for (const std::vector<uint8_t> &layer : p_data) {
		ERR_FAIL_COND_V_MSG(layer.size() != layer_size, RID(), vformat("texture_create: layer data is %zu bytes, expected %u.", layer.size(), layer_size));
	}

	Impl::Texture t;
	t.format = p_format;
	t.aspect = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
	VkImageCreateInfo ici = { VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO };
	ici.flags = flags;
	ici.imageType = image_type;
	ici.format = vkf;
	ici.extent = { p_format.width, p_format.height, p_format.depth };
	ici.mipLevels = p_format.mipmaps;
	ici.arrayLayers = p_format.array_layers;
	ici.samples = VK_SAMPLE_COUNT_1_BIT;
	ici.tiling = VK_IMAGE_TILING_OPTIMAL;
	ici.usage = usage;
	ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
	ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
	res = vkCreateImage(s->device, &ici, nullptr, &t.image);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateImage failed (VkResult %d).", res));
	VkMemoryRequirements req;
	vkGetImageMemoryRequirements(s->device, t.image, &req);
	int32_t type = s->find_memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
	if (type < 0) {
		type = s->find_memory_type(req.memoryTypeBits, 0);
	}
	VkMemoryAllocateInfo ai = { VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO };
	ai.allocationSize = req.size;
	ai.memoryTypeIndex = (uint32_t)std::max(type, 0);
	res = type < 0 ? VK_ERROR_OUT_OF_DEVICE_MEMORY : vkAllocateMemory(s->device, &ai, nullptr, &t.memory);
	if (res != VK_SUCCESS) {
		vkDestroyImage(s->device, t.image, nullptr);
		ERR_FAIL_V_MSG(RID(), vformat("Could not allocate %llu bytes for a texture (VkResult %d).", (unsigned long long)req.size, res));
	}
	vkBindImageMemory(s->device, t.image, t.memory, 0);

	VkImageViewCreateInfo vci = { VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO };
	vci.image = t.image;
	static const VkImageViewType view_types[] = { VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_VIEW_TYPE_2D_ARRAY, VK_IMAGE_VIEW_TYPE_CUBE, VK_IMAGE_VIEW_TYPE_CUBE_ARRAY, VK_IMAGE_VIEW_TYPE_3D };
	vci.viewType = view_types[tt];
	vci.format = vkf;
	vci.subresourceRange = { t.aspect, 0, p_format.mipmaps, 0, p_format.array_layers };
	res = vkCreateImageView(s->device, &vci, nullptr, &t.view);
	if (res != VK_SUCCESS) {
		vkDestroyImage(s->device, t.image, nullptr);
		vkFreeMemory(s->device, t.memory, nullptr);
		ERR_FAIL_V_MSG(RID(), vformat("vkCreateImageView failed (VkResult %d).", res));
	}

	// Move to GENERAL once and for all, then zero it.
	s->ensure_recording();
	VkImageMemoryBarrier ib = { VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER };
	ib.srcAccessMask = 0;
	ib.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
	ib.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
	ib.newLayout = VK_IMAGE_LAYOUT_GENERAL;
	ib.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
	ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
	ib.image = t.image;
	ib.subresourceRange = vci.subresourceRange;
	vkCmdPipelineBarrier(s->command_buffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0, nullptr, 1, &ib);
	if (depth) {
		VkClearDepthStencilValue cv = { 0.0f, 0 };
		vkCmdClearDepthStencilImage(s->command_buffer, t.image, VK_IMAGE_LAYOUT_GENERAL, &cv, 1, &vci.subresourceRange);
	} else {
		VkClearColorValue cv = {};
		vkCmdClearColorImage(s->command_buffer, t.image, VK_IMAGE_LAYOUT_GENERAL, &cv, 1, &vci.subresourceRange);
	}
	s->full_barrier();

	RID rid = s->texture_owner.make_rid(t);
	Impl::Texture *tp = s->texture_owner.get_or_null(rid);
	for (uint32_t i = 0; i < p_data.size(); i++) {
		VkBuffer src;
		VkDeviceSize src_offset;
		if (s->stage_data(p_data[i].data(), layer_size, src, src_offset)) {
			copy_texture_layer(s, tp, i, src, src_offset, true);
		}
	}
	return rid;
}

RID RenderingDevice::texture_create_shared_from_slice(RID p_texture, uint32_t p_layer, uint32_t p_mipmap) {
	Impl *s = impl;
	Impl::Texture *parent = s->texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(parent, RID(), "texture_create_shared_from_slice: invalid texture RID.");
	ERR_FAIL_COND_V_MSG(parent->is_slice, RID(), "texture_create_shared_from_slice: cannot slice a slice; slice the original texture.");
	ERR_FAIL_COND_V_MSG(parent->format.texture_type == TEXTURE_TYPE_3D, RID(), "texture_create_shared_from_slice: 3D textures cannot be sliced.");
	ERR_FAIL_INDEX_V_MSG((int64_t)p_layer, (int64_t)parent->format.array_layers, RID(), "texture_create_shared_from_slice: layer out of range.");
	ERR_FAIL_INDEX_V_MSG((int64_t)p_mipmap, (int64_t)parent->format.mipmaps, RID(), "texture_create_shared_from_slice: mipmap out of range.");
	Impl::Texture t;
	t.image = parent->image;
	t.is_slice = true;
	t.parent = p_texture;
	t.aspect = parent->aspect;
	t.base_layer = p_layer;
	t.base_mip = p_mipmap;
	t.format = parent->format;
	t.format.texture_type = TEXTURE_TYPE_2D;
	t.format.array_layers = 1;
	t.format.mipmaps = 1;
	t.format.width = std::max(1u, parent->format.width >> p_mipmap);
	t.format.height = std::max(1u, parent->format.height >> p_mipmap);
	VkImageViewCreateInfo vci = { VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO };
	vci.image = t.image;
	vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
	vci.format = Impl::to_vk_format(parent->format.format);
	vci.subresourceRange = { t.aspect, p_mipmap, 1, p_layer, 1 };
	VkResult res = vkCreateImageView(s->device, &vci, nullptr, &t.view);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateImageView failed (VkResult %d).", res));
	RID rid = s->texture_owner.make_rid(t);
	s->add_dependency(p_texture, rid);
	return rid;
}

bool RenderingDevice::texture_update(RID p_texture, uint32_t p_layer, const std::vector<uint8_t> &p_data) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, false, "texture_update is not allowed while a draw or compute list is open.");
	Impl::Texture *t = s->texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, false, "texture_update: invalid texture RID.");
	ERR_FAIL_INDEX_V_MSG((int64_t)p_layer, (int64_t)t->format.array_layers, false, "texture_update: layer out of range.");
	uint32_t layer_size = t->format.width * t->format.height * t->format.depth * get_format_size(t->format.format);
	ERR_FAIL_COND_V_MSG(p_data.size() != layer_size, false, vformat("texture_update: data is %zu bytes, expected %u.", p_data.size(), layer_size));
	VkBuffer src;
	VkDeviceSize src_offset;
	ERR_FAIL_COND_V(!s->stage_data(p_data.data(), layer_size, src, src_offset), false);
	copy_texture_layer(s, t, p_layer, src, src_offset, true);
	return true;
}

bool RenderingDevice::texture_clear(RID p_texture, const Color &p_color, uint32_t p_base_mipmap, uint32_t p_mipmaps, uint32_t p_base_layer, uint32_t p_layers) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, false, "texture_clear is not allowed while a draw or compute list is open.");
	Impl::Texture *t = s->texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, false, "texture_clear: invalid texture RID.");
	ERR_FAIL_COND_V_MSG(p_mipmaps == 0 || p_layers == 0, false, "texture_clear: empty range.");
	ERR_FAIL_COND_V_MSG(p_base_mipmap + p_mipmaps > t->format.mipmaps || p_base_layer + p_layers > t->format.array_layers, false, "texture_clear: range out of bounds.");
	VkImageSubresourceRange range = { t->aspect, t->base_mip + p_base_mipmap, p_mipmaps, t->base_layer + p_base_layer, p_layers };
	s->full_barrier();
	if (t->aspect == VK_IMAGE_ASPECT_DEPTH_BIT) {
		VkClearDepthStencilValue cv = { p_color.r, 0 };
		vkCmdClearDepthStencilImage(s->command_buffer, t->image, VK_IMAGE_LAYOUT_GENERAL, &cv, 1, &range);
	} else {
		VkClearColorValue cv;
		DataFormat f = t->format.format;
		if (f == DATA_FORMAT_R32_UINT || f == DATA_FORMAT_R32G32_UINT || f == DATA_FORMAT_R32G32B32A32_UINT) {
			cv.uint32[0] = (uint32_t)p_color.r;
			cv.uint32[1] = (uint32_t)p_color.g;
			cv.uint32[2] = (uint32_t)p_color.b;
			cv.uint32[3] = (uint32_t)p_color.a;
		} else if (f == DATA_FORMAT_R32_SINT) {
			cv.int32[0] = (int32_t)p_color.r;
			cv.int32[1] = (int32_t)p_color.g;
			cv.int32[2] = (int32_t)p_color.b;
			cv.int32[3] = (int32_t)p_color.a;
		} else {
			cv.float32[0] = p_color.r;
			cv.float32[1] = p_color.g;
			cv.float32[2] = p_color.b;
			cv.float32[3] = p_color.a;
		}
		vkCmdClearColorImage(s->command_buffer, t->image, VK_IMAGE_LAYOUT_GENERAL, &cv, 1, &range);
	}
	s->full_barrier();
	return true;
}

std::vector<uint8_t> RenderingDevice::texture_get_data(RID p_texture, uint32_t p_layer) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(s->list.active, std::vector<uint8_t>(), "texture_get_data is not allowed while a draw or compute list is open.");
	Impl::Texture *t = s->texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, std::vector<uint8_t>(), "texture_get_data: invalid texture RID.");
	ERR_FAIL_INDEX_V_MSG((int64_t)p_layer, (int64_t)t->format.array_layers, std::vector<uint8_t>(), "texture_get_data: layer out of range.");
	uint32_t layer_size = t->format.width * t->format.height * t->format.depth * get_format_size(t->format.format);
	s->ensure_recording();
	Impl::Staging st = s->create_staging(layer_size);
	ERR_FAIL_COND_V(!st.buffer, std::vector<uint8_t>());
	copy_texture_layer(s, t, p_layer, st.buffer, 0, false);
	submit();
	sync();
	std::vector<uint8_t> out(layer_size);
	memcpy(out.data(), st.mapped, layer_size);
	destroy_staging(s->device, st);
	return out;
}

bool RenderingDevice::texture_is_valid(RID p_texture) const {
	return impl->texture_owner.owns(p_texture) && impl->texture_owner.get_or_null(p_texture) != nullptr;
}

uint64_t RenderingDevice::get_driver_resource(DriverResource p_resource, RID p_rid) const {
	Impl::Texture *t = impl->texture_owner.get_or_null(p_rid);
	ERR_FAIL_NULL_V_MSG(t, 0, "get_driver_resource: invalid texture RID.");
	return p_resource == DRIVER_RESOURCE_TEXTURE ? (uint64_t)t->image : (uint64_t)t->view;
}

RenderingDevice::TextureFormat RenderingDevice::texture_get_format(RID p_texture) const {
	Impl::Texture *t = impl->texture_owner.get_or_null(p_texture);
	ERR_FAIL_NULL_V_MSG(t, TextureFormat(), "texture_get_format: invalid texture RID.");
	return t->format;
}

/******************/
/**** SAMPLERS ****/
/******************/

RID RenderingDevice::sampler_create(const SamplerState &p_state) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, RID(), "RenderingDevice is not initialized.");
	static const VkSamplerAddressMode modes[] = { VK_SAMPLER_ADDRESS_MODE_REPEAT, VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER };
	static const VkBorderColor borders[] = { VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK, VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK, VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE };
	ERR_FAIL_COND_V_MSG(p_state.repeat_u < 0 || p_state.repeat_u > SAMPLER_REPEAT_MODE_CLAMP_TO_BORDER || p_state.repeat_v < 0 || p_state.repeat_v > SAMPLER_REPEAT_MODE_CLAMP_TO_BORDER || p_state.repeat_w < 0 || p_state.repeat_w > SAMPLER_REPEAT_MODE_CLAMP_TO_BORDER, RID(), "sampler_create: invalid repeat mode.");
	ERR_FAIL_COND_V_MSG(p_state.border_color < 0 || p_state.border_color > SAMPLER_BORDER_COLOR_FLOAT_OPAQUE_WHITE, RID(), "sampler_create: invalid border colour.");
	ERR_FAIL_COND_V_MSG(p_state.min_lod > p_state.max_lod, RID(), "sampler_create: min_lod is greater than max_lod.");
	VkSamplerCreateInfo ci = { VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO };
	ci.magFilter = p_state.mag_filter == SAMPLER_FILTER_LINEAR ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
	ci.minFilter = p_state.min_filter == SAMPLER_FILTER_LINEAR ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
	ci.mipmapMode = p_state.mip_filter == SAMPLER_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
	ci.addressModeU = modes[p_state.repeat_u];
	ci.addressModeV = modes[p_state.repeat_v];
	ci.addressModeW = modes[p_state.repeat_w];
	ci.mipLodBias = std::min(std::max(p_state.lod_bias, -s->properties.limits.maxSamplerLodBias), s->properties.limits.maxSamplerLodBias);
	ci.compareEnable = p_state.enable_compare ? VK_TRUE : VK_FALSE;
	ci.compareOp = Impl::to_vk_compare(p_state.compare_op);
	ci.minLod = p_state.min_lod;
	ci.maxLod = p_state.max_lod;
	ci.borderColor = borders[p_state.border_color];
	Impl::Sampler smp;
	VkResult res = vkCreateSampler(s->device, &ci, nullptr, &smp.sampler);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateSampler failed (VkResult %d).", res));
	return s->sampler_owner.make_rid(smp);
}
