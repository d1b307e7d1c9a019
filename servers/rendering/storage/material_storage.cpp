/**************************************************************************/
/*  material_storage.cpp                                                  */
/**************************************************************************/
/* godot-area: shared helpers of the abstract material storage.           */

#include "servers/rendering/storage/material_storage.h"

#include "core/error/error_macros.h"

#include <cmath>

static bool _check_unit(const char *p_name, float p_value) {
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_value) || p_value < 0.0f || p_value > 1.0f, false,
			vformat("Material %s must be a finite number between 0 and 1, got %s; the old parameters are kept.", p_name, rtos(p_value).c_str()));
	return true;
}

bool RendererMaterialStorage::validate_params(const RS::MaterialParams &p_params) {
	ERR_FAIL_COND_V_MSG(!p_params.albedo.is_finite(), false, "Material albedo must be finite; the old parameters are kept.");
	ERR_FAIL_COND_V_MSG(!p_params.emission.is_finite(), false, "Material emission must be finite; the old parameters are kept.");
	if (!_check_unit("roughness", p_params.roughness) || !_check_unit("metallic", p_params.metallic) || !_check_unit("specular", p_params.specular)) {
		return false;
	}
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_params.normal_scale), false, "Material normal_scale must be finite; the old parameters are kept.");
	ERR_FAIL_COND_V_MSG(!std::isfinite(p_params.emission_energy) || p_params.emission_energy < 0.0f, false,
			"Material emission_energy must be finite and not negative; the old parameters are kept.");
	if (!_check_unit("alpha_scissor_threshold", p_params.alpha_scissor_threshold)) {
		return false;
	}
	ERR_FAIL_INDEX_V_MSG((int)p_params.transparency, (int)RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR + 1, false, "Material transparency is not a MaterialTransparency value.");
	ERR_FAIL_INDEX_V_MSG((int)p_params.diffuse_mode, (int)RS::MATERIAL_DIFFUSE_TOON + 1, false, "Material diffuse_mode is not a MaterialDiffuseMode value.");
	ERR_FAIL_INDEX_V_MSG((int)p_params.specular_mode, (int)RS::MATERIAL_SPECULAR_DISABLED + 1, false, "Material specular_mode is not a MaterialSpecularMode value.");
	return true;
}
