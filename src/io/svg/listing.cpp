// The listing of an SVG drawing's contours (io/contour_listing.hpp): every subpath of every drawn element, in
// viewport units with y up (read_svg_shapes with the defaults: flip_y, no unit conversion, scale 1), each with
// the scene snippet that selects it (docs/scene_format.md, "SVG contours"); hidden ones marked, selected only by
// an id. n log n in the shapes: the shapes near a point come from an R-tree of segment boxes (SegmentIndex).
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/svg/reader.hpp"

#include "../segment_geometry.hpp"
#include "detail.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

namespace rollkin::io {
namespace {

using P = Vec2<double>;
using ordered_json = nlohmann::ordered_json;

/// The drawn (not hidden) shapes, which "near" and "subpath" without an id choose among, with an index of their
/// segments: finding the shapes near a point costs log n, not a loop over all (the listing stays n log n).
class DrawnShapes {
 public:
  explicit DrawnShapes(const std::vector<SvgShape>& shapes) : shapes_(shapes), number_(shapes.size(), 0) {
    std::vector<std::pair<const BezierSegment<double>*, std::size_t>> segments;
    std::size_t drawn = 0;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      if (!shapes[k].hidden.empty()) continue;
      number_[k] = ++drawn;
      extent_ = std::max(extent_, svg_detail::control_extent(shapes[k].segments));
      for (const auto& s : shapes[k].segments) segments.emplace_back(&s, k);
    }
    index_ = std::make_unique<SegmentIndex>(segments);
  }

  /// Shape k's number among the drawn shapes (its "subpath" without an id), 1-based.
  std::size_t number(std::size_t k) const { return number_[k]; }

  /// A point on drawn shape k that "near" picks it by, the first of near_candidates: no other drawn shape within
  /// twice the tie margin of a selection (selection.cpp: kNearTie times the distance to shape k, round-off
  /// for a point on it, plus 1e-9 of the drawing's extent); nullopt when there is none (the shapes coincide
  /// there: the selector is then its number among the shapes the document draws, "subpath" without "path").
  std::optional<P> near_point(std::size_t k) const {
    for (const P& p : near_candidates(shapes_[k].segments))
      if (!index_->other_within(p, 2e-9 * extent_, k)) return p;
    return std::nullopt;
  }

 private:
  const std::vector<SvgShape>& shapes_;
  std::vector<std::size_t> number_;
  double extent_ = 0;
  std::unique_ptr<SegmentIndex> index_;
};

/// The selector of shape k (the id that draws it, else "near" or "subpath" among the drawn shapes), or empty
/// with `why`.
std::string selector(const std::string& file, const std::vector<SvgShape>& shapes, const DrawnShapes& drawn,
                     std::size_t k, std::string& why) {
  ordered_json j;
  j["type"] = "svg";
  j["file"] = file;
  const SvgShape& s = shapes[k];
  if (!s.selector_id.empty()) {
    j["path"] = s.selector_id;
    if (s.selector_subpath) j["subpath"] = s.selector_subpath;
  } else if (!s.hidden.empty()) {
    why = "it is hidden (" + s.hidden + "): \"near\" and \"subpath\" pass it over, and no element with a unique id "
          "draws it where nothing inside that element hides it (it is hidden inside a <use>'s clone, or has no id up "
          "to what hides it); give it an id in the editor";
    return "";
  } else if (const std::optional<P> p = drawn.near_point(k)) {
    j["near"] = ordered_json::array({p->x(), p->y()});
  } else {
    j["subpath"] = drawn.number(k);
  }
  return j.dump(-1, ' ', false, ordered_json::error_handler_t::replace);  // (ids and file names: UTF-8 read by pugixml)
}

}  // namespace

std::vector<ListedChain> list_svg_contours(const std::string& path) {
  const std::vector<SvgShape> shapes = read_svg_shapes(path, "");
  const DrawnShapes drawn(shapes);
  std::vector<ListedChain> out;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const SvgShape& s = shapes[k];
    ListedChain c;
    const std::string sub = ", subpath " + std::to_string(s.subpath);
    c.group = s.location;
    if (s.subpaths > 1) c.group.erase(c.group.find(sub), sub.size());  // the element; the subpath is the entity
    c.entities = {s.subpaths > 1 ? "subpath " + std::to_string(s.subpath) : s.element};
    c.closed = s.closed;
    c.length = svg_bezier_path(s).total_length();
    segments_box(s.segments, c.min, c.max);
    c.corners = s.corners.size();
    c.segments = s.segments;
    c.hidden = s.hidden;
    c.selector = selector(path, shapes, drawn, k, c.no_selector);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace rollkin::io
