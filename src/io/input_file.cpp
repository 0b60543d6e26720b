#include "rollkin/io/input_file.hpp"

#include "rollkin/io/input_error.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <filesystem>
#include <cstring>
#include <fstream>
#include <sstream>

namespace rollkin::io {

namespace {

/// The staged outputs this thread reads instead of their targets (StagedOutputs), targets resolved.
thread_local std::vector<std::pair<std::string, std::string>> t_staged;

std::string resolved(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path : p.string();
}

}  // namespace

StagedOutputs::StagedOutputs(const std::vector<std::pair<std::string, std::string>>& target_and_staged)
    : previous_(t_staged) {
  for (const auto& [target, staged] : target_and_staged) files_.emplace_back(resolved(target), staged);
  t_staged.insert(t_staged.end(), files_.begin(), files_.end());
}

StagedOutputs::~StagedOutputs() { t_staged = std::move(previous_); }

std::string non_regular_kind(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "";  // missing or not accessible: opening reports the reason
  const mode_t m = st.st_mode;
  if (S_ISREG(m)) return "";
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  return "a special file";
}

void require_regular_file(const std::string& path, const std::string& what) {
  const std::string kind = non_regular_kind(path);
  if (kind.empty()) return;
  throw InputError(path, "", what + " is " + kind + ", not a regular file; expected the path of a regular file");
}

/// read_input_file of `path`, named `shown` in messages.
static std::string read_input_file_as(const std::string& path, const std::string& shown, const std::string& what) {
  require_regular_file(path, what);  // before opening: a FIFO would block in open(2)
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(shown, "", "cannot open " + what + ": " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(shown, "", "cannot read " + what + ": " + std::strerror(errno));
  return text.str();
}

std::string opened_path(const std::string& path) {
  if (t_staged.empty()) return path;
  const std::string r = resolved(path);
  for (const auto& [target, staged] : t_staged)
    if (target == r) return staged;
  return path;
}

std::string read_input_file(const std::string& path, const std::string& what) {
  return read_input_file_as(opened_path(path), path, what);
}


}  // namespace rollkin::io
