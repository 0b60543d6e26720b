// The listing of a drawing's contours by the file's extension (io/contour_listing.hpp).
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/input_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
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
