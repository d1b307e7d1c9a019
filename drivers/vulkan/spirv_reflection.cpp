/**************************************************************************/
/*  spirv_reflection.cpp                                                  */
/**************************************************************************/

#include "drivers/vulkan/spirv_reflection.h"

#include <unordered_map>

namespace {

// Opcodes, decorations and storage classes used below (SPIR-V 1.x specification).
enum : uint32_t {
	OP_EXECUTION_MODE = 16,
	OP_TYPE_INT = 21,
	OP_TYPE_FLOAT = 22,
	OP_TYPE_VECTOR = 23,
	OP_TYPE_MATRIX = 24,
	OP_TYPE_IMAGE = 25,
	OP_TYPE_SAMPLER = 26,
	OP_TYPE_SAMPLED_IMAGE = 27,
	OP_TYPE_ARRAY = 28,
	OP_TYPE_RUNTIME_ARRAY = 29,
	OP_TYPE_STRUCT = 30,
	OP_TYPE_POINTER = 32,
	OP_CONSTANT = 43,
	OP_VARIABLE = 59,
	OP_DECORATE = 71,
	OP_MEMBER_DECORATE = 72,

	DEC_BLOCK = 2,
	DEC_BUFFER_BLOCK = 3,
	DEC_ARRAY_STRIDE = 6,
	DEC_MATRIX_STRIDE = 7,
	DEC_NON_WRITABLE = 24,
	DEC_BINDING = 33,
	DEC_DESCRIPTOR_SET = 34,
	DEC_OFFSET = 35,

	SC_UNIFORM_CONSTANT = 0,
	SC_UNIFORM = 2,
	SC_PUSH_CONSTANT = 9,
	SC_STORAGE_BUFFER = 12,

	EXEC_MODE_LOCAL_SIZE = 17,
	IMAGE_DIM_BUFFER = 5,
	IMAGE_DIM_SUBPASS = 6,
};

struct TypeInfo {
	uint32_t op = 0;
	std::vector<uint32_t> operands; // Words after the result id.
};

struct DecorationInfo {
	bool block = false;
	bool buffer_block = false;
	bool non_writable = false;
	bool has_set = false;
	bool has_binding = false;
	uint32_t set = 0;
	uint32_t binding = 0;
	uint32_t array_stride = 0;
};

struct Parser {
	std::unordered_map<uint32_t, TypeInfo> types;
	std::unordered_map<uint32_t, uint32_t> constants; // id -> first value word.
	std::unordered_map<uint32_t, DecorationInfo> decorations;
	std::unordered_map<uint64_t, uint32_t> member_offsets; // (struct id << 32 | member) -> offset.
	std::unordered_map<uint64_t, uint32_t> member_matrix_strides;

	static uint64_t key(uint32_t p_id, uint32_t p_member) { return (uint64_t(p_id) << 32) | p_member; }

	uint32_t type_size(uint32_t p_type, uint32_t p_matrix_stride, int p_depth) const {
		if (p_depth > 16) {
			return 0;
		}
		auto it = types.find(p_type);
		if (it == types.end()) {
			return 0;
		}
		const TypeInfo &t = it->second;
		switch (t.op) {
			case OP_TYPE_INT:
			case OP_TYPE_FLOAT:
				return t.operands.size() > 0 ? t.operands[0] / 8 : 4;
			case OP_TYPE_VECTOR:
				return t.operands.size() > 1 ? type_size(t.operands[0], 0, p_depth + 1) * t.operands[1] : 0;
			case OP_TYPE_MATRIX: {
				if (t.operands.size() < 2) {
					return 0;
				}
				uint32_t column = p_matrix_stride ? p_matrix_stride : type_size(t.operands[0], 0, p_depth + 1);
				return column * t.operands[1];
			}
			case OP_TYPE_ARRAY: {
				if (t.operands.size() < 2) {
					return 0;
				}
				auto c = constants.find(t.operands[1]);
				uint32_t len = c == constants.end() ? 1 : c->second;
				auto d = decorations.find(p_type);
				uint32_t stride = (d != decorations.end() && d->second.array_stride) ? d->second.array_stride : type_size(t.operands[0], p_matrix_stride, p_depth + 1);
				return stride * len;
			}
			case OP_TYPE_STRUCT: {
				uint32_t size = 0;
				for (uint32_t m = 0; m < t.operands.size(); m++) {
					auto o = member_offsets.find(key(p_type, m));
					uint32_t offset = o == member_offsets.end() ? size : o->second;
					auto ms = member_matrix_strides.find(key(p_type, m));
					uint32_t member_size = type_size(t.operands[m], ms == member_matrix_strides.end() ? 0 : ms->second, p_depth + 1);
					if (offset + member_size > size) {
						size = offset + member_size;
					}
				}
				return size;
			}
			default:
				return 0;
		}
	}
};

} // namespace

