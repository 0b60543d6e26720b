// The grid of input values of a sweep of one driver: from, from + step, ... up to `to`, given in the
// scene's units (degrees or radians for an angle input, scene length units for a length input) with the
// factor that converts them to solver units. Read from a scene's "sweep" (io/scene/reader.hpp) or the CLI's
// --from/--to/--step, and fed to sweep() (solve/continuation.hpp).
//
// The grid is the DECIMAL one the user wrote: with from -50 and step 0.001, value k is the double nearest
// to the decimal -50 + k/1000 (row 2 is -49.999, row 1030 the double nearest -48.971), not the binary sum
// from + k * step, which drifts off the decimal grid. from, to and step are read as decimals (their text
// when given, else the shortest decimal that reads back to the double: for a number written with at most
// 15 significant digits, as in a JSON scene, that is exactly the number written), scaled to integers of a
// common power of ten, F + k S computed exactly, and each value converted to double once, correctly rounded.
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
  // The decimal text of from, to and step when known (the command line's); empty: the shortest decimal of
  // the double is used (see the file comment).
  std::string from_text = {}, to_text = {}, step_text = {};
};

/// The requested input values, in INTERNAL units: from, from + step, ... up to `to` (the decimal grid, see
/// the file comment), inclusive of `to` when it falls on the grid within 1e-9 of a step. Throws std::invalid_argument for a zero step, a step of the
/// wrong sign or more than 9e15 values (how many a run may ask for: io/work_bound.hpp, max_steps).
std::vector<double> sweep_inputs(const Sweep& sweep);

/// The same values in the FILE's units: the double nearest to the decimal from + k step.
std::vector<double> sweep_values(const Sweep& sweep);

/// Checks a sweep's numbers (step non-zero, with the sign of to - from, finite, at most 9e15 values);
/// returns an empty string when fine, else what is wrong.
std::string check_sweep(const Sweep& sweep);

}  // namespace rollkin
