/**************************************************************************/
/*  scene_test_fixture.h                                                  */
/**************************************************************************/
/* godot-area: shared helpers for scene and server tests: the engine      */
/* (GodotInstance) on the dummy (CPU-only) backend with the scene classes */
/* registered, and an error catcher that silences and records errors.     */

#pragma once

#include "core/error/error_macros.h"
#include "scene/main/godot_instance.h"
#include "servers/rendering/dummy/rasterizer_dummy.h"
#include "servers/rendering/rendering_server_default.h"

#include <doctest/doctest.h>

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
	GodotInstance engine;
	RasterizerDummy *rasterizer = nullptr; // Owned by the engine.
	RenderingServerDefault *rs = nullptr;
	DummyServer() {
		String error;
		REQUIRE_MESSAGE(engine.start(GodotInstance::BACKEND_DUMMY, &error), error);
		rasterizer = static_cast<RasterizerDummy *>(engine.get_compositor());
		rs = static_cast<RenderingServerDefault *>(engine.get_rendering_server());
	}
	// What the server handed to the (dummy) renderer in the last draw.
	const RenderSceneData &last_scene() const { return rasterizer->get_scene_dummy()->get_last_scene_data(); }
};

} // namespace SceneTest
