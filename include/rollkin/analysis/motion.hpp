// The contact analysis of a solved pose: what a cam or gear designer reads off a contact pair (pressure
// angle, sliding, slide-to-roll, curvatures) and every link's angular velocity and acceleration, all per unit
// of the swept input (docs/analysis.md).
//
// Given a pose q and its rates qdot per unit rate of the input (SweepPose::qdot), the accelerations come from
// J_u qddot_u = -J_d qddot_d - gamma(q, qdot) (solve_acceleration, kinematics.hpp) with the inputs moving
// at constant rate (qddot_d = 0: the swept input is the independent variable, the others are held).
//
// World motion of the links: their spatial twists V = (v, omega) along the spanning tree (link_twists,
// kinematics.hpp); a point x moving with link i has velocity v_i(x) = v + omega J x (se2.hpp, residual_rate).
//
// At a cam or rolling pair, with A the link of the pair's first contour and B the link of its second one:
//   c  contact point (world), t the unit tangent of the first contour there (its direction of increasing
//      parameter, material on the left), n = -J t its outward normal: the common normal, pointing to B;
//   pressure_angle = angle between the line of n and v_B(f), the velocity of the point f of B (the driven
//      member) where the contact force enters it, in [0, pi/2] radians; NaN where v_B(f) vanishes (relative
//      to the motion at the contact). f is c itself, except at a cam pair whose second contour is a circle:
//      that stands for a roller turning on its pin at the circle's centre (the cam pair's sliding is the
//      roller's turning, the same motion), and the force enters the follower there, so f is the centre
//      (the textbook angle of a roller follower: between the common normal and the velocity of the roller's
//      centre; docs/analysis.md). For a translating follower both give the same angle; for a turning one
//      they differ. At a rolling pair the circle is the link's own rim and f = c;
//   sliding = (v_B(c) - v_A(c)) . t, the relative tangential velocity of the two material points at c
//      (its normal part is zero while the contact holds). The contact point travels along contour A at
//      sigma_A udot and along contour B at sigma_B vdot (each along its own tangent; B's is -t, eq. 1),
//      and c' = v_A + sigma_A udot t = v_B - sigma_B vdot t, so sliding = sigma_A udot + sigma_B vdot, which
//      the rolling constraint (eqs. 2-3) makes zero;
//   rolling_speed = (sigma_A udot - sigma_B vdot) / 2, the mean of the contact point's two travel speeds,
//      both measured along t (minus the mean of the surfaces' tangential velocities relative to c);
//   slide_to_roll = sliding / rolling_speed, NaN where the rolling speed vanishes;
//   kappa1, kappa2 = signed curvatures of the first and second contour at c (ContourPoint::curvature:
//      positive where the contour is convex toward the other body, negative where concave, as a ring);
//   relative_curvature = kappa1 + kappa2: the rate relation of docs/method.md section 5, relative angular
//      velocity = (contact speed along the contours) x (kappa1 + kappa2); zero where the contours osculate.
// Velocities, sliding and rolling speed are per unit of the input (per radian for an angle input).
//
// Jerk: the acceleration residual G(q, q', q'') = J_s q'' + gamma(q, q') (acceleration_residual,
// kinematics.hpp: the exact spatial acceleration of every loop's closing transform and the rolling rows'
// second derivatives, at any q) vanishes along the motion, so its derivative along the motion does too:
//   J_u q'''_u = -D G,   D G = dG/dq q' + dG/dq' q''   (the input's q''' is zero),
// and a link's angular jerk is D alpha + omega(q''') (alpha(q, q', q'') of link_motion, omega(x) the
// angular velocity of the rates x). The contour jets stop at the third derivative, so D is taken as the
// fourth-order central difference of G and alpha along the motion, (q, q') -> (q + e q', q' + e q''),
// e = +-h, +-2h, with h such that the largest variable moves by eps^(1/5) of its scale: truncation ~ h^4,
// round-off ~ eps / h, about 1e-12 relative in double where the contours are C4 (on a sampled spline the jerk jumps at the
// knots, where p''' does, and the difference there averages the two sides).
#pragma once

#include "rollkin/solve/position.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace rollkin {

