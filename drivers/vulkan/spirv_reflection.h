/**************************************************************************/
/*  spirv_reflection.h                                                    */
/**************************************************************************/
/* Minimal SPIR-V reflection for RenderingDevice: descriptor bindings     */
/* (set, binding, kind, array size), push constant block size and compute */
/* local size, read straight from the module's instructions.              */

#pragma once

#include "core/string/ustring.h"

#include <cstdint>
#include <vector>

struct SPIRVReflection {
	enum BindingKind {
		KIND_SAMPLER,
		KIND_COMBINED_IMAGE_SAMPLER,
		KIND_SAMPLED_IMAGE,
		KIND_STORAGE_IMAGE,
		KIND_UNIFORM_BUFFER,
		KIND_STORAGE_BUFFER,
	};

	struct Binding {
		uint32_t set = 0;
		uint32_t binding = 0;
		BindingKind kind = KIND_UNIFORM_BUFFER;
		uint32_t count = 1; // Array length (1 when not an array).
		bool writable = true; // Storage buffers/images: false when decorated NonWritable.
	};

	std::vector<Binding> bindings;
	uint32_t push_constant_size = 0;
	uint32_t local_size[3] = { 1, 1, 1 };

	// Parses p_words; on failure returns false and sets r_error.
	bool parse(const std::vector<uint32_t> &p_words, String &r_error);
};
