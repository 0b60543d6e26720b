// Bounded work (see include/rollkin/io/work_bound.hpp).
#include "rollkin/io/work_bound.hpp"
#include "rollkin/io/format.hpp"

#include "rollkin/solve/continuation.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace rollkin::io {
namespace {

/// The number of values of a checked sweep, counted without making them (as sweep_values counts them).
double value_count(const Sweep& s) { return std::floor((s.to - s.from) / s.step + 1e-9) + 1; }

}  // namespace

std::string max_steps_problem(double max_steps) {
  if (std::isfinite(max_steps) && max_steps >= 1) return "";
  return "expects a finite number of continuation sub-steps, at least 1, got " + format_number(max_steps);
}

std::vector<double> bounded_inputs(const Scene& scene, const Sweep& sweep, double max_steps, const std::string& option) {
  const std::string bad_bound = max_steps_problem(max_steps);
  if (!bad_bound.empty()) throw std::invalid_argument(option + ": " + bad_bound);
  const std::string bad_sweep = check_sweep(sweep);
  if (!bad_sweep.empty()) throw std::invalid_argument(bad_sweep);
  // Formatted only for a message (a sweep is bounded for every run of a batch).
  const auto range = [&] { return "the sweep of " + sweep.input + " from " + format_number(sweep.from) + " to " + format_number(sweep.to); };
  const double values = value_count(sweep);
  if (values > max_steps) {
    std::ostringstream os;
    os << range() << " by " << format_number(sweep.step) << " has " << std::scientific << std::setprecision(2) << values
       << " values, above the limit " << max_steps << " (" << option << "): each value is at least one continuation"
       << " sub-step; ask for a smaller range or a larger step (fewer values), or raise the limit with " << option;
    throw WorkLimitError(os.str());
  }
  std::vector<double> inputs = sweep_inputs(sweep);
  const double estimate = estimate_substeps(scene.mechanism, scene.guess, sweep.driver, inputs);
  if (estimate > max_steps) {
    std::ostringstream os;
    os << range() << " needs an estimated " << std::scientific << std::setprecision(2) << estimate
       << " continuation sub-steps, above the limit " << max_steps << " (" << option << "); ask for a smaller range"
       << " (from/to), a larger step (fewer values), or raise the limit with " << option;
    throw WorkLimitError(os.str());
  }
  return inputs;
}

}  // namespace rollkin::io