template <class S> struct ContactAnalysis {
  int pair = -1;             // index in Mechanism::pairs
  Vec2<S> point, tangent, normal;  // c, t, n (world)
  Vec2<S> velocity_a, velocity_b;  // v_A(c), v_B(c) per unit input
  Vec2<S> force_point;       // f: where the pressure angle is measured on B (c, or a roller's centre; top of file)
  Vec2<S> force_point_velocity;  // v_B(f) per unit input
  S pressure_angle;          // radians in [0, pi/2]; NaN where v_B(f) = 0
  S sliding;                 // (v_B - v_A) . t
  S rolling_speed;           // (sigma_A udot - sigma_B vdot) / 2
  S slide_to_roll;           // sliding / rolling_speed; NaN where rolling_speed = 0
  S kappa1, kappa2;          // curvature of the first and second contour at c (1/length)
  S relative_curvature;      // kappa1 + kappa2
};

template <class S> struct PoseAnalysis {
  std::vector<ContactAnalysis<S>> contacts;  // one per cam or rolling pair, in pair order
  std::vector<SE2<S>> link_pose;             // world pose per link
  std::vector<Twist<S>> link_velocity;       // world (spatial) twist per link per unit input: (v, omega)
  std::vector<S> angular_acceleration;       // per link, d^2(angle)/d(input)^2
  std::vector<S> angular_jerk;               // per link, d^3(angle)/d(input)^3
  VectorX<S> qddot;                          // every pair variable's second derivative
  VectorX<S> qdddot;                         // ... and third derivative
};

/// Workspace of analyse_pose: buffers sized once per mechanism.
template <class S> struct AnalysisData {
  SolveData<S> solve;
  KinematicsData<S> moved;  // pairs at the shifted poses of the jerk's differences
  explicit AnalysisData(const Mechanism<S>& m) : solve(m), moved(m) {}
};

