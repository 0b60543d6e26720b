// "nurbs" contours: a NURBS curve given inline, converted exactly to rational Bezier pieces by
// nurbs_to_bezier (profile/nurbs.hpp) and made a BezierPath (docs/scene_format.md, "nurbs").
#include "contour_reader.hpp"

#include "rollkin/profile/nurbs.hpp"

#include <cmath>

namespace rollkin::io {

namespace {

std::vector<double> numbers(const json& v, const std::string& path, const std::string& what, const JsonAccess& js) {
  js.array(v, path, "a list of " + what);
  std::vector<double> out;
  for (std::size_t k = 0; k < v.size(); ++k) out.push_back(js.number(v[k], index(path, k), what));
  return out;
}

/// The key of the contour object that an invalid_argument of validate_nurbs / nurbs_to_bezier is about.
std::string key_of(const std::string& message) {
  if (message.find("marked closed") != std::string::npos) return "closed";
  if (message.find("weight") != std::string::npos) return "weights";
  if (message.find("knot") != std::string::npos) return "knots";
  if (message.find("control point") != std::string::npos) return "points";
  if (message.find("degree") != std::string::npos) return "degree";
  return "";
}

}  // namespace

ContourShape read_nurbs_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"degree", "knots", "points", "weights", "closed", "parameter"});
  Nurbs<double> n;
  const double degree = js.number(js.require(c, path, "degree", "the NURBS degree"), child(path, "degree"), "the degree");
  if (degree != std::floor(degree) || degree < 1 || degree > 32)
    js.fail(child(path, "degree"), "expected an integer degree from 1 to 32, got " + format_number(degree));
  n.degree = static_cast<int>(degree);
  n.knots = numbers(js.require(c, path, "knots", "the knot vector"), child(path, "knots"), "knots", js);
  n.points = js.points(js.require(c, path, "points", "the control points"), child(path, "points"));
  if (const json* w = js.get(c, "weights")) n.weights = numbers(*w, child(path, "weights"), "weights", js);
  if (const json* cl = js.get(c, "closed")) n.closed = js.boolean(*cl, child(path, "closed"), "whether the curve is closed");
  NurbsPieces<double> pieces;
  try {
    pieces = nurbs_to_bezier(n);
  } catch (const std::invalid_argument& e) {
    const std::string key = key_of(e.what());
    js.fail(key.empty() ? path : child(path, key), e.what());
  }
  std::optional<BezierPath<double>> bezier;
  try {
    bezier.emplace(pieces.segments, pieces.closed);
  } catch (const std::exception& e) {
    js.fail(path, std::string("the NURBS is not a usable contour: ") + e.what());
  }
  const bool reversed = pieces.closed ? ctx.material(c, path, signed_area(control_polygon(pieces.segments)) > 0, "inside")
                                      : ctx.material(c, path, std::nullopt, "left");
  std::vector<std::string> corners = describe_joints(*bezier, [&](std::size_t piece) {
    return "NURBS knot u = " + format_number(pieces.breaks[piece]) + " (" + child(path, "knots") + ")";
  }, "nurbs " + path, ctx);
  return {ctx.parameterised(std::move(*bezier), c, path), reversed, std::move(corners)};
}

}  // namespace rollkin::io
