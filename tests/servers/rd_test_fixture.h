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
		RenderingDevice *rd = new RenderingDevice;
		String err;
		if (!rd->initialize(&err)) {
			fprintf(stderr, "rd_test_get_device: RenderingDevice initialization failed: %s\n", err.c_str());
			delete rd;
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
#define RD_TEST_CHECK_NO_VALIDATION_ERRORS(m_rd)              \
	do {                                                      \
		(m_rd)->submit_and_sync();                            \
		CHECK((m_rd)->get_validation_error_count() == 0);     \
	} while (0)
