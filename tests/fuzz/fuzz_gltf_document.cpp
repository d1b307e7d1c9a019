/**************************************************************************/
/*  fuzz_gltf_document.cpp                                                */
/**************************************************************************/
/* libFuzzer harness (scons fuzz=yes): the glTF/GLB importer. An input    */
/* starting with "glTF" is a GLB container, anything else glTF JSON. A    */
/* document that parses is also turned into a node tree. External URIs    */
/* resolve under an empty folder. Run:                                    */
/*   bin/fuzz_gltf_document tests/fuzz/corpus/gltf                        */
/*       -dict=tests/fuzz/gltf.dict -max_total_time=60                    */

#include "core/error/error_macros.h"
#include "modules/gltf/gltf_document.h"
#include "modules/gltf/register_types.h"
#include "scene/main/node.h"
#include "scene/register_scene_types.h"
#include "servers/rendering/rendering_server_default.h"

#include <cstdint>
#include <cstring>

static RenderingServer *fuzz_server = nullptr;

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
	set_error_print_silenced(true);
	fuzz_server = RenderingServerDefault::create_dummy();
	register_scene_types();
	initialize_gltf_module();
	return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *p_data, size_t p_size) {
	GLTFDocument doc;
	String error;
	bool ok = false;
	if (p_size >= 4 && memcmp(p_data, "glTF", 4) == 0) {
		ok = doc.parse_glb(p_data, p_size, "/nonexistent/fuzz", &error);
	} else {
		ok = doc.parse_string(String(reinterpret_cast<const char *>(p_data), p_size), "/nonexistent/fuzz", &error);
	}
	if (ok) {
		Node *root = gltf_generate_scene(doc, "Fuzz", &error);
		delete root;
	}
	return 0;
}
