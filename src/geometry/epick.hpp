// Internal to src/geometry (not installed): the EPICK kernel and conversions shared by the CGAL-using
// translation units. EPICK = exact predicates (filtered, exact on double input), inexact constructions.
#pragma once

#include "rollkin/scalar.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/variant/get.hpp>

namespace rollkin::geometry::detail {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Epick::Point_2;
using Segment2 = Epick::Segment_2;

inline Point2 to_point(const Vec2<double>& v) { return Point2(v.x(), v.y()); }
inline Vec2<double> to_vec(const Point2& p) { return Vec2<double>(p.x(), p.y()); }

/// A point common to two segments known to intersect (CGAL::do_intersect): their crossing point, or for
/// overlapping collinear segments the start of the overlap. EPICK construction: rounded, not exact.
inline Vec2<double> common_point(const Segment2& s, const Segment2& t) {
  const auto result = CGAL::intersection(s, t);
  if (!result) return to_vec(s.source());  // not reached for intersecting segments
  if (const Point2* p = boost::get<Point2>(&*result)) return to_vec(*p);
  return to_vec(boost::get<Segment2>(*result).source());
}

}  // namespace rollkin::geometry::detail
