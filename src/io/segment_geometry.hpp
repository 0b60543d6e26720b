// Points, distances and bounding boxes of the rational Bezier segments the DXF and SVG readers produce: what
// "near" selections and the listing of a drawing's chains (io/contour_listing.hpp) measure, one definition
// for both readers.
#pragma once

#include "rollkin/profile/bezier.hpp"

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace rollkin::io {

/// The point at parameter t in [0, 1] (de Casteljau in homogeneous coordinates).
Vec2<double> segment_point(const BezierSegment<double>& s, double t);

/// Distance from q to the segment: 64 samples, then a golden-section search around every sample nearer than
/// its neighbours (the distance is smooth there; at a minimum its error is the square of the parameter's).
double distance_to_segment(const BezierSegment<double>& s, const Vec2<double>& q);

/// Distance from q to the nearest of the segments; segments whose control points' box (which holds the curve:
/// the weights are positive) is already farther than the best are skipped.
double distance_to_segments(const std::vector<BezierSegment<double>>& segments, const Vec2<double>& q);

/// The bounding box of the segments' curves: per segment and coordinate, the extreme of 32 samples refined by
/// a golden-section search between its neighbours (the curve's extremes, to round-off).
void segments_box(const std::vector<BezierSegment<double>>& segments, Vec2<double>& lo, Vec2<double>& hi);

/// Points on end-to-end segments that "near" may name them by (the listings of DXF and SVG drawings): the
/// middle of the middle segment first, then up to 64 more spread along them (where other chains cross the
/// middle, another point names it). At most 65 points, whatever the number of segments.
std::vector<Vec2<double>> near_candidates(const std::vector<BezierSegment<double>>& segments);

/// The segments of many owners (the chains of a layer, the shapes of a document) in an R-tree of their
/// control-point boxes (Boost.Geometry, bulk-loaded: n log n), so that "does another owner pass within d of
/// q" costs log n plus the segments whose boxes are that near, not a loop over every owner: the listing of a
/// drawing stays n log n in its chains (docs/reliability.md, "CAD readers (issue 37)").
class SegmentIndex {
 public:
  /// The segments (kept by address: they must outlive the index) with the owner each belongs to.
  explicit SegmentIndex(const std::vector<std::pair<const BezierSegment<double>*, std::size_t>>& segments);
  ~SegmentIndex();
  SegmentIndex(const SegmentIndex&) = delete;
  SegmentIndex& operator=(const SegmentIndex&) = delete;

  /// Whether a segment of an owner other than `owner` passes within `d` of q (distance_to_segment).
  bool other_within(const Vec2<double>& q, double d, std::size_t owner) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace rollkin::io
