/**************************************************************************/
/*  rendering_device.cpp                                                  */
/**************************************************************************/
/* Singleton, formats, staging, timestamps, freeing, debug names. Frames  */
/* in flight live in rendering_device_frames.cpp.                         */
/* Instance/device creation and teardown live in                          */
/* rendering_device_setup.cpp; buffers, textures and samplers in          */
/* rendering_device_resources.cpp,                                        */
/* Shaders/pipelines live in rendering_device_pipelines.cpp, draw and     */
/* compute lists in rendering_device_lists.cpp.                           */

#include "servers/rendering/rendering_device.h"

#include "servers/rendering/rendering_device_impl.h"

#include <algorithm>
#include <cstring>

RenderingDevice *RenderingDevice::singleton = nullptr;

typedef RenderingDevice::Impl RDImpl;

/**************************/
/**** STATIC FORMAT INFO ***/
/**************************/

namespace {

struct FormatInfo {
	VkFormat vk;
	uint32_t size;
	const char *name;
};

const FormatInfo format_infos[RenderingDevice::DATA_FORMAT_MAX] = {
	{ VK_FORMAT_R8_UNORM, 1, "R8_UNORM" },
	{ VK_FORMAT_R8G8_UNORM, 2, "R8G8_UNORM" },
	{ VK_FORMAT_R8G8B8A8_UNORM, 4, "R8G8B8A8_UNORM" },
	{ VK_FORMAT_R8G8B8A8_SRGB, 4, "R8G8B8A8_SRGB" },
	{ VK_FORMAT_R16_SFLOAT, 2, "R16_SFLOAT" },
	{ VK_FORMAT_R16G16_SFLOAT, 4, "R16G16_SFLOAT" },
	{ VK_FORMAT_R16G16B16A16_SFLOAT, 8, "R16G16B16A16_SFLOAT" },
	{ VK_FORMAT_R32_SFLOAT, 4, "R32_SFLOAT" },
	{ VK_FORMAT_R32G32_SFLOAT, 8, "R32G32_SFLOAT" },
	{ VK_FORMAT_R32G32B32_SFLOAT, 12, "R32G32B32_SFLOAT" },
	{ VK_FORMAT_R32G32B32A32_SFLOAT, 16, "R32G32B32A32_SFLOAT" },
	{ VK_FORMAT_R32_UINT, 4, "R32_UINT" },
	{ VK_FORMAT_R32G32_UINT, 8, "R32G32_UINT" },
	{ VK_FORMAT_R32G32B32A32_UINT, 16, "R32G32B32A32_UINT" },
	{ VK_FORMAT_R32_SINT, 4, "R32_SINT" },
	{ VK_FORMAT_D16_UNORM, 2, "D16_UNORM" },
	{ VK_FORMAT_D32_SFLOAT, 4, "D32_SFLOAT" },
};

} // namespace

uint32_t RenderingDevice::get_format_size(DataFormat p_format) {
	if (p_format < 0 || p_format >= DATA_FORMAT_MAX) {
		return 0;
	}
	return format_infos[p_format].size;
}

bool RenderingDevice::is_depth_format(DataFormat p_format) {
	return p_format == DATA_FORMAT_D16_UNORM || p_format == DATA_FORMAT_D32_SFLOAT;
}

const char *RenderingDevice::get_format_name(DataFormat p_format) {
	if (p_format < 0 || p_format >= DATA_FORMAT_MAX) {
		return "INVALID";
	}
	return format_infos[p_format].name;
}

const char *RenderingDevice::get_shader_stage_name(ShaderStage p_stage) {
	switch (p_stage) {
		case SHADER_STAGE_VERTEX:
			return "vertex";
		case SHADER_STAGE_FRAGMENT:
			return "fragment";
		case SHADER_STAGE_COMPUTE:
			return "compute";
		default:
			return "invalid";
	}
}

VkFormat RDImpl::to_vk_format(DataFormat p_format) {
	if (p_format < 0 || p_format >= DATA_FORMAT_MAX) {
		return VK_FORMAT_UNDEFINED;
	}
	return format_infos[p_format].vk;
}

VkCompareOp RDImpl::to_vk_compare(CompareOperator p_op) {
	static const VkCompareOp ops[] = { VK_COMPARE_OP_NEVER, VK_COMPARE_OP_LESS, VK_COMPARE_OP_EQUAL, VK_COMPARE_OP_LESS_OR_EQUAL, VK_COMPARE_OP_GREATER, VK_COMPARE_OP_NOT_EQUAL, VK_COMPARE_OP_GREATER_OR_EQUAL, VK_COMPARE_OP_ALWAYS };
	if (p_op < 0 || p_op > COMPARE_OP_ALWAYS) {
		return VK_COMPARE_OP_ALWAYS;
	}
	return ops[p_op];
}

