/**************************************************************************/
/*  test_python_module.cpp                                                */
/**************************************************************************/
/* Runs tests/python/test_godot_area.py with the Debian interpreter       */
/* against the extension SConstruct built (bin/python[_<variant>]).       */

#include "core/string/ustring.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <sys/wait.h>

#ifndef GODOT_AREA_PYTHON_MODULE_DIR
#define GODOT_AREA_PYTHON_MODULE_DIR ""
#endif

namespace TestPythonModule {

TEST_CASE("[Python] the godot_area module passes tests/python/test_godot_area.py (/usr/bin/python3)") {
	const String module_dir = GODOT_AREA_PYTHON_MODULE_DIR;
	if (module_dir.empty()) {
		MESSAGE("skipped: the Python extension was not built (python3-dev/python3-pybind11/pybind11-dev missing, see misc/scripts/install_deps.sh, or modules/python/ filtered out with only=)");
		return;
	}
	REQUIRE_MESSAGE(std::filesystem::exists("/usr/bin/python3"), "the Python test needs the Debian interpreter /usr/bin/python3");
	bool built = false;
	if (std::filesystem::is_directory(module_dir)) {
		for (const auto &entry : std::filesystem::directory_iterator(module_dir)) {
			built = built || entry.path().filename().string().rfind("godot_area", 0) == 0;
		}
	}
	REQUIRE_MESSAGE(built, "build the extension first (scons builds it by default): " << module_dir);

	const String script = String(GODOT_AREA_ROOT) + "/tests/python/test_godot_area.py";
	const String cmd = "PYTHONPATH='" + module_dir + "' PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 '" + script + "' 2>&1";
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
	INFO("python output:\n" << output);
	CHECK(code == 0);
	CHECK(output.find("tests passed") != String::npos);
}

} // namespace TestPythonModule
