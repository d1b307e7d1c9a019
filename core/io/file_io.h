/**************************************************************************/
/*  file_io.h                                                             */
/**************************************************************************/
/* Whole-file reads with a size bound and atomic, checked writes.         */
/*                                                                        */
/* file_write_atomic() writes to a temporary file in the target's folder, */
/* fsyncs it, checks fclose() and renames it over the target (rename(2)   */
/* is atomic on POSIX), so a reader sees the old file or the whole new    */
/* one, never a partial one; on any failure the temporary is removed and  */
/* the error names the path and errno's text. A target that exists and is */
/* not a regular file (/dev/full, /dev/stdout, a FIFO) is written in      */
/* place, with the same checks through fsync and close.                   */

#pragma once

#include "core/string/ustring.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>

// The default bound for text resources (.tscn, .tres, glTF JSON): far above any scene this project reads,
// low enough that `render /dev/zero` stops with an error instead of exhausting memory.
constexpr uint64_t FILE_READ_MAX_BYTES = uint64_t(256) << 20;

// Reads all of p_path into r_data. Fails (r_error names the path and reason) when the file cannot be
// opened or read, or holds more than p_max_bytes (checked while reading, so endless devices stop too).
bool file_read_bounded(const String &p_path, String &r_data, String *r_error, uint64_t p_max_bytes = FILE_READ_MAX_BYTES);

// Replaces p_path with p_size bytes atomically (see above). Returns false with r_error on any failure.
bool file_write_atomic(const String &p_path, const void *p_data, size_t p_size, String *r_error);
inline bool file_write_atomic(const String &p_path, const String &p_text, String *r_error) {
	return file_write_atomic(p_path, p_text.data(), p_text.size(), r_error);
}

// For writers that print with fprintf(): text goes to an in-memory FILE, and commit() writes it with
// file_write_atomic(). Nothing reaches p_path until commit() succeeds.
class FileWriteBuffer {
	char *buffer = nullptr;
	size_t size = 0;
	FILE *stream = nullptr;

public:
	FileWriteBuffer();
	~FileWriteBuffer();
	FileWriteBuffer(const FileWriteBuffer &) = delete;
	FileWriteBuffer &operator=(const FileWriteBuffer &) = delete;

	FILE *file() const { return stream; } // Null only when out of memory.
	bool commit(const String &p_path, String *r_error);
};
