/**************************************************************************/
/*  register_module_types.h                                               */
/**************************************************************************/
/* Registers what the modules add to the engine (Godot's                  */
/* modules/register_module_types.h): today the glTF scene loader. Call    */
/* after GodotInstance::start(); both calls may repeat.                   */

#pragma once

void initialize_modules();
void uninitialize_modules();
