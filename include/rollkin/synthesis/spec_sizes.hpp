// The sizes a synthesis spec may give (docs/synthesis.md; docs/reliability.md, "Outputs, signals and messages
// (issue 37)"): every length and lift of a cam or gear spec has a magnitude of 0 or between 1e-100 and 1e100 in the
// spec's units. The synthesis squares lengths and sums them (envelopes, pitch radii): at 1e300 the squares
// overflowed and a base radius of 1e300 was reported as an undercut ("a larger base circle avoids it"), and a lift
// of 1e300 wrote a point file of coinciding points; below 1e-100 they underflow alike.
#pragma once

#include "rollkin/io/format.hpp"

#include <cmath>
#include <string>

namespace rollkin::synthesis {

/// "" for a size the synthesis computes with, else what is wrong and what is expected.
inline std::string spec_size_problem(double x) {
  const double m = std::abs(x);
  if (m == 0 || (m >= 1e-100 && m <= 1e100)) return "";
  return "of " + io::format_number(x) + " is beyond the sizes the synthesis computes with (their squares " +
         (m > 1 ? "overflow" : "underflow") + " a double); expected a magnitude between 1e-100 and 1e100 (or 0), e.g. in another unit";
}

}  // namespace rollkin::synthesis
