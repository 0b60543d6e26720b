// Constraint equations of a mechanism and their derivatives (the "data" side: all buffers live in
// KinematicsData, sized once, so evaluation does not allocate).
//
//   loop l:    T_l(q) = X_1 X_2 ... X_n = I, X_k = E_k or E_k^-1 (eq. 6); residual (T.x, T.y, angle T)
//   rolling k: s_A(u_ref -> u) + s_B(v_ref -> v) = 0                               (eqs. 3-4)
//
// The Jacobian column of a variable of edge k is the rate of the residual under the spatial twist
// Ad_{L_k} lambda, L_k = X_1 ... X_{k-1} (se2.hpp). For accelerations the bias
// gamma = Jdot qdot is assembled from the twists' time derivatives:
//   d/dt (Ad_{L_k} lambda) = Ad_{L_k} lambdadot + ad_{V_k} (Ad_{L_k} lambda),  V_k = sum_{i<k} twists qdot
// and for a rolling row from sigma' udot^2 + sigma' vdot^2. At a closed loop (T = I, V = 0) the
// acceleration residual is exactly Vdot, so J qddot + gamma = 0.
#pragma once

#include "rollkin/mechanism.hpp"

#include <Eigen/Dense>

#include <optional>

namespace rollkin {

template <class S> using VectorX = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <class S> using MatrixX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

/// Where the Jacobian's nonzeros sit, fixed per mechanism: each loop's 3 rows times the variables of its
/// pairs (in loop order, 3 consecutive entries per variable), then each rolling row's two contact
/// parameters. A variable met twice in a loop has two entries at the same place: they add up.
struct JacobianPattern {
  std::vector<int> row, column;  // per entry
  std::vector<int> loop_begin;   // per loop: its first entry; one past the last loop: the rolling rows' first

  template <class S> explicit JacobianPattern(const Mechanism<S>& m) {
    int r = 0;
    for (const auto& loop : m.loops) {
      loop_begin.push_back(static_cast<int>(row.size()));
      for (const LoopEdge& e : loop)
        for (int j = 0; j < m.pairs[e.pair].variable_count(); ++j)
          for (int k = 0; k < 3; ++k) add(r + k, m.pairs[e.pair].first_variable + j);
      r += 3;
    }
    loop_begin.push_back(static_cast<int>(row.size()));
    for (int k : m.rolling_pairs) {
      add(r, m.pairs[k].first_variable);
      add(r, m.pairs[k].first_variable + 1);
      ++r;
    }
  }
  int size() const { return static_cast<int>(row.size()); }

