// The listing of an SVG drawing's contours (io/contour_listing.hpp): every subpath of every drawn element, in
// viewport units with y up (read_svg_shapes with the defaults: flip_y, no unit conversion, scale 1), each with
// the scene snippet that selects it (docs/scene_format.md, "SVG contours").
#include "rollkin/io/contour_listing.hpp"
#include "rollkin/io/svg/reader.hpp"

#include "../segment_geometry.hpp"
#include "detail.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollkin::io {
namespace {

using P = Vec2<double>;
using ordered_json = nlohmann::ordered_json;

/// Points along the segments (`per_segment` steps each, ends included): for the bounding box and the near point.
std::vector<P> sampled(const std::vector<BezierSegment<double>>& segments, int per_segment) {
  std::vector<P> out;
  for (const auto& s : segments)
    for (int i = 0; i <= per_segment; ++i) out.push_back(segment_point(s, double(i) / per_segment));
  return out;
}

/// A point on shape k that "near" picks it by: among points along it, the farthest from every other shape;
/// nullopt when even that one is about equally near another shape (the two coincide there: the selector is
/// then its number among all the document draws, "subpath" without "path").
std::optional<P> near_point(const std::vector<SvgShape>& shapes, std::size_t k) {
  double extent = 0;
  for (const SvgShape& s : shapes) extent = std::max(extent, svg_detail::control_extent(s.segments));
  std::optional<P> best;
  double best_clearance = 0;
  for (const P& p : sampled(shapes[k].segments, 4)) {
    double clearance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < shapes.size() && clearance > best_clearance; ++j)
      if (j != k) clearance = std::min(clearance, distance_to_segments(shapes[j].segments, p));
    if (!best || clearance > best_clearance) {
      best = p;
      best_clearance = clearance;
    }
  }
  const double own = distance_to_segments(shapes[k].segments, *best);
  if (!(best_clearance - own > svg_detail::kNearTie * own + 1e-9 * extent)) return std::nullopt;
  return best;
}

std::string selector(const std::string& file, const std::vector<SvgShape>& shapes, std::size_t k) {
  ordered_json j;
  j["type"] = "svg";
  j["file"] = file;
  const SvgShape& s = shapes[k];
  if (!s.selector_id.empty()) {
    j["path"] = s.selector_id;
    if (s.selector_subpath) j["subpath"] = s.selector_subpath;
  } else {
    if (const std::optional<P> p = near_point(shapes, k))
      j["near"] = ordered_json::array({p->x(), p->y()});
    else
      j["subpath"] = k + 1;
  }
  return j.dump();
}

}  // namespace

std::vector<ListedChain> list_svg_contours(const std::string& path) {
  const std::vector<SvgShape> shapes = read_svg_shapes(path, "");
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
    c.selector = selector(path, shapes, k);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace rollkin::io
