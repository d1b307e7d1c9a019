/**************************************************************************/
/*  image_saver_exr.cpp                                                   */
/**************************************************************************/
/* godot-area: OpenEXR writer. OpenEXR reports errors with C++            */
/* exceptions; all of them are caught here and turned into messages.      */

#include "modules/openexr/image_saver_exr.h"
#include "core/io/file_io.h"

#include "core/error/error_macros.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cstring>
#include <exception>
#include <vector>

// Collects the encoded file in memory; ImageSaverEXR::save() then writes it atomically.
class _EXRMemoryStream : public Imf::OStream {
	std::vector<char> bytes;
	uint64_t position = 0;

public:
	_EXRMemoryStream() :
			Imf::OStream("memory") {}
	void write(const char p_c[], int p_n) override {
		if (position + uint64_t(p_n) > bytes.size()) {
			bytes.resize(position + p_n);
		}
		memcpy(bytes.data() + position, p_c, p_n);
		position += p_n;
	}
	uint64_t tellp() override { return position; }
	void seekp(uint64_t p_pos) override { position = p_pos; }
	const std::vector<char> &get_bytes() const { return bytes; }
};

static bool _exr_save_fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

bool ImageSaverEXR::save(const Image &p_image, const String &p_path, bool p_half, String *r_error) {
	if (p_path.empty()) {
		return _exr_save_fail(r_error, "Cannot write EXR: the file path is empty.");
	}
	if (p_image.is_empty()) {
		return _exr_save_fail(r_error, vformat("Cannot write EXR \"%s\": the image is empty (%dx%d).", p_path.c_str(), p_image.get_width(), p_image.get_height()));
	}
	const int width = p_image.get_width();
	const int height = p_image.get_height();
	static const char *channel_names[Image::CHANNELS] = { "R", "G", "B", "A" };

	try {
		Imf::Header header(width, height);
		const Imf::PixelType type = p_half ? Imf::HALF : Imf::FLOAT;
		for (int c = 0; c < Image::CHANNELS; c++) {
			header.channels().insert(channel_names[c], Imf::Channel(type));
		}

		Imf::FrameBuffer frame_buffer;
		std::vector<Imath::half> halves;
		if (p_half) {
			const std::vector<float> &data = p_image.get_data();
			halves.resize(data.size());
			for (size_t i = 0; i < data.size(); i++) {
				halves[i] = Imath::half(data[i]);
			}
			const size_t x_stride = sizeof(Imath::half) * Image::CHANNELS;
			for (int c = 0; c < Image::CHANNELS; c++) {
				frame_buffer.insert(channel_names[c], Imf::Slice(Imf::HALF, (char *)(halves.data() + c), x_stride, x_stride * width));
			}
		} else {
			const size_t x_stride = sizeof(float) * Image::CHANNELS;
			for (int c = 0; c < Image::CHANNELS; c++) {
				frame_buffer.insert(channel_names[c], Imf::Slice(Imf::FLOAT, (char *)(p_image.ptr() + c), x_stride, x_stride * width));
			}
		}

		_EXRMemoryStream stream;
		{
			Imf::OutputFile file(stream, header);
			file.setFrameBuffer(frame_buffer);
			file.writePixels(height);
		} // The destructor writes the line offset table.
		String error;
		if (!file_write_atomic(p_path, stream.get_bytes().data(), stream.get_bytes().size(), &error)) {
			return _exr_save_fail(r_error, vformat("Cannot write EXR: %s", error.c_str()));
		}
	} catch (const std::exception &e) {
		return _exr_save_fail(r_error, vformat("Cannot write EXR \"%s\": %s", p_path.c_str(), e.what()));
	} catch (...) {
		return _exr_save_fail(r_error, vformat("Cannot write EXR \"%s\": unknown OpenEXR error.", p_path.c_str()));
	}
	return true;
}
