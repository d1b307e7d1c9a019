/**************************************************************************/
/*  editor_icons.cpp                                                      */
/**************************************************************************/
/* godot-area: see editor_icons.h.                                        */

#include "editor/editor_icons.h"

#include "core/error/error_macros.h"
#include "core/object/class_db.h"
#include "core/object/object.h"
#include "editor/editor_icons.gen.h"
#include "scene/3d/light_3d.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <map>
#include <memory>

namespace {

bool _parse_number(const String &p_text, real_t &r_value) {
	const char *begin = p_text.c_str();
	char *end = nullptr;
	double v = strtod(begin, &end);
	if (end == begin) {
		return false;
	}
	while (*end == ' ') {
		end++;
	}
	if (*end != '\0' && String(end) != "px") {
		return false;
	}
	r_value = (real_t)v;
	return true;
}

int _hex(char p_c) {
	if (p_c >= '0' && p_c <= '9') {
		return p_c - '0';
	}
	if (p_c >= 'a' && p_c <= 'f') {
		return p_c - 'a' + 10;
	}
	if (p_c >= 'A' && p_c <= 'F') {
		return p_c - 'A' + 10;
	}
	return -1;
}

// "#rgb" or "#rrggbb"; "none" gives r_none.
bool _parse_color(const String &p_text, Color &r_color, bool &r_none) {
	r_none = p_text == "none";
	if (r_none) {
		return true;
	}
	if (p_text.size() != 4 && p_text.size() != 7) {
		return false;
	}
	if (p_text[0] != '#') {
		return false;
	}
	int v[6];
	for (size_t i = 1; i < p_text.size(); i++) {
		v[i - 1] = _hex(p_text[i]);
		if (v[i - 1] < 0) {
			return false;
		}
	}
	if (p_text.size() == 4) {
		r_color = Color(v[0] * 17 / 255.0f, v[1] * 17 / 255.0f, v[2] * 17 / 255.0f, 1.0f);
	} else {
		r_color = Color((v[0] * 16 + v[1]) / 255.0f, (v[2] * 16 + v[3]) / 255.0f, (v[4] * 16 + v[5]) / 255.0f, 1.0f);
	}
	return true;
}

// One element: its name and attributes (quoted with " or ').
struct Element {
	String name;
	std::map<String, String> attributes;
	bool closing = false;
};

bool _read_element(const String &p_tag, Element &r_element, String *r_error) {
	size_t i = 0;
	if (i < p_tag.size() && p_tag[i] == '/') {
		r_element.closing = true;
		i++;
	}
	size_t name_begin = i;
	while (i < p_tag.size() && p_tag[i] != ' ' && p_tag[i] != '/' && p_tag[i] != '\t' && p_tag[i] != '\n') {
		i++;
	}
	r_element.name = p_tag.substr(name_begin, i - name_begin);
	while (i < p_tag.size()) {
		while (i < p_tag.size() && (p_tag[i] == ' ' || p_tag[i] == '\t' || p_tag[i] == '\n' || p_tag[i] == '\r' || p_tag[i] == '/')) {
			i++;
		}
		if (i >= p_tag.size()) {
			break;
		}
		size_t eq = p_tag.find('=', i);
		if (eq == String::npos || eq + 1 >= p_tag.size() || (p_tag[eq + 1] != '"' && p_tag[eq + 1] != '\'')) {
			*r_error = vformat("malformed attribute in <%s>", r_element.name.c_str());
			return false;
		}
		const char quote = p_tag[eq + 1];
		size_t close = p_tag.find(quote, eq + 2);
		if (close == String::npos) {
			*r_error = vformat("unterminated attribute value in <%s>", r_element.name.c_str());
			return false;
		}
		r_element.attributes[string_strip_edges(p_tag.substr(i, eq - i))] = p_tag.substr(eq + 2, close - eq - 2);
		i = close + 1;
	}
	return true;
}

bool _number_attribute(const Element &p_e, const char *p_name, bool p_required, real_t &r_value, String *r_error) {
	auto it = p_e.attributes.find(p_name);
	if (it == p_e.attributes.end()) {
		if (p_required) {
			*r_error = vformat("<%s> has no %s", p_e.name.c_str(), p_name);
		}
		return !p_required;
	}
	if (!_parse_number(it->second, r_value)) {
		*r_error = vformat("<%s> %s=\"%s\" is not a number", p_e.name.c_str(), p_name, it->second.c_str());
		return false;
	}
	return true;
}

bool _paint_attributes(const Element &p_e, EditorIconShape &r_shape, String *r_error) {
	static const char *known[] = { "x", "y", "width", "height", "rx", "cx", "cy", "r", "points", "fill", "fill-opacity", "stroke", "stroke-width", nullptr };
	for (const auto &a : p_e.attributes) {
		bool ok = false;
		for (int i = 0; known[i]; i++) {
			ok = ok || a.first == known[i];
		}
		if (!ok) {
			*r_error = vformat("<%s> has the unsupported attribute '%s'", p_e.name.c_str(), a.first.c_str());
			return false;
		}
	}
	bool none = false;
	auto fill = p_e.attributes.find("fill");
	if (fill != p_e.attributes.end()) {
		if (!_parse_color(fill->second, r_shape.fill, none)) {
			*r_error = vformat("<%s> fill=\"%s\" is not #rgb, #rrggbb or none", p_e.name.c_str(), fill->second.c_str());
			return false;
		}
		r_shape.has_fill = !none;
	}
	real_t opacity = 1;
	if (!_number_attribute(p_e, "fill-opacity", false, opacity, r_error)) {
		return false;
	}
	r_shape.fill.a = (float)std::min<real_t>(std::max<real_t>(opacity, 0), 1);
	auto stroke = p_e.attributes.find("stroke");
	if (stroke != p_e.attributes.end()) {
		if (!_parse_color(stroke->second, r_shape.stroke, none)) {
			*r_error = vformat("<%s> stroke=\"%s\" is not #rgb, #rrggbb or none", p_e.name.c_str(), stroke->second.c_str());
			return false;
		}
		r_shape.has_stroke = !none;
	}
	return _number_attribute(p_e, "stroke-width", false, r_shape.stroke_width, r_error);
}

} // namespace

