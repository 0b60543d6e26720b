// Contact location (geometry/contact.hpp): the closest points of two polylines (find_contact: crossings from
// the segment hierarchies of interference.cpp, otherwise AABB-tree closest-point queries), and the initial
// contact of two placed contours (locate_contact: sampling in the world frame, then find_contact).
//
// CGAL 5.5's AABB tree is three-dimensional, so find_contact lifts the planar segments to z = 0: distances
// and intersections of coplanar 3D segments are those of the planar ones.
#include "rollkin/geometry/contact.hpp"

#include "rollkin/profile/profile.hpp"
#include "rollkin/se2.hpp"

#include "epick.hpp"
#include "segment_pairs.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rollkin::geometry {

namespace {

using detail::Epick;
using detail::NearPair;
using detail::Polyline;
using detail::max_abs_coordinate;
using detail::near_pairs;
using detail::require_samples;
using detail::rounding_margin;
using detail::segment_closest_points;

using Point3 = Epick::Point_3;
using Segment3 = Epick::Segment_3;
using Segment3Iterator = std::vector<Segment3>::const_iterator;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, CGAL::AABB_segment_primitive<Epick, Segment3Iterator>>>;

// Samples per polyline in find_contact's first, coarse pass.
constexpr std::size_t kCoarseSamples = 256;

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

/// Samples of a contour in the world: parameters (a closed contour's list ends with its domain's hi, the
/// implicit closing segment's end) and points.
struct WorldSamples {
  std::vector<double> u;
  std::vector<Vec2<double>> points;
  bool closed = false;
};

WorldSamples sample_in_world(const Contour<double>& c, const SE2<double>& pose, int n) {
  WorldSamples w;
  const Domain<double> d = c.domain();
  w.closed = d.closed;
  for (int i = 0; i < n; ++i) {
    const double t = d.sample(i, n);
    w.u.push_back(t);
    w.points.push_back(pose.act(c.jet(t, 0).p));
  }
  if (d.closed) w.u.push_back(d.hi);
  return w;
}

double parameter_at(const WorldSamples& w, const PolylinePoint& on) {
  const std::size_t s = on.segment;
  return w.u[s] + on.fraction * (w.u[s + 1] - w.u[s]);
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

std::array<double, 2> locate_contact(const Contour<double>& a, const SE2<double>& pose_a, const Contour<double>& b,
                                     const SE2<double>& pose_b, int samples) {
  const WorldSamples wa = sample_in_world(a, pose_a, samples);
  const WorldSamples wb = sample_in_world(b, pose_b, samples);
  const ContactCandidate cc = find_contact(wa.points, wa.closed, wb.points, wb.closed);
  return {parameter_at(wa, cc.on_a), parameter_at(wb, cc.on_b)};
}

}  // namespace rollkin::geometry
