/**************************************************************************/
/*  register_scene_types.h                                                */
/**************************************************************************/
/* godot-area: registers every scene class (nodes and resources) with     */
/* ClassDB, so scene files can instantiate them by name. Idempotent.      */

#pragma once

void register_scene_types();
// Nothing to undo per class; ClassDB::cleanup() at exit drops everything.
void unregister_scene_types();
