// The solver for double, compiled once: position, velocity, acceleration, assembly and the sweeps (one
// translation unit, so that the sweep inlines the Newton solve it calls).
// The headers declare these `extern template` with the same lists (ROLLKIN_*_INSTANCES), so every other
// translation unit that calls them for double only parses them (docs/benchmark.md, "Build times").
#include "rollkin/solve/continuation.hxx"

namespace rollkin {

ROLLKIN_SOLVE_DATA_INSTANCES(template, double)
ROLLKIN_POSITION_INSTANCES(template, double)
ROLLKIN_CONTINUATION_INSTANCES(template, double)

}  // namespace rollkin
