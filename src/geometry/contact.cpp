// Closest points, crossings and touching zones of two polylines (geometry/contact.hpp).
//
// CGAL 5.5's AABB tree is three-dimensional, so find_contact lifts the planar segments to z = 0: distances
// and intersections of coplanar 3D segments are those of the planar ones.
#include "rollkin/geometry/contact.hpp"

#include "rollkin/se2.hpp"

#include "epick.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

namespace rollkin::geometry {
namespace {

using detail::Epick;
using detail::Segment2;
using detail::to_point;

using Point3 = Epick::Point_3;
using Segment3 = Epick::Segment_3;
using Segment3Iterator = std::vector<Segment3>::const_iterator;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, CGAL::AABB_segment_primitive<Epick, Segment3Iterator>>>;

// Samples per polyline in find_contact's first, coarse pass.
constexpr std::size_t kCoarseSamples = 256;

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

void require_samples(const Polyline& p, const char* name) {
  if (p.pts.size() < (p.closed ? 3u : 2u))
    throw std::invalid_argument(std::string("find_contact/check_interference: polyline ") + name + " has " +
                                std::to_string(p.pts.size()) + " samples; it needs at least " +
                                (p.closed ? "3 (closed)" : "2 (open)"));
}

// ---- find_contact: AABB trees -----------------------------------------------------------------------

Point3 lift(const Vec2<double>& v) { return Point3(v.x(), v.y(), 0); }

std::vector<Segment3> lifted_segments(const Polyline& p) {
  std::vector<Segment3> s;
  s.reserve(p.segments());
  for (std::size_t i = 0; i < p.segments(); ++i) s.emplace_back(lift(p.start(i)), lift(p.end(i)));
  return s;
}

/// Closest point of `to`'s AABB tree to every `stride`-th sample of `from`
/// (CGAL::AABB_tree::closest_point_and_primitive), keeping the best pair in `best` (`from` is polyline a
/// when from_is_a). Two savings, both exact:
/// - a sample p is skipped when the last queried sample q proves it cannot beat the best pair:
///   dist(p, to) >= dist(q, to) - |p - q| >= best (triangle inequality);
/// - each query starts from the previous answer as its hint, which bounds the search ball at once
///   (consecutive samples have nearby answers).
void closest_to_samples(const Polyline& from, const Polyline& to, const std::vector<Segment3>& segs,
                        const AabbTree& tree, bool from_is_a, std::size_t stride, ContactCandidate& best) {
  AabbTree::Point_and_primitive_id hint(segs.front().source(), segs.begin());
  Vec2<double> queried = from.pts.front();
  double queried_distance = -1;  // no query yet
  for (std::size_t i = 0; i < from.pts.size(); i += stride) {
    const Vec2<double>& p = from.pts[i];
    if (queried_distance - (p - queried).norm() >= best.distance) continue;
    hint = tree.closest_point_and_primitive(lift(p), hint);
    const std::size_t j = static_cast<std::size_t>(hint.second - segs.begin());
    const PolylinePoint on_from = from.at_sample(i);
    const PolylinePoint on_to = to.project(j, p);
    const double d = (on_to.point - p).norm();
    queried = p;
    queried_distance = d;
    if (d >= best.distance) continue;
    best.distance = d;
    best.on_a = from_is_a ? on_from : on_to;
    best.on_b = from_is_a ? on_to : on_from;
  }
}

// ---- check_interference: near segment pairs and union-find ---------------------------------------------

struct NearPair {
  std::size_t i, j;  // segment of a, segment of b
  double distance;
  bool crossing;
};

/// Closest points of two segments. Crossing segments meet at their common point; otherwise the minimum
/// is attained at an endpoint of one of them, so it is the best of the four endpoint projections.
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

// ---- check_interference: bounding-circle hierarchies ----------------------------------------------------

constexpr std::size_t kLeafSegments = 4;  // segments per leaf of a SegmentHierarchy

/// Distance within which candidates are kept: touch_tol and a few ulps of the coordinates' scale, so that no
/// pair within touch_tol is dropped because a circle or a moved point was rounded.
double rounding_margin(double touch_tol, double scale) { return touch_tol + 8 * epsilon<double>() * scale; }

CGAL::Bbox_2 grown(const CGAL::Bbox_2& b, double margin) {
  return CGAL::Bbox_2(b.xmin() - margin, b.ymin() - margin, b.xmax() + margin, b.ymax() + margin);
}

/// Segment pairs of a and b (b's points already moved into a's frame: b_in_a) within touch_tol, found by
/// descending both hierarchies together (circles moved by b_to_a); each candidate measured with
/// CGAL::squared_distance and tested with the exact predicate CGAL::do_intersect. Sorted by (i, j).
/// Circles of na and nb (moved by b_to_a) farther apart than margin.
bool far_apart(const SegmentHierarchy::Node& na, const SegmentHierarchy::Node& nb, const SE2<double>& b_to_a,
               double margin) {
  const double reach = na.radius + nb.radius + margin;
  return (na.centre - b_to_a.act(nb.centre)).squaredNorm() > reach * reach;
}

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

ContactCandidate find_contact(const std::vector<Vec2<double>>& a_pts, bool a_closed,
                              const std::vector<Vec2<double>>& b_pts, bool b_closed) {
  const Polyline a{a_pts, a_closed}, b{b_pts, b_closed};
  require_samples(a, "a");
  require_samples(b, "b");
  ContactCandidate best;
  const SE2<double> identity;
  const std::vector<NearPair> crossings =  // sorted by (a segment, b segment)
      near_pairs(SegmentHierarchy(a_pts, a_closed), SegmentHierarchy(b_pts, b_closed), identity, b, 0.0,
                 rounding_margin(0.0, std::max(max_abs_coordinate(a_pts), max_abs_coordinate(b_pts))));
  if (!crossings.empty()) {
    std::tie(best.on_a, best.on_b) = segment_closest_points(a, crossings.front().i, b, crossings.front().j, true);
    best.intersect = true;
    return best;
  }
  const std::vector<Segment3> a3 = lifted_segments(a), b3 = lifted_segments(b);
  AabbTree a_tree(a3.begin(), a3.end()), b_tree(b3.begin(), b3.end());
  a_tree.do_not_accelerate_distance_queries();  // every query gets a hint instead of the internal kd-tree
  b_tree.do_not_accelerate_distance_queries();
  // A coarse pass first makes `best` small, so that the full pass can skip most samples.
  best.distance = std::numeric_limits<double>::infinity();
  for (const std::size_t stride : {std::max<std::size_t>(1, std::max(a_pts.size(), b_pts.size()) / kCoarseSamples),
                                   std::size_t{1}}) {
    closest_to_samples(a, b, b3, b_tree, true, stride, best);
    closest_to_samples(b, a, a3, a_tree, false, stride, best);
  }
  return best;
}

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
