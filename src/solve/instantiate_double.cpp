// The solver for double, compiled once: position, velocity, acceleration, assembly and the sweeps (one
// translation unit, so that the sweep inlines the Newton solve it calls).
// The headers declare these `extern template` with the same lists (ROLLKIN_*_INSTANCES), so every other
// translation unit that calls them for double only parses them (docs/benchmark.md, "Build times").
#include "rollkin/solve/sweep.hxx"
#include "rollkin/solve/tracer.hxx"

namespace rollkin {

ROLLKIN_SOLVE_DATA_INSTANCES(template, double)
ROLLKIN_POSITION_INSTANCES(template, double)
ROLLKIN_CONTINUATION_INSTANCES(template, double)
// Every member of the tracer and the contact limits, also those no entry point reaches yet
// (tests/test_instantiation.cpp lists the other class templates).
template class detail::Tracer<double>;
template class detail::ContactLimits<double>;

}  // namespace rollkin
