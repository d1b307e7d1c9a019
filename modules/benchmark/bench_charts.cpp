/**************************************************************************/
/*  bench_charts.cpp                                                      */
/**************************************************************************/
/* godot-area: chart scripts of the benchmark sweeps (see the header).    */

#include "modules/benchmark/bench_charts.h"

#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

namespace {

bool file_exists(const String &p_path) {
	struct stat st;
	return stat(p_path.c_str(), &st) == 0;
}

String chart_python() {
	const char *env_python = getenv("GODOT_AREA_PYTHON");
	return env_python != nullptr && env_python[0] != '\0' ? String(env_python) : String("/usr/bin/python3");
}

// The chart scripts are development tools of the source tree: run from its root, or point
// $GODOT_AREA_SOURCE at it.
String chart_script(const String &p_script) {
	const char *source = getenv("GODOT_AREA_SOURCE");
	return (source != nullptr && source[0] != '\0' ? String(source) + "/" : String()) + "misc/scripts/" + p_script;
}

bool fail(String *r_error, const String &p_message) {
	if (r_error) {
		*r_error = "cannot draw the charts: " + p_message;
	}
	return false;
}

} // namespace

String BenchCharts::shell_quote(const String &p_text) {
	String out = "'";
	for (char c : p_text) {
		out += c == '\'' ? String("'\\''") : String(1, c);
	}
	return out + "'";
}

String BenchCharts::directory_of(const String &p_path) {
	size_t slash = p_path.find_last_of('/');
	return slash == String::npos ? String(".") : (slash == 0 ? String("/") : p_path.substr(0, slash));
}

bool BenchCharts::check(const String &p_script, String *r_error) {
	const String python = chart_python();
	if (access(python.c_str(), X_OK) != 0) {
		return fail(r_error, "the Python interpreter '" + python + "' is missing or not executable (install python3 and python3-matplotlib, see misc/scripts/install_deps.sh; GODOT_AREA_PYTHON picks another interpreter; --no-charts skips the charts).");
	}
	if (std::system((shell_quote(python) + " -c 'import matplotlib' >/dev/null 2>&1").c_str()) != 0) {
		return fail(r_error, "matplotlib is not installed for '" + python + "' (install python3-matplotlib, see misc/scripts/install_deps.sh; --no-charts skips the charts).");
	}
	if (!file_exists(chart_script(p_script))) {
		return fail(r_error, "misc/scripts/" + p_script + " not found (run from the repository root or pass --no-charts).");
	}
	return true;
}

bool BenchCharts::draw(const String &p_script, const String &p_csv, const std::vector<String> &p_extra_args, String *r_error) {
	if (!check(p_script, r_error)) {
		return false;
	}
	String command = shell_quote(chart_python()) + " " + shell_quote(chart_script(p_script)) + " " + shell_quote(p_csv) + " --out " + shell_quote(directory_of(p_csv));
	for (const String &a : p_extra_args) {
		command += " " + shell_quote(a);
	}
	printf("Drawing the charts: %s\n", command.c_str());
	fflush(stdout);
	const int status = std::system(command.c_str());
	if (status != 0) {
		return fail(r_error, vformat("'%s' failed (status %d).", command.c_str(), status));
	}
	return true;
}
