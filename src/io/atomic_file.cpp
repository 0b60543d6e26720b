#include "rollkin/io/atomic_file.hpp"

namespace rollkin::io {

void write_file_atomic(const std::string& path, const std::string& content) {
  OutputSet out;
  out.set(out.add("", path), content);
  out.commit();
}

}  // namespace rollkin::io
