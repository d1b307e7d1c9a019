/**************************************************************************/
/*  variant_parser.cpp                                                    */
/**************************************************************************/

#include "core/variant/variant_parser.h"

#include "core/object/object.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace {

enum TokenType {
	TK_BRACKET_OPEN,
	TK_BRACKET_CLOSE,
	TK_CURLY_OPEN,
	TK_CURLY_CLOSE,
	TK_PAREN_OPEN,
	TK_PAREN_CLOSE,
	TK_COLON,
	TK_COMMA,
	TK_EQUAL,
	TK_IDENTIFIER,
	TK_STRING,
	TK_STRING_NAME,
	TK_NODE_PATH,
	TK_NUMBER,
	TK_EOF,
};

const char *token_names[] = { "'['", "']'", "'{'", "'}'", "'('", "')'", "':'", "','", "'='", "identifier", "string", "StringName", "NodePath", "number", "end of file" };

struct Token {
	TokenType type = TK_EOF;
	String str;
	Variant value;
	int line = 1;
};

bool _is_ident_start(int c) {
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

bool _is_ident_char(int c) {
	return _is_ident_start(c) || (c >= '0' && c <= '9');
}

void _skip_space(VariantParser::Stream &s) {
	while (!s.is_eof()) {
		char c = s.text[s.pos];
		if (c == '\n') {
			s.line++;
			s.pos++;
		} else if (c == ';') { // Comment to end of line.
			while (!s.is_eof() && s.text[s.pos] != '\n') {
				s.pos++;
			}
		} else if ((unsigned char)c <= 32) {
			s.pos++;
		} else {
			return;
		}
	}
}

void _append_utf8(String &r_str, uint32_t p_cp) {
	if (p_cp < 0x80) {
		r_str += (char)p_cp;
	} else if (p_cp < 0x800) {
		r_str += (char)(0xC0 | (p_cp >> 6));
		r_str += (char)(0x80 | (p_cp & 0x3F));
	} else if (p_cp < 0x10000) {
		r_str += (char)(0xE0 | (p_cp >> 12));
		r_str += (char)(0x80 | ((p_cp >> 6) & 0x3F));
		r_str += (char)(0x80 | (p_cp & 0x3F));
	} else {
		r_str += (char)(0xF0 | (p_cp >> 18));
		r_str += (char)(0x80 | ((p_cp >> 12) & 0x3F));
		r_str += (char)(0x80 | ((p_cp >> 6) & 0x3F));
		r_str += (char)(0x80 | (p_cp & 0x3F));
	}
}

// After the opening quote.
bool _lex_string(VariantParser::Stream &s, String &r_str, String &r_err) {
	int start_line = s.line;
	r_str.clear();
	while (true) {
		if (s.is_eof()) {
			s.line = start_line;
			r_err = "Unterminated string (missing closing '\"').";
			return false;
		}
		char c = s.text[s.pos++];
		if (c == '"') {
			return true;
		}
		if (c == '\n') {
			s.line++;
		}
		if (c != '\\') {
			r_str += c;
			continue;
		}
		if (s.is_eof()) {
			continue; // Reported as unterminated on the next turn.
		}
		char e = s.text[s.pos++];
		switch (e) {
			case 'n':
				r_str += '\n';
				break;
			case 't':
				r_str += '\t';
				break;
			case 'r':
				r_str += '\r';
				break;
			case 'b':
				r_str += '\b';
				break;
			case 'f':
				r_str += '\f';
				break;
			case 'a':
				r_str += '\a';
				break;
			case 'v':
				r_str += '\v';
				break;
			case '"':
			case '\\':
			case '\'':
				r_str += e;
				break;
			case 'u':
			case 'U': {
				int digits = e == 'u' ? 4 : 6;
				uint32_t cp = 0;
				for (int i = 0; i < digits; i++) {
					if (s.is_eof() || !isxdigit((unsigned char)s.text[s.pos])) {
						r_err = "Invalid unicode escape sequence in string.";
						return false;
					}
					char h = s.text[s.pos++];
					cp = cp * 16 + (uint32_t)(isdigit((unsigned char)h) ? h - '0' : (tolower(h) - 'a' + 10));
				}
				_append_utf8(r_str, cp);
			} break;
			default:
				r_err = vformat("Invalid escape sequence '\\%c' in string.", e);
				return false;
		}
	}
}

bool _lex_number(VariantParser::Stream &s, Token &r_tk, String &r_err) {
	size_t begin = s.pos;
	if (s.text[s.pos] == '-' || s.text[s.pos] == '+') {
		s.pos++;
	}
	// One pass, constant work per character: an 'x' seen so far makes 'e' a hex digit, not an exponent.
	bool hex = false;
	while (!s.is_eof()) {
		char c = s.text[s.pos];
		char prev = s.pos > begin ? s.text[s.pos - 1] : 0;
		if (_is_ident_char(c) || c == '.' || ((c == '+' || c == '-') && !hex && (prev == 'e' || prev == 'E'))) {
			hex = hex || c == 'x' || c == 'X';
			s.pos++;
		} else {
			break;
		}
	}
	String num = s.text.substr(begin, s.pos - begin);
	r_tk.type = TK_NUMBER;
	r_tk.str = num;
	const char *cstr = num.c_str();
	char *end = nullptr;
	errno = 0;
	bool is_hex = num.find_first_of("xX") != String::npos;
	bool is_float = !is_hex && num.find_first_of(".eE") != String::npos;
	if (is_float) {
		double d = strtod(cstr, &end);
		if (end && *end == 0 && end != cstr) {
			r_tk.value = d;
			return true;
		}
	} else {
		long long v = strtoll(cstr, &end, is_hex ? 16 : 10);
		if (end && *end == 0 && end != cstr && errno != ERANGE) {
			r_tk.value = (int64_t)v;
			return true;
		}
	}
	r_err = vformat("Invalid number literal '%s'.", num.c_str());
	return false;
}

bool _get_token(VariantParser::Stream &s, Token &r_tk, String &r_err) {
	_skip_space(s);
	r_tk = Token();
	r_tk.line = s.line;
	if (s.is_eof()) {
		r_tk.type = TK_EOF;
		return true;
	}
	char c = s.text[s.pos];
	switch (c) {
		case '[':
			s.pos++;
			r_tk.type = TK_BRACKET_OPEN;
			return true;
		case ']':
			s.pos++;
			r_tk.type = TK_BRACKET_CLOSE;
			return true;
		case '{':
			s.pos++;
			r_tk.type = TK_CURLY_OPEN;
			return true;
		case '}':
			s.pos++;
			r_tk.type = TK_CURLY_CLOSE;
			return true;
		case '(':
			s.pos++;
			r_tk.type = TK_PAREN_OPEN;
			return true;
		case ')':
			s.pos++;
			r_tk.type = TK_PAREN_CLOSE;
			return true;
		case ':':
			s.pos++;
			r_tk.type = TK_COLON;
			return true;
		case ',':
			s.pos++;
			r_tk.type = TK_COMMA;
			return true;
		case '=':
			s.pos++;
			r_tk.type = TK_EQUAL;
			return true;
		case '"':
			s.pos++;
			r_tk.type = TK_STRING;
			return _lex_string(s, r_tk.str, r_err);
		case '&':
		case '^':
			if (s.pos + 1 < s.text.size() && s.text[s.pos + 1] == '"') {
				s.pos += 2;
				r_tk.type = c == '&' ? TK_STRING_NAME : TK_NODE_PATH;
				return _lex_string(s, r_tk.str, r_err);
			}
			break;
		default:
			break;
	}
	if ((c >= '0' && c <= '9') || ((c == '-' || c == '+' || c == '.') && s.pos + 1 < s.text.size() && (isdigit((unsigned char)s.text[s.pos + 1]) || s.text[s.pos + 1] == '.'))) {
		return _lex_number(s, r_tk, r_err);
	}
	if (_is_ident_start(c)) {
		size_t begin = s.pos;
		while (!s.is_eof() && _is_ident_char(s.text[s.pos])) {
			s.pos++;
		}
		r_tk.type = TK_IDENTIFIER;
		r_tk.str = s.text.substr(begin, s.pos - begin);
		return true;
	}
	r_err = vformat("Unexpected character '%c'.", c);
	return false;
}

bool _expect(VariantParser::Stream &s, TokenType p_type, const char *p_context, String &r_err) {
	Token tk;
	if (!_get_token(s, tk, r_err)) {
		return false;
	}
	if (tk.type != p_type) {
		s.line = tk.line;
		r_err = vformat("Expected %s %s, got %s.", token_names[p_type], p_context, tk.type == TK_IDENTIFIER || tk.type == TK_NUMBER ? ("'" + tk.str + "'").c_str() : token_names[tk.type]);
		return false;
	}
	return true;
}

// Skips a balanced (), [] or {} group whose opening token was just read.
bool _skip_group(VariantParser::Stream &s, TokenType p_open, String &r_err) {
	std::vector<TokenType> stack = { p_open };
	int start_line = s.line;
	while (!stack.empty()) {
		Token tk;
		if (!_get_token(s, tk, r_err)) {
			return false;
		}
		switch (tk.type) {
			case TK_PAREN_OPEN:
			case TK_BRACKET_OPEN:
			case TK_CURLY_OPEN:
				stack.push_back(tk.type);
				break;
			case TK_PAREN_CLOSE:
			case TK_BRACKET_CLOSE:
			case TK_CURLY_CLOSE: {
				TokenType open = tk.type == TK_PAREN_CLOSE ? TK_PAREN_OPEN : (tk.type == TK_BRACKET_CLOSE ? TK_BRACKET_OPEN : TK_CURLY_OPEN);
				if (stack.back() != open) {
					s.line = tk.line;
					r_err = vformat("Mismatched %s.", token_names[tk.type]);
					return false;
				}
				stack.pop_back();
			} break;
			case TK_EOF:
				s.line = start_line;
				r_err = vformat("Unterminated %s group.", token_names[stack.back()]);
				return false;
			default:
				break;
		}
	}
	return true;
}

bool _is_skipped_type(const String &p_name) {
	static const char *names[] = { "Vector2i", "Vector3i", "Vector4", "Vector4i", "Rect2", "Rect2i", "Transform2D", "Plane", "Quaternion", "Quat",
		"AABB", "Basis", "Projection", "NodePath", "StringName", "RID", "Object", "Callable", "Signal", "Dictionary", "Array",
		"PackedByteArray", "PackedInt32Array", "PackedInt64Array", "PackedFloat32Array", "PackedFloat64Array", "PackedStringArray",
		"PackedVector2Array", "PackedVector3Array", "PackedColorArray", "PackedVector4Array", "Resource", nullptr };
	for (int i = 0; names[i]; i++) {
		if (p_name == names[i]) {
			return true;
		}
	}
	return false;
}

bool _parse_value_tk(VariantParser::Stream &s, Token &tk, Variant &r_value, String &r_err, const VariantParser::ResourceFunc &p_res, String *r_unsupported);

// Reads "(n, n, ...)" of numbers (after the type identifier).
bool _parse_numbers(VariantParser::Stream &s, const String &p_type, std::vector<double> &r_args, String &r_err) {
	if (!_expect(s, TK_PAREN_OPEN, ("after '" + p_type + "'").c_str(), r_err)) {
		return false;
	}
	int start_line = s.line;
	r_args.clear();
	while (true) {
		Token tk;
		if (!_get_token(s, tk, r_err)) {
			return false;
		}
		if (tk.type == TK_PAREN_CLOSE && r_args.empty()) {
			return true;
		}
		double v = 0;
		if (tk.type == TK_NUMBER) {
			v = tk.value.to_float();
		} else if (tk.type == TK_IDENTIFIER && (tk.str == "inf" || tk.str == "inf_neg" || tk.str == "nan")) {
			v = tk.str == "nan" ? std::numeric_limits<double>::quiet_NaN() : (tk.str == "inf" ? INFINITY : -INFINITY);
		} else {
			s.line = tk.line == start_line || tk.type != TK_EOF ? tk.line : start_line;
			r_err = vformat("Expected a number in %s(...), got %s.", p_type.c_str(), tk.type == TK_IDENTIFIER || tk.type == TK_NUMBER ? ("'" + tk.str + "'").c_str() : token_names[tk.type]);
			return false;
		}
		r_args.push_back(v);
		if (!_get_token(s, tk, r_err)) {
			return false;
		}
		if (tk.type == TK_PAREN_CLOSE) {
			return true;
		}
		if (tk.type != TK_COMMA) {
			s.line = tk.type == TK_EOF ? start_line : tk.line;
			r_err = vformat("Expected ',' or ')' in %s(...), got %s.", p_type.c_str(), token_names[tk.type]);
			return false;
		}
	}
}

bool _parse_constructor(VariantParser::Stream &s, const Token &p_ident, Variant &r_value, String &r_err, const VariantParser::ResourceFunc &p_res, String *r_unsupported) {
	const String &id = p_ident.str;
	if (id == "SubResource" || id == "ExtResource") {
		if (!_expect(s, TK_PAREN_OPEN, ("after '" + id + "'").c_str(), r_err)) {
			return false;
		}
		Token tk;
		if (!_get_token(s, tk, r_err)) {
			return false;
		}
		String res_id;
		if (tk.type == TK_STRING) {
			res_id = tk.str;
		} else if (tk.type == TK_NUMBER && tk.value.get_type() == Variant::INT) { // Format 2 used bare numbers.
			res_id = tk.str;
		} else {
			s.line = tk.line;
			r_err = vformat("Expected a string id in %s(...).", id.c_str());
			return false;
		}
		if (!_expect(s, TK_PAREN_CLOSE, ("after the id in " + id + "(...)").c_str(), r_err)) {
			return false;
		}
		if (!p_res) {
			s.line = p_ident.line;
			r_err = vformat("%s(\"%s\") is not allowed here.", id.c_str(), res_id.c_str());
			return false;
		}
		if (!p_res(id, res_id, r_value, r_err)) {
			s.line = p_ident.line;
			return false;
		}
		return true;
	}

	std::vector<double> a;
	if (id == "Vector2") {
		if (!_parse_numbers(s, id, a, r_err)) {
			return false;
		}
		if (a.size() != 2) {
			s.line = p_ident.line;
			r_err = vformat("Vector2(...) takes 2 numbers, got %d.", (int)a.size());
			return false;
		}
		r_value = Vector2(a[0], a[1]);
		return true;
	}
	if (id == "Vector3") {
		if (!_parse_numbers(s, id, a, r_err)) {
			return false;
		}
		if (a.size() != 3) {
			s.line = p_ident.line;
			r_err = vformat("Vector3(...) takes 3 numbers, got %d.", (int)a.size());
			return false;
		}
		r_value = Vector3(a[0], a[1], a[2]);
		return true;
	}
	if (id == "Color") {
		if (!_parse_numbers(s, id, a, r_err)) {
			return false;
		}
		if (a.size() != 3 && a.size() != 4) {
			s.line = p_ident.line;
			r_err = vformat("Color(...) takes 3 or 4 numbers, got %d.", (int)a.size());
			return false;
		}
		r_value = Color(a[0], a[1], a[2], a.size() == 4 ? a[3] : 1.0);
		return true;
	}
	if (id == "Transform3D" || id == "Transform") {
		if (!_parse_numbers(s, id, a, r_err)) {
			return false;
		}
		if (a.size() != 12) {
			s.line = p_ident.line;
			r_err = vformat("%s(...) takes 12 numbers, got %d.", id.c_str(), (int)a.size());
			return false;
		}
		Transform3D t;
		for (int i = 0; i < 3; i++) {
			t.basis.rows[i] = Vector3(a[i * 3 + 0], a[i * 3 + 1], a[i * 3 + 2]);
		}
		t.origin = Vector3(a[9], a[10], a[11]);
		r_value = t;
		return true;
	}
	if (_is_skipped_type(id)) {
		Token tk;
		if (!_get_token(s, tk, r_err)) {
			return false;
		}
		if (tk.type == TK_BRACKET_OPEN) { // Typed container: Array[int]([...]).
			if (!_skip_group(s, TK_BRACKET_OPEN, r_err) || !_get_token(s, tk, r_err)) {
				return false;
			}
		}
		if (tk.type != TK_PAREN_OPEN) {
			s.line = tk.line;
			r_err = vformat("Expected '(' after '%s'.", id.c_str());
			return false;
		}
		if (!_skip_group(s, TK_PAREN_OPEN, r_err)) {
			return false;
		}
		if (r_unsupported) {
			*r_unsupported = id;
		}
		r_value = Variant();
		return true;
	}
	s.line = p_ident.line;
	r_err = vformat("Unknown value type '%s'.", id.c_str());
	return false;
}

bool _parse_value_tk(VariantParser::Stream &s, Token &tk, Variant &r_value, String &r_err, const VariantParser::ResourceFunc &p_res, String *r_unsupported) {
	switch (tk.type) {
		case TK_NUMBER:
			r_value = tk.value;
			return true;
		case TK_STRING:
		case TK_STRING_NAME:
			r_value = tk.str;
			return true;
		case TK_NODE_PATH:
			if (r_unsupported) {
				*r_unsupported = "NodePath";
			}
			r_value = Variant();
			return true;
		case TK_BRACKET_OPEN:
		case TK_CURLY_OPEN:
			if (!_skip_group(s, tk.type, r_err)) {
				return false;
			}
			if (r_unsupported) {
				*r_unsupported = tk.type == TK_BRACKET_OPEN ? "Array" : "Dictionary";
			}
			r_value = Variant();
			return true;
		case TK_IDENTIFIER: {
			const String &id = tk.str;
			if (id == "true" || id == "false") {
				r_value = id == "true";
				return true;
			}
			if (id == "null" || id == "nil") {
				r_value = Variant();
				return true;
			}
			if (id == "inf" || id == "inf_neg") {
				r_value = id == "inf" ? (double)INFINITY : (double)-INFINITY;
				return true;
			}
			if (id == "nan") {
				r_value = std::numeric_limits<double>::quiet_NaN();
				return true;
			}
			// A constructor must be followed by '('.
			size_t save_pos = s.pos;
			int save_line = s.line;
			_skip_space(s);
			bool has_paren = !s.is_eof() && (s.text[s.pos] == '(' || s.text[s.pos] == '[');
			s.pos = save_pos;
			s.line = save_line;
			if (!has_paren) {
				s.line = tk.line;
				r_err = vformat("Unexpected identifier '%s' (not a value).", id.c_str());
				return false;
			}
			return _parse_constructor(s, tk, r_value, r_err, p_res, r_unsupported);
		}
		case TK_EOF:
			r_err = "Expected a value, got end of file.";
			return false;
		default:
			s.line = tk.line;
			r_err = vformat("Expected a value, got %s.", token_names[tk.type]);
			return false;
	}
}

// True when only blanks or a comment remain on the current line.
bool _rest_of_line_empty(VariantParser::Stream &s) {
	size_t p = s.pos;
	while (p < s.text.size() && s.text[p] != '\n') {
		char c = s.text[p];
		if (c == ';') {
			return true;
		}
		if ((unsigned char)c > 32) {
			return false;
		}
		p++;
	}
	return true;
}

} // namespace

