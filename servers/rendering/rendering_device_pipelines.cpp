/**************************************************************************/
/*  rendering_device_pipelines.cpp                                        */
/**************************************************************************/
/* RenderingDevice: GLSL compilation, shaders + reflection, uniform sets, */
/* framebuffer/vertex formats, framebuffers, vertex/index arrays and      */
/* pipelines.                                                             */

#include "servers/rendering/rendering_device.h"

#include "drivers/vulkan/spirv_reflection.h"
#include "servers/rendering/rendering_device_impl.h"

#include <glslang/Include/glslang_c_interface.h>
#include <glslang/Public/resource_limits_c.h>

#include <algorithm>
#include <cstring>
#include <mutex>

typedef RenderingDevice::Impl RDImpl;

/*****************/
/**** SHADERS ****/
/*****************/

// glslang's C interface is used: glslang is built without RTTI, and its C++ classes would make
// UBSan (-fsanitize=vptr) builds fail to link.
std::vector<uint32_t> RenderingDevice::shader_compile_spirv_from_source(ShaderStage p_stage, const String &p_source, const String &p_name, String *r_error) {
	static std::once_flag glslang_once;
	std::call_once(glslang_once, []() { glslang_initialize_process(); });
	String dummy;
	String &err = r_error ? *r_error : dummy;
	err.clear();
	glslang_stage_t stage;
	switch (p_stage) {
		case SHADER_STAGE_VERTEX:
			stage = GLSLANG_STAGE_VERTEX;
			break;
		case SHADER_STAGE_FRAGMENT:
			stage = GLSLANG_STAGE_FRAGMENT;
			break;
		case SHADER_STAGE_COMPUTE:
			stage = GLSLANG_STAGE_COMPUTE;
			break;
		default:
			err = "Invalid shader stage.";
			ERR_FAIL_V_MSG(std::vector<uint32_t>(), err);
	}
	String name = p_name.empty() ? String("shader") : p_name;
	glslang_input_t input;
	memset(&input, 0, sizeof(input));
	input.language = GLSLANG_SOURCE_GLSL;
	input.stage = stage;
	input.client = GLSLANG_CLIENT_VULKAN;
	input.client_version = GLSLANG_TARGET_VULKAN_1_1;
	input.target_language = GLSLANG_TARGET_SPV;
	input.target_language_version = GLSLANG_TARGET_SPV_1_3;
	input.code = p_source.c_str();
	input.default_version = 450;
	input.default_profile = GLSLANG_NO_PROFILE;
	input.force_default_version_and_profile = 0;
	input.forward_compatible = 0;
	input.messages = (glslang_messages_t)(GLSLANG_MSG_SPV_RULES_BIT | GLSLANG_MSG_VULKAN_RULES_BIT);
	input.resource = glslang_default_resource();

	glslang_shader_t *shader = glslang_shader_create(&input);
	if (!shader) {
		err = "glslang_shader_create failed.";
		return std::vector<uint32_t>();
	}
	std::vector<uint32_t> spirv;
	if (!glslang_shader_preprocess(shader, &input) || !glslang_shader_parse(shader, &input)) {
		err = vformat("%s shader compilation failed (%s):\n%s", get_shader_stage_name(p_stage), name.c_str(), glslang_shader_get_info_log(shader));
		glslang_shader_delete(shader);
		return spirv;
	}
	glslang_program_t *program = glslang_program_create();
	glslang_program_add_shader(program, shader);
	if (!glslang_program_link(program, GLSLANG_MSG_SPV_RULES_BIT | GLSLANG_MSG_VULKAN_RULES_BIT)) {
		err = vformat("%s shader link failed (%s):\n%s", get_shader_stage_name(p_stage), name.c_str(), glslang_program_get_info_log(program));
	} else {
		glslang_spv_options_t options;
		memset(&options, 0, sizeof(options));
		options.disable_optimizer = true;
		glslang_program_SPIRV_generate_with_options(program, stage, &options);
		size_t words = glslang_program_SPIRV_get_size(program);
		if (words > 0) {
			spirv.resize(words);
			glslang_program_SPIRV_get(program, spirv.data());
		} else {
			const char *msgs = glslang_program_SPIRV_get_messages(program);
			err = vformat("SPIR-V generation failed (%s): %s", name.c_str(), msgs ? msgs : "");
		}
	}
	glslang_program_delete(program);
	glslang_shader_delete(shader);
	return spirv;
}

String RDImpl::make_set_key(const std::vector<SetLayoutBinding> &p_bindings) {
	String key;
	for (const SetLayoutBinding &b : p_bindings) {
		key += vformat("%u:%d:%u;", b.binding, (int)b.type, b.count);
	}
	return key;
}

static VkDescriptorType uniform_type_to_vk(RenderingDevice::UniformType p_type) {
	switch (p_type) {
		case RenderingDevice::UNIFORM_TYPE_SAMPLER:
			return VK_DESCRIPTOR_TYPE_SAMPLER;
		case RenderingDevice::UNIFORM_TYPE_SAMPLER_WITH_TEXTURE:
			return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
		case RenderingDevice::UNIFORM_TYPE_TEXTURE:
			return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
		case RenderingDevice::UNIFORM_TYPE_IMAGE:
			return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
		case RenderingDevice::UNIFORM_TYPE_UNIFORM_BUFFER:
			return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
		default:
			return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
	}
}

static const char *uniform_type_name(RenderingDevice::UniformType p_type) {
	static const char *names[] = { "sampler", "sampler with texture", "texture", "image", "uniform buffer", "storage buffer" };
	return (p_type >= 0 && p_type < RenderingDevice::UNIFORM_TYPE_MAX) ? names[p_type] : "invalid";
}

VkDescriptorSetLayout RDImpl::get_set_layout(const std::vector<SetLayoutBinding> &p_bindings, const String &p_key) {
	auto it = set_layout_cache.find(p_key);
	if (it != set_layout_cache.end()) {
		return it->second;
	}
	std::vector<VkDescriptorSetLayoutBinding> vk_bindings;
	for (const SetLayoutBinding &b : p_bindings) {
		VkDescriptorSetLayoutBinding lb = {};
		lb.binding = b.binding;
		lb.descriptorType = uniform_type_to_vk(b.type);
		lb.descriptorCount = b.count;
		lb.stageFlags = VK_SHADER_STAGE_ALL;
		vk_bindings.push_back(lb);
	}
	VkDescriptorSetLayoutCreateInfo ci = { VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO };
	ci.bindingCount = (uint32_t)vk_bindings.size();
	ci.pBindings = vk_bindings.data();
	VkDescriptorSetLayout layout = VK_NULL_HANDLE;
	VkResult res = vkCreateDescriptorSetLayout(device, &ci, nullptr, &layout);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, VK_NULL_HANDLE, vformat("vkCreateDescriptorSetLayout failed (VkResult %d).", res));
	set_layout_cache[p_key] = layout;
	return layout;
}