/*****************/
/**** HELPERS ****/
/*****************/

int32_t RDImpl::find_memory_type(uint32_t p_type_bits, VkMemoryPropertyFlags p_flags) const {
	for (uint32_t i = 0; i < memory_properties.memoryTypeCount; i++) {
		if ((p_type_bits & (1u << i)) && (memory_properties.memoryTypes[i].propertyFlags & p_flags) == p_flags) {
			return (int32_t)i;
		}
	}
	return -1;
}

bool RDImpl::create_buffer(VkDeviceSize p_size, VkBufferUsageFlags p_usage, VkMemoryPropertyFlags p_flags, VkBuffer &r_buffer, VkDeviceMemory &r_memory) {
	VkBufferCreateInfo ci = { VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO };
	ci.size = p_size;
	ci.usage = p_usage;
	ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
	VkResult res = vkCreateBuffer(device, &ci, nullptr, &r_buffer);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("vkCreateBuffer failed (%d) for %llu bytes.", res, (unsigned long long)p_size));
	VkMemoryRequirements req;
	vkGetBufferMemoryRequirements(device, r_buffer, &req);
	int32_t type = find_memory_type(req.memoryTypeBits, p_flags);
	if (type < 0 && (p_flags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)) {
		type = find_memory_type(req.memoryTypeBits, 0);
	}
	if (type < 0) {
		vkDestroyBuffer(device, r_buffer, nullptr);
		r_buffer = VK_NULL_HANDLE;
		ERR_FAIL_V_MSG(false, "No suitable memory type for a buffer.");
	}
	VkMemoryAllocateInfo ai = { VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO };
	ai.allocationSize = req.size;
	ai.memoryTypeIndex = (uint32_t)type;
	res = vkAllocateMemory(device, &ai, nullptr, &r_memory);
	if (res != VK_SUCCESS) {
		vkDestroyBuffer(device, r_buffer, nullptr);
		r_buffer = VK_NULL_HANDLE;
		ERR_FAIL_V_MSG(false, vformat("vkAllocateMemory failed (%d) for %llu bytes.", res, (unsigned long long)req.size));
	}
	vkBindBufferMemory(device, r_buffer, r_memory, 0);
	return true;
}

RDImpl::Staging RDImpl::create_staging(VkDeviceSize p_size) {
	Staging s;
	if (!create_buffer(p_size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, s.buffer, s.memory)) {
		return Staging();
	}
	s.size = p_size;
	if (vkMapMemory(device, s.memory, 0, VK_WHOLE_SIZE, 0, &s.mapped) != VK_SUCCESS) {
		vkDestroyBuffer(device, s.buffer, nullptr);
		vkFreeMemory(device, s.memory, nullptr);
		ERR_FAIL_V_MSG(Staging(), "vkMapMemory failed for a staging buffer.");
	}
	return s;
}

RDImpl::Staging RDImpl::acquire_readback_staging(VkDeviceSize p_size) {
	int best = -1;
	for (size_t i = 0; i < readback_pool.size(); i++) {
		if (readback_pool[i].size >= p_size && (best < 0 || readback_pool[i].size < readback_pool[best].size)) {
			best = int(i);
		}
	}
	if (best >= 0) {
		Staging s = readback_pool[best];
		readback_pool.erase(readback_pool.begin() + best);
		return s;
	}
	return create_staging(std::max<VkDeviceSize>(p_size, 256));
}

void RDImpl::release_readback_staging(Staging &p_staging) {
	if (readback_pool.size() < READBACK_POOL_SIZE) {
		readback_pool.push_back(p_staging);
		p_staging = Staging();
	} else {
		destroy_staging(device, p_staging);
	}
}

void destroy_staging(VkDevice p_device, RDImpl::Staging &p_s) {
	if (p_s.buffer) {
		vkDestroyBuffer(p_device, p_s.buffer, nullptr);
	}
	if (p_s.memory) {
		vkFreeMemory(p_device, p_s.memory, nullptr);
	}
	p_s = RDImpl::Staging();
}

void RDImpl::full_barrier() {
	ensure_recording();
	VkMemoryBarrier mb = { VK_STRUCTURE_TYPE_MEMORY_BARRIER };
	mb.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
	mb.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
	vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &mb, 0, nullptr, 0, nullptr);
}

