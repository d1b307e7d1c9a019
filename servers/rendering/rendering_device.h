/**************************************************************************/
/*  rendering_device.h                                                    */
/**************************************************************************/
/* RenderingDevice: a small, headless, RID-based GPU abstraction over     */
/* Vulkan 1.1 in the spirit of Godot's RenderingDevice.                   */
/*                                                                        */
/* Model (read this before using it):                                     */
/* - Frames in flight (Godot's rendering/rendering_device/vsync/          */
/*   frame_queue_size, default 2): each frame records into its own slot   */
/*   (command buffer, fence, timestamp queries, upload arena, readbacks,  */
/*   deferred frees). Everything that touches the GPU (buffer/texture     */
/*   updates with data, clears, copies, draw lists, compute lists,        */
/*   timestamps) is recorded into the open frame in call order.           */
/*   swap_buffers() submits it and opens the next slot, waiting only for  */
/*   the frame that used that slot (queue size frames ago), so the CPU    */
/*   records frame N+1 while the GPU runs frame N. submit() ends and      */
/*   submits the frame; sync() waits for EVERY submitted frame and opens  */
/*   the next one (submit_and_sync() does both: a full flush). Queue size */
/*   1 waits for each frame before the next opens.                        */
/* - Synchronisation is automatic and conservative: a full memory barrier */
/*   is recorded before/after every transfer, draw list and compute list, */
/*   and between consecutive dispatches of a compute list.                */
/* - Every image lives in VK_IMAGE_LAYOUT_GENERAL for its whole life, so  */
/*   a texture can be sampled, stored to, copied and rendered to without  */
/*   layout tracking. Texture slices share the parent's image.            */
/* - buffer_get_data()/texture_get_data() flush: they submit the frame,   */
/*   wait for it, read back and leave a fresh frame open.                 */
/*   buffer_get_data_async() does not: its callback runs once the fence   */
/*   of the frame which recorded the copy was waited for (by the          */
/*   swap_buffers() queue size frames later, or by a sync()).             */
/* - free() is deferred: Vulkan objects are destroyed once every frame    */
/*   submitted so far (and the open one) has completed, so freeing        */
/*   something a frame in flight uses is safe.                            */
/*   Freeing a texture or buffer also frees the uniform sets and          */
/*   framebuffers (and texture slices) that depend on it, like Godot.     */
/* - Descriptor set layouts come from SPIR-V reflection (own parser of    */
/*   DescriptorSet/Binding decorations + variable types). Every binding   */
/*   is visible to all stages, and identical set layouts are shared, so a */
/*   uniform set made for shader A's set N can be bound with any pipeline */
/*   whose shader declares the same bindings in set N. Bound uniform sets */
/*   and push constants are (re)applied at draw/dispatch time against the */
/*   current pipeline.                                                    */
/* - Push constants: one range per shader covering the shader's block.    */
/*                                                                        */
/* Environment: GODOT_AREA_VALIDATION=1 enables VK_LAYER_KHRONOS_validation*/
/* (errors are printed and counted); GODOT_AREA_DEVICE=<index or name     */
/* substring> forces a physical device.                                   */

#pragma once

#include "core/math/color.h"
#include "core/string/ustring.h"
#include "core/templates/rid.h"

#include <cstdint>
#include <functional>
#include <vector>

class RenderingDevice {
public:
	typedef int64_t DrawListID;
	typedef int64_t ComputeListID;
	typedef int64_t FramebufferFormatID;
	typedef int64_t VertexFormatID;

	static constexpr int64_t INVALID_ID = -1;
	static constexpr FramebufferFormatID INVALID_FORMAT_ID = -1;

	enum DeviceType {
		DEVICE_TYPE_OTHER,
		DEVICE_TYPE_INTEGRATED_GPU,
		DEVICE_TYPE_DISCRETE_GPU,
		DEVICE_TYPE_VIRTUAL_GPU,
		DEVICE_TYPE_CPU,
	};

