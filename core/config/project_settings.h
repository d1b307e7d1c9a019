/**************************************************************************/
/*  project_settings.h                                                    */
/**************************************************************************/
/* godot-area: a minimal Godot ProjectSettings. Named settings            */
/* ("section/group/name") with a default (the value GLOBAL_DEF registers) */
/* and an optional override (set from the CLI with --setting name=value,  */
/* or from tests). GLOBAL_GET returns the override if set, else the       */
/* default. No project.godot file: settings live for the process.        */
/*                                                                        */
/* Registered by the engine so far:                                       */
/*   rendering/lights_and_shadows/area_light_error_budget (float, 0.05):  */
/*     the largest predicted mean LDR-FLIP an AUTO area light may show    */
/*     (see renderer_rd/area_lights/area_method_selector.h).              */
/*   rendering/lights_and_shadows/area_light_auto_default_roughness       */
/*     (float, 0.5): the dominant roughness AUTO assumes when no visible  */
/*     receiver lies in a light's influence box.                          */

#pragma once

#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <map>
#include <mutex>
#include <vector>

class ProjectSettings {
	struct Setting {
		Variant default_value;
		Variant value;
		bool overridden = false;
		bool registered = false; // A GLOBAL_DEF gave it a default (else it was only set).
	};

	mutable std::mutex mutex;
	std::map<String, Setting> settings;

	static bool _is_valid_name(const String &p_name);

public:
	// The process-wide instance (always exists).
	static ProjectSettings *get_singleton();

	// Registers p_name with p_default (the first registration wins; later calls keep the first
	// default) and returns the current value. An invalid name prints an error and returns p_default.
	Variant global_def(const String &p_name, const Variant &p_default);
	// The override if set, else the registered default; an unknown name prints an error and returns Variant().
	Variant get_setting(const String &p_name) const;
	// Same, but p_fallback (no error) when the name is unknown.
	Variant get_setting_with_fallback(const String &p_name, const Variant &p_fallback) const;
	// Overrides p_name (registered or not yet: the override then wins once it is registered).
	// When the setting is registered, the value must convert to the default's type (int <-> float
	// allowed) or it is rejected with an error naming the setting. Returns false on rejection.
	bool set_setting(const String &p_name, const Variant &p_value);
	// Drops the override: GLOBAL_GET returns the default again.
	void clear_override(const String &p_name);
	bool has_setting(const String &p_name) const;
	bool is_registered(const String &p_name) const;
	Variant get_default(const String &p_name) const;
	// Registered and overridden names, sorted.
	std::vector<String> get_setting_names() const;

	// Parses "name=value" (the CLI's --setting argument). The value is parsed as the registered
	// type when known (bool true/false/1/0, int, float, else string); unknown names are stored as
	// float when the text is a number, else as string. False (r_error set) on a malformed argument.
	bool parse_override(const String &p_assignment, String *r_error = nullptr);
};

// Godot's macros: define a setting with its default (returns the current value) and read it.
#define GLOBAL_DEF(m_name, m_default) ProjectSettings::get_singleton()->global_def((m_name), Variant(m_default))
#define GLOBAL_GET(m_name) ProjectSettings::get_singleton()->get_setting((m_name))
