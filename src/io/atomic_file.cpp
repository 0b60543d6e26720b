#include "rollkin/io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace rollkin::io {

std::string temporary_path(const std::string& path) { return path + ".tmp"; }

namespace {
[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
  std::string msg = "cannot write file '" + path + "': " + what;
  if (err != 0) msg += ": " + std::string(std::strerror(err));
  throw std::runtime_error(msg);
}
}  // namespace

void write_file_atomic(const std::string& path, const std::string& content) {
  if (path.empty()) throw std::runtime_error("cannot write file '': empty path");
  const std::string tmp = temporary_path(path);
  errno = 0;
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) fail(path, "cannot create temporary file '" + tmp + "'", errno);
  errno = 0;
  const std::size_t written = content.empty() ? 0 : std::fwrite(content.data(), 1, content.size(), f);
  int err = errno;
  const bool write_ok = written == content.size();
  errno = 0;
  const bool flush_ok = std::fflush(f) == 0;
  if (!flush_ok && err == 0) err = errno;
  errno = 0;
  const bool close_ok = std::fclose(f) == 0;
  if (!close_ok && err == 0) err = errno;
  if (!write_ok || !flush_ok || !close_ok) {
    std::remove(tmp.c_str());
    fail(path, "error while writing temporary file '" + tmp + "'", err);
  }
  errno = 0;
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    err = errno;
    std::remove(tmp.c_str());
    fail(path, "cannot rename '" + tmp + "' to it", err);
  }
}

}  // namespace rollkin::io
