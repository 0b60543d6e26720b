// The tracer of one branch of the continuation declared in solve/continuation.hpp (whose file comment
// describes the method): predictor, Newton corrector, step control, limits and the strides of the dense
// output. The sweeps that drive it are in solve/sweep.hxx, the dense output's stride in solve/dense_output.hxx.
#pragma once

#include "rollkin/solve/continuation.hpp"

#include "rollkin/solve/contact_limits.hpp"
#include "rollkin/solve/position.hxx"

#include <algorithm>
#include <sstream>

namespace rollkin {

namespace detail {

/// Cubic Hermite through (q0, v0) at driver value t0 and (q1, v1) at t1, evaluated at t (s = (t - t0)/(t1 - t0);
/// s > 1 extrapolates); with `rate`, also its derivative d/dt there.
template <class S> void hermite(const VectorX<S>& q0, const VectorX<S>& v0, const S& t0, const VectorX<S>& q1,
                                const VectorX<S>& v1, const S& t1, const S& t, VectorX<S>& out, VectorX<S>* rate = nullptr) {
  const S dt = t1 - t0;
  const S s = (t - t0) / dt, s2 = s * s, s3 = s2 * s;
  const S h00 = S(2) * s3 - S(3) * s2 + S(1), h10 = s3 - S(2) * s2 + s;
  const S h01 = S(-2) * s3 + S(3) * s2, h11 = s3 - s2;
  out = h00 * q0 + (h10 * dt) * v0 + h01 * q1 + (h11 * dt) * v1;
  if (!rate) return;
  const S d00 = S(6) * s2 - S(6) * s, d10 = S(3) * s2 - S(4) * s + S(1);
  const S d01 = S(-6) * s2 + S(6) * s, d11 = S(3) * s2 - S(2) * s;
  *rate = (d00 / dt) * q0 + d10 * v0 + (d01 / dt) * q1 + d11 * v1;
}

/// Follows one branch along one driver. Holds the current pose and its velocity (and the previous ones for
/// the Hermite predictor); all buffers are allocated once.
template <class S> class Tracer {
 public:
  Tracer(const Mechanism<S>& m, SolveData<S>& sd, int driver, const ContinuationSettings<S>& cfg, const VectorX<S>& q0)
      : m_(m), sd_(sd), var_(m.drivers[driver]), cfg_(cfg), q_(q0), q_prev_(q0), trial_(q0), tangent_(q0), v_(q0),
        v_prev_(q0), rate_(VectorX<S>::Zero(m.drivers.size())), weight_(q0.size()), limits_(m), span_q_(q0),
        span_v_(q0), pose_q_(q0), pose_v_(q0), held_(q0), held_v_(q0), reach_(q0), undo_q_(q0), undo_v_(q0) {
    rate_(driver) = S(1);
    for (Eigen::Index i = 0; i < weight_.size(); ++i) weight_(i) = S(1) / m.variable_scale(static_cast<int>(i));
    const S scale = m.variable_scale(var_);
    max_step_ = cfg.max_step * scale;
    min_step_ = cfg.min_step * scale;
    cross_step_ = max_step_ * cfg.cross_fraction;
    start_ = solve_position(m_, q_, sd_);
    sign_ = sd_.determinant_sign();
    solve_velocity(m_, sd_, rate_, v_);
    base_condition_ = start_.condition;
  }

  const SolveReport<S>& start() const { return start_; }
  /// The pose at the last target advance() reached, and its velocity.
  const VectorX<S>& q() const { return inside_span_ ? pose_q_ : q_; }
  const VectorX<S>& v() const { return inside_span_ ? pose_v_ : v_; }
  /// The driver's value at the current pose.
  const S& driver_value() const { return q_(var_); }

  /// Dense output (file comment): the distance in the driver over which a stride may interpolate.
  const S& interpolation_span() const { return span_; }

  /// A stride: one sub-step to driver value `end`, kept only when clean (Newton converged to a regular pose
  /// on the followed branch: no sign change of det J_u, no contact limit, no singular span pending). Then
  /// the pose is accepted and the last two poses bracket the stride; otherwise nothing changes and advance()
  /// takes the input.
  bool stride(const S& end, SolveReport<S>& rep) {
    using std::abs;
    const S h = end - q_(var_);
    if (has_span_ || h == S(0) || abs(h) > max_step_) return false;
    if (!try_step(end, rep) || singular_trial(rep)) return false;
    const int sign = sd_.determinant_sign();
    if (sign * sign_ < 0 || limits_.met(q_, trial_)) return false;
    undo_q_ = q_prev_;
    undo_v_ = v_prev_;
    undo_has_prev_ = has_prev_;
    undo_sign_ = sign_;
    accept();
    if (sign != 0) sign_ = sign;
    interpolated_ = rep;
    interpolated_.iterations = 0;
    interpolated_.evaluations = 1;
    return true;
  }

  /// The pose at driver value t inside the last stride, the cubic Hermite between its ends, and its scaled
  /// residual (the constraints evaluated there, no Jacobian).
  const S& interpolate(const S& t) {
    hermite(q_prev_, v_prev_, q_prev_(var_), q_, v_, q_(var_), t, pose_q_);
    hold_drivers(pose_q_, t);
    evaluate_pairs<S>(m_, pose_q_, nullptr, 2, sd_.kin);
    compute_residual(m_, pose_q_, sd_.kin);
    interpolated_.residual = weighted_max_norm<S>(sd_.kin.residual, sd_.row_weight);
    return interpolated_.residual;
  }
  /// The last interpolated pose is kept: its residual is within a quarter of Newton's tolerance and its
  /// error bound (with the stride end's condition) is not singular.
  bool interpolation_verified() const {
    return interpolated_.residual <= sd_.settings.residual_tolerance / S(4) && !singular_trial(interpolated_);
  }
  const VectorX<S>& interpolated_pose() const { return pose_q_; }
  const SolveReport<S>& interpolated_report() const { return interpolated_; }
  /// Newton's residual tolerance (NewtonSettings) of the solves.
  const S& newton_tolerance() const { return sd_.settings.residual_tolerance; }

  /// Back to the pose the last stride started from; the span shrinks to half the distance to the input
  /// whose interpolation failed (t).
  void undo_stride(const S& t) {
    using std::abs;
    restore_stride_start();
    span_ = abs(t - q_(var_)) / S(2);
  }

  /// The next interpolation span after a completed stride whose interpolated poses' largest residual was
  /// `largest`: that residual scales as span^4 and is aimed at 8 epsilon, the span at most twice the stride
  /// and within max_step. A stride that interpolated nothing doubles the span when its end's prediction
  /// already met Newton's tolerance (no iteration but the refining step: the cubic is that accurate over
  /// the stride), else keeps it (on a grid too coarse to interpolate, no stride is tried and undone).
  /// `round_off` is the round-off level of the residual at these poses (interpolate_stride: the larger of
  /// the stride end's residual, solved, and the residuals of the interpolated poses next to the stride's
  /// ends, where the cubic's error is a fifth of its largest), which grows with the number of rows and the
  /// size of their terms (trains of many rolling disks, angles after turns). Interpolated poses within twice it show
  /// no error of the cubic at all, only round-off, and aiming that at 8 epsilon would shrink the span at
  /// every stride until nothing is interpolated: the span doubles instead, as when the prediction met the
  /// tolerance. Every interpolated pose is still verified (interpolation_verified), so the span decides the
  /// cost only, never what is reported.
  void update_span(const S& largest, bool prediction_met, const S& round_off) {
    using std::abs;
    using std::min;
    using std::sqrt;
    const S target = S(8) * epsilon<S>();
    S growth(prediction_met ? 2 : 1);
    if (largest > S(0))
      growth = largest <= S(2) * round_off ? S(2) : S(S(9) / S(10) * sqrt(sqrt(S(target / largest))));
    span_ = min(S(abs(q_(var_) - q_prev_(var_)) * min(growth, S(2))), max_step_);
  }

  /// Advances to the driver value `target`. Returns Converged (iterations and evaluations summed over the
  /// sub-steps), Singular (values interpolated on the branch, see the file comment), or the limit met, with
  /// the state left at the last pose reached.
  SolveReport<S> advance(const S& target) {
    using std::abs;
    inside_span_ = false;
    if (has_span_ && between(span_q_(var_), q_(var_), target)) return pose_in_span(target);
    has_span_ = false;
    S h = clamp_step(target - q_(var_));
    SolveReport<S> rep = start_;
    int iterations = 0, evaluations = 0;
    while (q_(var_) != target) {
      // Go to the target when it is within the step or would leave a sliver behind.
      const bool lands = abs(target - q_(var_)) <= abs(h) * (S(1) + S(1) / S(64));
      const S t = lands ? target : S(q_(var_) + h);
      const bool accepted = try_step(t, rep);
      iterations += rep.iterations;
      evaluations += rep.evaluations;
      bool singular = singular_trial(rep);
      const bool near = abs(t - q_(var_)) <= cross_step_;
      int sign = accepted && !singular ? sd_.determinant_sign() : 0;
      if (sign * sign_ < 0 && !near) {  // a singular point lies in between: approach it, cross it short
        h /= S(2);
        continue;
      }
      // A singular pose at t (or no solution exactly at a target that lies on one): step over it.
      if ((singular || (lands && !accepted)) && near) {
        if (accepted) {
          held_.swap(trial_);
          held_report_ = rep;
        }
        if (step_over(t, rep, iterations, evaluations)) {
          if (has_span_ && between(span_q_(var_), q_(var_), target)) {
            SolveReport<S> inside = pose_in_span(target);
            inside.iterations += iterations;
            inside.evaluations += evaluations;
            return inside;
          }
          h = clamp_step(target - q_(var_), S(abs(h) * S(2)));
          continue;
        }
        if (accepted) {
          // No regular pose beyond (e.g. a dead point just ahead, where the condition grows without the
          // branches meeting): the converged pose is the best there is and is taken as before, its sign unused.
          trial_.swap(held_);
          rep = held_report_;
          evaluate_and_factor(m_, trial_, sd_, m_.equation_count());
          ++evaluations;
          singular = false;
        }
      }
      if (accepted && !singular) {
        if (const ContactLimit limit = limits_.met(q_, trial_)) return locate_contact_limit(t, limit);
        accept();
        if (sign != 0) sign_ = sign;
        h = clamp_step(target - q_(var_), S(abs(h) * S(2)));
        continue;
      }
      h /= S(2);
      if (abs(h) < min_step_) return classify_stop(rep);
    }
    rep.iterations = iterations;
    rep.evaluations = evaluations;
    return rep;
  }

 private:
  /// Pins the drivers on `pose`: the swept one at t, the other inputs exactly where they are.
  void hold_drivers(VectorX<S>& pose, const S& t) const {
    for (int d : m_.drivers) pose(d) = q_(d);
    pose(var_) = t;
  }

  /// The state before the last stride's accept().
  void restore_stride_start() {
    q_.swap(q_prev_);
    v_.swap(v_prev_);
    q_prev_.swap(undo_q_);
    v_prev_.swap(undo_v_);
    has_prev_ = undo_has_prev_;
    sign_ = undo_sign_;
  }

  /// Predicts trial_ at driver value t, corrects it with Newton; accepted if converged and the correction is
  /// small against the tangent step (a larger one means Newton went to another branch).
  bool try_step(const S& t, SolveReport<S>& rep) {
    const S h = t - q_(var_);
    tangent_ = q_ + v_ * h;
    tangent_(var_) = t;
    predict(t, h);
    rep = solve_position(m_, trial_, sd_);
    if (!rep.ok() && !(rep.status == SolveStatus::Underdetermined && start_.ok())) return false;
    return scaled_distance(trial_, tangent_) <= cfg_.max_correction_ratio * scaled_distance(tangent_, q_) +
                                                    sd_.settings.step_tolerance;
  }

  /// A converged trial whose values are not accurate: the Jacobian of the unknowns is rank deficient, or its
  /// error bound (SolveData::error_bound: condition x the residual of the square system its LU solves)
  /// exceeds eps^(2/3) after Newton's refining step (solve_position). A pose no LU could take (the COD) is
  /// singular.
  bool singular_trial(const SolveReport<S>& rep) const {
    if (rep.status == SolveStatus::Underdetermined) return start_.ok();
    return rep.ok() && sd_.error_bound(rep.residual, rep.equations) > tolerance_once<S, 2, 3>();
  }

  /// From the current (regular) pose, steps over the singular input t to a regular pose beyond it, at least
  /// as far beyond as the current pose is before it (and at least cross_step); a far pose that converges but
  /// is still singular (the condition decays only like 1/distance from the singular point, and the condition
  /// estimates of the dense and sparse paths differ) is tried again twice as far, up to far_tries times. The
  /// far pose must be on the same branch: the cubic Hermite through both regular poses must satisfy the
  /// constraints at t (to eps^(1/2), against the O(h^4) interpolation error), which a pose on another branch
  /// or past a dead point does not. On success the current pose becomes the far one and the span
  /// [previous pose, far pose] is kept for interpolation.
  bool step_over(const S& t, SolveReport<S>& rep, int& iterations, int& evaluations) {
    using std::abs;
    using std::max;
    using std::min;
    constexpr int far_tries = 4;
    const S before = t - q_(var_);
    S beyond = max(abs(before), cross_step_), t_far = t;
    for (int attempt = 1;; ++attempt) {
      t_far = t + (before < S(0) ? S(-beyond) : beyond);
      const bool accepted = try_step(t_far, rep);
      iterations += rep.iterations;
      evaluations += rep.evaluations;
      if (!accepted || limits_.met(q_, trial_)) return false;
      if (!singular_trial(rep)) break;
      if (attempt == far_tries || beyond >= max_step_) return false;
      beyond = min(S(beyond * S(2)), max_step_);
    }
    const int sign = sd_.determinant_sign();
    solve_velocity(m_, sd_, rate_, held_v_);  // sd is factored at the far pose
    // Checked at t and at the middle of the span (t may lie next to an end, where any cubic fits).
    for (const S& at : {t, S((q_(var_) + t_far) / S(2))}) {
      hermite(q_, v_, q_(var_), trial_, held_v_, t_far, at, pose_q_);
      hold_drivers(pose_q_, at);
      evaluate_and_factor(m_, pose_q_, sd_, m_.equation_count());
      ++evaluations;
      if (!(weighted_max_norm<S>(sd_.kin.residual, sd_.row_weight) <= tolerance<S>(S(1) / S(2)))) return false;
    }
    evaluate_and_factor(m_, trial_, sd_, m_.equation_count());  // accept() takes the velocity there
    ++evaluations;
    span_q_ = q_;
    span_v_ = v_;
    has_span_ = true;
    accept();
    if (sign != 0) sign_ = sign;
    return true;
  }

  /// a < x < b or b < x < a.
  static bool between(const S& a, const S& b, const S& x) { return (a < x && x < b) || (b < x && x < a); }

  /// The pose at driver value t inside the span stepped over: cubic Hermite between the regular poses at its
  /// ends (q and qdot), then Newton from there; kept if Newton converges to a regular pose close to the
  /// interpolant (round-off accurate on the followed branch), otherwise the interpolant with status Singular.
  SolveReport<S> pose_in_span(const S& t) {
    const S t0 = span_q_(var_);
    hermite(span_q_, span_v_, t0, q_, v_, q_(var_), t, pose_q_, &pose_v_);
    hold_drivers(pose_q_, t);
    for (std::size_t k = 0; k < m_.drivers.size(); ++k) pose_v_(m_.drivers[k]) = rate_(static_cast<Eigen::Index>(k));
    inside_span_ = true;
    trial_ = pose_q_;
    SolveReport<S> rep = solve_position(m_, trial_, sd_);
    using std::min;
    const S room = min(scaled_distance(pose_q_, span_q_), scaled_distance(pose_q_, q_)) / S(8);
    if (rep.ok() && !singular_trial(rep) && scaled_distance(trial_, pose_q_) <= room) {
      pose_q_.swap(trial_);
      solve_velocity(m_, sd_, rate_, pose_v_);
      return rep;
    }
    evaluate_and_factor(m_, pose_q_, sd_, m_.equation_count());  // the residual of the values returned
    rep.residual = weighted_max_norm<S>(sd_.kin.residual, sd_.row_weight);
    rep.condition = sd_.condition;
    rep.rank = sd_.rank;
    rep.status = SolveStatus::Singular;
    rep.limit_input = t;
    std::ostringstream os;
    os << "singular pose at " << m_.variables[var_].name << " = " << to_double(t)
       << ": the branches meet (Jacobian of the unknowns singular); the values follow the branch, interpolated"
       << " between the regular poses at " << to_double(t0) << " and " << to_double(q_(var_));
    rep.detail = os.str();
    return rep;
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
        hermite(q_prev_, v_prev_, q_prev_(var_), q_, v_, q_(var_), t, trial_);
        break;
      }
    }
    hold_drivers(trial_, t);
  }