bool VariantParser::Tag::has(const String &p_key) const {
	for (const auto &F : fields) {
		if (F.first == p_key) {
			return true;
		}
	}
	return false;
}

Variant VariantParser::Tag::get(const String &p_key, const Variant &p_default) const {
	for (const auto &F : fields) {
		if (F.first == p_key) {
			return F.second;
		}
	}
	return p_default;
}

bool VariantParser::parse_value(Stream &p_stream, Variant &r_value, String &r_error, const ResourceFunc &p_res, String *r_unsupported) {
	Token tk;
	if (!_get_token(p_stream, tk, r_error)) {
		return false;
	}
	return _parse_value_tk(p_stream, tk, r_value, r_error, p_res, r_unsupported);
}

bool VariantParser::parse_tag(Stream &p_stream, Tag &r_tag, String &r_error, const ResourceFunc &p_res) {
	r_tag = Tag();
	Stream &s = p_stream;
	if (!_expect(s, TK_BRACKET_OPEN, "to open a tag", r_error)) {
		return false;
	}
	int tag_line = s.line;
	r_tag.line = tag_line;
	Token tk;
	if (!_get_token(s, tk, r_error)) {
		return false;
	}
	if (tk.type != TK_IDENTIFIER || tk.line != tag_line) {
		s.line = tag_line;
		r_error = "Expected a tag name after '['.";
		return false;
	}
	r_tag.name = tk.str;
	while (true) {
		if (!_get_token(s, tk, r_error)) {
			return false;
		}
		if (tk.type == TK_BRACKET_CLOSE && tk.line == tag_line) {
			break;
		}
		if (tk.line != tag_line || tk.type == TK_EOF) {
			s.line = tag_line;
			r_error = vformat("Missing ']' at the end of the [%s] header.", r_tag.name.c_str());
			return false;
		}
		if (tk.type != TK_IDENTIFIER) {
			s.line = tk.line;
			r_error = vformat("Expected a field name or ']' in the [%s] header, got %s.", r_tag.name.c_str(), token_names[tk.type]);
			return false;
		}
		String key = tk.str;
		if (!_expect(s, TK_EQUAL, ("after '" + key + "' in the [" + r_tag.name + "] header").c_str(), r_error)) {
			return false;
		}
		Variant value;
		String unsupported;
		if (!parse_value(s, value, r_error, p_res, &unsupported)) {
			return false;
		}
		if (!unsupported.empty()) {
			r_tag.unsupported_fields.push_back(key);
		}
		r_tag.fields.push_back(std::make_pair(key, value));
	}
	return true;
}

