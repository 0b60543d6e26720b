// Continuation along one driver: from the assembled pose, follow the same branch to every requested input
// value, in both directions when the requested range straddles the assembly input.
//
// Each sub-step predicts the pose at the new input (by default a cubic Hermite extrapolation through the
// last two poses and their velocities), corrects it with Newton and is accepted only if Newton converged
// and the result lies close to the tangent prediction q + qdot h compared with the tangent step itself (no
// silent jump to another branch); otherwise the step is halved. When the step falls below min_step the motion ends
// there: a dead point if the unknowns' Jacobian has become ill-conditioned (the limit then lies within
// about 2 min_step of the last pose), otherwise no convergence. After every accepted step, contact
// parameters on open contours are checked against their domains; an exit is located by bisection.
#pragma once

#include "rollkin/solve/position.hpp"

#include <algorithm>
#include <sstream>

namespace rollkin {

/// How the next pose is predicted before Newton corrects it.
enum class Predictor {
  Previous,  // the last pose itself (zero order), kept for comparison in the benchmark
  Tangent,   // q + qdot h, the velocity solution (first order)
  Hermite    // cubic through the last two poses and their velocities (third order), tangent at the start
};

template <class S> struct ContinuationSettings {
  S max_step = pi<S>() / S(36);      // largest sub-step of the driver (5 degrees for angles)
  S min_step = S(1) / S(1000000000); // 1e-9: limits are located to about 2e-9 in the driver
  S max_correction_ratio = S(1) / S(2);
  S ill_conditioned = S(100);        // condition growth (vs the sweep's start) that marks a dead point
  Predictor predictor = Predictor::Hermite;
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

/// The contact variables on open contours with their domains, in pair order (closed contours wrap: any
/// parameter value is inside). Collected once per sweep: the check runs after every accepted step.
template <class S> struct OpenDomains {
  std::vector<int> variables;
  std::vector<Domain<S>> domains;

  explicit OpenDomains(const Mechanism<S>& m) {
    for (const Pair<S>& p : m.pairs) {
      if (!is_contact(p.kind)) continue;
      for (int j = 0; j < 2; ++j) {
        const Domain<S> d = m.contours[j == 0 ? p.contour_a : p.contour_b].domain();
        if (d.closed) continue;
        variables.push_back(p.first_variable + j);
        domains.push_back(d);
      }
    }
  }
  /// First contact variable outside its open contour's domain, or -1.
  int violation(const VectorX<S>& q) const {
    for (std::size_t k = 0; k < variables.size(); ++k)
      if (!domains[k].contains(q(variables[k]))) return variables[k];
    return -1;
  }
};

/// Follows one branch along one driver. Holds the current pose and its velocity (and the previous ones for
/// the Hermite predictor); all buffers are allocated once.
template <class S> class Tracer {
 public:
  Tracer(const Mechanism<S>& m, SolveData<S>& sd, int driver, const ContinuationSettings<S>& cfg, const VectorX<S>& q0)
      : m_(m), sd_(sd), var_(m.drivers[driver]), cfg_(cfg), q_(q0), q_prev_(q0), trial_(q0), tangent_(q0), v_(q0),
        v_prev_(q0), rate_(VectorX<S>::Zero(m.drivers.size())), weight_(q0.size()), open_(m) {
    rate_(driver) = S(1);
    for (Eigen::Index i = 0; i < weight_.size(); ++i) weight_(i) = S(1) / m.variable_scale(static_cast<int>(i));
    start_ = solve_position(m_, q_, sd_);
    solve_velocity(m_, sd_, rate_, v_);
    base_condition_ = start_.condition;
  }

  const SolveReport<S>& start() const { return start_; }
  const VectorX<S>& q() const { return q_; }
  const VectorX<S>& v() const { return v_; }

  /// Advances to the driver value `target`. Returns Converged (iterations and evaluations summed over the
  /// sub-steps), or the limit met, with the state left at the last pose reached.
  SolveReport<S> advance(const S& target) {
    using std::abs;
    S h = clamp_step(target - q_(var_));
    SolveReport<S> rep = start_;
    int iterations = 0, evaluations = 0;
    while (q_(var_) != target) {
      // Go to the target when it is within the step or would leave a sliver behind.
      const S t = abs(target - q_(var_)) <= abs(h) * (S(1) + S(1) / S(64)) ? target : S(q_(var_) + h);
      const bool accepted = try_step(t, rep);
      iterations += rep.iterations;
      evaluations += rep.evaluations;
      if (accepted) {
        const int out = open_.violation(trial_);
        if (out >= 0) return locate_domain_exit(t, out);
        accept();
        h = clamp_step(target - q_(var_), S(abs(h) * S(2)));
        continue;
      }
      h /= S(2);
      if (abs(h) < cfg_.min_step) return classify_stop(rep);
    }
    rep.iterations = iterations;
    rep.evaluations = evaluations;
    return rep;
  }

 private:
  /// Predicts trial_ at driver value t, corrects it with Newton; accepted if converged and the correction is
  /// small against the tangent step (a larger one means Newton went to another branch).
  bool try_step(const S& t, SolveReport<S>& rep) {
    const S h = t - q_(var_);
    tangent_ = q_ + v_ * h;
    tangent_(var_) = t;
    predict(t, h);
    rep = solve_position(m_, trial_, sd_);
    if (!rep.ok()) return false;
    return scaled_distance(trial_, tangent_) <= cfg_.max_correction_ratio * scaled_distance(tangent_, q_) +
                                                    sd_.settings.step_tolerance;
  }

  void predict(const S& t, const S& h) {
    switch (cfg_.predictor) {
      case Predictor::Previous: trial_ = q_; break;
      case Predictor::Tangent: trial_ = tangent_; break;
      case Predictor::Hermite: {
        // Cubic Hermite on [t_prev, t_now] evaluated at s = (t - t_prev)/dt, an extrapolation (s > 1) that is
        // trusted up to s = 3 (a step at most twice the last one); beyond that, the tangent.
        using std::abs;
        const S dt = q_(var_) - q_prev_(var_);
        if (!has_prev_ || abs(h) > S(2) * abs(dt)) {
          trial_ = tangent_;
          break;
        }
        {
          const S s = (t - q_prev_(var_)) / dt, s2 = s * s, s3 = s2 * s;
          const S h00 = S(2) * s3 - S(3) * s2 + S(1), h10 = s3 - S(2) * s2 + s;
          const S h01 = S(-2) * s3 + S(3) * s2, h11 = s3 - s2;
          trial_ = h00 * q_prev_ + (h10 * dt) * v_prev_ + h01 * q_ + (h11 * dt) * v_;
        }
        break;
      }
    }
    for (int d : m_.drivers) trial_(d) = q_(d);  // the other inputs stay exactly where they are
    trial_(var_) = t;
  }

  void accept() {
    q_prev_.swap(q_);
    v_prev_.swap(v_);
    q_.swap(trial_);
    has_prev_ = true;
    solve_velocity(m_, sd_, rate_, v_);  // sd is factored at the accepted pose
  }

  S clamp_step(const S& remaining, const S& preferred = std::numeric_limits<S>::infinity()) const {
    using std::abs;
    using std::min;
    const S len = min(min(abs(remaining), cfg_.max_step), preferred);
    return remaining < S(0) ? S(-len) : len;
  }

  /// Max-norm of a - b in scaled variables (the expression a - b is read entry by entry, no temporary).
  S scaled_distance(const VectorX<S>& a, const VectorX<S>& b) const { return weighted_max_norm<S>(a - b, weight_); }

  /// The step collapsed at the current pose: a dead point if the Jacobian of the unknowns has become
  /// ill-conditioned (condition grown by ill_conditioned over the sweep's start, or above eps^-1/3), else
  /// no convergence.
  SolveReport<S> classify_stop(const SolveReport<S>& failed) {
    trial_ = q_;
    SolveReport<S> rep = solve_position(m_, trial_, sd_);  // refactor at the last accepted pose
    rep.limit_input = q_(var_);
    std::ostringstream os;
    // Ill-conditioned against the sweep's start or, when the sweep started next to the limit, outright.
    const S outright = S(1) / tolerance<S>(S(1) / S(3));
    if (rep.condition > cfg_.ill_conditioned * base_condition_ || rep.condition > outright || rep.rank < rep.unknowns) {
      rep.status = SolveStatus::DeadPoint;
      os << "dead point (motion limit): the mechanism cannot move past " << m_.variables[var_].name << " = "
         << to_double(q_(var_)) << " (Jacobian singular there, condition " << to_double(rep.condition) << ")";
    } else {
      rep.status = failed.status == SolveStatus::CannotAssemble ? SolveStatus::CannotAssemble : SolveStatus::NoConvergence;
      os << "no convergence beyond " << m_.variables[var_].name << " = " << to_double(q_(var_));
    }
    rep.detail = os.str();
    return rep;
  }

  /// Contact variable `out` leaves its domain before driver value t: bisect between the current pose and t.
  SolveReport<S> locate_domain_exit(S t, int out) {
    using std::abs;
    SolveReport<S> rep;
    while (abs(t - q_(var_)) > cfg_.min_step) {
      const S mid = (q_(var_) + t) / S(2);
      if (try_step(mid, rep) && open_.violation(trial_) < 0) accept();
      else t = mid;
    }
    trial_ = q_;
    rep = solve_position(m_, trial_, sd_);
    rep.status = SolveStatus::DomainExit;
    rep.limit_input = q_(var_);
    const Pair<S>& p = m_.pairs[m_.variables[out].pair];
    rep.pair = m_.variables[out].pair;
    rep.contour = out == p.first_variable ? p.contour_a : p.contour_b;
    std::ostringstream os;
    os << "contact of pair '" << p.name << "' leaves contour '" << m_.contours[rep.contour].name() << "' ("
       << m_.variables[out].name << " reaches the end of its domain) at " << m_.variables[var_].name << " = "
       << to_double(q_(var_));
    rep.detail = os.str();
    return rep;
  }

  const Mechanism<S>& m_;
  SolveData<S>& sd_;
  int var_;
  const ContinuationSettings<S>& cfg_;
  VectorX<S> q_, q_prev_, trial_, tangent_, v_, v_prev_, rate_;
  VectorX<S> weight_;  // 1 / m.variable_scale of every variable, for scaled_distance
  OpenDomains<S> open_;
  bool has_prev_ = false;
  SolveReport<S> start_;
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
  up.reserve(inputs.size());
  down.reserve(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) (inputs[i] >= q0(var) ? up : down).push_back(i);
  std::sort(up.begin(), up.end(), [&](auto a, auto b) { return inputs[a] < inputs[b]; });
  std::sort(down.begin(), down.end(), [&](auto a, auto b) { return inputs[a] > inputs[b]; });

  for (const auto* side : {&up, &down}) {
    if (side->empty()) continue;
    detail::Tracer<S> tracer(m, sd, driver, cfg, q0);
    for (std::size_t k = 0; k < side->size(); ++k) {
      SweepPose<S>& pose = out.poses[(*side)[k]];
      const SolveReport<S> rep = tracer.advance(pose.input);
      if (!rep.ok()) {  // this input and all beyond it on this side are past the limit
        out.limits.push_back(rep);
        for (std::size_t rest = k; rest < side->size(); ++rest) {
          out.poses[(*side)[rest]].report = rep;
          out.poses[(*side)[rest]].report.status = rest == k ? rep.status : SolveStatus::NotReached;
        }
        break;
      }
      pose.q = tracer.q();
      pose.qdot = tracer.v();
      pose.report = rep;
    }
  }
  return out;
}

}  // namespace rollkin