	struct DeviceInfo {
		String name;
		DeviceType type = DEVICE_TYPE_OTHER;
		String type_name; // "discrete GPU", "integrated GPU", "CPU", ...
		String driver_name;
		String driver_info;
		uint32_t driver_version = 0;
		uint32_t vendor_id = 0;
		uint32_t device_id = 0;
		String api_version; // "1.3.255"
		uint32_t device_index = 0; // Index in vkEnumeratePhysicalDevices.
		bool validation_enabled = false;
		bool debug_utils_enabled = false;
		bool timestamps_supported = false;
		float timestamp_period_ns = 1.0f;
		// Key limits.
		uint32_t max_texture_size_2d = 0;
		uint32_t max_texture_array_layers = 0;
		uint32_t max_push_constant_size = 0;
		uint32_t max_uniform_buffer_size = 0;
		uint32_t max_storage_buffer_size = 0;
		uint32_t max_bound_descriptor_sets = 0;
		uint32_t max_color_attachments = 0;
		uint32_t max_compute_workgroup_count[3] = { 0, 0, 0 };
		uint32_t max_compute_workgroup_size[3] = { 0, 0, 0 };
		uint32_t max_compute_workgroup_invocations = 0;
		uint32_t min_uniform_buffer_offset_alignment = 0;
		uint32_t min_storage_buffer_offset_alignment = 0;
		uint64_t device_local_memory = 0; // Bytes of the largest device-local heap.
	};

	/*****************/
	/**** FORMATS ****/
	/*****************/

	// Used for textures and vertex attributes alike.
	enum DataFormat {
		DATA_FORMAT_R8_UNORM,
		DATA_FORMAT_R8G8_UNORM,
		DATA_FORMAT_R8G8B8A8_UNORM,
		DATA_FORMAT_R8G8B8A8_SRGB,
		DATA_FORMAT_R16_SFLOAT,
		DATA_FORMAT_R16G16_SFLOAT,
		DATA_FORMAT_R16G16B16A16_SFLOAT,
		DATA_FORMAT_R32_SFLOAT,
		DATA_FORMAT_R32G32_SFLOAT,
		DATA_FORMAT_R32G32B32_SFLOAT, // Vertex attributes only.
		DATA_FORMAT_R32G32B32A32_SFLOAT,
		DATA_FORMAT_R32_UINT,
		DATA_FORMAT_R32G32_UINT,
		DATA_FORMAT_R32G32B32A32_UINT,
		DATA_FORMAT_R32_SINT,
		DATA_FORMAT_D16_UNORM,
		DATA_FORMAT_D32_SFLOAT,
		DATA_FORMAT_MAX,
	};
	// Bytes per texel (or per vertex attribute); 0 for DATA_FORMAT_MAX.
	static uint32_t get_format_size(DataFormat p_format);
	static bool is_depth_format(DataFormat p_format);
	static const char *get_format_name(DataFormat p_format);

	/*****************/
	/**** BUFFERS ****/
	/*****************/

	enum IndexBufferFormat {
		INDEX_BUFFER_FORMAT_UINT16,
		INDEX_BUFFER_FORMAT_UINT32,
	};

	enum StorageBufferUsage {
		STORAGE_BUFFER_USAGE_NONE = 0,
		STORAGE_BUFFER_USAGE_DISPATCH_INDIRECT = 1, // Also usable as an indirect draw/dispatch argument buffer.
	};

	// All buffers are device-local; p_data (may be null = zero-filled) must hold p_size bytes.
	// Every buffer can be a copy source/destination and be read back.
	RID storage_buffer_create(uint32_t p_size, const void *p_data = nullptr, uint32_t p_usage = STORAGE_BUFFER_USAGE_NONE);
	RID uniform_buffer_create(uint32_t p_size, const void *p_data = nullptr);
	// A vertex buffer can also be bound as a storage buffer (compute skinning etc.).
	RID vertex_buffer_create(uint32_t p_size, const void *p_data = nullptr);
	// p_index_count indices of the given format.
	RID index_buffer_create(uint32_t p_index_count, IndexBufferFormat p_format, const void *p_data = nullptr);

