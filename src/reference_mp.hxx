// The MPFR reference sweep (include/rollkin/reference.hpp), included by the one translation unit per precision
// that compiles it: src/reference_mp30.cpp, reference_mp50.cpp, reference_mp100.cpp. Each compiles the
// solver in one MPFR type only, so the three build in parallel and none holds all three in memory
// (docs/benchmark.md, "Build times").
#pragma once

#include "rollkin/reference.hpp"

#include "rollkin/io/units.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/sweep.hxx"  // compiled here for 30 and 100 digits
#include "rollkin/solve/mpfr50_instances.hpp"  // the 50-digit solver: src/solve/instantiate_mpfr50.cpp

namespace rollkin {

namespace {

template <class S> std::string decimal(const S& x, int digits) {
  using std::isfinite;
  if (!(x == x)) return "nan";
  return x.str(digits, std::ios_base::fmtflags(0));
}

template <class S> S display_scale(const Mechanism<S>& m, int var) {
  return m.variables[var].kind == ParamKind::Angle ? rad_to_deg(S(1)) : S(1);
}

template <class S> std::string limit_text(const SolveReport<S>& r, int digits) {
  return std::string(to_string(r.status)) + " at " + decimal(r.limit_input, digits) + ": " + r.detail;
}

}  // namespace

template <class S>
ReferenceSweep reference_sweep_mp(const Mechanism<S>& m, const VectorX<S>& guess, const std::vector<int>& held,
                                  int driver, const std::vector<S>& inputs, const ReferenceOptions& options) {
  const int digits = std::numeric_limits<S>::digits10;
  ReferenceSweep out;
  out.digits = digits;
  for (const auto& v : m.variables) {
    out.variables.push_back(v.name);
    out.kinds.push_back(v.kind);
  }
  SolveData<S> sd(m);
  sd.settings.consistency_tolerance = S(options.consistency_tolerance);
  VectorX<S> q = guess;
  const SolveReport<S> assembly = assemble(m, q, sd, held);
  out.assembly_status = assembly.status;
  out.assembly_detail = assembly.detail;
  out.assembly_residual = decimal(assembly.residual, 3);
  out.rank = assembly.rank;
  out.equations = assembly.equations;
  out.unknowns = assembly.unknowns;
  for (Eigen::Index i = 0; i < q.size(); ++i) out.assembly_q_raw.push_back(decimal(q(i), digits));

  const SweepResult<S> r = sweep(m, sd, q, assembly, driver, inputs);
  const int var = m.drivers.at(driver);
  for (const auto& lim : r.limits) out.limits.push_back(limit_text(lim, digits));
  for (const auto& pose : r.poses) {
    ReferencePose p;
    p.status = pose.report.status;
    p.iterations = pose.report.iterations;
    p.input = decimal(S(pose.input * display_scale(m, var)), digits);
    if (pose.report.has_pose()) {
      p.residual = decimal(pose.report.residual, 3);
      for (Eigen::Index i = 0; i < pose.q.size(); ++i) {
        p.q_raw.push_back(decimal(pose.q(i), digits));
        p.q.push_back(decimal(S(pose.q(i) * display_scale(m, static_cast<int>(i))), digits));
      }
    }
    out.poses.push_back(std::move(p));
  }
  return out;
}

namespace detail {

/// reference_sweep() at D digits: the mechanism, guess and inputs cast to MPFR, then reference_sweep_mp.
template <unsigned D>
ReferenceSweep reference_run(const Mechanism<double>& mech, const VectorX<double>& guess, const std::vector<int>& held,
                        int driver, const std::vector<std::string>* decimal_inputs,
                        const std::vector<double>* inputs, const ReferenceOptions& options) {
  using S = mpfr_scalar<D>;
  const Mechanism<S> m = mech.template cast<S>();
  const VectorX<S> g = guess.template cast<S>();
  std::vector<S> in;
  const int var = m.drivers.at(driver);
  if (decimal_inputs) {
    const S to_solver = m.variables[var].kind == ParamKind::Angle ? io::radians_per<S>(io::AngleUnit::Degree) : S(1);
    for (const auto& s : *decimal_inputs) in.push_back(S(s) * to_solver);
  } else {
    for (double x : *inputs) in.push_back(S(x));
  }
  return reference_sweep_mp<S>(m, g, held, driver, in, options);
}

}  // namespace detail

}  // namespace rollkin

/// Compiles the reference sweep at D digits (in one of the src/reference_mp*.cpp).
#define ROLLKIN_INSTANTIATE_REFERENCE(D)                                                                          \
  namespace rollkin {                                                                                           \
  template ReferenceSweep reference_sweep_mp<mpfr_scalar<D>>(const Mechanism<mpfr_scalar<D>>&,                   \
                                                             const VectorX<mpfr_scalar<D>>&, const std::vector<int>&, \
                                                             int, const std::vector<mpfr_scalar<D>>&,           \
                                                             const ReferenceOptions&);                          \
  template ReferenceSweep detail::reference_run<D>(const Mechanism<double>&, const VectorX<double>&,              \
                                                   const std::vector<int>&, int, const std::vector<std::string>*, \
                                                   const std::vector<double>*, const ReferenceOptions&);         \
  }
