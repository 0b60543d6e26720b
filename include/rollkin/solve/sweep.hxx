// The bodies of the sweeps declared in solve/continuation.hpp (whose file comment describes the method): the
// continuation from the assembled pose to every requested input on both sides, with the tracer of one branch
// (solve/tracer.hxx) and its dense output (solve/dense_output.hxx). Included by the translation units that
// compile them (src/solve/instantiate_double.cpp, instantiate_mpfr50.cpp, the MPFR reference) and by code
// that sweeps in another scalar; everything else includes continuation.hpp only (docs/benchmark.md, "Build
// times").
#pragma once

#include "rollkin/solve/continuation.hpp"
#include "rollkin/solve/dense_output.hxx"
#include "rollkin/solve/tracer.hxx"

#include <algorithm>

namespace rollkin {

template <class S> S estimate_substeps(const Mechanism<S>& m, const VectorX<S>& q0, int driver, const std::vector<S>& inputs,
                                       const ContinuationSettings<S>& cfg) {
  using std::max;
  const int var = m.drivers[driver];
  S up(0), down(0);
  for (const S& x : inputs) {
    up = max(up, S(x - q0(var)));
    down = max(down, S(q0(var) - x));
  }
  return (up + down) / (cfg.max_step * m.variable_scale(var)) + S(static_cast<long long>(inputs.size()));
}

namespace detail {

/// Sorts indices by `before`; a grid in either direction is already in order or reversed, in O(n).
template <class Before> void nearest_first(std::vector<std::size_t>& indices, Before before) {
  if (std::is_sorted(indices.begin(), indices.end(), before)) return;
  const auto after = [&](std::size_t a, std::size_t b) { return before(b, a); };
  if (std::is_sorted(indices.begin(), indices.end(), after))
    std::reverse(indices.begin(), indices.end());
  else
    std::sort(indices.begin(), indices.end(), before);
}

/// sweep()'s continuation from the assembled pose q0 to every requested input, reported into out (a
/// SweepResult, a SweepSummary for sweep_summary(), or the caller's SweepSink for sweep_into()).
template <class S, class Out>
void trace_sweep(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0, int driver, const std::vector<S>& inputs,
                 const ContinuationSettings<S>& cfg, Out& out) {
  const int var = m.drivers[driver];
  // Requested inputs on each side of the assembly input, nearest first.
  std::vector<std::size_t> up, down;
  up.reserve(inputs.size());
  down.reserve(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) (inputs[i] >= q0(var) ? up : down).push_back(i);
  nearest_first(up, [&](auto a, auto b) { return inputs[a] < inputs[b]; });
  nearest_first(down, [&](auto a, auto b) { return inputs[a] > inputs[b]; });

  for (const auto* side : {&up, &down}) {
    if (side->empty()) continue;
    detail::Tracer<S> tracer(m, sd, driver, cfg, q0);
    for (std::size_t k = 0; k < side->size(); ++k) {
      if (cfg.cancel && cfg.cancel->load(std::memory_order_relaxed)) return;
      if constexpr (!Out::holds_values) {
        if (cfg.interpolate && !keeps_values(out)) {
          if (const std::size_t done = interpolate_stride(tracer, inputs, *side, k, out)) {
            k += done - 1;
            continue;
          }
        }
      }
      const std::size_t at = (*side)[k];
      const SolveReport<S> rep = tracer.advance(inputs[at]);
      if (!rep.has_pose()) {  // this input and all beyond it on this side are past the limit
        out.add_limit(rep);
        out.set_report(at, rep);
        if (k + 1 < side->size()) {
          SolveReport<S> beyond = rep;
          beyond.status = SolveStatus::NotReached;
          out.set_report((*side)[k + 1], beyond);
          for (std::size_t rest = k + 2; rest < side->size(); ++rest) out.share_report((*side)[rest], (*side)[k + 1]);
        }
        break;
      }
      out.set_pose(at, tracer.q(), tracer.v(), rep);
      if constexpr (Out::holds_values) {
        if (out.keeps_link_poses()) out.set_link_poses(at, m, sd.kin, tracer.q());
      }
    }
  }
}

}  // namespace detail

template <class S>
void sweep_into(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0, const SolveReport<S>& assembly, int driver,
                const std::vector<S>& inputs, const ContinuationSettings<S>& cfg, SweepSink<S>& out) {
  if (assembly.ok()) detail::trace_sweep(m, sd, q0, driver, inputs, cfg, out);
}

template <class S> SweepResult<S> sweep(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0,
                                        const SolveReport<S>& assembly, int driver, const std::vector<S>& inputs,
                                        const ContinuationSettings<S>& cfg) {
  // Sized once for every requested input: storing a pose below allocates nothing.
  SweepResult<S> out(assembly, inputs, static_cast<Eigen::Index>(m.variable_count()),
                     assembly.ok() ? SolveStatus::NotReached : assembly.status, cfg.link_poses ? m.links.size() : 0);
  if (assembly.ok()) detail::trace_sweep(m, sd, q0, driver, inputs, cfg, out);
  out.zero_columns_without_values();
  return out;
}

template <class S> SweepSummary<S> sweep_summary(const Mechanism<S>& m, SolveData<S>& sd, const VectorX<S>& q0,
                                                 const SolveReport<S>& assembly, int driver, const std::vector<S>& inputs,
                                                 const ContinuationSettings<S>& cfg) {
  SweepSummary<S> out(assembly, inputs.size(), assembly.ok() ? SolveStatus::NotReached : assembly.status);
  if (assembly.ok()) detail::trace_sweep(m, sd, q0, driver, inputs, cfg, out);
  out.sort_singular();
  return out;
}

}  // namespace rollkin