bool VariantParser::parse_tag_assign_eof(Stream &p_stream, Tag &r_tag, String &r_assign, Variant &r_value, String &r_error, const ResourceFunc &p_res, bool *r_eof, String *r_unsupported) {
	Stream &s = p_stream;
	r_assign.clear();
	r_tag = Tag();
	r_value = Variant();
	if (r_eof) {
		*r_eof = false;
	}
	_skip_space(s);
	if (s.is_eof()) {
		if (r_eof) {
			*r_eof = true;
		}
		return true;
	}
	if (s.text[s.pos] == '[') {
		return parse_tag(s, r_tag, r_error, p_res);
	}
	int key_line = s.line;
	String key;
	if (s.text[s.pos] == '"') {
		s.pos++;
		if (!_lex_string(s, key, r_error)) {
			return false;
		}
		_skip_space(s);
		if (s.line != key_line || s.is_eof() || s.text[s.pos] != '=') {
			s.line = key_line;
			r_error = vformat("Expected '=' after property name \"%s\".", key.c_str());
			return false;
		}
		s.pos++;
	} else {
		while (true) {
			if (s.is_eof() || s.text[s.pos] == '\n') {
				s.line = key_line;
				r_error = vformat("Expected 'name = value', got '%s'.", string_strip_edges(key).c_str());
				return false;
			}
			char c = s.text[s.pos++];
			if (c == '=') {
				break;
			}
			key += c;
		}
		key = string_strip_edges(key);
		if (key.empty() || key.find_first_of(" \t\"[]()") != String::npos) {
			s.line = key_line;
			r_error = vformat("Invalid property name '%s'.", key.c_str());
			return false;
		}
	}
	_skip_space(s);
	int value_line = s.line;
	if (!parse_value(s, r_value, r_error, p_res, r_unsupported)) {
		return false;
	}
	if (!_rest_of_line_empty(s)) {
		if (r_value.get_type() == Variant::STRING && s.line > value_line) {
			// A multi-line string followed by junk: almost always a missing closing quote.
			r_error = vformat("Unterminated string: the string of '%s' that starts here runs on to line %d.", key.c_str(), s.line);
			s.line = value_line;
			return false;
		}
		r_error = vformat("Unexpected text after the value of '%s'.", key.c_str());
		return false;
	}
	r_assign = key;
	r_tag.line = key_line;
	return true;
}

