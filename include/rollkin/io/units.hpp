// Units of the input and output files, in one place: angle units (deg, rad) and length units (m, cm, mm,
// in, ft, the SVG units pt, pc, px, and "unitless" for numbers without a declared unit). Internally angles
// are radians; lengths are in the scene's unit (units.length of docs/scene_format.md), and contour files
// that declare a physical unit are converted with length_factor(file unit, scene unit).
#pragma once

#include "rollkin/scalar.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace rollkin::io {

enum class AngleUnit { Degree, Radian };

/// Pixel is the CSS pixel, 1/96 in; point 1/72 in; pica 12 points (SVG 1.1, section 7.10).
enum class LengthUnit { Unitless, Metre, Centimetre, Millimetre, Inch, Foot, Point, Pica, Pixel };

/// The spelling of a unit in files and messages: "deg", "rad"; "m", "cm", ..., "px"; "" for unitless.
inline const char* unit_label(AngleUnit u) { return u == AngleUnit::Degree ? "deg" : "rad"; }
inline const char* unit_label(LengthUnit u) {
  switch (u) {
    case LengthUnit::Unitless: return "";
    case LengthUnit::Metre: return "m";
    case LengthUnit::Centimetre: return "cm";
    case LengthUnit::Millimetre: return "mm";
    case LengthUnit::Inch: return "in";
    case LengthUnit::Foot: return "ft";
    case LengthUnit::Point: return "pt";
    case LengthUnit::Pica: return "pc";
    case LengthUnit::Pixel: return "px";
  }
  return "";
}

/// Radians per unit u (pi/180 for degrees), and the conversions of an angle value.
template <class S> inline S radians_per(AngleUnit u) { return u == AngleUnit::Degree ? deg_to_rad(S(1)) : S(1); }
template <class S> inline S to_radians(const S& value, AngleUnit u) { return u == AngleUnit::Degree ? deg_to_rad(value) : value; }
template <class S> inline S from_radians(const S& value, AngleUnit u) { return u == AngleUnit::Degree ? rad_to_deg(value) : value; }

/// Metres per unit u (exact decimal definitions: 1 in = 0.0254 m, 1 ft = 12 in); 1 for unitless numbers.
inline double metres_per(LengthUnit u) {
  switch (u) {
    case LengthUnit::Unitless: return 1;
    case LengthUnit::Metre: return 1;
    case LengthUnit::Centimetre: return 0.01;
    case LengthUnit::Millimetre: return 0.001;
    case LengthUnit::Inch: return 0.0254;
    case LengthUnit::Foot: return 12 * 0.0254;
    case LengthUnit::Point: return 0.0254 / 72;
    case LengthUnit::Pica: return 0.0254 / 6;
    case LengthUnit::Pixel: return 0.0254 / 96;
  }
  return 1;
}

/// The factor that converts a length in `from` units to `to` units (value_to = factor * value_from). When
/// either side is unitless the numbers are taken as they are: 1.
inline double length_factor(LengthUnit from, LengthUnit to) {
  if (from == LengthUnit::Unitless || to == LengthUnit::Unitless || from == to) return 1;
  return metres_per(from) / metres_per(to);
}

/// The length units a scene's units.length accepts.
inline const std::vector<LengthUnit>& scene_length_units() {
  static const std::vector<LengthUnit> units = {LengthUnit::Metre, LengthUnit::Centimetre, LengthUnit::Millimetre,
                                                LengthUnit::Inch, LengthUnit::Foot};
  return units;
}

/// "\"m\", \"cm\", ..." for messages.
inline std::string accepted_spellings(const std::vector<LengthUnit>& accepted) {
  std::string out;
  for (std::size_t i = 0; i < accepted.size(); ++i) out += std::string(i ? ", " : "") + "\"" + unit_label(accepted[i]) + "\"";
  return out;
}

/// The length unit spelled `text`, one of `accepted`. Throws std::invalid_argument naming the accepted
/// spellings otherwise.
inline LengthUnit parse_length_unit(const std::string& text, const std::vector<LengthUnit>& accepted = scene_length_units()) {
  for (LengthUnit u : accepted)
    if (text == unit_label(u)) return u;
  throw std::invalid_argument("unknown length unit \"" + text + "\"; expected one of " + accepted_spellings(accepted));
}

/// The angle unit spelled `text` ("deg" or "rad"). Throws std::invalid_argument naming both otherwise.
inline AngleUnit parse_angle_unit(const std::string& text) {
  if (text == "deg") return AngleUnit::Degree;
  if (text == "rad") return AngleUnit::Radian;
  throw std::invalid_argument("unknown angle unit \"" + text + "\"; expected \"deg\" or \"rad\"");
}

}  // namespace rollkin::io