	// Recorded into the current frame (ordered with draw/compute lists). Not allowed inside a list.
	bool buffer_update(RID p_buffer, uint32_t p_offset, uint32_t p_size, const void *p_data);
	bool buffer_clear(RID p_buffer, uint32_t p_offset, uint32_t p_size); // Zero fill; offset/size multiples of 4.
	bool buffer_copy(RID p_src, RID p_dst, uint32_t p_src_offset, uint32_t p_dst_offset, uint32_t p_size);
	// Flushes (submit + sync) and returns the contents; p_size 0 = to the end.
	std::vector<uint8_t> buffer_get_data(RID p_buffer, uint32_t p_offset = 0, uint32_t p_size = 0);
	// No flush (Godot 4.4's buffer_get_data_async): records a copy of the range into this frame, after
	// everything recorded so far; p_callback gets the bytes once the frame's fence has signalled, from the
	// sync() that waited for it (after the next frame opened: it may record). Dropped with the device or a
	// failed submit. Returns false (and never calls back) on bad arguments.
	bool buffer_get_data_async(RID p_buffer, const std::function<void(const std::vector<uint8_t> &)> &p_callback, uint32_t p_offset = 0, uint32_t p_size = 0);
	uint32_t buffer_get_size(RID p_buffer) const;

	/******************/
	/**** TEXTURES ****/
	/******************/

	enum TextureType {
		TEXTURE_TYPE_2D,
		TEXTURE_TYPE_2D_ARRAY,
		TEXTURE_TYPE_CUBE, // array_layers must be 6.
		TEXTURE_TYPE_CUBE_ARRAY, // array_layers must be a multiple of 6.
		TEXTURE_TYPE_3D,
	};

	enum TextureUsageBits {
		TEXTURE_USAGE_SAMPLING_BIT = (1 << 0),
		TEXTURE_USAGE_COLOR_ATTACHMENT_BIT = (1 << 1),
		TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT = (1 << 2),
		TEXTURE_USAGE_STORAGE_BIT = (1 << 3),
		TEXTURE_USAGE_CAN_UPDATE_BIT = (1 << 4), // texture_update / initial data.
		TEXTURE_USAGE_CAN_COPY_FROM_BIT = (1 << 5), // texture_get_data / copies from it.
		TEXTURE_USAGE_CAN_COPY_TO_BIT = (1 << 6), // texture_clear / copies to it.
	};

	struct TextureFormat {
		DataFormat format = DATA_FORMAT_R8G8B8A8_UNORM;
		uint32_t width = 1;
		uint32_t height = 1;
		uint32_t depth = 1; // TEXTURE_TYPE_3D only.
		uint32_t array_layers = 1;
		uint32_t mipmaps = 1; // Data upload/readback addresses mip 0 only.
		TextureType texture_type = TEXTURE_TYPE_2D;
		uint32_t usage_bits = TEXTURE_USAGE_SAMPLING_BIT;
	};

	// p_data: empty, or one entry per array layer (width*height*depth*texel size bytes each, mip 0).
	RID texture_create(const TextureFormat &p_format, const std::vector<std::vector<uint8_t>> &p_data = {});
	// A view of one layer (and one mip) of p_texture, typed TEXTURE_TYPE_2D; usable as an attachment
	// (e.g. render a shadow into one layer of an array). Freed automatically with its parent.
	RID texture_create_shared_from_slice(RID p_texture, uint32_t p_layer, uint32_t p_mipmap = 0);
	// Replace mip 0 of one layer; p_data holds width*height*depth*texel size bytes.
	bool texture_update(RID p_texture, uint32_t p_layer, const std::vector<uint8_t> &p_data);
	// Clears mips [base_mip, base_mip+mip_count) of layers [base_layer, base_layer+layer_count).
	// Colour textures use p_color; depth textures use p_color.r as depth.
	bool texture_clear(RID p_texture, const Color &p_color, uint32_t p_base_mipmap = 0, uint32_t p_mipmaps = 1, uint32_t p_base_layer = 0, uint32_t p_layers = 1);
	// Flushes (submit + sync); returns mip 0 of p_layer, tightly packed rows.
	std::vector<uint8_t> texture_get_data(RID p_texture, uint32_t p_layer = 0);
	bool texture_is_valid(RID p_texture) const;
	TextureFormat texture_get_format(RID p_texture) const;

