// The input speed of a scene's "dynamics" (docs/forces.md) and of `rollkin solve --speed`: a number with a
// unit, "rpm", "rad/s", "deg/s" for an angle input, "<length unit>/s" (e.g. "mm/s") for a length input.
#pragma once

#include "rollkin/io/units.hpp"

#include <string>

namespace rollkin::io {

/// A speed unit: its label as written and how many internal units per second one of it is (radians per
/// second for an angle input, scene length units per second for a length input).
struct SpeedUnit {
  std::string label;
  double per_second = 1;
  bool angular = true;
};

/// The speed unit `text` for an input of angle kind (`angular`) or length kind in a scene of length unit
/// `scene_length`. Throws std::invalid_argument naming the units accepted.
SpeedUnit parse_speed_unit(const std::string& text, bool angular, LengthUnit scene_length);

/// "500rpm", "52.3 rad/s", "20mm/s": the number and its unit (parse_speed_unit); a number without a unit
/// takes `default_unit`. Throws std::invalid_argument.
double parse_speed(const std::string& text, bool angular, LengthUnit scene_length, const SpeedUnit& default_unit,
                   SpeedUnit& unit);

}  // namespace rollkin::io
