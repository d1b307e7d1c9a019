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
	VkCommandBuffer command_buffer = VK_NULL_HANDLE; // frames[frame_index]'s, where commands are recorded.
	VkQueryPool query_pool = VK_NULL_HANDLE; // frames[frame_index]'s; null without timestamp support.
	bool has_debug_utils = false;
	std::vector<String> extra_instance_extensions; // From set_extra_extensions() (presentation).
	std::vector<String> extra_device_extensions;
	PFN_vkSetDebugUtilsObjectNameEXT set_object_name = nullptr;
	PFN_vkCmdBeginDebugUtilsLabelEXT cmd_begin_label = nullptr;
	PFN_vkCmdEndDebugUtilsLabelEXT cmd_end_label = nullptr;

	DeviceInfo info;
	bool initialized = false;
	bool recording = false;
	bool submitted = false; // frames[frame_index] was submitted and the next frame is not open yet.
	uint64_t frames_submitted = 0;
	uint64_t frames_completed = 0; // Serial of the newest frame whose fence was waited for.
	uint64_t fence_waits = 0; // vkWaitForFences calls (tests count them).
	uint64_t fence_wait_usec = 0; // Wall time spent in them (bench --frame-queue).
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

	// buffer_get_data_async(): copies recorded into a frame, delivered after its fence wait.
	struct Readback {
		Staging staging;
		uint32_t size = 0;
		std::function<void(const std::vector<uint8_t> &)> callback;
	};

	// Frames in flight (Godot's rendering/rendering_device/vsync/frame_queue_size): one slot per frame
	// that may be queued. Frame serial S records into slot (S - 1) % queue size; opening a slot waits
	// only for the fence of the frame that used it last (S - queue size).
	struct Frame {
		VkCommandPool command_pool = VK_NULL_HANDLE;
		VkCommandBuffer command_buffer = VK_NULL_HANDLE;
		VkFence fence = VK_NULL_HANDLE;
		VkQueryPool query_pool = VK_NULL_HANDLE;
		Staging timestamp_results; // Mapped; the frame copies its query results here before it ends.
		bool in_flight = false; // Submitted; its fence has not been waited for yet.
		uint64_t serial = 0; // frames_submitted after its submit.
		std::vector<Staging> staging; // Upload arena; reused once the fence signalled.
		std::vector<Readback> readbacks;
		std::vector<String> timestamp_names;
		std::vector<String> label_names;
		// Deferred destruction of what was freed while this frame was the newest: every frame that may
		// use it was submitted no later than this one, so this frame's fence covers them all.
		std::vector<std::function<void()>> pending_destroy;
	};
	// What a completed frame hands back, delivered once the next frame is open.
	struct Completed {
		uint64_t serial = 0;
		std::vector<String> timestamp_names;
		std::vector<uint64_t> timestamp_times;
		std::vector<std::pair<std::vector<uint8_t>, std::function<void(const std::vector<uint8_t> &)>>> readbacks;
	};
	static constexpr uint32_t MAX_FRAME_QUEUE_SIZE = 3;
	std::vector<Frame> frames;
	uint32_t frame_index = 0;
	Frame &current_frame() { return frames[frame_index]; }
	// Their staging buffers are reused (a readback per frame must not allocate device memory each time).
	static constexpr size_t READBACK_POOL_SIZE = 8;
	std::vector<Staging> readback_pool;
	Staging acquire_readback_staging(VkDeviceSize p_size);
	void release_readback_staging(Staging &p_staging);

	// Timestamps.
	static constexpr uint32_t MAX_TIMESTAMPS = 256;
	std::vector<String> captured_timestamp_names;
	std::vector<uint64_t> captured_timestamp_times;
	uint64_t captured_timestamps_frame = 0;

	// Debug labels.
	std::vector<String> captured_label_names;
	uint32_t open_labels = 0;

	ListState list;

	// Helpers (rendering_device.cpp).
	int32_t find_memory_type(uint32_t p_type_bits, VkMemoryPropertyFlags p_flags) const;
	bool create_buffer(VkDeviceSize p_size, VkBufferUsageFlags p_usage, VkMemoryPropertyFlags p_flags, VkBuffer &r_buffer, VkDeviceMemory &r_memory);
	Staging create_staging(VkDeviceSize p_size); // Host visible + coherent, mapped; caller destroys it.
	// Copies p_data into this frame's staging arena (blocks freed after sync); false on failure.
	bool stage_data(const void *p_data, VkDeviceSize p_size, VkBuffer &r_buffer, VkDeviceSize &r_offset);
	bool create_frames(uint32_t p_count, bool p_timestamps);
	void destroy_frames();
	void begin_frame();
	void submit_frame();
	// Waits for p_frame's fence and collects what it hands back; recycles its arena, runs its frees.
	void complete_frame(Frame &p_frame, std::vector<Completed> &r_completed);
	void deliver(std::vector<Completed> &p_completed); // Timestamps, then readback callbacks, per frame.
	void advance_frame(); // Submits if needed; opens the next slot, waiting only for that slot's frame.
	void sync_frame(); // Submits if needed, waits for every frame in flight, begins the next frame.
	void ensure_recording(); // If the frame was submitted, opens the next one so commands can be recorded.
	void full_barrier();
	void destroy_pending(Frame &p_frame);
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