	// Native handles for a presenter on this device and queue (the editor window samples the
	// viewport's texture; Godot: RenderingDevice::get_driver_resource). Images stay in
	// VK_IMAGE_LAYOUT_GENERAL (see top). 0 with an error for an invalid RID.
	enum DriverResource {
		DRIVER_RESOURCE_TEXTURE, // VkImage.
		DRIVER_RESOURCE_TEXTURE_VIEW, // VkImageView (all layers and mips of the texture).
	};
	uint64_t get_driver_resource(DriverResource p_resource, RID p_rid) const;

	/******************/
	/**** SAMPLERS ****/
	/******************/

	enum SamplerFilter {
		SAMPLER_FILTER_NEAREST,
		SAMPLER_FILTER_LINEAR,
	};
	enum SamplerRepeatMode {
		SAMPLER_REPEAT_MODE_REPEAT,
		SAMPLER_REPEAT_MODE_MIRRORED_REPEAT,
		SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE,
		SAMPLER_REPEAT_MODE_CLAMP_TO_BORDER,
	};
	enum SamplerBorderColor {
		SAMPLER_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK,
		SAMPLER_BORDER_COLOR_FLOAT_OPAQUE_BLACK,
		SAMPLER_BORDER_COLOR_FLOAT_OPAQUE_WHITE,
	};
	enum CompareOperator {
		COMPARE_OP_NEVER,
		COMPARE_OP_LESS,
		COMPARE_OP_EQUAL,
		COMPARE_OP_LESS_OR_EQUAL,
		COMPARE_OP_GREATER,
		COMPARE_OP_NOT_EQUAL,
		COMPARE_OP_GREATER_OR_EQUAL,
		COMPARE_OP_ALWAYS,
	};

	struct SamplerState {
		SamplerFilter mag_filter = SAMPLER_FILTER_NEAREST;
		SamplerFilter min_filter = SAMPLER_FILTER_NEAREST;
		SamplerFilter mip_filter = SAMPLER_FILTER_NEAREST;
		SamplerRepeatMode repeat_u = SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE;
		SamplerRepeatMode repeat_v = SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE;
		SamplerRepeatMode repeat_w = SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE;
		float lod_bias = 0.0f;
		float min_lod = 0.0f;
		float max_lod = 1e20f;
		bool enable_compare = false; // Depth comparison sampler (sampler2DShadow etc.).
		CompareOperator compare_op = COMPARE_OP_LESS_OR_EQUAL;
		SamplerBorderColor border_color = SAMPLER_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
	};

	RID sampler_create(const SamplerState &p_state);

	/*****************/
	/**** SHADERS ****/
	/*****************/

	enum ShaderStage {
		SHADER_STAGE_VERTEX,
		SHADER_STAGE_FRAGMENT,
		SHADER_STAGE_COMPUTE,
		SHADER_STAGE_MAX,
	};
	static const char *get_shader_stage_name(ShaderStage p_stage); // "vertex", "fragment", "compute".

	struct ShaderStageSPIRVData {
		ShaderStage shader_stage = SHADER_STAGE_VERTEX;
		std::vector<uint32_t> spirv;
	};

	// GLSL (#version 450, Vulkan semantics) -> SPIR-V 1.3 with glslang. No #include support here
	// (ShaderRD expands includes). #line "file" directives are accepted (GL_GOOGLE_cpp_style_line_directive
	// is enabled by the caller's source). On failure returns empty and puts glslang's log in r_error.
	std::vector<uint32_t> shader_compile_spirv_from_source(ShaderStage p_stage, const String &p_source, const String &p_name = "", String *r_error = nullptr);
	// Either one compute stage, or vertex (+ optional fragment). Reflection errors return an invalid RID.
	RID shader_create_from_spirv(const std::vector<ShaderStageSPIRVData> &p_stages, const String &p_name = "");
	uint32_t shader_get_push_constant_size(RID p_shader) const;
	bool shader_is_compute(RID p_shader) const;

	/***********************/
	/**** UNIFORM SETS  ****/
	/***********************/

	enum UniformType {
		UNIFORM_TYPE_SAMPLER, // ids: samplers.
		UNIFORM_TYPE_SAMPLER_WITH_TEXTURE, // ids: sampler, texture, sampler, texture, ... (combined image sampler).
		UNIFORM_TYPE_TEXTURE, // ids: textures (sampled image).
		UNIFORM_TYPE_IMAGE, // ids: textures with TEXTURE_USAGE_STORAGE_BIT (storage image).
		UNIFORM_TYPE_UNIFORM_BUFFER, // ids: one uniform buffer.
		UNIFORM_TYPE_STORAGE_BUFFER, // ids: storage buffers (vertex buffers also allowed).
		UNIFORM_TYPE_MAX,
	};

