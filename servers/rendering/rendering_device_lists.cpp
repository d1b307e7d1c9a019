/**************************************************************************/
/*  rendering_device_lists.cpp                                            */
/**************************************************************************/
/* RenderingDevice: draw lists and compute lists. Pipeline, uniform sets  */
/* and push constants are recorded lazily, right before each draw or      */
/* dispatch, against the pipeline bound at that moment.                   */

#include "servers/rendering/rendering_device.h"

#include "servers/rendering/rendering_device_impl.h"

#include <algorithm>
#include <cstring>

typedef RenderingDevice::Impl RDImpl;

static const int64_t DRAW_LIST_ID = 1;
static const int64_t COMPUTE_LIST_ID = 2;

void RDImpl::bind_list_state() {
	Pipeline *p = pipeline_owner.get_or_null(list.pipeline);
	VkPipelineBindPoint bp = list.is_compute ? VK_PIPELINE_BIND_POINT_COMPUTE : VK_PIPELINE_BIND_POINT_GRAPHICS;
	if (list.pipeline_dirty) {
		vkCmdBindPipeline(command_buffer, bp, p->pipeline);
		list.pipeline_dirty = false;
		// A new pipeline may have a different layout: re-apply everything.
		std::fill(list.set_dirty.begin(), list.set_dirty.end(), true);
		list.push_dirty = true;
	}
	for (uint32_t i = 0; i < p->set_keys.size(); i++) {
		if (p->set_keys[i].empty() || i >= list.sets.size() || !list.set_dirty[i]) {
			continue;
		}
		UniformSet *us = uniform_set_owner.get_or_null(list.sets[i]);
		if (!us) {
			continue;
		}
		vkCmdBindDescriptorSets(command_buffer, bp, p->layout, i, 1, &us->set, 0, nullptr);
		list.set_dirty[i] = false;
	}
	if (list.push_dirty && p->push_constant_size > 0 && list.push_data.size() == p->push_constant_size) {
		vkCmdPushConstants(command_buffer, p->layout, p->push_stages, 0, p->push_constant_size, list.push_data.data());
		list.push_dirty = false;
	}
}

// Checks that the bound pipeline has everything it needs; prints the first problem.
static bool validate_list_state(RDImpl *s, const char *p_what) {
	RDImpl::Pipeline *p = s->pipeline_owner.get_or_null(s->list.pipeline);
	ERR_FAIL_NULL_V_MSG(p, false, vformat("%s: no valid pipeline is bound.", p_what));
	for (uint32_t i = 0; i < p->set_keys.size(); i++) {
		if (p->set_keys[i].empty()) {
			continue;
		}
		ERR_FAIL_COND_V_MSG(i >= s->list.sets.size() || s->list.sets[i].is_null(), false, vformat("%s: the pipeline uses uniform set %u but none was bound.", p_what, i));
		RDImpl::UniformSet *us = s->uniform_set_owner.get_or_null(s->list.sets[i]);
		ERR_FAIL_NULL_V_MSG(us, false, vformat("%s: the uniform set bound at index %u was freed (or a resource it used was freed).", p_what, i));
		ERR_FAIL_COND_V_MSG(us->key != p->set_keys[i], false, vformat("%s: the uniform set bound at index %u does not match the pipeline's shader layout for that set.", p_what, i));
	}
	ERR_FAIL_COND_V_MSG(p->push_constant_size > 0 && s->list.push_data.size() != p->push_constant_size, false, vformat("%s: the shader needs %u bytes of push constants, %zu were set.", p_what, p->push_constant_size, s->list.push_data.size()));
	return true;
}

static void set_viewport(VkCommandBuffer p_cmd, const RenderingDevice::Rect &p_rect) {
	VkViewport vp = { (float)p_rect.x, (float)p_rect.y, (float)p_rect.width, (float)p_rect.height, 0.0f, 1.0f };
	vkCmdSetViewport(p_cmd, 0, 1, &vp);
	VkRect2D sc = { { p_rect.x, p_rect.y }, { p_rect.width, p_rect.height } };
	vkCmdSetScissor(p_cmd, 0, 1, &sc);
}

/********************/
/**** DRAW LISTS ****/
/********************/

