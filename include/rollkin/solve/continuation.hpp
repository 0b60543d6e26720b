// Continuation along one driver: from the assembled pose, follow the same branch to every requested input
// value, in both directions when the requested range straddles the assembly input.
//
// Each sub-step predicts with the velocity solution (q + qdot h), corrects with Newton at the new input and
// is accepted only if Newton converged and the correction is small against the prediction (no silent jump
// to another branch); otherwise the step is halved. When the step falls below min_step the motion ends
// there: a dead point if the unknowns' Jacobian has become ill-conditioned (the limit then lies within
// about 2 min_step of the last pose), otherwise no convergence. After every accepted step, contact
// parameters on open contours are checked against their domains; an exit is located by bisection.
#pragma once

#include "rollkin/solve/position.hpp"

#include <algorithm>
#include <sstream>

namespace rollkin {

template <class S> struct ContinuationSettings {
  S max_step = pi<S>() / S(36);      // largest sub-step of the driver (5 degrees for angles)
  S min_step = S(1) / S(1000000000); // 1e-9: limits are located to about 2e-9 in the driver
  S max_correction_ratio = S(1) / S(2);
  S ill_conditioned = S(1000);       // condition growth (vs assembly) that marks a dead point
};

template <class S> struct SweepPose {
  S input;
  VectorX<S> q, qdot;  // qdot: rates per unit rate of the swept driver
  SolveReport<S> report;
};

template <class S> struct SweepResult {
  SolveReport<S> assembly;
  std::vector<SweepPose<S>> poses;          // one per requested input, in the requested order
  std::vector<SolveReport<S>> limits;       // limits met (at most one per direction)
  bool all_solved() const {
    for (const auto& p : poses)
      if (!p.report.ok()) return false;
    return assembly.ok();
  }
};

namespace detail {

template <class S> VectorX<S> unit_driver_rate(const Mechanism<S>& m, int driver) {
  VectorX<S> r = VectorX<S>::Zero(m.drivers.size());
  r(driver) = S(1);
  return r;
}

/// First contact variable outside its open contour's domain, or -1.
template <class S> int domain_violation(const Mechanism<S>& m, const VectorX<S>& q) {
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    const Pair<S>& p = m.pairs[k];
    if (!is_contact(p.kind)) continue;
    for (int j = 0; j < 2; ++j) {
      const Domain<S> d = m.contours[j == 0 ? p.contour_a : p.contour_b].domain();
      if (!d.contains(q(p.first_variable + j))) return p.first_variable + j;
    }
  }
  return -1;
}

template <class S> class Tracer {
 public:
  Tracer(const Mechanism<S>& m, SolveData<S>& sd, int driver, const ContinuationSettings<S>& cfg, S base_condition)
      : m_(m), sd_(sd), driver_(driver), var_(m.drivers[driver]), cfg_(cfg), base_condition_(base_condition) {}

  /// One corrector at input t = q0(var) + h from (q0, v0); true (and q set) if accepted.
  bool try_step(const VectorX<S>& q0, const VectorX<S>& v0, const S& t, VectorX<S>& q, SolveReport<S>& rep) {
    q = q0 + v0 * (t - q0(var_));
    q(var_) = t;
    const VectorX<S> predicted = q;
    rep = solve_position(m_, q, sd_);
    if (!rep.ok()) return false;
    const S correction = scaled_distance(q, predicted);
    const S prediction = scaled_distance(predicted, q0);
    return correction <= cfg_.max_correction_ratio * prediction + sd_.settings.step_tolerance;
  }

  /// Advances (q, v) at input q(var) to `target`. Returns Converged, or the limit met (q at the last pose).
  SolveReport<S> advance(VectorX<S>& q, VectorX<S>& v, const S& target) {
    using std::abs;
    S h = clamp_step(target - q(var_));
    VectorX<S> trial(q.size());
    SolveReport<S> rep;
    if (q(var_) == target) rep = solve_position(m_, q, sd_);
    while (q(var_) != target) {
      const S t = abs(target - q(var_)) <= abs(h) ? target : S(q(var_) + h);
      if (try_step(q, v, t, trial, rep)) {
        const int out = domain_violation(m_, trial);
        if (out >= 0) return locate_domain_exit(q, v, h, out);
        q = trial;
        v = solve_velocity(m_, sd_, unit_driver_rate(m_, driver_));
        h = clamp_step(target - q(var_), S(abs(h) * S(2)));
        continue;
      }
      h /= S(2);
      if (abs(h) < cfg_.min_step) return classify_stop(q, rep);
    }
    return rep;
  }

 private:
  S clamp_step(const S& remaining, const S& preferred = std::numeric_limits<S>::infinity()) const {
    using std::abs;
    using std::min;
    const S len = min(min(abs(remaining), cfg_.max_step), preferred);
    return remaining < S(0) ? S(-len) : len;
  }

  S scaled_distance(const VectorX<S>& a, const VectorX<S>& b) const {
    using std::abs;
    using std::max;
    S d(0);
    for (Eigen::Index i = 0; i < a.size(); ++i) d = max(d, S(abs(a(i) - b(i)) / m_.variable_scale(static_cast<int>(i))));
    return d;
  }

  SolveReport<S> classify_stop(const VectorX<S>& q, const SolveReport<S>& failed) {
    VectorX<S> at = q;
    SolveReport<S> rep = solve_position(m_, at, sd_);  // refactor at the last accepted pose
    rep.limit_input = q(var_);
    if (rep.condition > cfg_.ill_conditioned * base_condition_ || rep.rank < rep.unknowns) {
      rep.status = SolveStatus::DeadPoint;
      std::ostringstream os;
      os << "dead point (motion limit): the mechanism cannot move past " << m_.variables[var_].name
         << " = " << to_double(q(var_)) << " (Jacobian singular there, condition " << to_double(rep.condition) << ")";
      rep.detail = os.str();
    } else {
      rep.status = failed.status == SolveStatus::CannotAssemble ? SolveStatus::CannotAssemble : SolveStatus::NoConvergence;
      std::ostringstream os;
      os << "no convergence beyond " << m_.variables[var_].name << " = " << to_double(q(var_));
      rep.detail = os.str();
    }
    return rep;
  }

  /// The contact variable `out` leaves its domain between q's input and q's input + h: bisect on h.
  SolveReport<S> locate_domain_exit(VectorX<S>& q, VectorX<S>& v, S h, int out) {
    using std::abs;
    VectorX<S> trial(q.size());
    SolveReport<S> rep;
    while (abs(h) > cfg_.min_step) {
      const S half = h / S(2);
      if (try_step(q, v, S(q(var_) + half), trial, rep) && domain_violation(m_, trial) < 0) {
        q = trial;
        v = solve_velocity(m_, sd_, unit_driver_rate(m_, driver_));
      }
      h = half;
    }
    VectorX<S> at = q;
    rep = solve_position(m_, at, sd_);
    rep.status = SolveStatus::DomainExit;
    rep.limit_input = q(var_);
    const Pair<S>& p = m_.pairs[m_.variables[out].pair];
    const bool on_a = out == p.first_variable;
    rep.pair = m_.variables[out].pair;
    rep.contour = on_a ? p.contour_a : p.contour_b;
    std::ostringstream os;
    os << "contact of pair '" << p.name << "' leaves contour '" << m_.contours[rep.contour].name() << "' ("
       << m_.variables[out].name << " reaches the end of its domain) at " << m_.variables[var_].name << " = "
       << to_double(q(var_));
    rep.detail = os.str();
    return rep;
  }

  const Mechanism<S>& m_;
  SolveData<S>& sd_;
  int driver_, var_;
  const ContinuationSettings<S>& cfg_;
  S base_condition_;
};

}  // namespace detail

