/**************************************************************************/
/*  test_variant.cpp                                                      */
/**************************************************************************/
/* Variant conversions and the text literal parser/writer.                */

#include "core/error/error_macros.h"
#include "core/io/resource.h"
#include "core/variant/variant.h"
#include "core/variant/variant_parser.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestVariant {

struct ErrorCapture {
	ErrorHandlerList handler;
	std::vector<String> messages;
	ErrorCapture() {
		handler.callback = [this](ErrorHandlerType p_type, const String &p_text) { messages.push_back(p_text); };
		add_error_handler(&handler);
		set_error_print_silenced(true);
	}
	~ErrorCapture() {
		set_error_print_silenced(false);
		remove_error_handler(&handler);
	}
};

TEST_CASE("[Variant] Types, conversions and equality") {
	CHECK(Variant().get_type() == Variant::NIL);
	CHECK(Variant(true).get_type() == Variant::BOOL);
	CHECK(Variant(3).get_type() == Variant::INT);
	CHECK(Variant((int64_t)1 << 40).to_int() == ((int64_t)1 << 40));
	CHECK(Variant(2.5f).get_type() == Variant::FLOAT);
	CHECK(Variant("abc").get_type() == Variant::STRING);
	CHECK(Variant(Vector2(1, 2)).get_type() == Variant::VECTOR2);
	CHECK(Variant(Vector3(1, 2, 3)).get_type() == Variant::VECTOR3);
	CHECK(Variant(Color(1, 0, 0)).get_type() == Variant::COLOR);
	CHECK(Variant(Transform3D()).get_type() == Variant::TRANSFORM3D);
	CHECK(Variant::get_type_name(Variant::TRANSFORM3D) == "Transform3D");
	CHECK(Variant::get_type_name(Variant::FLOAT) == "float");

	// int <-> float convert.
	CHECK(Variant(3).to_float() == 3.0);
	CHECK(Variant(3.9).to_int() == 3);
	float f = Variant(7);
	CHECK(f == 7.0f);
	CHECK(Variant(3) == Variant(3.0));
	CHECK(Variant(3) != Variant(3.5));
	CHECK(Variant("a") != Variant(1));
	CHECK(Variant(Vector3(1, 2, 3)) == Variant(Vector3(1, 2, 3)));
	CHECK(Variant(Vector3(1, 2, 3)) != Variant(Vector3(1, 2, 4)));
	CHECK(Variant() == Variant());

	CHECK(Variant(2.5).stringify() == "2.5");
	CHECK(Variant(Vector3(1, 0.5, -2)).stringify() == "(1, 0.5, -2)");
	CHECK(Variant(false).stringify() == "false");

	SUBCASE("Incompatible conversions print an error and give a neutral value") {
		ErrorCapture capture;
		CHECK(Variant("text").to_float() == 0.0);
		Vector3 v = Variant(5);
		CHECK(v == Vector3());
		REQUIRE(capture.messages.size() == 2);
		CHECK(capture.messages[0].find("String") != String::npos);
		CHECK(capture.messages[0].find("float") != String::npos);
		CHECK(capture.messages[1].find("Vector3") != String::npos);
	}

	SUBCASE("Objects are reference counted through Variant") {
		Ref<Resource> res;
		res.instantiate();
		CHECK(res->get_reference_count() == 1);
		{
			Variant v = res;
			CHECK(v.get_type() == Variant::OBJECT);
			CHECK(res->get_reference_count() == 2);
			Variant w = v;
			CHECK(res->get_reference_count() == 3);
			CHECK(w == v);
			Ref<Resource> back = w;
			CHECK(back == res);
		}
		CHECK(res->get_reference_count() == 1);
		CHECK(Variant((const Object *)nullptr).get_type() == Variant::NIL);
	}
}

static Variant parse_ok(const String &p_text) {
	Variant v;
	String err;
	bool ok = VariantParser::parse_string(p_text, v, &err);
	CHECK_MESSAGE(ok, ("parse failed: " + p_text + " -> " + err).c_str());
	return v;
}

