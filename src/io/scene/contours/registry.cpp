// The contour kinds of the scene format, keyed by their "type" (one line per kind: declaration and entry), and
// for a kind read from a file its file format (io/contour_formats.hpp: extensions, lister, description).
#include "contour_reader.hpp"

#include "rollkin/io/contour_formats.hpp"

namespace rollkin::io {

ContourShape read_line_contour(const json& c, const std::string& path, const ContourContext& ctx);      // analytic.cpp
ContourShape read_circle_contour(const json& c, const std::string& path, const ContourContext& ctx);    // analytic.cpp
ContourShape read_parabola_contour(const json& c, const std::string& path, const ContourContext& ctx);  // analytic.cpp
ContourShape read_ellipse_contour(const json& c, const std::string& path, const ContourContext& ctx);   // analytic.cpp
ContourShape read_samples_contour(const json& c, const std::string& path, const ContourContext& ctx);   // samples.cpp
ContourShape read_bezier_contour(const json& c, const std::string& path, const ContourContext& ctx);    // bezier.cpp
ContourShape read_svg_contour(const json& c, const std::string& path, const ContourContext& ctx);       // svg.cpp
ContourShape read_dxf_contour(const json& c, const std::string& path, const ContourContext& ctx);       // dxf.cpp
ContourShape read_nurbs_contour(const json& c, const std::string& path, const ContourContext& ctx);     // nurbs.cpp
std::vector<ListedChain> list_point_file_contours(const std::string& path);                             // samples.cpp

namespace {

/// One contour kind: its "type" and reader, and for a kind read from a file, that file's format.
struct ContourKind {
  const char* type;
  ContourReader read;
  ContourFileFormat file = {};
};

const std::vector<ContourKind>& contour_kinds() {
  static const std::vector<ContourKind> kinds{
      {"line", read_line_contour},
      {"circle", read_circle_contour},
      {"parabola", read_parabola_contour},
      {"ellipse", read_ellipse_contour},
      {"samples", read_samples_contour,
       {"point file", {".txt", ".csv"},
        "the one spline a \"samples\" contour fits; closed when its last point repeats its first",
        list_point_file_contours}},
      {"bezier", read_bezier_contour},
      {"svg", read_svg_contour,
       {"SVG drawing", {".svg"},
        "every subpath of every drawn element (<use>, <symbol>, <switch> expanded), y up",
        list_svg_contours}},
      {"dxf", read_dxf_contour,
       {"DXF drawing", {".dxf"}, "per layer, the chains its entities form end to end, in drawing units", list_dxf_contours}},
      {"nurbs", read_nurbs_contour},
  };
  return kinds;
}

}  // namespace

ContourReader find_contour_reader(const std::string& type) {
  for (const ContourKind& k : contour_kinds())
    if (type == k.type) return k.read;
  return nullptr;
}

std::vector<std::string> contour_types() {
  std::vector<std::string> out;
  for (const ContourKind& k : contour_kinds()) out.push_back(k.type);
  return out;
}

const std::vector<ContourFileFormat>& contour_file_formats() {
  static const std::vector<ContourFileFormat> formats = [] {
    std::vector<ContourFileFormat> out;
    for (const ContourKind& k : contour_kinds())
      if (k.file.list) {
        out.push_back(k.file);
        out.back().type = k.type;
      }
    return out;
  }();
  return formats;
}

}  // namespace rollkin::io
