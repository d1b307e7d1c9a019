/**************************************************************************/
/*  image_loader_exr.cpp                                                  */
/**************************************************************************/
/* godot-area: OpenEXR reader. OpenEXR reports errors with C++            */
/* exceptions; all of them are caught here and turned into messages.      */

#include "modules/openexr/image_loader_exr.h"

#include "core/error/error_macros.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <exception>
#include <filesystem>
#include <vector>

static bool _exr_load_fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = p_message;
	}
	ERR_PRINT(p_message);
	return false;
}

bool ImageLoaderEXR::load(const String &p_path, Image &r_image, String *r_error) {
	r_image.clear();
	std::error_code ec;
	if (p_path.empty() || !std::filesystem::is_regular_file(p_path, ec)) {
		return _exr_load_fail(r_error, vformat("Cannot read EXR \"%s\": file not found.", p_path.c_str()));
	}

	try {
		Imf::InputFile file(p_path.c_str());
		const Imath::Box2i data_window = file.header().dataWindow();
		const long long width = (long long)data_window.max.x - data_window.min.x + 1;
		const long long height = (long long)data_window.max.y - data_window.min.y + 1;
		if (width <= 0 || height <= 0 || width > Image::MAX_SIZE || height > Image::MAX_SIZE) {
			return _exr_load_fail(r_error, vformat("Cannot read EXR \"%s\": unsupported data window size %lldx%lld (max %d per side).", p_path.c_str(), width, height, Image::MAX_SIZE));
		}

		const Imf::ChannelList &channels = file.header().channels();
		const bool has_r = channels.findChannel("R") != nullptr;
		const bool has_g = channels.findChannel("G") != nullptr;
		const bool has_b = channels.findChannel("B") != nullptr;
		const bool has_y = channels.findChannel("Y") != nullptr;
		const bool luminance_only = has_y && !has_r && !has_g && !has_b;
		if (!has_r && !has_g && !has_b && !has_y) {
			return _exr_load_fail(r_error, vformat("Cannot read EXR \"%s\": it has none of the channels R, G, B or Y.", p_path.c_str()));
		}

		std::vector<float> data((size_t)width * (size_t)height * Image::CHANNELS, 0.0f);
		const size_t x_stride = sizeof(float) * Image::CHANNELS;
		const size_t y_stride = x_stride * (size_t)width;
		Imf::FrameBuffer frame_buffer;
		static const char *channel_names[Image::CHANNELS] = { "R", "G", "B", "A" };
		for (int c = 0; c < Image::CHANNELS; c++) {
			const char *source = (luminance_only && c < 3) ? "Y" : channel_names[c];
			const double fill = (c == 3) ? 1.0 : 0.0;
			if (luminance_only && c > 0 && c < 3) {
				continue; // Copied from R after reading; a FrameBuffer cannot hold one channel twice.
			}
			frame_buffer.insert(source, Imf::Slice::Make(Imf::FLOAT, data.data() + c, data_window, x_stride, y_stride, 1, 1, fill));
		}
		file.setFrameBuffer(frame_buffer);
		file.readPixels(data_window.min.y, data_window.max.y);

		if (luminance_only) {
			for (size_t i = 0; i < data.size(); i += Image::CHANNELS) {
				data[i + 1] = data[i];
				data[i + 2] = data[i];
			}
		}
		if (!r_image.set_data((int)width, (int)height, data)) {
			return _exr_load_fail(r_error, vformat("Cannot read EXR \"%s\": could not store the pixels.", p_path.c_str()));
		}
	} catch (const std::exception &e) {
		r_image.clear();
		return _exr_load_fail(r_error, vformat("Cannot read EXR \"%s\": %s", p_path.c_str(), e.what()));
	} catch (...) {
		r_image.clear();
		return _exr_load_fail(r_error, vformat("Cannot read EXR \"%s\": unknown OpenEXR error.", p_path.c_str()));
	}
	return true;
}