namespace detail {

/// Velocity of the world point x moving with spatial twist V: v + omega J x (se2.hpp, residual_rate).
template <class S> Vec2<S> point_velocity(const Twist<S>& V, const Vec2<S>& x) {
  return Vec2<S>(V.x() - V.z() * x.y(), V.y() + V.z() * x.x());
}

/// Angle in [0, pi/2] between the line of the unit vector n and the vector v (atan2: accurate near 0 and
/// pi/2, where acos and asin lose half the digits).
template <class S> S angle_to_line(const Vec2<S>& n, const Vec2<S>& v) {
  using std::abs;
  using std::atan2;
  return atan2(abs(cross2(n, v)), abs(n.dot(v)));
}

/// Whether x is zero to round-off compared with the size of the motion it is part of.
template <class S> bool negligible(const S& x, const S& motion) {
  using std::abs;
  return abs(x) <= motion * tolerance<S>(S(3) / S(4));
}

/// World twists (link_twists, kinematics.hpp) and angular accelerations of the links along the spanning tree
/// (pairs in d evaluated at q with order 3 and qdot): as the angular part of Ad is the identity, with
/// loop_step's twists (lambda, or -Ad_{E^-1} lambda backwards),
///   alpha_child = alpha_parent + sum_j (lambda_j.omega qddot_j + lambdadot_j.omega qdot_j).
template <class S> void link_motion(const Mechanism<S>& m, const KinematicsData<S>& d, const VectorX<S>& qdot,
                                    const VectorX<S>& qddot, PoseAnalysis<S>& out) {
  out.link_velocity = link_twists(m, d, out.link_pose, qdot);
  out.angular_acceleration.assign(m.links.size(), S(0));
  for (int i : m.tree_order) {
    if (i == m.ground) continue;
    const LoopEdge e = m.tree[i].edge;
    const Pair<S>& p = m.pairs[e.pair];
    const PairState<S>& st = d.pairs[e.pair];
    std::array<Twist<S>, 2> tw;
    loop_step(st, e.forward, tw);
    S alpha(0);
    for (int j = 0; j < p.variable_count(); ++j) {
      const int v = p.first_variable + j;
      // lambdadot's angular part: st.twist_rate (already a time derivative), negated backwards.
      const S rate = e.forward ? S(st.twist_rate[j].z()) : S(-st.twist_rate[j].z());
      alpha += tw[j].z() * qddot(v) + rate * qdot(v);
    }
    out.angular_acceleration[i] = out.angular_acceleration[m.tree[i].parent] + alpha;
  }
}

/// Step of the jerk's differences (top of this file): the largest variable moves by eps^(1/5) of its scale
/// (7e-4 in double), which balances the difference's truncation (h^4) against round-off (eps / h).
template <class S> S jerk_step(const Mechanism<S>& m, const VectorX<S>& qdot) {
  using std::abs;
  using std::max;
  using std::pow;
  S fastest(0);
  for (int i = 0; i < m.variable_count(); ++i) fastest = max(fastest, S(abs(qdot(i)) / m.variable_scale(i)));
  const S step = pow(epsilon<S>(), S(1) / S(5));
  return fastest > S(0) ? S(step / fastest) : step;
}

/// The acceleration residual G and the links' angular accelerations, one vector, at (q, qdot, qddot).
template <class S> VectorX<S> accelerations_at(const Mechanism<S>& m, const VectorX<S>& q, const VectorX<S>& qdot,
                                               const VectorX<S>& qddot, KinematicsData<S>& d) {
  evaluate_pairs(m, q, &qdot, 3, d);
  VectorX<S> g;
  acceleration_residual(m, qdot, qddot, d, g);
  PoseAnalysis<S> motion;
  motion.link_pose = link_poses(m, d);
  link_motion(m, d, qdot, qddot, motion);
  VectorX<S> out(g.size() + static_cast<Eigen::Index>(m.links.size()));
  out.head(g.size()) = g;
  for (std::size_t l = 0; l < m.links.size(); ++l) out(g.size() + static_cast<Eigen::Index>(l)) = motion.angular_acceleration[l];
  return out;
}

/// D (G, alpha): their derivative along the motion (top of this file), fourth-order central difference
///   D f = (8 (f(h) - f(-h)) - (f(2h) - f(-2h))) / (12 h),  f(e) = f(q + e q', q' + e q'', q'').
template <class S> VectorX<S> along_motion(const Mechanism<S>& m, const VectorX<S>& q, const VectorX<S>& qdot,
                                           const VectorX<S>& qddot, KinematicsData<S>& d) {
  const S h = jerk_step(m, qdot);
  auto f = [&](const S& e) -> VectorX<S> {
    const VectorX<S> qe = q + e * qdot, qde = qdot + e * qddot;
    return accelerations_at<S>(m, qe, qde, qddot, d);
  };
  const VectorX<S> near = f(h) - f(S(-h)), far = f(S(2) * h) - f(S(-2) * h);
  return (S(8) * near - far) / (S(12) * h);
}

/// The point of B where the contact force enters it (top of this file): the centre of B's circle at a cam pair
/// (a roller on its pin), else the contact point c.
template <class S> Vec2<S> force_point(const Mechanism<S>& m, const Pair<S>& p, const PoseAnalysis<S>& motion, const Vec2<S>& c) {
  if (p.traits().constrains_sliding) return c;  // a rolling contact: the force enters at the contact point
  const std::optional<Vec2<S>> centre = m.contours[p.contour_b].circle_centre();
  return centre ? motion.link_pose[p.link_b].act(*centre) : c;
}

/// The contact quantities of one cam or rolling pair (see the top of this file).
template <class S> ContactAnalysis<S> contact_analysis(const Mechanism<S>& m, int k, const PairState<S>& st,
                                                       const VectorX<S>& qdot, const PoseAnalysis<S>& motion) {
  using std::abs;
  using std::max;
  const Pair<S>& p = m.pairs[k];
  const ContourPoint<S>& a = st.contact[0];
  const ContourPoint<S>& b = st.contact[1];
  const SE2<S>& ga = motion.link_pose[p.link_a];
  const S nan = std::numeric_limits<S>::quiet_NaN();
  ContactAnalysis<S> c;
  c.pair = k;
  c.point = ga.act(a.p);
  c.tangent = ga.rotate(a.tangent);
  c.normal = ga.rotate(a.outward_normal());
  c.velocity_a = point_velocity(motion.link_velocity[p.link_a], c.point);
  c.velocity_b = point_velocity(motion.link_velocity[p.link_b], c.point);
  const S travel_a = a.speed * qdot(p.first_variable);      // sigma_A udot, along t
  const S travel_b = b.speed * qdot(p.first_variable + 1);  // sigma_B vdot, along -t
  // Size of the motion at the contact, against which a zero is judged.
  const S motion_size = max(max(c.velocity_a.norm(), c.velocity_b.norm()), max(abs(travel_a), abs(travel_b)));
  c.force_point = force_point(m, p, motion, c.point);
  c.force_point_velocity = point_velocity(motion.link_velocity[p.link_b], c.force_point);
  const S driven_speed = c.force_point_velocity.norm();
  c.pressure_angle = negligible(driven_speed, max(motion_size, driven_speed)) ? nan : angle_to_line(c.normal, c.force_point_velocity);
  c.sliding = (c.velocity_b - c.velocity_a).dot(c.tangent);
  c.rolling_speed = (travel_a - travel_b) / S(2);
  c.slide_to_roll = negligible(c.rolling_speed, motion_size) ? nan : S(c.sliding / c.rolling_speed);
  c.kappa1 = a.curvature();
  c.kappa2 = b.curvature();
  c.relative_curvature = c.kappa1 + c.kappa2;
  return c;
}

}  // namespace detail

