/**************************************************************************/
/*  rid.h                                                                 */
/**************************************************************************/
/* An opaque handle to a server-side object. 0 is the invalid RID.         */

#pragma once

#include <cstdint>
#include <functional>

class RID {
	uint64_t _id = 0;

public:
	bool operator==(const RID &p_rid) const { return _id == p_rid._id; }
	bool operator!=(const RID &p_rid) const { return _id != p_rid._id; }
	bool operator<(const RID &p_rid) const { return _id < p_rid._id; }
	bool is_valid() const { return _id != 0; }
	bool is_null() const { return _id == 0; }
	uint64_t get_id() const { return _id; }

	static RID from_uint64(uint64_t p_id) {
		RID r;
		r._id = p_id;
		return r;
	}
	RID() {}
};

template <>
struct std::hash<RID> {
	size_t operator()(const RID &p_rid) const { return std::hash<uint64_t>()(p_rid.get_id()); }
};
