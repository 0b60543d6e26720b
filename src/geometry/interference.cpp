// Crossings and touching zones of two polylines (geometry/contact.hpp, check_interference): bounding-circle
// hierarchies (SegmentHierarchy) descended together, each candidate pair tested with the exact predicates of
// EPICK, and the near pairs grouped into zones by union-find.
#include "rollkin/geometry/contact.hpp"

#include "rollkin/se2.hpp"

#include "epick.hpp"
#include "segment_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <string>

namespace rollkin::geometry {
namespace {

using detail::NearPair;
using detail::Polyline;
using detail::Segment2;
using detail::max_abs_coordinate;
using detail::near_pairs;
using detail::require_samples;
using detail::rounding_margin;
using detail::segment_closest_points;

constexpr std::size_t kLeafSegments = 4;  // segments per leaf of a SegmentHierarchy

CGAL::Bbox_2 grown(const CGAL::Bbox_2& b, double margin) {
  return CGAL::Bbox_2(b.xmin() - margin, b.ymin() - margin, b.xmax() + margin, b.ymax() + margin);
}

/// Circles of na and nb (moved by b_to_a) farther apart than margin.
bool far_apart(const SegmentHierarchy::Node& na, const SegmentHierarchy::Node& nb, const SE2<double>& b_to_a,
               double margin) {
  const double reach = na.radius + nb.radius + margin;
  return (na.centre - b_to_a.act(nb.centre)).squaredNorm() > reach * reach;
}

}  // namespace

namespace detail {

std::pair<PolylinePoint, PolylinePoint> segment_closest_points(const Polyline& a, std::size_t i, const Polyline& b,
                                                               std::size_t j, bool crossing) {
  if (crossing) {
    const Vec2<double> x = detail::common_point(a.segment(i), b.segment(j));
    return {a.locate(i, x), b.locate(j, x)};
  }
  std::pair<PolylinePoint, PolylinePoint> best;
  double best_d = std::numeric_limits<double>::infinity();
  auto consider = [&](const PolylinePoint& pa, const PolylinePoint& pb) {
    const double d = (pa.point - pb.point).squaredNorm();
    if (d < best_d) best_d = d, best = {pa, pb};
  };
  consider(PolylinePoint{i, 0.0, a.start(i)}, b.project(j, a.start(i)));
  consider(PolylinePoint{i, 1.0, a.end(i)}, b.project(j, a.end(i)));
  consider(a.project(i, b.start(j)), PolylinePoint{j, 0.0, b.start(j)});
  consider(a.project(i, b.end(j)), PolylinePoint{j, 1.0, b.end(j)});
  return best;
}

double max_abs_coordinate(const std::vector<Vec2<double>>& pts) {
  double m = 0;
  for (const auto& p : pts) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

double rounding_margin(double touch_tol, double scale) { return touch_tol + 8 * epsilon<double>() * scale; }

std::vector<NearPair> near_pairs(const SegmentHierarchy& a, const SegmentHierarchy& b, const SE2<double>& b_to_a,
                                 const Polyline& b_in_a, double touch_tol, double margin) {
  const Polyline pa{a.points(), a.closed()};
  std::vector<NearPair> pairs;
  thread_local std::vector<std::pair<int, int>> stack;  // node pairs to visit (kept: no allocation per call)
  stack.assign(1, {0, 0});
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const SegmentHierarchy::Node& na = a.nodes()[static_cast<std::size_t>(i)];
    const SegmentHierarchy::Node& nb = b.nodes()[static_cast<std::size_t>(j)];
    if (far_apart(na, nb, b_to_a, margin)) continue;
    const bool a_leaf = na.left < 0, b_leaf = nb.left < 0;
    if (!a_leaf && (b_leaf || na.radius >= nb.radius)) {
      stack.emplace_back(na.left, j);
      stack.emplace_back(na.right, j);
    } else if (!b_leaf) {
      stack.emplace_back(i, nb.left);
      stack.emplace_back(i, nb.right);
    } else {
      for (std::size_t sj = nb.first; sj < nb.last; ++sj) {
        const Segment2 t = b_in_a.segment(sj);
        const CGAL::Bbox_2 near_t = grown(t.bbox(), margin);
        for (std::size_t si = na.first; si < na.last; ++si) {
          const Segment2 s = pa.segment(si);
          if (!CGAL::do_overlap(s.bbox(), near_t)) continue;
          const bool crossing = CGAL::do_intersect(s, t);
          const double d = crossing ? 0.0 : std::sqrt(CGAL::squared_distance(s, t));
          if (d <= touch_tol) pairs.push_back({si, sj, d, crossing});
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const NearPair& p, const NearPair& q) {
    return p.i != q.i ? p.i < q.i : p.j < q.j;
  });
  return pairs;
}

}  // namespace detail

namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t x, std::size_t y) { parent_[find(x)] = find(y); }

