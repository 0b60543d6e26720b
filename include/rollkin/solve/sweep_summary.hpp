// What a sweep found, without its poses: each requested input's status, the largest residual of the solved
// poses, the limits met and the singular poses' reports. sweep_summary() (continuation.hpp) fills one by the
// same continuation as sweep() for a run that reports only this (`rollkin solve` without output files): it
// stores no values, where a SweepResult's columns are written once per pose (their first touch, page faults
// and zeroing, was 29 % of such a run of the paper example), and on a fine grid interpolates the poses
// between its sub-steps, each verified by its residual (dense output, continuation.hpp). summarise() reads
// one from a SweepResult, so a report is written from a summary whichever way the sweep ran.
//
//   const SweepSummary<double> s = sweep_summary(m, sd, q0, assembly, 0, inputs);
//   if (s.solved() < inputs.size()) for (const auto& l : s.limits) explain(l);
#pragma once

#include "rollkin/solve/sweep_result.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace rollkin {

template <class S> struct SweepSummary {
  /// A pose the continuation found singular: its index among the requested inputs, and its report.
  struct SingularPose {
    std::size_t index;
    SolveReport<S> report;
  };
  SolveReport<S> assembly;
  std::vector<SolveReport<S>> limits;  // limits met (at most one per direction), as SweepResult::limits
  std::vector<SolveStatus> status;     // per requested input
  std::vector<SingularPose> singular;  // in the order of the requested inputs
  S max_residual = S(0);               // over the plainly solved poses
  std::size_t interpolated = 0;        // poses interpolated between sub-steps (dense output, continuation.hpp)
  /// Keeps no values: the continuation may interpolate poses between its sub-steps (continuation.hpp).
  static constexpr bool holds_values = false;

  SweepSummary() = default;
  /// `poses` requested inputs, each with status `initial` until it is reported.
  SweepSummary(const SolveReport<S>& assembly_report, std::size_t poses, SolveStatus initial)
      : assembly(assembly_report), status(poses, initial) {}

  std::size_t size() const { return status.size(); }
  /// Plainly solved poses (status Converged).
  std::size_t solved() const { return static_cast<std::size_t>(std::count(status.begin(), status.end(), SolveStatus::Converged)); }

  // What the continuation reports (detail::trace_sweep), as into a SweepResult.
  void set_report(std::size_t k, const SolveReport<S>& rep) {
    using std::max;
    status[k] = rep.status;
    if (rep.ok()) max_residual = max(max_residual, rep.residual);
    if (rep.status == SolveStatus::Singular) singular.push_back({k, rep});
  }
  template <class Q, class V> void set_pose(std::size_t k, const Q&, const V&, const SolveReport<S>& rep) { set_report(k, rep); }
  /// A pose interpolated and verified by its residual (dense output): plainly solved, counted apart.
  template <class Q> void set_interpolated_pose(std::size_t k, const Q&, const SolveReport<S>& rep) {
    set_report(k, rep);
    ++interpolated;
  }
  /// Pose k has the status of pose `like`, which the continuation gives only to poses without values (not
  /// reached beyond a limit), so nothing else is counted.
  void share_report(std::size_t k, std::size_t like) { status[k] = status[like]; }
  void add_limit(const SolveReport<S>& limit) { limits.push_back(limit); }
  /// Singular poses in the order of the requested inputs (the continuation reports both sides of the
  /// assembly input in turn).
  void sort_singular() {
    std::sort(singular.begin(), singular.end(), [](const SingularPose& a, const SingularPose& b) { return a.index < b.index; });
  }
};

/// The summary of a stored sweep: the same as sweep_summary() on the same request.
template <class S> SweepSummary<S> summarise(const SweepResult<S>& r) {
  SweepSummary<S> s(r.assembly, r.size(), SolveStatus::NotReached);
  s.limits = r.limits;
  for (std::size_t k = 0; k < r.size(); ++k) s.set_report(k, r.report(k));
  return s;
}

}  // namespace rollkin
