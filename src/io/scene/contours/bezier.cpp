// "bezier" contours: polynomial or rational Bezier segments given inline (docs/scene_format.md).
#include "contour_reader.hpp"

namespace rollkin::io {

namespace {

BezierSegment<double> read_segment(const json& seg, const std::string& sp, const JsonAccess& js) {
  js.object(seg, sp, {"points", "weights"});
  BezierSegment<double> s;
  s.points = js.points(js.require(seg, sp, "points", "the control points"), child(sp, "points"));
  if (s.points.size() < 2) js.fail(child(sp, "points"), "expected at least 2 control points, got " + std::to_string(s.points.size()));
  if (const json* w = js.get(seg, "weights")) {
    js.array(*w, child(sp, "weights"), "one weight per control point", s.points.size());
    for (std::size_t k = 0; k < w->size(); ++k) {
      const double x = js.number((*w)[k], index(child(sp, "weights"), k), "a weight");
      if (!(x > 0)) js.fail(index(child(sp, "weights"), k), "expected a positive weight, got " + format_number(x));
      s.weights.push_back(x);
    }
  }
  return s;
}

}  // namespace

ContourShape read_bezier_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"segments", "closed", "parameter"});
  const bool closed = js.get(c, "closed") ? js.boolean(c["closed"], child(path, "closed"), "whether the path is closed") : false;
  const json& segs = js.array(js.require(c, path, "segments", "the Bezier segments"), child(path, "segments"), "a list of segments");
  if (segs.empty()) js.fail(child(path, "segments"), "contour too short: no segments; expected at least one");
  std::vector<BezierSegment<double>> out;
  std::vector<Vec2<double>> polygon;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    BezierSegment<double> s = read_segment(segs[i], index(child(path, "segments"), i), js);
    for (std::size_t k = (i == 0 ? 0 : 1); k < s.points.size(); ++k) polygon.push_back(s.points[k]);
    out.push_back(std::move(s));
  }
  std::optional<BezierPath<double>> bezier;
  try {
    bezier.emplace(std::move(out), closed);
  } catch (const std::exception& e) {
    js.fail(child(path, "segments"), e.what());
  }
  const bool reversed =
      closed ? ctx.material(c, path, signed_area(polygon) > 0, "inside") : ctx.material(c, path, std::nullopt, "left");
  return {ctx.parameterised(std::move(*bezier), c, path), reversed};
}

}  // namespace rollkin::io
