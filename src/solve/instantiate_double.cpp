// The solver for double, compiled once: position, velocity, acceleration, assembly and the sweeps (one
// translation unit, so that the sweep inlines the Newton solve it calls).
// The headers declare these `extern template`, so every other translation unit that calls them for double only
// parses them (docs/benchmark.md, "Build times").
#include "rollkin/solve/position.hpp"
#include "rollkin/solve/continuation.hpp"

namespace rollkin {

template SolveReport<double> solve_position(const Mechanism<double>&, VectorX<double>&, SolveData<double>&, int);
template void solve_velocity(const Mechanism<double>&, SolveData<double>&, const VectorX<double>&, VectorX<double>&);
template VectorX<double> solve_velocity(const Mechanism<double>&, SolveData<double>&, const VectorX<double>&);
template VectorX<double> solve_acceleration(const Mechanism<double>&, const VectorX<double>&, SolveData<double>&,
                                            const VectorX<double>&, const VectorX<double>&);
template SolveReport<double> assemble(const Mechanism<double>&, VectorX<double>&, SolveData<double>&,
                                      const std::vector<int>&);
template double estimate_substeps(const Mechanism<double>&, const VectorX<double>&, int, const std::vector<double>&,
                                  const ContinuationSettings<double>&);
template SweepResult<double> sweep(const Mechanism<double>&, SolveData<double>&, const VectorX<double>&,
                                   const SolveReport<double>&, int, const std::vector<double>&,
                                   const ContinuationSettings<double>&);
template SweepSummary<double> sweep_summary(const Mechanism<double>&, SolveData<double>&, const VectorX<double>&,
                                            const SolveReport<double>&, int, const std::vector<double>&,
                                            const ContinuationSettings<double>&);

}  // namespace rollkin