	struct Uniform {
		UniformType uniform_type = UNIFORM_TYPE_IMAGE;
		uint32_t binding = 0;
		std::vector<RID> ids; // More than one for arrays (array size must match the shader).

		Uniform() {}
		Uniform(UniformType p_type, uint32_t p_binding, RID p_id) :
				uniform_type(p_type), binding(p_binding), ids{ p_id } {}
		Uniform(UniformType p_type, uint32_t p_binding, const std::vector<RID> &p_ids) :
				uniform_type(p_type), binding(p_binding), ids(p_ids) {}
	};

	// Every binding the shader declares in set p_set_index must be provided, with the matching type.
	RID uniform_set_create(const std::vector<Uniform> &p_uniforms, RID p_shader, uint32_t p_set_index);
	bool uniform_set_is_valid(RID p_uniform_set) const;

	/**********************/
	/**** FRAMEBUFFERS ****/
	/**********************/

	struct AttachmentFormat {
		DataFormat format = DATA_FORMAT_R8G8B8A8_UNORM;
		uint32_t usage_flags = TEXTURE_USAGE_COLOR_ATTACHMENT_BIT;
	};

	// Colour attachments in order, then at most one depth attachment (last). Formats are cached: equal
	// lists give equal IDs.
	FramebufferFormatID framebuffer_format_create(const std::vector<AttachmentFormat> &p_format);
	uint32_t framebuffer_format_get_color_attachment_count(FramebufferFormatID p_format) const;
	// Textures (or slices) with COLOR/DEPTH attachment usage, all the same size. Depth last.
	RID framebuffer_create(const std::vector<RID> &p_textures);
	FramebufferFormatID framebuffer_get_format(RID p_framebuffer) const;
	bool framebuffer_is_valid(RID p_framebuffer) const;
	uint32_t framebuffer_get_width(RID p_framebuffer) const;
	uint32_t framebuffer_get_height(RID p_framebuffer) const;

	/************************/
	/**** VERTEX FORMATS ****/
	/************************/

	enum VertexFrequency {
		VERTEX_FREQUENCY_VERTEX,
		VERTEX_FREQUENCY_INSTANCE,
	};

	// Each attribute reads from its own buffer binding (the i-th buffer of the vertex array).
	struct VertexAttribute {
		uint32_t location = 0;
		uint32_t offset = 0;
		DataFormat format = DATA_FORMAT_R32G32B32_SFLOAT;
		uint32_t stride = 0;
		VertexFrequency frequency = VERTEX_FREQUENCY_VERTEX;
	};

	// Cached: equal lists give equal IDs. An empty list is valid (procedural vertices).
	VertexFormatID vertex_format_create(const std::vector<VertexAttribute> &p_vertex_descriptions);
	// One buffer per attribute of the format (the same buffer may repeat); p_offsets optional.
	RID vertex_array_create(uint32_t p_vertex_count, VertexFormatID p_vertex_format, const std::vector<RID> &p_src_buffers, const std::vector<uint64_t> &p_offsets = {});
	// p_index_count 0 = all indices from p_index_offset on.
	RID index_array_create(RID p_index_buffer, uint32_t p_index_offset, uint32_t p_index_count);

	/*******************/
	/**** PIPELINES ****/
	/*******************/

	enum RenderPrimitive {
		RENDER_PRIMITIVE_POINTS,
		RENDER_PRIMITIVE_LINES,
		RENDER_PRIMITIVE_LINE_STRIPS,
		RENDER_PRIMITIVE_TRIANGLES,
		RENDER_PRIMITIVE_TRIANGLE_STRIPS,
	};

	enum PolygonCullMode {
		POLYGON_CULL_DISABLED,
		POLYGON_CULL_FRONT,
		POLYGON_CULL_BACK,
	};

	enum PolygonFrontFace {
		POLYGON_FRONT_FACE_CLOCKWISE,
		POLYGON_FRONT_FACE_COUNTER_CLOCKWISE,
	};

