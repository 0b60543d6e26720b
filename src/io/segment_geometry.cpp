// Points, distances and bounding boxes of rational Bezier segments (segment_geometry.hpp).
#include "segment_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollkin::io {
namespace {

using V = Vec2<double>;

const double kGolden = (std::sqrt(5.0) - 1) / 2;

/// The largest of f over [0, 1]: the best of `samples` + 1 samples, refined by a golden-section search between
/// its neighbours.
template <class F> double largest(F f, int samples) {
  int at = 0;
  for (int i = 1; i <= samples; ++i)
    if (f(double(i) / samples) > f(double(at) / samples)) at = i;
  double a = std::max(0, at - 1) / double(samples), b = std::min(samples, at + 1) / double(samples);
  for (int it = 0; it < 80 && b - a > 1e-16; ++it) {
    const double c = b - kGolden * (b - a), e = a + kGolden * (b - a);
    if (f(c) > f(e)) b = e;
    else a = c;
  }
  return std::max(f(double(at) / samples), f((a + b) / 2));
}

/// Lower bound of the distance from q to a segment: to the box of its control points.
double hull_distance(const BezierSegment<double>& s, const V& q) {
  V lo = s.points.front(), hi = lo;
  for (const V& p : s.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (lo - q).cwiseMax(q - hi).cwiseMax(V(0, 0)).norm();
}

}  // namespace

V segment_point(const BezierSegment<double>& s, double t) {
  std::vector<V> p(s.points.size());
  std::vector<double> w(s.points.size());
  for (std::size_t i = 0; i < p.size(); ++i) w[i] = s.weight(i), p[i] = s.points[i] * w[i];
  for (std::size_t r = 1; r < p.size(); ++r)
    for (std::size_t i = 0; i + r < p.size(); ++i) {
      p[i] = (1 - t) * p[i] + t * p[i + 1];
      w[i] = (1 - t) * w[i] + t * w[i + 1];
    }
  return p[0] / w[0];
}

double distance_to_segment(const BezierSegment<double>& s, const V& q) {
  constexpr int kSamples = 64;
  std::vector<double> d(kSamples + 1);
  for (int k = 0; k <= kSamples; ++k) d[k] = (segment_point(s, double(k) / kSamples) - q).norm();
  double best = *std::min_element(d.begin(), d.end());
  for (int k = 0; k <= kSamples; ++k) {
    if ((k > 0 && d[k - 1] < d[k]) || (k < kSamples && d[k + 1] < d[k])) continue;
    double a = double(std::max(0, k - 1)) / kSamples, b = double(std::min(kSamples, k + 1)) / kSamples;
    double x1 = b - kGolden * (b - a), x2 = a + kGolden * (b - a);
    double f1 = (segment_point(s, x1) - q).norm(), f2 = (segment_point(s, x2) - q).norm();
    for (int it = 0; it < 80 && b - a > 1e-17; ++it) {
      if (f1 < f2) {
        b = x2, x2 = x1, f2 = f1, x1 = b - kGolden * (b - a), f1 = (segment_point(s, x1) - q).norm();
      } else {
        a = x1, x1 = x2, f1 = f2, x2 = a + kGolden * (b - a), f2 = (segment_point(s, x2) - q).norm();
      }
    }
    best = std::min({best, f1, f2});
  }
  return best;
}

double distance_to_segments(const std::vector<BezierSegment<double>>& segments, const V& q) {
  double best = std::numeric_limits<double>::infinity();
  for (const BezierSegment<double>& s : segments)
    if (hull_distance(s, q) < best) best = std::min(best, distance_to_segment(s, q));
  return best;
}

void segments_box(const std::vector<BezierSegment<double>>& segments, V& lo, V& hi) {
  lo = hi = segments.front().points.front();
  for (const BezierSegment<double>& s : segments)
    for (int axis = 0; axis < 2; ++axis) {
      hi[axis] = std::max(hi[axis], largest([&](double t) { return segment_point(s, t)[axis]; }, 32));
      lo[axis] = std::min(lo[axis], -largest([&](double t) { return -segment_point(s, t)[axis]; }, 32));
    }
}

}  // namespace rollkin::io
