/**************************************************************************/
/*  register_module_types.cpp                                             */
/**************************************************************************/

#include "modules/register_module_types.h"

#include "modules/gltf/register_types.h"

void initialize_modules() {
	initialize_gltf_module();
}

void uninitialize_modules() {
	uninitialize_gltf_module();
}
