/**************************************************************************/
/*  test_python_module.cpp                                                */
/**************************************************************************/
/* Runs the pytest suite tests/python/ with the Debian interpreter        */
/* (/usr/bin/python3 -m pytest, python3-pytest) against the extension     */
/* SConstruct built (bin/python[_<variant>]) and the CLI built with it    */
/* (for the render-matches-CLI test), so the README test command is the   */
/* only entry point. Nothing is written into the tree (no bytecode, no    */
/* pytest cache); temporary files go to pytest's tmp_path.                */

#include "core/string/ustring.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>

#ifndef GODOT_AREA_PYTHON_MODULE_DIR
#define GODOT_AREA_PYTHON_MODULE_DIR ""
#endif

namespace TestPythonModule {

TEST_CASE("[Python] the godot_area module passes the pytest suite tests/python (/usr/bin/python3 -m pytest)") {
	const String module_dir = GODOT_AREA_PYTHON_MODULE_DIR;
	if (module_dir.empty()) {
		MESSAGE("skipped: the Python extension was not built (python3-dev/python3-pybind11/pybind11-dev missing, see misc/scripts/install_deps.sh, or modules/python/ filtered out with only=)");
		return;
	}
	REQUIRE_MESSAGE(std::filesystem::exists("/usr/bin/python3"), "the Python tests need the Debian interpreter /usr/bin/python3");
	bool built = false;
	if (std::filesystem::is_directory(module_dir)) {
		for (const auto &entry : std::filesystem::directory_iterator(module_dir)) {
			built = built || entry.path().filename().string().rfind("godot_area", 0) == 0;
		}
	}
	REQUIRE_MESSAGE(built, "build the extension first (scons builds it by default): " << module_dir);
	REQUIRE_MESSAGE(std::system("/usr/bin/python3 -c 'import pytest' > /dev/null 2>&1") == 0, "pytest is missing: install python3-pytest (misc/scripts/install_deps.sh)");

	const String root = GODOT_AREA_ROOT;
	const String cmd = "cd '" + root + "' && PYTHONPATH='" + module_dir + "' PYTHONDONTWRITEBYTECODE=1 GODOT_AREA_CLI='" + GODOT_AREA_CLI_PATH +
			"' /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/python 2>&1";
	FILE *pipe = popen(cmd.c_str(), "r");
	REQUIRE(pipe != nullptr);
	String output;
	char buffer[4096];
	size_t n = 0;
	while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) {
		output.append(buffer, n);
	}
	const int status = pclose(pipe);
	const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
	// pytest -q ends with "N passed[, M skipped] in T s"; failures and teardown errors add "failed" / "error".
	String summary = output;
	while (!summary.empty() && (summary.back() == '\n' || summary.back() == '\r')) {
		summary.pop_back();
	}
	summary = summary.substr(summary.rfind('\n') == String::npos ? 0 : summary.rfind('\n') + 1);
	INFO("pytest output:\n"
			<< output);
	CHECK(code == 0);
	CHECK(summary.find(" passed") != String::npos);
	CHECK(summary.find(" failed") == String::npos); // "1 xfailed" (a known engine bug, marked strict) is fine.
	CHECK(summary.find(" error") == String::npos);
}

} // namespace TestPythonModule
