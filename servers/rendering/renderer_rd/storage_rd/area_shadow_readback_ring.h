/**************************************************************************/
/*  area_shadow_readback_ring.h                                           */
/**************************************************************************/
/* godot-area: the no-stall readback policy of adaptive area shadows      */
/* (thesis section 6.3 needed a CPU stall; this does not), GPU-free so it */
/* is unit-testable.                                                      */
/*                                                                        */
/* A ring of N (2..4) slots, each standing for one GPU result buffer.     */
/* Frame F writes its banding flags into a free slot; the decisions of    */
/* frame F use the newest slot whose frame is COMPLETE (<= F - 1). The    */
/* completion test is an injected predicate (a fence, or the device's     */
/* completed-frame counter); the ring polls only frames older than the    */
/* one being built and never waits. When every slot is still in flight,   */
/* the frame issues no tests (skipped) instead of waiting.                */

#pragma once

#include <cstdint>
#include <functional>
#include <vector>

class AreaShadowReadbackRing {
public:
	/* Definition */

	static constexpr uint32_t MIN_SLOTS = 2;
	static constexpr uint32_t MAX_SLOTS = 4;
	static constexpr uint32_t DEFAULT_SLOTS = 3;

	// true when everything recorded in frame p_frame has finished on the GPU (must not block).
	using FrameCompletePredicate = std::function<bool(uint64_t p_frame)>;

	enum SlotState {
		SLOT_FREE,
		SLOT_IN_FLIGHT, // Written by a frame whose GPU work may still run.
		SLOT_COMPLETE, // Its frame finished: the buffer may be read without waiting.
	};

private:
	/* Private Members */

	struct Slot {
		SlotState state = SLOT_FREE;
		uint64_t frame = 0;
	};

	std::vector<Slot> slots;
	FrameCompletePredicate frame_complete;
	uint64_t current_frame = 0;
	bool in_frame = false;
	bool wrote_this_frame = false;
	uint64_t skipped_frames = 0;
	uint64_t dropped_results = 0;
	uint64_t polls = 0;
	uint64_t current_frame_polls = 0; // Polls about the frame being built: must stay 0.

	void _poll();

public:
	/* Public Methods */

	// Number of slots (2..4); frees every slot (results in flight are dropped). false on bad input.
	bool configure(uint32_t p_slots);
	uint32_t get_slot_count() const { return uint32_t(slots.size()); }
	void set_frame_complete_predicate(const FrameCompletePredicate &p_predicate) { frame_complete = p_predicate; }

	// Starts frame p_frame (strictly increasing): polls the slots in flight of older frames.
	void begin_frame(uint64_t p_frame);
	uint64_t get_current_frame() const { return current_frame; }
	// The newest completed slot (its frame <= current - 1), or -1. It and every older completed slot
	// are released (older results are stale). r_frame: the frame that wrote it.
	int take_newest_completed(uint64_t *r_frame = nullptr);
	// A slot to write this frame's results into (free, or completed and unread: dropped), or -1 when all
	// are in flight; then the frame must not issue tests. At most one slot per frame.
	int acquire_write_slot();

	SlotState get_slot_state(uint32_t p_slot) const;
	uint64_t get_slot_frame(uint32_t p_slot) const;
	uint32_t get_in_flight_count() const;
	uint64_t get_skipped_frame_count() const { return skipped_frames; }
	uint64_t get_dropped_result_count() const { return dropped_results; }
	uint64_t get_poll_count() const { return polls; }
	// Completion polls about the current frame or a newer one (instrumentation; always 0).
	uint64_t get_current_frame_poll_count() const { return current_frame_polls; }

	AreaShadowReadbackRing();
};
