// The centrode files (`rollkin centrodes`, Python Scene.centrodes): point files and DXF splines of the
// instant centre of one link relative to another over a solved sweep (rollkin/analysis/centrodes.hpp).
#pragma once

#include "rollkin/analysis/centrodes.hpp"
#include "rollkin/output/drawing.hpp"

#include <string>
#include <vector>

namespace rollkin::output {

/// A centrode as a point file (the format a `samples` contour reads): the instant centre of link b
/// relative to link a, in link a's frame (in_a) or link b's, one line "x y" per input value with a finite
/// centre, in sweep order; a comment line for each value without one (centre at infinity, not solved).
std::string centrode_text(const SweepOutput& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b,
                          bool in_a);

/// Both centrodes (in link a's frame on layer <a>, in link b's on layer <b>) as DXF SPLINE entities: each run
/// of consecutive finite centres is the cubic spline through its points (io/dxf/writer.hpp; closed when the
/// run is the whole sweep and ends where it starts), a run of two or three points the polyline through them.
/// Consecutive centres that coincide (a dwell) are one point of the spline.
std::string centrode_dxf(const SweepOutput& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b);

/// When every finite centre is one point in both links' frames (link b turns about one point of link a: a
/// revolute joins them), the sentence that says so, naming the point in both frames and the revolute; else "".
/// Such a centrode is written as its point files; it has no curve to draw as a DXF spline.
std::string centrode_single_point(const SweepOutput& ctx, const std::vector<InstantCentre<double>>& centres, int a,
                                  int b);

}  // namespace rollkin::output
