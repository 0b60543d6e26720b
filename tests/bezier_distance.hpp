// Distance from a point to the pieces of a Bezier path, for tests that compare a read contour with points an
// independent reader (ezdxf, svgelements) or a closed form puts on it.
#pragma once

#include "rollkin/profile/bezier.hpp"

#include <algorithm>
#include <cstddef>

namespace rollkin::testing {

/// Distance from q to segment i of `path`: the best of 64 samples of its own t in [0, 1], then Newton on
/// (C(t) - q) . C'(t) = 0 from there.
inline double distance_to_piece(const BezierPath<double>& path, std::size_t i, const Vec2<double>& q) {
  double best_t = 0, best = 1e300;
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 64.0, d = (path.segment_jet(i, t, 0).p - q).norm();
    if (d < best) best = d, best_t = t;
  }
  double t = best_t;
  for (int it = 0; it < 8; ++it) {
    const auto j = path.segment_jet(i, t, 2);
    const double f = (j.p - q).dot(j.d1), df = j.d1.squaredNorm() + (j.p - q).dot(j.d2);
    if (!(df > 0)) break;
    t = std::min(1.0, std::max(0.0, t - f / df));
  }
  return std::min(best, (path.segment_jet(i, t, 0).p - q).norm());
}

/// Distance from q to the whole path (every segment).
inline double distance_to_path(const BezierPath<double>& path, const Vec2<double>& q) {
  double best = 1e300;
  for (std::size_t i = 0; i < path.segments().size(); ++i) best = std::min(best, distance_to_piece(path, i, q));
  return best;
}

}  // namespace rollkin::testing
