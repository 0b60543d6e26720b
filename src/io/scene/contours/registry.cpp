// The contour kinds of the scene format, keyed by their "type" (one line per kind: declaration and entry).
#include "contour_reader.hpp"

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

namespace {

const ContourKind kContourKinds[] = {
    {"line", read_line_contour},         {"circle", read_circle_contour}, {"parabola", read_parabola_contour},
    {"ellipse", read_ellipse_contour},   {"samples", read_samples_contour}, {"bezier", read_bezier_contour},
    {"svg", read_svg_contour},           {"dxf", read_dxf_contour},       {"nurbs", read_nurbs_contour},
};

}  // namespace

ContourReader find_contour_reader(const std::string& type) {
  for (const ContourKind& k : kContourKinds)
    if (type == k.type) return k.read;
  return nullptr;
}

std::vector<std::string> contour_types() {
  std::vector<std::string> out;
  for (const ContourKind& k : kContourKinds) out.push_back(k.type);
  return out;
}

}  // namespace rollkin::io
