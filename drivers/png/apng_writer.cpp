/**************************************************************************/
/*  apng_writer.cpp                                                       */
/**************************************************************************/
/* godot-area: APNG assembly (APNG specification 1.0, the chunk layout;   */
/* PNG specification, ISO/IEC 15948, section 5 for chunks and CRC-32).    */
/*   signature, IHDR, acTL(num_frames, num_plays = 0 = loop forever),     */
/*   frame 0: fcTL(seq 0) + IDAT...   (the default image is frame 0)      */
/*   frame i: fcTL(seq) + fdAT(seq, IDAT data)...                          */
/*   IEND                                                                 */
/* Sequence numbers count fcTL and fdAT chunks together from 0.           */

#include "drivers/png/apng_writer.h"

#include "core/error/error_macros.h"
#include "core/io/file_io.h"
#include "drivers/png/png_writer.h"

#include <cstring>

namespace {

bool _apng_fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

// CRC-32 of the PNG specification (polynomial 0xEDB88320, reflected), over chunk type and data.
uint32_t _crc32(const uint8_t *p_data, size_t p_size, uint32_t p_crc = 0xFFFFFFFFu) {
	static uint32_t table[256];
	static bool table_ready = false;
	if (!table_ready) {
		for (uint32_t n = 0; n < 256; n++) {
			uint32_t c = n;
			for (int k = 0; k < 8; k++) {
				c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
			}
			table[n] = c;
		}
		table_ready = true;
	}
	uint32_t c = p_crc;
	for (size_t i = 0; i < p_size; i++) {
		c = table[(c ^ p_data[i]) & 0xFF] ^ (c >> 8);
	}
	return c;
}

void _put_u32(std::vector<uint8_t> &r_out, uint32_t p_value) {
	r_out.push_back(uint8_t(p_value >> 24));
	r_out.push_back(uint8_t(p_value >> 16));
	r_out.push_back(uint8_t(p_value >> 8));
	r_out.push_back(uint8_t(p_value));
}

void _put_u16(std::vector<uint8_t> &r_out, uint16_t p_value) {
	r_out.push_back(uint8_t(p_value >> 8));
	r_out.push_back(uint8_t(p_value));
}

uint32_t _get_u32(const uint8_t *p) {
	return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

void _put_chunk(std::vector<uint8_t> &r_out, const char *p_type, const std::vector<uint8_t> &p_data) {
	_put_u32(r_out, uint32_t(p_data.size()));
	const size_t type_at = r_out.size();
	r_out.insert(r_out.end(), p_type, p_type + 4);
	r_out.insert(r_out.end(), p_data.begin(), p_data.end());
	_put_u32(r_out, _crc32(&r_out[type_at], 4 + p_data.size()) ^ 0xFFFFFFFFu);
}

struct Chunk {
	String type;
	std::vector<uint8_t> data;
};

// Splits a PNG that libpng wrote into its chunks (CRCs were written by libpng; lengths are checked).
bool _split_chunks(const std::vector<uint8_t> &p_png, std::vector<Chunk> &r_chunks) {
	static const uint8_t signature[8] = { 137, 80, 78, 71, 13, 10, 26, 10 };
	if (p_png.size() < 8 || std::memcmp(p_png.data(), signature, 8) != 0) {
		return false;
	}
	size_t at = 8;
	while (at + 12 <= p_png.size()) {
		const uint32_t length = _get_u32(&p_png[at]);
		if (at + 12 + size_t(length) > p_png.size()) {
			return false;
		}
		Chunk c;
		c.type = String(reinterpret_cast<const char *>(&p_png[at + 4]), 4);
		c.data.assign(p_png.begin() + at + 8, p_png.begin() + at + 8 + length);
		r_chunks.push_back(std::move(c));
		at += 12 + size_t(length);
	}
	return at == p_png.size();
}

} // namespace

bool APNGWriter::save_rgba8(const std::vector<std::vector<uint8_t>> &p_frames, int p_width, int p_height, int p_delay_ms, const String &p_path, String *r_error) {
	if (p_path.empty()) {
		return _apng_fail(r_error, "Cannot write APNG: the file path is empty.");
	}
	if (p_frames.empty()) {
		return _apng_fail(r_error, vformat("Cannot write APNG \"%s\": no frames.", p_path.c_str()));
	}
	if (p_delay_ms < 1 || p_delay_ms > 65535) {
		return _apng_fail(r_error, vformat("Cannot write APNG \"%s\": the frame delay must be 1..65535 ms, got %d.", p_path.c_str(), p_delay_ms));
	}
	std::vector<uint8_t> out = { 137, 80, 78, 71, 13, 10, 26, 10 };
	uint32_t sequence = 0;
	for (size_t f = 0; f < p_frames.size(); f++) {
		std::vector<uint8_t> png;
		String error;
		if (!PNGWriter::encode_rgba8(p_frames[f], p_width, p_height, png, &error, true, p_path)) {
			return _apng_fail(r_error, vformat("Cannot write APNG \"%s\": frame %zu: %s", p_path.c_str(), f, error.c_str()));
		}
		std::vector<Chunk> chunks;
		if (!_split_chunks(png, chunks) || chunks.empty() || chunks[0].type != "IHDR") {
			return _apng_fail(r_error, vformat("Cannot write APNG \"%s\": frame %zu: libpng wrote an unexpected chunk layout.", p_path.c_str(), f));
		}
		if (f == 0) {
			// IHDR and the ancillary chunks before the image data (sRGB, gAMA...), then acTL.
			for (const Chunk &c : chunks) {
				if (c.type == "IDAT" || c.type == "IEND") {
					break;
				}
				_put_chunk(out, c.type.c_str(), c.data);
				if (c.type == "IHDR") {
					std::vector<uint8_t> actl;
					_put_u32(actl, uint32_t(p_frames.size()));
					_put_u32(actl, 0); // num_plays: 0 = forever.
					_put_chunk(out, "acTL", actl);
				}
			}
		}
		std::vector<uint8_t> fctl;
		_put_u32(fctl, sequence++);
		_put_u32(fctl, uint32_t(p_width));
		_put_u32(fctl, uint32_t(p_height));
		_put_u32(fctl, 0); // x_offset
		_put_u32(fctl, 0); // y_offset
		_put_u16(fctl, uint16_t(p_delay_ms)); // delay_num / delay_den seconds.
		_put_u16(fctl, 1000);
		fctl.push_back(0); // dispose_op: APNG_DISPOSE_OP_NONE.
		fctl.push_back(0); // blend_op: APNG_BLEND_OP_SOURCE.
		_put_chunk(out, "fcTL", fctl);
		for (const Chunk &c : chunks) {
			if (c.type != "IDAT") {
				continue;
			}
			if (f == 0) {
				_put_chunk(out, "IDAT", c.data);
			} else {
				std::vector<uint8_t> fdat;
				_put_u32(fdat, sequence++);
				fdat.insert(fdat.end(), c.data.begin(), c.data.end());
				_put_chunk(out, "fdAT", fdat);
			}
		}
	}
	_put_chunk(out, "IEND", {});
	String error;
	if (!file_write_atomic(p_path, out.data(), out.size(), &error)) {
		return _apng_fail(r_error, vformat("Cannot write APNG: %s", error.c_str()));
	}
	return true;
}
