/**************************************************************************/
/*  register_types.cpp                                                    */
/**************************************************************************/

#include "modules/gltf/register_types.h"

#include "modules/gltf/gltf_document.h"
#include "scene/resources/resource_format_text.h"

static Node *_load_gltf_scene(const String &p_path, String *r_error) {
	GLTFDocument doc;
	String error;
	if (!doc.parse_file(p_path, &error)) {
		*r_error = error;
		return nullptr;
	}
	String name = p_path.substr(p_path.rfind('/') == String::npos ? 0 : p_path.rfind('/') + 1);
	name = name.substr(0, name.rfind('.'));
	Node *root = gltf_generate_scene(doc, name, &error);
	if (!root) {
		*r_error = vformat("'%s': %s", p_path.c_str(), error.c_str());
	}
	return root;
}

void initialize_gltf_module() {
	ResourceFormatText::add_scene_loader("gltf", _load_gltf_scene);
	ResourceFormatText::add_scene_loader("glb", _load_gltf_scene);
}

void uninitialize_gltf_module() {
	ResourceFormatText::remove_scene_loader("gltf");
	ResourceFormatText::remove_scene_loader("glb");
}
