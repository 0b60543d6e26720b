// Pair matrices and their derivatives (docs/method.md sections 1-3). The closed set of pair types:
//   revolute   P(theta) = Rot(theta)                                       1 variable
//   prismatic  P(s)     = Trans(s, 0)   (slides along the joint frame's x)  1 variable
//   cam        P(u, v)  = T_A(u) Rot(pi) T_B(v)^-1   point contact, slip     2 variables   (eq. 1)
//   rolling    the cam pair plus  s_A(u0 -> u) + s_B(v0 -> v) = 0           2 variables   (eqs. 3-4)
// T_A(u) is the contact frame of contour A in link A's frame: x along the unit tangent, origin at p(u).
// Rot(pi) makes the tangents anti-parallel and the outward normals opposite, so the bodies lie on opposite
// sides of the common tangent; with both contours traversed material-on-left this holds for external and
// internal contact alike.
//
// Derivatives are spatial twists lambda_j = (dP/dq_j) P^-1 expressed in the pair's left frame:
//   revolute lambda = (0, 0, 1); prismatic lambda = (1, 0, 0);
//   contact  lambda_u = Ad_{T_A} (sigma_A, 0, kappa_A sigma_A)
//            lambda_v = Ad_{T_A} (sigma_B, 0, -kappa_B sigma_B)
// so that at a rolling contact (sigma_A du = -sigma_B dv) the relative motion is a pure rotation about the
// contact point at rate (kappa_A + kappa_B) ds (docs/method.md section 5, rate relation).
#pragma once

#include "rollkin/pair/pair_kind.hpp"
#include "rollkin/profile/profile.hpp"

#include <array>
#include <limits>
#include <type_traits>
#include <string>