bool EditorIcons::parse_svg(const String &p_text, const String &p_file, EditorIcon &r_icon, String *r_error) {
	String error;
	bool seen_svg = false;
	size_t pos = 0;
	r_icon.shapes.clear();
	while ((pos = p_text.find('<', pos)) != String::npos) {
		if (p_text.compare(pos, 4, "<!--") == 0) {
			size_t end = p_text.find("-->", pos);
			if (end == String::npos) {
				error = "unterminated comment";
				break;
			}
			pos = end + 3;
			continue;
		}
		if (p_text.compare(pos, 2, "<?") == 0) {
			pos = p_text.find("?>", pos);
			if (pos == String::npos) {
				error = "unterminated <?...?>";
				break;
			}
			continue;
		}
		size_t end = p_text.find('>', pos);
		if (end == String::npos) {
			error = "unterminated element";
			break;
		}
		Element e;
		if (!_read_element(p_text.substr(pos + 1, end - pos - 1), e, &error)) {
			break;
		}
		pos = end + 1;
		if (e.closing) {
			continue;
		}
		if (e.name == "svg") {
			seen_svg = true;
			auto vb = e.attributes.find("viewBox");
			if (vb != e.attributes.end()) {
				std::vector<String> parts;
				for (const String &p : string_split(vb->second, ' ', false)) {
					parts.push_back(p);
				}
				real_t w = 0, h = 0;
				if (parts.size() != 4 || !_parse_number(parts[2], w) || !_parse_number(parts[3], h) || w <= 0 || h <= 0) {
					error = vformat("<svg> viewBox=\"%s\" is not \"0 0 W H\"", vb->second.c_str());
					break;
				}
				r_icon.view_size = Vector2(w, h);
			}
			continue;
		}
		if (!seen_svg) {
			error = vformat("<%s> before <svg>", e.name.c_str());
			break;
		}
		EditorIconShape shape;
		if (e.name == "rect") {
			shape.type = EditorIconShape::RECT;
			if (!_number_attribute(e, "x", false, shape.position.x, &error) || !_number_attribute(e, "y", false, shape.position.y, &error) ||
					!_number_attribute(e, "width", true, shape.size.x, &error) || !_number_attribute(e, "height", true, shape.size.y, &error) ||
					!_number_attribute(e, "rx", false, shape.radius, &error)) {
				break;
			}
		} else if (e.name == "circle") {
			shape.type = EditorIconShape::CIRCLE;
			if (!_number_attribute(e, "cx", false, shape.position.x, &error) || !_number_attribute(e, "cy", false, shape.position.y, &error) ||
					!_number_attribute(e, "r", true, shape.radius, &error)) {
				break;
			}
		} else if (e.name == "polygon") {
			shape.type = EditorIconShape::POLYGON;
			auto pts = e.attributes.find("points");
			String list = pts == e.attributes.end() ? String() : pts->second;
			for (char &c : list) {
				c = c == ',' ? ' ' : c;
			}
			std::vector<String> numbers = string_split(list, ' ', false);
			if (numbers.size() < 6 || numbers.size() % 2) {
				error = vformat("<polygon> points=\"%s\" is not at least three x,y pairs", pts == e.attributes.end() ? "" : pts->second.c_str());
				break;
			}
			bool ok = true;
			for (size_t i = 0; i < numbers.size() && ok; i += 2) {
				Vector2 p;
				ok = _parse_number(numbers[i], p.x) && _parse_number(numbers[i + 1], p.y);
				shape.points.push_back(p);
			}
			if (!ok) {
				error = vformat("<polygon> points=\"%s\" holds a non-number", pts->second.c_str());
				break;
			}
		} else {
			error = vformat("<%s> is not supported (rect, circle and polygon are)", e.name.c_str());
			break;
		}
		if (!_paint_attributes(e, shape, &error)) {
			break;
		}
		r_icon.shapes.push_back(shape);
	}
	if (error.empty() && !seen_svg) {
		error = "no <svg> element";
	}
	if (!error.empty()) {
		if (r_error) {
			*r_error = vformat("%s: %s.", p_file.c_str(), error.c_str());
		}
		r_icon.shapes.clear();
		return false;
	}
	return true;
}