bool VariantParser::parse_string_literal(Stream &p_stream, String &r_str, String &r_error) {
	return _lex_string(p_stream, r_str, r_error);
}

bool VariantParser::parse_string(const String &p_text, Variant &r_value, String *r_error, const ResourceFunc &p_res) {
	Stream s(p_text);
	String err;
	String unsupported;
	bool ok = parse_value(s, r_value, err, p_res, &unsupported);
	if (ok) {
		_skip_space(s);
		if (!s.is_eof()) {
			ok = false;
			err = "Unexpected text after the value.";
		}
	}
	if (!ok && r_error) {
		*r_error = vformat("line %d: %s", s.line, err.c_str());
	}
	return ok;
}

// Writer.

static String _shortest(double p_value, bool p_single) {
	char buf[64];
	int prec = 1;
	double v = p_single ? (double)(float)p_value : p_value;
	for (; prec <= 17; prec++) {
		snprintf(buf, sizeof(buf), "%.*g", prec, v);
		double back = strtod(buf, nullptr);
		if (p_single ? (float)back == (float)v : back == v) {
			break;
		}
	}
	// "%g" switches to an exponent once the integer digits exceed the precision
	// ("3e+01"); write such moderate values in plain form ("30").
	if (strchr(buf, 'e')) {
		int exp10 = (int)std::floor(std::log10(std::fabs(v)));
		if (exp10 >= 0 && exp10 < 17) {
			snprintf(buf, sizeof(buf), "%.*g", std::max(prec, exp10 + 1), v);
		}
	}
	return String(buf);
}

