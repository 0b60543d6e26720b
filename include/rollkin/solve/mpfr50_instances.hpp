// The solver in rollkin::mpfr50 (50 digits), compiled once in src/solve/instantiate_mpfr50.cpp, as the solver
// for double is (solve/position.hpp, continuation.hpp; docs/benchmark.md, "Build times"). A translation unit
// that solves in mpfr50 includes this header, and then only parses the solver instead of compiling it again.
#pragma once

#include "rollkin/analysis.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/continuation.hpp"

namespace rollkin {

extern template SolveReport<mpfr50> solve_position(const Mechanism<mpfr50>&, VectorX<mpfr50>&, SolveData<mpfr50>&, int);
extern template void solve_velocity(const Mechanism<mpfr50>&, SolveData<mpfr50>&, const VectorX<mpfr50>&, VectorX<mpfr50>&);
extern template VectorX<mpfr50> solve_velocity(const Mechanism<mpfr50>&, SolveData<mpfr50>&, const VectorX<mpfr50>&);
extern template VectorX<mpfr50> solve_acceleration(const Mechanism<mpfr50>&, const VectorX<mpfr50>&, SolveData<mpfr50>&,
                                                   const VectorX<mpfr50>&, const VectorX<mpfr50>&);
extern template SolveReport<mpfr50> assemble(const Mechanism<mpfr50>&, VectorX<mpfr50>&, SolveData<mpfr50>&,
                                             const std::vector<int>&);
extern template SweepResult<mpfr50> sweep(const Mechanism<mpfr50>&, SolveData<mpfr50>&, const VectorX<mpfr50>&,
                                          const SolveReport<mpfr50>&, int, const std::vector<mpfr50>&,
                                          const ContinuationSettings<mpfr50>&);
extern template PoseAnalysis<mpfr50> analyse_pose(const Mechanism<mpfr50>&, const VectorX<mpfr50>&, const VectorX<mpfr50>&,
                                                  AnalysisData<mpfr50>&);

}  // namespace rollkin
