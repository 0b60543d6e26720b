// The bodies of analysis/forces.hpp, for the translation units that compile them
// (src/analysis/instantiate_double.cpp, src/solve/instantiate_mpfr50.cpp).
#pragma once

#include "rollkin/analysis/forces.hpp"

#include <cmath>

namespace rollkin {

template <class S>
std::vector<Twist<S>> link_accelerations(const Mechanism<S>& m, const KinematicsData<S>& d, const std::vector<SE2<S>>& pose,
                                         const std::vector<Twist<S>>& twist, const VectorX<S>& qdot, const VectorX<S>& qddot) {
  std::vector<Twist<S>> accel(m.links.size(), Twist<S>::Zero());
  for (int i : m.tree_order) {
    if (i == m.ground) continue;
    const LoopEdge e = m.tree[i].edge;
    const Pair<S>& p = m.pairs[e.pair];
    const PairState<S>& st = d.pairs[e.pair];
    std::array<Twist<S>, 2> tw;
    const SE2<S> step = loop_step(st, e.forward, tw);
    std::array<Twist<S>, 2> tw_rate = st.twist_rate;
    if (!e.forward) {  // as detail::loop_accelerations: lambda'dot = -Ad_{E^-1} mudot + ad_W lambda'
      Twist<S> w = Twist<S>::Zero();
      for (int j = 0; j < p.variable_count(); ++j) w += tw[j] * qdot(p.first_variable + j);
      for (int j = 0; j < 2; ++j) tw_rate[j] = -step.adjoint(st.twist_rate[j]) + lie_bracket<S>(w, tw[j]);
    }
    const int parent = m.tree[i].parent;
    const SE2<S>& left = pose[parent];
    Twist<S> a = accel[parent];
    for (int j = 0; j < p.variable_count(); ++j) {
      const int v = p.first_variable + j;
      const Twist<S> c = left.adjoint(tw[j]);
      a += c * qddot(v) + (left.adjoint(tw_rate[j]) + lie_bracket<S>(twist[parent], c)) * qdot(v);
    }
    accel[i] = a;
  }
  return accel;
}

namespace detail {

/// The wrench (Fx, Fy, M about the world origin) of the force f at the world point x.
template <class S> Vec3<S> wrench(const Vec2<S>& f, const Vec2<S>& x) { return Vec3<S>(f.x(), f.y(), cross2(x, f)); }

/// Adds the wrench w acting on link `link` to column `col` of the equations (no equation for the ground).
template <class S, class Block> void add_wrench(const ForceLayout& l, int link, const Vec3<S>& w, Block&& col) {
  const int row = l.link_row[static_cast<std::size_t>(link)];
  if (row >= 0) col.template segment<3>(row) += w;
}

/// Column k of E: unknown k's wrench per unit value on the pair's second link B, its opposite on A; and
/// its world force direction (zero for a moment).
template <class S> void reaction_column(const Mechanism<S>& m, const ForceData<S>& data, const PoseForces<S>& out, int k,
                                        MatrixX<S>& e, Vec2<S>& direction) {
  const Reaction& r = data.layout.unknowns[static_cast<std::size_t>(k)];
  const Pair<S>& p = m.pairs[static_cast<std::size_t>(r.pair)];
  const std::vector<SE2<S>>& pose = out.motion.link_pose;
  const SE2<S>& ga = pose[static_cast<std::size_t>(p.link_a)];
  const SE2<S>& gb = pose[static_cast<std::size_t>(p.link_b)];
  Vec3<S> w = Vec3<S>::Zero();
  direction.setZero();
  const ContactAnalysis<S>* c = nullptr;
  for (const auto& contact : out.contacts)
    if (contact.pair == r.pair) c = &contact;
  switch (r.kind) {
    case ReactionKind::ForceX:
    case ReactionKind::ForceY:
      direction = r.kind == ReactionKind::ForceX ? Vec2<S>(S(1), S(0)) : Vec2<S>(S(0), S(1));
      w = wrench(direction, ga.act(p.frame_a.translation()));
      break;
    case ReactionKind::GuideNormal:
      direction = ga.rotate(p.frame_a.rotate(Vec2<S>(S(0), S(1))));
      w = wrench(direction, gb.act(p.frame_b.translation()));
      break;
    case ReactionKind::GuideMoment: w = Vec3<S>(S(0), S(0), S(1)); break;
    case ReactionKind::Normal:
      direction = c->normal + out.friction_ratio[static_cast<std::size_t>(r.pair)] * c->tangent;
      w = wrench(direction, c->point);
      break;
    case ReactionKind::Tangential:
      direction = c->tangent;
      w = wrench(direction, c->point);
      break;
    case ReactionKind::Effort:
      if (p.traits().turns) {
        w = Vec3<S>(S(0), S(0), S(1));
      } else {  // prismatic: along the guide, at frame B's origin (the guide's moment M balances the rest)
        direction = ga.rotate(p.frame_a.rotate(Vec2<S>(S(1), S(0))));
        w = wrench(direction, gb.act(p.frame_b.translation()));
        direction.setZero();  // reported as the effort, not in the pair's Fx, Fy
      }
      break;
  }
  auto col = e.col(k);
  add_wrench<S>(data.layout, p.link_b, w, col);
  add_wrench<S>(data.layout, p.link_a, Vec3<S>(-w), col);
}

/// r_A (applied: gravity, springs, loads, moved to the right-hand side) and r_B (inertia per unit input speed
/// squared) of the equations (top of forces.hpp).
template <class S> void right_hand_sides(const Mechanism<S>& m, const Dynamics<S>& dyn, const PoseForces<S>& out,
                                         ForceData<S>& data) {
  using std::sqrt;
  data.rhs.setZero();
  auto applied = data.rhs.col(0);
  auto inertia = data.rhs.col(1);
  const S& l = dyn.metres_per_length;
  const std::vector<SE2<S>>& pose = out.motion.link_pose;
  for (std::size_t i = 0; i < m.links.size(); ++i) {
    const LinkMass<S>& body = dyn.links[i];
    if (static_cast<int>(i) == m.ground || body.mass == S(0)) continue;
    const Vec2<S> g = pose[i].act(body.centre);
    const Vec2<S> acc = point_acceleration(out.motion.link_velocity[i], out.link_acceleration[i], g);
    const S alpha = out.link_acceleration[i].z();
    add_wrench<S>(data.layout, static_cast<int>(i), Vec3<S>(-wrench<S>(body.mass * l * dyn.gravity, g)), applied);
    Vec3<S> inertial = wrench<S>(body.mass * l * acc, g);
    inertial.z() += body.inertia * l * alpha;
    add_wrench<S>(data.layout, static_cast<int>(i), inertial, inertia);
  }
  for (const Spring<S>& s : dyn.springs) {
    const Vec2<S> pa = pose[static_cast<std::size_t>(s.link_a)].act(s.at_a);
    const Vec2<S> pb = pose[static_cast<std::size_t>(s.link_b)].act(s.at_b);
    const Vec2<S> d = pb - pa;
    const S length = sqrt(d.squaredNorm());
    // Tension T = k (L - L0) pulls b toward a: -T u on b, +T u on a (u = d / L). At L = 0 the direction is
    // undefined: NaN, which the caller reports (the row is not determined).
    const Vec2<S> pull = d * (s.rate * (length - s.free_length) / length);
    add_wrench<S>(data.layout, s.link_b, wrench<S>(pull, pb), applied);  // moved to the right: minus (-pull)
    add_wrench<S>(data.layout, s.link_a, Vec3<S>(-wrench<S>(pull, pa)), applied);
  }
  for (const Load<S>& load : dyn.loads) {
    Vec3<S> w = wrench<S>(load.force, pose[static_cast<std::size_t>(load.link)].act(load.at));
    w.z() += load.torque;
    add_wrench<S>(data.layout, load.link, Vec3<S>(-w), applied);
  }
}

/// Whether the component z_i of a null combination is zero (top of forces.hpp): below half the digits of
/// the combination's size.
template <class S> bool null_component(const S& zi, const S& size) {
  using std::abs;
  return abs(zi) <= size * tolerance_once<S, 1, 2>();
}

/// Solves the scaled equations for both right-hand sides; marks the unique unknowns (top of forces.hpp).
template <class S> void solve_forces(ForceData<S>& data, PoseForces<S>& out) {
  using std::abs;
  using std::floor;
  using std::max;
  using std::sqrt;
  const Eigen::Index n = data.layout.size();
  if (n == 0) {
    out.determined = true;
    return;
  }
  const MatrixX<S> scaled = data.row_scale.asDiagonal() * data.matrix * data.col_scale.asDiagonal();
  const MatrixX<S> rhs = data.row_scale.asDiagonal() * data.rhs;
  data.qr.setThreshold(tolerance_once<S, 3, 4>());
  data.qr.compute(scaled);
  out.rank = static_cast<int>(data.qr.rank());
  const Eigen::Index r = out.rank;
  // The basic solution on the rank's pivots (Eigen's solve() keeps pivots down to eps, which a redundant
  // column reaches only approximately): x = P [R11^-1 (Q^T rhs)_1; 0].
  const MatrixX<S> qtb = data.qr.householderQ().adjoint() * rhs;
  MatrixX<S> xp = MatrixX<S>::Zero(n, 2);
  xp.topRows(r) = data.qr.matrixR().topLeftCorner(r, r).template triangularView<Eigen::Upper>().solve(qtb.topRows(r));
  const MatrixX<S> x = data.qr.colsPermutation() * xp;
  // Consistent when the basic solution satisfies the equations (a singular pose: a rank lost in the rows).
  const MatrixX<S> residual = scaled * x - rhs;
  S size(0);
  for (Eigen::Index c = 0; c < 2; ++c) size = max(size, S(rhs.col(c).cwiseAbs().maxCoeff()));
  for (Eigen::Index c = 0; c < 2; ++c) size = max(size, S(x.col(c).cwiseAbs().maxCoeff()));
  out.determined = residual.allFinite() && x.allFinite() &&
                   !(residual.cwiseAbs().maxCoeff() > size * tolerance_once<S, 1, 2>());
  out.a = data.col_scale.cwiseProduct(x.col(0));
  out.b = data.col_scale.cwiseProduct(x.col(1));
  out.unique.assign(static_cast<std::size_t>(n), true);
  if (r == n) return;
  // z = P [-R11^-1 R12 c; c], c_k in [1, 2) spread by the golden ratio.
  VectorX<S> c(n - r);
  for (Eigen::Index k = 0; k < n - r; ++k) {
    const S t = S(k + 1) * (sqrt(S(5)) - S(1)) / S(2);
    c(k) = S(1) + (t - floor(t));
  }
  const auto R = data.qr.matrixR();
  const VectorX<S> y = R.topLeftCorner(r, r).template triangularView<Eigen::Upper>().solve(R.topRightCorner(r, n - r) * c);
  VectorX<S> zp(n);
  zp.head(r) = -y;
  zp.tail(n - r) = c;
  const VectorX<S> z = data.qr.colsPermutation() * zp;
  const S zsize = z.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < n; ++k) out.unique[static_cast<std::size_t>(k)] = null_component(S(z(k)), zsize);
}

}  // namespace detail

