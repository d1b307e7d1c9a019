/**************************************************************************/
/*  rendering_device_frames.cpp                                           */
/**************************************************************************/
/* RenderingDevice frames in flight (issue 17 item 6). Godot's            */
/* rendering/rendering_device/vsync/frame_queue_size (default 2, 2..3;    */
/* 1 is accepted here too: the old one-frame-at-a-time behaviour, for     */
/* tests and the cost comparison in doc/methods.md) gives the number of   */
/* frame slots. Each slot owns a command buffer (+ pool), a fence, a      */
/* timestamp query pool and the frame's names, an upload arena, its async */
/* readbacks and a deferred-destruction list. swap_buffers() submits      */
/* frame S and opens S + 1 in the next slot, waiting only for the frame   */
/* that used that slot (S + 1 - queue size), so with 2 the CPU records    */
/* S + 1 while the GPU runs S. sync() waits for every frame in flight.    */
/* Queue submission order makes a fence cover every earlier submission    */
/* (Vulkan spec, "Fence signal operation ... all commands that occur      */
/* earlier in submission order"), so what is freed while frame S is the   */
/* newest is destroyed once S's fence signalled. GPU-side hazards between */
/* frames need nothing new: every transfer, list and dispatch is fenced   */
/* by full pipeline barriers, whose scopes reach back across submissions  */
/* on the one queue.                                                      */

#include "servers/rendering/rendering_device.h"

#include "core/config/project_settings.h"
#include "servers/rendering/rendering_device_impl.h"

#include <algorithm>
#include <chrono>
#include <cstring>

typedef RenderingDevice::Impl RDImpl;

bool RDImpl::create_frames(uint32_t p_count, bool p_timestamps) {
	frames.resize(p_count);
	frame_index = 0;
	for (Frame &f : frames) {
		VkCommandPoolCreateInfo pci = { VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO };
		pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
		pci.queueFamilyIndex = queue_family;
		VkResult res = vkCreateCommandPool(device, &pci, nullptr, &f.command_pool);
		ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("vkCreateCommandPool failed (VkResult %d).", res));
		VkCommandBufferAllocateInfo cai = { VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO };
		cai.commandPool = f.command_pool;
		cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
		cai.commandBufferCount = 1;
		res = vkAllocateCommandBuffers(device, &cai, &f.command_buffer);
		ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("vkAllocateCommandBuffers failed (VkResult %d).", res));
		VkFenceCreateInfo fci = { VK_STRUCTURE_TYPE_FENCE_CREATE_INFO };
		res = vkCreateFence(device, &fci, nullptr, &f.fence);
		ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("vkCreateFence failed (VkResult %d).", res));
		if (p_timestamps) {
			VkQueryPoolCreateInfo qpci = { VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO };
			qpci.queryType = VK_QUERY_TYPE_TIMESTAMP;
			qpci.queryCount = MAX_TIMESTAMPS;
			res = vkCreateQueryPool(device, &qpci, nullptr, &f.query_pool);
			ERR_FAIL_COND_V_MSG(res != VK_SUCCESS, false, vformat("vkCreateQueryPool failed (VkResult %d).", res));
			f.timestamp_results = create_staging(MAX_TIMESTAMPS * sizeof(uint64_t));
			ERR_FAIL_COND_V_MSG(!f.timestamp_results.buffer, false, "The timestamp results buffer could not be created.");
		}
	}
	return true;
}

// Only with no frame in flight (after vkDeviceWaitIdle or sync()).
void RDImpl::destroy_frames() {
	for (Frame &f : frames) {
		destroy_pending(f);
		for (Staging &st : f.staging) {
			destroy_staging(device, st);
		}
		for (Readback &r : f.readbacks) {
			destroy_staging(device, r.staging); // Never delivered.
		}
		destroy_staging(device, f.timestamp_results);
		if (f.query_pool) {
			vkDestroyQueryPool(device, f.query_pool, nullptr);
		}
		if (f.fence) {
			vkDestroyFence(device, f.fence, nullptr);
		}
		if (f.command_pool) {
			vkDestroyCommandPool(device, f.command_pool, nullptr);
		}
	}
	frames.clear();
	command_buffer = VK_NULL_HANDLE;
	query_pool = VK_NULL_HANDLE;
}

/****************/
/**** FRAMES ****/
/****************/