/// Third derivatives (top of this file): J_u q'''_u = -D G with the factorisation of J at q in data.solve, and
/// the angular jerks D alpha + omega(q''').
template <class S> void jerk(const Mechanism<S>& m, const VectorX<S>& q, const VectorX<S>& qdot, AnalysisData<S>& data,
                             PoseAnalysis<S>& out) {
  SolveData<S>& sd = data.solve;
  const VectorX<S> d = detail::along_motion(m, q, qdot, out.qddot, data.moved);
  const Eigen::Index rows = m.equation_count();
  sd.rhs = -d.head(rows).cwiseProduct(sd.row_weight);
  sd.solve(sd.rhs, sd.step);
  out.qdddot = VectorX<S>::Zero(m.variable_count());
  for (std::size_t c = 0; c < m.unknowns.size(); ++c) out.qdddot(m.unknowns[c]) = sd.step(c) * sd.col_scale(c);
  const std::vector<Twist<S>> omega = link_twists(m, sd.kin, out.link_pose, out.qdddot);
  out.angular_jerk.resize(m.links.size());
  for (std::size_t l = 0; l < m.links.size(); ++l)
    out.angular_jerk[l] = d(rows + static_cast<Eigen::Index>(l)) + omega[l].z();
}

/// Contact analysis at the solved pose q with rates qdot (per unit rate of the swept input; the other inputs
/// held). Needs C2 contours at the contacts (curvature and its rate). A singular pose gives the minimum-norm
/// accelerations of the rank-deficient system: no more meaningful there than the rates themselves.
/// (q and qdot do not take part in deducing S: a sweep's pose columns, SweepResult::q(k), convert.)
template <class S> PoseAnalysis<S> analyse_pose(const Mechanism<S>& m, const std::common_type_t<VectorX<S>>& q,
                                                const std::common_type_t<VectorX<S>>& qdot, AnalysisData<S>& data) {
  SolveData<S>& sd = data.solve;
  // Arc lengths counted from q itself: the rolling rows' residual is not needed here, only their Jacobian.
  sd.kin.reference = q;
  evaluate_and_factor(m, q, sd, m.equation_count());
  PoseAnalysis<S> out;
  // J_u qddot_u = -gamma (inputs at constant rate); leaves the pairs evaluated at order 3 with qdot.
  const VectorX<S> input_accels = VectorX<S>::Zero(static_cast<Eigen::Index>(m.drivers.size()));
  out.qddot = solve_acceleration(m, q, sd, qdot, input_accels);
  out.link_pose = link_poses(m, sd.kin);
  detail::link_motion(m, sd.kin, qdot, out.qddot, out);
  jerk(m, q, qdot, data, out);
  for (std::size_t k = 0; k < m.pairs.size(); ++k)
    if (m.pairs[k].traits().has_contours)
      out.contacts.push_back(detail::contact_analysis(m, static_cast<int>(k), sd.kin.pairs[k], qdot, out));
  return out;
}

// The pose analysis for one scalar S, after KEYWORD (`extern template` or `template`; ROLLKIN_POSITION_INSTANCES
// in solve/position.hpp, docs/benchmark.md, "Build times").
#define ROLLKIN_ANALYSIS_INSTANCES(KEYWORD, S) \
  KEYWORD PoseAnalysis<S> analyse_pose(const Mechanism<S>&, const VectorX<S>&, const VectorX<S>&, AnalysisData<S>&);

// Compiled once for double, in src/analysis/instantiate_double.cpp.
ROLLKIN_ANALYSIS_INSTANCES(extern template, double)

}  // namespace rollkin
