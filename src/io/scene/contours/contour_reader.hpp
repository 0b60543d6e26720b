// Contour readers of the scene format (docs/scene_format.md, "contours"): one function per contour "type",
// listed in registry.cpp. A reader checks the contour object's keys, builds the profile and says on which
// side the material lies; the scene reader adds the common part (name, "at") and hands it to the builder.
//
// Adding a contour kind: one new file under src/io/contours/ defining its reader, and one line in
// registry.cpp (its declaration and table entry).
#pragma once

#include "../../json/access.hpp"

#include "rollkin/profile/profile.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rollkin::io {

/// What every contour reader may use: the JSON accessors, the scene's directory and angle unit, and the
/// checks shared by several kinds.
class ContourContext {
 public:
  ContourContext(const JsonAccess& access, std::filesystem::path scene_dir, AngleUnit angle_unit, LengthUnit length_unit,
                 std::vector<std::string>& files_read, std::vector<std::string>& notes)
      : js(access),
        dir_(std::move(scene_dir)),
        angle_unit_(angle_unit),
        length_unit_(length_unit),
        files_read_(files_read),
        notes_(notes) {}

  const JsonAccess& js;

  /// An angle of the file in radians.
  double angle(double file_value) const { return to_radians(file_value, angle_unit_); }
  /// The scene's length unit (units.length; Unitless when not given). A contour file that declares its
  /// unit converts its coordinates by length_factor(file unit, length_unit()) (io/units.hpp).
  LengthUnit length_unit() const { return length_unit_; }

  /// A line for --verbose (Scene::notes): how an imported contour was converted.
  void note(const std::string& line) const { notes_.push_back(line); }
  /// "scale" of an imported contour: a positive factor applied after the unit conversion, 1 when absent.
  double scale(const json& c, const std::string& path) const;
  /// Converts a file's coordinates to scene units: length_factor(file unit, units.length), 1 when either
  /// is unitless; file_metres_per_unit is 0 (or empty) for a file without a declared unit.
  double unit_factor(double file_metres_per_unit) const;

  /// Checks that the contour object has only the keys common to all contours and `extra`.
  void keys(const json& c, const std::string& path, std::vector<std::string> extra) const;
  /// A contour file path, relative to the scene file's directory; recorded in Scene::files_read.
  std::string contour_file(const json& v, const std::string& path) const;
  /// "material" -> reversed. natural_inside: whether the profile's natural direction has "inside" on the
  /// left (nullopt: "inside"/"outside" are not defined for this contour). def: the default side.
  bool material(const json& c, const std::string& path, std::optional<bool> natural_inside, const std::string& def) const;
  /// "arc_length": {"method", "order", "panels"} of an analytic curve.
  ArcLengthMethod arc_length_method(const json& v, const std::string& path) const;
  /// "parameter" of a sampled or Bezier/SVG contour: "native" (default: chord length, segment parameter)
  /// or "arc_length" (the profile re-parameterised by arc length, ArcLengthProfile), applied to `shape`.
  ProfileShape<double> parameterised(ProfileShape<double> shape, const json& c, const std::string& path) const;

 private:
  std::filesystem::path dir_;
  AngleUnit angle_unit_;
  LengthUnit length_unit_;
  std::vector<std::string>& files_read_;
  std::vector<std::string>& notes_;
};

/// A contour's profile and material side (reversed: the material is on the right of the profile's
/// natural direction), and descriptions of its corners in the user's terms (Contour's corner_labels).
struct ContourShape {
  ProfileShape<double> shape;
  bool reversed;
  std::vector<std::string> corner_labels = {};
};

/// Describes the joint at the start of segment `piece` of an imported path in the user's terms (the DXF
/// entities, the SVG commands, the NURBS knot that meet there).
using JointDescriber = std::function<std::string(std::size_t piece)>;

/// Labels of the path's corners in BezierPath::corners() order, "<describe(piece)>, turning T deg", and
/// --verbose notes for `what`: each corner (a contact stops there) and each tangent joint whose curvature
/// jumps (a contact rolls through it).
std::vector<std::string> describe_joints(const BezierPath<double>& path, const JointDescriber& describe,
                                         const std::string& what, const ContourContext& ctx);

/// Reads the contour object c at JSON path `path`. Throws InputError.
using ContourReader = ContourShape (*)(const json& c, const std::string& path, const ContourContext& ctx);

struct ContourKind {
  const char* type;
  ContourReader read;
};

/// The reader of a "type", or nullptr when the type is unknown.
ContourReader find_contour_reader(const std::string& type);
/// The known types, in the order of the registry (for the "unknown contour type" message).
std::vector<std::string> contour_types();

/// Joins consecutive line pieces (polynomial, degree 1) that continue one straight line, each joint within
/// round-off of the line through the run's ends and ahead of the one before, into one line piece from the
/// run's first point to its last (docs/scene_format.md, "Straight runs"). A straight run drawn with many
/// vertices of different spacing is one line: its joints, where the path parameter's speed would jump, are
/// gone. The start of a closed path stays a joint. Returns, for each piece of the result, the index of the
/// input piece it starts with (its joint in the file's terms).
std::vector<std::size_t> join_straight_runs(std::vector<BezierSegment<double>>& segments);

/// The control points of end-to-end segments, each joint once (for the orientation by signed_area).
std::vector<Vec2<double>> control_polygon(const std::vector<BezierSegment<double>>& segments);

/// Signed area of the polygon through pts (shoelace), > 0 counter-clockwise.
double signed_area(const std::vector<Vec2<double>>& pts);

}  // namespace rollkin::io
