/**************************************************************************/
/*  renderer_compositor_reference.h                                       */
/**************************************************************************/
/* godot-area: the CPU reference backend: the dummy (CPU) storages plus   */
/* the Embree ReferenceRenderer, so the same RenderingServer scene can be */
/* rendered as ground truth:                                              */
/*   RenderingServerDefault *rs = new RenderingServerDefault(             */
/*           new RendererCompositorReference(options));                   */

#pragma once

#include "modules/reference/reference_renderer.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"
#include "servers/rendering/renderer_compositor.h"

class RendererCompositorReference : public RendererCompositor {
	// Declared before the renderer: it keeps pointers to them.
	RendererDummy::LightStorage light_storage;
	RendererDummy::MeshStorage mesh_storage;
	RendererDummy::MaterialStorage material_storage;
	ReferenceRenderer scene;

public:
	RendererLightStorage *get_light_storage() override { return &light_storage; }
	RendererMeshStorage *get_mesh_storage() override { return &mesh_storage; }
	RendererMaterialStorage *get_material_storage() override { return &material_storage; }
	RendererSceneRender *get_scene_render() override { return &scene; }
	// The reference renderer itself (options, statistics).
	ReferenceRenderer *get_reference_renderer() { return &scene; }

	explicit RendererCompositorReference(const ReferenceRenderOptions &p_options = ReferenceRenderOptions()) :
			scene(&light_storage, &mesh_storage, &material_storage, p_options) {}
};
