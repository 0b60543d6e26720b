// The listing of a drawing's contours by the file's extension (io/contour_listing.hpp).
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/input_error.hpp"

#include <cctype>
#include <filesystem>

namespace rollkin::io {

std::vector<ListedChain> list_contours(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".dxf") return list_dxf_contours(path);
  if (ext == ".svg") return list_svg_contours(path);
  throw InputError(path, "", "cannot list the contours of a file named \"" +
                                 std::filesystem::path(path).filename().string() +
                                 "\"; expected a drawing ending in .dxf or .svg (case does not matter)");
}

}  // namespace rollkin::io
