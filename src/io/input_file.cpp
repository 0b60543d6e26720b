#include "rollkin/io/input_file.hpp"

#include "rollkin/io/input_error.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace rollkin::io {

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

std::string read_input_file(const std::string& path, const std::string& what) {
  require_regular_file(path, what);  // before opening: a FIFO would block in open(2)
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open " + what + ": " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "cannot read " + what + ": " + std::strerror(errno));
  return text.str();
}

}  // namespace rollkin::io
