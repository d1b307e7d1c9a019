/**************************************************************************/
/*  bench_charts.h                                                        */
/**************************************************************************/
/* godot-area: runs a sweep's chart script (misc/scripts/<name>.py) with  */
/* matplotlib at the end of a `bench --sweep` command. The interpreter is */
/* /usr/bin/python3 (GODOT_AREA_PYTHON picks another); the script is      */
/* looked up under $GODOT_AREA_SOURCE, else relative to the working      */
/* directory. Charts go next to the CSV (--out <CSV directory>).          */

#pragma once

#include "core/string/ustring.h"

#include <vector>

class BenchCharts {
public:
	// Single-quotes p_text for /bin/sh.
	static String shell_quote(const String &p_text);
	// Directory part of p_path ("." when it has none).
	static String directory_of(const String &p_path);
	// Checks that the charts can be drawn: the interpreter, matplotlib and misc/scripts/<p_script>. A sweep
	// runs it up front so that a missing tool does not cost a whole run. False with r_error naming the problem.
	static bool check(const String &p_script, String *r_error);
	// Runs `python misc/scripts/<p_script> <p_csv> --out <dir of p_csv> <p_extra_args...>` after check().
	// False with r_error naming the problem (no interpreter, no matplotlib, no script, the script failed).
	static bool draw(const String &p_script, const String &p_csv, const std::vector<String> &p_extra_args, String *r_error);
};
