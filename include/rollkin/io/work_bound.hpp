// Bounded work (docs/reliability.md, "Bounded work"): the one rule the command line (--max-steps) and the
// Python module (max_steps=) apply before solving a sweep.
//
//   max_steps: a finite number of at least 1 (default 1e7); NaN, infinities and values below 1 are refused.
//   The work of a sweep is its estimated continuation sub-steps (estimate_substeps: the driver's travel over
//   the largest sub-step, plus one sub-step per requested value). So the number of values is bounded by the
//   same max_steps: a sweep of more values than max_steps is refused before its values are even made, and
//   raising max_steps raises both. There is no other cap on the number of values.
#pragma once

#include "rollkin/io/scene/reader.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin::io {

/// The default bound, in continuation sub-steps.
inline constexpr double kDefaultMaxSteps = 1e7;

/// A request above the bound. The message names `option` (how the caller raises the bound) and says what to do.
class WorkLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "" when `max_steps` is a bound (a finite number >= 1), else what is expected, e.g.
/// "expects a finite number of continuation sub-steps, at least 1, got nan".
std::string max_steps_problem(double max_steps);

/// The input values (internal units) of `sweep` (checked: check_sweep) when its work is within `max_steps`
/// (checked: max_steps_problem); WorkLimitError naming `option` otherwise. std::invalid_argument for a bad
/// max_steps or sweep (the message names `option` or says what is wrong with the sweep).
std::vector<double> bounded_inputs(const Scene& scene, const Sweep& sweep, double max_steps, const std::string& option);

}  // namespace rollkin::io
