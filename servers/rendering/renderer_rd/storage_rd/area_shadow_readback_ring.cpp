/**************************************************************************/
/*  area_shadow_readback_ring.cpp                                         */
/**************************************************************************/

#include "servers/rendering/renderer_rd/storage_rd/area_shadow_readback_ring.h"

#include "core/error/error_macros.h"

AreaShadowReadbackRing::AreaShadowReadbackRing() {
	configure(DEFAULT_SLOTS);
}

bool AreaShadowReadbackRing::configure(uint32_t p_slots) {
	ERR_FAIL_COND_V_MSG(p_slots < MIN_SLOTS || p_slots > MAX_SLOTS, false, vformat("Area shadow readback ring: %u slots is invalid (expected %u..%u).", p_slots, MIN_SLOTS, MAX_SLOTS));
	slots.assign(p_slots, Slot());
	return true;
}

void AreaShadowReadbackRing::_poll() {
	for (Slot &s : slots) {
		if (s.state != SLOT_IN_FLIGHT) {
			continue;
		}
		if (s.frame >= current_frame) {
			current_frame_polls++; // Never happens: a slot of this frame is not polled.
			continue;
		}
		polls++;
		if (!frame_complete || frame_complete(s.frame)) {
			s.state = SLOT_COMPLETE;
		}
	}
}

void AreaShadowReadbackRing::begin_frame(uint64_t p_frame) {
	ERR_FAIL_COND_MSG(in_frame && p_frame <= current_frame, vformat("Area shadow readback ring: frame %llu does not follow frame %llu.", (unsigned long long)p_frame, (unsigned long long)current_frame));
	current_frame = p_frame;
	in_frame = true;
	wrote_this_frame = false;
	_poll();
}

int AreaShadowReadbackRing::take_newest_completed(uint64_t *r_frame) {
	int best = -1;
	for (uint32_t i = 0; i < slots.size(); i++) {
		const Slot &s = slots[i];
		if (s.state == SLOT_COMPLETE && s.frame < current_frame && (best < 0 || s.frame > slots[best].frame)) {
			best = int(i);
		}
	}
	if (best < 0) {
		return -1;
	}
	uint64_t newest = slots[best].frame;
	for (uint32_t i = 0; i < slots.size(); i++) {
		Slot &s = slots[i];
		if (s.state == SLOT_COMPLETE && s.frame <= newest) {
			if (int(i) != best) {
				dropped_results++;
			}
			s.state = SLOT_FREE;
		}
	}
	if (r_frame) {
		*r_frame = newest;
	}
	return best; // Free from now on; the caller reads its buffer before writing it again.
}

int AreaShadowReadbackRing::acquire_write_slot() {
	ERR_FAIL_COND_V_MSG(wrote_this_frame, -1, "Area shadow readback ring: one result slot per frame.");
	int pick = -1;
	for (uint32_t i = 0; i < slots.size(); i++) {
		if (slots[i].state == SLOT_FREE) {
			pick = int(i);
			break;
		}
	}
	if (pick < 0) {
		// A completed but unread slot (the oldest) may be overwritten: its results are stale anyway.
		for (uint32_t i = 0; i < slots.size(); i++) {
			if (slots[i].state == SLOT_COMPLETE && (pick < 0 || slots[i].frame < slots[pick].frame)) {
				pick = int(i);
			}
		}
		if (pick >= 0) {
			dropped_results++;
		}
	}
	if (pick < 0) {
		skipped_frames++;
		return -1; // Everything in flight: skip the tests rather than wait.
	}
	slots[pick].state = SLOT_IN_FLIGHT;
	slots[pick].frame = current_frame;
	wrote_this_frame = true;
	return pick;
}

AreaShadowReadbackRing::SlotState AreaShadowReadbackRing::get_slot_state(uint32_t p_slot) const {
	ERR_FAIL_COND_V_MSG(p_slot >= slots.size(), SLOT_FREE, "Area shadow readback ring: slot index out of range.");
	return slots[p_slot].state;
}

uint64_t AreaShadowReadbackRing::get_slot_frame(uint32_t p_slot) const {
	ERR_FAIL_COND_V_MSG(p_slot >= slots.size(), 0, "Area shadow readback ring: slot index out of range.");
	return slots[p_slot].frame;
}

uint32_t AreaShadowReadbackRing::get_in_flight_count() const {
	uint32_t n = 0;
	for (const Slot &s : slots) {
		n += s.state == SLOT_IN_FLIGHT ? 1 : 0;
	}
	return n;
}
