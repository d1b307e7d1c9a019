/**************************************************************************/
/*  ltc_lut_rd.h                                                          */
/**************************************************************************/
/* godot-area: the LTC lookup table (thesis section 5.4, Heitz et al.     */
/* 2016) on the GPU. Uploads LTC_LUT_ENGINE_GGX from ltc_lut_data.inc as  */
/* a 64 x 64 RGBA32F 2D array texture with six layers:                    */
/*   layer 0 = (a, b, c, d), layer 1 = (e, fn, fg, 0)                     */
/* and the two-lobe table (LTC_2LOBE, ltc_lut_2lobe_data.inc) in layers   */
/* 2-5: (a1, b1, c1, d1), (e1, fn, fg, w1), (a2, b2, c2, d2),             */
/* (e2, w2, 0, 0); one texture, so the two-lobe method binds nothing      */
/* more (its fetch is compiled only into shader versions that use it).   */
/* (x = roughness index, y = view-angle index), plus a linear,            */
/* clamp-to-edge sampler without mipmaps. The shader side (sampling      */
/* formula, matrix inversion) is shaders/area_light_ltc_inc.glsl.         */

#pragma once

#include "core/templates/rid.h"

#include <cstdint>
#include <vector>

class LTCLutRD {
public:
	/* Definition */

	// Which fitted table to upload (both in ltc_lut_data.inc).
	enum Table {
		TABLE_ENGINE_GGX, // The engine's lobe (D_GGX * V_SmithGGXCorrelatedFast); the default.
		TABLE_SMITH_GGX, // GGX with the exact height-correlated Smith G2.
	};

private:
	/* Private Members */

	RID texture; // RGBA32F, 2D array, LAYERS layers.
	RID sampler;

public:
	/* Public Methods */

	static constexpr uint32_t LAYERS = 6;

	// The LUT size (cells per side; must match LTC_LUT_SIZE in shaders/area_light_ltc_inc.glsl).
	static uint32_t get_size();
	// The LAYERS layers as RGBA32F texel bytes (layer 0: a, b, c, d and layer 1: e, fn, fg, 0 of p_table;
	// layers 2-5: the two-lobe table, whatever p_table).
	static std::vector<std::vector<uint8_t>> build_layers(Table p_table);

	// Creates the texture and sampler (needs an initialized RenderingDevice).
	bool initialize(Table p_table = TABLE_ENGINE_GGX);
	void finalize();
	bool is_initialized() const { return texture.is_valid(); }
	RID get_texture() const { return texture; }
	RID get_sampler() const { return sampler; }

	LTCLutRD() {}
	~LTCLutRD();
};
