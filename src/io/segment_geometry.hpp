// Points, distances and bounding boxes of the rational Bezier segments the DXF and SVG readers produce: what
// "near" selections and the listing of a drawing's chains (io/contour_listing.hpp) measure, one definition
// for both readers.
#pragma once

#include "rollkin/profile/bezier.hpp"

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

}  // namespace rollkin::io
