/**************************************************************************/
/*  shadows_sweep_command.h                                               */
/**************************************************************************/
/* godot-area: `godot-area bench --sweep shadows`, the area soft-shadow   */
/* sweep on the command line (shadows_sweep.h):                           */
/*                                                                        */
/*   godot-area bench --sweep shadows [--csv F] [--resolution N]          */
/*        [--atlas 2048,8192] [--maps 4,9,25,49,81] [--blur 0,1,2]        */
/*        [--frames N] [--reference-error E] [--no-errors] [--no-timing]  */
/*        [--progress]                                                    */
/*                                                                        */
/* --maps takes squares of 2..9 (grid^2). Defaults: 96 x 96, atlases 2048 */
/* and 8192, 4..81 maps, shadow_blur 0, 1, 2, 9 timed frames, reference  */
/* to 1 % relative error; CSV to doc/results/shadows_sweep.csv. Charts:   */
/* /usr/bin/python3 misc/scripts/plot_shadows.py CSV. Starts its own      */
/* GodotInstance (no engine may be running).                              */

#pragma once

#include "core/string/ustring.h"

#include <vector>

// p_args: the arguments after "bench" ("--sweep" and "shadows" are skipped).
// Returns 0 on success, 1 on a failed run, 2 on bad arguments.
int shadows_sweep_command(const std::vector<String> &p_args);
