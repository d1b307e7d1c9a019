/**************************************************************************/
/*  dolly_sweep_command.h                                                 */
/**************************************************************************/
/* godot-area: `godot-area bench --sweep dolly`, the adaptive-shadow      */
/* dolly benchmark on the command line (dolly_sweep.h):                   */
/*                                                                        */
/*   godot-area bench --sweep dolly [--csv F] [--positions N]             */
/*        [--far M] [--near M] [--resolution WxH] [--supersample K]       */
/*        [--modes adaptive,heuristic,fixed25,fixed81] [--atlas N]        */
/*        [--subdivision N] [--frames N] [--converge-max N]               */
/*        [--converge-stable N] [--blur B] [--reference-error E]          */
/*        [--no-errors] [--no-charts] [--progress]                        */
/*                                                                        */
/* Defaults: 8 positions from 10 m to 0.5 m, reference 96 x 54 and the   */
/* engine at 3x (288 x 162), atlas 2048 in 8 x 8 tiles, 7 timed frames;   */
/* CSV to doc/results/dolly.csv, then the chart (dolly.png next to the    */
/* CSV) with /usr/bin/python3 misc/scripts/plot_dolly.py, and the three   */
/* target ratios of issue 7 printed. Starts its own GodotInstance.        */

#pragma once

#include "core/string/ustring.h"

#include <vector>

// p_args: the arguments after "bench" ("--sweep" and "dolly" are skipped).
// Returns 0 on success, 1 on a failed run, 2 on bad arguments.
int dolly_sweep_command(const std::vector<String> &p_args);