RID RenderingDevice::shader_create_from_spirv(const std::vector<ShaderStageSPIRVData> &p_stages, const String &p_name) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, RID(), "RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(p_stages.empty(), RID(), vformat("shader_create_from_spirv(%s): no stages given.", p_name.c_str()));
	bool stage_present[SHADER_STAGE_MAX] = {};
	for (const ShaderStageSPIRVData &st : p_stages) {
		ERR_FAIL_COND_V_MSG(st.shader_stage < 0 || st.shader_stage >= SHADER_STAGE_MAX, RID(), "shader_create_from_spirv: invalid stage.");
		ERR_FAIL_COND_V_MSG(stage_present[st.shader_stage], RID(), vformat("shader_create_from_spirv(%s): stage %s given twice.", p_name.c_str(), get_shader_stage_name(st.shader_stage)));
		ERR_FAIL_COND_V_MSG(st.spirv.empty(), RID(), vformat("shader_create_from_spirv(%s): empty SPIR-V for stage %s.", p_name.c_str(), get_shader_stage_name(st.shader_stage)));
		stage_present[st.shader_stage] = true;
	}
	bool compute = stage_present[SHADER_STAGE_COMPUTE];
	ERR_FAIL_COND_V_MSG(compute && p_stages.size() != 1, RID(), vformat("shader_create_from_spirv(%s): a compute shader cannot have other stages.", p_name.c_str()));
	ERR_FAIL_COND_V_MSG(!compute && !stage_present[SHADER_STAGE_VERTEX], RID(), vformat("shader_create_from_spirv(%s): a render shader needs a vertex stage.", p_name.c_str()));

	Impl::Shader sh;
	sh.name = p_name;
	sh.is_compute = compute;
	static const VkShaderStageFlagBits vk_stages[] = { VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_FRAGMENT_BIT, VK_SHADER_STAGE_COMPUTE_BIT };

	// Reflect and merge.
	std::vector<std::vector<Impl::SetLayoutBinding>> sets;
	for (const ShaderStageSPIRVData &st : p_stages) {
		SPIRVReflection refl;
		String err;
		ERR_FAIL_COND_V_MSG(!refl.parse(st.spirv, err), RID(), vformat("shader_create_from_spirv(%s), %s stage: %s", p_name.c_str(), get_shader_stage_name(st.shader_stage), err.c_str()));
		sh.stage_flags |= vk_stages[st.shader_stage];
		sh.push_constant_size = std::max(sh.push_constant_size, refl.push_constant_size);
		if (st.shader_stage == SHADER_STAGE_COMPUTE) {
			for (int i = 0; i < 3; i++) {
				sh.local_size[i] = refl.local_size[i];
			}
		}
		for (const SPIRVReflection::Binding &b : refl.bindings) {
			ERR_FAIL_COND_V_MSG(b.set >= s->properties.limits.maxBoundDescriptorSets, RID(), vformat("shader_create_from_spirv(%s): set %u exceeds the device limit.", p_name.c_str(), b.set));
			if (sets.size() <= b.set) {
				sets.resize(b.set + 1);
			}
			static const UniformType kinds[] = { UNIFORM_TYPE_SAMPLER, UNIFORM_TYPE_SAMPLER_WITH_TEXTURE, UNIFORM_TYPE_TEXTURE, UNIFORM_TYPE_IMAGE, UNIFORM_TYPE_UNIFORM_BUFFER, UNIFORM_TYPE_STORAGE_BUFFER };
			Impl::SetLayoutBinding lb;
			lb.binding = b.binding;
			lb.type = kinds[b.kind];
			lb.count = b.count;
			bool found = false;
			for (const Impl::SetLayoutBinding &existing : sets[b.set]) {
				if (existing.binding == b.binding) {
					ERR_FAIL_COND_V_MSG(!(existing == lb), RID(), vformat("shader_create_from_spirv(%s): set %u binding %u is declared differently in two stages.", p_name.c_str(), b.set, b.binding));
					found = true;
				}
			}
			if (!found) {
				sets[b.set].push_back(lb);
			}
		}
	}
	ERR_FAIL_COND_V_MSG(sh.push_constant_size > s->properties.limits.maxPushConstantsSize, RID(), vformat("shader_create_from_spirv(%s): push constant block of %u bytes exceeds the device limit %u.", p_name.c_str(), sh.push_constant_size, s->properties.limits.maxPushConstantsSize));

	std::vector<VkDescriptorSetLayout> layouts;
	for (std::vector<Impl::SetLayoutBinding> &set : sets) {
		std::sort(set.begin(), set.end(), [](const Impl::SetLayoutBinding &a, const Impl::SetLayoutBinding &b) { return a.binding < b.binding; });
		String key = Impl::make_set_key(set);
		VkDescriptorSetLayout l = s->get_set_layout(set, key);
		ERR_FAIL_COND_V(l == VK_NULL_HANDLE, RID());
		sh.set_keys.push_back(key);
		layouts.push_back(l);
	}
	sh.sets = sets;
	sh.set_layouts = layouts;

	VkPipelineLayoutCreateInfo plci = { VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO };
	plci.setLayoutCount = (uint32_t)layouts.size();
	plci.pSetLayouts = layouts.data();
	VkPushConstantRange range = { sh.stage_flags, 0, sh.push_constant_size };
	if (sh.push_constant_size > 0) {
		plci.pushConstantRangeCount = 1;
		plci.pPushConstantRanges = &range;
	}
	VkResult res = vkCreatePipelineLayout(s->device, &plci, nullptr, &sh.pipeline_layout);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreatePipelineLayout failed (VkResult %d).", res));

	for (const ShaderStageSPIRVData &st : p_stages) {
		VkShaderModuleCreateInfo mci = { VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO };
		mci.codeSize = st.spirv.size() * sizeof(uint32_t);
		mci.pCode = st.spirv.data();
		res = vkCreateShaderModule(s->device, &mci, nullptr, &sh.modules[st.shader_stage]);
		if (res != VK_SUCCESS) {
			for (VkShaderModule m : sh.modules) {
				if (m) {
					vkDestroyShaderModule(s->device, m, nullptr);
				}
			}
			vkDestroyPipelineLayout(s->device, sh.pipeline_layout, nullptr);
			ERR_FAIL_V_MSG(RID(), vformat("vkCreateShaderModule failed (VkResult %d) for %s.", res, p_name.c_str()));
		}
		if (!p_name.empty()) {
			s->name_object(VK_OBJECT_TYPE_SHADER_MODULE, (uint64_t)sh.modules[st.shader_stage], p_name + ":" + get_shader_stage_name(st.shader_stage));
		}
	}
	return s->shader_owner.make_rid(sh);
}

