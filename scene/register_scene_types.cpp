/**************************************************************************/
/*  register_scene_types.cpp                                              */
/**************************************************************************/

#include "scene/register_scene_types.h"

#include "core/io/image_loader.h"
#include "core/io/missing_resource.h"
#include "core/object/class_db.h"
#include "scene/3d/camera_3d.h"
#include "scene/3d/geometry_instance_3d.h"
#include "scene/3d/light_3d.h"
#include "scene/3d/mesh_instance_3d.h"
#include "scene/3d/node_3d.h"
#include "scene/3d/visual_instance_3d.h"
#include "scene/3d/world_environment.h"
#include "scene/main/missing_node.h"
#include "scene/main/node.h"
#include "scene/resources/environment.h"
#include "scene/resources/material.h"
#include "scene/resources/mesh.h"
#include "scene/resources/primitive_meshes.h"
#include "scene/resources/resource_format_text.h"
#include "scene/resources/sky.h"
#include "scene/resources/sky_material.h"
#include "scene/resources/texture.h"
#include "scene/resources/world_3d.h"

void register_scene_types() {
	// Nodes.
	GDREGISTER_CLASS(Node);
	GDREGISTER_CLASS(Node3D);
	GDREGISTER_CLASS(MissingNode);
	GDREGISTER_ABSTRACT_CLASS(VisualInstance3D);
	GDREGISTER_ABSTRACT_CLASS(GeometryInstance3D);
	GDREGISTER_CLASS(MeshInstance3D);
	GDREGISTER_CLASS(Camera3D);
	GDREGISTER_ABSTRACT_CLASS(Light3D);
	GDREGISTER_CLASS(DirectionalLight3D);
	GDREGISTER_CLASS(OmniLight3D);
	GDREGISTER_CLASS(SpotLight3D);
	GDREGISTER_CLASS(AreaLight3D);
	GDREGISTER_CLASS(WorldEnvironment);

	// Resources.
	GDREGISTER_ABSTRACT_CLASS(Texture2D);
	GDREGISTER_CLASS(ImageTexture);
	GDREGISTER_ABSTRACT_CLASS(Material);
	GDREGISTER_ABSTRACT_CLASS(BaseMaterial3D);
	GDREGISTER_CLASS(StandardMaterial3D);
	GDREGISTER_CLASS(ORMMaterial3D);
	GDREGISTER_ABSTRACT_CLASS(Mesh);
	GDREGISTER_CLASS(ArrayMesh);
	GDREGISTER_ABSTRACT_CLASS(PrimitiveMesh);
	GDREGISTER_CLASS(PlaneMesh);
	GDREGISTER_CLASS(QuadMesh);
	GDREGISTER_CLASS(BoxMesh);
	GDREGISTER_CLASS(SphereMesh);
	GDREGISTER_CLASS(CylinderMesh);
	GDREGISTER_CLASS(CapsuleMesh);
	GDREGISTER_CLASS(TorusMesh);
	GDREGISTER_CLASS(PrismMesh);
	GDREGISTER_CLASS(ProceduralSkyMaterial);
	GDREGISTER_CLASS(PhysicalSkyMaterial);
	GDREGISTER_CLASS(Sky);
	GDREGISTER_CLASS(Environment);
	GDREGISTER_CLASS(World3D);
	GDREGISTER_CLASS(MissingResource);

	// Image files referenced by scenes (ext_resource type="Texture2D") load as ImageTexture.
	for (const String &ext : ImageLoader::get_recognized_extensions()) {
		ResourceFormatText::add_resource_loader(ext, [](const String &p_path, const String &p_type, String *r_error) -> Ref<Resource> {
			Image image;
			if (!ImageLoader::load_image(p_path, image, r_error)) {
				return Ref<Resource>();
			}
			return ImageTexture::create_from_image(image);
		});
	}
}

void unregister_scene_types() {
}
