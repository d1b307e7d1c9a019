/**************************************************************************/
/*  property_info.h                                                       */
/**************************************************************************/
/* Description of one bound property: type, name, editor hint and usage.  */

#pragma once

#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <cstdint>

// Same order as Godot's PropertyHint for the values we keep.
enum PropertyHint {
	PROPERTY_HINT_NONE,
	PROPERTY_HINT_RANGE, // "min,max,step[,or_greater][,or_less][,exp][,degrees][,radians_as_degrees][,suffix:unit]"
	PROPERTY_HINT_ENUM, // "Name0,Name1,Name2" or "Name:value,..."
	PROPERTY_HINT_ENUM_SUGGESTION,
	PROPERTY_HINT_EXP_EASING, // "attenuation", "positive_only"
	PROPERTY_HINT_LINK,
	PROPERTY_HINT_FLAGS, // "Flag0,Flag1,..."
	PROPERTY_HINT_LAYERS_2D_RENDER,
	PROPERTY_HINT_LAYERS_2D_PHYSICS,
	PROPERTY_HINT_LAYERS_2D_NAVIGATION,
	PROPERTY_HINT_LAYERS_3D_RENDER,
	PROPERTY_HINT_LAYERS_3D_PHYSICS,
	PROPERTY_HINT_LAYERS_3D_NAVIGATION,
	PROPERTY_HINT_FILE,
	PROPERTY_HINT_DIR,
	PROPERTY_HINT_GLOBAL_FILE,
	PROPERTY_HINT_GLOBAL_DIR,
	PROPERTY_HINT_RESOURCE_TYPE, // hint_string = resource class name, e.g. "Texture2D"
	PROPERTY_HINT_MULTILINE_TEXT,
	PROPERTY_HINT_EXPRESSION,
	PROPERTY_HINT_PLACEHOLDER_TEXT,
	PROPERTY_HINT_COLOR_NO_ALPHA,
	PROPERTY_HINT_MAX,
};

// Bit values follow Godot's PropertyUsageFlags.
enum PropertyUsageFlags {
	PROPERTY_USAGE_NONE = 0,
	PROPERTY_USAGE_STORAGE = 1 << 1, // Saved to scene files.
	PROPERTY_USAGE_EDITOR = 1 << 2, // Shown in the inspector.
	PROPERTY_USAGE_INTERNAL = 1 << 3,
	PROPERTY_USAGE_CHECKABLE = 1 << 4,
	PROPERTY_USAGE_CHECKED = 1 << 5,
	PROPERTY_USAGE_GROUP = 1 << 6, // Entry is a group marker (name = label, hint_string = prefix).
	PROPERTY_USAGE_CATEGORY = 1 << 7,
	PROPERTY_USAGE_SUBGROUP = 1 << 8, // Entry is a subgroup marker.
	PROPERTY_USAGE_READ_ONLY = 1 << 28,
	PROPERTY_USAGE_DEFAULT = PROPERTY_USAGE_STORAGE | PROPERTY_USAGE_EDITOR,
	PROPERTY_USAGE_NO_EDITOR = PROPERTY_USAGE_STORAGE,
};

struct PropertyInfo {
	Variant::Type type = Variant::NIL;
	String name;
	String class_name; // For OBJECT properties: the expected class (RESOURCE_TYPE hint string when empty).
	PropertyHint hint = PROPERTY_HINT_NONE;
	String hint_string;
	uint32_t usage = PROPERTY_USAGE_DEFAULT;

	bool is_group_marker() const { return usage & (PROPERTY_USAGE_GROUP | PROPERTY_USAGE_SUBGROUP | PROPERTY_USAGE_CATEGORY); }

	PropertyInfo() {}
	PropertyInfo(Variant::Type p_type, const String &p_name, PropertyHint p_hint = PROPERTY_HINT_NONE, const String &p_hint_string = String(), uint32_t p_usage = PROPERTY_USAGE_DEFAULT, const String &p_class_name = String()) :
			type(p_type), name(p_name), class_name(p_class_name), hint(p_hint), hint_string(p_hint_string), usage(p_usage) {
		if (class_name.empty() && hint == PROPERTY_HINT_RESOURCE_TYPE) {
			class_name = hint_string;
		}
	}
};