RenderingDevice::DrawListID RenderingDevice::draw_list_begin(RID p_framebuffer, InitialAction p_initial_color_action, InitialAction p_initial_depth_action, const std::vector<Color> &p_clear_colors, float p_clear_depth, const Rect &p_region) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, INVALID_ID, "RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(s->list.active, INVALID_ID, "draw_list_begin: a draw or compute list is already open.");
	Impl::Framebuffer *fb = s->framebuffer_owner.get_or_null(p_framebuffer);
	ERR_FAIL_NULL_V_MSG(fb, INVALID_ID, "draw_list_begin: invalid framebuffer RID.");
	Rect region = p_region;
	if (region.width == 0 || region.height == 0) {
		region = Rect(0, 0, fb->width, fb->height);
	}
	ERR_FAIL_COND_V_MSG(region.x < 0 || region.y < 0 || (uint64_t)region.x + region.width > fb->width || (uint64_t)region.y + region.height > fb->height, INVALID_ID, "draw_list_begin: region is outside the framebuffer.");
	VkRenderPass pass = s->get_render_pass(fb->format, p_initial_color_action, p_initial_depth_action);
	ERR_FAIL_COND_V(pass == VK_NULL_HANDLE, INVALID_ID);
	s->ensure_recording();
	const Impl::FramebufferFormat &ff = s->framebuffer_formats[fb->format];
	std::vector<VkClearValue> clears(ff.attachments.size());
	uint32_t color_index = 0;
	for (size_t i = 0; i < ff.attachments.size(); i++) {
		if (is_depth_format(ff.attachments[i].format)) {
			clears[i].depthStencil = { p_clear_depth, 0 };
		} else {
			Color c = color_index < p_clear_colors.size() ? p_clear_colors[color_index] : Color(0, 0, 0, 0);
			DataFormat f = ff.attachments[i].format;
			if (f == DATA_FORMAT_R32_UINT || f == DATA_FORMAT_R32G32_UINT || f == DATA_FORMAT_R32G32B32A32_UINT) {
				clears[i].color.uint32[0] = (uint32_t)c.r;
				clears[i].color.uint32[1] = (uint32_t)c.g;
				clears[i].color.uint32[2] = (uint32_t)c.b;
				clears[i].color.uint32[3] = (uint32_t)c.a;
			} else if (f == DATA_FORMAT_R32_SINT) {
				clears[i].color.int32[0] = (int32_t)c.r;
				clears[i].color.int32[1] = (int32_t)c.g;
				clears[i].color.int32[2] = (int32_t)c.b;
				clears[i].color.int32[3] = (int32_t)c.a;
			} else {
				clears[i].color.float32[0] = c.r;
				clears[i].color.float32[1] = c.g;
				clears[i].color.float32[2] = c.b;
				clears[i].color.float32[3] = c.a;
			}
			color_index++;
		}
	}
	s->full_barrier();
	VkRenderPassBeginInfo bi = { VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO };
	bi.renderPass = pass;
	bi.framebuffer = fb->framebuffer;
	bi.renderArea = { { region.x, region.y }, { region.width, region.height } };
	bi.clearValueCount = (uint32_t)clears.size();
	bi.pClearValues = clears.data();
	vkCmdBeginRenderPass(s->command_buffer, &bi, VK_SUBPASS_CONTENTS_INLINE);
	set_viewport(s->command_buffer, region);

	s->list = Impl::ListState();
	s->list.active = true;
	s->list.is_compute = false;
	s->list.framebuffer_format = fb->format;
	return DRAW_LIST_ID;
}

#define DRAW_LIST_CHECK(m_list) \
	ERR_FAIL_COND_MSG(!impl->list.active || impl->list.is_compute || (m_list) != DRAW_LIST_ID, "Invalid or closed draw list.")

