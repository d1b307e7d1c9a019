/**************************************************************************/
/*  file_io.cpp                                                           */
/**************************************************************************/
/* POSIX open/write/fsync/close/rename; see file_io.h.                    */

#include "core/io/file_io.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

bool file_read_bounded(const String &p_path, String &r_data, String *r_error, uint64_t p_max_bytes) {
	r_data.clear();
	int fd = open(p_path.c_str(), O_RDONLY | O_CLOEXEC);
	if (fd < 0) {
		if (r_error) {
			*r_error = vformat("%s: cannot open (%s).", p_path.c_str(), strerror(errno));
		}
		return false;
	}
	char chunk[65536];
	for (;;) {
		ssize_t n = read(fd, chunk, sizeof(chunk));
		if (n < 0 && errno == EINTR) {
			continue;
		}
		if (n < 0) {
			int e = errno;
			close(fd);
			r_data.clear();
			if (r_error) {
				*r_error = vformat("%s: read error (%s).", p_path.c_str(), strerror(e));
			}
			return false;
		}
		if (n == 0) {
			break;
		}
		if (r_data.size() + size_t(n) > p_max_bytes) {
			close(fd);
			r_data.clear();
			if (r_error) {
				*r_error = vformat("%s: larger than the %llu-byte limit for this kind of file.", p_path.c_str(), (unsigned long long)p_max_bytes);
			}
			return false;
		}
		r_data.append(chunk, size_t(n));
	}
	close(fd);
	return true;
}

static bool _write_all(int p_fd, const void *p_data, size_t p_size, int *r_errno) {
	const char *p = static_cast<const char *>(p_data);
	while (p_size > 0) {
		ssize_t n = write(p_fd, p, p_size);
		if (n < 0 && errno == EINTR) {
			continue;
		}
		if (n <= 0) {
			*r_errno = n < 0 ? errno : EIO;
			return false;
		}
		p += n;
		p_size -= size_t(n);
	}
	return true;
}

// Writes, fsyncs (where the file supports it) and closes p_fd; false with *r_errno on the first failure.
static bool _write_sync_close(int p_fd, const void *p_data, size_t p_size, int *r_errno) {
	bool ok = _write_all(p_fd, p_data, p_size, r_errno);
	if (ok && fsync(p_fd) != 0 && errno != EINVAL && errno != EROFS) {
		// EINVAL/EROFS: the file (a pipe, a character device) cannot be synced; the data is written.
		*r_errno = errno;
		ok = false;
	}
	if (close(p_fd) != 0 && ok) {
		*r_errno = errno;
		ok = false;
	}
	return ok;
}

bool file_write_atomic(const String &p_path, const void *p_data, size_t p_size, String *r_error) {
	auto fail = [&](const char *p_what, int p_errno) {
		if (r_error) {
			*r_error = vformat("Cannot write \"%s\": %s (%s).", p_path.c_str(), p_what, strerror(p_errno));
		}
		return false;
	};
	if (p_path.empty()) {
		if (r_error) {
			*r_error = "Cannot write a file: the path is empty.";
		}
		return false;
	}
	int err = 0;
	struct stat st;
	if (stat(p_path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
		if (S_ISDIR(st.st_mode)) {
			return fail("it is a folder", EISDIR);
		}
		int fd = open(p_path.c_str(), O_WRONLY | O_CLOEXEC);
		if (fd < 0) {
			return fail("cannot open", errno);
		}
		return _write_sync_close(fd, p_data, p_size, &err) ? true : fail("write failed", err);
	}

	// The temporary lives beside the target so that rename() stays on one file system.
	static std::atomic<unsigned> counter{ 0 };
	const String temp = vformat("%s.tmp-%d-%u", p_path.c_str(), int(getpid()), counter.fetch_add(1));
	// A replaced file keeps its permissions; a new one gets 0666 less the umask, as fopen() would give it.
	const bool existed = stat(p_path.c_str(), &st) == 0;
	const mode_t mode = existed ? (st.st_mode & 07777) : 0666;
	int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
	if (fd < 0) {
		return fail("cannot create a file in its folder", errno);
	}
	if (existed) {
		fchmod(fd, mode);
	}
	if (!_write_sync_close(fd, p_data, p_size, &err)) {
		unlink(temp.c_str());
		return fail("write failed", err);
	}
	if (rename(temp.c_str(), p_path.c_str()) != 0) {
		err = errno;
		unlink(temp.c_str());
		return fail("cannot replace the file", err);
	}
	// Make the rename itself durable (best effort: not every file system can sync a folder).
	size_t slash = p_path.find_last_of('/');
	const String dir = slash == String::npos ? String(".") : (slash == 0 ? String("/") : p_path.substr(0, slash));
	int dfd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dfd >= 0) {
		fsync(dfd);
		close(dfd);
	}
	return true;
}

FileWriteBuffer::FileWriteBuffer() {
	stream = open_memstream(&buffer, &size);
}

FileWriteBuffer::~FileWriteBuffer() {
	if (stream) {
		fclose(stream);
	}
	free(buffer);
}

bool FileWriteBuffer::commit(const String &p_path, String *r_error) {
	if (!stream || fflush(stream) != 0 || ferror(stream)) {
		if (r_error) {
			*r_error = vformat("Cannot write \"%s\": out of memory while formatting it.", p_path.c_str());
		}
		return false;
	}
	return file_write_atomic(p_path, buffer, size, r_error);
}
