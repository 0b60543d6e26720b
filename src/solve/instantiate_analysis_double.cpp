// What follows a sweep for double, compiled once: the contact analysis, the design check, the centrodes and
// the interference check.
// The headers declare these `extern template`, so every other translation unit that calls them for double only
// parses them (docs/benchmark.md, "Build times").
#include "rollkin/analysis.hpp"
#include "rollkin/design_check.hpp"
#include "rollkin/centrodes.hpp"
#include "rollkin/solve/interference.hpp"

namespace rollkin {

template PoseAnalysis<double> analyse_pose(const Mechanism<double>&, const VectorX<double>&, const VectorX<double>&,
                                           AnalysisData<double>&);
template DesignCheck<double> check_design(const Mechanism<double>&, const SweepResult<double>&,
                                          const DesignCheckOptions&);
template std::vector<InstantCentre<double>> centrodes(const Mechanism<double>&, KinematicsData<double>&,
                                                      const SweepResult<double>&, int, int);
template SweepInterference check_interference(const Mechanism<double>&, const SweepResult<double>&,
                                              const InterferenceCheck&);

}  // namespace rollkin
