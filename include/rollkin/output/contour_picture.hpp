// The picture of what a CAD drawing offers as contours (`rollkin contours FILE --draw OUT.svg`): every chain of
// the listing (io/contour_listing.hpp) in its own colour, numbered at its start as listed, on the canvas of
// `rollkin solve --draw` (output/svg_drawing.hpp).
#pragma once

#include "rollkin/io/contour_listing.hpp"

#include <string>
#include <vector>

namespace rollkin::output {

/// The SVG document of `chains` (as io::list_contours(file) lists them), titled with the file's name and the
/// number of chains. Each chain is drawn through 24 points per segment.
std::string contour_listing_svg(const std::string& file, const std::vector<io::ListedChain>& chains);

}  // namespace rollkin::output
