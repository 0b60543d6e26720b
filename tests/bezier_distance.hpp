// Distance from a point to the pieces of a Bezier path, for tests that compare a read contour with points an
// independent reader (ezdxf, svgelements) or a closed form puts on it.
#pragma once

#include "rollkin/profile/bezier.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace rollkin::testing {

/// The smallest distance from q to segment i of `path` over t in [a, b]: 32 samples; in every sample interval
/// where f(t) = (C(t) - q) . C'(t) (half the derivative of the squared distance) goes from negative to
/// positive, the local minimum there by Newton steps safeguarded by bisection; around every sample nearer
/// than both its neighbours the same again on the two intervals beside it, `depth` times (rational segments
/// with uneven weights turn so tightly that the distance has several local minima within one interval).
inline double distance_on(const BezierPath<double>& path, std::size_t i, const Vec2<double>& q, double a, double b, int depth) {
  constexpr int kSamples = 32;
  std::array<double, kSamples + 1> t{}, f{}, d{};
  for (int k = 0; k <= kSamples; ++k) {
    t[k] = a + (b - a) * k / kSamples;
    const auto j = path.segment_jet(i, t[k], 1);
    d[k] = (j.p - q).norm();
    f[k] = (j.p - q).dot(j.d1);
  }
  double best = *std::min_element(d.begin(), d.end());
  for (int k = 0; k < kSamples; ++k) {
    if (!(f[k] < 0 && f[k + 1] >= 0)) continue;
    double lo = t[k], hi = t[k + 1], x = lo + (hi - lo) / 2;
    for (int it = 0; it < 200; ++it) {
      const auto j = path.segment_jet(i, x, 2);
      const double fx = (j.p - q).dot(j.d1), dfx = j.d1.squaredNorm() + (j.p - q).dot(j.d2);
      best = std::min(best, (j.p - q).norm());
      (fx < 0 ? lo : hi) = x;
      double next = x - fx / dfx;
      if (!(dfx > 0) || !(next > lo && next < hi)) next = lo + (hi - lo) / 2;
      if (!(lo < next && next < hi)) break;
      x = next;
    }
  }
  if (depth > 0)
    for (int k = 0; k <= kSamples; ++k)
      if (!((k > 0 && d[k - 1] < d[k]) || (k < kSamples && d[k + 1] < d[k])))
        best = std::min(best, distance_on(path, i, q, t[std::max(0, k - 1)], t[std::min(kSamples, k + 1)], depth - 1));
  return best;
}

/// Distance from q to segment i of `path` (distance_on over its whole t in [0, 1], refined twice).
inline double distance_to_piece(const BezierPath<double>& path, std::size_t i, const Vec2<double>& q) {
  return distance_on(path, i, q, 0.0, 1.0, 2);
}

/// Distance from q to the whole path (every segment).
inline double distance_to_path(const BezierPath<double>& path, const Vec2<double>& q) {
  double best = 1e300;
  for (std::size_t i = 0; i < path.segments().size(); ++i) best = std::min(best, distance_to_piece(path, i, q));
  return best;
}

}  // namespace rollkin::testing
