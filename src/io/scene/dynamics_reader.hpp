// The scene's optional "dynamics" object (docs/forces.md), read after the mechanism is built (internal to
// the scene reader, src/io/scene/reader.cpp). Every problem is an InputError at its JSON path.
#pragma once

#include "../json/access.hpp"

#include "rollkin/io/scene/reader.hpp"

namespace rollkin::io {

/// Reads `dynamics` (the value of the scene's "dynamics" key) into scene.dynamics, scene.speed_unit.
void read_dynamics(const json& dynamics, const JsonAccess& js, Scene& scene);

}  // namespace rollkin::io
