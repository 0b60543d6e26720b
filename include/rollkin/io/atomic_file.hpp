// Atomic file output shared by the CSV and SVG writers (and usable by any other writer).
//
// write_file_atomic is an OutputSet (rollkin/io/output_set.hpp) of one file: the content goes to a
// temporary made by mkstemp(3) in the target's directory (a name that cannot collide with any file of the
// user's), is closed, then renamed over PATH (rename(2) replaces atomically on POSIX). Readers see either
// the old file or the complete new one. A PATH that is a symbolic link is written to its target and stays a
// link. On any failure the temporary is removed, PATH is left untouched and rollkin::io::OutputError (a
// std::runtime_error) is thrown with a message that names PATH and the reason.
#pragma once

#include "rollkin/io/output_set.hpp"

#include <string>

namespace rollkin::io {

/// Writes `content` to `path` atomically (see above). Throws OutputError naming `path` on failure.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace rollkin::io
