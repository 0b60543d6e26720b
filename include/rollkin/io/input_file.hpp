// Reading an input file (a scene, a point file, an SVG or DXF drawing, a reference table): the one place that
// opens what a user names as input (docs/reliability.md, "Input files").
//
// Only a regular file (or a symbolic link to one) is read. Anything else is refused before it is opened, with
// InputError naming the file and what it is: a directory (libdxflib would spin on it forever), a FIFO (opening
// it blocks until a writer appears), a character or block device (/dev/zero never ends), a socket.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rollkin::io {

/// "a directory", "a FIFO (named pipe)", ... for a path that exists and is not a regular file; "" for a
/// regular file or a path that cannot be examined (then opening it says why).
std::string non_regular_kind(const std::string& path);

/// Throws InputError(path, "", "<what> is <kind>, not a regular file; ...") when `path` exists and is not a
/// regular file. `what` names the file's role, e.g. "the DXF file" or "the point file".
void require_regular_file(const std::string& path, const std::string& what);

/// The whole content of the input file `path`, read in binary, after require_regular_file. Throws InputError
/// naming the file when it is not a regular file or cannot be opened or read ("cannot open <what>: reason").
std::string read_input_file(const std::string& path, const std::string& what);

/// The path read_input_file opens for `path`: the temporary of a staged output (StagedOutputs), else `path`.
/// For a reader that opens the file by name again (libdxflib).
std::string opened_path(const std::string& path);

/// While alive, read_input_file on this thread reads each staged output (target path, a path that opens its
/// temporary) from its temporary: the check of an io::OutputSet (commit(check)) reads the files it is about to
/// commit before they exist under their names. Paths are compared resolved (absolute, existing links resolved).
class StagedOutputs {
 public:
  explicit StagedOutputs(const std::vector<std::pair<std::string, std::string>>& target_and_staged);
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

 private:
  std::vector<std::pair<std::string, std::string>> files_, previous_;
};

}  // namespace rollkin::io
