// The bodies of the position, velocity and acceleration solvers declared in solve/position.hpp. Included by the
// translation units that compile them (src/solve/instantiate_double.cpp, instantiate_mpfr50.cpp, the MPFR
// reference) and by code that solves in another scalar; everything else includes position.hpp only
// (docs/benchmark.md, "Build times").
#pragma once

#include "rollkin/solve/position.hpp"

#include "rollkin/solve/contact_limits.hpp"
#include "rollkin/solve/solve_data.hxx"

#include <sstream>

namespace rollkin {

/// Evaluates the constraints at q and factors the scaled Jacobian of the unknowns (first `rows` rows).
template <class S> void evaluate_and_factor(const Mechanism<S>& m, const VectorX<S>& q, SolveData<S>& sd, int rows) {
  evaluate_pairs<S>(m, q, nullptr, 2, sd.kin);
  compute_constraints(m, q, sd.kin);
  sd.factor(rows);
}

namespace detail {

/// A converged pose whose error bound (condition x residual, SolveData::error_bound) exceeds eps^(2/3) while
/// a round-off residual would meet it: the residual tolerance (64 eps) let Newton stop before the unknowns
/// were accurate, and one more step brings the residual to round-off. Not at a singular pose (condition
/// x eps above eps^(2/3)), where no step can.
template <class S> bool worth_refining(const SolveData<S>& sd, const SolveReport<S>& rep) {
  const S& limit = tolerance_once<S, 2, 3>();
  return rep.status == SolveStatus::Converged && sd.error_bound(rep.residual, rep.equations) > limit &&
         sd.condition * epsilon<S>() <= limit;
}

/// The Newton step of the first `rows` equations at the pose sd is evaluated and factored at, into sd.step
/// (scaled); returns its largest entry (NaN where the Jacobian broke down).
template <class S> S newton_step(SolveData<S>& sd, int rows) {
  sd.rhs.head(rows) = -sd.kin.residual.head(rows).cwiseProduct(sd.row_weight.head(rows));
  sd.solve(sd.rhs.head(rows), sd.step);
  return sd.step.size() == 0 ? S(0) : S(sd.step.cwiseAbs().maxCoeff());
}

/// q += sign x sd.step, unscaled.
template <class S> void add_step(const Mechanism<S>& m, VectorX<S>& q, const SolveData<S>& sd, int sign = 1) {
  for (std::size_t c = 0; c < m.unknowns.size(); ++c) q(m.unknowns[c]) += S(sign) * sd.step(c) * sd.col_scale(c);
}

/// The refining step did not lower the residual: back to the pose it started from (q minus the step),
/// factored again there, with its report.
template <class S>
SolveReport<S> undo_refining_step(const Mechanism<S>& m, VectorX<S>& q, SolveData<S>& sd, int rows,
                                  SolveReport<S> rep, int evaluations) {
  add_step(m, q, sd, -1);
  evaluate_and_factor(m, q, sd, rows);
  rep.evaluations = evaluations;
  return rep;
}

}  // namespace detail

/// Newton-Raphson at fixed driver values (taken from q). Uses the first `rows` equations (all by default).
/// A converged pose whose error bound is not yet at round-off takes one refining step
/// (detail::worth_refining). On return q holds the last iterate and sd is evaluated and factored there.
/// Plain Newton does not know branches: started from a poor guess near a motion limit it may converge to
/// another assembly mode. The continuation (continuation.hpp) guards against that; call sweep() to follow
/// a motion.
template <class S> SolveReport<S> solve_position(const Mechanism<S>& m, VectorX<S>& q, SolveData<S>& sd, int rows) {
  if (rows < 0) rows = m.equation_count();
  const NewtonSettings<S>& cfg = sd.settings;
  SolveReport<S> rep;
  rep.equations = rows;
  rep.unknowns = static_cast<int>(m.unknowns.size());
  S last_step = std::numeric_limits<S>::infinity();
  S residual_before = std::numeric_limits<S>::infinity();  // two iterations back: stagnation test
  S residual_last = std::numeric_limits<S>::infinity();
  bool stagnant = false;
  SolveReport<S> before_refining;  // the converged pose a refining step started from (status Converged)
  for (int it = 0;; ++it) {
    evaluate_and_factor(m, q, sd, rows);
    rep.iterations = it;
    rep.evaluations = it + 1;
    rep.residual = weighted_max_norm<S>(sd.kin.residual.head(rows), sd.row_weight.head(rows));
    rep.rank = sd.rank;
    rep.condition = sd.condition;
    if (before_refining.ok()) {  // after the refining step: the better of the two poses
      if (!(rep.residual < before_refining.residual))
        return detail::undo_refining_step(m, q, sd, rows, before_refining, it + 2);
      rep.status = before_refining.status;
      return rep;
    }
    const bool settled = last_step <= cfg.step_tolerance && rep.residual <= cfg.consistency_tolerance;
    // A least-squares residual that no longer halves in two iterations while the steps are small has reached
    // its minimum: consistent if within the tolerance, otherwise the constraints disagree.
    stagnant = it >= 2 && rep.residual > residual_before / S(2) && last_step <= tolerance_once<S, 1, 3>();
    if (rep.residual <= cfg.residual_tolerance || settled || (stagnant && rep.residual <= cfg.consistency_tolerance)) {
      rep.status = rep.rank < rep.unknowns ? SolveStatus::Underdetermined : SolveStatus::Converged;
      if (it == cfg.max_iterations || !detail::worth_refining(sd, rep)) return rep;
      before_refining = rep;  // one more step (detail::worth_refining)
    } else if (it == cfg.max_iterations || stagnant) {
      break;
    }
    residual_before = residual_last;
    residual_last = rep.residual;
    last_step = detail::newton_step(sd, rows);
    if (!(last_step == last_step)) break;  // NaN: the Jacobian broke down
    detail::add_step(m, q, sd);
  }
  const bool inconsistent = rep.residual > cfg.consistency_tolerance && (stagnant || last_step <= cfg.step_tolerance);
  rep.status = inconsistent ? SolveStatus::CannotAssemble : SolveStatus::NoConvergence;
  std::ostringstream os;
  if (inconsistent)
    os << "the constraints cannot all be met: the least-squares residual stays at " << to_double(rep.residual)
       << " (relative to the mechanism size), above the consistency tolerance " << to_double(cfg.consistency_tolerance);
  else
    os << "Newton-Raphson did not converge in " << cfg.max_iterations << " iterations (residual "
       << to_double(rep.residual) << ")";
  rep.detail = os.str();
  return rep;
}

/// Rates of all variables for the given driver rates: J_u qdot_u = -J_d qdot_d (sd factored at the pose).
template <class S> void solve_velocity(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& driver_rates,
                                       VectorX<S>& qdot) {
  qdot.setZero(m.variable_count());
  for (std::size_t k = 0; k < m.drivers.size(); ++k) qdot(m.drivers[k]) = driver_rates(k);
  // rhs = -R^-1 J_d qdot_d: only the drivers' columns (the unknowns' rates are still zero).
  if (sd.kin.sparse) {
    sd.kin.jacobian_times(qdot, sd.rhs);
    sd.rhs = -sd.rhs.cwiseProduct(sd.row_weight);
  } else {
    for (Eigen::Index r = 0; r < sd.rhs.size(); ++r) {
      S sum(0);
      for (std::size_t k = 0; k < m.drivers.size(); ++k) sum += sd.kin.jacobian(r, m.drivers[k]) * driver_rates(k);
      sd.rhs(r) = -sum * sd.row_weight(r);
    }
  }
  sd.solve(sd.rhs, sd.step);
  for (std::size_t c = 0; c < m.unknowns.size(); ++c) qdot(m.unknowns[c]) = sd.step(c) * sd.col_scale(c);
}
template <class S> VectorX<S> solve_velocity(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& driver_rates) {
  VectorX<S> qdot;
  solve_velocity(m, sd, driver_rates, qdot);
  return qdot;
}

/// Second derivatives: J_u qddot_u = -J_d qddot_d - gamma(q, qdot). Needs C2 contours (continuity >= 2).
template <class S> VectorX<S> solve_acceleration(const Mechanism<S>& m, const VectorX<S>& q, SolveData<S>& sd,
                                                 const VectorX<S>& qdot, const VectorX<S>& driver_accels) {
  VectorX<S> qdd = VectorX<S>::Zero(m.variable_count());
  for (std::size_t k = 0; k < m.drivers.size(); ++k) qdd(m.drivers[k]) = driver_accels(k);
  evaluate_pairs(m, q, &qdot, 3, sd.kin);
  compute_bias(m, qdot, sd.kin);
  sd.kin.jacobian_times(qdd, sd.rhs);
  sd.rhs = -(sd.rhs + sd.kin.bias).cwiseProduct(sd.row_weight);
  sd.solve(sd.rhs, sd.step);
  for (std::size_t c = 0; c < m.unknowns.size(); ++c) qdd(m.unknowns[c]) = sd.step(c) * sd.col_scale(c);
  return qdd;
}

namespace detail {

/// A contact parameter of q beyond the end of its open contour (Domain::contains): the loops close there
/// only on the contour's extension, which is not drawn (profile/profile.hpp), so the mechanism cannot be
/// assembled as given. Sets rep to CannotAssemble naming the pair, the contour, the parameter and the
/// contour's range; returns whether it did.
template <class S> bool refuse_contact_off_contour(const Mechanism<S>& m, const VectorX<S>& q, SolveReport<S>& rep) {
  const ContactOffContour off = contact_off_contour(m, q);
  if (!off) return false;
  const Contour<S>& c = m.contours[off.contour];
  const bool angle = c.parameter_kind() == ParamKind::Angle;
  const auto shown = [angle](const S& v) { return angle ? rad_to_deg(to_double(v)) : to_double(v); };  // deg for angles
  std::ostringstream os;
  os.precision(10);
  os << "the contact of pair '" << m.pairs[off.pair].name << "' lies at " << m.variables[off.variable].name << " = "
     << shown(q(off.variable)) << (angle ? " deg" : "") << ", beyond the end of contour '" << c.name()
     << "', which is drawn for " << shown(c.domain().lo) << " .. " << shown(c.domain().hi)
     << (angle ? " deg" : "") << "; give the pair \"values\" on the drawn contour (or draw the contour where the"
     << " contact is)";
  rep.status = SolveStatus::CannotAssemble;
  rep.pair = off.pair;
  rep.contour = off.contour;
  rep.detail = os.str();
  return true;
}

}  // namespace detail

/// Assembly: closes the loops (rolling rows left out) with minimum-norm corrections from the guess in q,
/// keeping the drivers and the `held` variables at their given values; then makes the assembled contact
/// parameters the rolling pairs' arc-length origins (eq. 3: D_i = D_i-1 counted from the assembly pose) and
/// solves the full system there, which reports its rank, redundancy and mobility. A contact left beyond the
/// end of an open contour, after closing the loops or after the full solve, is CannotAssemble
/// (detail::refuse_contact_off_contour).
template <class S> SolveReport<S> assemble(const Mechanism<S>& m, VectorX<S>& q, SolveData<S>& sd,
                                           const std::vector<int>& held) {
  SolveReport<S> rep;
  if (!m.loops.empty()) {
    Mechanism<S> closing = m;
    closing.drivers.insert(closing.drivers.end(), held.begin(), held.end());
    closing.finalize();
    SolveData<S> closing_data(closing, sd.method);
    closing_data.settings = sd.settings;
    rep = solve_position(closing, q, closing_data, 3 * static_cast<int>(m.loops.size()));
    if (rep.status == SolveStatus::NoConvergence || rep.status == SolveStatus::CannotAssemble) {
      rep.status = SolveStatus::CannotAssemble;
      rep.detail = "the loops cannot be closed from the given assembly pose (" + rep.detail + ")";
      return rep;
    }
  }
  if (detail::refuse_contact_off_contour(m, q, rep)) return rep;
  sd.kin.reference = q;
  rep = solve_position(m, q, sd);
  if (rep.status == SolveStatus::Underdetermined)
    rep.detail = "the drivers do not fix the pose: the mechanism has " +
                 std::to_string(rep.unknowns - rep.rank) + " more degree(s) of freedom than inputs";
  if (rep.has_pose()) detail::refuse_contact_off_contour(m, q, rep);
  return rep;
}

}  // namespace rollkin
