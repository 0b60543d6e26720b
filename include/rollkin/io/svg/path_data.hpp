// SVG path data (the `d` attribute) read as exact Bezier segments; io/svg/reader.hpp reads whole documents.
//
// Path data: all commands of SVG 1.1 section 8.3 are read, absolute and relative: M L H V C S Q T A Z, with
// implicit repetition (extra coordinate pairs after M are line-tos), compact numbers ("-.5.5", "1e-3") and
// compact arc flags ("a1 1 0 01 1 1"). Lines become degree-1 segments, C/S cubic and Q/T quadratic ones, and
// elliptical arcs (A) are converted exactly to rational quadratics of at most 90 degrees each, by the
// endpoint-to-centre conversion of the SVG implementation notes (F.6.5, with the radii correction of F.6.6
// when the radii are too small). Zero-length pieces are dropped; a piece whose control points all lie
// within round-off (sqrt(eps) of the subpath's size, the joint tolerance of BezierPath) of its start is
// dropped too and its neighbour snapped to its end, so that a path closed by Z after a last point equal to
// the first (to round-off) has no degenerate closing segment. Z closes the subpath and marks it closed.
// Commands are numbered as the user counts them: the k-th command letter of `d` is "command k (L)";
// coordinate sets repeated without a letter are "command k (L, set 2)".
#pragma once

#include "rollkin/io/input_error.hpp"
#include "rollkin/profile/bezier.hpp"

#include <string>
#include <vector>

namespace rollkin::io {

struct SvgPathOptions {
  bool flip_y = true;  // (x, y) -> (x, -y): SVG's y-down drawing becomes rollkin's y-up world
  double scale = 1.0;  // applied after the flip
};

/// One subpath: the segments between a moveto and the next moveto (or the end).
struct SvgSubpath {
  std::vector<BezierSegment<double>> segments;
  bool closed = false;               // ended by Z
  std::vector<std::string> origins;  // per segment, in the user's numbering: "command 7 (C)"
};

/// Parses path data. `file` and `path_id` only name the source in InputError messages, whose location is
/// the command (index and letter) and the character offset in `d`.
std::vector<SvgSubpath> parse_svg_path_data(const std::string& d, const SvgPathOptions& options = {},
                                            const std::string& file = "", const std::string& path_id = "");

}  // namespace rollkin::io
