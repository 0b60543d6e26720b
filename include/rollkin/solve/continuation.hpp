// Continuation along one driver: from the assembled pose, follow the same branch to every requested input
// value, in both directions when the requested range straddles the assembly input.
//
// Each sub-step predicts the pose at the new input (by default a cubic Hermite extrapolation through the
// last two poses and their velocities), corrects it with Newton and is accepted only if Newton converged
// and the result lies close to the tangent prediction q + qdot h compared with the tangent step itself (no
// silent jump to another branch); otherwise the step is halved. An accepted pose takes the closing step, the
// Newton step of its own last evaluation without evaluating again, which brings it from the residual
// tolerance to round-off (the prediction extrapolates the last poses and would multiply their errors).
// When the step falls below min_step the motion ends there: a dead point if the unknowns' Jacobian has
// become ill-conditioned (the limit then lies within about 2 min_step of the last pose), otherwise no
// convergence. After every accepted step, contact parameters are checked against their contours' domains
// (open contours) and corners (tangent discontinuities, which a contact may not pass); the limit is located
// by bisection to min_step.
//
// Singular points on the way (branches meet: bifurcations, singular cam poses). The sign of det J_u (square
// systems, from the LU's pivots and row parity) is kept along the branch. A converged step that changes it
// has passed a singular point: while the step is long it is halved toward that point, and the point is crossed
// only with a step of at most cross_step (a 64th of max_step), whose prediction error (O(h^4) for Hermite) is
// far below the O(h) separation of the branches, so Newton stays on the followed branch. A converged pose
// that is itself singular (condition x residual above eps^(2/3): its values are not accurate) is never the
// base of a prediction: the tracer steps over it from the last regular pose to a regular pose beyond, and a
// requested input in between gets the cubic Hermite interpolant of the two regular poses (q and qdot),
// polished by Newton when that is regular there, otherwise reported with status Singular.
// Dense output (a sweep that reports no values, sweep_summary()). Where the requested inputs lie closer
// together than accuracy needs, one sub-step (a stride) goes to the last input within the interpolation span;
// the inputs before it take the cubic Hermite interpolant between the stride's ends (q and qdot), with their
// residual evaluated (no Jacobian, no factorisation). One is kept when that residual is within a quarter of
// Newton's tolerance (a solved pose meets the tolerance and then takes the closing step; an interpolated one
// takes none) and its error bound is not singular; one that fails undoes the stride from there. The residual
// of the interpolant is the Jacobian times its error, which grows as the span^4: the span follows the
// stride's largest residual toward 8 epsilon (residuals of exact poses are a few epsilon of round-off), and
// a stride that interpolated nothing doubles it only when its end's prediction met Newton's tolerance.
// max_step, min_step are relative to the driver's variable scale (Mechanism::variable_scale).
#pragma once

#include "rollkin/solve/position.hpp"
#include "rollkin/solve/sweep_result.hpp"
#include "rollkin/solve/sweep_summary.hpp"

#include <atomic>
#include <cstddef>
#include <vector>

