// The listing of a file's contours by its format (io/contour_listing.hpp), and the look-ups over the table of
// contour file formats (io/contour_formats.hpp; the table itself is in src/io/scene/contours/registry.cpp).
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/contour_formats.hpp"
#include "rollkin/io/input_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
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

std::string contours_json(const std::vector<ListedChain>& chains, int indent) {
  using json = nlohmann::ordered_json;
  json all = json::array();
  for (const ListedChain& c : chains) {
    json j;
    j["group"] = c.group;
    j["entities"] = c.entities;
    const bool chain = c.unreadable.empty();
    j["closed"] = chain ? json(c.closed) : json();
    j["length"] = chain ? json(c.length) : json();
    j["min"] = chain ? json::array({c.min.x(), c.min.y()}) : json();
    j["max"] = chain ? json::array({c.max.x(), c.max.y()}) : json();
    j["corners"] = chain ? json(c.corners) : json();
    j["selector"] = c.selector.empty() ? json() : json::parse(c.selector);
    if (c.selector.empty()) j["no_selector"] = c.no_selector;
    if (!c.hidden.empty()) j["hidden"] = c.hidden;
    if (!chain) j["unreadable"] = c.unreadable;
    all.push_back(std::move(j));
  }
  return all.dump(indent, ' ', false, json::error_handler_t::replace);  // a layer name in another code page
}

std::size_t unreadable_count(const std::vector<ListedChain>& chains) {
  return static_cast<std::size_t>(
      std::count_if(chains.begin(), chains.end(), [](const ListedChain& c) { return !c.unreadable.empty(); }));
}

}  // namespace rollkin::io
