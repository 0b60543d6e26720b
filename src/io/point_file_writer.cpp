// The point files rollkin writes (include/rollkin/io/point_file.hpp, point_file_text): synthesize's profiles and
// pitch curves, the envelope's points.
#include "rollkin/io/point_file.hpp"

#include "rollkin/io/csv.hpp"
#include "rollkin/io/output_set.hpp"

#include <cmath>

namespace rollkin::io {

std::string point_file_text(const std::string& comment, const std::vector<Vec2<double>>& points) {
  std::string out;
  std::size_t from = 0;
  while (from <= comment.size()) {  // every line of the comment as a comment line
    const std::size_t end = std::min(comment.find('\n', from), comment.size());
    out += "# " + comment.substr(from, end - from) + "\n";
    from = end + 1;
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec2<double>& p = points[k];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw InternalError("point " + std::to_string(k + 1) + " of " + std::to_string(points.size()) + " to write (" +
                          format_double(p.x()) + ", " + format_double(p.y()) + ") is not finite; a point file cannot hold it");
    append_double(out, p.x());
    out += ' ';
    append_double(out, p.y());
    out += '\n';
  }
  return out;
}

}  // namespace rollkin::io
