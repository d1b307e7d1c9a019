/**************************************************************************/
/*  methods_sweep_command.h                                               */
/**************************************************************************/
/* godot-area: `godot-area bench --sweep methods`, the shading-method     */
/* sweep on the command line (methods_sweep.h):                           */
/*                                                                        */
/*   godot-area bench --sweep methods [--csv F] [--maps DIR]              */
/*        [--resolution WxH] [--lights 1,4,16,..] [--frames N]            */
/*        [--warmup N] [--error-resolution N] [--configs LTC,MRP,..]      */
/*        [--no-errors] [--no-timing] [--frame-cap-ms N] [--progress]     */
/*        [--no-charts] [--shapes]                                        */
/*   godot-area bench --sweep methods --spirv-sources DIR                 */
/*        (writes the per-method fragment sources and exits)              */
/*                                                                        */
/* Defaults: CSV doc/results/methods_sweep.csv, 256x144, lights           */
/* 1,4,16,64,256, 7 frames after 2 warm-up frames, errors at 64x64 on the */
/* CI subset + the failure scenes. After the CSV, the command draws the   */
/* charts into the CSV's directory by running                            */
/*   /usr/bin/python3 misc/scripts/plot_methods.py CSV --out DIR --maps M */
/* (methods_pareto.png, methods_lights.png, methods_failure_*.png; the    */
/* failure strips go to a temporary M unless --maps is given). Without    */
/* the interpreter (GODOT_AREA_PYTHON overrides the path) or matplotlib   */
/* it fails before the sweep with a message naming the problem            */
/* (bench_charts.h runs the script);                                      */
/* --no-charts skips the charts.                                          */
/* --shapes: the shape axis only (methods_sweep.h: LTC, MRP, MC8 x       */
/* rectangle, disk, sphere, tube; --configs picks among those three);     */
/* default CSV doc/results/methods_shapes.csv, chart                      */
/* methods_shapes_pareto.png beside it; no failure strips.                */
/* Runs with no engine started: the sweep starts its own GodotInstance.   */

#pragma once

#include "core/string/ustring.h"

#include <vector>

// p_args: the arguments after "bench" ("--sweep" and "methods" are skipped).
// Returns 0 on success, 1 on a failed run, 2 on bad arguments.
int methods_sweep_command(const std::vector<String> &p_args);
