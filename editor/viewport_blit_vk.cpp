/**************************************************************************/
/*  viewport_blit_vk.cpp                                                  */
/**************************************************************************/
/* godot-area: see viewport_blit_vk.h. The fragment shader's tonemap is   */
/* core/io/tonemap.cpp's (same published curves and constants, cited     */
/* there), in float instead of double.                                    */

#include "editor/viewport_blit_vk.h"

#ifdef GODOT_AREA_EDITOR_WINDOW

#include "core/error/error_macros.h"

#include <imgui.h>

#include <algorithm>

namespace {

struct PushConstants {
	float rect[4]; // x, y, w, h (framebuffer pixels).
	float fb_size[2];
	int32_t mode; // Tonemap::Mode.
	float exposure;
	float white;
	float pad[3];
};
static_assert(sizeof(PushConstants) == 48, "PushConstants must match the GLSL block.");

const char *VERTEX_SHADER = R"GLSL(#version 450
layout(push_constant, std430) uniform Params {
	vec4 rect;
	vec2 fb_size;
	int mode;
	float exposure;
	float white;
} params;
void main() {
	vec2 uv = vec2(float(gl_VertexIndex & 1), float(gl_VertexIndex >> 1));
	vec2 pixel = params.rect.xy + uv * params.rect.zw;
	gl_Position = vec4(pixel / params.fb_size * 2.0 - 1.0, 0.0, 1.0);
}
)GLSL";

const char *FRAGMENT_SHADER = R"GLSL(#version 450
layout(push_constant, std430) uniform Params {
	vec4 rect;
	vec2 fb_size;
	int mode;
	float exposure;
	float white;
} params;
layout(set = 0, binding = 0) uniform sampler2D scene_texture;
layout(set = 0, binding = 1) uniform sampler2D overlay_texture;
layout(location = 0) out vec4 frag_color;

// Tonemap::Mode.
#define MODE_LINEAR 0
#define MODE_ACES_FITTED 1
#define MODE_REINHARD 2
#define MODE_FILMIC 3
#define MODE_ACES 4
#define MODE_AGX 5

float hable(float x) {
	const float A = 0.22, B = 0.30, C = 0.10, D = 0.20, E = 0.01, F = 0.30;
	return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

float aces_rrt_odt(float x) {
	return (x * (x + 0.0245786) - 0.000090537) / (x * (0.983729 * x + 0.432951) + 0.238081);
}

vec3 map_linear(vec3 c) {
	vec3 x;
	for (int i = 0; i < 3; i++) {
		float v = c[i];
		v = (isnan(v) || !(v > 0.0)) ? 0.0 : v * params.exposure;
		x[i] = (isinf(v) || isnan(v)) ? 1e30 : v;
	}
	if (params.mode == MODE_ACES_FITTED) {
		x = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
		x = min(x, vec3(1.0));
		x = mix(x, vec3(1.0), greaterThanEqual(c * params.exposure, vec3(1e15)));
	} else if (params.mode == MODE_REINHARD) {
		float w2 = params.white * params.white;
		vec3 r = x * (1.0 + x / w2) / (1.0 + x);
		x = mix(r, vec3(1.0), greaterThanEqual(x, vec3(1e15)));
	} else if (params.mode == MODE_FILMIC) {
		// Godot's exposure bias 2 on the input and the white point; huge inputs reach the limit.
		x = min(x, vec3(1e15));
		float w = hable(2.0 * params.white);
		x = vec3(hable(2.0 * x.r), hable(2.0 * x.g), hable(2.0 * x.b)) / w;
	} else if (params.mode == MODE_ACES) {
		const mat3 aces_input = transpose(mat3(0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777));
		const mat3 aces_output = transpose(mat3(1.60475, -0.53108, -0.07367, -0.10208, 1.10813, -0.00605, -0.00327, -0.07276, 1.07602));
		vec3 rrt = aces_input * (min(x, vec3(1e15)) * 1.8);
		vec3 curve = vec3(aces_rrt_odt(rrt.r), aces_rrt_odt(rrt.g), aces_rrt_odt(rrt.b));
		x = (aces_output * curve) / aces_rrt_odt(params.white * 1.8);
	} else if (params.mode == MODE_AGX) {
		const mat3 agx_inset = transpose(mat3(0.842479062253094, 0.0784335999999992, 0.0792237451477643, 0.0423282422610123, 0.878468636469772, 0.0791661274605434, 0.0423756549057051, 0.0784336, 0.879142973793104));
		const mat3 agx_outset = transpose(mat3(1.19687900512017, -0.0980208811401368, -0.0990297440797205, -0.0528968517574562, 1.15190312990417, -0.0989611768448433, -0.0529716355144438, -0.0980434501171241, 1.15107367264116));
		const float min_ev = -12.47393, max_ev = 4.026069;
		vec3 ev = clamp(log2(max(agx_inset * x, vec3(1e-10))), vec3(min_ev), vec3(max_ev));
		vec3 t = (ev - min_ev) / (max_ev - min_ev);
		vec3 t2 = t * t, t4 = t2 * t2;
		vec3 curve = 15.5 * t4 * t2 - 40.14 * t4 * t + 31.96 * t4 - 6.868 * t2 * t + 0.4298 * t2 + 0.1191 * t - 0.00232;
		x = pow(max(agx_outset * curve, vec3(0.0)), vec3(2.2));
	}
	return clamp(x, vec3(0.0), vec3(1.0));
}

vec3 linear_to_srgb(vec3 x) {
	return mix(1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055, 12.92 * x, lessThanEqual(x, vec3(0.0031308)));
}

void main() {
	// One texel per framebuffer pixel: the panel and the viewport have the same size.
	ivec2 size = textureSize(scene_texture, 0);
	ivec2 texel = clamp(ivec2(floor(gl_FragCoord.xy - params.rect.xy)), ivec2(0), size - 1);
	vec3 scene = texelFetch(scene_texture, texel, 0).rgb;
	vec4 gizmos = texelFetch(overlay_texture, clamp(texel, ivec2(0), textureSize(overlay_texture, 0) - 1), 0);
	vec3 linear = scene * (1.0 - gizmos.a) + gizmos.rgb;
	frag_color = vec4(linear_to_srgb(map_linear(linear)), 1.0);
}
)GLSL";

