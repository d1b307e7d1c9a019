/**************************************************************************/
/*  image_saver_exr.cpp                                                   */
/**************************************************************************/
/* godot-area: OpenEXR writer. OpenEXR reports errors with C++            */
/* exceptions; all of them are caught here and turned into messages.      */

#include "modules/openexr/image_saver_exr.h"

#include "core/error/error_macros.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/half.h>

#include <exception>
#include <vector>

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

		Imf::OutputFile file(p_path.c_str(), header);
		file.setFrameBuffer(frame_buffer);
		file.writePixels(height);
	} catch (const std::exception &e) {
		return _exr_save_fail(r_error, vformat("Cannot write EXR \"%s\": %s", p_path.c_str(), e.what()));
	} catch (...) {
		return _exr_save_fail(r_error, vformat("Cannot write EXR \"%s\": unknown OpenEXR error.", p_path.c_str()));
	}
	return true;
}