void RenderingDevice::draw_list_bind_render_pipeline(DrawListID p_list, RID p_render_pipeline) {
	DRAW_LIST_CHECK(p_list);
	Impl *s = impl;
	Impl::Pipeline *p = s->pipeline_owner.get_or_null(p_render_pipeline);
	ERR_FAIL_NULL_MSG(p, "draw_list_bind_render_pipeline: invalid pipeline RID.");
	ERR_FAIL_COND_MSG(p->is_compute, "draw_list_bind_render_pipeline: this is a compute pipeline.");
	ERR_FAIL_COND_MSG(p->framebuffer_format != s->list.framebuffer_format, "draw_list_bind_render_pipeline: the pipeline was created for a different framebuffer format.");
	if (s->list.pipeline == p_render_pipeline) {
		return;
	}
	s->list.pipeline = p_render_pipeline;
	s->list.pipeline_dirty = true;
}

void RenderingDevice::draw_list_bind_uniform_set(DrawListID p_list, RID p_uniform_set, uint32_t p_index) {
	DRAW_LIST_CHECK(p_list);
	Impl *s = impl;
	Impl::UniformSet *us = s->uniform_set_owner.get_or_null(p_uniform_set);
	ERR_FAIL_NULL_MSG(us, "draw_list_bind_uniform_set: invalid uniform set RID (it may have been freed with a resource it used).");
	ERR_FAIL_COND_MSG(p_index >= s->properties.limits.maxBoundDescriptorSets, "draw_list_bind_uniform_set: set index exceeds the device limit.");
	if (s->list.sets.size() <= p_index) {
		s->list.sets.resize(p_index + 1);
		s->list.set_dirty.resize(p_index + 1, true);
	}
	s->list.sets[p_index] = p_uniform_set;
	s->list.set_dirty[p_index] = true;
}

void RenderingDevice::draw_list_bind_vertex_array(DrawListID p_list, RID p_vertex_array) {
	DRAW_LIST_CHECK(p_list);
	Impl *s = impl;
	Impl::VertexArray *va = s->vertex_array_owner.get_or_null(p_vertex_array);
	ERR_FAIL_NULL_MSG(va, "draw_list_bind_vertex_array: invalid vertex array RID.");
	s->list.vertex_array = p_vertex_array;
	if (!va->buffers.empty()) {
		vkCmdBindVertexBuffers(s->command_buffer, 0, (uint32_t)va->buffers.size(), va->buffers.data(), va->offsets.data());
	}
}

void RenderingDevice::draw_list_bind_index_array(DrawListID p_list, RID p_index_array) {
	DRAW_LIST_CHECK(p_list);
	Impl *s = impl;
	Impl::IndexArray *ia = s->index_array_owner.get_or_null(p_index_array);
	ERR_FAIL_NULL_MSG(ia, "draw_list_bind_index_array: invalid index array RID.");
	s->list.index_array = p_index_array;
	vkCmdBindIndexBuffer(s->command_buffer, ia->buffer, 0, ia->index_type);
}

void RenderingDevice::draw_list_set_push_constant(DrawListID p_list, const void *p_data, uint32_t p_data_size) {
	DRAW_LIST_CHECK(p_list);
	ERR_FAIL_NULL_MSG(p_data, "draw_list_set_push_constant: data is null.");
	Impl *s = impl;
	Impl::Pipeline *p = s->pipeline_owner.get_or_null(s->list.pipeline);
	ERR_FAIL_NULL_MSG(p, "draw_list_set_push_constant: bind a pipeline first.");
	ERR_FAIL_COND_MSG(p_data_size != p->push_constant_size, vformat("draw_list_set_push_constant: %u bytes given, the shader's push constant block is %u bytes.", p_data_size, p->push_constant_size));
	s->list.push_data.assign((const uint8_t *)p_data, (const uint8_t *)p_data + p_data_size);
	s->list.push_dirty = true;
}

void RenderingDevice::draw_list_set_viewport(DrawListID p_list, const Rect &p_rect) {
	DRAW_LIST_CHECK(p_list);
	ERR_FAIL_COND_MSG(p_rect.width == 0 || p_rect.height == 0 || p_rect.x < 0 || p_rect.y < 0, "draw_list_set_viewport: empty or negative rectangle.");
	set_viewport(impl->command_buffer, p_rect);
}

void RenderingDevice::draw_list_set_depth_bias(DrawListID p_list, float p_constant, float p_slope) {
	DRAW_LIST_CHECK(p_list);
	vkCmdSetDepthBias(impl->command_buffer, p_constant, 0.0f, p_slope);
}

