/**************************************************************************/
/*  rendering_device_impl.h                                               */
/**************************************************************************/
/* Internal: the Vulkan state behind RenderingDevice. Only the            */
/* rendering_device*.cpp files include this.                              */

#pragma once

#include "core/templates/rid_owner.h"
#include "servers/rendering/rendering_device.h"

#include <vulkan/vulkan.h>

#include <functional>
#include <map>
#include <unordered_map>

struct RenderingDevice::Impl {
	typedef RenderingDevice RDC;

	struct Buffer {
		VkBuffer buffer = VK_NULL_HANDLE;
		VkDeviceMemory memory = VK_NULL_HANDLE;
		uint32_t size = 0;
		enum Kind {
			KIND_STORAGE,
			KIND_UNIFORM,
			KIND_VERTEX,
			KIND_INDEX,
		} kind = KIND_STORAGE;
		IndexBufferFormat index_format = INDEX_BUFFER_FORMAT_UINT32;
		uint32_t index_count = 0;
	};

	struct Texture {
		VkImage image = VK_NULL_HANDLE;
		VkDeviceMemory memory = VK_NULL_HANDLE; // Null for slices (the parent owns the image).
		VkImageView view = VK_NULL_HANDLE;
		TextureFormat format; // For a slice: 2D, one layer, one mip, size of that mip.
		VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
		bool is_slice = false;
		RID parent;
		uint32_t base_layer = 0;
		uint32_t base_mip = 0;
	};

	struct Sampler {
		VkSampler sampler = VK_NULL_HANDLE;
	};

	struct SetLayoutBinding {
		uint32_t binding = 0;
		UniformType type = UNIFORM_TYPE_MAX;
		uint32_t count = 1;
		bool operator==(const SetLayoutBinding &p_o) const { return binding == p_o.binding && type == p_o.type && count == p_o.count; }
	};

	struct Shader {
		String name;
		VkShaderModule modules[SHADER_STAGE_MAX] = {};
		VkShaderStageFlags stage_flags = 0;
		bool is_compute = false;
		std::vector<std::vector<SetLayoutBinding>> sets; // Index = set number; sorted by binding.
		std::vector<String> set_keys;
		std::vector<VkDescriptorSetLayout> set_layouts; // Shared, owned by the cache.
		VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
		uint32_t push_constant_size = 0;
		uint32_t local_size[3] = { 1, 1, 1 };
	};

	struct UniformSet {
		VkDescriptorPool pool = VK_NULL_HANDLE;
		VkDescriptorSet set = VK_NULL_HANDLE;
		String key;
		uint32_t set_index = 0;
	};

	struct FramebufferFormat {
		std::vector<AttachmentFormat> attachments;
		uint32_t color_count = 0;
		bool has_depth = false;
		VkRenderPass passes[3][3] = {}; // [color action][depth action], created on demand.
	};

	struct Framebuffer {
		VkFramebuffer framebuffer = VK_NULL_HANDLE;
		FramebufferFormatID format = INVALID_FORMAT_ID;
		std::vector<RID> textures;
		uint32_t width = 0;
		uint32_t height = 0;
	};

	struct VertexFormat {
		std::vector<VertexAttribute> attributes;
	};

	struct VertexArray {
		uint32_t vertex_count = 0;
		VertexFormatID format = INVALID_ID;
		std::vector<VkBuffer> buffers;
		std::vector<VkDeviceSize> offsets;
	};

	struct IndexArray {
		VkBuffer buffer = VK_NULL_HANDLE;
		uint32_t offset = 0;
		uint32_t count = 0;
		VkIndexType index_type = VK_INDEX_TYPE_UINT32;
	};

	struct Pipeline {
		VkPipeline pipeline = VK_NULL_HANDLE;
		RID shader;
		VkPipelineLayout layout = VK_NULL_HANDLE;
		bool is_compute = false;
		FramebufferFormatID framebuffer_format = INVALID_FORMAT_ID;
		VertexFormatID vertex_format = INVALID_ID;
		uint32_t push_constant_size = 0;
		VkShaderStageFlags push_stages = 0;
		std::vector<String> set_keys;
		uint32_t local_size[3] = { 1, 1, 1 };
	};

	struct Staging {
		VkBuffer buffer = VK_NULL_HANDLE;
		VkDeviceMemory memory = VK_NULL_HANDLE;
		void *mapped = nullptr;
		VkDeviceSize size = 0;
		VkDeviceSize used = 0; // Frame arena blocks: bytes handed out.
	};
	static constexpr VkDeviceSize STAGING_BLOCK_SIZE = 4 * 1024 * 1024;

	// List state (draw or compute).
	struct ListState {
		bool active = false;
		bool is_compute = false;
		RID pipeline;
		std::vector<RID> sets; // Requested per index.
		std::vector<bool> set_dirty;
		bool pipeline_dirty = false;
		std::vector<uint8_t> push_data;
		bool push_dirty = false;
		RID vertex_array;
		RID index_array;
		uint32_t dispatch_count = 0;
		FramebufferFormatID framebuffer_format = INVALID_FORMAT_ID;
	};

