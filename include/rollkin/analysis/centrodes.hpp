// Centrodes: the loci of the instant centre of the relative motion of two links, in each link's frame.
//
// With the links' spatial twists V = (v, omega) (kinematics.hpp, link_twists: a world point P moving with
// link L has velocity v_L + omega_L J P, J the rotation by 90 degrees), the instant centre of link B's motion
// relative to link A is the world point with the same velocity on both links:
//   v_A + omega_A J P = v_B + omega_B J P   =>   P = J (v_B - v_A) / (omega_B - omega_A)      (J^-1 = -J)
// It is computed from the velocity solution (the rates qdot of a sweep), not from differences of poses. Seen
// from link A it traces the fixed centrode, from link B the moving centrode; the two roll on each other
// without slipping and reproduce the relative motion (the basis of non-circular gear synthesis).
// Where omega_B = omega_A the relative motion is a translation and the centre lies at infinity in the
// direction normal to v_B - v_A; it is reported as not finite when it would lie farther than
// length_scale / sqrt(eps) from the origin.
#pragma once

#include "rollkin/kinematics.hpp"
#include "rollkin/solve/continuation.hpp"

#include <vector>

namespace rollkin {

template <class S> struct InstantCentre {
  bool finite = false;  // false: pure relative translation (direction) or no relative motion (direction 0)
  Vec2<S> world = Vec2<S>::Zero();  // the centre in the world frame (finite)
  Vec2<S> in_a = Vec2<S>::Zero();   // ... in link A's frame (on the fixed centrode when A is the ground)
  Vec2<S> in_b = Vec2<S>::Zero();   // ... in link B's frame (the moving centrode)
  Vec2<S> direction = Vec2<S>::Zero();  // not finite: unit direction of B's velocity relative to A (world)
};

/// The instant centre of link b relative to link a from the links' world poses and spatial twists.
template <class S> InstantCentre<S> instant_centre(const std::vector<SE2<S>>& pose, const std::vector<Twist<S>>& twist,
                                                   int a, int b, const S& length_scale) {
  using std::abs;
  using std::sqrt;
  InstantCentre<S> c;
  const Vec2<S> dv(twist[b].x() - twist[a].x(), twist[b].y() - twist[a].y());
  const S domega = twist[b].z() - twist[a].z();
  if (!(abs(domega) * length_scale > sqrt(epsilon<S>()) * dv.norm())) {
    if (dv.norm() > S(0)) c.direction = dv / dv.norm();
    return c;
  }
  c.finite = true;
  c.world = Vec2<S>(-dv.y(), dv.x()) / domega;
  c.in_a = pose[a].inverse().act(c.world);
  c.in_b = pose[b].inverse().act(c.world);
  return c;
}

/// The instant centre of link b relative to link a at every pose of a sweep that has one (has_pose(): solved
/// or singular with values on the branch); an unsolved pose gives a non-finite centre with zero direction.
template <class S> std::vector<InstantCentre<S>> centrodes(const Mechanism<S>& m, KinematicsData<S>& d,
                                                           const SweepResult<S>& sweep, int a, int b) {
  std::vector<InstantCentre<S>> out(sweep.poses.size());
  for (std::size_t k = 0; k < sweep.poses.size(); ++k) {
    const SweepPose<S>& p = sweep.poses[k];
    if (!p.report.has_pose()) continue;
    evaluate_pairs<S>(m, p.q, nullptr, 1, d);
    const std::vector<SE2<S>> pose = link_poses(m, d);
    out[k] = instant_centre(pose, link_twists<S>(m, d, pose, p.qdot), a, b, m.length_scale);
  }
  return out;
}

// The centrodes for one scalar S, after KEYWORD (`extern template` or `template`; ROLLKIN_POSITION_INSTANCES in
// solve/position.hpp, docs/benchmark.md, "Build times").
#define ROLLKIN_CENTRODES_INSTANCES(KEYWORD, S)                                                                \
  KEYWORD std::vector<InstantCentre<S>> centrodes(const Mechanism<S>&, KinematicsData<S>&, const SweepResult<S>&, \
                                                  int, int);

// Compiled once for double, in src/analysis/instantiate_double.cpp.
ROLLKIN_CENTRODES_INSTANCES(extern template, double)

}  // namespace rollkin
