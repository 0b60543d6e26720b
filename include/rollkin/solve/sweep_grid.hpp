// The grid of input values of a sweep of one driver: from, from + step, ... up to `to`, given in the
// scene's units (degrees or radians for an angle input, scene length units for a length input) with the
// factor that converts them to solver units. Read from a scene's "sweep" (io/scene.hpp) or the CLI's
// --from/--to/--step, and fed to sweep() (solve/continuation.hpp).
#pragma once

#include <string>
#include <vector>

namespace rollkin {

/// A sweep of one driver: from, to and step in the FILE's units; `unit` converts them to internal units
/// (pi/180 for degrees).
struct Sweep {
  std::string input;   // full variable name, e.g. "O_A.theta2"
  int driver = 0;      // index into mechanism.drivers
  int variable = 0;    // index into q
  double from = 0, to = 0, step = 1;
  double unit = 1;     // internal value = file value * unit
};

/// The requested input values, in INTERNAL units: from, from + step, ... up to `to`, inclusive of `to` when
/// it falls on the grid within 1e-9 of a step. Throws std::invalid_argument for a zero step, a step of the
/// wrong sign or more than 10 million values.
std::vector<double> sweep_inputs(const Sweep& sweep);

/// The same values in the FILE's units (from + k step, exactly as the grid defines them).
std::vector<double> sweep_values(const Sweep& sweep);

/// Checks a sweep's numbers (step non-zero, with the sign of to - from, finite, not too many values);
/// returns an empty string when fine, else what is wrong.
std::string check_sweep(const Sweep& sweep);

}  // namespace rollkin