uint32_t RenderingDevice::shader_get_push_constant_size(RID p_shader) const {
	Impl::Shader *sh = impl->shader_owner.get_or_null(p_shader);
	ERR_FAIL_NULL_V_MSG(sh, 0, "shader_get_push_constant_size: invalid shader RID.");
	return sh->push_constant_size;
}

bool RenderingDevice::shader_is_compute(RID p_shader) const {
	Impl::Shader *sh = impl->shader_owner.get_or_null(p_shader);
	ERR_FAIL_NULL_V_MSG(sh, false, "shader_is_compute: invalid shader RID.");
	return sh->is_compute;
}

/**********************/
/**** UNIFORM SETS ****/
/**********************/

RID RenderingDevice::uniform_set_create(const std::vector<Uniform> &p_uniforms, RID p_shader, uint32_t p_set_index) {
	Impl *s = impl;
	Impl::Shader *sh = s->shader_owner.get_or_null(p_shader);
	ERR_FAIL_NULL_V_MSG(sh, RID(), "uniform_set_create: invalid shader RID.");
	ERR_FAIL_COND_V_MSG(p_set_index >= sh->sets.size() || sh->sets[p_set_index].empty(), RID(), vformat("uniform_set_create: shader '%s' declares no uniforms in set %u.", sh->name.c_str(), p_set_index));
	const std::vector<Impl::SetLayoutBinding> &layout = sh->sets[p_set_index];

	// Descriptor writes (stored so the info arrays stay alive).
	std::vector<VkDescriptorImageInfo> image_infos;
	std::vector<VkDescriptorBufferInfo> buffer_infos;
	struct PendingWrite {
		uint32_t binding;
		VkDescriptorType type;
		uint32_t count;
		size_t first;
		bool is_image;
	};
	std::vector<PendingWrite> writes;
	std::vector<RID> deps;
	uint32_t pool_counts[UNIFORM_TYPE_MAX] = {};

	for (const Impl::SetLayoutBinding &lb : layout) {
		const Uniform *u = nullptr;
		for (const Uniform &cand : p_uniforms) {
			if (cand.binding == lb.binding) {
				u = &cand;
			}
		}
		ERR_FAIL_NULL_V_MSG(u, RID(), vformat("uniform_set_create: shader '%s' set %u binding %u (%s) was not supplied.", sh->name.c_str(), p_set_index, lb.binding, uniform_type_name(lb.type)));
		ERR_FAIL_COND_V_MSG(u->uniform_type != lb.type, RID(), vformat("uniform_set_create: shader '%s' set %u binding %u expects a %s, got a %s.", sh->name.c_str(), p_set_index, lb.binding, uniform_type_name(lb.type), uniform_type_name(u->uniform_type)));
		uint32_t per_element = lb.type == UNIFORM_TYPE_SAMPLER_WITH_TEXTURE ? 2 : 1;
		ERR_FAIL_COND_V_MSG(u->ids.size() != lb.count * per_element, RID(), vformat("uniform_set_create: set %u binding %u needs %u ids, got %zu.", p_set_index, lb.binding, lb.count * per_element, u->ids.size()));
		PendingWrite w;
		w.binding = lb.binding;
		w.type = uniform_type_to_vk(lb.type);
		w.count = lb.count;
		w.is_image = lb.type != UNIFORM_TYPE_UNIFORM_BUFFER && lb.type != UNIFORM_TYPE_STORAGE_BUFFER;
		w.first = w.is_image ? image_infos.size() : buffer_infos.size();
		pool_counts[lb.type] += lb.count;
		for (uint32_t i = 0; i < lb.count; i++) {
			switch (lb.type) {
				case UNIFORM_TYPE_SAMPLER: {
					Impl::Sampler *smp = s->sampler_owner.get_or_null(u->ids[i]);
					ERR_FAIL_NULL_V_MSG(smp, RID(), vformat("uniform_set_create: binding %u: invalid sampler RID.", lb.binding));
					image_infos.push_back({ smp->sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED });
					deps.push_back(u->ids[i]);
				} break;
				case UNIFORM_TYPE_SAMPLER_WITH_TEXTURE: {
					Impl::Sampler *smp = s->sampler_owner.get_or_null(u->ids[i * 2 + 0]);
					Impl::Texture *t = s->texture_owner.get_or_null(u->ids[i * 2 + 1]);
					ERR_FAIL_NULL_V_MSG(smp, RID(), vformat("uniform_set_create: binding %u: invalid sampler RID (ids are sampler, texture pairs).", lb.binding));
					ERR_FAIL_NULL_V_MSG(t, RID(), vformat("uniform_set_create: binding %u: invalid texture RID (ids are sampler, texture pairs).", lb.binding));
					ERR_FAIL_COND_V_MSG(!(t->format.usage_bits & TEXTURE_USAGE_SAMPLING_BIT), RID(), vformat("uniform_set_create: binding %u: texture lacks TEXTURE_USAGE_SAMPLING_BIT.", lb.binding));
					image_infos.push_back({ smp->sampler, t->view, VK_IMAGE_LAYOUT_GENERAL });
					deps.push_back(u->ids[i * 2 + 0]);
					deps.push_back(u->ids[i * 2 + 1]);
				} break;
				case UNIFORM_TYPE_TEXTURE:
				case UNIFORM_TYPE_IMAGE: {
					Impl::Texture *t = s->texture_owner.get_or_null(u->ids[i]);
					ERR_FAIL_NULL_V_MSG(t, RID(), vformat("uniform_set_create: binding %u: invalid texture RID.", lb.binding));
					uint32_t needed = lb.type == UNIFORM_TYPE_IMAGE ? TEXTURE_USAGE_STORAGE_BIT : TEXTURE_USAGE_SAMPLING_BIT;
					ERR_FAIL_COND_V_MSG(!(t->format.usage_bits & needed), RID(), vformat("uniform_set_create: binding %u: texture lacks %s.", lb.binding, lb.type == UNIFORM_TYPE_IMAGE ? "TEXTURE_USAGE_STORAGE_BIT" : "TEXTURE_USAGE_SAMPLING_BIT"));
					image_infos.push_back({ VK_NULL_HANDLE, t->view, VK_IMAGE_LAYOUT_GENERAL });
					deps.push_back(u->ids[i]);
				} break;
				case UNIFORM_TYPE_UNIFORM_BUFFER:
				case UNIFORM_TYPE_STORAGE_BUFFER: {
					Impl::Buffer *b = s->buffer_owner.get_or_null(u->ids[i]);
					ERR_FAIL_NULL_V_MSG(b, RID(), vformat("uniform_set_create: binding %u: invalid buffer RID.", lb.binding));
					if (lb.type == UNIFORM_TYPE_UNIFORM_BUFFER) {
						ERR_FAIL_COND_V_MSG(b->kind != Impl::Buffer::KIND_UNIFORM, RID(), vformat("uniform_set_create: binding %u expects a uniform buffer.", lb.binding));
					} else {
						ERR_FAIL_COND_V_MSG(b->kind == Impl::Buffer::KIND_UNIFORM, RID(), vformat("uniform_set_create: binding %u expects a storage buffer, got a uniform buffer.", lb.binding));
					}
					buffer_infos.push_back({ b->buffer, 0, VK_WHOLE_SIZE });
					deps.push_back(u->ids[i]);
				} break;
				default:
					ERR_FAIL_V_MSG(RID(), "uniform_set_create: invalid uniform type.");
			}
		}
		writes.push_back(w);
	}

	Impl::UniformSet us;
	us.key = sh->set_keys[p_set_index];
	us.set_index = p_set_index;
	std::vector<VkDescriptorPoolSize> sizes;
	for (int t = 0; t < UNIFORM_TYPE_MAX; t++) {
		if (pool_counts[t]) {
			sizes.push_back({ uniform_type_to_vk((UniformType)t), pool_counts[t] });
		}
	}
	VkDescriptorPoolCreateInfo pci = { VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO };
	pci.maxSets = 1;
	pci.poolSizeCount = (uint32_t)sizes.size();
	pci.pPoolSizes = sizes.data();
	VkResult res = vkCreateDescriptorPool(s->device, &pci, nullptr, &us.pool);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateDescriptorPool failed (VkResult %d).", res));
	VkDescriptorSetLayout layout_handle = sh->set_layouts[p_set_index];
	VkDescriptorSetAllocateInfo dai = { VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO };
	dai.descriptorPool = us.pool;
	dai.descriptorSetCount = 1;
	dai.pSetLayouts = &layout_handle;
	res = vkAllocateDescriptorSets(s->device, &dai, &us.set);
	if (res != VK_SUCCESS) {
		vkDestroyDescriptorPool(s->device, us.pool, nullptr);
		ERR_FAIL_V_MSG(RID(), vformat("vkAllocateDescriptorSets failed (VkResult %d).", res));
	}
	std::vector<VkWriteDescriptorSet> vk_writes;
	for (const PendingWrite &w : writes) {
		VkWriteDescriptorSet wd = { VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET };
		wd.dstSet = us.set;
		wd.dstBinding = w.binding;
		wd.descriptorCount = w.count;
		wd.descriptorType = w.type;
		if (w.is_image) {
			wd.pImageInfo = &image_infos[w.first];
		} else {
			wd.pBufferInfo = &buffer_infos[w.first];
		}
		vk_writes.push_back(wd);
	}
	vkUpdateDescriptorSets(s->device, (uint32_t)vk_writes.size(), vk_writes.data(), 0, nullptr);
	RID rid = s->uniform_set_owner.make_rid(us);
	std::sort(deps.begin(), deps.end());
	deps.erase(std::unique(deps.begin(), deps.end()), deps.end());
	for (RID d : deps) {
		s->add_dependency(d, rid);
	}
	return rid;
}