/// Sweeps driver number `driver` (index into m.drivers) over `inputs`, starting from the assembled pose q0
/// (sd.kin.reference must hold the assembly pose, as assemble() leaves it).
template <class S> SweepResult<S> sweep(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0,
                                        const SolveReport<S>& assembly, int driver, const std::vector<S>& inputs,
                                        const ContinuationSettings<S>& cfg = {}) {
  SweepResult<S> out;
  out.assembly = assembly;
  out.poses.resize(inputs.size());
  const int var = m.drivers[driver];
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    out.poses[i].input = inputs[i];
    out.poses[i].report.status = assembly.ok() ? SolveStatus::NotReached : assembly.status;
  }
  if (!assembly.ok()) return out;

  // Requested inputs on each side of the assembly input, nearest first.
  std::vector<std::size_t> up, down;
  for (std::size_t i = 0; i < inputs.size(); ++i) (inputs[i] >= q0(var) ? up : down).push_back(i);
  std::sort(up.begin(), up.end(), [&](auto a, auto b) { return inputs[a] < inputs[b]; });
  std::sort(down.begin(), down.end(), [&](auto a, auto b) { return inputs[a] > inputs[b]; });

  for (const auto* side : {&up, &down}) {
    VectorX<S> q = q0;
    SolveReport<S> rep = solve_position(m, q, sd);
    VectorX<S> v = solve_velocity(m, sd, detail::unit_driver_rate(m, driver));
    detail::Tracer<S> tracer(m, sd, driver, cfg, rep.condition);
    for (std::size_t k = 0; k < side->size(); ++k) {
      SweepPose<S>& pose = out.poses[(*side)[k]];
      rep = tracer.advance(q, v, pose.input);
      if (!rep.ok()) {  // this input and all beyond it on this side are past the limit
        out.limits.push_back(rep);
        for (std::size_t rest = k; rest < side->size(); ++rest) {
          out.poses[(*side)[rest]].report = rep;
          out.poses[(*side)[rest]].report.status = rest == k ? rep.status : SolveStatus::NotReached;
        }
        break;
      }
      pose.q = q;
      pose.qdot = v;
      pose.report = rep;
    }
  }
  return out;
}

}  // namespace rollkin