TEST_CASE("[Variant] Parser reads each literal") {
	CHECK(parse_ok("null").get_type() == Variant::NIL);
	CHECK(parse_ok("true") == Variant(true));
	CHECK(parse_ok("false") == Variant(false));
	Variant i = parse_ok("-42");
	CHECK(i.get_type() == Variant::INT);
	CHECK(i.to_int() == -42);
	Variant fl = parse_ok("1.5");
	CHECK(fl.get_type() == Variant::FLOAT);
	CHECK(fl.to_float() == 1.5);
	CHECK(parse_ok("1e-05").to_float() == 1e-05);
	CHECK(parse_ok("2.0").get_type() == Variant::FLOAT);
	CHECK(parse_ok("0x1F").to_int() == 31);
	CHECK(std::isinf(parse_ok("inf").to_float()));
	CHECK(parse_ok("inf_neg").to_float() < 0);
	CHECK(std::isnan(parse_ok("nan").to_float()));
	CHECK(parse_ok("\"a\\\"b\\n\\\\c\"").to_string() == "a\"b\n\\c");
	CHECK(parse_ok("\"\\u00e9\"").to_string() == "\xc3\xa9");
	CHECK(parse_ok("&\"name\"").to_string() == "name");
	CHECK(parse_ok("Vector2(1, -2.5)") == Variant(Vector2(1, -2.5)));
	CHECK(parse_ok("Vector3( 0, 1 , 0 )") == Variant(Vector3(0, 1, 0)));
	CHECK(parse_ok("Color(1, 0.5, 0)") == Variant(Color(1, 0.5, 0, 1)));
	CHECK(parse_ok("Color(1, 0.5, 0, 0.25)") == Variant(Color(1, 0.5, 0, 0.25)));

	// Rows, row-major: a 90 degree turn about Y has rows (0,0,1), (0,1,0), (-1,0,0),
	// i.e. local X (column 0) points along -Z.
	Transform3D t = parse_ok("Transform3D(0, 0, 1, 0, 1, 0, -1, 0, 0, 1, 2, 3)");
	CHECK(t.basis.rows[0] == Vector3(0, 0, 1));
	CHECK(t.basis.rows[2] == Vector3(-1, 0, 0));
	CHECK(t.basis.get_column(0) == Vector3(0, 0, -1));
	CHECK(t.origin == Vector3(1, 2, 3));

	SUBCASE("SubResource/ExtResource go through the resolver") {
		String seen;
		VariantParser::ResourceFunc res = [&](const String &p_kind, const String &p_id, Variant &r_value, String &r_error) {
			seen = p_kind + ":" + p_id;
			r_value = Variant(17);
			return true;
		};
		Variant v;
		CHECK(VariantParser::parse_string("SubResource(\"Mat_abc\")", v, nullptr, res));
		CHECK(seen == "SubResource:Mat_abc");
		CHECK(v == Variant(17));
		CHECK(VariantParser::parse_string("ExtResource(\"1_x\")", v, nullptr, res));
		CHECK(seen == "ExtResource:1_x");
		String err;
		CHECK_FALSE(VariantParser::parse_string("ExtResource(\"1_x\")", v, &err));
		CHECK(err.find("not allowed") != String::npos);
	}

	SUBCASE("Unsupported Godot types parse as NIL and are flagged") {
		VariantParser::Stream s("[1, 2, [3]] Quaternion(0, 0, 0, 1) {\"a\": 1} Array[int]([1])");
		for (const char *expected : { "Array", "Quaternion", "Dictionary", "Array" }) {
			Variant v = 5;
			String err, unsupported;
			REQUIRE(VariantParser::parse_value(s, v, err, nullptr, &unsupported));
			CHECK(v.get_type() == Variant::NIL);
			CHECK(unsupported == expected);
		}
	}
}

TEST_CASE("[Variant] Writer output reads back identically") {
	std::vector<Variant> values = { Variant(), Variant(true), Variant(-7), Variant(0.1), Variant(2.0), Variant(1e-30), Variant(123456789.125),
		Variant(30.0), Variant(4096.0), Variant(1e20), Variant(-123456.0), Variant(std::nan("")), Variant(INFINITY), Variant(-INFINITY), Variant("quote \" backslash \\ newline\n end"),
		Variant(Vector2(0.25, -3)), Variant(Vector3(0.1f, 1.0f / 3.0f, 1e10f)), Variant(Color(0.2f, 0.4f, 0.6f, 0.8f)),
		Variant(Transform3D(Basis::from_euler(Vector3(0.3f, 1.1f, -0.4f)), Vector3(1.5f, -2, 0.001f))) };
	for (const Variant &v : values) {
		String text = VariantWriter::write_to_string(v);
		Variant back;
		String err;
		REQUIRE_MESSAGE(VariantParser::parse_string(text, back, &err), (text + " -> " + err).c_str());
		CHECK_MESSAGE(back.get_type() == v.get_type(), text.c_str());
		CHECK_MESSAGE(back == v, text.c_str());
		CHECK(VariantWriter::write_to_string(back) == text);
	}
	CHECK(VariantWriter::write_to_string(Variant(2.0)) == "2.0");
	CHECK(VariantWriter::write_to_string(Variant(1.5f)) == "1.5");
	CHECK(VariantWriter::write_to_string(Variant(0.1f)) == "0.1"); // Single-precision values stay short.
	CHECK(VariantWriter::write_to_string(Variant(Vector3(0, 1, 0))) == "Vector3(0, 1, 0)");
	CHECK(VariantWriter::write_to_string(Variant(Color(1, 1, 1))) == "Color(1, 1, 1, 1)");
	CHECK(VariantWriter::write_to_string(Variant(Transform3D())) == "Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0)");
	CHECK(VariantWriter::write_to_string(Variant(INFINITY)) == "inf");
	CHECK(VariantWriter::write_to_string(Variant(30.0)) == "30.0");
	CHECK(VariantWriter::write_to_string(Variant(Vector3(100, 2500, -40))) == "Vector3(100, 2500, -40)");
	CHECK(VariantWriter::write_to_string(Variant(1e20)) == "1e+20");
	CHECK(VariantWriter::write_to_string(Variant(0.0001)) == "0.0001");
}