bool RenderingDevice::uniform_set_is_valid(RID p_uniform_set) const {
	return impl->uniform_set_owner.get_or_null(p_uniform_set) != nullptr;
}

/**********************/
/**** FRAMEBUFFERS ****/
/**********************/

RenderingDevice::FramebufferFormatID RenderingDevice::framebuffer_format_create(const std::vector<AttachmentFormat> &p_format) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(p_format.empty(), INVALID_FORMAT_ID, "framebuffer_format_create: no attachments.");
	uint32_t colors = 0;
	bool depth = false;
	for (size_t i = 0; i < p_format.size(); i++) {
		const AttachmentFormat &a = p_format[i];
		ERR_FAIL_COND_V_MSG(a.format < 0 || a.format >= DATA_FORMAT_MAX, INVALID_FORMAT_ID, "framebuffer_format_create: invalid format.");
		if (is_depth_format(a.format)) {
			ERR_FAIL_COND_V_MSG(i != p_format.size() - 1, INVALID_FORMAT_ID, "framebuffer_format_create: the depth attachment must be last.");
			depth = true;
		} else {
			colors++;
		}
	}
	ERR_FAIL_COND_V_MSG(s->initialized && colors > s->properties.limits.maxColorAttachments, INVALID_FORMAT_ID, "framebuffer_format_create: too many colour attachments.");
	for (size_t i = 0; i < s->framebuffer_formats.size(); i++) {
		const std::vector<AttachmentFormat> &o = s->framebuffer_formats[i].attachments;
		if (o.size() != p_format.size()) {
			continue;
		}
		bool same = true;
		for (size_t j = 0; j < o.size(); j++) {
			same = same && o[j].format == p_format[j].format;
		}
		if (same) {
			return (FramebufferFormatID)i;
		}
	}
	Impl::FramebufferFormat ff;
	ff.attachments = p_format;
	ff.color_count = colors;
	ff.has_depth = depth;
	s->framebuffer_formats.push_back(ff);
	return (FramebufferFormatID)(s->framebuffer_formats.size() - 1);
}

uint32_t RenderingDevice::framebuffer_format_get_color_attachment_count(FramebufferFormatID p_format) const {
	ERR_FAIL_INDEX_V_MSG(p_format, (FramebufferFormatID)impl->framebuffer_formats.size(), 0, "Invalid framebuffer format ID.");
	return impl->framebuffer_formats[p_format].color_count;
}

static VkAttachmentLoadOp action_to_load_op(RenderingDevice::InitialAction p_action) {
	switch (p_action) {
		case RenderingDevice::INITIAL_ACTION_LOAD:
			return VK_ATTACHMENT_LOAD_OP_LOAD;
		case RenderingDevice::INITIAL_ACTION_CLEAR:
			return VK_ATTACHMENT_LOAD_OP_CLEAR;
		default:
			return VK_ATTACHMENT_LOAD_OP_DONT_CARE;
	}
}