void host_read_barrier(VkCommandBuffer p_cmd) {
	VkMemoryBarrier mb = { VK_STRUCTURE_TYPE_MEMORY_BARRIER };
	mb.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
	mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
	vkCmdPipelineBarrier(p_cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, nullptr, 0, nullptr);
}

void RDImpl::begin_frame() {
	Frame &f = current_frame();
	command_buffer = f.command_buffer;
	query_pool = f.query_pool;
	VkCommandBufferBeginInfo bi = { VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO };
	bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
	vkBeginCommandBuffer(command_buffer, &bi); // Implicit reset (pool has RESET_COMMAND_BUFFER_BIT).
	if (query_pool) {
		vkCmdResetQueryPool(command_buffer, query_pool, 0, MAX_TIMESTAMPS);
	}
	f.timestamp_names.clear();
	f.label_names.clear();
	recording = true;
}

void RDImpl::destroy_pending(Frame &p_frame) {
	// Keep one standard block for the slot's next frame; free the rest.
	Staging keep;
	for (Staging &s : p_frame.staging) {
		if (!keep.buffer && s.size == STAGING_BLOCK_SIZE) {
			keep = s;
			keep.used = 0;
		} else {
			destroy_staging(device, s);
		}
	}
	p_frame.staging.clear();
	if (keep.buffer) {
		p_frame.staging.push_back(keep);
	}
	std::vector<std::function<void()>> work;
	work.swap(p_frame.pending_destroy);
	for (auto &f : work) {
		f();
	}
}

void RDImpl::add_dependency(RID p_resource, RID p_dependent) {
	dependents[p_resource.get_id()].push_back(p_dependent);
}

void RDImpl::name_object(VkObjectType p_type, uint64_t p_handle, const String &p_name) {
	if (!set_object_name || !p_handle) {
		return;
	}
	VkDebugUtilsObjectNameInfoEXT ni = { VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT };
	ni.objectType = p_type;
	ni.objectHandle = p_handle;
	ni.pObjectName = p_name.c_str();
	set_object_name(device, &ni);
}

bool RDImpl::stage_data(const void *p_data, VkDeviceSize p_size, VkBuffer &r_buffer, VkDeviceSize &r_offset) {
	// Sync first if needed: syncing frees the arena.
	ensure_recording();
	std::vector<Staging> &frame_staging = current_frame().staging;
	Staging *block = frame_staging.empty() ? nullptr : &frame_staging.back();
	VkDeviceSize offset = block ? ((block->used + 15) & ~VkDeviceSize(15)) : 0;
	if (!block || offset + p_size > block->size) {
		Staging s = create_staging(std::max(p_size, STAGING_BLOCK_SIZE));
		if (!s.buffer) {
			return false;
		}
		frame_staging.push_back(s);
		block = &frame_staging.back();
		offset = 0;
	}
	memcpy((uint8_t *)block->mapped + offset, p_data, p_size);
	block->used = offset + p_size;
	r_buffer = block->buffer;
	r_offset = offset;
	return true;
}

void RDImpl::upload_to_buffer(VkBuffer p_buffer, uint32_t p_offset, uint32_t p_size, const void *p_data) {
	VkBuffer src;
	VkDeviceSize src_offset;
	if (!stage_data(p_data, p_size, src, src_offset)) {
		return;
	}
	full_barrier();
	VkBufferCopy region = { src_offset, p_offset, p_size };
	vkCmdCopyBuffer(command_buffer, src, p_buffer, 1, &region);
	full_barrier();
}

/************************/
/**** INITIALIZATION ****/
/************************/

RenderingDevice *RenderingDevice::get_singleton() {
	return singleton;
}

RenderingDevice::RenderingDevice() {
	impl = new Impl;
	if (singleton) {
		WARN_PRINT("A RenderingDevice already exists; the new one replaces it as the singleton.");
	}
	singleton = this;
}

RenderingDevice::~RenderingDevice() {
	if (impl->initialized) {
		finalize();
	}
	delete impl;
	if (singleton == this) {
		singleton = nullptr;
	}
}

bool RenderingDevice::is_initialized() const {
	return impl->initialized;
}

/********************/
/**** TIMESTAMPS ****/
/********************/

