/**************************************************************************/
/*  reference_texture.h                                                   */
/**************************************************************************/
/* godot-area: material texture sampling of the Embree reference, as the  */
/* GPU's material samplers do it (Vulkan 1.3 section 16: NEAREST and      */
/* LINEAR texel filters with REPEAT; for the *_WITH_MIPMAPS filters the   */
/* level of detail of section 16.6 and a LINEAR blend of the two nearest  */
/* levels of the chain of texture_mipmaps.h).                             */
/*                                                                        */
/* Footprint: the GPU takes du/dx, dv/dy from neighbouring pixels of a    */
/* 2x2 quad. The reference takes them from ray differentials (Igehy 1999, */
/* "Tracing Ray Differentials"): the rays through the pixel centres one   */
/* pixel right and one pixel down meet the plane of the hit triangle;     */
/* their barycentric texture coordinates minus the hit's are the          */
/* per-pixel steps (Reference rays of a diffuse bounce have no            */
/* differential and read level 0).                                        */

#pragma once

#include "core/io/image.h"
#include "core/math/color.h"
#include "core/math/vector2.h"
#include "core/math/vector3.h"

#include <vector>

// Vulkan NEAREST with REPEAT: the texel holding p_uv * size. Raw texels (no colour conversion).
Color reference_sample_texture_nearest(const Image &p_image, const Vector2 &p_uv);
// Bilinear, repeat-wrapped sample of a float RGBA image at uv (Vulkan's LINEAR filter, texel centres
// at (i + 0.5) / size), as the GPU's material sampler. Returns raw texels (no colour conversion).
Color reference_sample_texture_bilinear(const Image &p_image, const Vector2 &p_uv);

// A sample at level of detail p_lod (Vulkan's lambda, texture_mipmap_lod): levels 0 (p_base) and
// p_levels (1..n) blended linearly between the two nearest, each read NEAREST or LINEAR. A lod at or
// below 0 (magnification, -inf included) reads level 0; p_levels nullptr or empty reads level 0.
Color reference_sample_texture_lod(const Image &p_base, const std::vector<Image> *p_levels, const Vector2 &p_uv, float p_lod, bool p_nearest);

// The texture coordinate of the point where the ray (p_origin, p_dir) meets the plane of the triangle
// p0 p1 p2 (with coordinates p_uv0..2), from that point's barycentric coordinates (outside the
// triangle too). False when the ray is parallel to the plane.
bool reference_ray_plane_uv(const Vector3 &p_origin, const Vector3 &p_dir, const Vector3 p_positions[3], const Vector2 p_uvs[3], Vector2 &r_uv);
