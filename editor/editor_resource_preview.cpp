/**************************************************************************/
/*  editor_resource_preview.cpp                                           */
/**************************************************************************/
/* godot-area: EditorResourcePreview (see editor_resource_preview.h).     */

#include "editor/editor_resource_preview.h"

#include "core/io/resource.h"
#include "core/math/color.h"
#include "core/object/class_db.h"
#include "scene/resources/resource_format_text.h"
#include "scene/resources/texture.h"

#include <algorithm>
#include <cmath>

Image EditorResourcePreview::make_texture_thumbnail(const Image &p_image, int p_max_size) {
	if (p_image.is_empty() || p_max_size < 1) {
		return Image();
	}
	const int sw = p_image.get_width();
	const int sh = p_image.get_height();
	const double scale = std::min(double(p_max_size) / sw, double(p_max_size) / sh);
	const int tw = std::clamp(int(std::lround(sw * scale)), 1, p_max_size);
	const int th = std::clamp(int(std::lround(sh * scale)), 1, p_max_size);
	const float dark = Color::srgb_to_linear_channel(CHECKER_DARK);
	const float light = Color::srgb_to_linear_channel(CHECKER_LIGHT);
	Image thumb(tw, th);
	for (int y = 0; y < th; y++) {
		// The source rows this pixel covers: [y0, y1), at least one (nearest when enlarging).
		const int y0 = int(int64_t(y) * sh / th);
		const int y1 = std::max(y0 + 1, int(int64_t(y + 1) * sh / th));
		for (int x = 0; x < tw; x++) {
			const int x0 = int(int64_t(x) * sw / tw);
			const int x1 = std::max(x0 + 1, int(int64_t(x + 1) * sw / tw));
			double r = 0.0, g = 0.0, b = 0.0, a = 0.0;
			for (int sy = y0; sy < y1; sy++) {
				for (int sx = x0; sx < x1; sx++) {
					const Color c = p_image.get_pixel(sx, sy);
					const double alpha = std::isfinite(c.a) ? std::clamp(double(c.a), 0.0, 1.0) : 0.0;
					const Color lin = c.srgb_to_linear();
					// Premultiplied: a transparent texel's colour does not bleed into its neighbours.
					r += alpha * (std::isfinite(lin.r) ? std::max(0.0f, lin.r) : 0.0f);
					g += alpha * (std::isfinite(lin.g) ? std::max(0.0f, lin.g) : 0.0f);
					b += alpha * (std::isfinite(lin.b) ? std::max(0.0f, lin.b) : 0.0f);
					a += alpha;
				}
			}
			const double n = double(x1 - x0) * double(y1 - y0);
			const float under = ((x / CHECKER_CELL) + (y / CHECKER_CELL)) % 2 == 0 ? light : dark;
			const double coverage = a / n;
			thumb.set_pixel(x, y, Color(float(r / n + (1.0 - coverage) * under), float(g / n + (1.0 - coverage) * under), float(b / n + (1.0 - coverage) * under), 1.0f));
		}
	}
	return thumb;
}

String EditorResourcePreview::describe(const Variant &p_value) {
	const Resource *res = Object::cast_to<Resource>(p_value.get_object());
	if (!res) {
		return "<empty>";
	}
	String text = res->get_class();
	if (const Texture2D *tex = Object::cast_to<Texture2D>(res)) {
		text += vformat(" %dx%d", tex->get_width(), tex->get_height());
	}
	text += res->get_path().empty() ? String(" (built-in)") : String(" ") + res->get_path();
	return text;
}

Variant EditorResourcePreview::load_for_property(const String &p_path, const String &p_scene_path, const String &p_type, String *r_error) {
	const String file = ResourceFormatText::resolve_path(p_path, p_scene_path);
	String error;
	Ref<Resource> res = ResourceFormatText::load_resource(file, p_type, &error);
	if (res.is_null()) {
		if (r_error) {
			*r_error = vformat("%s: %s", file.c_str(), error.empty() ? "no loader for this kind of file" : error.c_str());
		}
		return Variant();
	}
	if (!p_type.empty() && !ClassDB::is_parent_class(res->get_class(), p_type)) {
		if (r_error) {
			*r_error = vformat("%s is a %s; this property takes a %s.", file.c_str(), res->get_class().c_str(), p_type.c_str());
		}
		return Variant();
	}
	if (string_begins_with(p_path, "res://")) {
		res->set_path(p_path); // Written back as the ext_resource path the user typed, as Godot does.
	}
	return Variant(res.ptr());
}
