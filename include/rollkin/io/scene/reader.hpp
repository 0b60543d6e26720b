// Scene files: a mechanism described in JSON (format in docs/scene_format.md), read into a finalized
// Mechanism<double> with its assembly guess, the variables held during assembly and an optional sweep.
//
//   rollkin::io::Scene scene = rollkin::io::load_scene("examples/paper_fourbar.json");
//   rollkin::SolveData<double> sd(scene.mechanism);
//   rollkin::VectorX<double> q = scene.guess;
//   auto assembly = rollkin::assemble(scene.mechanism, q, sd, scene.held);
//   auto result = rollkin::sweep(scene.mechanism, sd, q, assembly, scene.sweep->driver,
//                                rollkin::sweep_inputs(*scene.sweep));
//
// Every problem with the file is an InputError naming the scene file, the JSON path of the offending value
// (e.g. "pairs[2].contours[1]") and what was expected. Internally angles are radians; the file's angle unit
// ("deg" by default, or "rad") applies to every angle in the file, and Scene converts back and forth.
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/io/json/document.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/kinematics.hpp"
#include "rollkin/reference.hpp"
#include "rollkin/solve/sweep_grid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rollkin::io {

struct Scene {
  Mechanism<double> mechanism;       // finalized, drivers set from "inputs"
  VectorX<double> guess;             // assembly guess (internal units), one entry per variable
  std::vector<int> held;             // variables held at their given value during assembly
  std::optional<Sweep> sweep;        // the scene's "sweep", if any
  std::string file;                  // the scene file's path as given
  std::string length_unit = "m";     // label of lengths in outputs: units.length, "m" when not given
  LengthUnit length = LengthUnit::Unitless;  // units.length; Unitless when not given (numbers as they are)
  AngleUnit angle_unit = AngleUnit::Degree;  // units.angle: the unit of every angle in the file
  std::vector<std::string> inputs;   // full names of the drivers, in "inputs" order
  std::vector<std::string> files_read;  // every contour file read (point files, SVG), as opened
  std::vector<std::string> notes;       // one line per imported contour (SVG, DXF): its unit conversion (--verbose)

  /// Internal units per file unit of variable i: radians_per(angle_unit) for angles (pi/180 in a "deg"
  /// file), else 1.
  double unit_of(int variable) const;
  /// Short unit label of variable i in the file's units: "deg", "rad", the length unit, or "".
  std::string unit_label(int variable) const;
};

/// Reads and checks a scene file. Throws InputError (file, JSON path, message) for every problem.
Scene load_scene(const std::string& path);

/// Builds a scene from JSON text; `file` names the source in messages and anchors relative contour paths
/// (they are resolved against its directory).
Scene parse_scene(const std::string& text, const std::string& file);

/// The sweep a run asks for: the scene's "sweep" with `from`, `to`, `step` replaced where given (file units).
/// A scene without a "sweep" sweeps its first input and then needs all three: nullopt when one is missing
/// (the caller names its own options in the message). check_sweep() says whether the numbers are fine.
std::optional<Sweep> requested_sweep(const Scene& scene, std::optional<double> from, std::optional<double> to,
                                     std::optional<double> step);

/// The error for a scene whose mechanism cannot be assembled (SolveStatus::CannotAssemble, `detail` from the
/// assembly's report): a problem of the scene (sizes, frames, values), not a motion limit; named at "pairs".
InputError assembly_error(const Scene& scene, const std::string& detail);

/// The reference sweep (reference.hpp) of `sweep` on the scene's mechanism at `digits` decimal digits (30, 50,
/// 100). An input in degrees or in length units is taken as the decimal text of its file values ("-50" is
/// exactly -50 degrees, not the double nearest -50 pi/180); an input in radians as the doubles of the grid.
ReferenceSweep scene_reference(const Scene& scene, const Sweep& sweep, int digits);

/// Reads a scene file as a JSON document (io/json/document.hpp), without building the scene: the errors of
/// load_scene about the file itself and its JSON syntax. load_scene(p) is build_scene(read_scene_document(p), p).
nlohmann::ordered_json read_scene_document(const std::string& path);

/// Builds a scene from a parsed JSON document (e.g. one edited with io::set_at_path, or built by a program);
/// `file` names the source in messages; relative contour paths are resolved against `dir`, by default the
/// directory of `file`.
Scene build_scene(const nlohmann::ordered_json& document, const std::string& file,
                  const std::optional<std::string>& dir = std::nullopt);

}  // namespace rollkin::io
