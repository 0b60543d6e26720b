// "svg" contours: one subpath of an SVG file, selected by the element's id and "subpath", or by "near", read by
// read_svg_shape (io/svg/reader.hpp) with the scene's length unit, then made a BezierPath (docs/scene_format.md,
// "SVG contours").
#include "contour_reader.hpp"

#include "rollkin/io/svg/reader.hpp"

#include <cmath>
#include <sstream>

namespace rollkin::io {

namespace {

/// The element id: "path" (or its alias "id"), at most one of the two; "" when absent and `near` chooses.
std::string element_id(const json& c, const std::string& path, const JsonAccess& js) {
  const json* p = js.get(c, "path");
  const json* i = js.get(c, "id");
  if (p && i) js.fail(child(path, "id"), "give the element id once: \"path\" and its alias \"id\" are both present");
  if (!p && !i) {
    if (js.get(c, "near") || js.get(c, "subpath")) return "";  // among everything the drawing draws
    js.fail(path, "missing key \"path\": expected the id of the SVG element (path, circle, ellipse, rect, line, "
                  "polyline, polygon, or a group or <use> drawing them), or \"near\": [x, y] or \"subpath\": k");
  }
  const std::string key = p ? "path" : "id";
  const std::string id = js.string(p ? *p : *i, child(path, key), "an element id");
  if (id.empty()) js.fail(child(path, key), "expected an element id, got an empty string");
  return id;
}

/// "subpath": a whole number from 1.
std::optional<std::size_t> subpath_number(const json& c, const std::string& path, const JsonAccess& js) {
  const json* k = js.get(c, "subpath");
  if (!k) return std::nullopt;
  const double v = js.number(*k, child(path, "subpath"), "a subpath number (1 for the first)");
  if (!(v >= 1) || v != std::floor(v) || v > 1e9)
    js.fail(child(path, "subpath"), "expected a whole number from 1 (subpaths count from 1), got " + format_number(v));
  return static_cast<std::size_t>(v);
}

}  // namespace

ContourShape read_svg_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"file", "path", "id", "subpath", "near", "flip_y", "scale", "parameter"});
  const std::string svg = ctx.contour_file(js.require(c, path, "file", "the SVG file"), child(path, "file"));
  const std::string id = element_id(c, path, js);
  SvgReadOptions opt;
  if (const json* fy = js.get(c, "flip_y")) opt.flip_y = js.boolean(*fy, child(path, "flip_y"), "whether to flip y");
  opt.scale = ctx.scale(c, path);
  opt.subpath = subpath_number(c, path, js);
  if (const json* near = js.get(c, "near")) opt.near = js.point(*near, child(path, "near"));
  if (opt.subpath && opt.near) js.fail(child(path, "subpath"), "give \"subpath\" or \"near\", not both");
  if (ctx.length_unit() != LengthUnit::Unitless) opt.metres_per_scene_unit = metres_per(ctx.length_unit());
  std::optional<BezierPath<double>> bezier;
  SvgShape shape;
  std::vector<std::size_t> first;  // per piece of the path, its first segment of the shape (origins)
  try {
    shape = read_svg_shape(svg, id, opt);
    first = join_straight_runs(shape.segments);
    bezier.emplace(svg_bezier_path(shape));
    std::ostringstream read;  // what was read, for --verbose (and to compare with `rollkin contours`)
    read.precision(15);
    read << "; read " << (shape.closed ? "closed" : "open") << ", length " << bezier->total_length() << " (scene units)";
    ctx.note(shape.conversion + read.str());
  } catch (const InputError& e) {
    js.fail(child(path, "file"), e.what());
  }
  const bool reversed = shape.closed ? ctx.material(c, path, signed_area(control_polygon(shape.segments)) > 0, "inside")
                                     : ctx.material(c, path, std::nullopt, "left");
  const std::size_t n = shape.origins.size();
  std::vector<std::string> corners = describe_joints(*bezier, [&](std::size_t piece) {
    const std::size_t k = first[piece];
    return "where " + shape.origins[(k + n - 1) % n] + " meets " + shape.origins[k] + " (" + shape.location + " of " + svg + ")";
  }, "svg " + shape.location, ctx);
  return {ctx.parameterised(std::move(*bezier), c, path), reversed, std::move(corners)};
}

}  // namespace rollkin::io
