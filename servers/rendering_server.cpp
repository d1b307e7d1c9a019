/**************************************************************************/
/*  rendering_server.cpp                                                  */
/**************************************************************************/

#include "servers/rendering_server.h"

#include "core/error/error_macros.h"

RenderingServer *RenderingServer::singleton = nullptr;

RenderingServer::RenderingServer() {
	if (singleton) {
		ERR_PRINT("A RenderingServer already exists; the new one replaces it as the singleton.");
	}
	singleton = this;
}

RenderingServer::~RenderingServer() {
	if (singleton == this) {
		singleton = nullptr;
	}
}

void RenderingServer::material_texture_channel_weights(RS::MaterialTextureChannel p_channel, float r_weights[4]) {
	for (int i = 0; i < 4; i++) {
		r_weights[i] = 0.0f;
	}
	if (p_channel == RS::MATERIAL_TEXTURE_CHANNEL_GRAYSCALE) {
		r_weights[0] = r_weights[1] = r_weights[2] = 1.0f / 3.0f;
	} else if (int(p_channel) >= 0 && int(p_channel) < 4) {
		r_weights[int(p_channel)] = 1.0f;
	} else {
		r_weights[0] = 1.0f; // Out of range: red, as the default.
	}
}
