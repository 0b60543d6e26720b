// The files of `rollkin synthesize` (docs/synthesis.md) and the pictures Python's synthesize_cam and
// synthesize_gears return: point files (io/point_file.hpp), DXF splines (io/dxf/writer.hpp), the scene that
// analyses the result and the pictures, drawn on the canvas of `rollkin solve --draw` (output/svg_drawing.hpp).
// The command builds its files by one call here, so the CLI and Python write the same bytes.
//   cam:      PREFIX.txt, PREFIX.dxf, PREFIX.svg, PREFIX.json          (cam_files)
//   gears:    PREFIX.1.txt, PREFIX.2.txt, PREFIX.dxf, PREFIX.svg, PREFIX.json   (gear_files)
//   envelope: PREFIX.txt (io::point_file_text), PREFIX.dxf (envelope_dxf)
#pragma once

#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <string>
#include <vector>

namespace rollkin::output {

/// The files of `rollkin synthesize cam`:
///  - profile: the profile as a point file (closed, counter-clockwise, the cam's frame), its comment naming the
///    spec and the length unit;
///  - dxf: the profile as one closed SPLINE on layer CAM, the spline a `samples` contour fits through it;
///  - svg: cam_svg();
///  - scene: the scene that analyses the cam (synthesis::cam_scene), reading the profile from `profile_file` (a
///    path relative to the scene's directory).
struct CamFiles {
  std::string profile, dxf, svg, scene;
};
CamFiles cam_files(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile, const std::string& profile_file);

/// The cam (filled profile, id "cam", its revolute marked) and the follower at the law's start (id "roller",
/// "face" or "follower"; an oscillating follower's arm, id "arm", and pivot), y up, the contact point red.
std::string cam_svg(const synthesis::CamSpec& spec, const synthesis::CamProfile& profile);

/// The files of `rollkin synthesize gears`:
///  - gear1, gear2: the pitch curves as point files (closed, counter-clockwise, each gear's frame with its pivot
///    at the origin);
///  - dxf: both as closed SPLINEs on layers GEAR1 and GEAR2, each in its gear's frame;
///  - svg: gear_svg();
///  - scene: the scene rolling them (synthesis::gear_scene), reading them from `file1` and `file2`.
struct GearFiles {
  std::string gear1, gear2, dxf, svg, scene;
};
GearFiles gear_files(const synthesis::GearSpec& spec, const synthesis::GearDesign& design, const std::string& file1,
                     const std::string& file2);

/// Both pitch curves (ids "gear1", "gear2") at the scene's assembly pose: gear 1 about the origin at phi1 = 0,
/// gear 2 about (E, 0) turned by -f(0); the pivots and the contact point marked, y up.
std::string gear_svg(const synthesis::GearSpec& spec, const synthesis::GearDesign& design);

/// PREFIX.dxf of `rollkin synthesize envelope`: the spline through the envelope's points (closed when the
/// envelope is) on layer ENVELOPE.
std::string envelope_dxf(const std::vector<Vec2<double>>& points, bool closed, const std::string& length_unit);

}  // namespace rollkin::output
