// The solver in rollkin::mpfr50 (50 digits), compiled once in src/solve/instantiate_mpfr50.cpp, as the solver
// for double is (the ROLLKIN_*_INSTANCES lists of solve/position.hpp, continuation.hpp and analysis/motion.hpp;
// docs/benchmark.md, "Build times"). A translation unit that solves in mpfr50 includes this header, and then
// only parses the solver instead of compiling it again.
#pragma once

#include "rollkin/analysis/motion.hpp"
#include "rollkin/scalar_mpfr.hpp"
#include "rollkin/solve/continuation.hpp"

namespace rollkin {

ROLLKIN_SOLVE_DATA_INSTANCES(extern template, mpfr50)
ROLLKIN_POSITION_INSTANCES(extern template, mpfr50)
ROLLKIN_CONTINUATION_INSTANCES(extern template, mpfr50)
ROLLKIN_ANALYSIS_INSTANCES(extern template, mpfr50)

}  // namespace rollkin
