// Output of the command-line tool: the CSV table, the chart of the pair variables and the drawing of the
// mechanism (the animation: animation.hpp), each built in memory as text from one solved sweep (the caller
// writes them atomically once everything succeeded).
#pragma once

#include "rollkin/analysis.hpp"
#include "rollkin/centrodes.hpp"
#include "rollkin/io/scene.hpp"
#include "rollkin/io/sweep_table.hpp"
#include "rollkin/solve/continuation.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace rollkin::cli {

// The table of a solved sweep lives in the library (rollkin/io/sweep_table.hpp, shared with the Python module);
// these names keep the CLI's writers as they were.
using OutputContext = io::SweepOutput;
using io::contact_pairs;
using io::input_column;
using io::input_column_unit;

/// The sweep's table (io::sweep_table: its columns) as CSV text.
std::string csv_text(const OutputContext& ctx, bool rates);

/// SVG charts against the input, stacked in one document: the non-input pair angles; the lengths and
/// unitless parameters (when there are any); with ctx.analysis also the pressure angles, the sliding
/// velocities, the slide-to-roll ratios, the contact curvatures and the links' angular accelerations. One
/// pass over the poses; each series is reduced to the chart's pixel columns as it is read (io/decimate.hpp),
/// so the document's size and the memory do not grow with the number of poses.
std::string plot_svg(const OutputContext& ctx);

/// A centrode as a point file (the format a `samples` contour reads): the instant centre of link b
/// relative to link a, in link a's frame (in_a) or link b's, one line "x y" per input value with a finite
/// centre, in sweep order; a comment line for each value without one (centre at infinity, not solved).
std::string centrode_text(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b,
                          bool in_a);

/// Both centrodes (in link a's frame on layer <a>, in link b's on layer <b>) as DXF SPLINE entities: each run
/// of consecutive finite centres is the cubic spline through its points (io/dxf_writer.hpp; closed when the
/// run is the whole sweep and ends where it starts), a run of two or three points the polyline through them.
/// Consecutive centres that coincide (a dwell) are one point of the spline.
std::string centrode_dxf(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b);

/// When every finite centre is one point in both links' frames (link b turns about one point of link a: a
/// revolute joins them), the sentence that says so, naming the point in both frames and the revolute; else "".
/// Such a centrode is written as its point files; it has no curve to draw as a DXF spline.
std::string centrode_single_point(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a,
                                  int b);

/// SVG drawing of the mechanism at up to four poses spread over the solved ones, one panel per pose at a
/// common scale (small multiples: no two poses overlap).
std::string draw_svg(const OutputContext& ctx);

/// The file name of a path, without its directories (titles of the outputs).
std::string base_name(const std::string& file);

/// An SVG document from its <svg> element on, without the XML declaration: to nest it in another document
/// (plot_svg's stacked charts, draw_svg's tiled panels).
std::string strip_header(const std::string& svg);

/// A link as drawn, in its own frame: --draw places it at each drawn pose, --animate draws it once and moves
/// it with one transform per frame.
struct LinkSketch {
  std::string color;                                   // black for the ground, else the palette's colour
  std::vector<std::vector<Eigen::Vector2d>> contours;  // the link's contours, 200 samples each
  std::vector<bool> closed;                            // per contour
  std::vector<Eigen::Vector2d> body;     // joints and contour origins, joined by a line (moving links, >= 2)
  std::vector<Eigen::Vector2d> joints;   // joints to another moving link whose link_a this is (circles)
  std::vector<Eigen::Vector2d> pivots;   // ground: the joints to moving links (squares, labelled)
  std::vector<std::string> pivot_names;  // ground: the names of those pairs
};
std::vector<LinkSketch> link_sketches(const Mechanism<double>& m);

/// The world contact point of every contact pair (on its link_a's contour) at poses lp with kin evaluated.
std::vector<Eigen::Vector2d> contact_points(const Mechanism<double>& m, const KinematicsData<double>& kin,
                                            const std::vector<SE2<double>>& lp);

/// Rank of the full (scaled) constraint Jacobian at the pose sd was last evaluated at.
struct AssemblyRank {
  int rank = 0;
  int redundant = 0;  // equations - rank
  int mobility = 0;   // variables - rank
};
AssemblyRank full_rank(const Mechanism<double>& m, const SolveData<double>& sd);

}  // namespace rollkin::cli