	struct PipelineRasterizationState {
		bool enable_depth_clamp = false;
		bool wireframe = false;
		PolygonCullMode cull_mode = POLYGON_CULL_DISABLED;
		PolygonFrontFace front_face = POLYGON_FRONT_FACE_CLOCKWISE;
		bool depth_bias_enabled = false;
		float depth_bias_constant_factor = 0.0f;
		float depth_bias_slope_factor = 0.0f;
	};

	struct PipelineDepthStencilState {
		bool enable_depth_test = false;
		bool enable_depth_write = false;
		CompareOperator depth_compare_operator = COMPARE_OP_LESS_OR_EQUAL;
	};

	enum BlendFactor {
		BLEND_FACTOR_ZERO,
		BLEND_FACTOR_ONE,
		BLEND_FACTOR_SRC_ALPHA,
		BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
		BLEND_FACTOR_DST_ALPHA,
		BLEND_FACTOR_ONE_MINUS_DST_ALPHA,
	};
	enum BlendOperation {
		BLEND_OP_ADD,
		BLEND_OP_SUBTRACT,
		BLEND_OP_REVERSE_SUBTRACT,
		BLEND_OP_MINIMUM,
		BLEND_OP_MAXIMUM,
	};

	struct PipelineColorBlendState {
		struct Attachment {
			bool enable_blend = false;
			BlendFactor src_color_blend_factor = BLEND_FACTOR_ZERO;
			BlendFactor dst_color_blend_factor = BLEND_FACTOR_ZERO;
			BlendOperation color_blend_op = BLEND_OP_ADD;
			BlendFactor src_alpha_blend_factor = BLEND_FACTOR_ZERO;
			BlendFactor dst_alpha_blend_factor = BLEND_FACTOR_ZERO;
			BlendOperation alpha_blend_op = BLEND_OP_ADD;
			bool write_r = true;
			bool write_g = true;
			bool write_b = true;
			bool write_a = true;
		};
		// One per colour attachment of the framebuffer format (missing entries = no blending).
		std::vector<Attachment> attachments;

		static PipelineColorBlendState create_disabled(int p_attachments = 1);
		// dst = src + dst (light accumulation).
		static PipelineColorBlendState create_additive(int p_attachments = 1);
		// dst = src * src.a + dst * (1 - src.a).
		static PipelineColorBlendState create_blend(int p_attachments = 1);
	};

	enum PipelineDynamicStateFlags {
		DYNAMIC_STATE_DEPTH_BIAS = (1 << 0), // Set with draw_list_set_depth_bias().
	};

	// Viewport and scissor are always dynamic (set by draw_list_begin / draw_list_set_viewport).
	RID render_pipeline_create(RID p_shader, FramebufferFormatID p_framebuffer_format, VertexFormatID p_vertex_format, RenderPrimitive p_render_primitive, const PipelineRasterizationState &p_rasterization_state, const PipelineDepthStencilState &p_depth_stencil_state, const PipelineColorBlendState &p_blend_state, uint32_t p_dynamic_state_flags = 0);
	RID compute_pipeline_create(RID p_shader);
	bool render_pipeline_is_valid(RID p_pipeline) const;
	bool compute_pipeline_is_valid(RID p_pipeline) const;

	/********************/
	/**** DRAW LISTS ****/
	/********************/

	enum InitialAction {
		INITIAL_ACTION_LOAD,
		INITIAL_ACTION_CLEAR,
		INITIAL_ACTION_DISCARD,
	};

	// A sub-rectangle of a framebuffer in pixels. width or height 0 = the whole framebuffer.
	struct Rect {
		int32_t x = 0;
		int32_t y = 0;
		uint32_t width = 0;
		uint32_t height = 0;
		Rect() {}
		Rect(int32_t p_x, int32_t p_y, uint32_t p_width, uint32_t p_height) :
				x(p_x), y(p_y), width(p_width), height(p_height) {}
	};

