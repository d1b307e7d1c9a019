/**************************************************************************/
/*  rendering_server_globals.h                                            */
/**************************************************************************/
/* godot-area: pointers to the live backend parts (Godot's                */
/* RenderingServerGlobals, alias RSG). Set by RenderingServerDefault's    */
/* constructor and cleared by its destructor; nullptr when no server.     */

#pragma once

class RendererLightStorage;
class RendererMeshStorage;
class RendererMaterialStorage;
class RendererEnvironmentStorage;
class RendererSceneRender;
class RendererSceneCull;
class RendererCompositor;

class RenderingServerGlobals {
public:
	static RendererLightStorage *light_storage;
	static RendererMeshStorage *mesh_storage;
	static RendererMaterialStorage *material_storage;
	static RendererEnvironmentStorage *environment_storage;
	static RendererSceneRender *scene_render;
	static RendererSceneCull *scene;
	static RendererCompositor *rasterizer;
};

#define RSG RenderingServerGlobals
