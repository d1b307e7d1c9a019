/**************************************************************************/
/*  rendering_server_globals.cpp                                          */
/**************************************************************************/

#include "servers/rendering/rendering_server_globals.h"

RendererLightStorage *RenderingServerGlobals::light_storage = nullptr;
RendererMeshStorage *RenderingServerGlobals::mesh_storage = nullptr;
RendererMaterialStorage *RenderingServerGlobals::material_storage = nullptr;
RendererEnvironmentStorage *RenderingServerGlobals::environment_storage = nullptr;
RendererSceneRender *RenderingServerGlobals::scene_render = nullptr;
RendererSceneCull *RenderingServerGlobals::scene = nullptr;
RendererCompositor *RenderingServerGlobals::rasterizer = nullptr;
