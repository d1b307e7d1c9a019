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