namespace rollkin {

/// How the next pose is predicted before Newton corrects it.
enum class Predictor {
  Previous,  // the last pose itself (zero order), kept for comparison in the benchmark
  Tangent,   // q + qdot h, the velocity solution (first order)
  Hermite    // cubic through the last two poses and their velocities (third order), tangent at the start
};

/// Steps are in units of the driver's variable scale (Mechanism::variable_scale: radians for angles, the
/// mechanism's length scale for lengths), so a scene scaled by any factor takes the same sub-steps.
template <class S> struct ContinuationSettings {
  S max_step = pi<S>() / S(36);      // largest sub-step of the driver (5 degrees for angles)
  S min_step = S(1) / S(1000000000); // 1e-9: limits are located to about 2e-9 in the driver
  S cross_fraction = S(1) / S(64);   // singular points are crossed with sub-steps of at most this x max_step
  S max_correction_ratio = S(1) / S(2);
  S ill_conditioned = S(100);        // condition growth (vs the sweep's start) that marks a dead point
  Predictor predictor = Predictor::Hermite;
  /// Dense output (file comment) where the sweep reports no values; false: every input is solved.
  bool interpolate = true;
  /// Cancellation (e.g. a Ctrl-C in the Python module): when set and true, sweep() stops before the next
  /// requested pose; the poses not reached keep the status NotReached.
  const std::atomic<bool>* cancel = nullptr;
  /// sweep() keeps every solved pose's link poses (SweepResult::link_poses), from the pair states of the
  /// pose's last evaluation (link_poses_near): what a table of link poses reads instead of evaluating the
  /// spanning tree's pairs again at every pose.
  bool link_poses = false;
};

/// Where sweep_into() reports the continuation, for a caller that keeps the poses its own way (e.g. in a
/// file, output/sweep_file.hpp). Each side of the assembly input is reported nearest first: ascending above it,
/// then descending below it. A sink that does not keep values (keeps_values() false) may be given poses
/// interpolated between the continuation's sub-steps (dense output, file comment).
template <class S> struct SweepSink {
  static constexpr bool holds_values = false;  // decided at run time: keeps_values()
  virtual ~SweepSink() = default;
  virtual bool keeps_values() const = 0;
  /// A limit met (at most one per direction), as SweepResult::limits.
  virtual void add_limit(const SolveReport<S>& limit) = 0;
  /// Requested input k solved: its pose, its rates for a unit driver rate and its report.
  virtual void set_pose(std::size_t k, const VectorX<S>& q, const VectorX<S>& qdot, const SolveReport<S>& rep) = 0;
  /// Requested input k without a pose (beyond a limit).
  virtual void set_report(std::size_t k, const SolveReport<S>& rep) = 0;
  /// Requested input k has the report of input `like` (not reached beyond a limit).
  virtual void share_report(std::size_t k, std::size_t like) = 0;
  /// Requested input k interpolated and verified by its residual (only where keeps_values() is false).
  virtual void set_interpolated_pose(std::size_t k, const VectorX<S>& q, const SolveReport<S>& rep) = 0;
};

/// Bounded work: a lower bound on the continuation sub-steps sweep() takes for `inputs` from the assembly
/// pose q0, checked before solving. The driver travels from q0 to both ends of the requested range in
/// sub-steps of at most max_step (in its variable scale), and every requested value ends a sub-step.
template <class S> S estimate_substeps(const Mechanism<S>& m, const VectorX<S>& q0, int driver, const std::vector<S>& inputs,
                                       const ContinuationSettings<S>& cfg = {});

/// Sweeps driver number `driver` (index into m.drivers) over `inputs`, starting from the assembled pose q0
/// (sd.kin.reference must hold the assembly pose, as assemble() leaves it).
template <class S> SweepResult<S> sweep(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0,
                                        const SolveReport<S>& assembly, int driver, const std::vector<S>& inputs,
                                        const ContinuationSettings<S>& cfg = {});

/// The same continuation as sweep(), keeping only what a summary reports (sweep_summary.hpp): statuses,
/// the largest residual, limits and singular poses, no values.
template <class S> SweepSummary<S> sweep_summary(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0,
                                                 const SolveReport<S>& assembly, int driver, const std::vector<S>& inputs,
                                                 const ContinuationSettings<S>& cfg = {});

/// The continuation of sweep() reported into the caller's sink instead of a SweepResult.
template <class S>
void sweep_into(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0, const SolveReport<S>& assembly, int driver,
                const std::vector<S>& inputs, const ContinuationSettings<S>& cfg, SweepSink<S>& out);

// The sweeps for one scalar S, after KEYWORD (`extern template` or `template`; ROLLKIN_POSITION_INSTANCES,
// docs/benchmark.md, "Build times").
#define ROLLKIN_CONTINUATION_INSTANCES(KEYWORD, S)                                                            \
  KEYWORD S estimate_substeps(const Mechanism<S>&, const VectorX<S>&, int, const std::vector<S>&,               \
                              const ContinuationSettings<S>&);                                                  \
  KEYWORD SweepResult<S> sweep(const Mechanism<S>&, SolveData<S>&, const VectorX<S>&, const SolveReport<S>&, int, \
                               const std::vector<S>&, const ContinuationSettings<S>&);                          \
  KEYWORD SweepSummary<S> sweep_summary(const Mechanism<S>&, SolveData<S>&, const VectorX<S>&, const SolveReport<S>&, \
                                        int, const std::vector<S>&, const ContinuationSettings<S>&);             \
  KEYWORD void sweep_into(const Mechanism<S>&, SolveData<S>&, const VectorX<S>&, const SolveReport<S>&, int,      \
                          const std::vector<S>&, const ContinuationSettings<S>&, SweepSink<S>&);

// Compiled once for double, in src/solve/instantiate_double.cpp.
ROLLKIN_CONTINUATION_INSTANCES(extern template, double)

}  // namespace rollkin