  void accept() {
    take_closing_step();
    q_prev_.swap(q_);
    v_prev_.swap(v_);
    q_.swap(trial_);
    has_prev_ = true;
    solve_velocity(m_, sd_, rate_, v_);  // sd is factored at the accepted pose
  }

  /// The closing step (file comment): sd is factored at trial_, whose Newton step from there, without a
  /// further evaluation, takes its unknowns from up to condition x 64 eps (Newton's residual tolerance) to
  /// round-off. Skipped where that step is not small (a pose taken at a singular point).
  void take_closing_step() {
    if (newton_step(sd_, m_.equation_count()) <= sd_.settings.step_tolerance) add_step(m_, trial_, sd_);
  }

  S clamp_step(const S& remaining, const S& preferred = std::numeric_limits<S>::infinity()) const {
    using std::abs;
    using std::min;
    const S len = min(min(abs(remaining), max_step_), preferred);
    return remaining < S(0) ? S(-len) : len;
  }

  /// Max-norm of a - b in scaled variables (the expression a - b is read entry by entry, no temporary).
  S scaled_distance(const VectorX<S>& a, const VectorX<S>& b) const { return weighted_max_norm<S>(a - b, weight_); }

  /// The step collapsed at the current pose: a dead point if the Jacobian of the unknowns has become
  /// ill-conditioned (condition grown by ill_conditioned over the sweep's start, or above eps^-1/3), else
  /// no convergence.
  SolveReport<S> classify_stop(const SolveReport<S>& failed) {
    using std::abs;
    // The limit lies within about 2 min_step of the current pose; a contact parameter that moves by up to
    // 4 min_step |du/dt| from here reaches a corner that lies there: the step collapsed at the corner.
    reach_ = (S(4) * min_step_) * v_.cwiseAbs();
    if (const ContactLimit corner = limits_.at_corner(q_, reach_)) return contact_limit_report(corner);
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

  /// A contact limit met before driver value t: bisect between the current pose and t (to min_step), the
  /// current pose staying on the near side; the limit reported is the one met by the last step that failed.
  SolveReport<S> locate_contact_limit(S t, ContactLimit limit) {
    using std::abs;
    SolveReport<S> rep;
    while (abs(t - q_(var_)) > min_step_) {
      const S mid = (q_(var_) + t) / S(2);
      if (!try_step(mid, rep)) {
        t = mid;
        continue;
      }
      if (const ContactLimit met = limits_.met(q_, trial_)) {
        limit = met;
        t = mid;
      } else {
        accept();
      }
    }
    return contact_limit_report(limit);
  }

  /// The report of a contact limit met just beyond the current pose (its input value: the limit's).
  SolveReport<S> contact_limit_report(const ContactLimit& limit) {
    trial_ = q_;
    SolveReport<S> rep = solve_position(m_, trial_, sd_);
    rep.status = limit.corner < 0 ? SolveStatus::DomainExit : SolveStatus::Corner;
    rep.limit_input = q_(var_);
    const Pair<S>& p = m_.pairs[m_.variables[limit.variable].pair];
    rep.pair = m_.variables[limit.variable].pair;
    rep.contour = limit.variable == p.first_variable ? p.contour_a : p.contour_b;
    rep.corner = limit.corner;
    const Contour<S>& c = m_.contours[rep.contour];
    std::ostringstream os;
    os << "contact of pair '" << p.name << "' ";
    if (limit.corner < 0) {
      os << "leaves contour '" << c.name() << "' (" << m_.variables[limit.variable].name << " reaches the end of its domain)";
    } else {
      const ContourCorner<S>& k = c.corners()[static_cast<std::size_t>(limit.corner)];
      os << "reaches a corner of contour '" << c.name() << "' (" << k.label << ", at (" << to_double(k.point.x()) << ", "
         << to_double(k.point.y()) << ") in the contour's frame, " << m_.variables[limit.variable].name << " = "
         << to_double(trial_(limit.variable)) << "): the contact cannot pass it";
    }
    os << " at " << m_.variables[var_].name << " = " << to_double(q_(var_));
    rep.detail = os.str();
    return rep;
  }

  const Mechanism<S>& m_;
  SolveData<S>& sd_;
  int var_;
  const ContinuationSettings<S>& cfg_;
  VectorX<S> q_, q_prev_, trial_, tangent_, v_, v_prev_, rate_;
  VectorX<S> weight_;  // 1 / m.variable_scale of every variable, for scaled_distance
  ContactLimits<S> limits_;
  bool has_prev_ = false;
  SolveReport<S> start_;
  S base_condition_;
  S max_step_, min_step_, cross_step_;  // in the driver's own unit (ContinuationSettings times its scale)
  int sign_ = 0;                        // sign of det J_u along the followed branch (0: unknown)
  // The span last stepped over (singular input inside): its regular start pose; the end is the current pose.
  VectorX<S> span_q_, span_v_;
  bool has_span_ = false;
  // The pose returned for a target inside the span.
  VectorX<S> pose_q_, pose_v_;
  bool inside_span_ = false;
  // A converged but singular trial kept while stepping over it.
  VectorX<S> held_, held_v_;
  SolveReport<S> held_report_;
  VectorX<S> reach_;  // how far each variable may move within the located limit (classify_stop)
  // Dense output: the interpolation span, the report of the interpolated poses, the state a stride undoes.
  S span_ = S(0);
  SolveReport<S> interpolated_;
  VectorX<S> undo_q_, undo_v_;
  bool undo_has_prev_ = false;
  int undo_sign_ = 0;
};

}  // namespace detail

}  // namespace rollkin
