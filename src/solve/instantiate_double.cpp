// The solver for double, compiled once: position, velocity, acceleration, assembly and the sweeps (one
// translation unit, so that the sweep inlines the Newton solve it calls).
// The headers declare these `extern template` with the same lists (ROLLKIN_*_INSTANCES), so every other
// translation unit that calls them for double only parses them (docs/benchmark.md, "Build times").
#include "rollkin/solve/position.hpp"
#include "rollkin/solve/continuation.hpp"

namespace rollkin {

ROLLKIN_POSITION_INSTANCES(template, double)
ROLLKIN_CONTINUATION_INSTANCES(template, double)

}  // namespace rollkin
