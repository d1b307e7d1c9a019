/**************************************************************************/
/*  test_area_shadow_readback_ring.cpp                                    */
/**************************************************************************/
/* godot-area: the no-stall readback ring of adaptive area shadows: the   */
/* decisions of frame N use only results of frames <= N - 1, completion   */
/* is never asked about the frame being built, and a full ring skips the  */
/* frame's tests instead of waiting.                                      */

#include "servers/rendering/renderer_rd/storage_rd/area_shadow_readback_ring.h"

#include "core/error/error_macros.h"

#include <doctest/doctest.h>

#include <random>

namespace TestAreaShadowReadbackRing {

TEST_CASE("[AreaShadowReadbackRing] decisions use completed older frames only and never wait") {
	for (uint32_t slots = AreaShadowReadbackRing::MIN_SLOTS; slots <= 3; slots++) {
		AreaShadowReadbackRing ring;
		REQUIRE(ring.configure(slots));
		std::mt19937 rng(slots * 77);
		uint64_t frame = 0;
		uint64_t gpu_done = 0; // Frames complete up to here (in order, with a random lag).
		uint64_t asked_current = 0;
		uint64_t asked_total = 0;
		ring.set_frame_complete_predicate([&](uint64_t p_frame) {
			asked_total++;
			if (p_frame >= frame) {
				asked_current++; // Would be a wait on the frame being built.
			}
			return p_frame <= gpu_done;
		});
		std::vector<uint64_t> written(slots, 0);
		uint32_t consumed = 0;
		uint64_t newest_used = 0;
		for (frame = 1; frame <= 400; frame++) {
			// The GPU finishes 0..3 frames behind the CPU.
			uint64_t lag = rng() % 4;
			uint64_t target = frame > lag + 1 ? frame - 1 - lag : 0;
			gpu_done = std::max(gpu_done, target);
			ring.begin_frame(frame);
			uint64_t data_frame = 0;
			int slot = ring.take_newest_completed(&data_frame);
			if (slot >= 0) {
				CHECK(data_frame < frame); // <= N - 1.
				CHECK(data_frame <= gpu_done); // Complete: readable without waiting.
				CHECK(written[slot] == data_frame); // The buffer holds that frame's data.
				CHECK(data_frame > newest_used); // Never older than what was already used.
				newest_used = data_frame;
				consumed++;
			}
			int w = ring.acquire_write_slot();
			if (w >= 0) {
				written[w] = frame;
			}
		}
		CHECK(asked_current == 0);
		CHECK(ring.get_current_frame_poll_count() == 0);
		CHECK(asked_total > 0);
		CHECK(consumed > 100); // Results do flow.
	}
}

TEST_CASE("[AreaShadowReadbackRing] a ring full of frames in flight skips instead of waiting") {
	AreaShadowReadbackRing ring;
	REQUIRE(ring.configure(2));
	uint64_t frame = 0;
	bool gpu_stuck = true;
	ring.set_frame_complete_predicate([&](uint64_t p_frame) { return !gpu_stuck && p_frame < frame; });
	for (frame = 1; frame <= 2; frame++) {
		ring.begin_frame(frame);
		CHECK(ring.take_newest_completed() == -1);
		CHECK(ring.acquire_write_slot() >= 0);
	}
	ring.begin_frame(3);
	frame = 3;
	CHECK(ring.take_newest_completed() == -1);
	CHECK(ring.acquire_write_slot() == -1); // Both in flight: no tests this frame, no wait.
	CHECK(ring.get_skipped_frame_count() == 1);
	CHECK(ring.get_in_flight_count() == 2);
	gpu_stuck = false;
	frame = 4;
	ring.begin_frame(4);
	uint64_t f = 0;
	int s = ring.take_newest_completed(&f);
	CHECK(s >= 0);
	CHECK(f == 2); // The newest; frame 1's results are dropped as stale.
	CHECK(ring.get_dropped_result_count() == 1);
	CHECK(ring.get_in_flight_count() == 0);
	CHECK(ring.acquire_write_slot() >= 0);
	set_error_print_silenced(true);
	CHECK(ring.acquire_write_slot() == -1); // One slot per frame.
	CHECK_FALSE(ring.configure(1));
	CHECK_FALSE(ring.configure(9));
	set_error_print_silenced(false);
	CHECK(ring.get_slot_count() == 2);
}

} // namespace TestAreaShadowReadbackRing
