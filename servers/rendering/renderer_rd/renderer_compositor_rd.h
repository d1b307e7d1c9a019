/**************************************************************************/
/*  renderer_compositor_rd.h                                              */
/**************************************************************************/
/* godot-area: the Vulkan backend bundle (Godot's RendererCompositorRD):  */
/* RD light/mesh/material storages and the Forward+ scene renderer.       */
/* Usage: create a RenderingDevice and initialize() it first, then        */
/*   RendererCompositorRD *c = new RendererCompositorRD;                  */
/*   if (!c->initialize()) { ... }   // compiles shaders                  */
/*   new RenderingServerDefault(c); // takes ownership                   */
/* Destroy it (through the server) before finalizing the device.          */

#pragma once

#include "servers/rendering/renderer_compositor.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

class RendererCompositorRD : public RendererCompositor {
	RendererRD::LightStorage light_storage;
	RendererRD::MeshStorage mesh_storage;
	RendererRD::MaterialStorage material_storage;
	RenderForwardClustered scene_render;

public:
	// Sets up every GPU part (needs an initialized RenderingDevice). Returns false on failure.
	bool initialize(uint32_t p_max_lights_per_type = 512);
	// Frees every GPU object; called by the destructor too.
	void finalize();

	RendererLightStorage *get_light_storage() override { return &light_storage; }
	RendererMeshStorage *get_mesh_storage() override { return &mesh_storage; }
	RendererMaterialStorage *get_material_storage() override { return &material_storage; }
	RendererSceneRender *get_scene_render() override { return &scene_render; }

	RendererRD::LightStorage *get_light_storage_rd() { return &light_storage; }
	RendererRD::MeshStorage *get_mesh_storage_rd() { return &mesh_storage; }
	RendererRD::MaterialStorage *get_material_storage_rd() { return &material_storage; }
	RenderForwardClustered *get_render_forward_clustered() { return &scene_render; }

	RendererCompositorRD();
	~RendererCompositorRD();
};
