/**************************************************************************/
/*  isr_sweep_command.h                                                   */
/**************************************************************************/
/* godot-area: `godot-area bench --sweep isr`, the image-space radiosity  */
/* evaluation (isr_sweep.h) on the command line:                          */
/*                                                                        */
/*   godot-area bench --sweep isr [--csv F] [--resolution WxH]            */
/*        [--bounce-samples N] [--frames N] [--no-quality] [--no-timing]  */
/*        [--no-charts] [--progress]                                      */
/*                                                                        */
/* Quality: every frame of the closed room's and the open scene's camera  */
/* paths (isr_sweep_scenes.h) at --resolution (default 64x48) against the */
/* one-bounce truth with --bounce-samples rays (default 32): eqs. 19-21,  */
/* mean-error gain, pixels improved -> F (default                         */
/* doc/results/isr_quality.csv). Timing: the room at 160x120, 320x240 and */
/* 640x480 with SSIL off and with 24, 48 and 80 samples, configurations   */
/* interleaved frame by frame in one engine for --frames rounds           */
/* (default 6): median "opaque" and "ss_radiosity" pass ms (GPU           */
/* timestamps; wall clock on lavapipe) and process CPU ms per frame ->    */
/* isr_timing.csv beside F. Charts: misc/scripts/plot_isr.py.             */

#pragma once

#include "core/string/ustring.h"

#include <vector>

// p_args: the arguments after "bench" ("--sweep" and "isr" are skipped).
// Returns 0 on success, 1 on a failed run, 2 on bad arguments.
int isr_sweep_command(const std::vector<String> &p_args);
