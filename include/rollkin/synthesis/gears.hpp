// Non-circular gear pairs from a transmission function phi2 = f(phi1) and a centre distance E: the pitch curves
// of include/rollkin/synthesis/pitch_curves.hpp sampled to a tolerance, their convexity, the scene that rolls them and the
// round trip (docs/synthesis.md, "Non-circular gears").
//
// Transmission functions:
//   elliptical (twin ellipses of eccentricity e turning about a focus each; k = (1 + e) / (1 - e)):
//     f(p) = p + 2 atan((k - 1) sin(p/2) cos(p/2) / (cos^2(p/2) + k sin^2(p/2))),
//     f'(p) = k / (cos^2(p/2) + k^2 sin^2(p/2))       (tan(f/2) = k tan(p/2); f'(0) = k)
//   sinusoidal: f(p) = p + k sin p, |k| < 1;
//   table: points (phi1, phi2) over one turn of phi1; g = f - p is fitted by the periodic C2 spline of a
//   motion law table (motion_law.hpp), f' = 1 + g'. The pair closes when f(p + 2 pi) = f(p) + 2 pi: the
//   table's last phi2 must be its first + 2 pi (a last row at phi1 + 2 pi), else it is reported.
#pragma once

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/synthesis/pitch_curves.hpp"
#include "rollkin/synthesis/motion_law.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rollkin::synthesis {

struct GearSpec {
  std::string file;
  std::vector<std::string> files_read;
  io::LengthUnit length = io::LengthUnit::Unitless;
  std::string length_label;
  io::AngleUnit angle_unit = io::AngleUnit::Degree;
  double centre_distance = 0;
  std::string kind;             // "elliptical", "sinusoidal" or "table"
  double parameter = 0;         // eccentricity or k
  std::optional<MotionLaw<double>> table_excess;  // g = f - p of a table
  double closure_error = 0;     // table: f(p + 2 pi) - f(p) - 2 pi (radians)
  double tolerance = 2e-9 * 3.141592653589793;  // of the analysed gear 2 angle (radians): 1e-9 of a turn by default
};

/// Reads and checks a gear spec: InputError with the JSON path for every problem.
GearSpec read_gear_spec(const std::string& path);

/// The same for a document in memory (`file` names it in messages; a table file is read relative to `dir`).
GearSpec gear_spec_from_document(const nlohmann::ordered_json& document, const std::string& file, const std::string& dir);

/// f and f' of the spec (TransmissionFunction of synthesis.hpp).
TransmissionFunction<double> transmission(const GearSpec& spec);

struct GearDesign {
  GearPair<double> pair;            // the pitch curves (counter-clockwise, body frames)
  double profile_tolerance = 0;     // each spline within this of the true pitch curve at every mid-angle
  double min_curvature1 = 0, min_curvature2 = 0;  // of the fitted splines (negative: a concave part)
  double min_curvature1_at = 0, min_curvature2_at = 0;  // body polar angle (radians)
};

/// The pitch curves, sampled at 2^k equal body angles until the fitted splines are within the profile
/// tolerance (a sixteenth of spec.tolerance times the centre distance) at every mid-angle.
GearDesign synthesise_gears(const GearSpec& spec);

/// The scene rolling the two pitch curves: revolutes `gear1` (variable phi, at the origin) and `gear2` (phi, at
/// (E, 0)), the rolling pair `mesh` of `gear1.pitch` and `gear2.pitch` (samples read from the two files).
nlohmann::ordered_json gear_scene(const GearSpec& spec, const GearDesign& design, const std::string& file1,
                                  const std::string& file2);

struct GearRoundTrip {
  std::size_t poses = 0, solved = 0;
  double worst_deviation = 0, worst_deviation_at = 0;  // |gear2.phi - (-f(phi1))| (radians), phi1 there
  std::vector<std::string> problems;
};

/// Reads the scene back, sweeps gear1.phi over one turn at 997 + 1 angles and compares gear2.phi with -f.
GearRoundTrip gear_round_trip(const GearSpec& spec, const std::string& scene_file);

/// The same for a scene already built.
GearRoundTrip gear_round_trip(const GearSpec& spec, const io::Scene& scene);

}  // namespace rollkin::synthesis