void RDImpl::submit_frame() {
	if (submitted || !recording) {
		return;
	}
	Frame &f = current_frame();
	if (open_labels > 0) {
		ERR_PRINT(vformat("submit: %u debug label(s) still open; closing them (each draw_command_begin_label() needs an end).", open_labels));
		for (; open_labels > 0; open_labels--) {
			if (cmd_end_label) {
				cmd_end_label(command_buffer);
			}
		}
	}
	captured_label_names = f.label_names;
	if (!f.timestamp_names.empty() && f.timestamp_results.buffer) {
		// Results to host memory on the GPU timeline, read after the fence (complete_frame).
		full_barrier();
		vkCmdCopyQueryPoolResults(command_buffer, query_pool, 0, uint32_t(f.timestamp_names.size()), f.timestamp_results.buffer, 0, sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
		host_read_barrier(command_buffer);
	}
	vkEndCommandBuffer(command_buffer);
	recording = false;
	VkSubmitInfo si = { VK_STRUCTURE_TYPE_SUBMIT_INFO };
	si.commandBufferCount = 1;
	si.pCommandBuffers = &command_buffer;
	VkResult res = vkQueueSubmit(queue, 1, &si, f.fence);
	if (res != VK_SUCCESS) {
		ERR_PRINT(vformat("vkQueueSubmit failed (VkResult %d); the frame's commands are lost.", res));
		for (Readback &r : f.readbacks) {
			release_readback_staging(r.staging); // Never written: dropped without a callback.
		}
		f.readbacks.clear();
		begin_frame();
		return;
	}
	f.in_flight = true;
	f.serial = ++frames_submitted;
	submitted = true;
}

void RDImpl::complete_frame(Frame &p_frame, std::vector<Completed> &r_completed) {
	if (!p_frame.in_flight) {
		return;
	}
	fence_waits++;
	const auto wait_begin = std::chrono::steady_clock::now();
	VkResult res = vkWaitForFences(device, 1, &p_frame.fence, VK_TRUE, UINT64_MAX);
	fence_wait_usec += uint64_t(std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - wait_begin).count());
	if (res != VK_SUCCESS) {
		ERR_PRINT(vformat("vkWaitForFences failed (VkResult %d); waiting for the device to idle.", res));
		vkDeviceWaitIdle(device);
	}
	vkResetFences(device, 1, &p_frame.fence);
	p_frame.in_flight = false;
	// Fences signal in submission order on the one queue: every earlier frame is complete too.
	frames_completed = std::max(frames_completed, p_frame.serial);
	Completed c;
	c.serial = p_frame.serial;
	// The frame is complete: its async readbacks hold their data.
	for (Readback &r : p_frame.readbacks) {
		std::vector<uint8_t> bytes(r.size);
		memcpy(bytes.data(), r.staging.mapped, r.size);
		release_readback_staging(r.staging);
		c.readbacks.emplace_back(std::move(bytes), std::move(r.callback));
	}
	p_frame.readbacks.clear();
	uint32_t count = (uint32_t)p_frame.timestamp_names.size();
	if (count > 0 && p_frame.query_pool) {
		// The frame copied its results into its mapped buffer (submit_frame): reading them takes no driver
		// call. vkGetQueryPoolResults would: on lavapipe it takes the queue's lock, so it waits for the frame
		// the queue runs now (the next one in flight), which undid the overlap.
		std::vector<uint64_t> ticks(count, 0);
		memcpy(ticks.data(), p_frame.timestamp_results.mapped, count * sizeof(uint64_t));
		c.timestamp_names = p_frame.timestamp_names;
		c.timestamp_times.resize(count);
		double period = properties.limits.timestampPeriod;
		for (uint32_t i = 0; i < count; i++) {
			c.timestamp_times[i] = (uint64_t)((double)ticks[i] * period);
		}
	}
	destroy_pending(p_frame);
	r_completed.push_back(std::move(c));
}

void RDImpl::deliver(std::vector<Completed> &p_completed) {
	for (Completed &c : p_completed) {
		if (!c.timestamp_names.empty()) {
			// A frame without timestamps keeps the previous ones (as before frames in flight).
			captured_timestamp_names = std::move(c.timestamp_names);
			captured_timestamp_times = std::move(c.timestamp_times);
			captured_timestamps_frame = c.serial;
		}
		for (auto &d : c.readbacks) {
			d.second(d.first); // The next frame is open: callbacks may record.
		}
	}
}

void RDImpl::advance_frame() {
	if (!submitted) {
		submit_frame();
	}
	if (!submitted) {
		return;
	}
	frame_index = (frame_index + 1) % (uint32_t)frames.size();
	std::vector<Completed> completed;
	complete_frame(current_frame(), completed); // The frame frame_queue_size frames ago, if any.
	submitted = false;
	begin_frame();
	deliver(completed);
}

void RDImpl::sync_frame() {
	if (!submitted) {
		submit_frame();
	}
	if (!submitted) {
		return;
	}
	// Oldest first: the slot after the current one holds the oldest frame that may be in flight.
	std::vector<Completed> completed;
	const uint32_t count = (uint32_t)frames.size();
	for (uint32_t i = 1; i <= count; i++) {
		complete_frame(frames[(frame_index + i) % count], completed);
	}
	frame_index = (frame_index + 1) % count;
	submitted = false;
	begin_frame();
	deliver(completed);
}