 private:
  void add(int r, int c) {
    row.push_back(r);
    column.push_back(c);
  }
};

/// Evaluation buffers. The Jacobian is kept either dense (`jacobian`, equation_count x variable_count: the
/// small mechanisms, whose fixed-size kernels read it directly) or, when constructed with sparse = true, as
/// the values of its nonzeros in the order of `pattern` (`jacobian_values`): filling it then costs the
/// nonzeros only, linear in the number of loops, where zeroing the dense matrix alone grows as its square.
template <class S> struct KinematicsData {
  std::vector<PairState<S>> pairs;
  std::vector<Twist<S>> spatial;   // per variable, current loop's spatial twist (scratch)
  VectorX<S> residual;             // equation_count
  bool sparse;                     // which of the two Jacobian stores below is filled
  MatrixX<S> jacobian;             // dense: equation_count x variable_count (empty when sparse)
  JacobianPattern pattern;         // the nonzeros' places (both stores)
  VectorX<S> jacobian_values;      // sparse: per entry of `pattern` (empty when dense)
  VectorX<S> bias;                 // gamma = Jdot qdot
  VectorX<S> reference;            // q at assembly: the rolling pairs' arc-length origins

  explicit KinematicsData(const Mechanism<S>& m, bool sparse_jacobian = false)
      : pairs(m.pairs.size()),
        spatial(m.variable_count()),
        residual(m.equation_count()),
        sparse(sparse_jacobian),
        jacobian(sparse ? 0 : m.equation_count(), sparse ? 0 : m.variable_count()),
        pattern(m),
        jacobian_values(sparse ? pattern.size() : 0),
        bias(m.equation_count()),
        reference(VectorX<S>::Zero(m.variable_count())),
        origins_(m.variable_count()) {}

  /// out = J x (either store).
  void jacobian_times(const VectorX<S>& x, VectorX<S>& out) const {
    if (!sparse) {
      out.noalias() = jacobian * x;
      return;
    }
    out.setZero(residual.size());
    for (int e = 0; e < pattern.size(); ++e) out(pattern.row[e]) += jacobian_values(e) * x(pattern.column[e]);
  }
  /// The Jacobian as a dense matrix (either store); for diagnostics, not for the per-pose path.
  MatrixX<S> dense_jacobian() const {
    if (!sparse) return jacobian;
    MatrixX<S> j = MatrixX<S>::Zero(residual.size(), static_cast<Eigen::Index>(spatial.size()));
    for (int e = 0; e < pattern.size(); ++e) j(pattern.row[e], pattern.column[e]) += jacobian_values(e);
    return j;
  }

  /// Arc length on contour c from reference(i) to u (eq. 4). The origin's primitive s(reference(i)) is
  /// evaluated once and kept until reference(i) changes, so a solve pays one primitive per contact.
  S arc_length_from_reference(const Contour<S>& c, int i, const S& u) {
    std::optional<ArcOrigin<S>>& o = origins_[static_cast<std::size_t>(i)];
    if (!o || o->u0 != reference(i)) o = c.arc_origin(reference(i));
    return c.arc_length_from(*o, u);
  }

 private:
  std::vector<std::optional<ArcOrigin<S>>> origins_;  // per variable: used for the rolling pairs' ones
};

/// Evaluates every pair at q (and qdot when order >= 3, for accelerations).
template <class S> void evaluate_pairs(const Mechanism<S>& m, const VectorX<S>& q, const std::common_type_t<VectorX<S>>* qdot,
                                       int order, KinematicsData<S>& d) {
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const int i = m.pairs[k].first_variable;
    evaluate_pair(m.pairs[k], m.contours, q.data() + i, qdot ? qdot->data() + i : nullptr, order, d.pairs[k]);
  }
}

/// Transform of one loop step and the spatial twists of its variables in the step's left frame.
/// Backwards: d(E^-1) E = -Ad_{E^-1} (dE E^-1).
template <class S> SE2<S> loop_step(const PairState<S>& st, bool forward, std::array<Twist<S>, 2>& twist) {
  if (forward) {
    twist = st.twist;
    return st.transform;
  }
  const SE2<S> inv = st.transform.inverse();
  twist = {-inv.adjoint(st.twist[0]), -inv.adjoint(st.twist[1])};
  return inv;
}

/// A loop's residual rows (eq. 6): (x, y, angle) of its closing transform T = L_n+1.
template <class S> void write_loop_residual(const SE2<S>& closing, int row, KinematicsData<S>& d) {
  d.residual.template segment<3>(row) = Vec3<S>(closing.translation().x(), closing.translation().y(), closing.angle());
}

/// A rolling pair's residual row (eqs. 3-4): the arc lengths travelled on both contours from the reference.
template <class S> S rolling_residual(const Mechanism<S>& m, const Pair<S>& p, const VectorX<S>& q, KinematicsData<S>& d) {
  const int i = p.first_variable;
  return d.arc_length_from_reference(m.contours[p.contour_a], i, q(i)) +
         d.arc_length_from_reference(m.contours[p.contour_b], i + 1, q(i + 1));
}

