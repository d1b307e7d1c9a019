/**************************************************************************/
/*  renderer_compositor.h                                                 */
/**************************************************************************/
/* godot-area: a rendering backend bundle (Godot's RendererCompositor):   */
/* the storages and the scene renderer of one backend. RenderingServer-   */
/* Default takes ownership of one and publishes its parts through RSG::.  */
/* Backends: RasterizerDummy (CPU, no GPU), RendererCompositorRD. */

#pragma once

#include "servers/rendering/renderer_scene_render.h"
#include "servers/rendering/storage/light_storage.h"
#include "servers/rendering/storage/material_storage.h"
#include "servers/rendering/storage/mesh_storage.h"

class RendererCompositor {
public:
	// The light storage of this backend (owned by the compositor).
	virtual RendererLightStorage *get_light_storage() = 0;
	// The mesh storage of this backend (owned by the compositor).
	virtual RendererMeshStorage *get_mesh_storage() = 0;
	// The material and texture storage of this backend (owned by the compositor).
	virtual RendererMaterialStorage *get_material_storage() = 0;
	// The 3D scene renderer of this backend (owned by the compositor).
	virtual RendererSceneRender *get_scene_render() = 0;
	// Called by the server once per draw(), before any viewport is rendered.
	virtual void begin_frame() {}
	// Called by the server once per draw(), after every viewport is rendered.
	virtual void end_frame() {}

	virtual ~RendererCompositor() {}
};
