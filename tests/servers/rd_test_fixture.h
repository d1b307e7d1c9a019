/**************************************************************************/
/*  rd_test_fixture.h                                                     */
/**************************************************************************/
/* Shared test helper: one RenderingDevice per test process, created on   */
/* first use with the Khronos validation layer on (GODOT_AREA_VALIDATION) */
/* and finalized at process exit. Usage in a test:                        */
/*                                                                        */
/*   RenderingDevice *rd = rd_test_get_device();                          */
/*   REQUIRE(rd != nullptr);                                              */
/*   ... use rd ...                                                       */
/*   RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);  // at the end of each test  */

#pragma once

#include "scene/main/godot_instance.h"
#include "servers/rendering/rendering_device.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>

// Returns the shared device, or nullptr if Vulkan could not be initialized (the reason is printed).
inline RenderingDevice *rd_test_get_device() {
	static RenderingDevice *device = nullptr;
	static bool tried = false;
	if (!tried) {
		tried = true;
		setenv("GODOT_AREA_VALIDATION", "1", 1);
		String err;
		bool created = false;
		RenderingDevice *rd = GodotInstance::acquire_rendering_device(&created, &err);
		if (!rd) {
			fprintf(stderr, "rd_test_get_device: RenderingDevice initialization failed: %s\n", err.c_str());
		} else if (!created) {
			tried = false; // A running GodotInstance owns this one: borrow it, do not keep it.
			return rd;
		} else {
			device = rd;
			atexit([]() {
				RenderingDevice *d = RenderingDevice::get_singleton();
				if (d) {
					d->finalize();
					delete d;
				}
			});
		}
	}
	return device;
}

// Flushes pending work and asserts that the validation layer reported no error so far.
#define RD_TEST_CHECK_NO_VALIDATION_ERRORS(m_rd)          \
	do {                                                  \
		(m_rd)->submit_and_sync();                        \
		CHECK((m_rd)->get_validation_error_count() == 0); \
	} while (0)