VkShaderModule _module(VkDevice p_device, const std::vector<uint32_t> &p_spirv) {
	VkShaderModuleCreateInfo ci = { VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO };
	ci.codeSize = p_spirv.size() * sizeof(uint32_t);
	ci.pCode = p_spirv.data();
	VkShaderModule m = VK_NULL_HANDLE;
	vkCreateShaderModule(p_device, &ci, nullptr, &m);
	return m;
}

} // namespace

bool ViewportBlitVK::create(RenderingDevice *p_rd, VkRenderPass p_render_pass, String *r_error) {
	ERR_FAIL_COND_V_MSG(device != VK_NULL_HANDLE, false, "ViewportBlitVK::create: already created.");
	device = (VkDevice)p_rd->get_vulkan_handles().device;
	String error;
	std::vector<uint32_t> vs = p_rd->shader_compile_spirv_from_source(RenderingDevice::SHADER_STAGE_VERTEX, VERTEX_SHADER, "viewport_blit.vert", &error);
	std::vector<uint32_t> fs = vs.empty() ? std::vector<uint32_t>() : p_rd->shader_compile_spirv_from_source(RenderingDevice::SHADER_STAGE_FRAGMENT, FRAGMENT_SHADER, "viewport_blit.frag", &error);
	if (vs.empty() || fs.empty()) {
		*r_error = "ViewportBlitVK: the viewport shader does not compile: " + error;
		destroy();
		return false;
	}
	VkSamplerCreateInfo sci = { VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO };
	sci.magFilter = VK_FILTER_NEAREST;
	sci.minFilter = VK_FILTER_NEAREST;
	sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
	sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
	sci.maxLod = 0.0f;
	vkCreateSampler(device, &sci, nullptr, &sampler);

	VkDescriptorSetLayoutBinding bindings[2] = {};
	for (uint32_t i = 0; i < 2; i++) {
		bindings[i].binding = i;
		bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
		bindings[i].descriptorCount = 1;
		bindings[i].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
	}
	VkDescriptorSetLayoutCreateInfo lci = { VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO };
	lci.bindingCount = 2;
	lci.pBindings = bindings;
	vkCreateDescriptorSetLayout(device, &lci, nullptr, &set_layout);
	VkPushConstantRange range = { VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(PushConstants) };
	VkPipelineLayoutCreateInfo plci = { VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO };
	plci.setLayoutCount = 1;
	plci.pSetLayouts = &set_layout;
	plci.pushConstantRangeCount = 1;
	plci.pPushConstantRanges = &range;
	vkCreatePipelineLayout(device, &plci, nullptr, &pipeline_layout);

	VkDescriptorPoolSize ps = { VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 };
	VkDescriptorPoolCreateInfo dpci = { VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO };
	dpci.maxSets = 1;
	dpci.poolSizeCount = 1;
	dpci.pPoolSizes = &ps;
	vkCreateDescriptorPool(device, &dpci, nullptr, &pool);
	VkDescriptorSetAllocateInfo dsai = { VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO };
	dsai.descriptorPool = pool;
	dsai.descriptorSetCount = 1;
	dsai.pSetLayouts = &set_layout;
	vkAllocateDescriptorSets(device, &dsai, &set);

	VkShaderModule vsm = _module(device, vs), fsm = _module(device, fs);
	VkPipelineShaderStageCreateInfo stages[2] = { { VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO }, { VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO } };
	stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
	stages[0].module = vsm;
	stages[0].pName = "main";
	stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
	stages[1].module = fsm;
	stages[1].pName = "main";
	VkPipelineVertexInputStateCreateInfo vi = { VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO };
	VkPipelineInputAssemblyStateCreateInfo ia = { VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO };
	ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
	VkPipelineViewportStateCreateInfo vps = { VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO };
	vps.viewportCount = 1;
	vps.scissorCount = 1;
	VkPipelineRasterizationStateCreateInfo rs = { VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO };
	rs.polygonMode = VK_POLYGON_MODE_FILL;
	rs.cullMode = VK_CULL_MODE_NONE;
	rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
	rs.lineWidth = 1.0f;
	VkPipelineMultisampleStateCreateInfo ms = { VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO };
	ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
	VkPipelineColorBlendAttachmentState att = {};
	att.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
	VkPipelineColorBlendStateCreateInfo cb = { VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO };
	cb.attachmentCount = 1;
	cb.pAttachments = &att;
	VkDynamicState dyn[2] = { VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR };
	VkPipelineDynamicStateCreateInfo ds = { VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO };
	ds.dynamicStateCount = 2;
	ds.pDynamicStates = dyn;
	VkGraphicsPipelineCreateInfo gpci = { VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO };
	gpci.stageCount = 2;
	gpci.pStages = stages;
	gpci.pVertexInputState = &vi;
	gpci.pInputAssemblyState = &ia;
	gpci.pViewportState = &vps;
	gpci.pRasterizationState = &rs;
	gpci.pMultisampleState = &ms;
	gpci.pColorBlendState = &cb;
	gpci.pDynamicState = &ds;
	gpci.layout = pipeline_layout;
	gpci.renderPass = p_render_pass;
	gpci.subpass = 0;
	VkResult res = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &gpci, nullptr, &pipeline);
	vkDestroyShaderModule(device, vsm, nullptr);
	vkDestroyShaderModule(device, fsm, nullptr);
	if (res != VK_SUCCESS || !sampler || !set) {
		*r_error = vformat("ViewportBlitVK: cannot create the viewport pipeline (VkResult %d).", res);
		destroy();
		return false;
	}
	return true;
}