/// One loop's rows (eq. 6): walks the loop accumulating L_k, stores each variable's spatial twist
/// Ad_{L_k} lambda in d.spatial (for a backward step, Ad_{L_k} of -Ad_{E^-1} mu, as in loop_step), and
/// writes the residual of T = L_n+1 and the Jacobian columns, the residual rates under those twists.
/// Only the pair's own variables are mapped (a revolute's unused second twist is skipped).
template <class S> void loop_constraints(const Mechanism<S>& m, const std::vector<LoopEdge>& loop, int row,
                                         KinematicsData<S>& d) {
  SE2<S> left;  // L_k
  for (const LoopEdge& e : loop) {
    const Pair<S>& p = m.pairs[e.pair];
    const PairState<S>& st = d.pairs[e.pair];
    const int count = p.variable_count();
    Twist<S>* spatial = &d.spatial[static_cast<std::size_t>(p.first_variable)];
    if (e.forward) {
      for (int j = 0; j < count; ++j) spatial[j] = left.adjoint(st.twist[j]);
      left = left * st.transform;
    } else {
      const SE2<S> inv = st.transform.inverse();
      for (int j = 0; j < count; ++j) spatial[j] = left.adjoint(-inv.adjoint(st.twist[j]));
      left = left * inv;
    }
  }
  write_loop_residual(left, row, d);
  if (d.sparse) {  // entries in pattern order: 3 per variable, the loop's pairs in loop order
    int entry = d.pattern.loop_begin[static_cast<std::size_t>(row / 3)];
    for (const LoopEdge& e : loop) {
      const Pair<S>& p = m.pairs[e.pair];
      for (int j = 0; j < p.variable_count(); ++j, entry += 3)
        d.jacobian_values.template segment<3>(entry) =
            residual_rate(left, d.spatial[static_cast<std::size_t>(p.first_variable + j)]);
    }
    return;
  }
  for (const LoopEdge& e : loop) {
    const Pair<S>& p = m.pairs[e.pair];
    for (int j = 0; j < p.variable_count(); ++j) {
      const int v = p.first_variable + j;
      // Entry by entry: as a 3-vector block, GCC packs the rate's scalars through memory and the load that
      // follows stalls on them (store forwarding).
      const Vec3<S> rate = residual_rate(left, d.spatial[static_cast<std::size_t>(v)]);
      S* column = &d.jacobian.coeffRef(row, v);
      column[0] += rate.x();
      column[1] += rate.y();
      column[2] += rate.z();
    }
  }
}

/// Residual and Jacobian at the pair states in d (evaluate_pairs first).
template <class S> void compute_constraints(const Mechanism<S>& m, const VectorX<S>& q, KinematicsData<S>& d) {
  if (!d.sparse) d.jacobian.setZero();
  int row = 0;
  for (const auto& loop : m.loops) {
    loop_constraints(m, loop, row, d);
    row += 3;
  }
  for (int k : m.rolling_pairs) {
    const Pair<S>& p = m.pairs[k];
    const int i = p.first_variable;
    const PairState<S>& st = d.pairs[k];
    d.residual(row) = rolling_residual(m, p, q, d);
    if (d.sparse) {
      const int entry = d.pattern.loop_begin.back() + 2 * (row - 3 * static_cast<int>(m.loops.size()));
      d.jacobian_values(entry) = st.contact[0].speed;
      d.jacobian_values(entry + 1) = st.contact[1].speed;
    } else {
      d.jacobian(row, i) = st.contact[0].speed;
      d.jacobian(row, i + 1) = st.contact[1].speed;
    }
    ++row;
  }
}

/// The residual alone (eqs. 6 and 3-4) at the pair states in d (evaluate_pairs first): what
/// compute_constraints() writes to d.residual, without the twists and the Jacobian.
template <class S> void compute_residual(const Mechanism<S>& m, const VectorX<S>& q, KinematicsData<S>& d) {
  int row = 0;
  for (const auto& loop : m.loops) {
    SE2<S> left;
    for (const LoopEdge& e : loop) {
      const SE2<S>& edge = d.pairs[e.pair].transform;
      left = left * (e.forward ? edge : edge.inverse());
    }
    write_loop_residual(left, row, d);
    row += 3;
  }
  for (int k : m.rolling_pairs) d.residual(row++) = rolling_residual(m, m.pairs[k], q, d);
}

