/**************************************************************************/
/*  ltc_fit_command.h                                                     */
/**************************************************************************/
/* godot-area: the `godot-area ltc-fit` command line tool, which fits the */
/* LTC lookup tables and writes servers/rendering/renderer_rd/            */
/* ltc_lut_data.inc (thesis section 5.4.1).                               */
/*                                                                        */
/*   godot-area ltc-fit [--size N] [--brdf engine|smith|both] [-o PATH]   */
/*                      [--cells r0:r1,t0:t1] [--threads N]               */
/*                                                                        */
/* Defaults: --size 64, --brdf both, -o servers/rendering/renderer_rd/    */
/* ltc_lut_data.inc (relative: run from the source root), --threads 0    */
/* (= hardware concurrency). A variant that is not fitted keeps its built-in table.   */
/* --cells fits only roughness indices r0..r1 and view-angle indices      */
/* t0..t1 (inclusive), starting each chain from the built-in table, and   */
/* prints them with their difference to the built-in table; it writes a   */
/* file only when -o is given explicitly.                                 */
/*                                                                        */
/*   godot-area ltc-fit --polynomial [-o PATH] [--glsl PATH]              */
/*                                                                        */
/* fits degree-5 polynomials to the built-in engine table (thesis 5.4.3,  */
/* modules/ltc_fit/ltc_polynomial.h) and writes servers/rendering/        */
/* renderer_rd/ltc_poly_data.inc (-o) and servers/rendering/renderer_rd/shaders/ltc_poly_coeffs_inc.glsl */
/* (--glsl).                                                              */

#pragma once

#include "core/string/ustring.h"

#include <vector>

// p_args: the arguments after "ltc-fit" (a leading "ltc-fit" is skipped too).
// Returns 0 on success, 1 on a failed fit or write, 2 on bad arguments.
int ltc_fit_command(const std::vector<String> &p_args);
