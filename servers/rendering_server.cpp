/**************************************************************************/
/*  rendering_server.cpp                                                  */
/**************************************************************************/

#include "servers/rendering_server.h"

#include "core/error/error_macros.h"

RenderingServer *RenderingServer::singleton = nullptr;

int RenderingServer::get_ss_radiosity_sample_count(int p_quality) {
	static const int counts[ENV_SSIL_QUALITY_ULTRA + 1] = { 12, 24, 48, 80, 128 };
	return (p_quality >= 0 && p_quality <= ENV_SSIL_QUALITY_ULTRA) ? counts[p_quality] : 48;
}

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