VkRenderPass RDImpl::get_render_pass(FramebufferFormatID p_format, InitialAction p_color, InitialAction p_depth) {
	ERR_FAIL_INDEX_V(p_format, (FramebufferFormatID)framebuffer_formats.size(), VK_NULL_HANDLE);
	ERR_FAIL_COND_V(p_color < 0 || p_color > INITIAL_ACTION_DISCARD || p_depth < 0 || p_depth > INITIAL_ACTION_DISCARD, VK_NULL_HANDLE);
	FramebufferFormat &ff = framebuffer_formats[p_format];
	VkRenderPass &pass = ff.passes[p_color][p_depth];
	if (pass) {
		return pass;
	}
	std::vector<VkAttachmentDescription> atts;
	std::vector<VkAttachmentReference> color_refs;
	VkAttachmentReference depth_ref = { VK_ATTACHMENT_UNUSED, VK_IMAGE_LAYOUT_GENERAL };
	for (uint32_t i = 0; i < ff.attachments.size(); i++) {
		bool depth = is_depth_format(ff.attachments[i].format);
		VkAttachmentDescription d = {};
		d.format = to_vk_format(ff.attachments[i].format);
		d.samples = VK_SAMPLE_COUNT_1_BIT;
		d.loadOp = action_to_load_op(depth ? p_depth : p_color);
		d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
		d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
		d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
		d.initialLayout = VK_IMAGE_LAYOUT_GENERAL;
		d.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
		atts.push_back(d);
		if (depth) {
			depth_ref.attachment = i;
		} else {
			color_refs.push_back({ i, VK_IMAGE_LAYOUT_GENERAL });
		}
	}
	VkSubpassDescription sub = {};
	sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
	sub.colorAttachmentCount = (uint32_t)color_refs.size();
	sub.pColorAttachments = color_refs.data();
	sub.pDepthStencilAttachment = depth_ref.attachment == VK_ATTACHMENT_UNUSED ? nullptr : &depth_ref;
	VkSubpassDependency deps[2] = {};
	deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
	deps[0].dstSubpass = 0;
	deps[0].srcStageMask = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
	deps[0].dstStageMask = VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT;
	deps[0].srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
	deps[0].dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
	deps[1].srcSubpass = 0;
	deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
	deps[1].srcStageMask = VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT;
	deps[1].dstStageMask = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
	deps[1].srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
	deps[1].dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
	VkRenderPassCreateInfo ci = { VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO };
	ci.attachmentCount = (uint32_t)atts.size();
	ci.pAttachments = atts.data();
	ci.subpassCount = 1;
	ci.pSubpasses = &sub;
	ci.dependencyCount = 2;
	ci.pDependencies = deps;
	VkResult res = vkCreateRenderPass(device, &ci, nullptr, &pass);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, VK_NULL_HANDLE, vformat("vkCreateRenderPass failed (VkResult %d).", res));
	return pass;
}

RID RenderingDevice::framebuffer_create(const std::vector<RID> &p_textures) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, RID(), "RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(p_textures.empty(), RID(), "framebuffer_create: no textures.");
	std::vector<AttachmentFormat> formats;
	std::vector<VkImageView> views;
	uint32_t w = 0, h = 0;
	for (size_t i = 0; i < p_textures.size(); i++) {
		Impl::Texture *t = s->texture_owner.get_or_null(p_textures[i]);
		ERR_FAIL_NULL_V_MSG(t, RID(), vformat("framebuffer_create: texture %zu is invalid.", i));
		bool depth = is_depth_format(t->format.format);
		uint32_t needed = depth ? TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : TEXTURE_USAGE_COLOR_ATTACHMENT_BIT;
		ERR_FAIL_COND_V_MSG(!(t->format.usage_bits & needed), RID(), vformat("framebuffer_create: texture %zu lacks the %s attachment usage bit.", i, depth ? "depth" : "colour"));
		ERR_FAIL_COND_V_MSG(t->format.array_layers != 1 || t->format.mipmaps != 1 || t->format.texture_type != TEXTURE_TYPE_2D, RID(), vformat("framebuffer_create: texture %zu must be a single-layer, single-mip 2D texture (use texture_create_shared_from_slice for array layers).", i));
		if (i == 0) {
			w = t->format.width;
			h = t->format.height;
		}
		ERR_FAIL_COND_V_MSG(t->format.width != w || t->format.height != h, RID(), "framebuffer_create: all textures must have the same size.");
		AttachmentFormat af;
		af.format = t->format.format;
		af.usage_flags = t->format.usage_bits;
		formats.push_back(af);
		views.push_back(t->view);
	}
	FramebufferFormatID fmt = framebuffer_format_create(formats);
	ERR_FAIL_COND_V(fmt == INVALID_FORMAT_ID, RID());
	VkRenderPass pass = s->get_render_pass(fmt, INITIAL_ACTION_CLEAR, INITIAL_ACTION_CLEAR);
	ERR_FAIL_COND_V(pass == VK_NULL_HANDLE, RID());
	Impl::Framebuffer fb;
	fb.format = fmt;
	fb.textures = p_textures;
	fb.width = w;
	fb.height = h;
	VkFramebufferCreateInfo ci = { VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO };
	ci.renderPass = pass;
	ci.attachmentCount = (uint32_t)views.size();
	ci.pAttachments = views.data();
	ci.width = w;
	ci.height = h;
	ci.layers = 1;
	VkResult res = vkCreateFramebuffer(s->device, &ci, nullptr, &fb.framebuffer);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateFramebuffer failed (VkResult %d).", res));
	RID rid = s->framebuffer_owner.make_rid(fb);
	for (RID t : p_textures) {
		s->add_dependency(t, rid);
	}
	return rid;
}

RenderingDevice::FramebufferFormatID RenderingDevice::framebuffer_get_format(RID p_framebuffer) const {
	Impl::Framebuffer *fb = impl->framebuffer_owner.get_or_null(p_framebuffer);
	ERR_FAIL_NULL_V_MSG(fb, INVALID_FORMAT_ID, "framebuffer_get_format: invalid framebuffer RID.");
	return fb->format;
}

bool RenderingDevice::framebuffer_is_valid(RID p_framebuffer) const {
	return impl->framebuffer_owner.get_or_null(p_framebuffer) != nullptr;
}

uint32_t RenderingDevice::framebuffer_get_width(RID p_framebuffer) const {
	Impl::Framebuffer *fb = impl->framebuffer_owner.get_or_null(p_framebuffer);
	ERR_FAIL_NULL_V_MSG(fb, 0, "framebuffer_get_width: invalid framebuffer RID.");
	return fb->width;
}

uint32_t RenderingDevice::framebuffer_get_height(RID p_framebuffer) const {
	Impl::Framebuffer *fb = impl->framebuffer_owner.get_or_null(p_framebuffer);
	ERR_FAIL_NULL_V_MSG(fb, 0, "framebuffer_get_height: invalid framebuffer RID.");
	return fb->height;
}

/************************/
/**** VERTEX FORMATS ****/
/************************/

