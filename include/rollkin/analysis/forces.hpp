// Kinetostatics of a solved pose (docs/forces.md): the reactions of every pair and the drivers' efforts that
// move the mechanism through the pose with its swept input at a constant speed w, the other inputs held.
//
// Newton-Euler for every moving link i, in world axes, moments about the world origin O:
//   sum_pairs W_pair->i + W_applied,i = W_inertial,i
//   W_inertial,i = l (m a_G, I_G alpha + m r_G x a_G)           (a_G, alpha the link's accelerations)
// with l the metres per scene length unit (docs/forces.md, "Units": mass kg, time s, force N, lengths in
// scene units, so m a_G in kg * length / s^2 is l newtons). Each pair's reaction is a combination of its
// constraint directions, the columns of the (Cartesian) constraint Jacobian's transpose:
//   revolute   Fx, Fy at the joint's point                                   2 unknowns
//   prismatic  F_n normal to the guide at frame B's origin, the moment M     2 unknowns
//   cam        N along the common normal n at the contact point c, with its Coulomb friction
//              -mu sign(w sliding) N along t (analysis/motion.hpp's t, n, sliding)   1 unknown
//   rolling    N along n and F_t along t at c                                 2 unknowns
//   driver     its effort: a torque (revolute) or a force along the guide (prismatic) on the pair's second link
// Every wrench is the one the pair's first link A exerts on its second link B (B gets +W, A gets -W; the
// ground has no equation). One linear system E x = r per pose (3 rows per moving link).
//
// Speed in closed form: at constant w the accelerations are w^2 times those per unit of the input (q', q''
// per unit input, SweepPose::qdot and solve_acceleration), so r = r_A + w^2 r_B: r_A from gravity, springs
// and loads, r_B from the inertia per unit input speed squared. E does not depend on w (only the sign of w
// enters, through the friction's direction), so every unknown is x = A + w^2 B with E A = r_A, E B = r_B.
//
// Redundant constraints (examples/hypocycloid.json, gears on fixed centres): E has more columns than rank.
// The column-pivoted QR of E (columns scaled to unit norm, moment rows by the length scale) finds its rank;
// the basic solution sets the non-pivot columns to zero. A component is unique when every null vector of E
// has a zero there; one random combination of the null vectors, z = [-R11^-1 R12 c; c] (c fixed and
// irrational-like), has a zero exactly at the unique components (save a cancellation of measure zero). The
// efforts stay unique (virtual work) whenever the inputs set the mechanism's motion.
#pragma once

#include "rollkin/analysis/motion.hpp"
#include "rollkin/dynamics.hpp"

#include <Eigen/QR>

#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin {

/// What one unknown of the force system is.
enum class ReactionKind {
  ForceX, ForceY,   // revolute: world components
  GuideNormal,      // prismatic: the force normal to the guide (along frame A's y axis in world)
  GuideMoment,      // prismatic: the moment about frame B's origin
  Normal,           // cam, rolling: along the common normal n (positive: the contours pressed together)
  Tangential,       // rolling: along t
  Effort            // a driver's torque or force
};

struct Reaction {
  int pair = -1;
  ReactionKind kind = ReactionKind::ForceX;
  int driver = -1;  // index in Mechanism::drivers for an Effort
};

/// The unknowns of the force system and the rows of its equations, fixed per mechanism (the layout issue 39's
/// sensitivities reuse): per pair its reactions (first[pair], count[pair]), then one effort per driver.
struct ForceLayout {
  std::vector<Reaction> unknowns;
  std::vector<int> first, count;  // per pair
  std::vector<int> effort;        // per driver: its unknown
  std::vector<int> link_row;      // per link: its first equation (3 per moving link), -1 for the ground
  int rows = 0;

  /// Throws std::invalid_argument for a driver that is a contact parameter (its effort is not a torque or a
  /// force of the pair: docs/forces.md).
  template <class S> explicit ForceLayout(const Mechanism<S>& m);
  int size() const { return static_cast<int>(unknowns.size()); }
};

template <class S> ForceLayout::ForceLayout(const Mechanism<S>& m) : first(m.pairs.size()), count(m.pairs.size()) {
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const int pair = static_cast<int>(k);
    first[k] = size();
    // The reactions a pair carries follow from what it does (pair/pair_kind.hpp): a turning joint a force,
    // a sliding one the guide's normal force and moment, a contact the normal force and, when it does not
    // slip, the tangential one.
    const PairTraits& does = m.pairs[k].traits();
    if (does.turns) {
      unknowns.push_back({pair, ReactionKind::ForceX});
      unknowns.push_back({pair, ReactionKind::ForceY});
    } else if (does.slides) {
      unknowns.push_back({pair, ReactionKind::GuideNormal});
      unknowns.push_back({pair, ReactionKind::GuideMoment});
    } else if (does.has_contours) {
      unknowns.push_back({pair, ReactionKind::Normal});
      if (does.constrains_sliding) unknowns.push_back({pair, ReactionKind::Tangential});
    }
    count[k] = size() - first[k];
  }
  for (std::size_t d = 0; d < m.drivers.size(); ++d) {
    const Variable& v = m.variables[static_cast<std::size_t>(m.drivers[d])];
    if (m.pairs[static_cast<std::size_t>(v.pair)].traits().has_contours)
      throw std::invalid_argument("the input '" + v.name + "' is a contact parameter: its effort is neither a torque nor a force of "
                                  "a joint; drive a revolute or prismatic pair for --forces");
    effort.push_back(size());
    unknowns.push_back({v.pair, ReactionKind::Effort, static_cast<int>(d)});
  }
  link_row.assign(m.links.size(), -1);
  for (std::size_t i = 0; i < m.links.size(); ++i)
    if (static_cast<int>(i) != m.ground) {
      link_row[i] = rows;
      rows += 3;
    }
}