void ViewportBlitVK::destroy() {
	if (!device) {
		return;
	}
	if (pipeline) {
		vkDestroyPipeline(device, pipeline, nullptr);
	}
	if (pool) {
		vkDestroyDescriptorPool(device, pool, nullptr); // Frees the set.
	}
	if (pipeline_layout) {
		vkDestroyPipelineLayout(device, pipeline_layout, nullptr);
	}
	if (set_layout) {
		vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
	}
	if (sampler) {
		vkDestroySampler(device, sampler, nullptr);
	}
	pipeline = VK_NULL_HANDLE;
	pool = VK_NULL_HANDLE;
	set = VK_NULL_HANDLE;
	pipeline_layout = VK_NULL_HANDLE;
	set_layout = VK_NULL_HANDLE;
	sampler = VK_NULL_HANDLE;
	bound_scene = bound_overlay = VK_NULL_HANDLE;
	device = VK_NULL_HANDLE;
}

bool ViewportBlitVK::begin_frame(VkCommandBuffer p_command_buffer, int p_fb_width, int p_fb_height, RenderingDevice *p_rd, RID p_scene, RID p_overlay, const Tonemap::Settings &p_tonemap) {
	ready = false;
	command_buffer = p_command_buffer;
	fb_width = p_fb_width;
	fb_height = p_fb_height;
	tonemap = p_tonemap;
	if (!device || !p_rd || !p_rd->texture_is_valid(p_scene) || !p_rd->texture_is_valid(p_overlay)) {
		return false;
	}
	VkImageView scene = (VkImageView)p_rd->get_driver_resource(RenderingDevice::DRIVER_RESOURCE_TEXTURE_VIEW, p_scene);
	VkImageView overlay = (VkImageView)p_rd->get_driver_resource(RenderingDevice::DRIVER_RESOURCE_TEXTURE_VIEW, p_overlay);
	if (scene != bound_scene || overlay != bound_overlay) {
		// The previous frame has finished (begin_frame of the swapchain waited), so the set is free.
		VkDescriptorImageInfo infos[2] = { { sampler, scene, VK_IMAGE_LAYOUT_GENERAL }, { sampler, overlay, VK_IMAGE_LAYOUT_GENERAL } };
		VkWriteDescriptorSet writes[2] = { { VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET }, { VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET } };
		for (uint32_t i = 0; i < 2; i++) {
			writes[i].dstSet = set;
			writes[i].dstBinding = i;
			writes[i].descriptorCount = 1;
			writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
			writes[i].pImageInfo = &infos[i];
		}
		vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
		bound_scene = scene;
		bound_overlay = overlay;
	}
	// The RenderingDevice's frame (render, overlay upload) was submitted earlier on this queue.
	VkMemoryBarrier mb = { VK_STRUCTURE_TYPE_MEMORY_BARRIER };
	mb.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
	mb.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
	vkCmdPipelineBarrier(command_buffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 1, &mb, 0, nullptr, 0, nullptr);
	ready = true;
	return true;
}

