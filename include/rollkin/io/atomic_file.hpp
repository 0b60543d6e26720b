// Atomic file output shared by the CSV and SVG writers (and usable by any other writer).
//
// The content is written to "PATH.tmp" in the same directory, flushed and closed, then renamed over PATH
// (rename(2) replaces atomically on POSIX). Readers therefore see either the old file or the complete new
// one, never a half-written file. On any failure the temporary file is removed, PATH is left untouched and
// std::runtime_error is thrown with a message that names PATH and the system's reason.
#pragma once

#include <string>

namespace rollkin::io {

/// The temporary file name used while writing `path`: path + ".tmp".
std::string temporary_path(const std::string& path);

/// Writes `content` to `path` atomically (see above). Throws std::runtime_error naming `path` on failure.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace rollkin::io
