/**************************************************************************/
/*  ustring.h                                                             */
/**************************************************************************/
/* godot-area: Godot's String, reduced to std::string plus a few helpers. */

#pragma once

#include <cstdarg>
#include <string>
#include <vector>

using String = std::string;

// printf-style formatting into a String (Godot's vformat uses "%s" too).
String vformat(const char *p_format, ...) __attribute__((format(printf, 1, 2)));

String itos(long long p_value);
String rtos(double p_value);

// Splits on a single-character delimiter; empty pieces are kept when p_allow_empty.
std::vector<String> string_split(const String &p_string, char p_delimiter, bool p_allow_empty = true);
String string_strip_edges(const String &p_string);
bool string_begins_with(const String &p_string, const String &p_prefix);
bool string_ends_with(const String &p_string, const String &p_suffix);