namespace rollkin {

/// Description of one pair: which links it joins, where, and its variables' names.
template <class S> struct Pair {
  std::string name;
  PairKind kind = PairKind::Revolute;
  int link_a = -1, link_b = -1;
  SE2<S> frame_a, frame_b;             // joint frames in link A and link B (revolute, prismatic)
  int contour_a = -1, contour_b = -1;  // contours on link A and link B (cam, rolling)
  std::array<std::string, 2> variables;
  int first_variable = 0;              // index of the pair's first variable in the mechanism's q
  // Set by Mechanism::finalize(): the joint frame is exactly the identity, so evaluation skips composing
  // with it. False (always compose) until then, so a pair evaluated on its own stays correct.
  bool frame_a_identity = false, frame_b_identity = false;

  /// What the pair does (pair_kind.hpp): consumers ask this, never the kind.
  const PairTraits& traits() const { return rollkin::traits(kind); }
  int variable_count() const { return traits().variable_count; }
  template <class T> Pair<T> cast() const {
    Pair<T> p;
    p.name = name;
    p.kind = kind;
    p.link_a = link_a;
    p.link_b = link_b;
    p.frame_a = frame_a.template cast<T>();
    p.frame_b = frame_b.template cast<T>();
    p.contour_a = contour_a;
    p.contour_b = contour_b;
    p.variables = variables;
    p.first_variable = first_variable;
    p.frame_a_identity = frame_a_identity;
    p.frame_b_identity = frame_b_identity;
    return p;
  }
};

/// A pair evaluated at its variables: the edge transform E = F_A P F_B^-1 from link A's frame to link B's
/// frame, its spatial twists per variable in link A's frame, and (when rates are given) their time
/// derivatives, used for the acceleration terms.
template <class S> struct PairState {
  SE2<S> transform;
  std::array<Twist<S>, 2> twist;
  std::array<Twist<S>, 2> twist_rate;
  // Contact geometry, filled for cam and rolling pairs.
  std::array<ContourPoint<S>, 2> contact;
  // The variable a revolute or prismatic pair was last evaluated at (NaN: never). Its state depends on that
  // value only, and a driver keeps its value over a pose's Newton iterations.
  S joint_value = std::numeric_limits<S>::quiet_NaN();
  // The contact parameters a cam or rolling pair was last evaluated at (NaN: never).
  std::array<S, 2> contact_value{std::numeric_limits<S>::quiet_NaN(), std::numeric_limits<S>::quiet_NaN()};

  /// The value of the pair's variable j (0, or 1 for a contact pair) this state was evaluated at.
  const S& evaluated_value(const PairTraits& t, int j) const { return t.has_contours ? contact_value[j] : joint_value; }
};

/// The edge transform F_A P F_B^-1 of a joint pair. Identity joint frames (flagged by finalize()) are
/// skipped: composing with the exact identity changes no digit, and most joints sit at a link's origin on
/// at least one side.
template <class S> SE2<S> in_joint_frames(const Pair<S>& pair, const SE2<S>& p) {
  const SE2<S> left = pair.frame_a_identity ? p : SE2<S>(pair.frame_a * p);
  return pair.frame_b_identity ? left : SE2<S>(left * pair.frame_b.inverse());
}

/// The edge transform of a cam or rolling pair from its contact points a (on contour A) and b (on contour B),
/// eq. (1): T_A Rot(pi) T_B^-1, where T_A Rot(pi) is T_A with its axis reversed (exact).
template <class S> SE2<S> contact_transform(const ContourPoint<S>& a, const ContourPoint<S>& b) {
  const SE2<S> tb = SE2<S>::from_axis(b.tangent.x(), b.tangent.y(), b.p);
  return SE2<S>::from_axis(S(-a.tangent.x()), S(-a.tangent.y()), a.p) * tb.inverse();
}

/// Evaluates the pair into st (every field is written; contact only for cam and rolling pairs). A joint
/// pair whose variable has not changed since st was last written is left as it is.
/// Differential order needed from the contours: 1 for positions and velocities, 3 for accelerations.
template <class S> void evaluate_pair(const Pair<S>& pair, const std::vector<Contour<S>>& contours, const S* q,
                                      const std::common_type_t<S>* qdot, int order, PairState<S>& st) {
  if (!pair.traits().has_contours && q[0] == st.joint_value) return;
  st.twist_rate[0].setZero();
  st.twist_rate[1].setZero();
  switch (pair.kind) {
    case PairKind::Revolute:
      st.joint_value = q[0];
      st.transform = in_joint_frames(pair, SE2<S>::rotation(q[0]));
      // Ad_{F_A} (0, 0, 1) = (t_y, -t_x, 1): rotation about the joint's origin t in link A.
      st.twist[0] = Twist<S>(pair.frame_a.translation().y(), S(-pair.frame_a.translation().x()), S(1));
      st.twist[1].setZero();
      return;
    case PairKind::Prismatic:
      st.joint_value = q[0];
      st.transform = in_joint_frames(pair, SE2<S>::translation(Vec2<S>(q[0], S(0))));
      st.twist[0] = pair.frame_a.adjoint(Twist<S>(S(1), S(0), S(0)));
      st.twist[1].setZero();
      return;
    case PairKind::Cam:
    case PairKind::Rolling: break;
  }
  // Contours carry their placement: T_A, T_B are already in the link frames (F_A = F_B = I).
  const int geo = order >= 2 ? order : 2;  // curvature is needed for the twists themselves
  st.contact_value = {q[0], q[1]};
  st.contact[0] = contour_point(contours[pair.contour_a].jet(q[0], geo), geo);
  st.contact[1] = contour_point(contours[pair.contour_b].jet(q[1], geo), geo);
  const ContourPoint<S>& a = st.contact[0];
  const ContourPoint<S>& b = st.contact[1];
  const SE2<S> ta = SE2<S>::from_axis(a.tangent.x(), a.tangent.y(), a.p);
  st.transform = contact_transform(a, b);
  st.twist[0] = ta.adjoint(Twist<S>(a.speed, S(0), a.turn_rate));
  st.twist[1] = ta.adjoint(Twist<S>(b.speed, S(0), S(-b.turn_rate)));
  if (qdot != nullptr && order >= 3) {
    // d/dt Ad_{T_A} x = Ad_{T_A} xdot + ad_{lambda_u udot} Ad_{T_A} x   (T_A moves with u only)
    st.twist_rate[0] = ta.adjoint(Twist<S>(a.speed_rate, S(0), a.turn_accel)) * qdot[0];
    st.twist_rate[1] = lie_bracket<S>(st.twist[0] * qdot[0], st.twist[1]) +
                       ta.adjoint(Twist<S>(b.speed_rate, S(0), S(-b.turn_accel))) * qdot[1];
  }
}

/// The edge transform alone of the pair at its variables q: the transform evaluate_pair() writes, to the
/// last bit, without the twists (positions only: a table of link poses).
template <class S> SE2<S> pair_transform(const Pair<S>& pair, const std::vector<Contour<S>>& contours, const S* q) {
  switch (pair.kind) {
    case PairKind::Revolute: return in_joint_frames(pair, SE2<S>::rotation(q[0]));
    case PairKind::Prismatic: return in_joint_frames(pair, SE2<S>::translation(Vec2<S>(q[0], S(0))));
    case PairKind::Cam:
    case PairKind::Rolling: break;
  }
  // The contact points as evaluate_pair computes them (order 2), so that the transforms are the same numbers.
  return contact_transform(contour_point(contours[pair.contour_a].jet(q[0], 2), 2),
                           contour_point(contours[pair.contour_b].jet(q[1], 2), 2));
}

/// The angle by which the edge transform E (at variables q) turns link B's frame relative to link A's, summed
/// from the joint frames without atan2 where the kind knows it: a revolute edge turns by angle(F_A) + q -
/// angle(F_B), a prismatic one by angle(F_A) - angle(F_B), a contact edge by the angle of E.
template <class S> S pair_turn(const Pair<S>& pair, const S* q, const SE2<S>& E) {
  switch (pair.kind) {
    case PairKind::Revolute: return pair.frame_a.angle() + q[0] - pair.frame_b.angle();
    case PairKind::Prismatic: return pair.frame_a.angle() - pair.frame_b.angle();
    case PairKind::Cam:
    case PairKind::Rolling: break;
  }
  return E.angle();
}

template <class S> PairState<S> evaluate_pair(const Pair<S>& pair, const std::vector<Contour<S>>& contours,
                                             const S* q, const std::common_type_t<S>* qdot, int order) {
  PairState<S> st;
  evaluate_pair(pair, contours, q, qdot, order, st);
  return st;
}

}  // namespace rollkin
