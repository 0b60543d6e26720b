// SVG documents, the choice of one subpath among those drawn (io/svg/reader.hpp; docs/scene_format.md, "SVG
// contours"): by its number ("subpath"), by the point it passes nearest to ("near", refused when the second
// nearest is about as near), or the only one.
#include "document.hpp"

#include "../segment_geometry.hpp"
#include "detail.hpp"

#include <algorithm>
#include <iterator>

namespace rollkin::io::svg_detail {
namespace {

std::string point_text(const P& p) { return "(" + fmt(p.x() + 0.0) + ", " + fmt(p.y() + 0.0) + ")"; }  // no "-0"

/// "1: line 3, path "a", subpath 1 (closed, from (0, 0)); 2: ..." (at most 20).
std::string candidate_list(const std::vector<SvgShape>& all) {
  std::string list;
  for (std::size_t k = 0; k < all.size() && k < 20; ++k)
    list += (k ? "; " : "") + std::to_string(k + 1) + ": " + all[k].location + " (" + (all[k].closed ? "closed" : "open") +
            ", from " + point_text(all[k].segments.front().points.front()) + ")";
  if (all.size() > 20) list += "; ...";
  return list;
}

}  // namespace

/// The one subpath the options select among those `what` draws (docs/scene_format.md, "SVG contours").
SvgShape select_shape(std::vector<SvgShape> all, const SvgReadOptions& o, const std::string& file,
                      const std::string& location, const std::string& what) {
  const auto fail = [&](const std::string& m) -> void { throw InputError(file, location, m); };
  if (all.empty()) fail(what + " draws no shape (path, circle, ellipse, rect, line, polyline or polygon)");
  // Hidden shapes are no candidates (document.hpp, Hiding): "near", "subpath" and the only one choose
  // among what the drawing draws.
  const auto split = std::stable_partition(all.begin(), all.end(), [](const SvgShape& s) { return s.hidden.empty(); });
  std::vector<SvgShape> hidden(std::make_move_iterator(split), std::make_move_iterator(all.end()));
  all.erase(split, all.end());
  if (all.empty()) {
    std::string list;
    for (std::size_t k = 0; k < hidden.size() && k < 6; ++k) list += (k ? "; " : "") + hidden[k].location + " (" + hidden[k].hidden + ")";
    if (hidden.size() > 6) list += "; ...";
    fail(what + " draws " + std::to_string(hidden.size()) + " subpath(s), every one hidden: " + list +
         "; select a hidden element by its own id (or the id of the element that hides it), or show it in the editor");
  }
  if (o.subpath && o.near) fail("give \"subpath\" or \"near\", not both");
  const std::string count = what + " draws " + std::to_string(all.size()) + " subpath(s): " + candidate_list(all);
  if (o.subpath) {
    if (*o.subpath < 1 || *o.subpath > all.size())
      fail("subpath " + std::to_string(*o.subpath) + " does not exist (subpaths count from 1): " + count);
    return std::move(all[*o.subpath - 1]);
  }
  if (o.near) {
    std::vector<std::pair<double, std::size_t>> d;
    double extent = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
      d.emplace_back(io::distance_to_segments(all[k].segments, *o.near), k);
      extent = std::max(extent, svg_detail::control_extent(all[k].segments));
    }
    std::sort(d.begin(), d.end());
    if (d.size() > 1 && d[1].first - d[0].first <= svg_detail::kNearTie * d[0].first + 1e-9 * extent)
      fail("near " + point_text(*o.near) + " is about equally near " + all[d[0].second].location + " (distance " +
           fmt(d[0].first) + ") and " + all[d[1].second].location + " (distance " + fmt(d[1].first) +
           "); give a point closer to the one you mean, or select it by id and \"subpath\"");
    return std::move(all[d[0].second]);
  }
  if (all.size() > 1)
    fail(count + "; select one with \"subpath\": k (1 to " + std::to_string(all.size()) + ") or \"near\": [x, y]");
  return std::move(all.front());
}

}  // namespace rollkin::io::svg_detail
