// "svg" contours: one <path> of an SVG file, read by read_svg_path (docs/scene_format.md).
#include "contour_reader.hpp"

#include "rollkin/io/svg_path.hpp"

namespace rollkin::io {

ContourShape read_svg_contour(const json& c, const std::string& path, const ContourContext& ctx) {
  const JsonAccess& js = ctx.js;
  ctx.keys(c, path, {"file", "path", "flip_y", "scale", "parameter"});
  const std::string svg = ctx.contour_file(js.require(c, path, "file", "the SVG file"), child(path, "file"));
  const std::string id = js.string(js.require(c, path, "path", "the id of the <path> element"), child(path, "path"), "a path id");
  SvgPathOptions opt;
  if (const json* fy = js.get(c, "flip_y")) opt.flip_y = js.boolean(*fy, child(path, "flip_y"), "whether to flip y");
  opt.scale = js.number_or(c, path, "scale", 1.0, "a scale factor");
  if (!(opt.scale > 0)) js.fail(child(path, "scale"), "expected a positive scale factor, got " + fmt(opt.scale));
  std::vector<SvgSubpath> subs;
  try {
    subs = read_svg_path(svg, id, opt);
  } catch (const InputError& e) {
    js.fail(child(path, "file"), e.what());
  }
  if (subs.size() != 1)
    js.fail(child(path, "path"), "the SVG path \"" + id + "\" in " + svg + " has " + std::to_string(subs.size()) +
                                     " subpaths; expected exactly one (one contour per path)");
  std::vector<Vec2<double>> polygon;
  for (std::size_t i = 0; i < subs[0].segments.size(); ++i)
    for (std::size_t k = (i == 0 ? 0 : 1); k < subs[0].segments[i].points.size(); ++k) polygon.push_back(subs[0].segments[i].points[k]);
  const bool closed = subs[0].closed;
  std::optional<BezierPath<double>> bezier;
  try {
    bezier.emplace(subs[0].segments, closed);
  } catch (const std::exception& e) {
    js.fail(path, "the SVG path \"" + id + "\" in " + svg + " is not a usable contour: " + e.what());
  }
  const bool reversed =
      closed ? ctx.material(c, path, signed_area(polygon) > 0, "inside") : ctx.material(c, path, std::nullopt, "left");
  return {ctx.parameterised(std::move(*bezier), c, path), reversed};
}

}  // namespace rollkin::io
