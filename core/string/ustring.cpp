/**************************************************************************/
/*  ustring.cpp                                                           */
/**************************************************************************/

#include "core/string/ustring.h"

#include <cstdio>

String vformat(const char *p_format, ...) {
	va_list args;
	va_start(args, p_format);
	va_list copy;
	va_copy(copy, args);
	int size = vsnprintf(nullptr, 0, p_format, copy);
	va_end(copy);
	String result;
	if (size > 0) {
		result.resize(size + 1);
		vsnprintf(&result[0], size + 1, p_format, args);
		result.resize(size);
	}
	va_end(args);
	return result;
}

String itos(long long p_value) {
	return std::to_string(p_value);
}

String rtos(double p_value) {
	char buf[64];
	snprintf(buf, sizeof(buf), "%.9g", p_value);
	return String(buf);
}

std::vector<String> string_split(const String &p_string, char p_delimiter, bool p_allow_empty) {
	std::vector<String> out;
	size_t start = 0;
	while (true) {
		size_t pos = p_string.find(p_delimiter, start);
		String piece = p_string.substr(start, pos == String::npos ? String::npos : pos - start);
		if (p_allow_empty || !piece.empty()) {
			out.push_back(piece);
		}
		if (pos == String::npos) {
			break;
		}
		start = pos + 1;
	}
	return out;
}

String string_strip_edges(const String &p_string) {
	size_t b = 0;
	size_t e = p_string.size();
	while (b < e && (unsigned char)p_string[b] <= 32) {
		b++;
	}
	while (e > b && (unsigned char)p_string[e - 1] <= 32) {
		e--;
	}
	return p_string.substr(b, e - b);
}

bool string_begins_with(const String &p_string, const String &p_prefix) {
	return p_string.size() >= p_prefix.size() && p_string.compare(0, p_prefix.size(), p_prefix) == 0;
}

bool string_ends_with(const String &p_string, const String &p_suffix) {
	return p_string.size() >= p_suffix.size() && p_string.compare(p_string.size() - p_suffix.size(), p_suffix.size(), p_suffix) == 0;
}
