// The chart of a solved sweep (`rollkin solve --plot`, Python Scene.write(plot=)).
#pragma once

#include "rollkin/output/drawing.hpp"

#include <string>

namespace rollkin::output {

/// SVG charts against the input, stacked in one document: the non-input pair angles; the lengths and
/// unitless parameters (when there are any); with ctx.analysis also the pressure angles, the sliding
/// velocities, the slide-to-roll ratios, the contact curvatures and the links' angular accelerations. One
/// pass over the poses; each series is reduced to the chart's pixel columns as it is read (output/decimate.hpp),
/// so the document's size and the memory do not grow with the number of poses.
std::string plot_svg(const SweepOutput& ctx);

}  // namespace rollkin::output
