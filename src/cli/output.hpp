// Output of the command-line tool: the CSV table, the chart of the pair variables and the drawing of the
// mechanism (the animation: animation.hpp), each built in memory as text from one solved sweep (the caller
// writes them atomically once everything succeeded).
#pragma once

#include "rollkin/analysis.hpp"
#include "rollkin/centrodes.hpp"
#include "rollkin/io/scene.hpp"
#include "rollkin/solve/continuation.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace rollkin::cli {

/// The contact analysis (docs/analysis.md) of every pose of a sweep, computed once for all the writers;
/// empty where the pose was not solved.
using SweepAnalysis = std::vector<std::optional<PoseAnalysis<double>>>;
SweepAnalysis analyse_sweep(const Mechanism<double>& m, const SweepResult<double>& result);

struct OutputContext {
  const io::Scene& scene;
  const io::Sweep& sweep;
  const SweepResult<double>& result;
  const std::vector<double>& inputs;  // requested input values in the file's units (one per pose)
  const SweepAnalysis* analysis = nullptr;  // set with --analysis: its columns and charts are added
};

/// Columns: the input, every other pair variable, (rates) d(var)/d(input) per unknown, every link's
/// <link>.x, <link>.y, <link>.angle, (ctx.analysis) per cam or rolling pair P the columns P.pressure_angle,
/// P.sliding, P.slide_to_roll, P.kappa1, P.kappa2, P.relative_curvature and per moving link <link>.accel
/// (docs/analysis.md), residual, status. Angles in degrees, lengths in scene units, rates per input unit.
std::string csv_text(const OutputContext& ctx, bool rates);

/// SVG charts against the input, stacked in one document: the non-input pair angles; the lengths and
/// unitless parameters (when there are any); with ctx.analysis also the pressure angles, the sliding
/// velocities, the slide-to-roll ratios, the contact curvatures and the links' angular accelerations.
std::string plot_svg(const OutputContext& ctx);

/// A centrode as a point file (the format a `samples` contour reads): the instant centre of link b
/// relative to link a, in link a's frame (in_a) or link b's, one line "x y" per input value with a finite
/// centre, in sweep order; a comment line for each value without one (centre at infinity, not solved).
std::string centrode_text(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b,
                          bool in_a);

/// Both centrodes (in link a's frame on layer <a>, in link b's on layer <b>) as DXF SPLINE entities: each run
/// of consecutive finite centres is the cubic spline through its points (io/dxf_writer.hpp; closed when the
/// run is the whole sweep and ends where it starts), a run of two or three points the polyline through them.
std::string centrode_dxf(const OutputContext& ctx, const std::vector<InstantCentre<double>>& centres, int a, int b);

/// SVG drawing of the mechanism at up to four poses spread over the solved ones, one panel per pose at a
/// common scale (small multiples: no two poses overlap).
std::string draw_svg(const OutputContext& ctx);

/// The file name of a path, without its directories (titles of the outputs).
std::string base_name(const std::string& file);

/// The unit of the input column: degrees for an angle, the scene's length unit for a length, "" otherwise.
std::string input_column_unit(const OutputContext& ctx);

/// The value of the input column of row r (output units: degrees for an angle), as csv_text writes it.
double input_column(const OutputContext& ctx, std::size_t r);

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

/// The contact pairs (cam and rolling) in pair order: the order of the analysis columns and contact_points().
std::vector<int> contact_pairs(const Mechanism<double>& m);

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