void RenderingDevice::draw_list_draw(DrawListID p_list, bool p_use_indices, uint32_t p_instances, uint32_t p_procedural_vertices) {
	DRAW_LIST_CHECK(p_list);
	Impl *s = impl;
	ERR_FAIL_COND_MSG(p_instances == 0, "draw_list_draw: instance count is zero.");
	if (!validate_list_state(s, "draw_list_draw")) {
		return;
	}
	Impl::Pipeline *p = s->pipeline_owner.get_or_null(s->list.pipeline);
	const Impl::VertexFormat &vf = s->vertex_formats[p->vertex_format];
	if (p_procedural_vertices > 0) {
		ERR_FAIL_COND_MSG(p_use_indices, "draw_list_draw: procedural vertices cannot use indices.");
		ERR_FAIL_COND_MSG(!vf.attributes.empty(), "draw_list_draw: procedural draws need a pipeline with an empty vertex format.");
		s->bind_list_state();
		vkCmdDraw(s->command_buffer, p_procedural_vertices, p_instances, 0, 0);
		return;
	}
	Impl::VertexArray *va = s->vertex_array_owner.get_or_null(s->list.vertex_array);
	if (!vf.attributes.empty()) {
		ERR_FAIL_NULL_MSG(va, "draw_list_draw: the pipeline has vertex attributes but no (valid) vertex array is bound.");
		ERR_FAIL_COND_MSG(va->format != p->vertex_format, "draw_list_draw: the bound vertex array's format differs from the pipeline's vertex format.");
	}
	if (p_use_indices) {
		Impl::IndexArray *ia = s->index_array_owner.get_or_null(s->list.index_array);
		ERR_FAIL_NULL_MSG(ia, "draw_list_draw: p_use_indices is true but no (valid) index array is bound.");
		s->bind_list_state();
		vkCmdDrawIndexed(s->command_buffer, ia->count, p_instances, ia->offset, 0, 0);
	} else {
		ERR_FAIL_NULL_MSG(va, "draw_list_draw: no vertex array is bound (use p_procedural_vertices for attribute-less draws).");
		s->bind_list_state();
		vkCmdDraw(s->command_buffer, va->vertex_count, p_instances, 0, 0);
	}
}

void RenderingDevice::draw_list_end() {
	Impl *s = impl;
	ERR_FAIL_COND_MSG(!s->list.active || s->list.is_compute, "draw_list_end: no draw list is open.");
	vkCmdEndRenderPass(s->command_buffer);
	s->full_barrier();
	s->list = Impl::ListState();
}

/***********************/
/**** COMPUTE LISTS ****/
/***********************/

RenderingDevice::ComputeListID RenderingDevice::compute_list_begin() {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, INVALID_ID, "RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(s->list.active, INVALID_ID, "compute_list_begin: a draw or compute list is already open.");
	s->ensure_recording();
	s->full_barrier();
	s->list = Impl::ListState();
	s->list.active = true;
	s->list.is_compute = true;
	return COMPUTE_LIST_ID;
}

#define COMPUTE_LIST_CHECK(m_list) \
	ERR_FAIL_COND_MSG(!impl->list.active || !impl->list.is_compute || (m_list) != COMPUTE_LIST_ID, "Invalid or closed compute list.")

void RenderingDevice::compute_list_bind_compute_pipeline(ComputeListID p_list, RID p_compute_pipeline) {
	COMPUTE_LIST_CHECK(p_list);
	Impl *s = impl;
	Impl::Pipeline *p = s->pipeline_owner.get_or_null(p_compute_pipeline);
	ERR_FAIL_NULL_MSG(p, "compute_list_bind_compute_pipeline: invalid pipeline RID.");
	ERR_FAIL_COND_MSG(!p->is_compute, "compute_list_bind_compute_pipeline: this is a render pipeline.");
	if (s->list.pipeline == p_compute_pipeline) {
		return;
	}
	s->list.pipeline = p_compute_pipeline;
	s->list.pipeline_dirty = true;
}

