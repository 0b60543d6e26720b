// Position, velocity and acceleration analysis at one input value.
//
// Newton-Raphson on the constraints (eqs. 6 and 3) in the unknowns (all pair variables but the drivers),
// with the analytic Jacobian of kinematics.hpp. Rows and columns are scaled (lengths by the mechanism's
// length scale). Each step solves the factorisation SolveData chose (solve_data.hpp): redundant constraints
// (more equations than rank) on independent rows, a rank-deficient system by minimum-norm least-squares
// steps, so consistent constraints converge quadratically and inconsistent ones are reported as
// CannotAssemble. A converged pose whose error bound is not yet round-off takes one refining step.
#pragma once

#include "rollkin/solve/solve_data.hpp"

namespace rollkin {

/// Evaluates the constraints at q and factors the scaled Jacobian of the unknowns (first `rows` rows).
template <class S> void evaluate_and_factor(const Mechanism<S>& m, const VectorX<S>& q, SolveData<S>& sd, int rows);

/// Newton-Raphson at fixed driver values (taken from q). Uses the first `rows` equations (all by default).
/// A converged pose whose error bound is not yet at round-off takes one refining step
/// (detail::worth_refining). On return q holds the last iterate and sd is evaluated and factored there.
/// Plain Newton does not know branches: started from a poor guess near a motion limit it may converge to
/// another assembly mode. The continuation (continuation.hpp) guards against that; call sweep() to follow
/// a motion.
template <class S> SolveReport<S> solve_position(const Mechanism<S>& m, VectorX<S>& q, SolveData<S>& sd, int rows = -1);

/// Rates of all variables for the given driver rates: J_u qdot_u = -J_d qdot_d (sd factored at the pose).
template <class S> void solve_velocity(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& driver_rates,
                                       VectorX<S>& qdot);
template <class S> VectorX<S> solve_velocity(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& driver_rates);

/// Second derivatives: J_u qddot_u = -J_d qddot_d - gamma(q, qdot). Needs C2 contours (continuity >= 2).
template <class S> VectorX<S> solve_acceleration(const Mechanism<S>& m, const VectorX<S>& q, SolveData<S>& sd,
                                                 const VectorX<S>& qdot, const VectorX<S>& driver_accels);

/// Assembly: closes the loops (rolling rows left out) with minimum-norm corrections from the guess in q,
/// keeping the drivers and the `held` variables at their given values; then makes the assembled contact
/// parameters the rolling pairs' arc-length origins (eq. 3: D_i = D_i-1 counted from the assembly pose) and
/// solves the full system there, which reports its rank, redundancy and mobility. A contact left beyond the
/// end of an open contour, after closing the loops or after the full solve, is CannotAssemble
/// (detail::refuse_contact_off_contour).
template <class S> SolveReport<S> assemble(const Mechanism<S>& m, VectorX<S>& q, SolveData<S>& sd,
                                           const std::vector<int>& held = {});

// The entry points of this header for one scalar S, after KEYWORD: `extern template` declares them compiled
// elsewhere, `template` compiles them (Pinocchio's way: a translation unit that calls them only parses them;
// docs/benchmark.md, "Build times"). One list for every scalar and both uses.
#define ROLLKIN_POSITION_INSTANCES(KEYWORD, S)                                                                   \
  KEYWORD void evaluate_and_factor(const Mechanism<S>&, const VectorX<S>&, SolveData<S>&, int);                \
  KEYWORD SolveReport<S> solve_position(const Mechanism<S>&, VectorX<S>&, SolveData<S>&, int);                  \
  KEYWORD void solve_velocity(const Mechanism<S>&, SolveData<S>&, const VectorX<S>&, VectorX<S>&);              \
  KEYWORD VectorX<S> solve_velocity(const Mechanism<S>&, SolveData<S>&, const VectorX<S>&);                     \
  KEYWORD VectorX<S> solve_acceleration(const Mechanism<S>&, const VectorX<S>&, SolveData<S>&, const VectorX<S>&, \
                                        const VectorX<S>&);                                                     \
  KEYWORD SolveReport<S> assemble(const Mechanism<S>&, VectorX<S>&, SolveData<S>&, const std::vector<int>&);

// Compiled once for double, in src/solve/instantiate_double.cpp.
ROLLKIN_POSITION_INSTANCES(extern template, double)

}  // namespace rollkin
