// Points, distances and bounding boxes of rational Bezier segments (segment_geometry.hpp).
#include "segment_geometry.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <array>
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

namespace {

/// de Casteljau on n homogeneous points in p and w (overwritten).
V de_casteljau(V* p, double* w, std::size_t n, double t) {
  for (std::size_t r = 1; r < n; ++r)
    for (std::size_t i = 0; i + r < n; ++i) {
      p[i] = (1 - t) * p[i] + t * p[i + 1];
      w[i] = (1 - t) * w[i] + t * w[i + 1];
    }
  return p[0] / w[0];
}

}  // namespace

V segment_point(const BezierSegment<double>& s, double t) {
  // On the stack up to degree 7 (lines, arcs, cubics: every call of a listing), else on the heap: the heap's
  // allocations were half of the time of listing a drawing.
  constexpr std::size_t kStack = 8;
  const std::size_t n = s.points.size();
  std::array<V, kStack> ps;
  std::array<double, kStack> ws;
  std::vector<V> ph;
  std::vector<double> wh;
  if (n > kStack) ph.resize(n), wh.resize(n);
  V* p = n > kStack ? ph.data() : ps.data();
  double* w = n > kStack ? wh.data() : ws.data();
  for (std::size_t i = 0; i < n; ++i) w[i] = s.weight(i), p[i] = s.points[i] * w[i];
  return de_casteljau(p, w, n, t);
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

std::vector<V> near_candidates(const std::vector<BezierSegment<double>>& segments) {
  std::vector<V> at{segment_point(segments[segments.size() / 2], 0.5)};
  const std::size_t count = std::min<std::size_t>(64, 4 * segments.size());
  for (std::size_t k = 0; k < count; ++k) {
    const double u = (k + 0.5) * static_cast<double>(segments.size()) / static_cast<double>(count);
    const std::size_t i = std::min(segments.size() - 1, static_cast<std::size_t>(u));
    at.push_back(segment_point(segments[i], u - static_cast<double>(i)));
  }
  return at;
}

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using GeoPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using GeoBox = bg::model::box<GeoPoint>;
using Entry = std::pair<GeoBox, std::size_t>;  // a segment's control-point box, its index in Tree::segments

struct SegmentIndex::Tree {
  std::vector<std::pair<const BezierSegment<double>*, std::size_t>> segments;
  bgi::rtree<Entry, bgi::rstar<16>> boxes;
};

namespace {

std::vector<Entry> entries_of(const std::vector<std::pair<const BezierSegment<double>*, std::size_t>>& segments) {
  std::vector<Entry> out;
  out.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    V lo = segments[i].first->points.front(), hi = lo;
    for (const V& p : segments[i].first->points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    out.emplace_back(GeoBox(GeoPoint(lo.x(), lo.y()), GeoPoint(hi.x(), hi.y())), i);
  }
  return out;
}

}  // namespace

SegmentIndex::SegmentIndex(const std::vector<std::pair<const BezierSegment<double>*, std::size_t>>& segments)
    : tree_(new Tree{segments, bgi::rtree<Entry, bgi::rstar<16>>(entries_of(segments))}) {}  // packed (bulk) load

SegmentIndex::~SegmentIndex() = default;

bool SegmentIndex::other_within(const V& q, double d, std::size_t owner) const {
  const GeoBox around(GeoPoint(q.x() - d, q.y() - d), GeoPoint(q.x() + d, q.y() + d));
  for (auto it = tree_->boxes.qbegin(bgi::intersects(around)); it != tree_->boxes.qend(); ++it) {
    const auto& [segment, its_owner] = tree_->segments[it->second];
    if (its_owner != owner && hull_distance(*segment, q) <= d && distance_to_segment(*segment, q) <= d) return true;
  }
  return false;
}

}  // namespace rollkin::io
