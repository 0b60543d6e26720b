// The files `rollkin synthesize cam` and `rollkin synthesize gears` write, as text: one function per command, so
// that the CLI writes (all or nothing, io/output_set.hpp) exactly what the writers' contract test reads back
// (tests/test_io_writers_contract.cpp; docs/reliability.md, "Outputs, signals and messages (issue 37)").
//   cam:   PREFIX.txt (the profile, a closed point file in the cam's frame), PREFIX.dxf (one SPLINE on layer CAM),
//          PREFIX.svg (the cam, id "cam", and the follower at the law's start) and PREFIX.json (the scene);
//   gears: PREFIX.1.txt, PREFIX.2.txt (the pitch curves), PREFIX.dxf (SPLINEs on GEAR1 and GEAR2), PREFIX.json.
#pragma once

#include "rollkin/synthesis/cam.hpp"
#include "rollkin/synthesis/gears.hpp"

#include <string>

namespace rollkin::synthesis {

struct CamFiles {
  std::string profile, dxf, svg, scene;
};

/// The cam's files; `profile_file` is the name the scene gives its point file (relative to the scene's
/// directory).
CamFiles cam_files(const CamSpec& spec, const CamProfile& profile, const std::string& profile_file);

struct GearFiles {
  std::string gear1, gear2, dxf, scene;
};

/// The gear pair's files; `file1`, `file2` are the names the scene gives the pitch curves' point files.
GearFiles gear_files(const GearSpec& spec, const GearDesign& design, const std::string& file1, const std::string& file2);

}  // namespace rollkin::synthesis
