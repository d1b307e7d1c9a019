/**************************************************************************/
/*  accuracy_command.h                                                    */
/**************************************************************************/
/* godot-area: `godot-area bench --accuracy`, the area-light accuracy     */
/* suite on the command line (accuracy_suite.h):                          */
/*                                                                        */
/*   godot-area bench --accuracy [--ci] [--shapes] [--resolution N]       */
/*                    [--csv F]                                           */
/*                    [--thumbnails DIR] [--methods 0,1,..] [--filter S]  */
/*                    [--progress]                                        */
/*                                                                        */
/* --shapes: the disk / sphere / tube scenes (AccuracyScenes::           */
/* shape_suite()) instead of the rectangles.                              */
/* Defaults: the full suite at 96 x 96, method {LTC} (0). Prints the      */
/* summary table (markdown) and the mean reference time per image.        */
/* Runs with no engine started: the suite starts its own GodotInstance.   */

#pragma once

#include "core/string/ustring.h"

#include <vector>

// p_args: the arguments after "bench" ("--accuracy" itself is skipped).
// Returns 0 on success, 1 on a failed run, 2 on bad arguments.
int accuracy_command(const std::vector<String> &p_args);
