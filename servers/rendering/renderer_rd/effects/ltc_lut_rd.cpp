/**************************************************************************/
/*  ltc_lut_rd.cpp                                                        */
/**************************************************************************/

#include "servers/rendering/renderer_rd/effects/ltc_lut_rd.h"

#include "core/error/error_macros.h"
#include "servers/rendering/rendering_device.h"

#include <cstring>

#include "servers/rendering/renderer_rd/ltc_lut_2lobe_data.inc"
#include "servers/rendering/renderer_rd/ltc_lut_data.inc"

static_assert(LTC_LUT_2LOBE_SIZE == LTC_LUT_SIZE, "The two-lobe table shares the LUT texture's size.");

uint32_t LTCLutRD::get_size() {
	return uint32_t(LTC_LUT_SIZE);
}

std::vector<std::vector<uint8_t>> LTCLutRD::build_layers(Table p_table) {
	const float *src = p_table == TABLE_SMITH_GGX ? LTC_LUT_SMITH_GGX : LTC_LUT_ENGINE_GGX;
	const size_t cells = size_t(LTC_LUT_SIZE) * LTC_LUT_SIZE;
	std::vector<float> l0(cells * 4), l1(cells * 4);
	// The .inc stores cell (ti, ri) at float (ti * N + ri) * 8, i.e. row = view angle, column =
	// roughness: exactly the texel order of an N x N texture with x = roughness, y = view angle.
	for (size_t i = 0; i < cells; i++) {
		const float *c = src + i * 8;
		for (int k = 0; k < 4; k++) {
			l0[i * 4 + k] = c[k];
			l1[i * 4 + k] = c[4 + k];
		}
	}
	std::vector<std::vector<uint8_t>> layers(LAYERS);
	layers[0].resize(l0.size() * sizeof(float));
	layers[1].resize(l1.size() * sizeof(float));
	memcpy(layers[0].data(), l0.data(), layers[0].size());
	memcpy(layers[1].data(), l1.data(), layers[1].size());
	// Layers 2-5: the two-lobe table's four texels per cell (16 floats, ltc_lut_2lobe_data.inc).
	for (int l = 0; l < 4; l++) {
		std::vector<float> texels(cells * 4);
		for (size_t i = 0; i < cells; i++) {
			for (int k = 0; k < 4; k++) {
				texels[i * 4 + k] = LTC_LUT_ENGINE_GGX_2LOBE[i * 16 + l * 4 + k];
			}
		}
		layers[2 + l].resize(texels.size() * sizeof(float));
		memcpy(layers[2 + l].data(), texels.data(), layers[2 + l].size());
	}
	return layers;
}

bool LTCLutRD::initialize(Table p_table) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	ERR_FAIL_NULL_V_MSG(rd, false, "LTCLutRD::initialize() needs an initialized RenderingDevice.");
	finalize();
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	tf.width = LTC_LUT_SIZE;
	tf.height = LTC_LUT_SIZE;
	tf.array_layers = LAYERS;
	tf.texture_type = RD::TEXTURE_TYPE_2D_ARRAY;
	tf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT;
	texture = rd->texture_create(tf, build_layers(p_table));
	ERR_FAIL_COND_V_MSG(!texture.is_valid(), false, "LTCLutRD: cannot create the LTC lookup texture.");
	rd->set_resource_name(texture, "LTC LUT");

	RD::SamplerState ss;
	ss.mag_filter = RD::SAMPLER_FILTER_LINEAR;
	ss.min_filter = RD::SAMPLER_FILTER_LINEAR;
	ss.mip_filter = RD::SAMPLER_FILTER_NEAREST;
	ss.repeat_u = RD::SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE;
	ss.repeat_v = RD::SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE;
	ss.repeat_w = RD::SAMPLER_REPEAT_MODE_CLAMP_TO_EDGE;
	ss.max_lod = 0.0f;
	sampler = rd->sampler_create(ss);
	ERR_FAIL_COND_V_MSG(!sampler.is_valid(), false, "LTCLutRD: cannot create the LTC sampler.");
	return true;
}

void LTCLutRD::finalize() {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (rd && rd->is_initialized()) {
		if (texture.is_valid()) {
			rd->free(texture);
		}
		if (sampler.is_valid()) {
			rd->free(sampler);
		}
	}
	texture = RID();
	sampler = RID();
}

LTCLutRD::~LTCLutRD() {
	finalize();
}
