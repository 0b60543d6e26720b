// Closest points, crossings and touching zones of two polylines (geometry/contact.hpp).
//
// CGAL 5.5's AABB tree is three-dimensional, so find_contact lifts the planar segments to z = 0: distances
// and intersections of coplanar 3D segments are those of the planar ones.
#include "rollkin/geometry/contact.hpp"

#include "epick.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>

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
using SegmentBox = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

// Samples per polyline in find_contact's first, coarse pass.
constexpr std::size_t kCoarseSamples = 256;

/// A polyline with the sample convention of geometry/validation.hpp.
struct Polyline {
  const std::vector<Vec2<double>>& pts;
  bool closed;

  std::size_t segments() const { return closed ? pts.size() : pts.size() - 1; }
  const Vec2<double>& start(std::size_t i) const { return pts[i]; }
  const Vec2<double>& end(std::size_t i) const { return pts[(i + 1) % pts.size()]; }
  Segment2 segment(std::size_t i) const { return Segment2(to_point(start(i)), to_point(end(i))); }
  bool consecutive(std::size_t i, std::size_t j) const {
    return j == i + 1 || (closed && i + 1 == segments() && j == 0);
  }

  /// Sample i as a point of the polyline (the last sample of an open one ends the last segment).
  PolylinePoint at_sample(std::size_t i) const {
    return i < segments() ? PolylinePoint{i, 0.0, pts[i]} : PolylinePoint{i - 1, 1.0, pts[i]};
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

// ---- check_interference: box intersection and union-find -------------------------------------------

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

/// Segment pairs within touch_tol: CGAL::box_intersection_d (bipartite) between a's segment boxes grown by
/// touch_tol (plus a few ulps so rounding never drops a pair) and b's boxes; each candidate measured with
/// CGAL::squared_distance and tested with the exact predicate CGAL::do_intersect.
std::vector<NearPair> near_pairs(const Polyline& a, const Polyline& b, double touch_tol) {
  const double scale = std::max(max_abs_coordinate(a.pts), max_abs_coordinate(b.pts));
  const double margin = touch_tol + 4 * epsilon<double>() * scale;
  std::vector<SegmentBox> a_boxes, b_boxes;
  for (std::size_t i = 0; i < a.segments(); ++i) {
    const CGAL::Bbox_2 bb = a.segment(i).bbox();
    const CGAL::Bbox_2 grown(bb.xmin() - margin, bb.ymin() - margin, bb.xmax() + margin, bb.ymax() + margin);
    a_boxes.emplace_back(grown, i);
  }
  for (std::size_t j = 0; j < b.segments(); ++j) b_boxes.emplace_back(b.segment(j).bbox(), j);

  std::vector<NearPair> pairs;
  CGAL::box_intersection_d(a_boxes.begin(), a_boxes.end(), b_boxes.begin(), b_boxes.end(),
                           [&](const SegmentBox& ba, const SegmentBox& bb) {
                             const Segment2 s = a.segment(ba.info()), t = b.segment(bb.info());
                             const bool crossing = CGAL::do_intersect(s, t);
                             const double d = crossing ? 0.0 : std::sqrt(CGAL::squared_distance(s, t));
                             if (d <= touch_tol) pairs.push_back({ba.info(), bb.info(), d, crossing});
                           });
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

/// Joins consecutive near segments of one polyline (offset: its first node in the union-find).
void unite_runs(const Polyline& p, const std::vector<bool>& near, std::size_t offset, UnionFind& uf) {
  for (std::size_t i = 0; i < p.segments(); ++i) {
    const std::size_t next = (i + 1) % p.segments();
    if (near[i] && near[next] && p.consecutive(i, next)) uf.unite(offset + i, offset + next);
  }
}

std::vector<ContactZone> zones_of(const Polyline& a, const Polyline& b, const std::vector<NearPair>& pairs) {
  const std::size_t na = a.segments();
  std::vector<bool> near_a(na, false), near_b(b.segments(), false);
  UnionFind uf(na + b.segments());
  for (const auto& p : pairs) {
    near_a[p.i] = near_b[p.j] = true;
    uf.unite(p.i, na + p.j);
  }
  unite_runs(a, near_a, 0, uf);
  unite_runs(b, near_b, na, uf);

  std::map<std::size_t, ContactZone> by_root;
  for (std::size_t i = 0; i < na; ++i)
    if (near_a[i]) by_root[uf.find(i)].a_segments.push_back(i);
  for (std::size_t j = 0; j < b.segments(); ++j)
    if (near_b[j]) by_root[uf.find(na + j)].b_segments.push_back(j);
  std::map<std::size_t, const NearPair*> closest;
  for (const auto& p : pairs) {
    const std::size_t root = uf.find(p.i);
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
  const std::vector<NearPair> crossings = near_pairs(a, b, 0.0);  // sorted by (a segment, b segment)
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

InterferenceReport check_interference(const std::vector<Vec2<double>>& a_pts, bool a_closed,
                                      const std::vector<Vec2<double>>& b_pts, bool b_closed, double touch_tol) {
  const Polyline a{a_pts, a_closed}, b{b_pts, b_closed};
  require_samples(a, "a");
  require_samples(b, "b");
  const std::vector<NearPair> pairs = near_pairs(a, b, touch_tol);

  InterferenceReport report;
  for (const auto& p : pairs) {
    if (!p.crossing) continue;
    const auto points = segment_closest_points(a, p.i, b, p.j, true);
    report.crossings.push_back({points.first, points.second});
  }
  report.penetrate = !report.crossings.empty();
  report.zones = zones_of(a, b, pairs);
  return report;
}

}  // namespace rollkin::geometry