RenderingDevice::VertexFormatID RenderingDevice::vertex_format_create(const std::vector<VertexAttribute> &p_vertex_descriptions) {
	Impl *s = impl;
	for (const VertexAttribute &a : p_vertex_descriptions) {
		ERR_FAIL_COND_V_MSG(a.format < 0 || a.format >= DATA_FORMAT_MAX || is_depth_format(a.format), INVALID_ID, "vertex_format_create: invalid attribute format.");
		ERR_FAIL_COND_V_MSG(a.stride == 0 && a.frequency == VERTEX_FREQUENCY_VERTEX, INVALID_ID, vformat("vertex_format_create: attribute at location %u has stride 0.", a.location));
		for (const VertexAttribute &b : p_vertex_descriptions) {
			ERR_FAIL_COND_V_MSG(&a != &b && a.location == b.location, INVALID_ID, vformat("vertex_format_create: location %u used twice.", a.location));
		}
	}
	for (size_t i = 0; i < s->vertex_formats.size(); i++) {
		const std::vector<VertexAttribute> &o = s->vertex_formats[i].attributes;
		if (o.size() != p_vertex_descriptions.size()) {
			continue;
		}
		bool same = true;
		for (size_t j = 0; j < o.size(); j++) {
			const VertexAttribute &x = o[j];
			const VertexAttribute &y = p_vertex_descriptions[j];
			same = same && x.location == y.location && x.offset == y.offset && x.format == y.format && x.stride == y.stride && x.frequency == y.frequency;
		}
		if (same) {
			return (VertexFormatID)i;
		}
	}
	Impl::VertexFormat vf;
	vf.attributes = p_vertex_descriptions;
	s->vertex_formats.push_back(vf);
	return (VertexFormatID)(s->vertex_formats.size() - 1);
}

RID RenderingDevice::vertex_array_create(uint32_t p_vertex_count, VertexFormatID p_vertex_format, const std::vector<RID> &p_src_buffers, const std::vector<uint64_t> &p_offsets) {
	Impl *s = impl;
	ERR_FAIL_INDEX_V_MSG(p_vertex_format, (VertexFormatID)s->vertex_formats.size(), RID(), "vertex_array_create: invalid vertex format ID.");
	const Impl::VertexFormat &vf = s->vertex_formats[p_vertex_format];
	ERR_FAIL_COND_V_MSG(p_src_buffers.size() != vf.attributes.size(), RID(), vformat("vertex_array_create: %zu buffers given, the format has %zu attributes.", p_src_buffers.size(), vf.attributes.size()));
	ERR_FAIL_COND_V_MSG(!p_offsets.empty() && p_offsets.size() != p_src_buffers.size(), RID(), "vertex_array_create: offsets must be empty or one per buffer.");
	Impl::VertexArray va;
	va.vertex_count = p_vertex_count;
	va.format = p_vertex_format;
	for (size_t i = 0; i < p_src_buffers.size(); i++) {
		Impl::Buffer *b = s->buffer_owner.get_or_null(p_src_buffers[i]);
		ERR_FAIL_NULL_V_MSG(b, RID(), vformat("vertex_array_create: buffer %zu is invalid.", i));
		ERR_FAIL_COND_V_MSG(b->kind != Impl::Buffer::KIND_VERTEX, RID(), vformat("vertex_array_create: buffer %zu is not a vertex buffer.", i));
		uint64_t offset = p_offsets.empty() ? 0 : p_offsets[i];
		const VertexAttribute &a = vf.attributes[i];
		if (a.frequency == VERTEX_FREQUENCY_VERTEX && p_vertex_count > 0) {
			uint64_t needed = offset + (uint64_t)a.stride * (p_vertex_count - 1) + a.offset + get_format_size(a.format);
			ERR_FAIL_COND_V_MSG(needed > b->size, RID(), vformat("vertex_array_create: buffer %zu is too small for %u vertices (needs %llu bytes, has %u).", i, p_vertex_count, (unsigned long long)needed, b->size));
		}
		va.buffers.push_back(b->buffer);
		va.offsets.push_back(offset);
	}
	RID rid = s->vertex_array_owner.make_rid(va);
	for (RID b : p_src_buffers) {
		s->add_dependency(b, rid);
	}
	return rid;
}

RID RenderingDevice::index_array_create(RID p_index_buffer, uint32_t p_index_offset, uint32_t p_index_count) {
	Impl *s = impl;
	Impl::Buffer *b = s->buffer_owner.get_or_null(p_index_buffer);
	ERR_FAIL_NULL_V_MSG(b, RID(), "index_array_create: invalid index buffer RID.");
	ERR_FAIL_COND_V_MSG(b->kind != Impl::Buffer::KIND_INDEX, RID(), "index_array_create: the buffer is not an index buffer.");
	ERR_FAIL_COND_V_MSG(p_index_offset >= b->index_count, RID(), "index_array_create: offset out of range.");
	uint32_t count = p_index_count == 0 ? b->index_count - p_index_offset : p_index_count;
	ERR_FAIL_COND_V_MSG((uint64_t)p_index_offset + count > b->index_count, RID(), "index_array_create: range out of bounds.");
	Impl::IndexArray ia;
	ia.buffer = b->buffer;
	ia.offset = p_index_offset;
	ia.count = count;
	ia.index_type = b->index_format == INDEX_BUFFER_FORMAT_UINT16 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32;
	RID rid = s->index_array_owner.make_rid(ia);
	s->add_dependency(p_index_buffer, rid);
	return rid;
}

/*******************/
/**** PIPELINES ****/
/*******************/

RenderingDevice::PipelineColorBlendState RenderingDevice::PipelineColorBlendState::create_disabled(int p_attachments) {
	PipelineColorBlendState bs;
	bs.attachments.resize(std::max(p_attachments, 0));
	return bs;
}

RenderingDevice::PipelineColorBlendState RenderingDevice::PipelineColorBlendState::create_additive(int p_attachments) {
	PipelineColorBlendState bs;
	Attachment a;
	a.enable_blend = true;
	a.src_color_blend_factor = BLEND_FACTOR_ONE;
	a.dst_color_blend_factor = BLEND_FACTOR_ONE;
	a.src_alpha_blend_factor = BLEND_FACTOR_ONE;
	a.dst_alpha_blend_factor = BLEND_FACTOR_ONE;
	bs.attachments.assign(std::max(p_attachments, 0), a);
	return bs;
}

