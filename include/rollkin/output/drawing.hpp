// The drawing of a solved sweep's mechanism (`rollkin solve --draw`, Python Scene.write(draw=)): up to four
// poses, one panel each; and what the drawing, the charts and the animation share: each link's sketch in its
// own frame, the contact points, the file's name for titles and SVG documents nested in others.
#pragma once

#include "rollkin/output/sweep_table.hpp"
#include "rollkin/kinematics.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace rollkin::output {

/// What every writer of a solved sweep reads: the scene, the sweep, its rows and the inputs in file units.
using SweepOutput = io::SweepOutput;
using io::contact_pairs;
using io::input_column;
using io::input_column_unit;

/// SVG drawing of the mechanism at up to four poses spread over the solved ones, one panel per pose at a
/// common scale (small multiples: no two poses overlap).
std::string draw_svg(const SweepOutput& ctx);

/// The file name of a path, without its directories (titles of the outputs).
std::string base_name(const std::string& file);

/// An SVG document from its <svg> element on, without the XML declaration: to nest it in another document
/// (the stacked charts, the drawing's tiled panels).
std::string strip_header(const std::string& svg);

/// A link as drawn, in its own frame: the drawing places it at each drawn pose, the animation draws it once
/// and moves it with one transform per frame.
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

}  // namespace rollkin::output
