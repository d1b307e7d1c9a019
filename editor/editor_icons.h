/**************************************************************************/
/*  editor_icons.h                                                        */
/**************************************************************************/
/* godot-area: the editor's class icons (Godot: EditorNode::get_class_icon */
/* and get_object_icon over the theme's editor/icons/<name>.svg), headless.    */
/*                                                                        */
/* Every editor/icons/<name>.svg is embedded at build time (SConstruct writes  */
/* editor/editor_icons.gen.h, as Godot bakes editor_icons.gen.h) and      */
/* parsed once into shapes that a UI draws as vectors at any size:        */
/*   <rect x y width height rx>, <circle cx cy r>, <polygon points>       */
/*   (convex), each with fill / stroke (#rgb, #rrggbb, none),             */
/*   fill-opacity, stroke-width; the root <svg> gives the viewBox.        */
/* Anything else in a file is an error naming the file and the element   */
/* (the icons are hand-written in this subset).                           */
/*                                                                        */
/* Class icons fall back up the inheritance chain as Godot's editor does: */
/* a class without its own icon shows the nearest ancestor's (Light3D ->  */
/* VisualInstance3D -> Node3D has one), and a class with no icon on the   */
/* way to Object shows the fallback ("Node"). A MissingNode shows its own */
/* placeholder icon ("MissingNode"), never the icon of the class it      */
/* stands in for, since that class is not available. An AreaLight3D      */
/* shows the icon of its area_shape (AreaLight3D<Disk|Sphere|Tube>; the   */
/* rectangle keeps AreaLight3D), so the scene tree tells shapes apart.    */

#pragma once

#include "core/math/color.h"
#include "core/math/vector2.h"
#include "core/string/ustring.h"

#include <vector>

class Object;

struct EditorIconShape {
	enum Type {
		RECT,
		CIRCLE,
		POLYGON,
	};
	Type type = RECT;
	Vector2 position; // RECT: top-left corner; CIRCLE: centre. ViewBox units, y down.
	Vector2 size; // RECT only.
	real_t radius = 0; // CIRCLE: radius; RECT: corner radius (rx).
	std::vector<Vector2> points; // POLYGON only.
	bool has_fill = true; // SVG's default fill is black.
	Color fill = Color(0, 0, 0, 1); // sRGB, straight alpha.
	bool has_stroke = false;
	Color stroke = Color(0, 0, 0, 1);
	real_t stroke_width = 1;
};

struct EditorIcon {
	String name;
	Vector2 view_size = Vector2(16, 16); // The viewBox's width and height.
	std::vector<EditorIconShape> shapes;
};

class EditorIcons {
public:
	// Parses one icon. False with r_error naming p_file and the offending element or attribute.
	static bool parse_svg(const String &p_text, const String &p_file, EditorIcon &r_icon, String *r_error);

	// The embedded icons (parsed on first use; a file that fails to parse is reported once and left out).
	static std::vector<String> get_icon_names();
	static const EditorIcon *get_icon(const String &p_name); // nullptr when there is none.
	static bool has_icon(const String &p_name) { return get_icon(p_name) != nullptr; }

	// The icon a class shows: its own, else the nearest ancestor's in ClassDB, else p_fallback
	// (empty when p_fallback has no icon either).
	static String get_class_icon_name(const String &p_class, const String &p_fallback = "Node");
	// The icon an object shows in the scene tree: MissingNode's placeholder for a MissingNode,
	// otherwise its class icon; an AreaLight3D whose area_shape is not the rectangle shows
	// AreaLight3DDisk / AreaLight3DSphere / AreaLight3DTube.
	static String get_object_icon_name(const Object *p_object, const String &p_fallback = "Node");
};
