/**************************************************************************/
/*  fuzz_resource_format_text.cpp                                         */
/**************************************************************************/
/* libFuzzer harness (scons fuzz=yes): the .tscn/.tres text loader.       */
/* Each input is loaded as a scene; a scene that loads is saved, and the  */
/* saved text must load again (a file we write is a file we read) and     */
/* save to the same text. Run:                                            */
/*   bin/fuzz_resource_format_text tests/fuzz/corpus/tscn                 */
/*       -dict=tests/fuzz/tscn.dict -max_total_time=60                    */

#include "core/error/error_macros.h"
#include "modules/gltf/register_types.h"
#include "scene/main/node.h"
#include "scene/register_scene_types.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/rendering_server_default.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

static RenderingServer *fuzz_server = nullptr;

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
	set_error_print_silenced(true);
	fuzz_server = RenderingServerDefault::create_dummy();
	register_scene_types();
	initialize_gltf_module();
	return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *p_data, size_t p_size) {
	const String text(reinterpret_cast<const char *>(p_data), p_size);
	String error;
	// A folder that has no files: ext_resource paths resolve to nothing, never to the fuzzer's files.
	Node *root = ResourceFormatText::load_scene_from_string(text, "/nonexistent/fuzz/scene.tscn", &error);
	if (!root) {
		return 0;
	}
	const String saved = ResourceFormatText::save_scene_to_string(root);
	delete root;
	Node *again = ResourceFormatText::load_scene_from_string(saved, "/nonexistent/fuzz/scene.tscn", &error);
	if (!again) {
		fprintf(stderr, "a saved scene does not load again: %s\n--- saved text ---\n%s\n", error.c_str(), saved.c_str());
		abort();
	}
	const String saved_again = ResourceFormatText::save_scene_to_string(again);
	delete again;
	if (saved_again != saved) {
		fprintf(stderr, "save(load(save(x))) != save(x)\n--- first ---\n%s\n--- second ---\n%s\n", saved.c_str(), saved_again.c_str());
		abort();
	}
	return 0;
}