static String parse_error(const String &p_text) {
	Variant v;
	String err;
	CHECK_FALSE_MESSAGE(VariantParser::parse_string(p_text, v, &err), p_text.c_str());
	return err;
}

TEST_CASE("[Variant] Parser errors carry line numbers") {
	CHECK(parse_error("\"never closed").find("line 1: Unterminated string") == 0);
	CHECK(parse_error("\n\n\"opens on line 3\n\n").find("line 3: Unterminated string") == 0);
	CHECK(parse_error("\n1.2.3").find("line 2: Invalid number literal '1.2.3'") == 0);
	CHECK(parse_error("Vector3(1, 2)").find("takes 3 numbers") != String::npos);
	CHECK(parse_error("Color(1, 2, 3, 4, 5)").find("3 or 4") != String::npos);
	CHECK(parse_error("Transform3D(1, 0, 0)").find("12 numbers") != String::npos);
	CHECK(parse_error("\n\nVector3(1,\n 2,\n \"x\")").find("line 5: Expected a number") == 0);
	CHECK(parse_error("Vector3(1, 2, 3").find("line 1:") == 0);
	CHECK(parse_error("Banana(1)").find("Unknown value type 'Banana'") != String::npos);
	CHECK(parse_error("maybe").find("Unexpected identifier 'maybe'") != String::npos);
	CHECK(parse_error("\"bad \\q escape\"").find("Invalid escape") != String::npos);
	CHECK(parse_error("[1, 2").find("Unterminated") != String::npos);
	CHECK(parse_error("1 2").find("Unexpected text") != String::npos);
	CHECK(parse_error("").find("end of file") != String::npos);
}

TEST_CASE("[Variant] Tags and assignments") {
	VariantParser::Stream s("; comment\n[node name=\"Sun\" type=\"DirectionalLight3D\" parent=\".\"]\nlight_energy = 2.0\nsurface_material_override/0 = null\n\n");
	VariantParser::Tag tag;
	String assign, err;
	Variant value;
	bool eof = false;
	REQUIRE(VariantParser::parse_tag_assign_eof(s, tag, assign, value, err, nullptr, &eof));
	CHECK(tag.name == "node");
	CHECK(tag.line == 2);
	CHECK(tag.get("type") == Variant("DirectionalLight3D"));
	CHECK(tag.get("parent") == Variant("."));
	CHECK_FALSE(tag.has("instance"));
	REQUIRE(VariantParser::parse_tag_assign_eof(s, tag, assign, value, err, nullptr, &eof));
	CHECK(assign == "light_energy");
	CHECK(value == Variant(2.0));
	REQUIRE(VariantParser::parse_tag_assign_eof(s, tag, assign, value, err, nullptr, &eof));
	CHECK(assign == "surface_material_override/0");
	REQUIRE(VariantParser::parse_tag_assign_eof(s, tag, assign, value, err, nullptr, &eof));
	CHECK(eof);

	VariantParser::Stream bad("[node name=\"A\"\nlight_energy = 1\n");
	CHECK_FALSE(VariantParser::parse_tag_assign_eof(bad, tag, assign, value, err, nullptr, &eof));
	CHECK(bad.line == 1);
	CHECK(err.find("Missing ']'") != String::npos);

	VariantParser::Stream noeq("\n\nlight_energy 1\n");
	CHECK_FALSE(VariantParser::parse_tag_assign_eof(noeq, tag, assign, value, err, nullptr, &eof));
	CHECK(noeq.line == 3);
}

} // namespace TestVariant