namespace detail {

/// Spatial acceleration of each loop's closing transform, Vdot = sum_k Ad_{L_k} lambda_k qddot_k + gamma with
/// gamma = sum_k (Ad_{L_k} lambdadot_k + ad_{V_k} Ad_{L_k} lambda_k) qdot_k, and each rolling row's second
/// derivative sigma_A uddot + sigma_B vddot + sigma_A' udot^2 + sigma_B' vdot^2 (pairs evaluated with order 3
/// and this qdot). Exact at any q, closed or not. Without qddot: gamma alone (the bias).
template <class S> void loop_accelerations(const Mechanism<S>& m, const VectorX<S>& qdot, const VectorX<S>* qddot,
                                           KinematicsData<S>& d, VectorX<S>& out) {
  int row = 0;
  for (const auto& loop : m.loops) {
    SE2<S> left;
    Twist<S> velocity = Twist<S>::Zero();  // V_k, spatial velocity of L_k
    Twist<S> gamma = Twist<S>::Zero();
    std::array<Twist<S>, 2> tw;
    for (const LoopEdge& e : loop) {
      const Pair<S>& p = m.pairs[e.pair];
      const PairState<S>& st = d.pairs[e.pair];
      const SE2<S> step = loop_step(st, e.forward, tw);
      // Rates of the step's own twists (in its left frame).
      std::array<Twist<S>, 2> tw_rate = st.twist_rate;
      if (!e.forward) {
        // lambda' = -Ad_{E^-1} mu:  lambda'dot = -Ad_{E^-1} mudot + ad_W lambda',  W = sum lambda' qdot
        Twist<S> w = Twist<S>::Zero();
        for (int j = 0; j < p.variable_count(); ++j) w += tw[j] * qdot(p.first_variable + j);
        for (int j = 0; j < 2; ++j) tw_rate[j] = -step.adjoint(st.twist_rate[j]) + lie_bracket<S>(w, tw[j]);  // step = E^-1
      }
      Twist<S> step_velocity = Twist<S>::Zero();
      for (int j = 0; j < p.variable_count(); ++j) {
        const S& qd = qdot(p.first_variable + j);
        const Twist<S> c = left.adjoint(tw[j]);
        gamma += (left.adjoint(tw_rate[j]) + lie_bracket<S>(velocity, c)) * qd;
        if (qddot) gamma += c * (*qddot)(p.first_variable + j);
        step_velocity += c * qd;
      }
      velocity += step_velocity;
      left = left * step;
    }
    out.template segment<3>(row) = gamma;
    row += 3;
  }
  for (int k : m.rolling_pairs) {
    const Pair<S>& p = m.pairs[k];
    const int i = p.first_variable;
    const PairState<S>& st = d.pairs[k];
    out(row) = st.contact[0].speed_rate * qdot(i) * qdot(i) + st.contact[1].speed_rate * qdot(i + 1) * qdot(i + 1);
    if (qddot) out(row) += st.contact[0].speed * (*qddot)(i) + st.contact[1].speed * (*qddot)(i + 1);
    ++row;
  }
}

}  // namespace detail

/// gamma = Jdot qdot at a closed pose (pairs evaluated with order 3 and this qdot).
template <class S> void compute_bias(const Mechanism<S>& m, const VectorX<S>& qdot, KinematicsData<S>& d) {
  detail::loop_accelerations<S>(m, qdot, nullptr, d, d.bias);
}

/// The acceleration residual G(q, qdot, qddot) = Vdot (detail::loop_accelerations), pairs evaluated at q with
/// order 3 and qdot. Zero along every motion of the mechanism, wherever it is: the jerk equation is its
/// derivative along the motion (analysis/motion.hpp).
template <class S> void acceleration_residual(const Mechanism<S>& m, const VectorX<S>& qdot, const VectorX<S>& qddot,
                                              KinematicsData<S>& d, VectorX<S>& out) {
  out.resize(m.equation_count());
  detail::loop_accelerations(m, qdot, &qddot, d, out);
}

