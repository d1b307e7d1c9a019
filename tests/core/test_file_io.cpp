/**************************************************************************/
/*  test_file_io.cpp                                                      */
/**************************************************************************/

#include "core/io/file_io.h"

#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/resource.h>

namespace TestFileIO {

static String _read(const std::filesystem::path &p_path) {
	std::ifstream f(p_path, std::ios::binary);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

// Files in p_dir other than p_keep (a temporary left behind would show here).
static int _stray_files(const std::filesystem::path &p_dir, const std::filesystem::path &p_keep) {
	int n = 0;
	for (const auto &e : std::filesystem::directory_iterator(p_dir)) {
		n += e.path() != p_keep;
	}
	return n;
}

TEST_CASE("[FileIO] an atomic write replaces the file whole and leaves no temporary") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_file_io";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	std::filesystem::path path = dir / "out.txt";
	String error;
	REQUIRE_MESSAGE(file_write_atomic(path.string(), String("first version\n"), &error), error);
	CHECK(_read(path) == "first version\n");
	REQUIRE_MESSAGE(file_write_atomic(path.string(), String("second\n"), &error), error);
	CHECK(_read(path) == "second\n");
	CHECK(_stray_files(dir, path) == 0);

	// A folder that does not exist: an error naming the path, no file.
	error.clear();
	CHECK_FALSE(file_write_atomic((dir / "missing" / "x.txt").string(), String("x"), &error));
	CHECK_MESSAGE(error.find((dir / "missing" / "x.txt").string()) != String::npos, error);
	CHECK_FALSE(std::filesystem::exists(dir / "missing"));
	std::filesystem::remove_all(dir);
}

TEST_CASE("[FileIO] a write to a full device fails and names the path") {
	if (!std::filesystem::exists("/dev/full")) {
		MESSAGE("skipped: /dev/full is not available");
		return;
	}
	String error;
	std::vector<char> data(100000, 'x');
	CHECK_FALSE(file_write_atomic("/dev/full", data.data(), data.size(), &error));
	CHECK_MESSAGE(error.find("\"/dev/full\"") != String::npos, error);
	CHECK_MESSAGE(error.find("No space left on device") != String::npos, error);
}

TEST_CASE("[FileIO] a disk that fills up mid-write keeps the old file and leaves no partial one") {
	// RLIMIT_FSIZE makes write(2) fail with EFBIG past the limit, as a full disk fails with ENOSPC: the
	// same path through file_write_atomic(), without needing a full file system.
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_file_io_full";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	std::filesystem::path path = dir / "scene.tscn";
	String error;
	REQUIRE_MESSAGE(file_write_atomic(path.string(), String("old contents\n"), &error), error);

	struct rlimit old_limit;
	REQUIRE(getrlimit(RLIMIT_FSIZE, &old_limit) == 0);
	void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN);
	struct rlimit limit = old_limit;
	limit.rlim_cur = 4096;
	REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
	std::vector<char> data(65536, 'y');
	const bool ok = file_write_atomic(path.string(), data.data(), data.size(), &error);
	setrlimit(RLIMIT_FSIZE, &old_limit);
	signal(SIGXFSZ, old_handler);

	CHECK_FALSE(ok);
	CHECK_MESSAGE(error.find(path.string()) != String::npos, error);
	CHECK(_read(path) == "old contents\n");
	CHECK_MESSAGE(_stray_files(dir, path) == 0, "a temporary file was left behind");
	std::filesystem::remove_all(dir);
}

TEST_CASE("[FileIO] FileWriteBuffer writes nothing until commit, then the whole text") {
	std::filesystem::path dir = std::filesystem::temp_directory_path() / "godot_area_test_file_io_buf";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	std::filesystem::path path = dir / "rows.csv";
	{
		FileWriteBuffer out;
		REQUIRE(out.file() != nullptr);
		fprintf(out.file(), "a,b\n");
		CHECK_FALSE(std::filesystem::exists(path));
		for (int i = 0; i < 1000; i++) {
			fprintf(out.file(), "%d,%d\n", i, i * i);
		}
		String error;
		REQUIRE_MESSAGE(out.commit(path.string(), &error), error);
	}
	String text = _read(path);
	CHECK(text.compare(0, 4, "a,b\n") == 0);
	CHECK(text.find("999,998001\n") == text.size() - 11);
	std::filesystem::remove_all(dir);
}

TEST_CASE("[FileIO] bounded reads stop at the limit, also on an endless device") {
	String data, error;
	if (std::filesystem::exists("/dev/zero")) {
		CHECK_FALSE(file_read_bounded("/dev/zero", data, &error, 1 << 20));
		CHECK_MESSAGE(error.find("/dev/zero: larger than the 1048576-byte limit") != String::npos, error);
		CHECK(data.empty());
	}
	error.clear();
	CHECK_FALSE(file_read_bounded("/nonexistent/file.tscn", data, &error));
	CHECK_MESSAGE(error.find("/nonexistent/file.tscn: cannot open") != String::npos, error);
}

} // namespace TestFileIO