	// Vulkan objects.
	VkInstance instance = VK_NULL_HANDLE;
	VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
	VkPhysicalDevice physical_device = VK_NULL_HANDLE;
	VkDevice device = VK_NULL_HANDLE;
	VkQueue queue = VK_NULL_HANDLE;
	uint32_t queue_family = 0;
	VkPhysicalDeviceProperties properties = {};
	VkPhysicalDeviceFeatures enabled_features = {};
	VkPhysicalDeviceMemoryProperties memory_properties = {};
	VkCommandPool command_pool = VK_NULL_HANDLE;
	VkCommandBuffer command_buffer = VK_NULL_HANDLE;
	VkFence fence = VK_NULL_HANDLE;
	VkQueryPool query_pool = VK_NULL_HANDLE;
	bool has_debug_utils = false;
	std::vector<String> extra_instance_extensions; // From set_extra_extensions() (presentation).
	std::vector<String> extra_device_extensions;
	PFN_vkSetDebugUtilsObjectNameEXT set_object_name = nullptr;
	PFN_vkCmdBeginDebugUtilsLabelEXT cmd_begin_label = nullptr;
	PFN_vkCmdEndDebugUtilsLabelEXT cmd_end_label = nullptr;

	DeviceInfo info;
	bool initialized = false;
	bool recording = false;
	bool submitted = false;
	uint64_t frames_submitted = 0;
	uint32_t validation_errors = 0;
	uint32_t validation_warnings = 0;

	// Owners.
	RID_Owner<Buffer> buffer_owner{ "RenderingDevice buffer" };
	RID_Owner<Texture> texture_owner{ "RenderingDevice texture" };
	RID_Owner<Sampler> sampler_owner{ "RenderingDevice sampler" };
	RID_Owner<Shader> shader_owner{ "RenderingDevice shader" };
	RID_Owner<UniformSet> uniform_set_owner{ "RenderingDevice uniform set" };
	RID_Owner<Framebuffer> framebuffer_owner{ "RenderingDevice framebuffer" };
	RID_Owner<VertexArray> vertex_array_owner{ "RenderingDevice vertex array" };
	RID_Owner<IndexArray> index_array_owner{ "RenderingDevice index array" };
	RID_Owner<Pipeline> pipeline_owner{ "RenderingDevice pipeline" };

	std::vector<FramebufferFormat> framebuffer_formats;
	std::vector<VertexFormat> vertex_formats;
	std::map<String, VkDescriptorSetLayout> set_layout_cache;

	// Dependency tracking: resource id -> RIDs to free with it.
	std::unordered_map<uint64_t, std::vector<RID>> dependents;

	// Deferred work, run after the next fence wait.
	std::vector<std::function<void()>> pending_destroy;
	std::vector<Staging> frame_staging;
	// buffer_get_data_async(): copies recorded into the current frame, delivered after its fence wait.
	struct Readback {
		Staging staging;
		uint32_t size = 0;
		std::function<void(const std::vector<uint8_t> &)> callback;
	};
	std::vector<Readback> frame_readbacks;
	// Their staging buffers are reused (a readback per frame must not allocate device memory each time).
	static constexpr size_t READBACK_POOL_SIZE = 8;
	std::vector<Staging> readback_pool;
	Staging acquire_readback_staging(VkDeviceSize p_size);
	void release_readback_staging(Staging &p_staging);

	// Timestamps.
	static constexpr uint32_t MAX_TIMESTAMPS = 256;
	std::vector<String> frame_timestamp_names;
	std::vector<String> captured_timestamp_names;
	std::vector<uint64_t> captured_timestamp_times;

	// Debug labels.
	std::vector<String> frame_label_names;
	std::vector<String> captured_label_names;
	uint32_t open_labels = 0;

	ListState list;

	// Helpers (rendering_device.cpp).
	int32_t find_memory_type(uint32_t p_type_bits, VkMemoryPropertyFlags p_flags) const;
	bool create_buffer(VkDeviceSize p_size, VkBufferUsageFlags p_usage, VkMemoryPropertyFlags p_flags, VkBuffer &r_buffer, VkDeviceMemory &r_memory);
	Staging create_staging(VkDeviceSize p_size); // Host visible + coherent, mapped; caller destroys it.
	// Copies p_data into this frame's staging arena (blocks freed after sync); false on failure.
	bool stage_data(const void *p_data, VkDeviceSize p_size, VkBuffer &r_buffer, VkDeviceSize &r_offset);
	void begin_frame();
	void submit_frame();
	void sync_frame(); // Submits if needed, waits, reads timestamps, destroys freed objects, begins the next frame.
	void ensure_recording(); // If the frame was submitted but not synced, syncs so commands can be recorded.
	void full_barrier();
	void destroy_pending();
	void add_dependency(RID p_resource, RID p_dependent);
	void name_object(VkObjectType p_type, uint64_t p_handle, const String &p_name);
	RID buffer_create(Buffer::Kind p_kind, uint32_t p_size, VkBufferUsageFlags p_usage, const void *p_data);
	void upload_to_buffer(VkBuffer p_buffer, uint32_t p_offset, uint32_t p_size, const void *p_data);
	VkDescriptorSetLayout get_set_layout(const std::vector<SetLayoutBinding> &p_bindings, const String &p_key);
	VkRenderPass get_render_pass(FramebufferFormatID p_format, InitialAction p_color, InitialAction p_depth);
	void bind_list_state(); // Applies dirty pipeline/sets/push constants before draw/dispatch.
	bool free_rid(RID p_rid, bool p_report_error);

	static VkFormat to_vk_format(DataFormat p_format);
	static VkCompareOp to_vk_compare(CompareOperator p_op);
	static String make_set_key(const std::vector<SetLayoutBinding> &p_bindings);
};

// Shared by rendering_device.cpp and rendering_device_resources.cpp.
void destroy_staging(VkDevice p_device, RenderingDevice::Impl::Staging &p_s);
void host_read_barrier(VkCommandBuffer p_cmd);