void RenderingDevice::compute_list_bind_uniform_set(ComputeListID p_list, RID p_uniform_set, uint32_t p_index) {
	COMPUTE_LIST_CHECK(p_list);
	Impl *s = impl;
	ERR_FAIL_NULL_MSG(s->uniform_set_owner.get_or_null(p_uniform_set), "compute_list_bind_uniform_set: invalid uniform set RID (it may have been freed with a resource it used).");
	ERR_FAIL_COND_MSG(p_index >= s->properties.limits.maxBoundDescriptorSets, "compute_list_bind_uniform_set: set index exceeds the device limit.");
	if (s->list.sets.size() <= p_index) {
		s->list.sets.resize(p_index + 1);
		s->list.set_dirty.resize(p_index + 1, true);
	}
	s->list.sets[p_index] = p_uniform_set;
	s->list.set_dirty[p_index] = true;
}

void RenderingDevice::compute_list_set_push_constant(ComputeListID p_list, const void *p_data, uint32_t p_data_size) {
	COMPUTE_LIST_CHECK(p_list);
	ERR_FAIL_NULL_MSG(p_data, "compute_list_set_push_constant: data is null.");
	Impl *s = impl;
	Impl::Pipeline *p = s->pipeline_owner.get_or_null(s->list.pipeline);
	ERR_FAIL_NULL_MSG(p, "compute_list_set_push_constant: bind a pipeline first.");
	ERR_FAIL_COND_MSG(p_data_size != p->push_constant_size, vformat("compute_list_set_push_constant: %u bytes given, the shader's push constant block is %u bytes.", p_data_size, p->push_constant_size));
	s->list.push_data.assign((const uint8_t *)p_data, (const uint8_t *)p_data + p_data_size);
	s->list.push_dirty = true;
}

void RenderingDevice::compute_list_dispatch(ComputeListID p_list, uint32_t p_x_groups, uint32_t p_y_groups, uint32_t p_z_groups) {
	COMPUTE_LIST_CHECK(p_list);
	Impl *s = impl;
	const VkPhysicalDeviceLimits &lim = s->properties.limits;
	ERR_FAIL_COND_MSG(p_x_groups == 0 || p_y_groups == 0 || p_z_groups == 0, "compute_list_dispatch: a group count is zero.");
	ERR_FAIL_COND_MSG(p_x_groups > lim.maxComputeWorkGroupCount[0] || p_y_groups > lim.maxComputeWorkGroupCount[1] || p_z_groups > lim.maxComputeWorkGroupCount[2], "compute_list_dispatch: group count exceeds the device limit.");
	if (!validate_list_state(s, "compute_list_dispatch")) {
		return;
	}
	if (s->list.dispatch_count > 0) {
		s->full_barrier();
	}
	s->bind_list_state();
	vkCmdDispatch(s->command_buffer, p_x_groups, p_y_groups, p_z_groups);
	s->list.dispatch_count++;
}

void RenderingDevice::compute_list_dispatch_threads(ComputeListID p_list, uint32_t p_x_threads, uint32_t p_y_threads, uint32_t p_z_threads) {
	COMPUTE_LIST_CHECK(p_list);
	Impl::Pipeline *p = impl->pipeline_owner.get_or_null(impl->list.pipeline);
	ERR_FAIL_NULL_MSG(p, "compute_list_dispatch_threads: bind a pipeline first.");
	uint32_t gx = (p_x_threads + p->local_size[0] - 1) / p->local_size[0];
	uint32_t gy = (p_y_threads + p->local_size[1] - 1) / p->local_size[1];
	uint32_t gz = (p_z_threads + p->local_size[2] - 1) / p->local_size[2];
	compute_list_dispatch(p_list, std::max(gx, 1u), std::max(gy, 1u), std::max(gz, 1u));
}

void RenderingDevice::compute_list_add_barrier(ComputeListID p_list) {
	COMPUTE_LIST_CHECK(p_list);
	impl->full_barrier();
}

void RenderingDevice::compute_list_end() {
	Impl *s = impl;
	ERR_FAIL_COND_MSG(!s->list.active || !s->list.is_compute, "compute_list_end: no compute list is open.");
	s->full_barrier();
	s->list = Impl::ListState();
}
