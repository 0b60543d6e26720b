// Analytic contours: "line", "circle", "parabola", "ellipse" (docs/scene_format.md).
#include "contour_reader.hpp"

namespace rollkin::io {

ContourShape read_line_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"from", "to"});
  const double lo = js.number(js.require(c, path, "from", "start of the line along the contour frame's x"), child(path, "from"), "a length");
  const double hi = js.number(js.require(c, path, "to", "end of the line along the contour frame's x"), child(path, "to"), "a length");
  if (!(hi > lo))
    js.fail(path, "contour too short: the line runs from " + format_number(lo) + " to " + format_number(hi) +
                      "; expected \"to\" > \"from\" (a domain of non-zero length)");
  Line<double> line(lo, hi);
  return {line, ctx.material(c, path, std::nullopt, "left")};
}

ContourShape read_circle_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"radius", "arc"});
  const double r = js.number(js.require(c, path, "radius", "the circle's radius"), child(path, "radius"), "a radius");
  if (!(r > 0)) js.fail(child(path, "radius"), "non-positive radius " + format_number(r) + "; expected a radius > 0");
  std::optional<Circle<double>> circle;
  if (const json* a = js.get(c, "arc")) {
    const std::string ap = child(path, "arc");
    js.array(*a, ap, "an arc [from angle, to angle]", 2);
    const double a0 = js.number((*a)[0], index(ap, 0), "an angle"), a1 = js.number((*a)[1], index(ap, 1), "an angle");
    if (!(a1 > a0)) js.fail(ap, "contour too short: the arc [" + format_number(a0) + ", " + format_number(a1) + "] has no length; expected a1 > a0");
    circle.emplace(r, ctx.angle(a0), ctx.angle(a1));
  } else {
    circle.emplace(r);
  }
  return {*circle, ctx.material(c, path, true, "inside")};
}

ContourShape read_parabola_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"a", "x_range", "arc_length"});
  const double a = js.number(js.require(c, path, "a", "the coefficient in y = a x^2"), child(path, "a"), "the coefficient a");
  if (a == 0) js.fail(child(path, "a"), "a = 0 is a straight line; expected a non-zero coefficient (or use a \"line\" contour)");
  const std::string rp = child(path, "x_range");
  const json& xr = js.array(js.require(c, path, "x_range", "the parameter range [x0, x1]"), rp, "an x range [x0, x1]", 2);
  const double lo = js.number(xr[0], index(rp, 0), "x0"), hi = js.number(xr[1], index(rp, 1), "x1");
  if (!(hi > lo)) js.fail(rp, "contour too short: x_range [" + format_number(lo) + ", " + format_number(hi) + "] has no length; expected x1 > x0");
  ArcLengthMethod am;
  if (const json* al = js.get(c, "arc_length")) am = ctx.arc_length_method(*al, child(path, "arc_length"));
  Parabola<double> parabola(a, lo, hi, am);
  return {parabola, ctx.material(c, path, a > 0, "left")};  // left of x increasing is y > a x^2, the focus side iff a > 0
}

ContourShape read_ellipse_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"semi_axes", "arc_length"});
  const std::string sp = child(path, "semi_axes");
  const json& sa = js.array(js.require(c, path, "semi_axes", "the semi-axes [A, B]"), sp, "semi-axes [A, B]", 2);
  const double A = js.number(sa[0], index(sp, 0), "semi-axis A"), B = js.number(sa[1], index(sp, 1), "semi-axis B");
  if (!(A > 0) || !(B > 0)) js.fail(sp, "non-positive semi-axis; expected A > 0 and B > 0");
  ArcLengthMethod am;
  if (const json* al = js.get(c, "arc_length")) am = ctx.arc_length_method(*al, child(path, "arc_length"));
  Ellipse<double> ellipse(A, B, am);
  return {ellipse, ctx.material(c, path, true, "inside")};
}

}  // namespace rollkin::io
