// The input grid of a sweep (see include/rollkin/solve/sweep_grid.hpp).
#include "rollkin/solve/sweep_grid.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rollkin {

namespace {

std::string number_text(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

std::string check_sweep(const Sweep& s) {
  if (!std::isfinite(s.from) || !std::isfinite(s.to) || !std::isfinite(s.step)) return "from, to and step must be finite numbers";
  if (s.step == 0) return "step must not be zero; expected a step with the sign of to - from";
  const double span = s.to - s.from;
  const std::string from = number_text(s.from), to = number_text(s.to);
  if (span != 0 && (span > 0) != (s.step > 0))
    return "step " + number_text(s.step) + " has the wrong sign for a sweep from " + from + " to " + to +
           "; expected a step with the sign of to - from";
  if (span / s.step > 1e7)
    return "the sweep from " + from + " to " + to + " by " + number_text(s.step) +
           " has more than 10 million values; expected a larger step";
  return "";
}

std::vector<double> sweep_values(const Sweep& s) {
  const std::string bad = check_sweep(s);
  if (!bad.empty()) throw std::invalid_argument("sweep: " + bad);
  const double n = std::floor((s.to - s.from) / s.step + 1e-9);
  std::vector<double> out;
  for (long k = 0; k <= static_cast<long>(n); ++k) out.push_back(s.from + s.step * static_cast<double>(k));
  return out;
}

std::vector<double> sweep_inputs(const Sweep& s) {
  std::vector<double> out = sweep_values(s);
  for (double& v : out) v *= s.unit;
  return out;
}

}  // namespace rollkin