RenderingDevice::PipelineColorBlendState RenderingDevice::PipelineColorBlendState::create_blend(int p_attachments) {
	PipelineColorBlendState bs;
	Attachment a;
	a.enable_blend = true;
	a.src_color_blend_factor = BLEND_FACTOR_SRC_ALPHA;
	a.dst_color_blend_factor = BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
	a.src_alpha_blend_factor = BLEND_FACTOR_ONE;
	a.dst_alpha_blend_factor = BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
	bs.attachments.assign(std::max(p_attachments, 0), a);
	return bs;
}

static VkBlendFactor blend_factor_to_vk(RenderingDevice::BlendFactor p_f) {
	static const VkBlendFactor f[] = { VK_BLEND_FACTOR_ZERO, VK_BLEND_FACTOR_ONE, VK_BLEND_FACTOR_SRC_ALPHA, VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA, VK_BLEND_FACTOR_DST_ALPHA, VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA };
	return (p_f >= 0 && p_f <= RenderingDevice::BLEND_FACTOR_ONE_MINUS_DST_ALPHA) ? f[p_f] : VK_BLEND_FACTOR_ONE;
}

static VkBlendOp blend_op_to_vk(RenderingDevice::BlendOperation p_op) {
	static const VkBlendOp o[] = { VK_BLEND_OP_ADD, VK_BLEND_OP_SUBTRACT, VK_BLEND_OP_REVERSE_SUBTRACT, VK_BLEND_OP_MIN, VK_BLEND_OP_MAX };
	return (p_op >= 0 && p_op <= RenderingDevice::BLEND_OP_MAXIMUM) ? o[p_op] : VK_BLEND_OP_ADD;
}

