// The listing of a file's contours by its format (io/contour_listing.hpp), and the look-ups over the table of
// contour file formats (io/contour_formats.hpp; the table itself is in src/io/scene/contours/registry.cpp).
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/contour_formats.hpp"
#include "rollkin/io/input_error.hpp"

#include <cctype>
#include <filesystem>

namespace rollkin::io {

const ContourFileFormat* contour_file_format_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const ContourFileFormat& f : contour_file_formats())
    for (const std::string& e : f.extensions)
      if (ext == e) return &f;
  return nullptr;
}

std::string contour_file_extensions(const std::string& last) {
  std::vector<std::string> all;
  for (const ContourFileFormat& f : contour_file_formats()) all.insert(all.end(), f.extensions.begin(), f.extensions.end());
  std::string out;
  for (std::size_t k = 0; k < all.size(); ++k)
    out += (k == 0 ? "" : k + 1 == all.size() ? " " + last + " " : ", ") + all[k];
  return out;
}

std::string contour_file_formats_help(const std::string& indent) {
  std::string out;
  for (const ContourFileFormat& f : contour_file_formats()) {
    std::string ext;
    for (const std::string& e : f.extensions) ext += (ext.empty() ? "" : ", ") + e;
    out += indent + f.name + " (" + ext + "): " + f.description + "\n";
  }
  return out;
}

std::vector<ListedChain> list_contours(const std::string& path) {
  if (const ContourFileFormat* f = contour_file_format_of(path)) return f->list(path);
  throw InputError(path, "", "cannot list the contours of a file named \"" + std::filesystem::path(path).filename().string() +
                                 "\"; expected a file ending in " + contour_file_extensions() + " (case does not matter)");
}

}  // namespace rollkin::io
