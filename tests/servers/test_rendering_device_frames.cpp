/**************************************************************************/
/*  test_rendering_device_frames.cpp                                      */
/**************************************************************************/
/* RenderingDevice frames in flight (issue 17 item 6): with               */
/* rendering/rendering_device/vsync/frame_queue_size 2, swap_buffers()    */
/* after frame N waits only for frame N - 1 (counted fence waits and the  */
/* completed serial, not timing); 200 frames of changing uploads, compute */
/* and draws read back right through async readbacks and flushes; what is */
/* freed while frames are in flight is destroyed after they complete (the */
/* validation layer flags a destroy of an object a pending command buffer */
/* uses); queue size 1 waits for every frame as before.                   */

#include "servers/rendering/rendering_device.h"

#include "core/error/error_macros.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/rd_test_shaders.h"

#include <doctest/doctest.h>

#include <cstring>

namespace {

// out[i] = in[i] * 2 + frame.
const char *frames_compute = R"(#version 450
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) readonly buffer In { uint values[]; } in_buf;
layout(set = 0, binding = 1, std430) buffer Out { uint values[]; } out_buf;
layout(push_constant, std430) uniform Params { uint frame; uint count; uint pad0; uint pad1; } params;
void main() {
	uint i = gl_GlobalInvocationID.x;
	if (i >= params.count) { return; }
	out_buf.values[i] = in_buf.values[i] * 2u + params.frame;
}
)";

// The colour comes from a uniform buffer updated every frame.
const char *frames_fs = R"(#version 450
layout(set = 0, binding = 0, std140) uniform Colour { vec4 value; } colour;
layout(location = 0) out vec4 frag_color;
void main() { frag_color = colour.value; }
)";

struct FrameParams {
	uint32_t frame;
	uint32_t count;
	uint32_t pad0;
	uint32_t pad1;
};

// Records one frame's uniqueness into the compute output: in[i] = i + 1000 * p_frame.
void record_compute_frame(RenderingDevice *p_rd, RID p_pipeline, RID p_set, RID p_in, uint32_t p_frame, uint32_t p_count) {
	std::vector<uint32_t> in(p_count);
	for (uint32_t i = 0; i < p_count; i++) {
		in[i] = i + 1000u * p_frame;
	}
	CHECK(p_rd->buffer_update(p_in, 0, p_count * 4, in.data()));
	FrameParams params = { p_frame, p_count, 0, 0 };
	RD::ComputeListID list = p_rd->compute_list_begin();
	p_rd->compute_list_bind_compute_pipeline(list, p_pipeline);
	p_rd->compute_list_bind_uniform_set(list, p_set, 0);
	p_rd->compute_list_set_push_constant(list, &params, sizeof(params));
	p_rd->compute_list_dispatch_threads(list, p_count, 1, 1);
	p_rd->compute_list_end();
}

} // namespace

