// The solver in mpfr50, compiled once (include/rollkin/solve/mpfr50_instances.hpp declares these `extern
// template` with the same lists; docs/benchmark.md, "Build times").
#include "rollkin/solve/continuation.hxx"
#include "rollkin/solve/mpfr50_instances.hpp"

namespace rollkin {

ROLLKIN_SOLVE_DATA_INSTANCES(template, mpfr50)
ROLLKIN_POSITION_INSTANCES(template, mpfr50)
ROLLKIN_CONTINUATION_INSTANCES(template, mpfr50)
ROLLKIN_ANALYSIS_INSTANCES(template, mpfr50)

}  // namespace rollkin
