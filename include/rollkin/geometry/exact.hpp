// Exact geometry on double input, for regression data and for deciding degenerate cases.
//
// Every double is a dyadic rational, so the samples of a contour are exact rationals and so are the
// results of +, -, * on them. Computed in an exact rational kernel (CGAL::Simple_cartesian over GMP
// rationals, src/geometry/exact.cpp), predicates are exact and these quantities are exact:
//   - orientation / collinearity / "on a segment" of sample points;
//   - squared chord lengths |p_(i+1) - p_i|^2 and the signed area of a closed polygon (shoelace).
// Chord LENGTHS, and therefore cumulative chord lengths (arc length of a polyline), are square roots and
// in general irrational: they have no exact decimal form and are not offered here. The squared chords
// determine them uniquely, so they are the exact regression data for a chord-length parameterisation.
//
// Decimal strings: a dyadic rational n / 2^k equals n 5^k / 10^k, a finite decimal, so every value here is
// written out EXACTLY in plain decimal (no exponent, no rounding; e.g. 0.1 as a double is
// "0.1000000000000000055511151231257827021181583404541015625").
#pragma once

#include "rollkin/scalar.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rollkin::geometry {

/// Sign of the turn p -> q -> r, exactly: +1 counter-clockwise (r left of the line p->q), -1 clockwise,
/// 0 collinear.
int exact_orientation(const Vec2<double>& p, const Vec2<double>& q, const Vec2<double>& r);

bool exactly_collinear(const Vec2<double>& p, const Vec2<double>& q, const Vec2<double>& r);

/// Where p lies with respect to the closed segment [a, b], exactly.
enum class SegmentLocation { Off, AtStart, AtEnd, Inside };

SegmentLocation locate_on_segment_exact(const Vec2<double>& p, const Vec2<double>& a, const Vec2<double>& b);

/// p lies on the closed segment [a, b] (endpoints included), exactly.
bool point_on_segment_exact(const Vec2<double>& p, const Vec2<double>& a, const Vec2<double>& b);

/// Where p lies on a polyline (sample convention of validation.hpp), exactly: at a sample (a joint between
/// two segments unless it is an end of an open polyline), strictly inside a segment, or off the polyline.
/// Reports the first match in sample, then segment order. O(n) exact tests: for degenerate cases and
/// regression checks, not for inner loops.
struct PolylineLocation {
  enum class Kind { Off, AtSample, InsideSegment } kind = Kind::Off;
  std::size_t index = 0;  // the sample or the segment
};

PolylineLocation locate_on_polyline_exact(const Vec2<double>& p, const std::vector<Vec2<double>>& pts, bool closed);

/// The exact decimal expansion of a double (see the header comment).
std::string exact_decimal(double x);

/// |p_(i+1) - p_i|^2 for every segment i (with the closing segment when closed), exact decimals.
std::vector<std::string> exact_squared_chords(const std::vector<Vec2<double>>& pts, bool closed);

/// Signed area of the closed polygon through pts (shoelace formula, > 0 counter-clockwise), exact decimal.
std::string exact_signed_area(const std::vector<Vec2<double>>& pts);

}  // namespace rollkin::geometry