void RDImpl::ensure_recording() {
	if (submitted) {
		advance_frame();
	}
}

void RenderingDevice::submit() {
	ERR_FAIL_COND_MSG(!impl->initialized, "RenderingDevice is not initialized.");
	ERR_FAIL_COND_MSG(impl->list.active, "Cannot submit while a draw or compute list is open; end it first.");
	impl->submit_frame();
}

void RenderingDevice::sync() {
	ERR_FAIL_COND_MSG(!impl->initialized, "RenderingDevice is not initialized.");
	ERR_FAIL_COND_MSG(impl->list.active, "Cannot sync while a draw or compute list is open; end it first.");
	impl->sync_frame();
}

void RenderingDevice::wait_for_frame(uint64_t p_frame) {
	Impl *s = impl;
	ERR_FAIL_COND_MSG(!s->initialized, "RenderingDevice is not initialized.");
	ERR_FAIL_COND_MSG(p_frame > s->frames_submitted, vformat("wait_for_frame: frame %llu was not submitted (newest: %llu).", (unsigned long long)p_frame, (unsigned long long)s->frames_submitted));
	if (p_frame <= s->frames_completed) {
		return;
	}
	// Oldest first, up to p_frame; the open frame is left alone.
	std::vector<Impl::Completed> completed;
	const uint32_t count = uint32_t(s->frames.size());
	for (uint32_t i = 1; i <= count; i++) {
		Impl::Frame &f = s->frames[(s->frame_index + i) % count];
		if (f.in_flight && f.serial <= p_frame) {
			s->complete_frame(f, completed);
		}
	}
	s->deliver(completed);
}

void RenderingDevice::swap_buffers() {
	ERR_FAIL_COND_MSG(!impl->initialized, "RenderingDevice is not initialized.");
	ERR_FAIL_COND_MSG(impl->list.active, "Cannot swap buffers while a draw or compute list is open; end it first.");
	impl->advance_frame();
}

uint32_t RenderingDevice::get_project_frame_queue_size() {
	const int64_t v = GLOBAL_DEF(SETTING_FRAME_QUEUE_SIZE, int64_t(DEFAULT_FRAME_QUEUE_SIZE)).to_int();
	if (v < 1 || v > int64_t(Impl::MAX_FRAME_QUEUE_SIZE)) {
		ERR_PRINT(vformat("%s must be 1, 2 or 3; got %lld. Using %u.", SETTING_FRAME_QUEUE_SIZE, (long long)v, DEFAULT_FRAME_QUEUE_SIZE));
		return DEFAULT_FRAME_QUEUE_SIZE;
	}
	return uint32_t(v);
}

bool RenderingDevice::set_frame_queue_size(uint32_t p_size) {
	Impl *s = impl;
	ERR_FAIL_COND_V_MSG(!s->initialized, false, "set_frame_queue_size: RenderingDevice is not initialized.");
	ERR_FAIL_COND_V_MSG(p_size < 1 || p_size > Impl::MAX_FRAME_QUEUE_SIZE, false, vformat("set_frame_queue_size: %u is not 1, 2 or 3.", p_size));
	ERR_FAIL_COND_V_MSG(s->list.active, false, "set_frame_queue_size: not allowed while a draw or compute list is open.");
	if (p_size == s->frames.size()) {
		return true;
	}
	// Finish everything recorded so far (oldest first); the fresh slots start empty.
	s->submit_frame();
	ERR_FAIL_COND_V_MSG(!s->submitted, false, "set_frame_queue_size: the current frame could not be submitted.");
	std::vector<Impl::Completed> completed;
	const uint32_t count = uint32_t(s->frames.size());
	for (uint32_t i = 1; i <= count; i++) {
		s->complete_frame(s->frames[(s->frame_index + i) % count], completed);
	}
	s->submitted = false;
	const bool timestamps = s->query_pool != VK_NULL_HANDLE;
	s->destroy_frames();
	const bool ok = s->create_frames(p_size, timestamps);
	ERR_FAIL_COND_V_MSG(!ok, false, "set_frame_queue_size: the frame slots could not be created.");
	s->begin_frame();
	s->deliver(completed);
	return true;
}

uint32_t RenderingDevice::get_frame_queue_size() const {
	return uint32_t(impl->frames.size());
}

uint64_t RenderingDevice::get_frames_completed() const {
	return impl->frames_completed;
}

uint64_t RenderingDevice::get_fence_wait_count() const {
	return impl->fence_waits;
}

uint64_t RenderingDevice::get_fence_wait_time_usec() const {
	return impl->fence_wait_usec;
}
