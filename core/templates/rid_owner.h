/**************************************************************************/
/*  rid_owner.h                                                           */
/**************************************************************************/
/* RID_Owner<T>: owns the objects behind RIDs of one type. Freed RIDs are  */
/* never reused (ids are globally unique), so a stale RID is detected.     */
/* At destruction, every RID still allocated is reported as a leak.       */

#pragma once

#include "core/error/error_macros.h"
#include "core/templates/rid.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

class RID_AllocBase {
	static std::atomic<uint64_t> base_id;
	static std::atomic<uint64_t> leaked_total;

protected:
	static RID _gen_rid() { return RID::from_uint64(base_id.fetch_add(1) + 1); }
	static void _report_leaks(const char *p_description, uint64_t p_count);

public:
	// Number of RIDs reported leaked by owners destroyed so far (tests read it).
	static uint64_t get_leaked_total() { return leaked_total.load(); }
};

template <typename T, bool THREAD_SAFE = false>
class RID_Owner : public RID_AllocBase {
	std::unordered_map<uint64_t, std::unique_ptr<T>> owned;
	mutable std::mutex mutex;
	const char *description = "";

	void _lock() const {
		if (THREAD_SAFE) {
			mutex.lock();
		}
	}
	void _unlock() const {
		if (THREAD_SAFE) {
			mutex.unlock();
		}
	}

public:
	// Reserves a RID without an object; initialize_rid() gives it one (Godot's split creation).
	RID allocate_rid() {
		_lock();
		RID rid = _gen_rid();
		owned[rid.get_id()] = nullptr;
		_unlock();
		return rid;
	}
	void initialize_rid(RID p_rid, const T &p_value = T()) {
		_lock();
		auto it = owned.find(p_rid.get_id());
		if (it == owned.end()) {
			_unlock();
			ERR_FAIL_MSG("initialize_rid: RID was not allocated by this owner.");
		}
		it->second = std::make_unique<T>(p_value);
		_unlock();
	}
	RID make_rid(const T &p_value = T()) {
		RID rid = allocate_rid();
		initialize_rid(rid, p_value);
		return rid;
	}

	T *get_or_null(const RID &p_rid) const {
		_lock();
		auto it = owned.find(p_rid.get_id());
		T *ptr = it == owned.end() ? nullptr : it->second.get();
		_unlock();
		return ptr;
	}
	bool owns(const RID &p_rid) const {
		_lock();
		bool found = owned.count(p_rid.get_id()) != 0;
		_unlock();
		return found;
	}
	void free(const RID &p_rid) {
		_lock();
		auto it = owned.find(p_rid.get_id());
		if (it == owned.end()) {
			_unlock();
			ERR_FAIL_MSG(vformat("Attempted to free an invalid or already freed RID (%s).", description));
		}
		owned.erase(it);
		_unlock();
	}
	uint32_t get_rid_count() const {
		_lock();
		uint32_t c = (uint32_t)owned.size();
		_unlock();
		return c;
	}
	std::vector<RID> get_owned_list() const {
		_lock();
		std::vector<RID> list;
		for (const auto &kv : owned) {
			list.push_back(RID::from_uint64(kv.first));
		}
		_unlock();
		return list;
	}
	void set_description(const char *p_description) { description = p_description; }

	RID_Owner(const char *p_description = "") :
			description(p_description) {}
	~RID_Owner() {
		if (!owned.empty()) {
			_report_leaks(description, owned.size());
		}
	}
};