 private:
  std::vector<std::size_t> parent_;
};

/// The sorted distinct segments of one side of the pairs (first: a's, else b's).
std::vector<std::size_t> near_segments(const std::vector<NearPair>& pairs, bool first) {
  std::vector<std::size_t> s;
  s.reserve(pairs.size());
  for (const auto& p : pairs) s.push_back(first ? p.i : p.j);
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

/// Position of segment k in the sorted list `near` (k is in it).
std::size_t rank_of(const std::vector<std::size_t>& near, std::size_t k) {
  return static_cast<std::size_t>(std::lower_bound(near.begin(), near.end(), k) - near.begin());
}

/// Joins consecutive near segments of one polyline (`near` sorted; offset: its first node in the union-find).
/// Consecutive segments are neighbours in the list, or its last and first ones across a closed polyline's seam.
void unite_runs(const Polyline& p, const std::vector<std::size_t>& near, std::size_t offset, UnionFind& uf) {
  for (std::size_t r = 0; r + 1 < near.size(); ++r)
    if (p.consecutive(near[r], near[r + 1])) uf.unite(offset + r, offset + r + 1);
  if (near.size() > 1 && p.consecutive(near.back(), near.front())) uf.unite(offset + near.size() - 1, offset);
}

/// Zones of the near pairs: work proportional to the number of pairs, not to the polylines' sizes.
std::vector<ContactZone> zones_of(const Polyline& a, const Polyline& b, const std::vector<NearPair>& pairs) {
  const std::vector<std::size_t> near_a = near_segments(pairs, true), near_b = near_segments(pairs, false);
  const std::size_t na = near_a.size();
  UnionFind uf(na + near_b.size());
  for (const auto& p : pairs) uf.unite(rank_of(near_a, p.i), na + rank_of(near_b, p.j));
  unite_runs(a, near_a, 0, uf);
  unite_runs(b, near_b, na, uf);

  std::map<std::size_t, ContactZone> by_root;
  for (std::size_t r = 0; r < na; ++r) by_root[uf.find(r)].a_segments.push_back(near_a[r]);
  for (std::size_t r = 0; r < near_b.size(); ++r) by_root[uf.find(na + r)].b_segments.push_back(near_b[r]);
  std::map<std::size_t, const NearPair*> closest;
  for (const auto& p : pairs) {
    const std::size_t root = uf.find(rank_of(near_a, p.i));
    by_root[root].penetrating |= p.crossing;
    const NearPair*& c = closest[root];
    if (!c || p.distance < c->distance) c = &p;
  }

  std::vector<ContactZone> zones;
  for (auto& [root, zone] : by_root) {
    const NearPair& c = *closest[root];
    std::tie(zone.on_a, zone.on_b) = segment_closest_points(a, c.i, b, c.j, c.crossing);
    zone.distance = c.distance;
    zones.push_back(std::move(zone));
  }
  std::sort(zones.begin(), zones.end(),
            [](const ContactZone& z, const ContactZone& w) { return z.on_a.segment < w.on_a.segment; });
  return zones;
}

}  // namespace

SegmentHierarchy::SegmentHierarchy(std::vector<Vec2<double>> points, bool closed)
    : points_(std::move(points)), closed_(closed) {
  require_samples(Polyline{points_, closed_}, "of the hierarchy");
  extent_ = max_abs_coordinate(points_);
  nodes_.reserve(4 * (segments() / kLeafSegments + 1));
  build(0, segments());
}

/// The node of segments first .. last - 1: the circle about the centre of the bounding box of their end
/// points, through the farthest one (segments are convex, so they lie inside); split in halves down to
/// kLeafSegments.
int SegmentHierarchy::build(std::size_t first, std::size_t last) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Vec2<double> lo = points_[first], hi = lo;
  for (std::size_t k = first; k <= last; ++k) {
    const Vec2<double>& p = points_[k % points_.size()];
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec2<double> centre = (lo + hi) / 2;
  double radius = 0;
  for (std::size_t k = first; k <= last; ++k) radius = std::max(radius, (points_[k % points_.size()] - centre).norm());
  int left = -1, right = -1;
  if (last - first > kLeafSegments) {
    const std::size_t mid = first + (last - first) / 2;
    left = build(first, mid);
    right = build(mid, last);
  }
  nodes_[static_cast<std::size_t>(index)] = Node{centre, radius, first, last, left, right};
  return index;
}

InterferenceReport check_interference(const SegmentHierarchy& a, const SE2<double>& g_a, const SegmentHierarchy& b,
                                      const SE2<double>& g_b, double touch_tol) {
  const SE2<double> b_to_a = g_a.inverse() * g_b;
  const double margin = rounding_margin(touch_tol, std::max(a.extent(), b.extent() + b_to_a.translation().norm()));
  InterferenceReport report;
  if (far_apart(a.nodes().front(), b.nodes().front(), b_to_a, margin)) return report;

  const Polyline pa{a.points(), a.closed()}, pb{b.points(), b.closed(), &b_to_a};
  const std::vector<NearPair> pairs = near_pairs(a, b, b_to_a, pb, touch_tol, margin);
  for (const auto& p : pairs) {
    if (!p.crossing) continue;
    const auto points = segment_closest_points(pa, p.i, pb, p.j, true);
    report.crossings.push_back({points.first, points.second});
  }
  report.penetrate = !report.crossings.empty();
  report.zones = zones_of(pa, pb, pairs);
  // Back from a's frame to the world.
  for (Crossing& c : report.crossings) c.on_a.point = g_a.act(c.on_a.point), c.on_b.point = g_a.act(c.on_b.point);
  for (ContactZone& z : report.zones) z.on_a.point = g_a.act(z.on_a.point), z.on_b.point = g_a.act(z.on_b.point);
  return report;
}

InterferenceReport check_interference(const std::vector<Vec2<double>>& a_pts, bool a_closed,
                                      const std::vector<Vec2<double>>& b_pts, bool b_closed, double touch_tol) {
  const SE2<double> identity;
  return check_interference(SegmentHierarchy(a_pts, a_closed), identity, SegmentHierarchy(b_pts, b_closed), identity,
                            touch_tol);
}

}  // namespace rollkin::geometry
