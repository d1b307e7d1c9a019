/**************************************************************************/
/*  texture_mipmaps.h                                                     */
/**************************************************************************/
/* godot-area: the mip chain of a material texture (Williams 1983,        */
/* "Pyramidal Parametrics": each level halves the previous one, Vulkan's  */
/* sizes max(1, size >> level)), made once per texture and used by the    */
/* storages (the GPU uploads it, the Embree reference samples it), and    */
/* the level-of-detail selection of Vulkan 1.3 section 16.6 ("Scale       */
/* Factor Operation, Level-of-Detail Operation and Image Level(s)         */
/* Selection") that the reference applies to its ray differentials.       */
/*                                                                        */
/* Filter: an area-weighted box (each destination texel averages the      */
/* source texels its footprint covers, fractional weights on odd sizes),  */
/* so every level keeps the mean of the base level. sRGB-encoded colour   */
/* textures (albedo) are averaged in linear space and encoded back, as    */
/* the shader decodes what it samples: a black and white checker's mip    */
/* is linear 0.5 (sRGB 0.735), not sRGB 0.5 (linear 0.214).               */

#pragma once

#include "core/io/image.h"
#include "core/math/vector2.h"

#include <vector>

// Number of levels of a full chain (1 for 1x1): floor(log2(max(w, h))) + 1.
int texture_mipmap_level_count(int p_width, int p_height);

// Levels 1 .. count - 1 of p_base's chain (level 0 is p_base itself) into r_levels.
// p_srgb: rgb are sRGB-encoded and averaged in linear space (alpha is linear).
void texture_mipmaps_generate(const Image &p_base, bool p_srgb, std::vector<Image> &r_levels);

// Vulkan's lambda for a pixel whose texture coordinates change by p_duv_dx and p_duv_dy
// per pixel step: log2(max(|du/dx, dv/dx| * size, |du/dy, dv/dy| * size)). -inf for no change.
float texture_mipmap_lod(const Vector2 &p_duv_dx, const Vector2 &p_duv_dy, int p_width, int p_height);