	// One draw list at a time. p_clear_colors: one per colour attachment when clearing (missing = black).
	// p_region restricts rendering (and clearing) to a rectangle; viewport and scissor are set to it.
	DrawListID draw_list_begin(RID p_framebuffer, InitialAction p_initial_color_action = INITIAL_ACTION_CLEAR, InitialAction p_initial_depth_action = INITIAL_ACTION_CLEAR, const std::vector<Color> &p_clear_colors = {}, float p_clear_depth = 1.0f, const Rect &p_region = Rect());
	void draw_list_bind_render_pipeline(DrawListID p_list, RID p_render_pipeline);
	void draw_list_bind_uniform_set(DrawListID p_list, RID p_uniform_set, uint32_t p_index);
	void draw_list_bind_vertex_array(DrawListID p_list, RID p_vertex_array);
	void draw_list_bind_index_array(DrawListID p_list, RID p_index_array);
	// p_data_size must equal the bound pipeline shader's push constant size.
	void draw_list_set_push_constant(DrawListID p_list, const void *p_data, uint32_t p_data_size);
	void draw_list_set_viewport(DrawListID p_list, const Rect &p_rect); // Also sets the scissor.
	void draw_list_set_depth_bias(DrawListID p_list, float p_constant, float p_slope); // Needs DYNAMIC_STATE_DEPTH_BIAS.
	// p_procedural_vertices > 0: draw that many vertices without a vertex array (gl_VertexIndex).
	// Otherwise draws the bound index array (p_use_indices) or the bound vertex array.
	void draw_list_draw(DrawListID p_list, bool p_use_indices, uint32_t p_instances = 1, uint32_t p_procedural_vertices = 0);
	void draw_list_end();

	/***********************/
	/**** COMPUTE LISTS ****/
	/***********************/

	ComputeListID compute_list_begin();
	void compute_list_bind_compute_pipeline(ComputeListID p_list, RID p_compute_pipeline);
	void compute_list_bind_uniform_set(ComputeListID p_list, RID p_uniform_set, uint32_t p_index);
	void compute_list_set_push_constant(ComputeListID p_list, const void *p_data, uint32_t p_data_size);
	void compute_list_dispatch(ComputeListID p_list, uint32_t p_x_groups, uint32_t p_y_groups, uint32_t p_z_groups);
	// Dispatches covering p_x/y/z threads with the pipeline's local size (rounded up).
	void compute_list_dispatch_threads(ComputeListID p_list, uint32_t p_x_threads, uint32_t p_y_threads, uint32_t p_z_threads);
	// Explicit full barrier (dispatches are also separated by barriers automatically).
	void compute_list_add_barrier(ComputeListID p_list);
	void compute_list_end();

	/****************/
	/**** FRAMES ****/
	/****************/

	// rendering/rendering_device/vsync/frame_queue_size (Godot: default 2, range 2..3). 1 is accepted
	// too (each frame waits for the previous one: tests, and the cost comparison in doc/methods.md).
	static constexpr const char *SETTING_FRAME_QUEUE_SIZE = "rendering/rendering_device/vsync/frame_queue_size";
	static constexpr uint32_t DEFAULT_FRAME_QUEUE_SIZE = 2;
	static uint32_t get_project_frame_queue_size(); // Read by initialize(); invalid values give the default.
	// Waits for every frame in flight, then uses p_size (1..3) slots. False with an error otherwise.
	bool set_frame_queue_size(uint32_t p_size);
	uint32_t get_frame_queue_size() const;

	// Ends and submits the current frame's command buffer. No list may be open.
	void submit();
	// Waits for every submitted frame (timestamps read back, async readbacks delivered, freed objects
	// destroyed) and opens a new frame: a full flush.
	void sync();
	void submit_and_sync() {
		submit();
		sync();
	}
	// End of a rendered frame (Godot: RenderingDevice::swap_buffers): submits the frame and opens the
	// next slot, waiting only for the frame that used it last (frame_queue_size frames ago); that
	// frame's timestamps and async readbacks are delivered then.
	void swap_buffers();
	// Waits for submitted frame p_frame (and older ones) if still in flight and delivers what they hand
	// back (timestamps, async readbacks); the open frame is neither submitted nor touched.
	void wait_for_frame(uint64_t p_frame);
	// Serial of the newest frame whose fence was waited for (frames are numbered from 1 in submission
	// order; see get_frames_submitted()).
	uint64_t get_frames_completed() const;
	// vkWaitForFences calls so far (tests: swap_buffers() waits once, and only for an old frame).
	uint64_t get_fence_wait_count() const;
	// Wall time the CPU spent blocked in those waits, in microseconds.
	uint64_t get_fence_wait_time_usec() const;

