/**************************************************************************/
/*  area_light_texture.h                                                  */
/**************************************************************************/
/* godot-area: the exact texture of a textured area light in the CPU      */
/* reference renderer (AreaLight3D.area_texture). The emitted radiance at */
/* a point of the rectangle is L_e times the texture's colour there:      */
/* texels decoded from sRGB to linear and premultiplied by alpha, then    */
/* filtered bilinearly (mip 0, clamp to edge), as the GPU's level 0.      */
/* The image reads upright from the lit side: for the point (x, y) metres */
/* from the centre along the light's local +X and +Y,                     */
/*   uv = (0.5 - x / size_x, 0.5 - y / size_y)                            */
/* (shaders/area_light_texture_inc.glsl uses the same mapping).           */

#pragma once

#include "core/io/image.h"
#include "core/math/color.h"
#include "core/math/vector3.h"

#include <algorithm>
#include <cmath>

namespace ReferenceBRDF {

// Linear premultiplied colour of texel (p_x, p_y), coordinates clamped to the image.
inline Vector3 area_light_texel(const Image &p_image, int p_x, int p_y) {
	const int x = std::clamp(p_x, 0, p_image.get_width() - 1);
	const int y = std::clamp(p_y, 0, p_image.get_height() - 1);
	const float *t = p_image.ptr() + (size_t(y) * p_image.get_width() + x) * 4;
	const Color c = Color(t[0], t[1], t[2], t[3]).srgb_to_linear();
	const float a = std::clamp(t[3], 0.0f, 1.0f);
	return Vector3(std::max(c.r, 0.0f) * a, std::max(c.g, 0.0f) * a, std::max(c.b, 0.0f) * a);
}

// The texture's colour at p_uv in [0, 1]^2: bilinear between texel centres, clamped at the edges.
inline Vector3 area_light_texture_bilinear(const Image &p_image, float p_u, float p_v) {
	if (p_image.is_empty()) {
		return Vector3(1, 1, 1);
	}
	const float fx = std::clamp(p_u, 0.0f, 1.0f) * float(p_image.get_width()) - 0.5f;
	const float fy = std::clamp(p_v, 0.0f, 1.0f) * float(p_image.get_height()) - 0.5f;
	const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
	const float ax = fx - float(x0), ay = fy - float(y0);
	const Vector3 top = area_light_texel(p_image, x0, y0) * (1.0f - ax) + area_light_texel(p_image, x0 + 1, y0) * ax;
	const Vector3 bottom = area_light_texel(p_image, x0, y0 + 1) * (1.0f - ax) + area_light_texel(p_image, x0 + 1, y0 + 1) * ax;
	return top * (1.0f - ay) + bottom * ay;
}

// The texture factor at a point of the light, given its coordinates p_x, p_y (metres from the centre along
// the unit axes) and the light's size; (1, 1, 1) without a texture.
inline Vector3 area_light_texture_at(const Image *p_image, float p_x, float p_y, float p_size_x, float p_size_y) {
	if (!p_image || p_image->is_empty() || !(p_size_x > 0.0f) || !(p_size_y > 0.0f)) {
		return Vector3(1, 1, 1);
	}
	return area_light_texture_bilinear(*p_image, 0.5f - p_x / p_size_x, 0.5f - p_y / p_size_y);
}

} // namespace ReferenceBRDF
