// What follows a sweep for double, compiled once: the contact analysis, the design check, the centrodes and
// the interference check.
// The headers declare these `extern template` with the same lists (ROLLKIN_*_INSTANCES), so every other
// translation unit that calls them for double only parses them (docs/benchmark.md, "Build times").
#include "rollkin/analysis/motion.hpp"
#include "rollkin/analysis/design_check.hpp"
#include "rollkin/analysis/centrodes.hpp"
#include "rollkin/analysis/interference.hpp"

namespace rollkin {

ROLLKIN_ANALYSIS_INSTANCES(template, double)
ROLLKIN_DESIGN_CHECK_INSTANCES(template, double)
ROLLKIN_CENTRODES_INSTANCES(template, double)
ROLLKIN_INTERFERENCE_INSTANCES(template, double)

}  // namespace rollkin