void ViewportBlitVK::_callback(const ImDrawList *p_list, const ImDrawCmd *p_cmd) {
	const ImDrawCmd *cmd = p_cmd;
	ViewportBlitVK *self = (ViewportBlitVK *)cmd->UserCallbackData;
	if (!self || !self->ready || !self->command_buffer) {
		return;
	}
	// The panel's clip rectangle, clamped to the framebuffer (ImGui's DisplayPos is 0, scale 1).
	const float x0 = std::max(0.0f, cmd->ClipRect.x), y0 = std::max(0.0f, cmd->ClipRect.y);
	const float x1 = std::min((float)self->fb_width, cmd->ClipRect.z), y1 = std::min((float)self->fb_height, cmd->ClipRect.w);
	if (x1 <= x0 || y1 <= y0) {
		return;
	}
	VkCommandBuffer cb = self->command_buffer;
	vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, self->pipeline);
	VkViewport vp = { 0, 0, (float)self->fb_width, (float)self->fb_height, 0, 1 };
	vkCmdSetViewport(cb, 0, 1, &vp);
	VkRect2D scissor = { { (int32_t)x0, (int32_t)y0 }, { (uint32_t)(x1 - x0), (uint32_t)(y1 - y0) } };
	vkCmdSetScissor(cb, 0, 1, &scissor);
	vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, self->pipeline_layout, 0, 1, &self->set, 0, nullptr);
	PushConstants pc = {};
	for (int i = 0; i < 4; i++) {
		pc.rect[i] = self->rect[i];
	}
	pc.fb_size[0] = (float)self->fb_width;
	pc.fb_size[1] = (float)self->fb_height;
	pc.mode = (int32_t)self->tonemap.mode;
	pc.exposure = self->tonemap.exposure;
	pc.white = self->tonemap.white;
	vkCmdPushConstants(cb, self->pipeline_layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(pc), &pc);
	vkCmdDraw(cb, 4, 1, 0, 0);
	self->draws++;
}

void ViewportBlitVK::add_to_draw_list(ImDrawList *p_list, float p_x, float p_y, float p_w, float p_h) {
	rect[0] = p_x;
	rect[1] = p_y;
	rect[2] = p_w;
	rect[3] = p_h;
	p_list->AddCallback(&ViewportBlitVK::_callback, this);
	p_list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
}

#else

bool ViewportBlitVK::create(RenderingDevice *p_rd, VkRenderPass p_render_pass, String *r_error) {
	return false;
}
void ViewportBlitVK::destroy() {}
bool ViewportBlitVK::begin_frame(VkCommandBuffer p_command_buffer, int p_fb_width, int p_fb_height, RenderingDevice *p_rd, RID p_scene, RID p_overlay, const Tonemap::Settings &p_tonemap) {
	return false;
}
void ViewportBlitVK::add_to_draw_list(ImDrawList *p_list, float p_x, float p_y, float p_w, float p_h) {}

#endif
