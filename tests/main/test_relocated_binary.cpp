/**************************************************************************/
/*  test_relocated_binary.cpp                                             */
/**************************************************************************/
/* bin/godot-area carries its shaders (embedded at build time) and keeps  */
/* its SPIR-V cache in the user cache directory, so a copy of it renders  */
/* from anywhere, with the source tree out of reach.                      */

#include "core/io/image.h"
#include "modules/openexr/image_loader_exr.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace TestRelocatedBinary {

// Renames the source tree for its lifetime (and back on every exit path of the test).
struct HiddenSourceTree {
	std::filesystem::path root;
	std::filesystem::path hidden;
	bool active = false;

	explicit HiddenSourceTree(const std::filesystem::path &p_root) :
			root(p_root), hidden(p_root.string() + ".hidden-" + std::to_string(getpid())) {
		std::error_code ec;
		std::filesystem::rename(root, hidden, ec);
		active = !ec;
	}
	~HiddenSourceTree() {
		if (active) {
			std::error_code ec;
			std::filesystem::rename(hidden, root, ec);
		}
	}
};

TEST_CASE("[CLI][Render] a copy of bin/godot-area renders with the source tree renamed, caching SPIR-V under $XDG_CACHE_HOME") {
	REQUIRE_MESSAGE(std::filesystem::exists(GODOT_AREA_CLI_PATH), "build bin/godot-area first (scons builds it by default)");
	const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("godot_area_test_relocated_" + std::to_string(getpid()));
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir / "xdg_cache");
	const std::filesystem::path binary = dir / "godot-area";
	std::filesystem::copy_file(GODOT_AREA_CLI_PATH, binary);
	const std::filesystem::path exr = dir / "demo.exr";
	const std::filesystem::path root = std::filesystem::canonical(GODOT_AREA_ROOT);

	int status = -1;
	bool hidden = false;
	{
		HiddenSourceTree tree(root);
		hidden = tree.active && !std::filesystem::exists(root);
		// A cold cache: every shader comes from the binary's embedded sources. `timeout` bounds the
		// time the tree stays renamed.
		const std::string cmd = "cd '" + dir.string() + "' && env -u GODOT_AREA_SHADER_CACHE XDG_CACHE_HOME='" + (dir / "xdg_cache").string() +
				"' timeout 300 ./godot-area render --width 48 --height 27 -o demo.exr > render.log 2>&1";
		status = std::system(cmd.c_str());
	}
	REQUIRE(std::filesystem::exists(root)); // Restored.
	CHECK_MESSAGE(hidden, "could not rename " << root.string() << " (the render ran with the tree in place)");
	CHECK_MESSAGE((WIFEXITED(status) && WEXITSTATUS(status) == 0), "the relocated binary failed; see " << (dir / "render.log").string());

	Image image;
	String error;
	REQUIRE_MESSAGE(ImageLoaderEXR::load(exr.string(), image, &error), error);
	CHECK(image.get_width() == 48);
	CHECK(image.get_height() == 27);
	CHECK(image.is_finite());
	CHECK(image.has_non_black(0.01f));

	int spirv_files = 0;
	const std::filesystem::path cache = dir / "xdg_cache" / "godot-area" / "shaders";
	if (std::filesystem::is_directory(cache)) {
		for (const auto &entry : std::filesystem::directory_iterator(cache)) {
			spirv_files += entry.path().extension() == ".spv" ? 1 : 0;
		}
	}
	CHECK_MESSAGE(spirv_files > 0, "no SPIR-V written under " << cache.string());
	std::filesystem::remove_all(dir);
}

} // namespace TestRelocatedBinary
