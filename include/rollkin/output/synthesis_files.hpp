// The files of `rollkin synthesize` (docs/synthesis.md) and the pictures Python's synthesize_cam and
// synthesize_gears return: point files (io/point_file.hpp), DXF splines (io/dxf/writer.hpp), the scene that
// analyses the result and the pictures, drawn on the canvas of `rollkin solve --draw` (output/svg_drawing.hpp).
// The command builds each file by one call here, so the CLI and Python write the same bytes.
#pragma once

#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <string>
#include <vector>

namespace rollkin::output {

// ---- disk cams (`rollkin synthesize cam`) -----------------------------------------------------------------

/// PREFIX.txt: the profile as a point file (closed, counter-clockwise, the cam's frame), its comment naming
/// the spec and the length unit.
std::string cam_profile_text(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile);

/// PREFIX.dxf: the profile as one closed SPLINE on layer CAM, the spline a `samples` contour fits through it.
std::string cam_dxf(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile);

/// PREFIX.svg: the cam (filled profile, its centre marked) and the follower (roller, flat face or contour, the
/// arm of an oscillating follower to its pivot) at the law's start, y up.
std::string cam_svg(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile);

/// PREFIX.json: the scene that analyses the cam (synthesis::cam_scene), reading the profile from
/// `profile_file` (a path relative to the scene's directory).
std::string cam_scene_text(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile,
                           const std::string& profile_file);

// ---- non-circular gears (`rollkin synthesize gears`) --------------------------------------------------------

/// PREFIX.1.txt (gear 1) and PREFIX.2.txt (gear 2): the pitch curve of `gear` as a point file (closed,
/// counter-clockwise, the gear's frame with its pivot at the origin).
std::string gear_pitch_text(const synthesis::GearSpec& spec, const synthesis::GearDesign& design, int gear);

/// PREFIX.dxf: both pitch curves as closed SPLINEs on layers GEAR1 and GEAR2, each in its gear's frame.
std::string gear_dxf(const synthesis::GearSpec& spec, const synthesis::GearDesign& design);

/// PREFIX.svg: both pitch curves at the scene's assembly pose (gear 1 about the origin at phi1 = 0, gear 2
/// about (E, 0) turned by -f(0)), the pivots and the contact point marked, y up.
std::string gear_svg(const synthesis::GearSpec& spec, const synthesis::GearDesign& design);

/// PREFIX.json: the scene rolling the two pitch curves (synthesis::gear_scene), reading them from `file1`
/// and `file2` (paths relative to the scene's directory).
std::string gear_scene_text(const synthesis::GearSpec& spec, const synthesis::GearDesign& design,
                            const std::string& file1, const std::string& file2);

// ---- envelopes (`rollkin synthesize envelope`) --------------------------------------------------------------

/// PREFIX.txt: the envelope's points as a point file after the comment `what` (which contour, which frame,
/// from which scene, closed or open).
std::string envelope_text(const std::string& what, const std::vector<Vec2<double>>& points);

/// PREFIX.dxf: the spline through the envelope's points (closed when the envelope is) on layer ENVELOPE.
std::string envelope_dxf(const std::vector<Vec2<double>>& points, bool closed, const std::string& length_unit);

}  // namespace rollkin::output
