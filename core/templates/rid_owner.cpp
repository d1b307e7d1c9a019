/**************************************************************************/
/*  rid_owner.cpp                                                         */
/**************************************************************************/

#include "core/templates/rid_owner.h"

std::atomic<uint64_t> RID_AllocBase::base_id{ 0 };
std::atomic<uint64_t> RID_AllocBase::leaked_total{ 0 };

void RID_AllocBase::_report_leaks(const char *p_description, uint64_t p_count) {
	leaked_total.fetch_add(p_count);
	ERR_PRINT(vformat("%llu RID allocations of type '%s' were leaked at exit.", (unsigned long long)p_count, p_description && p_description[0] ? p_description : "unnamed"));
}
