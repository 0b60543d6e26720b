// `rollkin solve --animate FILE.html` (Python Scene.write(animate=)): the solved sweep as one self-contained HTML page (no external file,
// script or style) that animates the mechanism in an inline SVG.
//
// Each link is drawn once in its own frame (its contours as SVG paths, its body and joints: link_sketches(),
// shared with --draw) inside a <g> whose `transform` is the only thing a frame changes, taken from a table of
// the per-pose link poses (x, y, angle in degrees, 7 significant digits: the CSV's <link>.x, <link>.y,
// <link>.angle columns rounded) written into the page as JSON. The contact points move along the same way
// (one transform each per frame); their paths over the sweep and the centrodes of every moving link relative
// to the ground (fixed one in the ground's frame, moving one in the link's; the part within the picture and as
// much around it, none for a centre that stays within a pixel) are drawn once.
// Frames: every pose of a sweep of up to io::kAnimationFrames (2000) poses; of a longer one, 2000 evenly spaced
// and, where the status changes, the poses on both sides of the change (io::pick_frames, output/decimate.hpp), so
// that the page stays under a few megabytes for any number of poses and no limit, singular pose or unsolved
// stretch is lost from it. The paths and centrodes are drawn through the frames.
// Controls: a play/pause button, a slider over the frames (in CSV row order), the input value (the CSV's input
// column), the pose's CSV row and its status. A pose that was not solved shows its status and hides the moving links
// (nothing is interpolated); a singular pose shows its values and says they follow the branch.
// The page is also well-formed XML: names are escaped (io::xml_escape), the script is in a CDATA section and
// its data holds only numbers and fixed status texts.
#pragma once

#include "rollkin/output/drawing.hpp"

#include <string>

namespace rollkin::output {

/// The animation page of the solved sweep in ctx.
std::string animation_html(const SweepOutput& ctx);

}  // namespace rollkin::output