RID RenderingDevice::render_pipeline_create(RID p_shader, FramebufferFormatID p_framebuffer_format, VertexFormatID p_vertex_format, RenderPrimitive p_render_primitive, const PipelineRasterizationState &p_rasterization_state, const PipelineDepthStencilState &p_depth_stencil_state, const PipelineColorBlendState &p_blend_state, uint32_t p_dynamic_state_flags) {
	Impl *s = impl;
	Impl::Shader *sh = s->shader_owner.get_or_null(p_shader);
	ERR_FAIL_NULL_V_MSG(sh, RID(), "render_pipeline_create: invalid shader RID.");
	ERR_FAIL_COND_V_MSG(sh->is_compute, RID(), vformat("render_pipeline_create: shader '%s' is a compute shader.", sh->name.c_str()));
	ERR_FAIL_INDEX_V_MSG(p_framebuffer_format, (FramebufferFormatID)s->framebuffer_formats.size(), RID(), "render_pipeline_create: invalid framebuffer format ID.");
	ERR_FAIL_INDEX_V_MSG(p_vertex_format, (VertexFormatID)s->vertex_formats.size(), RID(), "render_pipeline_create: invalid vertex format ID (create an empty one with vertex_format_create({}) for procedural vertices).");
	ERR_FAIL_COND_V_MSG(p_render_primitive < RENDER_PRIMITIVE_POINTS || p_render_primitive > RENDER_PRIMITIVE_TRIANGLE_STRIPS, RID(), "render_pipeline_create: invalid primitive.");
	const Impl::FramebufferFormat &ff = s->framebuffer_formats[p_framebuffer_format];
	ERR_FAIL_COND_V_MSG(p_blend_state.attachments.size() > ff.color_count, RID(), vformat("render_pipeline_create: %zu blend attachments for %u colour attachments.", p_blend_state.attachments.size(), ff.color_count));
	VkRenderPass pass = s->get_render_pass(p_framebuffer_format, INITIAL_ACTION_CLEAR, INITIAL_ACTION_CLEAR);
	ERR_FAIL_COND_V(pass == VK_NULL_HANDLE, RID());

	std::vector<VkPipelineShaderStageCreateInfo> stages;
	static const VkShaderStageFlagBits vk_stages[] = { VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_FRAGMENT_BIT, VK_SHADER_STAGE_COMPUTE_BIT };
	for (int i = 0; i < SHADER_STAGE_COMPUTE; i++) {
		if (sh->modules[i]) {
			VkPipelineShaderStageCreateInfo st = { VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO };
			st.stage = vk_stages[i];
			st.module = sh->modules[i];
			st.pName = "main";
			stages.push_back(st);
		}
	}

	const Impl::VertexFormat &vf = s->vertex_formats[p_vertex_format];
	std::vector<VkVertexInputBindingDescription> vbinds;
	std::vector<VkVertexInputAttributeDescription> vattrs;
	for (uint32_t i = 0; i < vf.attributes.size(); i++) {
		const VertexAttribute &a = vf.attributes[i];
		vbinds.push_back({ i, a.stride, a.frequency == VERTEX_FREQUENCY_INSTANCE ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX });
		vattrs.push_back({ a.location, i, Impl::to_vk_format(a.format), a.offset });
	}
	VkPipelineVertexInputStateCreateInfo vi = { VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO };
	vi.vertexBindingDescriptionCount = (uint32_t)vbinds.size();
	vi.pVertexBindingDescriptions = vbinds.data();
	vi.vertexAttributeDescriptionCount = (uint32_t)vattrs.size();
	vi.pVertexAttributeDescriptions = vattrs.data();

	static const VkPrimitiveTopology topologies[] = { VK_PRIMITIVE_TOPOLOGY_POINT_LIST, VK_PRIMITIVE_TOPOLOGY_LINE_LIST, VK_PRIMITIVE_TOPOLOGY_LINE_STRIP, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP };
	VkPipelineInputAssemblyStateCreateInfo ia = { VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO };
	ia.topology = topologies[p_render_primitive];

	VkPipelineViewportStateCreateInfo vp = { VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO };
	vp.viewportCount = 1;
	vp.scissorCount = 1;

	const PipelineRasterizationState &rs = p_rasterization_state;
	VkPipelineRasterizationStateCreateInfo ra = { VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO };
	if (rs.enable_depth_clamp && !s->enabled_features.depthClamp) {
		WARN_PRINT_ONCE("render_pipeline_create: depth clamp is not supported by this device; disabled.");
	}
	ra.depthClampEnable = (rs.enable_depth_clamp && s->enabled_features.depthClamp) ? VK_TRUE : VK_FALSE;
	if (rs.wireframe && !s->enabled_features.fillModeNonSolid) {
		WARN_PRINT_ONCE("render_pipeline_create: wireframe is not supported by this device; using solid fill.");
	}
	ra.polygonMode = (rs.wireframe && s->enabled_features.fillModeNonSolid) ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
	ra.cullMode = rs.cull_mode == POLYGON_CULL_FRONT ? VK_CULL_MODE_FRONT_BIT : (rs.cull_mode == POLYGON_CULL_BACK ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
	ra.frontFace = rs.front_face == POLYGON_FRONT_FACE_CLOCKWISE ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
	ra.depthBiasEnable = (rs.depth_bias_enabled || (p_dynamic_state_flags & DYNAMIC_STATE_DEPTH_BIAS)) ? VK_TRUE : VK_FALSE;
	ra.depthBiasConstantFactor = rs.depth_bias_constant_factor;
	ra.depthBiasSlopeFactor = rs.depth_bias_slope_factor;
	ra.lineWidth = 1.0f;

	VkPipelineMultisampleStateCreateInfo ms = { VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO };
	ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

	VkPipelineDepthStencilStateCreateInfo ds = { VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO };
	ERR_FAIL_COND_V_MSG(!ff.has_depth && (p_depth_stencil_state.enable_depth_test || p_depth_stencil_state.enable_depth_write), RID(), "render_pipeline_create: depth test/write enabled but the framebuffer format has no depth attachment.");
	ds.depthTestEnable = p_depth_stencil_state.enable_depth_test ? VK_TRUE : VK_FALSE;
	ds.depthWriteEnable = p_depth_stencil_state.enable_depth_write ? VK_TRUE : VK_FALSE;
	ds.depthCompareOp = Impl::to_vk_compare(p_depth_stencil_state.depth_compare_operator);
	ds.maxDepthBounds = 1.0f;

	std::vector<VkPipelineColorBlendAttachmentState> cbas;
	bool differs = false;
	for (uint32_t i = 0; i < ff.color_count; i++) {
		PipelineColorBlendState::Attachment a = i < p_blend_state.attachments.size() ? p_blend_state.attachments[i] : PipelineColorBlendState::Attachment();
		VkPipelineColorBlendAttachmentState cb = {};
		cb.blendEnable = a.enable_blend ? VK_TRUE : VK_FALSE;
		cb.srcColorBlendFactor = blend_factor_to_vk(a.src_color_blend_factor);
		cb.dstColorBlendFactor = blend_factor_to_vk(a.dst_color_blend_factor);
		cb.colorBlendOp = blend_op_to_vk(a.color_blend_op);
		cb.srcAlphaBlendFactor = blend_factor_to_vk(a.src_alpha_blend_factor);
		cb.dstAlphaBlendFactor = blend_factor_to_vk(a.dst_alpha_blend_factor);
		cb.alphaBlendOp = blend_op_to_vk(a.alpha_blend_op);
		cb.colorWriteMask = (a.write_r ? VK_COLOR_COMPONENT_R_BIT : 0) | (a.write_g ? VK_COLOR_COMPONENT_G_BIT : 0) | (a.write_b ? VK_COLOR_COMPONENT_B_BIT : 0) | (a.write_a ? VK_COLOR_COMPONENT_A_BIT : 0);
		if (!cbas.empty() && memcmp(&cbas[0], &cb, sizeof(cb)) != 0) {
			differs = true;
		}
		cbas.push_back(cb);
	}
	ERR_FAIL_COND_V_MSG(differs && !s->enabled_features.independentBlend, RID(), "render_pipeline_create: per-attachment blend states differ but independentBlend is not supported.");
	VkPipelineColorBlendStateCreateInfo cbs = { VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO };
	cbs.attachmentCount = (uint32_t)cbas.size();
	cbs.pAttachments = cbas.data();

	std::vector<VkDynamicState> dyn = { VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR };
	if (p_dynamic_state_flags & DYNAMIC_STATE_DEPTH_BIAS) {
		dyn.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
	}
	VkPipelineDynamicStateCreateInfo dy = { VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO };
	dy.dynamicStateCount = (uint32_t)dyn.size();
	dy.pDynamicStates = dyn.data();

	VkGraphicsPipelineCreateInfo ci = { VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO };
	ci.stageCount = (uint32_t)stages.size();
	ci.pStages = stages.data();
	ci.pVertexInputState = &vi;
	ci.pInputAssemblyState = &ia;
	ci.pViewportState = &vp;
	ci.pRasterizationState = &ra;
	ci.pMultisampleState = &ms;
	ci.pDepthStencilState = &ds;
	ci.pColorBlendState = &cbs;
	ci.pDynamicState = &dy;
	ci.layout = sh->pipeline_layout;
	ci.renderPass = pass;
	ci.subpass = 0;
	Impl::Pipeline p;
	VkResult res = vkCreateGraphicsPipelines(s->device, VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateGraphicsPipelines failed (VkResult %d) for shader '%s'.", res, sh->name.c_str()));
	p.shader = p_shader;
	p.layout = sh->pipeline_layout;
	p.framebuffer_format = p_framebuffer_format;
	p.vertex_format = p_vertex_format;
	p.push_constant_size = sh->push_constant_size;
	p.push_stages = sh->stage_flags;
	p.set_keys = sh->set_keys;
	RID rid = s->pipeline_owner.make_rid(p);
	s->add_dependency(p_shader, rid);
	return rid;
}

RID RenderingDevice::compute_pipeline_create(RID p_shader) {
	Impl *s = impl;
	Impl::Shader *sh = s->shader_owner.get_or_null(p_shader);
	ERR_FAIL_NULL_V_MSG(sh, RID(), "compute_pipeline_create: invalid shader RID.");
	ERR_FAIL_COND_V_MSG(!sh->is_compute, RID(), vformat("compute_pipeline_create: shader '%s' is not a compute shader.", sh->name.c_str()));
	VkComputePipelineCreateInfo ci = { VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO };
	ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
	ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
	ci.stage.module = sh->modules[SHADER_STAGE_COMPUTE];
	ci.stage.pName = "main";
	ci.layout = sh->pipeline_layout;
	Impl::Pipeline p;
	VkResult res = vkCreateComputePipelines(s->device, VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline);
	ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, RID(), vformat("vkCreateComputePipelines failed (VkResult %d) for shader '%s'.", res, sh->name.c_str()));
	p.shader = p_shader;
	p.layout = sh->pipeline_layout;
	p.is_compute = true;
	p.push_constant_size = sh->push_constant_size;
	p.push_stages = sh->stage_flags;
	p.set_keys = sh->set_keys;
	for (int i = 0; i < 3; i++) {
		p.local_size[i] = sh->local_size[i];
	}
	RID rid = s->pipeline_owner.make_rid(p);
	s->add_dependency(p_shader, rid);
	return rid;
}

bool RenderingDevice::render_pipeline_is_valid(RID p_pipeline) const {
	Impl::Pipeline *p = impl->pipeline_owner.get_or_null(p_pipeline);
	return p && !p->is_compute;
}

bool RenderingDevice::compute_pipeline_is_valid(RID p_pipeline) const {
	Impl::Pipeline *p = impl->pipeline_owner.get_or_null(p_pipeline);
	return p && p->is_compute;
}
