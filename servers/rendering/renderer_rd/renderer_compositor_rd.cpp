/**************************************************************************/
/*  renderer_compositor_rd.cpp                                            */
/**************************************************************************/

#include "servers/rendering/renderer_rd/renderer_compositor_rd.h"

#include "core/error/error_macros.h"

RendererCompositorRD::RendererCompositorRD() :
		scene_render(&light_storage, &mesh_storage, &material_storage) {
}

bool RendererCompositorRD::initialize(uint32_t p_max_lights_per_type) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_COND_V_MSG(!rd || !rd->is_initialized(), false, "RendererCompositorRD::initialize() needs an initialized RenderingDevice.");
	ERR_FAIL_COND_V_MSG(!material_storage.initialize_gpu(), false, "RendererCompositorRD: material storage GPU setup failed.");
	ERR_FAIL_COND_V_MSG(!light_storage.initialize_gpu(p_max_lights_per_type), false, "RendererCompositorRD: light storage GPU setup failed.");
	ERR_FAIL_COND_V_MSG(!scene_render.initialize(p_max_lights_per_type), false, "RendererCompositorRD: the Forward+ renderer failed to initialize.");
	return true;
}

void RendererCompositorRD::finalize() {
	scene_render.finalize();
	light_storage.finalize_gpu();
	material_storage.finalize_gpu();
}

RendererCompositorRD::~RendererCompositorRD() {
	finalize();
}