	/********************/
	/**** TIMESTAMPS ****/
	/********************/

	// Records a GPU timestamp (bottom of pipe) with a name in the current frame; allowed inside lists.
	// A frame's results replace the captured ones when its fence was waited for (swap_buffers() queue
	// size frames later, or sync()); frames without timestamps leave them alone. At most 256 per frame.
	// Inside an async readback callback they are those of the callback's own frame.
	void capture_timestamp(const String &p_name);
	// The serial (get_frames_submitted() numbering) of the frame the captured timestamps belong to
	// (Godot: get_captured_timestamps_frame); 0 before any.
	uint64_t get_captured_timestamps_frame() const;
	uint32_t get_captured_timestamps_count() const;
	// Nanoseconds on the GPU clock (raw ticks * timestampPeriod); monotonic within a frame.
	uint64_t get_captured_timestamp_gpu_time(uint32_t p_index) const;
	String get_captured_timestamp_name(uint32_t p_index) const;

	/****************/
	/**** LABELS ****/
	/****************/

	// Names the commands recorded until the matching end label (VK_EXT_debug_utils: the pass name in
	// RenderDoc, Nsight and validation messages; without the extension only the name is kept). Labels
	// nest; not inside a draw or compute list. A frame submitted with labels open closes them (error).
	void draw_command_begin_label(const String &p_name, const Color &p_color = Color(1, 1, 1, 1));
	void draw_command_end_label();
	// The labels opened in the last submitted frame, in order of their begin.
	const std::vector<String> &get_captured_label_names() const;

	/***************/
	/**** MISC  ****/
	/***************/

	// Frees any RID created by this device (deferred; see top). Dependents are freed too.
	void free(RID p_rid);
	// Debug name via VK_EXT_debug_utils (no-op without it).
	void set_resource_name(RID p_rid, const String &p_name);

	// Chooses a device (discrete > integrated > virtual > CPU; GODOT_AREA_DEVICE overrides).
	bool initialize(String *r_error = nullptr);

	// Window presentation (the editor, editor/editor_node.h): extra Vulkan instance and device
	// extensions that the next initialize() enables, e.g. VK_KHR_surface + VK_KHR_xlib_surface and
	// VK_KHR_swapchain. initialize() fails with a message naming any the driver lacks. Empty by
	// default (headless); the list is used once and then cleared.
	static void set_extra_extensions(const std::vector<String> &p_instance_extensions, const std::vector<String> &p_device_extensions);
	// Raw handles (VkInstance, VkPhysicalDevice, VkDevice, VkQueue) for a presenter that shares this
	// device and its queue from the same thread; null before initialize().
	struct VulkanHandles {
		void *instance = nullptr;
		void *physical_device = nullptr;
		void *device = nullptr;
		void *queue = nullptr;
		uint32_t queue_family = 0;
	};
	VulkanHandles get_vulkan_handles() const;
	// Waits for idle, destroys everything; RIDs not freed by the user are reported as leaks.
	void finalize();
	bool is_initialized() const;

	const DeviceInfo &get_device_info() const;
	// Multi-line human-readable text for the `info` CLI command.
	String get_device_info_string() const;

	// Validation messages (errors/warnings) seen by the debug messenger since initialize().
	uint32_t get_validation_error_count() const;
	uint32_t get_validation_warning_count() const;
	// Sets both counters back to zero (tests that provoke a validation error on purpose).
	void reset_validation_counts();
	// Number of frames submitted so far; also the serial of the newest submitted frame.
	uint64_t get_frames_submitted() const;

	static RenderingDevice *get_singleton();

	RenderingDevice(); // Becomes the singleton.
	~RenderingDevice(); // Calls finalize() if needed.

	struct Impl; // Vulkan state, defined in rendering_device.cpp.

private:
	static RenderingDevice *singleton;
	Impl *impl = nullptr;

	RenderingDevice(const RenderingDevice &) = delete;
	RenderingDevice &operator=(const RenderingDevice &) = delete;
};

typedef RenderingDevice RD;
