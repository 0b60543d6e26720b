// The markup the SVG writers (output/svg_chart.hpp, output/svg_drawing.hpp) share: the colour palette, XML text
// escaping, the number formats of pixel coordinates and sizes, the document's opening tag, and the runs of
// finite points a polyline is broken into.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rollkin::io {

/// The default colour cycle (10 distinguishable colours); palette_color(i) wraps around.
const std::vector<std::string>& default_palette();
const std::string& palette_color(std::size_t i);

/// XML text escaping of &, <, >, " and '; control characters and bytes that are not UTF-8 (neither
/// allowed in XML 1.0) are written as visible escapes "\n", "\x01", "\xff", so the document stays
/// well-formed whatever a name holds.
std::string xml_escape(const std::string& text);

/// Pixel coordinate with two decimals ("12.50", never "-0.00"); non-finite values are written as 0 and huge
/// ones clamped to +-1e7 so the document stays sane.
std::string svg_pixel(double v);

/// Sizes and widths (font sizes, stroke widths, opacities): 4 significant digits.
std::string svg_size(double v);

/// The XML declaration and the opening <svg> tag of a document of w x h pixels (viewBox 0 0 w h).
std::string svg_document_open(int width_px, int height_px);

/// The runs [begin, end) of consecutive indices in [0, n) for which finite(i) holds, in order.
template <class Finite> std::vector<std::pair<std::size_t, std::size_t>> finite_runs(std::size_t n, Finite finite) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // [begin, end)
  std::size_t i = 0;
  while (i < n) {
    while (i < n && !finite(i)) ++i;
    const std::size_t b = i;
    while (i < n && finite(i)) ++i;
    if (i > b) runs.emplace_back(b, i);
  }
  return runs;
}

}  // namespace rollkin::io
