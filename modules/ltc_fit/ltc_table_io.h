/**************************************************************************/
/*  ltc_table_io.h                                                        */
/**************************************************************************/
/* godot-area: reads and writes the LTC lookup tables as the C++ include  */
/* servers/rendering/renderer_rd/ltc_lut_data.inc, and exposes the tables */
/* compiled into the engine from that file. Floats are printed with       */
/* %.9g, so parsing the file back reproduces every float bit for bit.     */

#pragma once

#include "modules/ltc_fit/ltc_brdf.h"

#include "core/string/ustring.h"

#include <vector>

class LTCTableIO {
public:
	// Path of the committed include, relative to the repository root.
	static const char *DEFAULT_INC_PATH;

	// The tables compiled in from ltc_lut_data.inc (LTC_LUT_SIZE^2 * 8 floats each).
	static int get_builtin_size();
	static const float *get_builtin_table(LTCBRDFVariant p_variant);

	// Formats the complete include: header comment (p_command, p_stats and the layout), LTC_LUT_SIZE and
	// both arrays. Each table must hold p_size^2 * 8 floats.
	static String format_inc(int p_size, const std::vector<float> &p_engine, const std::vector<float> &p_smith, const String &p_command, const String &p_stats);
	// One table as a C array definition "static const float NAME[N * N * F] = { ... };" (%.9g floats, a cell
	// a line with its "// t, r" comment).
	static String format_array(const char *p_name, int p_size, int p_floats_per_cell, const std::vector<float> &p_table);
	static bool save_inc(const String &p_path, const String &p_text);

	// Parses text written by format_inc. Returns false with r_error set when something is missing or malformed.
	static bool parse_inc(const String &p_text, int *r_size, std::vector<float> *r_engine, std::vector<float> *r_smith, String *r_error);
	static bool load_inc(const String &p_path, int *r_size, std::vector<float> *r_engine, std::vector<float> *r_smith, String *r_error);
};