String VariantWriter::real_to_string(double p_value) {
	if (std::isnan(p_value)) {
		return "nan";
	}
	if (std::isinf(p_value)) {
		return p_value > 0 ? "inf" : "inf_neg";
	}
	if (p_value == 0.0) {
		return "0"; // Also for -0.
	}
	bool single = (double)(float)p_value == p_value;
	return _shortest(p_value, single);
}

String VariantWriter::float_to_string(double p_value) {
	String s = real_to_string(p_value);
	if (s == "inf" || s == "inf_neg" || s == "nan") {
		return s;
	}
	if (s.find_first_of(".e") == String::npos) {
		s += ".0";
	}
	return s;
}

String VariantWriter::escape_string(const String &p_string) {
	String out = "\"";
	for (char c : p_string) {
		if (c == '"' || c == '\\') {
			out += '\\';
		}
		out += c;
	}
	return out + "\"";
}

String VariantWriter::escape_tag_string(const String &p_string) {
	String out = "\"";
	for (char c : p_string) {
		if (c == '\n') {
			out += "\\n";
		} else if (c == '\r') {
			out += "\\r";
		} else {
			if (c == '"' || c == '\\') {
				out += '\\';
			}
			out += c;
		}
	}
	return out + "\"";
}

String VariantWriter::write_to_string(const Variant &p_value, const ObjectEncoder &p_encoder) {
	switch (p_value.get_type()) {
		case Variant::NIL:
			return "null";
		case Variant::BOOL:
			return p_value.to_bool() ? "true" : "false";
		case Variant::INT:
			return itos(p_value.to_int());
		case Variant::FLOAT:
			return float_to_string(p_value.to_float());
		case Variant::STRING:
			return escape_string(p_value.to_string());
		case Variant::VECTOR2: {
			Vector2 v = p_value;
			return "Vector2(" + real_to_string(v.x) + ", " + real_to_string(v.y) + ")";
		}
		case Variant::VECTOR3: {
			Vector3 v = p_value;
			return "Vector3(" + real_to_string(v.x) + ", " + real_to_string(v.y) + ", " + real_to_string(v.z) + ")";
		}
		case Variant::COLOR: {
			Color c = p_value;
			return "Color(" + real_to_string(c.r) + ", " + real_to_string(c.g) + ", " + real_to_string(c.b) + ", " + real_to_string(c.a) + ")";
		}
		case Variant::TRANSFORM3D: {
			Transform3D t = p_value;
			String s = "Transform3D(";
			for (int i = 0; i < 3; i++) {
				const Vector3 &r = t.basis.rows[i];
				s += real_to_string(r.x) + ", " + real_to_string(r.y) + ", " + real_to_string(r.z) + ", ";
			}
			return s + real_to_string(t.origin.x) + ", " + real_to_string(t.origin.y) + ", " + real_to_string(t.origin.z) + ")";
		}
		case Variant::OBJECT: {
			Object *obj = p_value.get_object();
			if (!obj || !p_encoder) {
				return "null";
			}
			return p_encoder(obj);
		}
		case Variant::VARIANT_MAX:
			break;
	}
	return "null";
}