bool SPIRVReflection::parse(const std::vector<uint32_t> &p_words, String &r_error) {
	bindings.clear();
	push_constant_size = 0;
	local_size[0] = local_size[1] = local_size[2] = 1;

	if (p_words.size() < 5 || p_words[0] != 0x07230203) {
		r_error = "Not a SPIR-V module (bad magic number or too short).";
		return false;
	}
	Parser p;
	struct Variable {
		uint32_t id;
		uint32_t pointer_type;
		uint32_t storage_class;
	};
	std::vector<Variable> variables;

	size_t pos = 5;
	while (pos < p_words.size()) {
		uint32_t word = p_words[pos];
		uint32_t count = word >> 16;
		uint32_t op = word & 0xFFFF;
		if (count == 0 || pos + count > p_words.size()) {
			r_error = vformat("Malformed SPIR-V instruction at word %zu.", pos);
			return false;
		}
		const uint32_t *w = &p_words[pos];
		switch (op) {
			case OP_EXECUTION_MODE:
				if (count >= 6 && w[2] == EXEC_MODE_LOCAL_SIZE) {
					local_size[0] = w[3];
					local_size[1] = w[4];
					local_size[2] = w[5];
				}
				break;
			case OP_TYPE_INT:
			case OP_TYPE_FLOAT:
			case OP_TYPE_VECTOR:
			case OP_TYPE_MATRIX:
			case OP_TYPE_IMAGE:
			case OP_TYPE_SAMPLER:
			case OP_TYPE_SAMPLED_IMAGE:
			case OP_TYPE_ARRAY:
			case OP_TYPE_RUNTIME_ARRAY:
			case OP_TYPE_STRUCT:
			case OP_TYPE_POINTER: {
				if (count < 2) {
					break;
				}
				TypeInfo t;
				t.op = op;
				t.operands.assign(w + 2, w + count);
				p.types[w[1]] = t;
			} break;
			case OP_CONSTANT:
				if (count >= 4) {
					p.constants[w[2]] = w[3];
				}
				break;
			case OP_VARIABLE:
				if (count >= 4) {
					variables.push_back({ w[2], w[1], w[3] });
				}
				break;
			case OP_DECORATE:
				if (count >= 3) {
					DecorationInfo &d = p.decorations[w[1]];
					switch (w[2]) {
						case DEC_BLOCK:
							d.block = true;
							break;
						case DEC_BUFFER_BLOCK:
							d.buffer_block = true;
							break;
						case DEC_NON_WRITABLE:
							d.non_writable = true;
							break;
						case DEC_ARRAY_STRIDE:
							d.array_stride = count >= 4 ? w[3] : 0;
							break;
						case DEC_BINDING:
							d.has_binding = count >= 4;
							d.binding = count >= 4 ? w[3] : 0;
							break;
						case DEC_DESCRIPTOR_SET:
							d.has_set = count >= 4;
							d.set = count >= 4 ? w[3] : 0;
							break;
						default:
							break;
					}
				}
				break;
			case OP_MEMBER_DECORATE:
				if (count >= 5 && w[3] == DEC_OFFSET) {
					p.member_offsets[Parser::key(w[1], w[2])] = w[4];
				} else if (count >= 5 && w[3] == DEC_MATRIX_STRIDE) {
					p.member_matrix_strides[Parser::key(w[1], w[2])] = w[4];
				}
				break;
			default:
				break;
		}
		pos += count;
	}

	for (const Variable &v : variables) {
		if (v.storage_class != SC_UNIFORM_CONSTANT && v.storage_class != SC_UNIFORM && v.storage_class != SC_STORAGE_BUFFER && v.storage_class != SC_PUSH_CONSTANT) {
			continue;
		}
		auto ptr = p.types.find(v.pointer_type);
		if (ptr == p.types.end() || ptr->second.op != OP_TYPE_POINTER || ptr->second.operands.size() < 2) {
			r_error = vformat("Variable %u has no pointer type.", v.id);
			return false;
		}
		uint32_t type_id = ptr->second.operands[1];

		if (v.storage_class == SC_PUSH_CONSTANT) {
			uint32_t size = p.type_size(type_id, 0, 0);
			push_constant_size = (size + 3) & ~3u;
			continue;
		}

		Binding b;
		auto dec = p.decorations.find(v.id);
		if (dec == p.decorations.end() || !dec->second.has_binding) {
			continue; // Not a descriptor (e.g. an atomic counter without binding; not used here).
		}
		b.set = dec->second.has_set ? dec->second.set : 0;
		b.binding = dec->second.binding;
		b.writable = !dec->second.non_writable;

		// Strip one array level.
		auto t = p.types.find(type_id);
		if (t == p.types.end()) {
			r_error = vformat("Unknown type for binding %u in set %u.", b.binding, b.set);
			return false;
		}
		if (t->second.op == OP_TYPE_RUNTIME_ARRAY) {
			r_error = vformat("Runtime-sized descriptor arrays are not supported (set %u, binding %u).", b.set, b.binding);
			return false;
		}
		if (t->second.op == OP_TYPE_ARRAY) {
			auto c = p.constants.find(t->second.operands.size() > 1 ? t->second.operands[1] : 0);
			b.count = c == p.constants.end() ? 1 : c->second;
			type_id = t->second.operands[0];
			t = p.types.find(type_id);
			if (t == p.types.end()) {
				r_error = vformat("Unknown array element type for binding %u in set %u.", b.binding, b.set);
				return false;
			}
		}
		const TypeInfo &ti = t->second;
		auto tdec = p.decorations.find(type_id);
		bool is_block = tdec != p.decorations.end() && tdec->second.block;
		bool is_buffer_block = tdec != p.decorations.end() && tdec->second.buffer_block;
		if (v.storage_class == SC_STORAGE_BUFFER) {
			b.kind = KIND_STORAGE_BUFFER;
		} else if (v.storage_class == SC_UNIFORM) {
			if (is_buffer_block) {
				b.kind = KIND_STORAGE_BUFFER;
			} else if (is_block) {
				b.kind = KIND_UNIFORM_BUFFER;
			} else {
				r_error = vformat("Uniform variable at set %u, binding %u is not a block.", b.set, b.binding);
				return false;
			}
		} else {
			switch (ti.op) {
				case OP_TYPE_SAMPLER:
					b.kind = KIND_SAMPLER;
					break;
				case OP_TYPE_SAMPLED_IMAGE:
					b.kind = KIND_COMBINED_IMAGE_SAMPLER;
					break;
				case OP_TYPE_IMAGE: {
					// Operands: sampled type, dim, depth, arrayed, ms, sampled, format.
					uint32_t dim = ti.operands.size() > 1 ? ti.operands[1] : 0;
					uint32_t sampled = ti.operands.size() > 5 ? ti.operands[5] : 1;
					if (dim == IMAGE_DIM_BUFFER || dim == IMAGE_DIM_SUBPASS) {
						r_error = vformat("Texel buffers and subpass inputs are not supported (set %u, binding %u).", b.set, b.binding);
						return false;
					}
					b.kind = sampled == 2 ? KIND_STORAGE_IMAGE : KIND_SAMPLED_IMAGE;
				} break;
				default:
					r_error = vformat("Unsupported uniform type at set %u, binding %u.", b.set, b.binding);
					return false;
			}
		}
		bindings.push_back(b);
	}
	return true;
}