template <class S>
PoseForces<S> pose_forces(const Mechanism<S>& m, const Dynamics<S>& dyn, const std::common_type_t<VectorX<S>>& q,
                          const std::common_type_t<VectorX<S>>& qdot, ForceData<S>& data) {
  using std::abs;
  using std::max;
  SolveData<S>& sd = data.solve;
  PoseForces<S> out;
  // The accelerations per unit input (analysis/motion.hpp, analyse_pose): J_u q'' = -gamma, inputs at constant rate.
  sd.kin.reference = q;
  evaluate_and_factor(m, q, sd, m.equation_count());
  const VectorX<S> input_accels = VectorX<S>::Zero(static_cast<Eigen::Index>(m.drivers.size()));
  out.motion.qddot = solve_acceleration(m, q, sd, qdot, input_accels);
  out.motion.link_pose = link_poses(m, sd.kin);
  detail::link_motion(m, sd.kin, qdot, out.motion.qddot, out.motion);
  out.link_acceleration = link_accelerations(m, sd.kin, out.motion.link_pose, out.motion.link_velocity, qdot, out.motion.qddot);
  out.friction_ratio.assign(m.pairs.size(), S(0));
  const S speed_sign = dyn.speed > S(0) ? S(1) : dyn.speed < S(0) ? S(-1) : S(0);
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    if (!m.pairs[k].traits().has_contours) continue;
    out.contacts.push_back(detail::contact_analysis(m, static_cast<int>(k), sd.kin.pairs[k], qdot, out.motion));
    const ContactAnalysis<S>& c = out.contacts.back();
    if (m.pairs[k].traits().constrains_sliding || !(dyn.friction[k] > S(0))) continue;
    // Coulomb friction on B opposes B's sliding over A; none where the sliding is zero to round-off
    // (static friction: not determined by the motion).
    const S motion_size = max(c.velocity_a.norm(), c.velocity_b.norm());
    if (detail::negligible(c.sliding, motion_size)) continue;
    const S slide_sign = c.sliding > S(0) ? S(1) : S(-1);
    out.friction_ratio[k] = -dyn.friction[k] * slide_sign * speed_sign;
  }
  // The equations: E (columns per unknown), row and column scales.
  const ForceLayout& layout = data.layout;
  data.matrix.setZero();
  out.direction.assign(static_cast<std::size_t>(layout.size()), Vec2<S>::Zero());
  for (int k = 0; k < layout.size(); ++k)
    detail::reaction_column(m, data, out, k, data.matrix, out.direction[static_cast<std::size_t>(k)]);
  for (int r = 0; r < layout.rows; ++r) data.row_scale(r) = r % 3 == 2 ? S(S(1) / m.length_scale) : S(1);
  for (int k = 0; k < layout.size(); ++k) {
    const S norm = data.row_scale.cwiseProduct(data.matrix.col(k)).norm();
    data.col_scale(k) = norm > S(0) ? S(S(1) / norm) : S(1);
  }
  detail::right_hand_sides(m, dyn, out, data);
  detail::solve_forces(data, out);
  return out;
}

}  // namespace rollkin
