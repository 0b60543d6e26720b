// The solver in mpfr50, compiled once (include/rollkin/solve/mpfr50_instances.hpp declares these `extern
// template`; docs/benchmark.md, "Build times").
#include "rollkin/solve/mpfr50_instances.hpp"

namespace rollkin {

template SolveReport<mpfr50> solve_position(const Mechanism<mpfr50>&, VectorX<mpfr50>&, SolveData<mpfr50>&, int);
template void solve_velocity(const Mechanism<mpfr50>&, SolveData<mpfr50>&, const VectorX<mpfr50>&, VectorX<mpfr50>&);
template VectorX<mpfr50> solve_velocity(const Mechanism<mpfr50>&, SolveData<mpfr50>&, const VectorX<mpfr50>&);
template VectorX<mpfr50> solve_acceleration(const Mechanism<mpfr50>&, const VectorX<mpfr50>&, SolveData<mpfr50>&,
                                            const VectorX<mpfr50>&, const VectorX<mpfr50>&);
template SolveReport<mpfr50> assemble(const Mechanism<mpfr50>&, VectorX<mpfr50>&, SolveData<mpfr50>&, const std::vector<int>&);
template SweepResult<mpfr50> sweep(const Mechanism<mpfr50>&, SolveData<mpfr50>&, const VectorX<mpfr50>&,
                                   const SolveReport<mpfr50>&, int, const std::vector<mpfr50>&,
                                   const ContinuationSettings<mpfr50>&);
template PoseAnalysis<mpfr50> analyse_pose(const Mechanism<mpfr50>&, const VectorX<mpfr50>&, const VectorX<mpfr50>&,
                                           AnalysisData<mpfr50>&);

}  // namespace rollkin
