/**************************************************************************/
/*  scene_test_fixture.h                                                  */
/**************************************************************************/
/* godot-area: shared helpers for scene tests: a RenderingServerDefault   */
/* on the dummy (CPU-only) backend with the scene classes registered,     */
/* and an error catcher that silences and records error messages.         */

#pragma once

#include "core/error/error_macros.h"
#include "scene/register_scene_types.h"
#include "servers/rendering/dummy/rasterizer_dummy.h"
#include "servers/rendering/rendering_server_default.h"

#include <vector>

namespace SceneTest {

// Silences error printing and records every error/warning text while alive.
struct ErrorCatcher {
	ErrorHandlerList handler;
	std::vector<String> messages;

	bool contains(const String &p_text) const {
		for (const String &m : messages) {
			if (m.find(p_text) != String::npos) {
				return true;
			}
		}
		return false;
	}
	ErrorCatcher() {
		handler.callback = [this](ErrorHandlerType, const String &p_text) { messages.push_back(p_text); };
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~ErrorCatcher() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
};

// Create first in a test case; everything scene-side must be deleted before it goes.
struct DummyServer {
	RasterizerDummy *rasterizer = nullptr; // Owned by rs.
	RenderingServerDefault *rs = nullptr;
	DummyServer() {
		rasterizer = new RasterizerDummy;
		rs = new RenderingServerDefault(rasterizer);
		register_scene_types();
	}
	// What the server handed to the (dummy) renderer in the last draw.
	const RenderSceneData &last_scene() const { return rasterizer->get_scene_dummy()->get_last_scene_data(); }
	~DummyServer() { delete rs; }
};

} // namespace SceneTest
