// SVG path data (the `d` attribute) as Bezier segments for BezierPath<double>.
//
// All commands of SVG 1.1 section 8.3 are read, absolute and relative: M L H V C S Q T A Z, with implicit
// repetition (extra coordinate pairs after M are line-tos), compact numbers ("-.5.5", "1e-3") and compact
// arc flags ("a1 1 0 01 1 1"). Lines become degree-1 segments, C/S cubic and Q/T quadratic ones, and
// elliptical arcs (A) are converted exactly to rational quadratics of at most 90 degrees each, by the
// endpoint-to-centre conversion of the SVG implementation notes (F.6.5, with the radii correction of
// F.6.6 when the radii are too small). Zero-length pieces are dropped; Z closes the subpath (adding the
// closing line when needed) and marks it closed.
//
// Coordinates: SVG's y axis points down. With flip_y (the default) every point becomes (x, -y) so that
// the drawing looks the same in rollkin's y-up world. Mirroring reverses the sense of rotation: a path
// drawn clockwise on screen is counter-clockwise after the flip (material on the left means the inside
// of a clockwise-on-screen outline). `scale` multiplies all coordinates (drawing units -> scene units).
//
// Transforms are not applied: a `transform` attribute on the chosen <path> is an error (flatten it in the
// editor first); transforms on enclosing groups are not detected.
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/profile/bezier.hpp"

#include <string>
#include <vector>

namespace rollkin {

struct SvgPathOptions {
  bool flip_y = true;  // (x, y) -> (x, -y): SVG's y-down drawing becomes rollkin's y-up world
  double scale = 1.0;  // applied after the flip
};

/// One subpath: the segments between a moveto and the next moveto (or the end).
struct SvgSubpath {
  std::vector<BezierSegment<double>> segments;
  bool closed = false;  // ended by Z
};

/// Parses path data. `file` and `path_id` only name the source in InputError messages, whose location is
/// the character offset in `d`.
std::vector<SvgSubpath> parse_svg_path_data(const std::string& d, const SvgPathOptions& options = {},
                                            const std::string& file = "", const std::string& path_id = "");

/// The `d` attribute of the <path> element with the given id in an SVG file.
std::string read_svg_path_data(const std::string& svg_file, const std::string& path_id);

/// read_svg_path_data + parse_svg_path_data.
std::vector<SvgSubpath> read_svg_path(const std::string& svg_file, const std::string& path_id,
                                      const SvgPathOptions& options = {});

}  // namespace rollkin