void RenderingDevice::capture_timestamp(const String &p_name) {
	Impl *s = impl;
	ERR_FAIL_COND_MSG(!s->initialized, "capture_timestamp: RenderingDevice is not initialized.");
	s->ensure_recording();
	ERR_FAIL_COND_MSG(!s->query_pool, "capture_timestamp: the device does not support timestamps.");
	std::vector<String> &names = s->current_frame().timestamp_names;
	ERR_FAIL_COND_MSG(names.size() >= Impl::MAX_TIMESTAMPS, vformat("capture_timestamp: more than %u timestamps in one frame.", Impl::MAX_TIMESTAMPS));
	uint32_t index = (uint32_t)names.size();
	vkCmdWriteTimestamp(s->command_buffer, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, s->query_pool, index);
	names.push_back(p_name);
}

uint32_t RenderingDevice::get_captured_timestamps_count() const {
	return (uint32_t)impl->captured_timestamp_times.size();
}

uint64_t RenderingDevice::get_captured_timestamp_gpu_time(uint32_t p_index) const {
	ERR_FAIL_INDEX_V((int64_t)p_index, (int64_t)(uint32_t)impl->captured_timestamp_times.size(), 0);
	return impl->captured_timestamp_times[p_index];
}

uint64_t RenderingDevice::get_captured_timestamps_frame() const {
	return impl->captured_timestamps_frame;
}

String RenderingDevice::get_captured_timestamp_name(uint32_t p_index) const {
	ERR_FAIL_INDEX_V((int64_t)p_index, (int64_t)(uint32_t)impl->captured_timestamp_names.size(), String());
	return impl->captured_timestamp_names[p_index];
}

/****************/
/**** LABELS ****/
/****************/

void RenderingDevice::draw_command_begin_label(const String &p_name, const Color &p_color) {
	Impl *s = impl;
	ERR_FAIL_COND_MSG(!s->initialized, "draw_command_begin_label: RenderingDevice is not initialized.");
	ERR_FAIL_COND_MSG(s->list.active, "draw_command_begin_label: not allowed inside a draw or compute list.");
	s->ensure_recording();
	if (s->cmd_begin_label) {
		VkDebugUtilsLabelEXT label = { VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT };
		label.pLabelName = p_name.c_str();
		label.color[0] = p_color.r;
		label.color[1] = p_color.g;
		label.color[2] = p_color.b;
		label.color[3] = p_color.a;
		s->cmd_begin_label(s->command_buffer, &label);
	}
	s->current_frame().label_names.push_back(p_name);
	s->open_labels++;
}

void RenderingDevice::draw_command_end_label() {
	Impl *s = impl;
	ERR_FAIL_COND_MSG(!s->initialized, "draw_command_end_label: RenderingDevice is not initialized.");
	ERR_FAIL_COND_MSG(s->list.active, "draw_command_end_label: not allowed inside a draw or compute list.");
	ERR_FAIL_COND_MSG(s->open_labels == 0, "draw_command_end_label: no label is open.");
	if (s->cmd_end_label) {
		s->cmd_end_label(s->command_buffer);
	}
	s->open_labels--;
}

const std::vector<String> &RenderingDevice::get_captured_label_names() const {
	return impl->captured_label_names;
}

/*************/
/**** FREE ****/
/*************/

