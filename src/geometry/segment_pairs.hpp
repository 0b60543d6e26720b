// Internal to src/geometry (not installed): the segment pairs of two polylines that contact location
// (contact_location.cpp, find_contact) and interference (interference.cpp, check_interference) both use:
// a polyline view with an optional rigid motion, the near segment pairs found by descending two
// SegmentHierarchy trees, and the closest points of a segment pair.
#pragma once

#include "rollkin/geometry/contact.hpp"
#include "rollkin/se2.hpp"

#include "epick.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rollkin::geometry::detail {

/// A polyline with the sample convention of geometry/validation.hpp, optionally moved by a rigid motion
/// (its points are moved as they are read: only the segments looked at cost anything).
struct Polyline {
  const std::vector<Vec2<double>>& pts;
  bool closed;
  const SE2<double>* motion = nullptr;

  std::size_t segments() const { return closed ? pts.size() : pts.size() - 1; }
  Vec2<double> point(std::size_t k) const { return motion ? motion->act(pts[k]) : pts[k]; }
  Vec2<double> start(std::size_t i) const { return point(i); }
  Vec2<double> end(std::size_t i) const { return point((i + 1) % pts.size()); }
  Segment2 segment(std::size_t i) const { return Segment2(to_point(start(i)), to_point(end(i))); }
  bool consecutive(std::size_t i, std::size_t j) const {
    return j == i + 1 || (closed && i + 1 == segments() && j == 0);
  }

  /// Sample i as a point of the polyline (the last sample of an open one ends the last segment).
  PolylinePoint at_sample(std::size_t i) const {
    return i < segments() ? PolylinePoint{i, 0.0, point(i)} : PolylinePoint{i - 1, 1.0, point(i)};
  }

  /// Orthogonal projection of q onto segment i, clamped to the segment.
  PolylinePoint project(std::size_t i, const Vec2<double>& q) const {
    const Vec2<double> d = end(i) - start(i);
    const double len2 = d.squaredNorm();
    const double f = len2 > 0 ? std::clamp((q - start(i)).dot(d) / len2, 0.0, 1.0) : 0.0;
    return {i, f, start(i) + f * d};
  }

  /// A point known to lie on segment i (a crossing point): its fraction, the point itself kept.
  PolylinePoint locate(std::size_t i, const Vec2<double>& q) const {
    PolylinePoint p = project(i, q);
    p.point = q;
    return p;
  }
};

inline void require_samples(const Polyline& p, const char* name) {
  if (p.pts.size() < (p.closed ? 3u : 2u))
    throw std::invalid_argument(std::string("find_contact/check_interference: polyline ") + name + " has " +
                                std::to_string(p.pts.size()) + " samples; it needs at least " +
                                (p.closed ? "3 (closed)" : "2 (open)"));
}

/// A segment pair of a and b within touch_tol: their distance, 0 when they cross.
struct NearPair {
  std::size_t i, j;  // segment of a, segment of b
  double distance;
  bool crossing;
};

/// Closest points of two segments. Crossing segments meet at their common point; otherwise the minimum
/// is attained at an endpoint of one of them, so it is the best of the four endpoint projections.
std::pair<PolylinePoint, PolylinePoint> segment_closest_points(const Polyline& a, std::size_t i, const Polyline& b,
                                                               std::size_t j, bool crossing);

/// The largest absolute coordinate of the points (0 when there are none).
double max_abs_coordinate(const std::vector<Vec2<double>>& pts);

/// Distance within which candidates are kept: touch_tol and a few ulps of the coordinates' scale, so that no
/// pair within touch_tol is dropped because a circle or a moved point was rounded.
double rounding_margin(double touch_tol, double scale);

/// Segment pairs of a and b (b's points already moved into a's frame: b_in_a) within touch_tol, found by
/// descending both hierarchies together (circles moved by b_to_a); each candidate measured with
/// CGAL::squared_distance and tested with the exact predicate CGAL::do_intersect. Sorted by (i, j).
std::vector<NearPair> near_pairs(const SegmentHierarchy& a, const SegmentHierarchy& b, const SE2<double>& b_to_a,
                                 const Polyline& b_in_a, double touch_tol, double margin);

}  // namespace rollkin::geometry::detail