/// The forces of one pose: every unknown is a + w^2 b at input speed w (see the top of this file), with the
/// geometry the outputs need to resolve them.
template <class S> struct PoseForces {
  VectorX<S> a, b;                      // per unknown of the layout
  std::vector<bool> unique;             // per unknown: determined by the equations (not a redundant reaction)
  bool determined = false;              // the equations have a solution (false: a singular pose)
  int rank = 0;                         // of the equations' matrix
  std::vector<Vec2<S>> direction;       // per unknown: the world force on the pair's second link per unit value
  std::vector<S> friction_ratio;        // per pair: a cam pair's friction force along t per unit normal force
  std::vector<ContactAnalysis<S>> contacts;  // per cam or rolling pair, in pair order (analysis/motion.hpp)
  PoseAnalysis<S> motion;               // link poses, world twists, angular accelerations per unit input
  std::vector<Twist<S>> link_acceleration;   // per link: spatial acceleration (vdot, alpha) per unit input^2

  S value(int k, const S& w) const { return a(k) + w * w * b(k); }
};

/// Workspace of pose_forces: the kinematic solve data and the force system's buffers, sized once.
template <class S> struct ForceData {
  SolveData<S> solve;
  ForceLayout layout;
  MatrixX<S> matrix;           // E (rows x unknowns)
  MatrixX<S> rhs;              // [r_A r_B]
  VectorX<S> row_scale, col_scale;
  Eigen::ColPivHouseholderQR<MatrixX<S>> qr;
  explicit ForceData(const Mechanism<S>& m)
      : solve(m), layout(m), matrix(layout.rows, layout.size()), rhs(layout.rows, 2), row_scale(layout.rows),
        col_scale(layout.size()), qr(layout.rows, layout.size()) {}
};

/// Spatial accelerations (vdot, alpha) of every link per unit input^2, down the spanning tree (pairs evaluated
/// at order 3 with qdot; twists of link_twists): with tw_j, tw'_j a tree edge's twists in the parent's frame
/// and their rates (loop_step's conventions, kinematics.hpp),
///   Vdot_child = Vdot_parent + sum_j Ad_{T_p}(tw_j q''_j + tw'_j q'_j) + ad_{V_p}(Ad_{T_p} tw_j) q'_j.
/// A world point x of link i then accelerates at vdot + alpha J x + omega J (v + omega J x).
template <class S> std::vector<Twist<S>> link_accelerations(const Mechanism<S>& m, const KinematicsData<S>& d,
                                                            const std::vector<SE2<S>>& pose,
                                                            const std::vector<Twist<S>>& twist, const VectorX<S>& qdot,
                                                            const VectorX<S>& qddot);

/// Acceleration of the world point x of a link with world twist V and spatial acceleration A (per unit input^2).
template <class S> Vec2<S> point_acceleration(const Twist<S>& V, const Twist<S>& A, const Vec2<S>& x) {
  const Vec2<S> v = detail::point_velocity(V, x);
  return Vec2<S>(A.x() - A.z() * x.y() - V.z() * v.y(), A.y() + A.z() * x.x() + V.z() * v.x());
}

/// The forces at the solved pose q with rates qdot (per unit rate of the swept input), for the dynamics dyn
/// (its speed's sign sets the friction's direction). See the top of this file.
template <class S> PoseForces<S> pose_forces(const Mechanism<S>& m, const Dynamics<S>& dyn,
                                             const std::common_type_t<VectorX<S>>& q,
                                             const std::common_type_t<VectorX<S>>& qdot, ForceData<S>& data);

#define ROLLKIN_FORCES_INSTANCES(KEYWORD, S)                                                                   \
  KEYWORD PoseForces<S> pose_forces(const Mechanism<S>&, const Dynamics<S>&, const VectorX<S>&, const VectorX<S>&, \
                                    ForceData<S>&);                                                             \
  KEYWORD std::vector<Twist<S>> link_accelerations(const Mechanism<S>&, const KinematicsData<S>&,              \
                                                   const std::vector<SE2<S>>&, const std::vector<Twist<S>>&,    \
                                                   const VectorX<S>&, const VectorX<S>&);

// Compiled once for double, in src/analysis/instantiate_double.cpp.
ROLLKIN_FORCES_INSTANCES(extern template, double)

}  // namespace rollkin
