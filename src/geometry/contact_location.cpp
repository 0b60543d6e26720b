// Initial contact of two placed contours (geometry/contact.hpp, locate_contact): sampling in the world
// frame, then the closest points of the two polylines from find_contact.
#include "rollkin/geometry/contact.hpp"

#include "rollkin/profile/profile.hpp"

namespace rollkin::geometry {

namespace {

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

std::array<double, 2> locate_contact(const Contour<double>& a, const SE2<double>& pose_a, const Contour<double>& b,
                                     const SE2<double>& pose_b, int samples) {
  const WorldSamples wa = sample_in_world(a, pose_a, samples);
  const WorldSamples wb = sample_in_world(b, pose_b, samples);
  const ContactCandidate cc = find_contact(wa.points, wa.closed, wb.points, wb.closed);
  return {parameter_at(wa, cc.on_a), parameter_at(wb, cc.on_b)};
}

}  // namespace rollkin::geometry
