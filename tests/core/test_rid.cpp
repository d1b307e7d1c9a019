/**************************************************************************/
/*  test_rid.cpp                                                          */
/**************************************************************************/

#include "core/templates/rid_owner.h"

#include <doctest/doctest.h>

namespace TestRID {

struct Payload {
	int value = 0;
};

TEST_CASE("[RID] owner allocates, finds, frees and rejects stale RIDs") {
	RID_Owner<Payload> owner("Payload");
	RID a = owner.make_rid(Payload{ 7 });
	RID b = owner.make_rid();
	CHECK(a.is_valid());
	CHECK(a != b);
	REQUIRE(owner.get_or_null(a) != nullptr);
	CHECK(owner.get_or_null(a)->value == 7);
	owner.free(a);
	CHECK(owner.get_or_null(a) == nullptr);
	CHECK_FALSE(owner.owns(a));

	int errors = 0;
	ErrorHandlerList handler;
	handler.callback = [&](ErrorHandlerType p_type, const String &p_text) { errors++; };
	add_error_handler(&handler);
	set_error_print_silenced(true);
	owner.free(a); // Double free is reported, not a crash.
	set_error_print_silenced(false);
	remove_error_handler(&handler);
	CHECK(errors == 1);
	owner.free(b);
	CHECK(owner.get_rid_count() == 0);
}

TEST_CASE("[RID] leaks are reported when an owner is destroyed") {
	uint64_t before = RID_AllocBase::get_leaked_total();
	set_error_print_silenced(true);
	{
		RID_Owner<Payload> owner("LeakyPayload");
		owner.make_rid();
		owner.make_rid();
	}
	set_error_print_silenced(false);
	CHECK(RID_AllocBase::get_leaked_total() == before + 2);
}

} // namespace TestRID
