// The picture of a contour listing (rollkin/output/contour_picture.hpp).
#include "rollkin/output/contour_picture.hpp"

#include "rollkin/output/drawing.hpp"
#include "rollkin/output/svg_drawing.hpp"

namespace rollkin::output {

std::string contour_listing_svg(const std::string& file, const std::vector<io::ListedChain>& chains) {
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  io::SvgDrawing d(900, 700, 30);
  d.set_title(base_name(file) + ": " + std::to_string(chains.size()) + " chain(s)");
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const io::ListedChain& c = chains[k];
    if (c.segments.empty()) continue;  // an unreadable entity: nothing to draw
    std::vector<Eigen::Vector2d> points;
    for (const auto& s : c.segments) {
      BezierPath<double> piece({s}, false);
      for (int i = (points.empty() ? 0 : 1); i <= 24; ++i) points.push_back(piece.jet(i / 24.0, 0).p);
    }
    io::Stroke st;
    st.color = colours[k % (sizeof colours / sizeof *colours)];
    st.width = 1.4;
    d.add_polyline(points, st, c.closed);
    d.add_point(points.front(), st.color, 3.0);
    d.add_text(points.front(), std::to_string(k + 1), 11.0, st.color);
  }
  return d.to_svg();
}

}  // namespace rollkin::output