namespace {

const std::map<String, EditorIcon> &_icons() {
	static std::unique_ptr<std::map<String, EditorIcon>> icons;
	if (!icons) {
		icons = std::make_unique<std::map<String, EditorIcon>>();
		for (int i = 0; EDITOR_ICONS[i].name; i++) {
			EditorIcon icon;
			icon.name = EDITOR_ICONS[i].name;
			String error;
			if (!EditorIcons::parse_svg(EDITOR_ICONS[i].svg, vformat("editor/icons/%s.svg", EDITOR_ICONS[i].name), icon, &error)) {
				ERR_PRINT("Editor icon left out: " + error);
				continue;
			}
			(*icons)[icon.name] = icon;
		}
	}
	return *icons;
}

} // namespace

std::vector<String> EditorIcons::get_icon_names() {
	std::vector<String> names;
	for (int i = 0; EDITOR_ICONS[i].name; i++) {
		names.push_back(EDITOR_ICONS[i].name);
	}
	return names;
}

const EditorIcon *EditorIcons::get_icon(const String &p_name) {
	const std::map<String, EditorIcon> &icons = _icons();
	auto it = icons.find(p_name);
	return it == icons.end() ? nullptr : &it->second;
}

String EditorIcons::get_class_icon_name(const String &p_class, const String &p_fallback) {
	for (String c = p_class; !c.empty(); c = ClassDB::class_exists(c) ? ClassDB::get_parent_class(c) : String()) {
		if (has_icon(c)) {
			return c;
		}
	}
	return has_icon(p_fallback) ? p_fallback : String();
}

String EditorIcons::get_object_icon_name(const Object *p_object, const String &p_fallback) {
	if (!p_object) {
		return has_icon(p_fallback) ? p_fallback : String();
	}
	if (p_object->is_class("MissingNode")) {
		return has_icon("MissingNode") ? String("MissingNode") : get_class_icon_name("Node3D", p_fallback);
	}
	const String name = get_class_icon_name(p_object->get_class(), p_fallback);
	// An AreaLight3D shows the icon of its area_shape (issue 21) where there is one.
	const AreaLight3D *area = dynamic_cast<const AreaLight3D *>(p_object);
	if (area && name == "AreaLight3D") {
		static const char *suffixes[] = { "", "Disk", "Sphere", "Tube" };
		const int shape = int(area->get_area_shape());
		if (shape > 0 && shape < int(std::size(suffixes)) && has_icon(name + suffixes[shape])) {
			return name + suffixes[shape];
		}
	}
	return name;
}