bool RDImpl::free_rid(RID p_rid, bool p_report_error) {
	// Free dependents first (uniform sets, framebuffers, slices, arrays, pipelines).
	auto dep = dependents.find(p_rid.get_id());
	if (dep != dependents.end()) {
		std::vector<RID> list;
		list.swap(dep->second);
		dependents.erase(dep);
		for (RID d : list) {
			free_rid(d, false);
		}
	}
	VkDevice dev = device;
	std::vector<std::function<void()>> &pending_destroy = current_frame().pending_destroy;
	if (Buffer *b = buffer_owner.get_or_null(p_rid)) {
		VkBuffer buf = b->buffer;
		VkDeviceMemory mem = b->memory;
		pending_destroy.push_back([dev, buf, mem]() {
			vkDestroyBuffer(dev, buf, nullptr);
			vkFreeMemory(dev, mem, nullptr);
		});
		buffer_owner.free(p_rid);
	} else if (Texture *t = texture_owner.get_or_null(p_rid)) {
		VkImageView view = t->view;
		VkImage image = t->is_slice ? VK_NULL_HANDLE : t->image;
		VkDeviceMemory mem = t->memory;
		pending_destroy.push_back([dev, view, image, mem]() {
			vkDestroyImageView(dev, view, nullptr);
			if (image) {
				vkDestroyImage(dev, image, nullptr);
				vkFreeMemory(dev, mem, nullptr);
			}
		});
		texture_owner.free(p_rid);
	} else if (Sampler *smp = sampler_owner.get_or_null(p_rid)) {
		VkSampler h = smp->sampler;
		pending_destroy.push_back([dev, h]() { vkDestroySampler(dev, h, nullptr); });
		sampler_owner.free(p_rid);
	} else if (Shader *sh = shader_owner.get_or_null(p_rid)) {
		std::vector<VkShaderModule> modules;
		for (VkShaderModule m : sh->modules) {
			if (m) {
				modules.push_back(m);
			}
		}
		VkPipelineLayout layout = sh->pipeline_layout;
		pending_destroy.push_back([dev, modules, layout]() {
			for (VkShaderModule m : modules) {
				vkDestroyShaderModule(dev, m, nullptr);
			}
			vkDestroyPipelineLayout(dev, layout, nullptr);
		});
		shader_owner.free(p_rid);
	} else if (UniformSet *us = uniform_set_owner.get_or_null(p_rid)) {
		VkDescriptorPool pool = us->pool;
		pending_destroy.push_back([dev, pool]() { vkDestroyDescriptorPool(dev, pool, nullptr); });
		uniform_set_owner.free(p_rid);
	} else if (Framebuffer *fb = framebuffer_owner.get_or_null(p_rid)) {
		VkFramebuffer h = fb->framebuffer;
		pending_destroy.push_back([dev, h]() { vkDestroyFramebuffer(dev, h, nullptr); });
		framebuffer_owner.free(p_rid);
	} else if (vertex_array_owner.get_or_null(p_rid)) {
		vertex_array_owner.free(p_rid);
	} else if (index_array_owner.get_or_null(p_rid)) {
		index_array_owner.free(p_rid);
	} else if (Pipeline *p = pipeline_owner.get_or_null(p_rid)) {
		VkPipeline h = p->pipeline;
		pending_destroy.push_back([dev, h]() { vkDestroyPipeline(dev, h, nullptr); });
		pipeline_owner.free(p_rid);
	} else {
		if (p_report_error) {
			ERR_PRINT(vformat("RenderingDevice::free: RID %llu is invalid or already freed.", (unsigned long long)p_rid.get_id()));
		}
		return false;
	}
	return true;
}

void RenderingDevice::free(RID p_rid) {
	ERR_FAIL_COND_MSG(!impl->initialized, "RenderingDevice::free: device is not initialized.");
	if (impl->list.active && (impl->list.pipeline == p_rid)) {
		ERR_FAIL_MSG("RenderingDevice::free: the pipeline is bound in the open list.");
	}
	impl->free_rid(p_rid, true);
}

void RenderingDevice::set_resource_name(RID p_rid, const String &p_name) {
	Impl *s = impl;
	if (!s->set_object_name) {
		return;
	}
	if (Impl::Buffer *b = s->buffer_owner.get_or_null(p_rid)) {
		s->name_object(VK_OBJECT_TYPE_BUFFER, (uint64_t)b->buffer, p_name);
	} else if (Impl::Texture *t = s->texture_owner.get_or_null(p_rid)) {
		if (!t->is_slice) {
			s->name_object(VK_OBJECT_TYPE_IMAGE, (uint64_t)t->image, p_name);
		}
		s->name_object(VK_OBJECT_TYPE_IMAGE_VIEW, (uint64_t)t->view, p_name + " View");
	} else if (Impl::Sampler *smp = s->sampler_owner.get_or_null(p_rid)) {
		s->name_object(VK_OBJECT_TYPE_SAMPLER, (uint64_t)smp->sampler, p_name);
	} else if (Impl::Shader *sh = s->shader_owner.get_or_null(p_rid)) {
		for (VkShaderModule m : sh->modules) {
			s->name_object(VK_OBJECT_TYPE_SHADER_MODULE, (uint64_t)m, p_name);
		}
		sh->name = p_name;
	} else if (Impl::UniformSet *us = s->uniform_set_owner.get_or_null(p_rid)) {
		s->name_object(VK_OBJECT_TYPE_DESCRIPTOR_SET, (uint64_t)us->set, p_name);
	} else if (Impl::Framebuffer *fb = s->framebuffer_owner.get_or_null(p_rid)) {
		s->name_object(VK_OBJECT_TYPE_FRAMEBUFFER, (uint64_t)fb->framebuffer, p_name);
	} else if (Impl::Pipeline *p = s->pipeline_owner.get_or_null(p_rid)) {
		s->name_object(VK_OBJECT_TYPE_PIPELINE, (uint64_t)p->pipeline, p_name);
	} else if (!s->vertex_array_owner.owns(p_rid) && !s->index_array_owner.owns(p_rid)) {
		ERR_PRINT("set_resource_name: invalid RID.");
	}
}
