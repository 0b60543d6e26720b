// Point samples of a contour from a text file, one point per line:
//
//   # comment (anything after '#' is ignored), blank lines are skipped
//   x y            <- an optional non-numeric header line, allowed as the first non-comment line only
//   0.0  1.25      separators: spaces, tabs, ',' or ';' (any mix, "1.5,2" and "1.5; 2" too)
//   1e-3, -2.5
//
// Every other line must hold exactly two finite numbers. Each point is multiplied by `scale` (the file's
// unit in scene units, e.g. 0.001 for a file in mm read into a scene in m). Errors are InputError naming the
// file, the 1-based line and what was expected.
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/scalar.hpp"

#include <string>
#include <vector>

namespace rollkin {

/// Reads the file at `path`; throws InputError if it cannot be opened, is malformed, or holds fewer than
/// `min_points` points.
std::vector<Vec2<double>> read_point_file(const std::string& path, std::size_t min_points, double scale = 1.0);

/// The same for text already in memory; `source` names it in messages.
std::vector<Vec2<double>> parse_point_text(const std::string& text, const std::string& source,
                                           std::size_t min_points, double scale = 1.0);

}  // namespace rollkin
