// The solver in mpfr50, compiled once (include/rollkin/solve/mpfr50_instances.hpp declares these `extern
// template` with the same lists; docs/benchmark.md, "Build times").
#include "rollkin/analysis/forces.hxx"
#include "rollkin/solve/sweep.hxx"
#include "rollkin/solve/tracer.hxx"
#include "rollkin/solve/mpfr50_instances.hpp"

namespace rollkin {

ROLLKIN_SOLVE_DATA_INSTANCES(template, mpfr50)
ROLLKIN_POSITION_INSTANCES(template, mpfr50)
ROLLKIN_CONTINUATION_INSTANCES(template, mpfr50)
// Every member of the tracer and the contact limits, also those no entry point reaches yet
// (tests/test_instantiation.cpp lists the other class templates).
template class detail::Tracer<mpfr50>;
template class detail::ContactLimits<mpfr50>;
ROLLKIN_ANALYSIS_INSTANCES(template, mpfr50)
ROLLKIN_FORCES_INSTANCES(template, mpfr50)

}  // namespace rollkin
