// Disk cam synthesis: the cam profile that gives a follower a prescribed motion law, as the envelope of the
// follower's contour under its motion relative to the turning cam (synthesis/envelope.hpp), the scene that
// analyses that profile, and the round trip that proves it (docs/synthesis.md, "Disk cams").
//
// Frames. The cam turns about the world origin by alpha = +theta ("rotation": "ccw") or -theta ("cw"), theta
// being the law's cam angle; its profile is given in its own frame (the world frame at theta = 0).
//  - Translating follower: slides along the world y axis at x = e (the offset). A roller's centre is at
//    (e, y0 + s(theta)), y0 = sqrt((Rb + r)^2 - e^2) (on the prime circle of radius Rb + r at theta = 0); a flat
//    face is the line y = Rb + s(theta) (perpendicular to the guide; e does not change the profile).
//  - Oscillating follower: turns about the pivot P by psi = a0 + s(theta) (s an angle); the roller's centre is
//    at P + L (cos psi, sin psi). Rb is the base circle: |P + L (cos a0, sin a0)| = Rb + r is required.
//  - Any contour ("contact": {"contour": {...}}): given in the follower's frame, (e, Rb) with the world's axes
//    for a translating follower, the pivot with x along the arm (psi) for an oscillating one.
// The envelope is computed in the cam's frame with the follower's contour in a world-aligned frame at the
// roller's centre (or at the face's point above the guide).
#pragma once

#include "rollkin/io/scene/reader.hpp"
#include "rollkin/io/units.hpp"
#include "rollkin/synthesis/envelope.hpp"
#include "rollkin/synthesis/motion_law.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rollkin::synthesis {

enum class FollowerMotion { Translating, Oscillating };
enum class FollowerContact { Roller, Flat, Contour };

/// A cam spec (docs/synthesis.md, "The cam spec"), in internal units: lengths in the spec's length unit,
/// angles in radians (an oscillating follower's law too).
struct CamSpec {
  std::string file;                         // the spec file, for messages
  std::vector<std::string> files_read;      // the spec and its law file, if any
  io::LengthUnit length = io::LengthUnit::Unitless;
  std::string length_label = "";            // units.length as written ("" when not given)
  io::AngleUnit angle_unit = io::AngleUnit::Degree;
  double base_radius = 0;
  int rotation = 1;                         // +1 ccw, -1 cw
  FollowerMotion motion = FollowerMotion::Translating;
  double offset = 0;                        // translating: e
  Vec2<double> pivot = Vec2<double>::Zero();  // oscillating
  double arm = 0, start_angle = 0;          // oscillating: L, a0 (radians)
  FollowerContact contact = FollowerContact::Roller;
  double roller_radius = 0;
  // "contact": {"contour": {...}}: any contour of the scene format, in the follower's frame (translating: origin
  // at (e, Rb) at the law's zero, axes along the world's; oscillating: origin at the pivot, x along the arm),
  // read through a one-link scene (`follower_shape`, its contour 0) so that it is exactly the scene's contour.
  std::shared_ptr<const io::Scene> follower_shape;
  nlohmann::ordered_json follower_contour;
  std::optional<MotionLaw<double>> law;
  double tolerance = 0;                     // absolute, in the law's unit (length or radians)
  double stroke = 0;                        // of the law
};

/// Reads and checks a spec file; every problem an InputError naming the file and the JSON path.
CamSpec read_cam_spec(const std::string& path);

/// The same for a document in memory (`file` names it in messages; a law file is read relative to `dir`).
CamSpec cam_spec_from_document(const nlohmann::ordered_json& document, const std::string& file, const std::string& dir);

/// The profile and where the follower starts.
struct CamProfile {
  Envelope<double> envelope;              // samples in increasing theta (clockwise round a ccw cam)
  std::vector<Vec2<double>> points;       // the profile counter-clockwise, starting at the theta = 0 contact
  double profile_tolerance = 0;           // the envelope's sampling tolerance (length)
  Vec2<double> follower_origin;           // world position of the follower frame's origin at theta = 0
  Vec2<double> contact;                   // world contact point at theta = 0
  double face_half_length = 0;            // flat face: half its drawn length (covers every contact)
};

/// The follower's pose in the cam's frame at cam angle theta (with derivatives), and its contour (world-aligned
/// frame at the roller's centre or on the face): the envelope problem of the spec.
EnvelopeProblem<double> cam_envelope_problem(const CamSpec& spec);

/// The profile, sampled so that the fitted spline is within the profile tolerance of the true envelope.
/// Throws io::InputError (at the spec's "contact" or "base_radius") when the follower cannot touch the cam.
CamProfile synthesise_cam(const CamSpec& spec);

/// The scene that analyses the cam (docs/synthesis.md, "The scene written"): revolute `cam` (theta), the
/// follower on the pair `follower` (s or phi, zero at the law's zero), the cam pair `contact` of the profile
/// (a closed `samples` contour read from `profile_file`, relative to the scene) and the follower's contour.
nlohmann::ordered_json cam_scene(const CamSpec& spec, const CamProfile& profile, const std::string& profile_file);

/// The round trip's figures (docs/synthesis.md, "The round trip").
struct CamRoundTrip {
  std::size_t poses = 0, solved = 0;
  double worst_deviation = 0;          // max |analysed - prescribed| follower motion (law's unit)
  double worst_deviation_at = 0;       // cam angle theta (radians) of that
  double max_pressure_angle = 0;       // radians
  double max_pressure_angle_at = 0;
  double min_radius_of_curvature = 0;  // of the profile at the contacts (length; negative where concave)
  double min_radius_at = 0;
  std::vector<std::string> problems;   // limits met, poses not solved
  struct Pose {
    double theta, analysed, prescribed;  // cam angle (law's), follower variable from the analysis and the law
    double pressure_angle;               // radians, NaN where the follower does not move
    double radius_of_curvature;          // of the profile at the contact
  };
  std::vector<Pose> solved_poses;
};

/// Reads the scene at `scene_file`, assembles it, sweeps theta over one turn at `poses` + 1 equally spaced cam
/// angles (997 by default: a prime, so that the poses fall between the profile's samples) and compares the
/// follower's variable with the law.
CamRoundTrip cam_round_trip(const CamSpec& spec, const std::string& scene_file, std::size_t poses = 997);

/// The same for a scene already built (e.g. with the profile's points inline).
CamRoundTrip cam_round_trip(const CamSpec& spec, const io::Scene& scene, std::size_t poses = 997);

}  // namespace rollkin::synthesis