/// World pose of every link into `pose` (one per link, sized by the caller: nothing is allocated), from the
/// spanning tree (pairs evaluated at q).
template <class S> void link_poses(const Mechanism<S>& m, const KinematicsData<S>& d, std::vector<SE2<S>>& pose) {
  pose[static_cast<std::size_t>(m.ground)] = SE2<S>();
  for (int i : m.tree_order) {  // parents before children, the ground first
    if (i == m.ground) continue;
    const LoopEdge e = m.tree[i].edge;
    const SE2<S>& E = d.pairs[e.pair].transform;
    pose[i] = pose[m.tree[i].parent] * (e.forward ? E : E.inverse());
  }
}

/// World pose of every link at q into `pose` (sized by the caller), from the transforms of the spanning tree's
/// pairs alone (pair_transform: positions only, no pair closing a loop): the numbers link_poses() gives after
/// evaluate_pairs(q), for a fraction of the work (a table of link poses).
template <class S> void link_poses_at(const Mechanism<S>& m, const VectorX<S>& q, std::vector<SE2<S>>& pose) {
  pose[static_cast<std::size_t>(m.ground)] = SE2<S>();
  for (int i : m.tree_order) {  // parents before children, the ground first
    if (i == m.ground) continue;
    const LoopEdge e = m.tree[i].edge;
    const Pair<S>& pair = m.pairs[static_cast<std::size_t>(e.pair)];
    const SE2<S> E = pair_transform(pair, m.contours, q.data() + pair.first_variable);
    pose[i] = pose[m.tree[i].parent] * (e.forward ? E : E.inverse());
  }
}

namespace detail {

/// exp(xi) of a twist xi = (vx, vy, omega) small enough for its first order: translation v, rotation by
/// omega with cos omega = 1 - omega^2 / 2 (unit to O(omega^4)).
template <class S> SE2<S> small_motion(const Twist<S>& xi) {
  return SE2<S>::from_axis(S(1) - xi(2) * xi(2) / S(2), xi(2), Vec2<S>(xi(0), xi(1)));
}

/// The angle a of rotation r in [-pi, pi], as atan2 gives it: a brought there by whole turns (a itself when it
/// lies within: no rounding), and a half turn on the side of r's sine (a sum of angles rounds either way there).
template <class S> S angle_of(const S& a, const SE2<S>& r) {
  using std::abs;
  using std::round;
  using std::signbit;
  const S half = pi<S>(), turn = S(2) * pi<S>();
  S w = a;
  if (!(-half < w && w <= half)) {
    w -= turn * round(w / turn);
    if (w <= -half) w += turn;
    if (w > half) w -= turn;
  }
  if (abs(w) > half - tolerance_once<S, 1, 2>()) w = signbit(r.sin_angle()) ? S(-abs(w)) : S(abs(w));
  return w;
}

}  // namespace detail