TEST_CASE("[RenderingDevice] frame_queue_size: the setting, its default and its range") {
	CHECK(String(RD::SETTING_FRAME_QUEUE_SIZE) == "rendering/rendering_device/vsync/frame_queue_size");
	CHECK(RD::DEFAULT_FRAME_QUEUE_SIZE == 2); // Godot's default.
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	CHECK(rd->get_frame_queue_size() == RD::get_project_frame_queue_size());
	set_error_print_silenced(true);
	CHECK_FALSE(rd->set_frame_queue_size(0));
	CHECK_FALSE(rd->set_frame_queue_size(4));
	set_error_print_silenced(false);
	REQUIRE(rd->set_frame_queue_size(3));
	CHECK(rd->get_frame_queue_size() == 3);
	REQUIRE(rd->set_frame_queue_size(2));
	CHECK(rd->get_frame_queue_size() == 2);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] frames in flight: swap_buffers() waits only for the frame queue size frames old") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const uint32_t original = rd->get_frame_queue_size();

	SUBCASE("queue size 2: frame N+1 opens without waiting for frame N") {
		REQUIRE(rd->set_frame_queue_size(2));
		rd->submit_and_sync(); // Nothing in flight.
		const uint64_t s0 = rd->get_frames_submitted();
		CHECK(rd->get_frames_completed() == s0);
		const uint64_t w0 = rd->get_fence_wait_count();
		// First swap: the next slot held no frame, nothing to wait for.
		rd->capture_timestamp("frame a");
		rd->swap_buffers();
		CHECK(rd->get_frames_submitted() == s0 + 1);
		CHECK(rd->get_fence_wait_count() == w0);
		CHECK(rd->get_frames_completed() == s0); // Frame s0 + 1 is in flight.
		for (uint32_t n = 2; n <= 10; n++) {
			rd->capture_timestamp(vformat("frame %u", n));
			rd->swap_buffers();
			const uint64_t newest = s0 + n;
			CHECK(rd->get_frames_submitted() == newest);
			// Exactly one wait per swap, for frame newest - 1; frame newest was not waited for.
			CHECK(rd->get_fence_wait_count() == w0 + n - 1);
			CHECK(rd->get_frames_completed() == newest - 1);
			// The captured timestamps are those of the completed frame, named as it named them.
			CHECK(rd->get_captured_timestamps_frame() == newest - 1);
			if (rd->get_device_info().timestamps_supported) {
				REQUIRE(rd->get_captured_timestamps_count() == 1);
				CHECK(rd->get_captured_timestamp_name(0) == (n == 2 ? String("frame a") : vformat("frame %u", n - 1)));
			}
		}
		// sync() is a full flush: it waits for the frame still in flight too.
		rd->sync();
		CHECK(rd->get_frames_completed() == rd->get_frames_submitted());
	}

	SUBCASE("queue size 1: every swap waits for the frame it submitted, as before") {
		REQUIRE(rd->set_frame_queue_size(1));
		rd->submit_and_sync();
		const uint64_t w0 = rd->get_fence_wait_count();
		for (uint32_t n = 1; n <= 5; n++) {
			rd->capture_timestamp(vformat("single %u", n));
			rd->swap_buffers();
			CHECK(rd->get_fence_wait_count() == w0 + n);
			CHECK(rd->get_frames_completed() == rd->get_frames_submitted());
			if (rd->get_device_info().timestamps_supported) {
				CHECK(rd->get_captured_timestamp_name(0) == vformat("single %u", n));
			}
		}
	}

	REQUIRE(rd->set_frame_queue_size(original));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] frames in flight: 200 frames of changing uploads, compute and draws read back right") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const uint32_t original = rd->get_frame_queue_size();
	uint32_t queue_size = 2;
	SUBCASE("queue size 2") {
		queue_size = 2;
	}
	SUBCASE("queue size 3") {
		queue_size = 3;
	}
	REQUIRE(rd->set_frame_queue_size(queue_size));
	rd->reset_validation_counts();

	RID compute_shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_COMPUTE, frames_compute } }, "frames_compute");
	REQUIRE(compute_shader.is_valid());
	RID compute_pipeline = rd->compute_pipeline_create(compute_shader);
	const uint32_t count = 4096;
	RID in = rd->storage_buffer_create(count * 4);
	RID out = rd->storage_buffer_create(count * 4);
	RID compute_set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, in), RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, out) }, compute_shader, 0);
	REQUIRE(compute_set.is_valid());

	RID draw_shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_VERTEX, RD_TEST_FULLSCREEN_VS }, { RD::SHADER_STAGE_FRAGMENT, frames_fs } }, "frames_draw");
	REQUIRE(draw_shader.is_valid());
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R8G8B8A8_UNORM;
	tf.width = tf.height = 8;
	tf.usage_bits = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	RID target = rd->texture_create(tf);
	RID fb = rd->framebuffer_create({ target });
	REQUIRE(fb.is_valid());
	RID draw_pipeline = rd->render_pipeline_create(draw_shader, rd->framebuffer_get_format(fb), rd->vertex_format_create({}), RD::RENDER_PRIMITIVE_TRIANGLES, RD::PipelineRasterizationState(), RD::PipelineDepthStencilState(), RD::PipelineColorBlendState::create_disabled(1));
	REQUIRE(draw_pipeline.is_valid());
	RID colour = rd->uniform_buffer_create(16);
	RID draw_set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, colour) }, draw_shader, 0);
	REQUIRE(draw_set.is_valid());
	// A large upload every 16 frames: more than one 4 MiB staging block in a slot.
	RID big = rd->storage_buffer_create(6 * 1024 * 1024);
	std::vector<uint8_t> big_data(6 * 1024 * 1024);

	const uint32_t frames = 200;
	uint32_t delivered = 0;
	uint32_t wrong_values = 0;
	uint32_t out_of_order = 0;
	int64_t last_frame_delivered = -1;
	uint32_t draw_checks = 0;
	uint32_t wrong_pixels = 0;
	uint32_t frames_not_overlapped = 0;
	for (uint32_t f = 0; f < frames; f++) {
		record_compute_frame(rd, compute_pipeline, compute_set, in, f, count);
		CHECK(rd->buffer_get_data_async(out, [&, f](const std::vector<uint8_t> &p_bytes) {
			delivered++;
			if (int64_t(f) <= last_frame_delivered) {
				out_of_order++;
			}
			last_frame_delivered = f;
			if (p_bytes.size() != count * 4) {
				wrong_values++;
				return;
			}
			const uint32_t *v = reinterpret_cast<const uint32_t *>(p_bytes.data());
			for (uint32_t i = 0; i < count; i++) {
				if (v[i] != (i + 1000u * f) * 2u + f) {
					wrong_values++;
					return;
				}
			}
		}));
		if (f % 16 == 0) {
			memset(big_data.data(), int(f & 0xff), big_data.size());
			CHECK(rd->buffer_update(big, 0, uint32_t(big_data.size()), big_data.data()));
		}
		const uint8_t level = uint8_t((f * 37) % 256);
		float value[4] = { float(level) / 255.0f, float(255 - level) / 255.0f, float(f % 2), 1.0f };
		CHECK(rd->buffer_update(colour, 0, sizeof(value), value));
		RD::DrawListID dl = rd->draw_list_begin(fb, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, { Color(0, 0, 0, 0) });
		rd->draw_list_bind_render_pipeline(dl, draw_pipeline);
		rd->draw_list_bind_uniform_set(dl, draw_set, 0);
		rd->draw_list_draw(dl, false, 1, 3);
		rd->draw_list_end();
		if (f % 25 == 24) {
			// A synchronous readback in the middle of frames in flight waits for what it needs.
			std::vector<uint8_t> pixels = rd->texture_get_data(target);
			draw_checks++;
			if (pixels.size() != 8 * 8 * 4 || pixels[0] != level || pixels[1] != uint8_t(255 - level) || pixels[2] != uint8_t((f % 2) * 255) || pixels[(7 * 8 + 7) * 4] != level) {
				wrong_pixels++;
			}
			std::vector<uint8_t> big_back = rd->buffer_get_data(big, uint32_t(big_data.size()) - 4, 4);
			if (big_back.size() != 4 || big_back[3] != uint8_t((f / 16) * 16)) {
				wrong_pixels++;
			}
		}
		rd->swap_buffers();
		if (rd->get_frames_completed() >= rd->get_frames_submitted() && queue_size > 1 && f % 25 != 24) {
			frames_not_overlapped++; // The frame just submitted was waited for.
		}
	}
	rd->sync();
	CHECK(delivered == frames);
	CHECK(wrong_values == 0);
	CHECK(out_of_order == 0);
	CHECK(draw_checks == 8);
	CHECK(wrong_pixels == 0);
	CHECK(frames_not_overlapped == 0);

	rd->free(big);
	rd->free(colour);
	rd->free(target);
	rd->free(draw_shader);
	rd->free(in);
	rd->free(out);
	rd->free(compute_shader);
	REQUIRE(rd->set_frame_queue_size(original));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] frames in flight: what is freed while frames use it is destroyed after they complete") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	if (!rd->get_device_info().validation_enabled) {
		MESSAGE("skipped: the Khronos validation layer is not available, so an early destroy would go unseen");
		return;
	}
	const uint32_t original = rd->get_frame_queue_size();
	REQUIRE(rd->set_frame_queue_size(2));
	rd->reset_validation_counts();
	RID compute_shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_COMPUTE, frames_compute } }, "frames_free");
	REQUIRE(compute_shader.is_valid());
	RID compute_pipeline = rd->compute_pipeline_create(compute_shader);
	const uint32_t count = 64 * 1024;
	RID out = rd->storage_buffer_create(count * 4);
	uint32_t freed = 0;
	for (uint32_t f = 0; f < 6; f++) {
		// Per frame: a fresh input buffer and uniform set, used by this frame only and freed right after
		// recording, while this frame (and the previous one) are still in flight.
		RID in = rd->storage_buffer_create(count * 4);
		RID set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, in), RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 1, out) }, compute_shader, 0);
		REQUIRE(set.is_valid());
		record_compute_frame(rd, compute_pipeline, set, in, f, count);
		rd->submit(); // On the GPU (or queued), then freed.
		rd->free(in); // Frees the set too.
		freed++;
		CHECK(rd->get_frames_completed() < rd->get_frames_submitted()); // It still runs (or may).
		rd->swap_buffers();
	}
	// The last frame's output is right: nothing it used went away under it.
	std::vector<uint8_t> back = rd->buffer_get_data(out, 4 * 10, 4);
	REQUIRE(back.size() == 4);
	uint32_t v = 0;
	memcpy(&v, back.data(), 4);
	CHECK(v == (10u + 1000u * 5u) * 2u + 5u);
	CHECK(freed == 6);
	CHECK(rd->get_validation_error_count() == 0); // vkDestroyBuffer/-DescriptorPool of in-use objects would count.
	rd->free(out);
	rd->free(compute_shader);
	REQUIRE(rd->set_frame_queue_size(original));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}
