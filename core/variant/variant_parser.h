/**************************************************************************/
/*  variant_parser.h                                                      */
/**************************************************************************/
/* Godot's text literal syntax, as used in .tscn/.tres files:             */
/*   null  true  false  42  -1.5  1e-05  inf  inf_neg  nan  "text\n"      */
/*   Vector2(x, y)  Vector3(x, y, z)  Color(r, g, b[, a])                 */
/*   Transform3D(xx, xy, xz, yx, yy, yz, zx, zy, zz, ox, oy, oz)          */
/*   SubResource("id")  ExtResource("id")                                 */
/* Transform3D's first nine numbers are the basis ROWS, row-major, i.e.   */
/* basis.rows[0].x, rows[0].y, rows[0].z, rows[1].x, ... (Godot writes    */
/* `basis.rows[i][j]` and reads them back through Basis(xx, xy, ...),     */
/* which sets rows). So the 1st, 4th and 7th numbers form basis column 0  */
/* (local X). The last three are the origin.                              */
/*                                                                        */
/* Other Godot values (arrays, dictionaries, Quaternion, NodePath,        */
/* Packed*Array...) are parsed for syntax and returned as NIL with        */
/* r_unsupported set to the type name, so a loader can warn and go on.    */

#pragma once

#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <functional>
#include <utility>
#include <vector>

class VariantParser {
public:
	// Resolves SubResource("id") / ExtResource("id"). p_kind is "SubResource" or
	// "ExtResource". Return false with r_error set to reject the reference.
	typedef std::function<bool(const String &p_kind, const String &p_id, Variant &r_value, String &r_error)> ResourceFunc;

	struct Stream {
		String text;
		size_t pos = 0;
		int line = 1; // Current line (1-based); after an error, the line of the error.

		bool is_eof() const { return pos >= text.size(); }
		Stream() {}
		explicit Stream(const String &p_text) :
				text(p_text) {}
	};

	// A bracket header: [name key=value key2=value2].
	struct Tag {
		String name;
		std::vector<std::pair<String, Variant>> fields;
		std::vector<String> unsupported_fields; // Fields whose value type we skip.
		int line = 0;

		bool has(const String &p_key) const;
		Variant get(const String &p_key, const Variant &p_default = Variant()) const;
	};

	// Parses one value at the stream position. r_error holds the message
	// (without the line; the line is in p_stream.line).
	static bool parse_value(Stream &p_stream, Variant &r_value, String &r_error, const ResourceFunc &p_res = nullptr, String *r_unsupported = nullptr);

	// Parses a "[tag ...]" header (skipping blank lines and ';' comments first).
	static bool parse_tag(Stream &p_stream, Tag &r_tag, String &r_error, const ResourceFunc &p_res = nullptr);

	// Reads the next item of a resource file: either a "[tag ...]" (r_tag.name
	// set, r_assign empty), a "key = value" line (r_assign set), or the end of
	// the text (*r_eof true). r_tag.line is the line of the tag or of the key. Keys may contain '/' and '.' ("surface_material_override/0").
	static bool parse_tag_assign_eof(Stream &p_stream, Tag &r_tag, String &r_assign, Variant &r_value, String &r_error, const ResourceFunc &p_res, bool *r_eof, String *r_unsupported = nullptr);

	// Convenience: the whole text must be one value. Errors come back as
	// "line N: message".
	static bool parse_string(const String &p_text, Variant &r_value, String *r_error = nullptr, const ResourceFunc &p_res = nullptr);
	// A quoted string's text with its escapes resolved, read from just after the opening quote.
	static bool parse_string_literal(Stream &p_stream, String &r_str, String &r_error);
};

class VariantWriter {
public:
	// Encodes OBJECT values, e.g. returns `SubResource("Mat_1")`. Without one,
	// objects are written as null.
	typedef std::function<String(const Object *p_object)> ObjectEncoder;

	// Writes p_value in the syntax VariantParser reads. Floats are written with
	// the fewest digits that read back to the same value; a FLOAT that is
	// exactly a single-precision number is written at single precision (as
	// Godot's real_t properties are), and always has a '.' or exponent.
	static String write_to_string(const Variant &p_value, const ObjectEncoder &p_encoder = nullptr);
	static String escape_string(const String &p_string); // Adds quotes.
	static String escape_tag_string(const String &p_string); // escape_string with line breaks as \n, \r: a header is one line.
	static String float_to_string(double p_value); // "1.5", "2.0", "inf", "inf_neg", "nan".
	static String real_to_string(double p_value); // Component form: "1", "0.5".
};
