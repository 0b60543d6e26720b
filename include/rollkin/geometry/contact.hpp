// Contact between two sampled contours placed in one common (world) frame: where they are closest, whether
// they cross, and how many separate zones touch. Used to find the initial contact of an assembly without
// contact parameters from the user, and to flag "contours penetrate" or "touch at a second point" along a
// sweep.
//
// Part of the CGAL boundary: plain types here, CGAL (EPICK exact predicates, AABB tree) in
// src/geometry/contact_location.cpp (find_contact, locate_contact) and src/geometry/interference.cpp
// (SegmentHierarchy, check_interference). Polylines follow the sample convention of validation.hpp: segment i
// joins sample i to sample i + 1; a closed polyline has the implicit closing segment n - 1 -> 0 and does not
// repeat its first sample.
#pragma once

#include "rollkin/scalar.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace rollkin {
template <class S> class Contour;
template <class S> class SE2;
}  // namespace rollkin

namespace rollkin::geometry {

/// A point on a polyline: point = (1 - fraction) p_segment + fraction p_(segment + 1), fraction in [0, 1].
struct PolylinePoint {
  std::size_t segment = 0;
  double fraction = 0;
  Vec2<double> point = Vec2<double>::Zero();
};

/// The closest pair of points of two polylines. When they intersect, distance is 0 and both points are
/// the crossing point of the lowest-numbered crossing segment of `a` (and, for it, of `b`).
struct ContactCandidate {
  PolylinePoint on_a, on_b;
  double distance = 0;
  bool intersect = false;
};

/// Closest points of two polylines (each at least 2 samples; closed ones at least 3). Crossings are found
/// as in check_interference (circle hierarchies, exact do_intersect). Without a crossing the minimum distance
/// between two segments is attained at an endpoint of one of them, so it is the least distance from a
/// sample of either polyline to the other one: CGAL AABB-tree closest-point queries, each hinted with the
/// previous answer, samples skipped when the triangle inequality shows they cannot beat the best so far.
/// Throws std::invalid_argument for too few samples.
ContactCandidate find_contact(const std::vector<Vec2<double>>& a, bool a_closed, const std::vector<Vec2<double>>& b,
                              bool b_closed);

/// Where the polylines cross: the same point on both.
struct Crossing {
  PolylinePoint on_a, on_b;
};

/// One connected region where the polylines are within touch_tol of each other: the segments involved on
/// each (sorted indices) and the closest pair in it.
struct ContactZone {
  std::vector<std::size_t> a_segments, b_segments;
  PolylinePoint on_a, on_b;  // closest pair within the zone
  double distance = 0;
  bool penetrating = false;  // the zone contains a crossing
};

struct InterferenceReport {
  bool penetrate = false;           // some segments of a and b cross (or touch exactly)
  std::vector<Crossing> crossings;  // sorted by (a segment, b segment); a crossing exactly at a sample
                                    // appears once for each segment meeting there
  std::vector<ContactZone> zones;   // sorted by their closest pair's a segment

  std::size_t zone_count() const { return zones.size(); }
};

/// The segments of one polyline in a binary hierarchy of bounding circles over runs of consecutive
/// segments, built once in the polyline's own frame (a link's). A rigid motion moves a circle without
/// changing its radius, so one hierarchy serves every pose of its link. Throws std::invalid_argument for too
/// few samples (at least 2; closed: 3).
class SegmentHierarchy {
 public:
  struct Node {
    Vec2<double> centre = Vec2<double>::Zero();
    double radius = 0;               // every segment of the run lies in the circle
    std::size_t first = 0, last = 0;  // the run: segments first .. last - 1
    int left = -1, right = -1;        // children (-1: a leaf)
  };

  SegmentHierarchy(std::vector<Vec2<double>> points, bool closed);

  const std::vector<Vec2<double>>& points() const { return points_; }
  bool closed() const { return closed_; }
  std::size_t segments() const { return closed_ ? points_.size() : points_.size() - 1; }
  const std::vector<Node>& nodes() const { return nodes_; }  // nodes()[0] is the root
  /// Largest absolute coordinate of the points (the scale of the rounding margin).
  double extent() const { return extent_; }

 private:
  int build(std::size_t first, std::size_t last);
  std::vector<Vec2<double>> points_;
  bool closed_;
  std::vector<Node> nodes_;
  double extent_ = 0;
};

/// Crossings and touching zones of two polylines given in their own frames and placed in the world by g_a
/// and g_b (reported in world coordinates). Segment pairs closer than touch_tol (distance <= touch_tol) are
/// found by descending both hierarchies together in a's frame (a pair of circles farther apart than
/// touch_tol, plus a rounding margin, is skipped with all its segments; b's circles and the segments of the
/// leaves that come near are moved by g_a^-1 g_b), then measured with EPICK squared_distance; crossings are
/// decided by the exact predicate do_intersect on the segments as placed. Two near pairs belong to the same
/// zone when they share a segment or their segments are consecutive on a or on b (union-find), so a smooth
/// tangential contact is one zone however finely it is sampled.
InterferenceReport check_interference(const SegmentHierarchy& a, const SE2<double>& g_a, const SegmentHierarchy& b,
                                      const SE2<double>& g_b, double touch_tol);

/// The same for two polylines already in one frame.
InterferenceReport check_interference(const std::vector<Vec2<double>>& a, bool a_closed,
                                      const std::vector<Vec2<double>>& b, bool b_closed, double touch_tol);

/// The initial contact of two contours placed in the world by their links' poses: both contours sampled at
/// `samples` parameters each (Domain::sample) in world coordinates, the closest points of the polylines
/// (find_contact) and their parameters interpolated linearly within the segment. Returns {u on a, u on b}
/// in each contour's own parameter. Throws std::invalid_argument when find_contact does (too few samples).
std::array<double, 2> locate_contact(const Contour<double>& a, const SE2<double>& pose_a, const Contour<double>& b,
                                     const SE2<double>& pose_b, int samples = 2000);

}  // namespace rollkin::geometry