/// World pose of every link at q into pose[0 .. links), from the pair states in d evaluated at values next
/// to q: a sweep's accepted pose takes one Newton step after its last evaluation (continuation.hxx,
/// take_closing_step), so its link poses need no evaluation of their own. Each spanning-tree edge's
/// transform E, evaluated at values q_e (PairState::evaluated_value), is moved to q to first order:
///   E(q) = exp(xi) E(q_e),   xi = sum_j lambda_j (q_j - q_e,j)   (lambda_j = (dE/dq_j) E^-1, pair.hpp),
/// with an error O(|q - q_e|^2): below round-off where every |q_j - q_e,j| is within eps^(5/8) of its
/// variable's scale (the closing step is at most eps^(3/4), NewtonSettings::step_tolerance). An edge further
/// from its evaluation, or never evaluated, is evaluated at q (pair_transform). Where q_e = q the numbers
/// are link_poses_at's, to the last bit.
/// With `angle`, also each link's angle in [-pi, pi] (atan2's range), summed down the tree rather than taken
/// from the rotation (one atan2 per link): a revolute edge turns by angle(F_A) + q - angle(F_B), a prismatic one by
/// angle(F_A) - angle(F_B), a contact edge by the angle of its transform.
template <class S> void link_poses_near(const Mechanism<S>& m, const KinematicsData<S>& d, const VectorX<S>& q,
                                        SE2<S>* pose, S* angle = nullptr) {
  using std::abs;
  const S& near = tolerance_once<S, 5, 8>();
  pose[m.ground] = SE2<S>();
  if (angle) angle[m.ground] = S(0);
  for (int i : m.tree_order) {  // parents before children, the ground first
    if (i == m.ground) continue;
    const LoopEdge e = m.tree[i].edge;
    const Pair<S>& pair = m.pairs[static_cast<std::size_t>(e.pair)];
    const PairState<S>& st = d.pairs[static_cast<std::size_t>(e.pair)];
    Twist<S> xi = Twist<S>::Zero();
    bool moved = false, far = false;
    for (int j = 0; j < pair.variable_count(); ++j) {
      const int var = pair.first_variable + j;
      const S dq = q(var) - st.evaluated_value(pair.kind, j);
      if (!(abs(dq) <= near * m.variable_scale(var))) {
        far = true;  // (NaN included: never evaluated)
      } else if (dq != S(0)) {
        xi += st.twist[static_cast<std::size_t>(j)] * dq;
        moved = true;
      }
    }
    const SE2<S> E = far     ? pair_transform(pair, m.contours, q.data() + pair.first_variable)
                     : moved ? SE2<S>(detail::small_motion(xi) * st.transform)
                             : st.transform;
    const int parent = m.tree[i].parent;
    pose[i] = pose[parent] * (e.forward ? E : E.inverse());
    if (angle) {
      const S turn = pair.kind == PairKind::Revolute    ? S(pair.frame_a.angle() + q(pair.first_variable) - pair.frame_b.angle())
                     : pair.kind == PairKind::Prismatic ? S(pair.frame_a.angle() - pair.frame_b.angle())
                                                        : E.angle();
      angle[i] = angle[parent] + (e.forward ? turn : S(-turn));
    }
  }
  if (angle)
    for (std::size_t i = 0; i < m.links.size(); ++i) angle[i] = detail::angle_of(angle[i], pose[i]);
}

/// World pose of every link, from the spanning tree (pairs evaluated at q).
template <class S> std::vector<SE2<S>> link_poses(const Mechanism<S>& m, const KinematicsData<S>& d) {
  std::vector<SE2<S>> pose(m.links.size());
  link_poses(m, d, pose);
  return pose;
}

/// Spatial twist (v, omega) of every link in the world frame, per unit of the rates qdot: a world point P
/// moving with link i has velocity v_i + omega_i J P. Down the spanning tree, with lambda_j the pair's
/// spatial twists in its link A's frame (pair.hpp) and link_poses' `pose`:
///   forward edge (parent A, child B, T_B = T_A E):      V_B = V_A + Ad_{T_A} (sum_j lambda_j qdot_j)
///   backward edge (parent B, child A, T_A = T_B E^-1):  V_A = V_B - Ad_{T_A} (sum_j lambda_j qdot_j)
/// (the second from d(E^-1) E = -Ad_{E^-1}(dE E^-1), as loop_step, and Ad_{T_B} Ad_{E^-1} = Ad_{T_A}).
template <class S> std::vector<Twist<S>> link_twists(const Mechanism<S>& m, const KinematicsData<S>& d,
                                                     const std::vector<SE2<S>>& pose, const VectorX<S>& qdot) {
  std::vector<Twist<S>> twist(m.links.size(), Twist<S>::Zero());
  for (int i : m.tree_order) {
    if (i == m.ground) continue;
    const LoopEdge e = m.tree[i].edge;
    const Pair<S>& p = m.pairs[e.pair];
    Twist<S> lambda = Twist<S>::Zero();
    for (int j = 0; j < p.variable_count(); ++j) lambda += d.pairs[e.pair].twist[j] * qdot(p.first_variable + j);
    const int parent = m.tree[i].parent;
    twist[i] = twist[parent] + (e.forward ? pose[parent].adjoint(lambda) : Twist<S>(-pose[i].adjoint(lambda)));
  }
  return twist;
}

}  // namespace rollkin
