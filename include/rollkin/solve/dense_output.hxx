// The dense output of the continuation (solve/continuation.hpp's file comment, "Dense output"): one stride of
// the tracer (solve/tracer.hxx) over the inputs within its interpolation span, the poses before its end
// interpolated and kept when verified. Used by the sweeps (solve/sweep.hxx).
#pragma once

#include "rollkin/solve/tracer.hxx"

namespace rollkin {

namespace detail {

/// Dense output (file comment) from input side[k] on: the inputs within the tracer's interpolation span in
/// one stride, the last solved, those before it interpolated and kept when verified. Returns how many
/// inputs were reported (0: the tracer takes input side[k] itself).
template <class S, class Out>
std::size_t interpolate_stride(Tracer<S>& tracer, const std::vector<S>& inputs, const std::vector<std::size_t>& side,
                               std::size_t k, Out& out) {
  using std::abs;
  using std::max;
  const S from = tracer.driver_value();
  std::size_t end = k;
  while (end + 1 < side.size() && abs(inputs[side[end + 1]] - from) <= tracer.interpolation_span()) ++end;
  SolveReport<S> rep;
  if (!tracer.stride(inputs[side[end]], rep)) return 0;
  // The cubic's error is 16 s^2 (1 - s)^2 times its largest at the fraction s of the stride: within an
  // eighth of either end it is a fifth of that, and the residuals there show the round-off level.
  const S length = inputs[side[end]] - from;
  S largest(0), near_ends(0);
  for (std::size_t j = k; j < end; ++j) {
    const S residual = tracer.interpolate(inputs[side[j]]);
    largest = max(largest, residual);
    const S s = (inputs[side[j]] - from) / length;
    if (s <= S(1) / S(8) || s >= S(7) / S(8)) near_ends = max(near_ends, residual);
    if (!tracer.interpolation_verified()) {
      tracer.undo_stride(inputs[side[j]]);
      return j - k;
    }
    out.set_interpolated_pose(side[j], tracer.interpolated_pose(), tracer.interpolated_report());
  }
  // Where the condition times Newton's tolerance exceeds eps^(2/3), a converged prediction takes one
  // refining step (detail::worth_refining) and reports one iteration although it met the tolerance.
  const bool refined = rep.condition * tracer.newton_tolerance() > tolerance_once<S, 2, 3>();
  const bool prediction_met = rep.iterations == 0 || (rep.iterations == 1 && refined);
  tracer.update_span(largest, prediction_met, max(rep.residual, near_ends));
  out.set_pose(side[end], tracer.q(), tracer.v(), rep);
  return end + 1 - k;
}

/// Whether a sink of the continuation keeps every pose's values (then no pose is interpolated).
template <class S> bool keeps_values(const SweepSummary<S>&) { return false; }
template <class S> bool keeps_values(const SweepSink<S>& out) { return out.keeps_values(); }

}  // namespace detail

}  // namespace rollkin
