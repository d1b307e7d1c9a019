/**************************************************************************/
/*  rasterizer_dummy.h                                                    */
/**************************************************************************/
/* godot-area: the CPU-only backend (Godot's RasterizerDummy): dummy      */
/* storages that keep all data on the CPU and a renderer that draws       */
/* nothing. Lets the server and scene tests run without a GPU.            */

#pragma once

#include "servers/rendering/dummy/rasterizer_scene_dummy.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"
#include "servers/rendering/renderer_compositor.h"

class RasterizerDummy : public RendererCompositor {
	RendererDummy::LightStorage light_storage;
	RendererDummy::MeshStorage mesh_storage;
	RendererDummy::MaterialStorage material_storage;
	RasterizerSceneDummy scene;

public:
	RendererLightStorage *get_light_storage() override { return &light_storage; }
	RendererMeshStorage *get_mesh_storage() override { return &mesh_storage; }
	RendererMaterialStorage *get_material_storage() override { return &material_storage; }
	RendererSceneRender *get_scene_render() override { return &scene; }
	// The dummy scene renderer itself (tests read the last RenderSceneData).
	RasterizerSceneDummy *get_scene_dummy() { return &scene; }
};
