/**************************************************************************/
/*  register_types.h                                                      */
/**************************************************************************/
/* The glTF module: lets .tscn files instance .gltf/.glb scenes through   */
/* `instance=ExtResource("…")`.                                           */

#pragma once

void initialize_gltf_module();
void uninitialize_gltf_module();
