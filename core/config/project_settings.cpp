/**************************************************************************/
/*  project_settings.cpp                                                  */
/**************************************************************************/
/* godot-area: the minimal ProjectSettings (see project_settings.h).      */

#include "core/config/project_settings.h"

#include "core/error/error_macros.h"

#include <cstdlib>

ProjectSettings *ProjectSettings::get_singleton() {
	static ProjectSettings singleton;
	return &singleton;
}

bool ProjectSettings::_is_valid_name(const String &p_name) {
	if (p_name.empty() || p_name.front() == '/' || p_name.back() == '/') {
		return false;
	}
	for (char c : p_name) {
		if (c == '=' || c == ' ' || c == '\t' || c == '\n') {
			return false;
		}
	}
	return true;
}

Variant ProjectSettings::global_def(const String &p_name, const Variant &p_default) {
	ERR_FAIL_COND_V_MSG(!_is_valid_name(p_name), p_default, vformat("ProjectSettings: \"%s\" is not a valid setting name (\"section/name\", no spaces or '=').", p_name.c_str()));
	std::lock_guard<std::mutex> lock(mutex);
	Setting &s = settings[p_name];
	if (!s.registered) {
		s.registered = true;
		s.default_value = p_default;
		if (s.overridden && !Variant::can_convert(s.value.get_type(), p_default.get_type())) {
			ERR_PRINT(vformat("ProjectSettings: the override of \"%s\" (%s) does not convert to the setting's type (%s); it is dropped.", p_name.c_str(),
					Variant::get_type_name(s.value.get_type()).c_str(), Variant::get_type_name(p_default.get_type()).c_str()));
			s.overridden = false;
			s.value = Variant();
		}
	}
	return s.overridden ? s.value : s.default_value;
}

Variant ProjectSettings::get_setting(const String &p_name) const {
	std::lock_guard<std::mutex> lock(mutex);
	auto it = settings.find(p_name);
	ERR_FAIL_COND_V_MSG(it == settings.end(), Variant(), vformat("ProjectSettings: unknown setting \"%s\".", p_name.c_str()));
	return it->second.overridden ? it->second.value : it->second.default_value;
}

Variant ProjectSettings::get_setting_with_fallback(const String &p_name, const Variant &p_fallback) const {
	std::lock_guard<std::mutex> lock(mutex);
	auto it = settings.find(p_name);
	if (it == settings.end()) {
		return p_fallback;
	}
	return it->second.overridden ? it->second.value : it->second.default_value;
}

bool ProjectSettings::set_setting(const String &p_name, const Variant &p_value) {
	ERR_FAIL_COND_V_MSG(!_is_valid_name(p_name), false, vformat("ProjectSettings: \"%s\" is not a valid setting name.", p_name.c_str()));
	std::lock_guard<std::mutex> lock(mutex);
	Setting &s = settings[p_name];
	if (s.registered && !Variant::can_convert(p_value.get_type(), s.default_value.get_type())) {
		ERR_PRINT(vformat("ProjectSettings: \"%s\" is a %s setting; a %s value is rejected (the old value stays).", p_name.c_str(),
				Variant::get_type_name(s.default_value.get_type()).c_str(), Variant::get_type_name(p_value.get_type()).c_str()));
		return false;
	}
	s.value = p_value;
	s.overridden = true;
	return true;
}

void ProjectSettings::clear_override(const String &p_name) {
	std::lock_guard<std::mutex> lock(mutex);
	auto it = settings.find(p_name);
	if (it == settings.end()) {
		return;
	}
	it->second.overridden = false;
	it->second.value = Variant();
	if (!it->second.registered) {
		settings.erase(it);
	}
}

bool ProjectSettings::has_setting(const String &p_name) const {
	std::lock_guard<std::mutex> lock(mutex);
	return settings.count(p_name) > 0;
}

bool ProjectSettings::is_registered(const String &p_name) const {
	std::lock_guard<std::mutex> lock(mutex);
	auto it = settings.find(p_name);
	return it != settings.end() && it->second.registered;
}

Variant ProjectSettings::get_default(const String &p_name) const {
	std::lock_guard<std::mutex> lock(mutex);
	auto it = settings.find(p_name);
	return (it != settings.end() && it->second.registered) ? it->second.default_value : Variant();
}

std::vector<String> ProjectSettings::get_setting_names() const {
	std::lock_guard<std::mutex> lock(mutex);
	std::vector<String> names;
	for (const auto &kv : settings) {
		names.push_back(kv.first);
	}
	return names;
}

static bool parse_number(const String &p_text, double *r_value, bool *r_integer) {
	if (p_text.empty()) {
		return false;
	}
	char *end = nullptr;
	double v = std::strtod(p_text.c_str(), &end);
	if (end == p_text.c_str() || *end != '\0') {
		return false;
	}
	*r_value = v;
	*r_integer = p_text.find_first_of(".eEnN") == String::npos;
	return true;
}

bool ProjectSettings::parse_override(const String &p_assignment, String *r_error) {
	size_t eq = p_assignment.find('=');
	if (eq == String::npos || eq == 0) {
		if (r_error) {
			*r_error = vformat("--setting expects name=value, got \"%s\".", p_assignment.c_str());
		}
		return false;
	}
	String name = string_strip_edges(p_assignment.substr(0, eq));
	String text = string_strip_edges(p_assignment.substr(eq + 1));
	if (!_is_valid_name(name)) {
		if (r_error) {
			*r_error = vformat("\"%s\" is not a valid setting name.", name.c_str());
		}
		return false;
	}
	Variant::Type type = get_default(name).get_type();
	Variant value;
	double number = 0.0;
	bool integer = false;
	const bool numeric = parse_number(text, &number, &integer);
	if (type == Variant::BOOL) {
		if (text == "true" || text == "1") {
			value = true;
		} else if (text == "false" || text == "0") {
			value = false;
		}
	} else if (type == Variant::INT) {
		if (numeric && integer) {
			value = (long long)number;
		}
	} else if (type == Variant::FLOAT) {
		if (numeric) {
			value = number;
		}
	} else if (type == Variant::STRING || type == Variant::NIL) {
		value = (type == Variant::NIL && numeric) ? Variant(number) : Variant(text);
	}
	if (value.is_nil()) {
		if (r_error) {
			*r_error = vformat("\"%s\" is not a valid %s for setting \"%s\".", text.c_str(), Variant::get_type_name(type).c_str(), name.c_str());
		}
		return false;
	}
	if (!set_setting(name, value)) {
		if (r_error) {
			*r_error = vformat("setting \"%s\" rejected \"%s\".", name.c_str(), text.c_str());
		}
		return false;
	}
	return true;
}
